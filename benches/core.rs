//! Core benchmarks: building a `Triangulation` from a face list (vertex ids in the
//! generator's order, and shuffled; on pools of 1 and 2 threads), validating it from scratch, checking a tri-quad
//! conversion, and the `info` invariants, on the ~4.2M-triangle genus-0 paper brick B0.
//! Run: `cargo bench --bench core`. Divan reports medians.

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
    bench_build(b, b0());
}

/// B0 with vertex `v` renamed `id[v]`.
fn b0_renamed(id: &[u32]) -> TriMesh {
    let m = b0();
    TriMesh::combinatorial(
        m.vertex_count,
        m.faces.iter().map(|f| f.map(|v| id[v as usize])).collect(),
    )
}

/// `Triangulation::from_faces` on `m`.
fn bench_build(b: divan::Bencher, m: &TriMesh) {
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface"));
}

/// `Triangulation::from_faces` on B0 with its vertex ids permuted at random (seed 1):
/// ids that do not follow the surface, as in meshes from scans and modelling tools,
/// where the build's gathering of each vertex's faces misses the caches (unless the
/// build renumbers them).
#[divan::bench(sample_count = 10)]
fn build_b0_shuffled_ids(b: divan::Bencher) {
    static M: OnceLock<TriMesh> = OnceLock::new();
    let m = M.get_or_init(|| {
        let mut id: Vec<u32> = (0..b0().vertex_count as u32).collect();
        contractible::rng::Rng::new(1).shuffle(&mut id);
        b0_renamed(&id)
    });
    bench_build(b, m);
}

/// `Triangulation::from_faces` on B0 with its vertex ids renumbered in order of first
/// appearance in the face list.
#[divan::bench(sample_count = 10)]
fn build_b0_first_appearance_ids(b: divan::Bencher) {
    static M: OnceLock<TriMesh> = OnceLock::new();
    let m = M.get_or_init(|| {
        let mut id = vec![u32::MAX; b0().vertex_count];
        let mut next = 0;
        for &v in b0().faces.as_flattened() {
            if id[v as usize] == u32::MAX {
                id[v as usize] = next;
                next += 1;
            }
        }
        b0_renamed(&id)
    });
    bench_build(b, m);
}

/// `Triangulation::from_faces` on B0 on a rayon pool of 1 and of 2 threads: with the
/// `parallel` feature (on in the benchmarks) the edge classification runs on the pool's
/// threads above a size B0 passes, the rest of the build on the calling one.
#[divan::bench(args = [1, 2], sample_count = 10)]
fn build_b0_threads(b: divan::Bencher, threads: usize) {
    let m = b0();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| {
            pool.install(|| Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface"))
        });
}

/// The floor under `build_b0` that fresh memory sets: allocating and writing once as
/// many bytes as that build allocates (three arrays of one `u32` per corner: the
/// corner-to-vertex array, the gluing and the corners grouped by vertex; five of one
/// `u32` per vertex; one flag per vertex), and nothing else. Most of this is the kernel
/// handing out and zeroing pages, not the writes.
#[divan::bench(sample_count = 10)]
fn fresh_memory_b0(b: divan::Bencher) {
    let m = b0();
    let (corners, vertices) = (3 * m.faces.len(), m.vertex_count);
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| {
            let per_corner: [Vec<u32>; 3] = std::array::from_fn(|_| vec![1u32; corners]);
            let per_vertex: [Vec<u32>; 5] = std::array::from_fn(|_| vec![1u32; vertices]);
            let flags = vec![true; vertices];
            (per_corner, per_vertex, flags)
        });
}

/// `Triangulation::validate`, the independent from-scratch check, on B0.
#[divan::bench(sample_count = 10)]
fn validate_b0(b: divan::Bencher) {
    let m = b0();
    let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface");
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| t.validate().expect("valid"));
}

/// `task::verify_quadrangulation`, the independent check of a tri-quad conversion, on
/// B0's conversions by PS (the triangulation unchanged) and LRS (flipped).
#[divan::bench(args = ["ps", "lrs"], sample_count = 10)]
fn verify_quad_b0(b: divan::Bencher, algo: &str) {
    use contractible::quad::{convert, Algorithm, Options};
    let m = b0();
    let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface");
    let alg = match algo {
        "ps" => Algorithm::PulliSegal,
        _ => Algorithm::Lrs,
    };
    let q = convert(t.clone(), alg, &Options::default()).expect("converted");
    b.counter(divan::counter::ItemsCount::new(m.faces.len()))
        .bench(|| assert!(contractible::task::verify_quadrangulation(&t, &q)));
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
