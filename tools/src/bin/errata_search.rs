//! The search that found the witnesses of errata E1 and E4 (`spec/ERRATA.md`): RS with a
//! printed form of the pseudo-code — `e4`: the loop exit of Alg. 4.2 l.34
//! (`Variant::printed_loop_exit`); `e1`: the strict stamp of Alg. 4.3 l.13
//! (`Variant::printed_strict_stamp`) — on random small surfaces (genus 1–4, cross-caps
//! 1–4, 20–170 faces) under random vertex orders.
//!
//! A run fails when a specification check fires (built with `--features invariants`)
//! or, with the checks compiled out, when the output is reducible by the naive test. The first failure is shrunk by contracting
//! edges (keeping the relative vertex order) while it keeps failing, then printed.
//! Deterministic: the inputs come from the documented RNG stream of seed 12345.
//!
//! ```text
//! cargo run --release -p contractible-tools --features invariants,mutation-tests --bin errata_search -- e4 180
//! cargo run --release -p contractible-tools --features mutation-tests --bin errata_search -- e4 600
//! cargo run --release -p contractible-tools --features mutation-tests --bin errata_search -- e1 240
//! cargo run --release -p contractible-tools --features mutation-tests --bin errata_search -- e1 240 orientable
//! ```
//!
//! The feature `mutation-tests` makes the library's printed variants public; only this
//! tool requires it, so the package's other tools build the library as its users do.
use std::panic::{catch_unwind, AssertUnwindSafe};

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::rs::{reduce_variant, Variant};
use contractible::irreducible::Options;
use contractible::rng::Rng;
use contractible::{History, Triangulation};

/// The printed variant named by the first argument.
fn printed() -> Variant {
    match std::env::args().nth(1).as_deref() {
        Some("e1") => Variant {
            printed_strict_stamp: true,
            ..Variant::default()
        },
        Some("e4") => Variant {
            printed_loop_exit: true,
            ..Variant::default()
        },
        _ => {
            eprintln!("usage: errata_search e1|e4 [SECONDS]");
            std::process::exit(2)
        }
    }
}

fn main() {
    // Failures are expected panics; keep the output to the summary.
    std::panic::set_hook(Box::new(|_| {}));
    printed(); // validates the argument before searching
    let secs: u64 = std::env::args()
        .nth(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    // Optional third argument: `orientable` or `non-orientable` restricts the surfaces.
    let only = match std::env::args().nth(3).as_deref() {
        None => None,
        Some("orientable") => Some(true),
        Some("non-orientable") => Some(false),
        Some(other) => {
            eprintln!("unknown surface filter {other:?} (orientable | non-orientable)");
            std::process::exit(2)
        }
    };
    let start = std::time::Instant::now();
    let mut runs = 0u64;
    let mut rng = Rng::new(12345);
    while start.elapsed().as_secs() < secs {
        let k = rng.below(8) as u32;
        let surface = if k < 4 {
            SurfaceKind::Orientable(k + 1)
        } else {
            SurfaceKind::NonOrientable(k - 3)
        };
        if only.is_some_and(|o| o != matches!(surface, SurfaceKind::Orientable(_))) {
            continue;
        }
        let t = random(&RandomParams {
            surface,
            min_faces: 20 + rng.below(150) as usize,
            flip_percent: rng.below(100) as u32,
            seed: rng.below(1 << 40),
        })
        .expect("a random surface within the limits");
        let faces = t.face_list();
        let n = t.vertex_capacity();
        for _ in 0..50 {
            let mut perm: Vec<u32> = (0..n as u32).collect();
            rng.shuffle(&mut perm);
            let relabelled: Vec<[u32; 3]> =
                faces.iter().map(|f| f.map(|x| perm[x as usize])).collect();
            runs += 1;
            if fails(&relabelled) {
                println!("failure after {runs} runs: {surface:?}, {n} vertices");
                let m = shrink(relabelled);
                let v = m.iter().flatten().max().map_or(0, |&x| x + 1);
                println!("shrunk to {v} vertices, {} faces: {m:?}", m.len());
                return;
            }
        }
    }
    println!("no failure in {runs} runs");
}

/// Whether the printed variant fails on `faces` (a check fires or the output is
/// reducible).
fn fails(faces: &[[u32; 3]]) -> bool {
    let n = faces.iter().flatten().max().map_or(0, |&m| m as usize + 1);
    let Ok(t) = Triangulation::from_faces(n, faces) else {
        return false;
    };
    match catch_unwind(AssertUnwindSafe(|| {
        reduce_variant(t, &Options::default(), printed())
    })) {
        Err(_) => true,
        Ok((r, _)) => !r.tri.is_irreducible_naive(),
    }
}

/// Greedily contracts edges (first that keeps the failure, repeat) until none does.
fn shrink(mut faces: Vec<[u32; 3]>) -> Vec<[u32; 3]> {
    'outer: loop {
        let n = faces.iter().flatten().max().map_or(0, |&m| m as usize + 1);
        let Ok(t) = Triangulation::from_faces(n, &faces) else {
            return faces;
        };
        let edges: Vec<_> = t.edges().map(|(a, b, _)| (a, b)).collect();
        for (a, b) in edges {
            for (x, y) in [(a, b), (b, a)] {
                let mut smaller = t.clone();
                if smaller.contract(x, y, &mut History::new()).is_ok() {
                    // Renumbered 0..V keeping the relative vertex order, which RS follows.
                    let f = smaller.to_mesh().faces;
                    if fails(&f) {
                        faces = f;
                        continue 'outer;
                    }
                }
            }
        }
        return faces;
    }
}
