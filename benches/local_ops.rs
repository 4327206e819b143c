//! Local operations cost what their degrees say, not what the surface size says: 10⁵
//! random `is_contractible` tests, each followed by `contract_at` when it passes (and the
//! exact undo, so every sample sees the same surface), on a 10k-triangle surface and on
//! the 4.2M-triangle brick B0. With no hidden O(V) work the per-call cost is the same on
//! both. A second benchmark runs the "test, then contract" loop of a simplifier: 10⁵
//! calls on B0 without undo.
//!
//! Run: `cargo bench --bench local_ops`. Divan reports medians (and items/s: one item is
//! one test-and-maybe-contract call).

use contractible::gen::{paper_family, random, RandomParams, SurfaceKind};
use contractible::rng::Rng;
use contractible::{Corner, History, Triangulation};
use std::sync::OnceLock;

const CALLS: usize = 100_000;

fn small() -> &'static Triangulation {
    static T: OnceLock<Triangulation> = OnceLock::new();
    T.get_or_init(|| {
        random(&RandomParams {
            surface: SurfaceKind::Orientable(3),
            min_faces: 10_000,
            flip_percent: 30,
            seed: 1,
        })
        .expect("a random surface within the limits")
    })
}

fn b0() -> &'static Triangulation {
    static T: OnceLock<Triangulation> = OnceLock::new();
    T.get_or_init(|| {
        let m = paper_family('B', 0).expect("valid brick parameters");
        Triangulation::from_faces(m.vertex_count, &m.faces).expect("B0 is a surface")
    })
}

fn surface(size: &str) -> &'static Triangulation {
    match size {
        "10k" => small(),
        _ => b0(),
    }
}

fn main() {
    for size in ["10k", "4M"] {
        let t = surface(size);
        eprintln!(
            "{size}: {} vertices, {} faces",
            t.vertex_count(),
            t.face_count()
        );
    }
    divan::main();
}

/// A live corner, uniformly among the face slots (retrying removed faces).
fn live_corner(t: &Triangulation, rng: &mut Rng) -> Corner {
    loop {
        let c = Corner(rng.index(3 * t.face_capacity()) as u32);
        if t.is_face(c.face()) {
            return c;
        }
    }
}

/// 10⁵ × (random edge, `is_contractible`, `contract_at` if it passes, exact undo).
#[divan::bench(args = ["10k", "4M"], sample_count = 7)]
fn test_contract_undo(b: divan::Bencher, size: &str) {
    let t = surface(size);
    b.counter(divan::counter::ItemsCount::new(CALLS))
        .with_inputs(|| (t.clone(), History::new()))
        .bench_local_values(|(mut t, mut h)| {
            let mut rng = Rng::new(7);
            let mut contracted = 0usize;
            for _ in 0..CALLS {
                let c = live_corner(&t, &mut rng);
                let [a, b] = t.edge_endpoints(c);
                if t.is_contractible(a, b) && t.contract_at(c, &mut h).is_ok() {
                    contracted += 1;
                    h.undo(&mut t);
                }
            }
            (contracted, t)
        });
}

/// 10⁵ × (random edge, `is_contractible`, `contract_at` if it passes) on B0, no undo.
#[divan::bench(sample_count = 7)]
fn test_then_contract_b0(b: divan::Bencher) {
    let t = b0();
    b.counter(divan::counter::ItemsCount::new(CALLS))
        .with_inputs(|| (t.clone(), History::new()))
        .bench_local_values(|(mut t, mut h)| {
            let mut rng = Rng::new(11);
            for _ in 0..CALLS {
                let c = live_corner(&t, &mut rng);
                let [a, b] = t.edge_endpoints(c);
                if t.is_contractible(a, b) {
                    let _ = t.contract_at(c, &mut h);
                }
            }
            (t, h)
        });
}
