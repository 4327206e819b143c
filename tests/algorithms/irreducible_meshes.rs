//! The three irreducible-triangulation algorithms on every closed mesh, component by
//! component, with the independent checks of `common::check` (naive irreducibility,
//! validation, topology, Joret–Wood, exact expansion, counters): by default the
//! repository's meshes (`tests/data/meshes/closed`) and the generated closed surfaces of
//! `closed_inputs` (orientable and non-orientable, several components), in the
//! ignored `corpus` tests every mesh of the real-mesh corpus. Restrict the algorithms with
//! `CONTRACTIBLE_TEST_ALGORITHMS`.
//!
//! The largest corpus meshes make this slow in debug builds; `cargo test --release`
//! runs it in seconds.

use std::path::Path;

use crate::{closed_inputs, common};

use common::{algorithms, check};
use contractible::irreducible::reduce;
use contractible::Surfaces;

/// Every algorithm on every component of `surfaces`; returns the number of components.
fn reduce_components(surfaces: &Surfaces, name: &str) -> usize {
    let algs = algorithms();
    for (k, comp) in surfaces.components.iter().enumerate() {
        for &alg in &algs {
            let r = reduce(comp.tri.clone(), alg, &common::options(k as u64));
            check(&comp.tri, &r, alg, &format!("{name} component {k}"));
        }
    }
    surfaces.components.len()
}

/// Every mesh of `meshes/closed` (at least `min_files`), checked against `manifest.csv`
/// beside it, then reduced component by component.
fn every_closed_mesh_of(meshes: &Path, min_files: usize) {
    let dir = meshes.join("closed");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    assert!(
        files.len() >= min_files,
        "{} meshes in {}",
        files.len(),
        dir.display()
    );
    let manifest = common::manifest_in(meshes);
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
        components_checked += reduce_components(&surfaces, &name);
    }
    assert!(components_checked >= files.len());
}

/// Every closed mesh the repository carries (nine, 20 components, genus 0 to 24).
#[test]
fn every_repository_closed_mesh_reduces_to_irreducible_components() {
    let rows = common::data_manifest();
    let closed = rows.iter().filter(|r| r.set == "closed").count();
    assert_eq!(closed, 9, "closed rows of tests/data/meshes/manifest.csv");
    every_closed_mesh_of(&common::data_meshes(), closed);
}

/// Every generated closed surface of `closed_inputs`, checked against what its
/// construction makes (components, and per component χ and orientability), then reduced
/// component by component.
#[test]
fn every_generated_closed_surface_reduces_to_irreducible_components() {
    let mut components_checked = 0;
    for g in closed_inputs::closed_surfaces() {
        let surfaces = Surfaces::from_mesh(&g.mesh).unwrap_or_else(|e| panic!("{}: {e}", g.name));
        let mut types: Vec<(i64, bool)> = surfaces
            .components
            .iter()
            .map(|c| (c.tri.euler_characteristic(), c.tri.is_orientable()))
            .collect();
        types.sort_unstable();
        assert_eq!(types, g.types(), "{}", g.name);
        assert_eq!(surfaces.counts().2, g.mesh.faces.len(), "{}", g.name);
        components_checked += reduce_components(&surfaces, &g.name);
    }
    assert_eq!(components_checked, closed_inputs::COMPONENTS);
}

mod corpus {
    use super::*;

    /// Every closed mesh of the real-mesh corpus (99).
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_closed_mesh_reduces_to_irreducible_components() {
        every_closed_mesh_of(&common::corpus_meshes(), 90);
    }
}
