//! The core's local operations against independent checks: the naive link condition,
//! from-scratch validation, and the published small surfaces of `tests/data/irreducible`.

use crate::common;

use contractible::gen::{random, seed_surface, RandomParams, SurfaceKind};
use contractible::rng::Rng;
use contractible::{ContractError, History, LinkTester, Triangulation, VertexId};

const T4: [[u32; 3]; 4] = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];

fn all_edges(t: &Triangulation) -> Vec<(VertexId, VertexId)> {
    t.edges().map(|(a, b, _)| (a, b)).collect()
}

#[test]
fn tetrahedron_is_irreducible_and_never_collapses_to_a_pillow() {
    let mut t = Triangulation::from_faces(4, &T4).unwrap();
    t.validate().unwrap();
    assert_eq!(t.euler_characteristic(), 2);
    assert!(t.is_tetrahedron());
    assert!(t.is_irreducible());
    assert!(t.is_irreducible_naive());
    let before = t.clone();
    let mut h = History::new();
    for (a, b) in all_edges(&t) {
        assert!(
            !t.link_condition_naive(a, b),
            "T4 edge {a}-{b} passes the naive test"
        );
        assert!(!t.is_contractible(a, b));
        for (u, v) in [(a, b), (b, a)] {
            assert_eq!(
                t.contract(u, v, &mut h),
                Err(ContractError::NotContractible { u, v })
            );
        }
        assert!(!t.is_flippable(a, b), "T4 edges are not flippable either");
    }
    assert_eq!(t, before, "refused contractions must not change anything");
    assert!(h.is_empty());
}

#[test]
fn small_surfaces_irreducible_or_reducible_as_published() {
    let list = common::read_surface_list("surfaces-upto-8-vertices.txt");
    assert_eq!(list.len(), 57);
    for s in list {
        let t = Triangulation::from_faces(s.vertex_count, &s.faces)
            .unwrap_or_else(|e| panic!("{}: {e}", s.name));
        t.validate().unwrap();
        let (chi, orientable) = match &s.name[..2] {
            "S0" => (2, true),
            "S1" => (0, true),
            "N1" => (1, false),
            "N2" => (0, false),
            other => panic!("unknown surface code {other}"),
        };
        assert_eq!(t.euler_characteristic(), chi, "{}", s.name);
        assert_eq!(t.is_orientable(), orientable, "{}", s.name);
        let irr = s.name.contains("_irr_");
        assert_eq!(t.is_irreducible_naive(), irr, "{} naive", s.name);
        assert_eq!(t.is_irreducible(), irr, "{} marked", s.name);
        // Both link tests agree on every edge, in both directions.
        let mut lt = LinkTester::new(t.vertex_capacity());
        for (a, b) in all_edges(&t) {
            let naive = t.link_condition_naive(a, b);
            assert_eq!(naive, t.link_condition_naive(b, a));
            assert_eq!(naive, lt.test(&t, a, b), "{} edge {a}-{b}", s.name);
            assert_eq!(naive, lt.test(&t, b, a), "{} edge {b}-{a}", s.name);
        }
    }
}

#[test]
fn published_torus_and_projective_plane_lists_are_irreducible() {
    for (file, count, chi, orientable) in [
        ("torus.txt", 21, 0, true),
        ("projective-plane.txt", 2, 1, false),
    ] {
        let list = common::read_surface_list(file);
        assert_eq!(list.len(), count);
        for s in list {
            let t = Triangulation::from_faces(s.vertex_count, &s.faces).unwrap();
            t.validate().unwrap();
            assert_eq!(t.euler_characteristic(), chi);
            assert_eq!(t.is_orientable(), orientable);
            assert!(t.is_irreducible_naive(), "{}", s.name);
            assert!(t.is_irreducible(), "{}", s.name);
        }
    }
}

fn surfaces() -> Vec<SurfaceKind> {
    let mut v: Vec<SurfaceKind> = (0..=5).map(SurfaceKind::Orientable).collect();
    v.extend((1..=4).map(SurfaceKind::NonOrientable));
    v
}

#[test]
fn seed_surfaces_have_the_right_topology() {
    for s in surfaces() {
        let t = seed_surface(s).expect("a seed surface within the limits");
        t.validate().unwrap();
        assert_eq!(t.euler_characteristic(), s.euler_characteristic(), "{s:?}");
        assert_eq!(
            t.is_orientable(),
            matches!(s, SurfaceKind::Orientable(_)),
            "{s:?}"
        );
    }
}

/// A random edge `(u, v)` by the documented stream: face, then slot, then direction.
fn random_edge(t: &Triangulation, rng: &mut Rng) -> (VertexId, VertexId) {
    let faces: Vec<_> = t.faces().collect();
    let f = faces[rng.index(faces.len())];
    let [a, b] = t.edge_endpoints(f.corner(rng.index(3) as u32));
    if rng.chance(1, 2) {
        (a, b)
    } else {
        (b, a)
    }
}

#[test]
fn contractions_undo_exactly_and_preserve_topology() {
    for (k, s) in surfaces().into_iter().enumerate() {
        for seed in 0..3u64 {
            let input = random(&RandomParams {
                surface: s,
                min_faces: 150,
                flip_percent: 30,
                seed,
            })
            .expect("a random surface within the limits");
            input.validate().unwrap();
            let chi = input.euler_characteristic();
            let orientable = input.is_orientable();
            let mut t = input.clone();
            let mut h = History::new();
            let mut rng = Rng::new(1000 * k as u64 + seed);
            let mut lt = LinkTester::new(t.vertex_capacity());
            for _ in 0..400 {
                let (u, v) = random_edge(&t, &mut rng);
                let naive = t.link_condition_naive(u, v);
                assert_eq!(naive, lt.test(&t, u, v), "{s:?} edge {u}-{v}");
                let r = t.contract(u, v, &mut h);
                assert_eq!(r.is_ok(), naive);
                if r.is_ok() {
                    t.validate()
                        .unwrap_or_else(|e| panic!("{s:?} after contracting {u}-{v}: {e}"));
                    assert_eq!(t.euler_characteristic(), chi);
                    assert_eq!(t.is_orientable(), orientable);
                }
                if t.is_irreducible() {
                    break;
                }
            }
            assert!(!h.is_empty());
            while let Some(r) = h.undo(&mut t) {
                assert!(t.is_vertex(r.v));
            }
            assert_eq!(
                t, input,
                "{s:?} seed {seed}: undo did not restore the input exactly"
            );
        }
    }
}

#[test]
fn random_splits_flips_contractions_keep_every_invariant() {
    for (k, s) in surfaces().into_iter().enumerate() {
        let mut t = random(&RandomParams {
            surface: s,
            min_faces: 60,
            flip_percent: 0,
            seed: k as u64,
        })
        .expect("a random surface within the limits");
        let chi = t.euler_characteristic();
        let orientable = t.is_orientable();
        let mut rng = Rng::new(77 + k as u64);
        let mut h = History::new();
        for step in 0..300 {
            match rng.index(3) {
                0 => {
                    let (u, v) = random_edge(&t, &mut rng);
                    let _ = t.contract(u, v, &mut h);
                }
                1 => {
                    let vs: Vec<_> = t.vertices().collect();
                    let u = vs[rng.index(vs.len())];
                    let link: Vec<_> = t.link(u).collect();
                    let i = rng.index(link.len());
                    let j = (i + 1 + rng.index(link.len() - 1)) % link.len();
                    let v = t.split_vertex(u, link[i], link[j]).unwrap();
                    assert!(t.link_condition_naive(u, v) || t.is_tetrahedron());
                    assert_eq!(
                        t.edge_link(u, v).map(|mut l| {
                            l.sort();
                            l
                        }),
                        Some({
                            let mut l = [link[i], link[j]];
                            l.sort();
                            l
                        })
                    );
                }
                _ => {
                    let (u, v) = random_edge(&t, &mut rng);
                    let [w, z] = t.edge_link(u, v).unwrap();
                    let flippable = !t.has_edge(w, z);
                    assert_eq!(t.is_flippable(u, v), flippable);
                    if flippable {
                        let faces_in = sorted_faces(&t);
                        t.flip(u, v).unwrap();
                        t.validate().unwrap();
                        assert!(t.has_edge(w, z) && !t.has_edge(u, v));
                        // Flipping back restores the same face set.
                        let mut t2 = t.clone();
                        t2.flip(w, z).unwrap();
                        assert_eq!(sorted_faces(&t2), faces_in);
                    } else {
                        assert!(t.flip(u, v).is_err());
                    }
                }
            }
            // Contractions recorded before a split or flip can no longer be undone by
            // the history; keep the history to the current run of contractions.
            h = History::new();
            t.validate()
                .unwrap_or_else(|e| panic!("{s:?} step {step}: {e}"));
            assert_eq!(t.euler_characteristic(), chi);
            assert_eq!(t.is_orientable(), orientable);
        }
    }
}

fn sorted_faces(t: &Triangulation) -> Vec<[u32; 3]> {
    let mut f: Vec<[u32; 3]> = t
        .face_list()
        .into_iter()
        .map(|mut x| {
            x.sort();
            x
        })
        .collect();
    f.sort();
    f
}

/// Whether the face list is consistently oriented, from the faces alone: no directed
/// edge `a → b` is used by two faces (so each edge is run once each way).
fn consistently_oriented(t: &Triangulation) -> bool {
    let mut seen = std::collections::HashSet::new();
    t.face_list()
        .iter()
        .all(|f| (0..3).all(|k| seen.insert((f[k], f[(k + 1) % 3]))))
}

/// A consistently oriented input stays consistently oriented under random contractions,
/// vertex splits and edge flips (checked from the face list after every operation).
#[test]
fn orientation_is_preserved_by_contractions_splits_and_flips() {
    let mut t = random(&RandomParams {
        surface: SurfaceKind::Orientable(2),
        min_faces: 500,
        flip_percent: 50,
        seed: 3,
    })
    .expect("a random surface within the limits");
    assert!(consistently_oriented(&t), "random() output");
    let mut h = History::new();
    let mut rng = Rng::new(5);
    let mut done = [0usize; 3];
    for _ in 0..600 {
        let (u, v) = random_edge(&t, &mut rng);
        let kind = rng.index(3);
        let ok = match kind {
            0 => t.contract(u, v, &mut h).is_ok(),
            1 => {
                let link: Vec<VertexId> = t.link(u).collect();
                let x = link[rng.index(link.len())];
                let y = link[rng.index(link.len())];
                x != y && t.split_vertex(u, x, y).is_ok()
            }
            _ => t.flip(u, v).is_ok(),
        };
        if ok {
            done[kind] += 1;
            assert!(consistently_oriented(&t), "after operation kind {kind}");
        }
    }
    assert!(done.iter().all(|&n| n >= 50), "operations done: {done:?}");
    t.validate().unwrap();
    let o = t.orientation().unwrap();
    let live: Vec<bool> = t.faces().map(|f| o[f.index()]).collect();
    assert!(live.iter().all(|&x| x == live[0]));
}

/// `is_coherent` says whether the stored faces are consistently oriented, as the
/// directed edges of the face list tell; `is_orientable` and `orientation` agree with it
/// and with the surface's kind, on random surfaces with random faces reversed and after
/// contractions (removed faces in the table).
#[test]
fn coherence_and_orientation_agree_with_the_directed_edges() {
    let mut rng = Rng::new(11);
    let mut coherent = [0usize; 2];
    for kind in surfaces() {
        let t0 = random(&RandomParams {
            surface: kind,
            min_faces: 120,
            flip_percent: 30,
            seed: rng.next_u64(),
        })
        .expect("a random surface within the limits");
        let orientable = matches!(kind, SurfaceKind::Orientable(_));
        for trial in 0..12 {
            let mut faces = t0.face_list();
            for f in faces.iter_mut() {
                if trial % 2 == 1 && rng.chance(1, 2 * trial) {
                    f.swap(0, 1);
                }
            }
            let mut t = Triangulation::from_faces(t0.vertex_capacity(), &faces).expect("surface");
            if trial % 3 == 2 {
                let mut h = History::new();
                for _ in 0..20 {
                    let live: Vec<VertexId> = t.vertices().collect();
                    let u = live[rng.index(live.len())];
                    let v = t.link(u).next().expect("a neighbour");
                    let _ = t.contract(u, v, &mut h);
                }
            }
            let want = consistently_oriented(&t);
            assert_eq!(t.is_coherent(), want, "{kind:?} trial {trial}");
            coherent[usize::from(want)] += 1;
            assert_eq!(t.is_orientable(), orientable, "{kind:?} trial {trial}");
            match t.orientation() {
                Some(flip) => {
                    let fixed: Vec<[u32; 3]> = t
                        .faces()
                        .map(|f| {
                            let mut g = t.face_vertices(f).map(|v| v.0);
                            if flip[f.index()] {
                                g.swap(0, 1);
                            }
                            g
                        })
                        .collect();
                    let mut seen = std::collections::HashSet::new();
                    assert!(fixed
                        .iter()
                        .all(|g| (0..3).all(|k| seen.insert((g[k], g[(k + 1) % 3])))));
                }
                None => assert!(!orientable),
            }
        }
    }
    assert!(coherent[0] > 10 && coherent[1] > 5, "{coherent:?}");
}

/// The contraction record stays compact (RS keeps one per contraction: 2.1 M on B0), and
/// its undo, the only reader of the compacted fields, restores every surface exactly.
#[test]
fn contraction_records_are_compact_and_undo_exactly() {
    assert_eq!(std::mem::size_of::<contractible::ContractionRecord>(), 88);
    for kind in surfaces() {
        let t0 = random(&RandomParams {
            surface: kind,
            min_faces: 400,
            flip_percent: 20,
            seed: 7,
        })
        .expect("a random surface within the limits");
        let mut t = t0.clone();
        let mut h = History::new();
        for (u, v) in all_edges(&t0) {
            if t.is_vertex(u) && t.is_vertex(v) {
                let _ = t.contract(u, v, &mut h);
            }
        }
        assert!(!h.records().is_empty(), "{kind:?}: nothing contracted");
        h.undo_all(&mut t);
        assert_eq!(t, t0, "{kind:?}: undo did not restore the surface");
    }
}
