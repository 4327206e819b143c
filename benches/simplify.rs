//! Short-edge simplification on ≥ 1M-triangle marching-tetrahedra surfaces
//! and on the paper's Table 1 workloads, in one run, so that ratios compare medians of
//! one run.
//!
//! Inputs (generated once, outside the timed region): `large_torus` with both
//! tessellations (1,057,260 triangles body-centred), `large_hyperboloid` body-centred
//! (open: two discs), and the Table 1 sizes `paper_torus` / `paper_hyperboloid`
//! (body-centred). ε is a fraction of the bounding-box diagonal.
//!
//! Groups: `nested_1pct` (the throughput figure: input triangles per second from the
//! mesh), `naive_1pct`, `nested_3pct` (each sample one `simplify` call from the mesh:
//! validation and building included, the output mesh assembled), `nested_1pct_built`
//! (`simplify_surfaces` from surfaces built outside the timed region: the algorithm
//! alone, as the command line times it) and `build` (validation and coning alone). Run:
//! `cargo bench --bench simplify` (about a minute), then divide the input's triangle
//! count (printed by `cargo run --release -p contractible-tools --bin simplify_profile`) by the median.

use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

use contractible::gen::{
    isosurface, large_hyperboloid, large_torus, paper_hyperboloid, paper_torus, Tessellation,
};
use contractible::simplify::{bbox_diagonal, simplify, simplify_surfaces, Mode, Options};
use contractible::{ConedSurfaces, TriMesh};

fn main() {
    divan::main();
}

const INPUTS: &[&str] = &[
    "large_torus_bcc",
    "large_torus_six",
    "large_hyperboloid_bcc",
    "paper_torus_bcc",
    "paper_hyperboloid_bcc",
];

/// The input mesh and its bounding-box diagonal, generated once per process.
fn input(name: &str) -> &'static (TriMesh, f64) {
    static CACHE: OnceLock<Mutex<HashMap<String, &'static (TriMesh, f64)>>> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    let mut map = cache.lock().expect("no poisoned lock");
    map.entry(name.to_string()).or_insert_with(|| {
        let params = match name {
            "large_torus_bcc" => large_torus(Tessellation::BodyCentred),
            "large_torus_six" => large_torus(Tessellation::SixTetrahedra),
            "large_hyperboloid_bcc" => large_hyperboloid(Tessellation::BodyCentred),
            "paper_torus_bcc" => paper_torus(Tessellation::BodyCentred),
            "paper_hyperboloid_bcc" => paper_hyperboloid(Tessellation::BodyCentred),
            other => panic!("unknown input {other}"),
        };
        let mesh = isosurface(&params).expect("the presets are valid");
        let diag = bbox_diagonal(mesh.positions.as_deref().unwrap_or(&[]).iter().copied());
        Box::leak(Box::new((mesh, diag)))
    })
}

fn run(b: divan::Bencher, name: &str, mode: Mode, rel: f64) {
    let (mesh, diag) = input(name);
    let opts = Options {
        mode,
        ..Options::new(rel * diag)
    };
    b.bench_local(|| simplify(mesh, &opts).expect("a valid surface"));
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn nested_1pct(b: divan::Bencher, name: &str) {
    run(b, name, Mode::Nested, 0.01);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn naive_1pct(b: divan::Bencher, name: &str) {
    run(b, name, Mode::Naive, 0.01);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn nested_3pct(b: divan::Bencher, name: &str) {
    run(b, name, Mode::Nested, 0.03);
}

/// The algorithm alone: `simplify_surfaces` from surfaces built (and cloned) outside the
/// timed region, as the command line runs it after its own validation.
#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn nested_1pct_built(b: divan::Bencher, name: &str) {
    let (mesh, diag) = input(name);
    let built = ConedSurfaces::from_mesh(mesh).expect("a valid surface");
    let positions = mesh.positions.as_deref().unwrap_or(&[]);
    let opts = Options::new(0.01 * diag);
    b.with_inputs(|| built.clone()).bench_local_values(|s| {
        simplify_surfaces(s, positions, &opts, &mut |_| {}).expect("a valid surface")
    });
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn build(b: divan::Bencher, name: &str) {
    let (mesh, _) = input(name);
    b.bench_local(|| ConedSurfaces::from_mesh(mesh).expect("a valid surface"));
}
