//! The three irreducible-triangulation algorithms (RS, Schipper, brute force) against
//! checks that share nothing with the code under test: irreducibility by the naive link
//! condition on every output edge, from-scratch validation, topology, the Joret–Wood
//! bound, exact expansion back to the input, the published lists of irreducible
//! triangulations of the torus and projective plane (up to isomorphism), and
//! determinism.
//!
//! Every test runs each algorithm of `common::algorithms`: all three by default; set
//! `CONTRACTIBLE_TEST_ALGORITHMS` (comma-separated `rs`, `schipper`, `brute`) to
//! restrict the run. The checks themselves are `common::check`.

use crate::common;

use common::{algorithms, check, options};
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::{reduce, Algorithm, Options, Reduction, Stats};
use contractible::rng::Rng;
use contractible::{Triangulation, VertexId};

fn run(input: &Triangulation, alg: Algorithm, seed: u64, label: &str) -> Reduction {
    let r = reduce(input.clone(), alg, &options(seed));
    check(input, &r, alg, label);
    r
}

fn random_surfaces() -> Vec<SurfaceKind> {
    let mut v: Vec<SurfaceKind> = (0..=8).map(SurfaceKind::Orientable).collect();
    v.extend((1..=6).map(SurfaceKind::NonOrientable));
    v
}

#[test]
fn random_surfaces_reduce_to_irreducible_triangulations_of_the_same_surface() {
    for alg in algorithms() {
        for (k, surface) in random_surfaces().into_iter().enumerate() {
            for (seed, min_faces, flip_percent) in
                [(1u64, 200, 0), (2, 1200, 30), (3, 3000, 10), (4, 6000, 50)]
            {
                let input = random(&RandomParams {
                    surface,
                    min_faces,
                    flip_percent,
                    seed: 100 * k as u64 + seed,
                })
                .expect("a random surface within the limits");
                let label = format!("{surface:?} seed {seed} F={}", input.face_count());
                run(&input, alg, seed, &label);
            }
        }
    }
}

fn surface_code(name: &str) -> (i64, bool) {
    match &name[..2] {
        "S0" => (2, true),
        "S1" => (0, true),
        "N1" => (1, false),
        "N2" => (0, false),
        other => panic!("unknown surface code {other}"),
    }
}

/// Whether `t` is isomorphic to one of `list`.
fn on_list(t: &Triangulation, list: &[common::NamedSurface]) -> Option<String> {
    let faces = t.face_list();
    list.iter()
        .find(|s| common::is_isomorphic(&faces, &s.faces))
        .map(|s| s.name.clone())
}

#[test]
fn small_surfaces_are_reduced_as_their_published_labels_say() {
    let torus = common::read_surface_list("torus.txt");
    let rp2 = common::read_surface_list("projective-plane.txt");
    let list = common::read_surface_list("surfaces-upto-8-vertices.txt");
    assert_eq!(list.len(), 57);
    for alg in algorithms() {
        for s in &list {
            let input = Triangulation::from_faces(s.vertex_count, &s.faces).unwrap();
            let (chi, orientable) = surface_code(&s.name);
            assert_eq!(input.euler_characteristic(), chi, "{}", s.name);
            assert_eq!(input.is_orientable(), orientable, "{}", s.name);
            for seed in 0..3 {
                let r = run(&input, alg, seed, &s.name);
                if s.name.contains("_irr_") {
                    assert_eq!(r.stats.contractions, 0, "{} {}", alg.name(), s.name);
                    assert!(r.tri == input, "{} {}", alg.name(), s.name);
                } else {
                    assert!(s.name.contains("_red_"), "{}", s.name);
                    assert!(r.stats.contractions > 0, "{} {}", alg.name(), s.name);
                }
                let published = match &s.name[..2] {
                    "S1" => Some(&torus),
                    "N1" => Some(&rp2),
                    _ => None,
                };
                if let Some(published) = published {
                    assert!(
                        on_list(&r.tri, published).is_some(),
                        "{} {}: output is on no published list",
                        alg.name(),
                        s.name
                    );
                }
            }
        }
        for (list, chi, orientable) in [(&torus, 0, true), (&rp2, 1, false)] {
            for s in list.iter() {
                let input = Triangulation::from_faces(s.vertex_count, &s.faces).unwrap();
                assert_eq!(input.euler_characteristic(), chi);
                assert_eq!(input.is_orientable(), orientable);
                let r = run(&input, alg, 0, &s.name);
                assert_eq!(r.stats.contractions, 0, "{} {}", alg.name(), s.name);
                assert!(r.tri == input, "{} {}", alg.name(), s.name);
            }
        }
    }
}

/// `count` random vertex splits of `t` (vertex, then two distinct link positions).
fn split_randomly(t: &mut Triangulation, count: usize, rng: &mut Rng) {
    for _ in 0..count {
        let vs: Vec<VertexId> = t.vertices().collect();
        let u = vs[rng.index(vs.len())];
        let link: Vec<VertexId> = t.link(u).collect();
        let i = rng.index(link.len());
        let j = (i + 1 + rng.index(link.len() - 1)) % link.len();
        t.split_vertex(u, link[i], link[j]).unwrap();
    }
}

#[test]
fn torus_and_projective_plane_reduce_onto_the_published_lists() {
    let torus = common::read_surface_list("torus.txt");
    let rp2 = common::read_surface_list("projective-plane.txt");
    assert_eq!((torus.len(), rp2.len()), (21, 2));
    for alg in algorithms() {
        let mut reached = std::collections::BTreeSet::new();
        for (surface, list) in [
            (SurfaceKind::Orientable(1), &torus),
            (SurfaceKind::NonOrientable(1), &rp2),
        ] {
            // Random inputs grown from the generator's seed surfaces.
            for seed in 0..8u64 {
                let input = random(&RandomParams {
                    surface,
                    min_faces: 60 + 250 * seed as usize,
                    flip_percent: 25 * (seed % 3) as u32,
                    seed: 7000 + seed,
                })
                .expect("a random surface within the limits");
                let label = format!("{surface:?} seed {seed}");
                let r = run(&input, alg, seed, &label);
                let name = on_list(&r.tri, list)
                    .unwrap_or_else(|| panic!("{} {label}: output on no list", alg.name()));
                reached.insert(name);
            }
            // Vertex splits of every published triangulation.
            for (k, s) in list.iter().enumerate() {
                for (splits, seed) in [(1usize, 1u64), (5, 2), (40, 3)] {
                    let mut input = Triangulation::from_faces(s.vertex_count, &s.faces).unwrap();
                    let mut rng = Rng::new(1000 * k as u64 + seed);
                    split_randomly(&mut input, splits, &mut rng);
                    let label = format!("{} + {splits} splits", s.name);
                    let r = run(&input, alg, seed, &label);
                    let name = on_list(&r.tri, list)
                        .unwrap_or_else(|| panic!("{} {label}: output on no list", alg.name()));
                    reached.insert(name);
                }
            }
        }
        // Not every published triangulation need be reached, but more than one must be
        // (the splits of the 10-vertex torus cannot all land on the 7-vertex one).
        assert!(
            reached.len() > 2,
            "{}: reached only {reached:?}",
            alg.name()
        );
    }
}

fn without_time(s: &Stats) -> Stats {
    Stats {
        seconds: 0.0,
        ..s.clone()
    }
}

#[test]
fn same_input_and_seed_give_identical_results() {
    for alg in algorithms() {
        for surface in [
            SurfaceKind::Orientable(0),
            SurfaceKind::Orientable(3),
            SurfaceKind::NonOrientable(3),
        ] {
            let input = random(&RandomParams {
                surface,
                min_faces: 2000,
                flip_percent: 20,
                seed: 11,
            })
            .expect("a random surface within the limits");
            let a = reduce(input.clone(), alg, &options(5));
            let b = reduce(input.clone(), alg, &options(5));
            assert!(a.tri == b.tri, "{} {surface:?}: outputs differ", alg.name());
            assert!(a.history == b.history, "{} {surface:?}", alg.name());
            assert_eq!(without_time(&a.stats), without_time(&b.stats));
            // Turning ε counting off changes nothing but ε.
            let c = reduce(
                input.clone(),
                alg,
                &Options {
                    seed: 5,
                    count_retests: false,
                    keep_history: true,
                },
            );
            assert!(c.tri == a.tri && c.history == a.history, "{}", alg.name());
            assert_eq!(c.stats.edges_tested_more_than_once, 0);
            assert_eq!(
                without_time(&c.stats),
                Stats {
                    edges_tested_more_than_once: 0,
                    ..without_time(&a.stats)
                }
            );
            if alg == Algorithm::Brute {
                // The seed drives the shuffle: another seed, another contraction order.
                let d = reduce(input.clone(), alg, &options(6));
                check(&input, &d, alg, "seed 6");
                assert!(
                    d.history != a.history,
                    "brute force ignores its seed on {surface:?}"
                );
            }
        }
    }
}

#[test]
fn isomorphism_helper_separates_the_published_lists() {
    let torus = common::read_surface_list("torus.txt");
    for (i, a) in torus.iter().enumerate() {
        for (j, b) in torus.iter().enumerate() {
            assert_eq!(
                common::is_isomorphic(&a.faces, &b.faces),
                i == j,
                "{} vs {}",
                a.name,
                b.name
            );
        }
    }
    // A relabelled mirror image with shuffled faces is isomorphic; removing one face
    // breaks it, and so does replacing one vertex of one face.
    let mut rng = Rng::new(3);
    for s in &torus {
        let mut perm: Vec<u32> = (0..s.vertex_count as u32).collect();
        rng.shuffle(&mut perm);
        let mut faces: Vec<[u32; 3]> = s
            .faces
            .iter()
            .map(|f| {
                [
                    perm[f[0] as usize],
                    perm[f[2] as usize],
                    perm[f[1] as usize],
                ]
            })
            .collect();
        rng.shuffle(&mut faces);
        assert!(common::is_isomorphic(&s.faces, &faces), "{}", s.name);
        assert!(!common::is_isomorphic(&s.faces, &faces[1..]), "{}", s.name);
        let mut broken = faces.clone();
        let w = (0..s.vertex_count as u32)
            .find(|w| !broken[0].contains(w))
            .unwrap();
        broken[0][0] = w;
        assert!(!common::is_isomorphic(&s.faces, &broken), "{}", s.name);
    }
}
