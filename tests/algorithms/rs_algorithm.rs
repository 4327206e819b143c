//! The RS algorithm against independent checks: naive irreducibility, topology, exact
//! expansion, ℓ ≤ E and ε = 0, Sec. 4.6 for genus 0.

use crate::common;

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::rs::{reduce_variant, Variant};
use contractible::irreducible::{reduce, Algorithm, Options};
use contractible::Triangulation;

fn check_rs(input: &Triangulation, what: &str) {
    // Count retests (off by default): ε = 0 below is only meaningful with them counted.
    let opts = Options {
        count_retests: true,
        ..Options::default()
    };
    let (r, first) = reduce_variant(input.clone(), &opts, Variant::default());
    let t = &r.tri;
    t.validate().unwrap();
    assert!(t.is_irreducible_naive(), "{what}: RS output is reducible");
    assert_eq!(
        t.euler_characteristic(),
        input.euler_characteristic(),
        "{what}"
    );
    assert_eq!(t.is_orientable(), input.is_orientable(), "{what}");
    let h = t.euler_genus();
    if h == 0 {
        assert!(t.is_tetrahedron(), "{what}: genus 0 must give T4");
        assert_eq!(
            first, r.stats.contractions,
            "{what}: Sec. 4.6, all contractions in the first vertex"
        );
    } else {
        assert!(
            t.vertex_count() as i64 <= 13 * h - 4,
            "{what}: {} vertices > 13h-4",
            t.vertex_count()
        );
    }
    assert!(
        r.stats.link_tests <= r.stats.edges_in as u64,
        "{what}: ℓ = {} > E = {}",
        r.stats.link_tests,
        r.stats.edges_in
    );
    assert_eq!(
        r.stats.edges_tested_more_than_once, 0,
        "{what}: ε_RS must be 0"
    );
    assert_eq!(
        r.stats.contractions as usize,
        r.stats.vertices_in - r.stats.vertices_out
    );
    assert_eq!(
        &r.expand(),
        input,
        "{what}: expanding the history must give the input back"
    );
}

#[test]
fn rs_on_random_surfaces() {
    for g in 0..=8 {
        for seed in 0..4 {
            let t = random(&RandomParams {
                surface: SurfaceKind::Orientable(g),
                min_faces: 300 + 200 * g as usize,
                flip_percent: 30,
                seed,
            })
            .expect("a random surface within the limits");
            check_rs(&t, &format!("genus {g} seed {seed}"));
        }
    }
    for h in 1..=6 {
        for seed in 0..4 {
            let t = random(&RandomParams {
                surface: SurfaceKind::NonOrientable(h),
                min_faces: 300 + 150 * h as usize,
                flip_percent: 30,
                seed,
            })
            .expect("a random surface within the limits");
            check_rs(&t, &format!("euler genus {h} (non-orientable) seed {seed}"));
        }
    }
}

#[test]
fn rs_on_the_small_surfaces() {
    for file in [
        "surfaces-upto-8-vertices.txt",
        "torus.txt",
        "projective-plane.txt",
    ] {
        for s in common::read_surface_list(file) {
            let t = Triangulation::from_faces(s.vertex_count, &s.faces).unwrap();
            check_rs(&t, &s.name);
            let r = reduce(t.clone(), Algorithm::Rs, &Options::default());
            if s.name.contains("_irr_") || file != "surfaces-upto-8-vertices.txt" {
                assert_eq!(r.stats.contractions, 0, "{}: irreducible input", s.name);
            }
        }
    }
}

/// The ε counter is not vacuous: on the same inputs where RS keeps ε = 0, Schipper's
/// algorithm and the brute force re-test edges (ε > 0), so a re-testing RS would show.
#[test]
fn retest_counter_sees_the_retests_of_schipper_and_brute_force() {
    let opts = Options {
        seed: 5,
        count_retests: true,
        keep_history: true,
    };
    let mut seen = [0u64; 3];
    for (k, surface) in [SurfaceKind::Orientable(2), SurfaceKind::NonOrientable(3)]
        .into_iter()
        .enumerate()
    {
        let t = random(&RandomParams {
            surface,
            min_faces: 3000,
            flip_percent: 30,
            seed: k as u64,
        })
        .expect("a random surface within the limits");
        for (i, alg) in [Algorithm::Rs, Algorithm::Schipper, Algorithm::Brute]
            .into_iter()
            .enumerate()
        {
            seen[i] += reduce(t.clone(), alg, &opts)
                .stats
                .edges_tested_more_than_once;
        }
    }
    assert_eq!(seen[0], 0, "ε_RS");
    assert!(seen[1] > 0 && seen[2] > 0, "ε_S, ε_BF = {seen:?}");
}

/// RS on small surfaces under many vertex orders (the space in which erratum E4 showed:
/// `tools/src/bin/errata_search.rs`): every output irreducible by the naive test, same χ and
/// orientability, ε = 0, with the specification checks on (Definition 4 included).
#[test]
fn small_surfaces_under_many_vertex_orders() {
    use contractible::rng::Rng;
    let mut rng = Rng::new(2026);
    let opts = Options {
        seed: 0,
        count_retests: true,
        keep_history: true,
    };
    let mut runs = 0;
    for k in 0..80u32 {
        let surface = if k % 2 == 0 {
            SurfaceKind::Orientable(1 + k % 4)
        } else {
            SurfaceKind::NonOrientable(1 + k % 4)
        };
        let t = random(&RandomParams {
            surface,
            min_faces: 20 + rng.below(150) as usize,
            flip_percent: rng.below(100) as u32,
            seed: u64::from(k),
        })
        .expect("a random surface within the limits");
        let n = t.vertex_capacity();
        for _ in 0..25 {
            let mut perm: Vec<u32> = (0..n as u32).collect();
            rng.shuffle(&mut perm);
            let faces: Vec<[u32; 3]> = t
                .face_list()
                .iter()
                .map(|f| f.map(|x| perm[x as usize]))
                .collect();
            let input = Triangulation::from_faces(n, &faces).expect("relabelled");
            let r = reduce(input.clone(), Algorithm::Rs, &opts);
            assert!(r.tri.is_irreducible_naive(), "{surface:?} k={k}");
            assert_eq!(
                (r.tri.euler_characteristic(), r.tri.is_orientable()),
                (input.euler_characteristic(), input.is_orientable())
            );
            assert_eq!(r.stats.edges_tested_more_than_once, 0);
            runs += 1;
        }
    }
    assert_eq!(runs, 2000);
}

/// Without its history, each algorithm gives the same surface and the same counters
/// (the contraction count included), with an empty history; with it, the history has
/// one record per contraction and expands back to the input. The task call likewise.
#[test]
fn dropping_the_history_changes_nothing_else() {
    for (k, surface) in [
        SurfaceKind::Orientable(0),
        SurfaceKind::Orientable(2),
        SurfaceKind::NonOrientable(3),
    ]
    .into_iter()
    .enumerate()
    {
        let input = random(&RandomParams {
            surface,
            min_faces: 300,
            flip_percent: 20,
            seed: 40 + k as u64,
        })
        .expect("small surface");
        for algorithm in common::ALL {
            let with = Options {
                seed: 3,
                count_retests: true,
                keep_history: true,
            };
            let without = Options {
                keep_history: false,
                ..with
            };
            let a = reduce(input.clone(), algorithm, &with);
            let b = reduce(input.clone(), algorithm, &without);
            assert_eq!(a.tri, b.tri, "{algorithm:?}");
            let mut sb = b.stats.clone();
            sb.seconds = a.stats.seconds;
            assert_eq!(a.stats, sb, "{algorithm:?}");
            assert!(a.stats.contractions > 100, "{algorithm:?}: a weak test");
            assert_eq!(a.history.len() as u64, a.stats.contractions);
            assert!(b.history.is_empty(), "{algorithm:?}");
            assert_eq!(a.expand(), input, "{algorithm:?}");
        }
    }
    let mesh = contractible::gen::icosahedron();
    let keep = contractible::reduce(&mesh, &Default::default()).expect("a sphere");
    let drop = contractible::reduce(
        &mesh,
        &contractible::ReduceOptions {
            keep_history: false,
            ..Default::default()
        },
    )
    .expect("a sphere");
    assert_eq!(keep.mesh, drop.mesh);
    assert_eq!(keep.totals.contractions, drop.totals.contractions);
    assert_eq!(keep.components[0].reduction.history.len(), 8);
    assert!(drop.components[0].reduction.history.is_empty());
}
