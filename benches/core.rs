//! Core benchmarks: building a `Triangulation` from a face list and the `info`
//! invariants, on the ~4.2M-triangle genus-0 paper brick B0 and on a subdivided real
//! mesh. Run: `cargo bench --bench core`. Divan reports medians.

use contractible::gen::paper_family;
use contractible::{Surfaces, TriMesh, Triangulation};
use std::sync::OnceLock;

fn b0() -> &'static TriMesh {
    static M: OnceLock<TriMesh> = OnceLock::new();
    M.get_or_init(|| paper_family('B', 0).expect("valid brick parameters"))
}

fn main() {
    let m = b0();
    let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("B0 is a surface");
    eprintln!(
        "B0: {} vertices, {} faces; core heap {} bytes = {:.1} bytes/triangle",
        t.vertex_count(),
        t.face_count(),
        t.heap_bytes(),
        t.heap_bytes() as f64 / t.face_count() as f64
    );
    divan::main();
}

/// `Triangulation::from_faces` (full validation) on B0.
#[divan::bench(sample_count = 10)]
fn build_b0(b: divan::Bencher) {
    let m = b0();
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface"));
}

/// `Surfaces::from_mesh` (validation + component split) on B0.
#[divan::bench(sample_count = 10)]
fn surfaces_b0(b: divan::Bencher) {
    let m = b0();
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| Surfaces::from_mesh(m).expect("surface"));
}

/// What `contractible info` computes after building: χ, orientability, degree histogram.
#[divan::bench(sample_count = 10)]
fn info_invariants_b0(b: divan::Bencher) {
    let m = b0();
    let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface");
    b.bench(|| {
        (
            t.euler_characteristic(),
            t.is_orientable(),
            t.degree_histogram(),
        )
    });
}
