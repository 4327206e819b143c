//! Decimation (`contractible::decimate`: quadric edge collapse with the link condition on
//! every collapse) to 10 % and 1 % of the faces, on meshes of the repository and on
//! marching-tetrahedra surfaces of about a million triangles, with the default options
//! (the output checked independently inside the call) and with `skip_verify` (so the
//! difference is the check's cost).
//!
//! Inputs (read or generated once, outside the timed region): `bunny_npm` (3,674
//! triangles), `high_genus_3` (3,328, genus 3) and `letter` (8,832) from
//! `tests/data/meshes/closed/`; `sphere_1m`, the unit sphere at resolution 236 with six
//! tetrahedra per cell (1,005,624 triangles), and `large_torus_bcc`, the simplifier's
//! benchmark torus (1,057,260 triangles, body-centred).
//!
//! Groups: `keep_10pct`, `keep_1pct` (one `decimate` call from the mesh: validation,
//! building, the decimation, the output assembled and checked), `keep_10pct_unverified`,
//! `keep_1pct_unverified` (the same with `skip_verify`), `passes_10pct`, `passes_1pct`
//! (the default options but `Schedule::Passes`, the fast option), so that one run gives
//! the two schedules' ratio. Run: `cargo bench --bench decimate` (about four minutes);
//! input triangles per second = the input's triangle count divided by the median.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::{Mutex, OnceLock};

use contractible::decimate::Schedule;
use contractible::gen::{isosurface, large_torus, Implicit, IsoParams, Tessellation};
use contractible::{decimate, DecimateOptions, TriMesh};

fn main() {
    divan::main();
}

const INPUTS: &[&str] = &[
    "bunny_npm",
    "high_genus_3",
    "letter",
    "sphere_1m",
    "large_torus_bcc",
];

/// The cells along the sphere's box for about a million triangles.
const SPHERE_RESOLUTION: u32 = 236;

/// The input mesh, read or generated once per process.
fn input(name: &str) -> &'static TriMesh {
    static CACHE: OnceLock<Mutex<HashMap<String, &'static TriMesh>>> = OnceLock::new();
    let cache = CACHE.get_or_init(Default::default);
    let mut map = cache.lock().expect("no poisoned lock");
    map.entry(name.to_string()).or_insert_with(|| {
        let mesh = match name {
            "sphere_1m" => isosurface(&IsoParams::new(
                Implicit::Sphere { radius: 1.0 },
                Tessellation::SixTetrahedra,
                SPHERE_RESOLUTION,
            ))
            .expect("a valid sphere"),
            "large_torus_bcc" => {
                isosurface(&large_torus(Tessellation::BodyCentred)).expect("the preset is valid")
            }
            file => {
                let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                    .join("tests/data/meshes/closed")
                    .join(format!("{file}.off.gz"));
                contractible::io::read_tri_mesh(&path)
                    .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
            }
        };
        eprintln!("{name}: {} triangles", mesh.faces.len());
        Box::leak(Box::new(mesh))
    })
}

fn run(b: divan::Bencher, name: &str, keep: f64, skip_verify: bool) {
    run_with(b, name, keep, skip_verify, Schedule::Exact);
}

fn run_with(b: divan::Bencher, name: &str, keep: f64, skip_verify: bool, schedule: Schedule) {
    let mesh = input(name);
    let opts = DecimateOptions {
        skip_verify,
        schedule,
        ..DecimateOptions::keep(keep)
    };
    b.bench_local(|| decimate(mesh, &opts).expect("a valid surface"));
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn keep_10pct(b: divan::Bencher, name: &str) {
    run(b, name, 0.1, false);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn keep_1pct(b: divan::Bencher, name: &str) {
    run(b, name, 0.01, false);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn keep_10pct_unverified(b: divan::Bencher, name: &str) {
    run(b, name, 0.1, true);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn keep_1pct_unverified(b: divan::Bencher, name: &str) {
    run(b, name, 0.01, true);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn passes_10pct(b: divan::Bencher, name: &str) {
    run_with(b, name, 0.1, false, Schedule::Passes);
}

#[divan::bench(args = INPUTS, sample_count = 5, sample_size = 1)]
fn passes_1pct(b: divan::Bencher, name: &str) {
    run_with(b, name, 0.01, false, Schedule::Passes);
}
