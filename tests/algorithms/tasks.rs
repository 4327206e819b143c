//! The per-task library calls, checked from their outputs alone: the file-to-file
//! example (`examples/file_to_file.rs`, shown in the README) run on a mesh the
//! repository carries, each written file read back and checked independently; and the
//! README's copy of the example kept equal to the file.

use std::path::Path;

use contractible::diagnose::diagnose;
use contractible::io::{self, PolyMesh};
use contractible::task::component_types;
use contractible::{ConedSurfaces, Surfaces, TriMesh};

#[allow(dead_code)]
#[path = "../../examples/file_to_file.rs"]
mod file_to_file;

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("contractible-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).expect("a temporary directory");
    d
}

/// The topological types of a closed mesh's components, sorted.
fn types(m: &TriMesh) -> Vec<(i64, bool, usize)> {
    component_types(&ConedSurfaces::from_mesh(m).expect("a surface"))
}

#[test]
fn the_file_to_file_example_writes_three_checked_results() {
    let input = crate::common::data_meshes().join("closed/bunny_npm.off.gz");
    let mesh = io::read_tri_mesh(&input).expect("the repository's bunny");
    let out = temp_dir("file-to-file");
    file_to_file::run(&input, &out).expect("the example runs");

    // The irreducible triangulation: closed, the input's topology, and no edge passes
    // the link condition by its definition.
    let irr = io::read_tri_mesh(&out.join("irreducible.off")).expect("written");
    assert_eq!(types(&irr), types(&mesh));
    let s = Surfaces::from_mesh(&irr).expect("closed surfaces");
    assert!(s.components.iter().all(|c| c.tri.is_irreducible_naive()));
    assert!(irr.faces.len() < mesh.faces.len());
    // Survivors keep their input coordinates.
    let input_points = mesh.positions.as_deref().expect("positions");
    for p in irr.positions.as_deref().expect("positions") {
        assert!(input_points.contains(p), "{p:?} is not an input vertex");
    }

    // The quads: one per two input triangles, a closed polygon surface of the input's
    // χ on the input's vertices and positions.
    let quads = io::read_poly_mesh(&out.join("quads.obj"), None).expect("written");
    let q: &PolyMesh = &quads.mesh;
    assert_eq!(q.face_count(), mesh.faces.len() / 2);
    assert!(q.faces().all(|f| f.len() == 4));
    let d = diagnose(q, 5);
    assert!(d.is_closed_surface(), "{d:?}");
    let chi: i64 = types(&mesh).iter().map(|t| t.0).sum();
    assert_eq!(d.euler_characteristic, chi);
    assert_eq!(q.positions.as_deref(), mesh.positions.as_deref());

    // The simplification: the input's components and topology, fewer faces, and no
    // edge shorter than ε = 2 % of the bounding-box diagonal left unless it is one the
    // method cannot contract (counted by the library; here only the topology and size).
    let simp = io::read_tri_mesh(&out.join("simplified.ply")).expect("written");
    assert_eq!(types(&simp), types(&mesh));
    assert!(simp.faces.len() < mesh.faces.len());
    std::fs::remove_dir_all(&out).ok();
}

/// The README shows the example as it is in `examples/file_to_file.rs`.
#[test]
fn the_readme_shows_the_example_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let example = std::fs::read_to_string(root.join("examples/file_to_file.rs")).expect("read");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("read");
    assert!(
        readme.contains(example.trim_end()),
        "README.md must show examples/file_to_file.rs verbatim (in a ```rust block)"
    );
    assert!(example.lines().count() <= 25, "the example stays short");
}
