//! The three irreducible-triangulation algorithms on every closed mesh of
//! `../shared/meshes/closed`, component by component, with the independent checks of
//! `common::check` (naive irreducibility, validation, topology, Joret–Wood, exact
//! expansion, counters). Restrict the algorithms with `CONTRACTIBLE_TEST_ALGORITHMS`.
//!
//! The largest meshes make this slow in debug builds; `cargo test --release --test
//! irreducible_meshes` runs it in seconds.

use crate::common;

use common::{algorithms, check};
use contractible::irreducible::reduce;
use contractible::Surfaces;

#[test]
fn every_closed_mesh_reduces_to_irreducible_components() {
    let dir = common::shared_dir().join("meshes/closed");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no meshes in {}", dir.display());
    let manifest = common::manifest();
    let algs = algorithms();
    let mut components_checked = 0;
    for path in &files {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let mesh = contractible::io::read_tri_mesh(path).unwrap_or_else(|e| panic!("{name}: {e}"));
        let surfaces = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{name}: {e}"));
        // The manifest's component count and total Euler characteristic agree with ours,
        // so the reductions below start from the right surfaces.
        let row = manifest
            .iter()
            .find(|r| r.file == format!("closed/{name}"))
            .unwrap_or_else(|| panic!("{name}: not in manifest.csv"));
        assert_eq!(surfaces.components.len(), row.components, "{name}");
        let chi: i64 = surfaces
            .components
            .iter()
            .map(|c| c.tri.euler_characteristic())
            .sum();
        assert_eq!(chi, row.euler, "{name}");
        assert_eq!(surfaces.counts().2, row.f, "{name}");
        for (k, comp) in surfaces.components.iter().enumerate() {
            for &alg in &algs {
                let r = reduce(comp.tri.clone(), alg, &common::options(k as u64));
                check(&comp.tri, &r, alg, &format!("{name} component {k}"));
            }
            components_checked += 1;
        }
    }
    assert!(components_checked >= files.len());
}
