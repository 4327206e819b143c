//! The history replay: every algorithm's contractions pass; each step's verdict agrees
//! with the core's naive link condition on random walks; each kind of wrong history is
//! named with its step.

use super::tests::{kinds, random};
use super::*;
use crate::gen::{self, SurfaceKind};
use crate::irreducible::Algorithm;
use crate::rng::Rng;
use crate::{reduce as run_reduce, ReduceOptions, Triangulation, VertexId};

fn surfaces() -> Vec<(&'static str, TriMesh)> {
    let torus = random(SurfaceKind::Orientable(1), 120, 5);
    let octahedron = gen::octahedron();
    // Two components: the torus's ids after the octahedron's.
    let shift = octahedron.vertex_count as u32;
    let mut faces = octahedron.faces.clone();
    faces.extend(torus.faces.iter().map(|f| f.map(|v| v + shift)));
    vec![
        ("icosahedron", gen::icosahedron()),
        ("genus 2", random(SurfaceKind::Orientable(2), 400, 2)),
        (
            "projective plane",
            random(SurfaceKind::NonOrientable(1), 200, 3),
        ),
        (
            "klein bottle",
            random(SurfaceKind::NonOrientable(2), 300, 4),
        ),
        (
            "two components",
            TriMesh::combinatorial(octahedron.vertex_count + torus.vertex_count, faces),
        ),
    ]
}

/// A reduction's output in the input's vertex ids, and its contractions.
fn reduced(mesh: &TriMesh, algorithm: Algorithm, seed: u64) -> (TriMesh, Vec<[u32; 2]>) {
    let options = ReduceOptions {
        algorithm,
        seed,
        ..ReduceOptions::default()
    };
    let r = run_reduce(mesh, &options).expect("reduces");
    let faces = (r.mesh.faces.iter())
        .map(|f| f.map(|v| r.vertex_map[v as usize]))
        .collect();
    (
        TriMesh::combinatorial(mesh.vertex_count, faces),
        r.contractions(),
    )
}

fn first(v: &Verdict) -> (FailureKind, &str) {
    (v.failures[0].kind, v.failures[0].message.as_str())
}

#[test]
fn every_algorithm_s_contractions_replay_to_its_output() {
    for (name, mesh) in surfaces() {
        for (algorithm, seed) in [
            (Algorithm::Rs, 0),
            (Algorithm::Schipper, 0),
            (Algorithm::Brute, 7),
        ] {
            let (out, history) = reduced(&mesh, algorithm, seed);
            assert!(!history.is_empty(), "{name}");
            let v = reduce_history(&mesh, &out, &history).unwrap();
            assert!(v.passed(), "{name} {algorithm:?}: {:?}", v.failures);
        }
    }
}

#[test]
fn each_step_s_verdict_is_the_core_s_naive_link_condition() {
    // Random walks: each step names a random edge of the surface as it is; the replay
    // must accept it exactly when the core's naive link condition does (and then both
    // contract it, in the core by `contract`).
    let mut rng = Rng::new(11);
    let (mut accepted, mut refused) = (0, 0);
    for (name, mesh) in surfaces()
        .into_iter()
        .filter(|(n, _)| *n != "two components")
    {
        for walk in 0..6 {
            let mut tri = Triangulation::from_faces(mesh.vertex_count, &mesh.faces).unwrap();
            let mut steps: Vec<[u32; 2]> = Vec::new();
            let mut store = crate::History::new();
            for _ in 0..60 {
                let edges: Vec<(VertexId, VertexId)> =
                    tri.edges().map(|(a, b, _)| (a, b)).collect();
                let (a, b) = edges[rng.below(edges.len() as u64) as usize];
                let (u, v) = if rng.below(2) == 0 { (a, b) } else { (b, a) };
                let step = [u.index() as u32, v.index() as u32];
                let mut candidate = steps.clone();
                candidate.push(step);
                let mut verdict = Verdict::new("reduce");
                history::replay(mesh.vertex_count, &mesh.faces, &candidate, &mut verdict);
                let naive = tri.link_condition_naive(u, v);
                assert_eq!(
                    verdict.passed(),
                    naive,
                    "{name}, walk {walk}, step {}: {step:?} {:?}",
                    steps.len(),
                    verdict.failures
                );
                if naive {
                    tri.contract(u, v, &mut store).unwrap();
                    steps = candidate;
                    accepted += 1;
                } else {
                    assert_eq!(first(&verdict).0, FailureKind::InvalidHistory);
                    refused += 1;
                }
            }
            // The walk's end is the core's surface: the replay must end there too.
            let out = TriMesh::combinatorial(mesh.vertex_count, tri.face_list());
            let mut verdict = Verdict::new("reduce");
            let end = history::replay(mesh.vertex_count, &mesh.faces, &steps, &mut verdict);
            history::compare(&end.unwrap().faces, &out.faces, steps.len(), &mut verdict);
            assert!(
                verdict.passed(),
                "{name}, walk {walk}: {:?}",
                verdict.failures
            );
        }
    }
    // Both answers were exercised many times.
    assert!(accepted > 300 && refused > 100, "{accepted} {refused}");
}

#[test]
fn wrong_histories_are_named_with_their_step() {
    let sphere = gen::icosahedron();
    let (out, history) = reduced(&sphere, Algorithm::Rs, 0);
    let with = |h: &[[u32; 2]]| reduce_history(&sphere, &out, h).unwrap();

    // A step that names a vertex an earlier step removed.
    let mut h = history.clone();
    h.insert(1, history[0]);
    let v = with(&h);
    assert_eq!(first(&v).0, FailureKind::InvalidHistory);
    assert!(
        first(&v).1.contains("was removed by step 0"),
        "{}",
        first(&v).1
    );

    // Out of range, a vertex with itself.
    let v = with(&[[0, 12]]);
    assert!(
        first(&v).1.contains("beyond the input's 12 vertices"),
        "{}",
        first(&v).1
    );
    let v = with(&[[3, 3]]);
    assert!(first(&v).1.contains("with itself"), "{}", first(&v).1);

    // Two vertices of the icosahedron that share no edge.
    let tri = Triangulation::from_faces(sphere.vertex_count, &sphere.faces).unwrap();
    let far = (1..12u32)
        .find(|&w| tri.find_edge(VertexId(0), VertexId(w)).is_none())
        .unwrap();
    let v = with(&[[0, far]]);
    assert!(first(&v).1.contains("is no edge"), "{}", first(&v).1);
    assert_eq!(v.counts.len(), 1, "the first wrong step ends the replay");

    // Too few steps, or the ends of a step swapped: the replay ends elsewhere.
    let v = with(&history[..history.len() - 1]);
    assert_eq!(kinds(&v), vec![FailureKind::HistoryMismatch]);
    let mut h = history.clone();
    let last = h.len() - 1;
    h[last] = [h[last][1], h[last][0]];
    let v = with(&h);
    assert_eq!(kinds(&v), vec![FailureKind::HistoryMismatch]);
    // Each face of the difference is named: on the output's side with its index.
    assert!(v.failures.iter().any(|f| f.face.is_some()));
    assert!(v.failures.iter().any(|f| f.face.is_none()));
}

#[test]
fn the_link_condition_refuses_a_common_neighbour_and_the_tetrahedron() {
    // An irreducible torus: every edge's ends have a third common neighbour.
    let torus = random(SurfaceKind::Orientable(1), 200, 1);
    let (irreducible, _) = reduced(&torus, Algorithm::Rs, 0);
    let [a, b, _] = irreducible.faces[0];
    let v = reduce_history(&irreducible, &irreducible, &[[a, b]]).unwrap();
    assert_eq!(first(&v).0, FailureKind::InvalidHistory);
    assert!(first(&v).1.contains("common neighbour"), "{}", first(&v).1);

    // The tetrahedron: the ends' common neighbours are the opposite vertices, but the
    // edge between those is in both links.
    let t4 = TriMesh::combinatorial(4, vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [0, 2, 3]]);
    let v = reduce_history(&t4, &t4, &[[0, 1]]).unwrap();
    assert_eq!(first(&v).0, FailureKind::InvalidHistory);
    assert!(first(&v).1.contains("tetrahedron"), "{}", first(&v).1);
    // And the empty history of an irreducible input replays to itself.
    assert!(reduce_history(&t4, &t4, &[]).unwrap().passed());
}

#[test]
fn a_valid_history_to_a_wrong_output_fails_on_both_counts() {
    let sphere = gen::octahedron();
    let (mut out, history) = reduced(&sphere, Algorithm::Rs, 0);
    assert!(reduce_history(&sphere, &out, &history).unwrap().passed());
    out.faces.swap(0, 1);
    let f = out.faces[0];
    out.faces[0] = [f[1], f[2], f[0]];
    assert!(
        reduce_history(&sphere, &out, &history).unwrap().passed(),
        "face order and each face's first corner are free"
    );
    // The input itself as the output: reducible, and not where the steps lead.
    let v = reduce_history(&sphere, &sphere, &history).unwrap();
    assert_eq!(
        kinds(&v),
        vec![FailureKind::ContractibleEdge, FailureKind::HistoryMismatch]
    );
    // Without the steps, only the first.
    let v = reduce_history(&sphere, &sphere, &[]).unwrap();
    assert_eq!(kinds(&v), vec![FailureKind::ContractibleEdge]);
}

#[test]
fn an_output_on_the_survivors_in_input_order_is_read_so() {
    // As `reduce` writes its output: the survivors renumbered in increasing input order.
    // With every position the same (a mesh without geometry), matching by position
    // cannot tell the vertices apart; the replay's survivors can.
    let torus = random(SurfaceKind::Orientable(1), 300, 9);
    for positions in [None, Some(vec![[0.0; 3]; torus.vertex_count])] {
        let input = TriMesh {
            positions: positions.clone(),
            ..torus.clone()
        };
        let r = run_reduce(&input, &ReduceOptions::default()).unwrap();
        let history = r.contractions();
        let v = reduce_history(&input, &r.mesh, &history).unwrap();
        assert!(v.passed(), "{:?}", v.failures);
        if positions.is_some() {
            // -0.0 where the input has 0.0: the same positions.
            let mut minus = r.mesh.clone();
            for p in minus.positions.as_mut().unwrap() {
                *p = [-0.0; 3];
            }
            let v = reduce_history(&input, &minus, &history).unwrap();
            assert!(v.passed(), "{:?}", v.failures);
        }
        // One step fewer: the survivors are one more than the output's vertices, so the
        // output is read by position (or by id) and the replay does not end there.
        let v = reduce_history(&input, &r.mesh, &history[1..]).unwrap();
        assert!(!v.passed());
    }
}

#[test]
fn coincident_vertices_of_one_component_are_matched_one_to_one() {
    // The 7-vertex torus (irreducible) with vertices 2 and 6 at one position, answered
    // by itself on a vertex list of its own (an unused eighth vertex, vertices 0 and 1
    // swapped): matched by position, each of the two coincident output vertices must get
    // its own input vertex, or the faces in input ids are not the input's.
    let mut input = gen::torus7();
    let p = input.positions.as_mut().unwrap();
    p[6] = p[2];
    let mut positions = input.positions.clone().unwrap();
    positions.swap(0, 1);
    positions.push([9.0, 9.0, 9.0]);
    let swap = |v: u32| match v {
        0 => 1,
        1 => 0,
        v => v,
    };
    let output = TriMesh {
        vertex_count: 8,
        positions: Some(positions),
        faces: input.faces.iter().map(|f| f.map(swap)).collect(),
    };
    let v = reduce_history(&input, &output, &[]).unwrap();
    assert!(v.passed(), "{:?}", v.failures);
}

#[test]
fn an_output_on_the_survivors_in_another_order_is_read_by_position() {
    // Distinct positions; the reduction written with its vertex list reversed: as many
    // vertices as survivors, but not in increasing input order, so read by position.
    let torus = random(SurfaceKind::Orientable(1), 300, 9);
    let positions: Vec<[f64; 3]> = (0..torus.vertex_count)
        .map(|v| [v as f64, (v * v % 17) as f64, 0.5])
        .collect();
    let input = TriMesh::with_positions(positions, torus.faces.clone());
    let r = run_reduce(&input, &ReduceOptions::default()).unwrap();
    let n = r.mesh.vertex_count as u32;
    let mut reversed = r.mesh.clone();
    reversed.positions.as_mut().unwrap().reverse();
    for f in &mut reversed.faces {
        *f = f.map(|v| n - 1 - v);
    }
    let v = reduce_history(&input, &reversed, &r.contractions()).unwrap();
    assert!(v.passed(), "{:?}", v.failures);
}

/// The comparison walks both sorted face lists to their ends and names each face found on
/// one side only, once, on its own side: in the middle of the order and after the other
/// list has ended.
#[test]
fn each_face_on_one_side_only_is_named_once_on_its_side() {
    let (a, b, c, z) = ([0, 1, 2], [0, 1, 3], [0, 2, 3], [4, 5, 6]);
    let run = |ours: &[[u32; 3]], theirs: &[[u32; 3]]| {
        let mut v = Verdict::new("reduce");
        history::compare(ours, theirs, 7, &mut v);
        assert!(v
            .failures
            .iter()
            .all(|f| f.kind == FailureKind::HistoryMismatch));
        v.failures
            .iter()
            .map(|f| (f.face, f.message.contains("the output does not have")))
            .collect::<Vec<_>>()
    };
    // Equal lists, the output's in another order and with other first corners.
    assert_eq!(run(&[a, b, c], &[[2, 3, 0], a, [3, 0, 1]]), vec![]);
    // An output face between two of the replay's (given last, so located as face 2).
    assert_eq!(run(&[a, c], &[a, c, b]), vec![(Some(2), false)]);
    // A replay face between two of the output's.
    assert_eq!(run(&[a, b, c], &[c, a]), vec![(None, true)]);
    // A replay face after the output's last.
    assert_eq!(run(&[a, b, z], &[b, a]), vec![(None, true)]);
    // An output face after the replay's last.
    assert_eq!(run(&[a, b], &[z, a, b]), vec![(Some(0), false)]);
    // Only one side.
    assert_eq!(run(&[], &[a, b]), vec![(Some(0), false), (Some(1), false)]);
    assert_eq!(run(&[a, b], &[]), vec![(None, true), (None, true)]);
}
