//! The checker on right and wrong answers; its link test against the core's naive
//! predicate, and its surface analysis against the core's validation.

use super::*;
use crate::gen::{self, RandomParams, SurfaceKind};
use crate::{reduce as run_reduce, ReduceOptions, Triangulation};

pub(super) fn kinds(v: &Verdict) -> Vec<FailureKind> {
    let mut k: Vec<FailureKind> = v.counts.iter().map(|&(k, _)| k).collect();
    k.sort_unstable();
    k
}

pub(super) fn random(kind: SurfaceKind, faces: usize, seed: u64) -> TriMesh {
    let t = gen::random(&RandomParams {
        surface: kind,
        min_faces: faces,
        flip_percent: 30,
        seed,
    })
    .expect("a random surface");
    TriMesh::combinatorial(t.vertex_capacity(), t.face_list())
}

/// Two meshes side by side (the second's ids after the first's).
fn union(a: &TriMesh, b: &TriMesh) -> TriMesh {
    let shift = a.vertex_count as u32;
    let mut faces = a.faces.clone();
    faces.extend(b.faces.iter().map(|f| f.map(|v| v + shift)));
    let positions = match (&a.positions, &b.positions) {
        (Some(p), Some(q)) => Some(p.iter().chain(q).copied().collect()),
        _ => None,
    };
    TriMesh {
        vertex_count: a.vertex_count + b.vertex_count,
        positions,
        faces,
    }
}

/// Our reduction in the input's vertex ids and positions (as the protocol's answers
/// are written when there are no positions to match by).
fn reduced(mesh: &TriMesh) -> TriMesh {
    let r = run_reduce(mesh, &ReduceOptions::default()).expect("reduces");
    let faces = r
        .mesh
        .faces
        .iter()
        .map(|f| f.map(|v| r.vertex_map[v as usize]))
        .collect();
    TriMesh {
        vertex_count: mesh.vertex_count,
        positions: mesh.positions.clone(),
        faces,
    }
}

fn surfaces() -> Vec<(&'static str, TriMesh)> {
    vec![
        ("icosahedron", gen::icosahedron()),
        ("torus", random(SurfaceKind::Orientable(1), 200, 1)),
        ("genus 3", random(SurfaceKind::Orientable(3), 300, 2)),
        (
            "projective plane",
            random(SurfaceKind::NonOrientable(1), 150, 3),
        ),
        (
            "klein bottle",
            random(SurfaceKind::NonOrientable(2), 200, 4),
        ),
        (
            "two components",
            union(
                &gen::octahedron(),
                &random(SurfaceKind::Orientable(1), 120, 5),
            ),
        ),
    ]
}

#[test]
fn reductions_pass_and_their_inputs_fail_as_reducible() {
    for (name, mesh) in surfaces() {
        let v = reduce(&mesh, &reduced(&mesh)).expect("a closed input");
        assert!(v.passed(), "{name}: {:?}", v.failures);
        // Our own output as written (compacted): matched by position where there are
        // positions.
        if mesh.positions.is_some() {
            let r = run_reduce(&mesh, &ReduceOptions::default()).expect("reduces");
            assert!(reduce(&mesh, &r.mesh).expect("closed").passed(), "{name}");
        }
        let v = reduce(&mesh, &mesh).expect("a closed input");
        assert_eq!(kinds(&v), [FailureKind::ContractibleEdge], "{name}");
        assert!(v
            .failures
            .iter()
            .all(|f| f.edge.is_some() && f.face.is_some()));
    }
}

#[test]
fn the_contractible_edges_are_the_core_naive_predicates() {
    // Partly reduced surfaces (some edges contractible, some not) by the core's own
    // contraction, judged by both.
    for seed in 0..12u64 {
        let kind = [
            SurfaceKind::Orientable(0),
            SurfaceKind::Orientable(2),
            SurfaceKind::NonOrientable(3),
        ][seed as usize % 3];
        let mesh = random(kind, 60 + 10 * seed as usize, 100 + seed);
        let mut t = Triangulation::from_faces(mesh.vertex_count, &mesh.faces).expect("closed");
        let mut rng = crate::rng::Rng::new(seed);
        let mut scratch = Vec::new();
        for _ in 0..(t.face_count() / 3) {
            let edges: Vec<_> = t
                .edges()
                .filter(|&(a, b, _)| t.link_condition_naive(a, b))
                .collect();
            if edges.is_empty() {
                break;
            }
            let (a, b, _) = edges[rng.below(edges.len() as u64) as usize];
            t.collapse(a, b, &mut scratch);
        }
        let out = TriMesh::combinatorial(t.vertex_capacity(), t.face_list());
        let naive = t
            .edges()
            .filter(|&(a, b, _)| t.link_condition_naive(a, b))
            .count();
        let v = reduce(&mesh, &out).expect("closed");
        let found = v
            .counts
            .iter()
            .find(|(k, _)| *k == FailureKind::ContractibleEdge)
            .map_or(0, |&(_, n)| n);
        assert_eq!(found, naive, "seed {seed}");
        assert_eq!(v.passed(), t.is_irreducible_naive(), "seed {seed}");
        assert_eq!(v.failures.len(), found.min(surface::LISTED), "seed {seed}");
    }
}

#[test]
fn the_tetrahedron_is_irreducible() {
    let tet = gen::tetrahedron();
    assert!(reduce(&tet, &tet).expect("closed").passed());
    // Two of them side by side too.
    let two = union(&tet, &tet);
    assert!(reduce(&two, &two).expect("closed").passed());
}

#[test]
fn wrong_surfaces_and_components_are_named() {
    let torus = random(SurfaceKind::Orientable(1), 200, 7);
    let r = reduced(&torus);
    // A tetrahedron on four of the torus's vertices: a sphere, not a torus.
    let v0 = r.faces[0];
    let w = r.faces.iter().flatten().copied().find(|x| !v0.contains(x));
    let w = w.expect("a fourth vertex");
    let [a, b, c] = v0;
    let tet = TriMesh::combinatorial(
        torus.vertex_count,
        vec![[a, b, c], [a, w, b], [b, w, c], [c, w, a]],
    );
    let v = reduce(&torus, &tet).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::SurfaceChanged]);
    assert_eq!(v.failures[0].component, Some(0));
    // Two components in, one out: the other is lost.
    let two = union(&gen::octahedron(), &torus);
    let r2 = reduced(&two);
    let first_only = TriMesh::combinatorial(two.vertex_count, r2.faces[..4].to_vec());
    let v = reduce(&two, &first_only).expect("closed");
    assert!(kinds(&v).contains(&FailureKind::ComponentLost), "{v:?}");
    // One component's output twice (a copy on other vertices of the same input
    // component is impossible here, so split: the same tetrahedron twice on disjoint
    // vertices of the torus).
    let verts: Vec<u32> = torus.faces.iter().flatten().copied().collect();
    let mut distinct = verts.clone();
    distinct.sort_unstable();
    distinct.dedup();
    let (p, q) = (&distinct[..4], &distinct[4..8]);
    let tet_on = |s: &[u32]| {
        vec![
            [s[0], s[1], s[2]],
            [s[0], s[3], s[1]],
            [s[1], s[3], s[2]],
            [s[2], s[3], s[0]],
        ]
    };
    let mut faces = tet_on(p);
    faces.extend(tet_on(q));
    let v = reduce(&torus, &TriMesh::combinatorial(torus.vertex_count, faces)).expect("closed");
    assert_eq!(
        kinds(&v),
        [FailureKind::ComponentSplit],
        "two sphere outputs for one torus: {v:?}"
    );
    // An output component across two input components.
    let oct = gen::octahedron();
    let two_oct = union(&oct, &oct);
    let across = TriMesh::combinatorial(12, vec![[0, 1, 6], [0, 7, 1], [1, 7, 6], [6, 7, 0]]);
    let v = reduce(&two_oct, &across).expect("closed");
    assert!(kinds(&v).contains(&FailureKind::ComponentsMerged), "{v:?}");
}

#[test]
fn defects_of_the_face_list_are_located() {
    let ico = gen::icosahedron();
    let tet = reduced(&ico).faces;
    // A face dropped: three boundary edges.
    let v = reduce(&ico, &TriMesh::combinatorial(12, tet[1..].to_vec())).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::BoundaryEdge]);
    assert_eq!(v.counts, [(FailureKind::BoundaryEdge, 3)]);
    // A face repeated.
    let mut rep = tet.clone();
    rep.push(tet[0]);
    let v = reduce(&ico, &TriMesh::combinatorial(12, rep)).expect("closed");
    assert_eq!(v.failures[0].kind, FailureKind::RepeatedFace);
    assert_eq!(v.failures[0].face, Some(4));
    // A degenerate face and a vertex out of range.
    let mut deg = tet.clone();
    deg[2] = [deg[2][0], deg[2][0], deg[2][1]];
    let v = reduce(&ico, &TriMesh::combinatorial(12, deg)).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::DegenerateFace]);
    assert_eq!(v.failures[0].face, Some(2));
    let v = reduce(&ico, &TriMesh::combinatorial(3, tet.clone())).expect("closed");
    assert!(kinds(&v).contains(&FailureKind::VertexOutOfRange), "{v:?}");
    // Three faces on one edge.
    let [a, b, _] = tet[0];
    let mut nm = tet.clone();
    let spare = (0..12)
        .find(|x| !tet.iter().flatten().any(|y| y == x))
        .expect("spare");
    nm.push([a, b, spare]);
    let v = reduce(&ico, &TriMesh::combinatorial(12, nm)).expect("closed");
    assert!(kinds(&v).contains(&FailureKind::NonManifoldEdge), "{v:?}");
    assert_eq!(
        v.failures
            .iter()
            .find(|f| f.kind == FailureKind::NonManifoldEdge)
            .and_then(|f| f.edge),
        Some([a.min(b), a.max(b)])
    );
    // Two tetrahedra sharing a vertex: a pinched vertex.
    let pinch = vec![
        [0, 1, 2],
        [0, 3, 1],
        [1, 3, 2],
        [2, 3, 0],
        [0, 4, 5],
        [0, 6, 4],
        [4, 6, 5],
        [5, 6, 0],
    ];
    let v = reduce(&ico, &TriMesh::combinatorial(12, pinch)).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::NonManifoldVertex]);
    assert_eq!(v.failures[0].vertex, Some(0));
}

#[test]
fn vertices_match_by_id_or_by_exact_position() {
    let ico = gen::icosahedron();
    let r = reduced(&ico);
    // Compacted, as another implementation may write it: matched by position.
    let (compact, dropped) = r.compacted().expect("consistent");
    assert_eq!(dropped, 8);
    assert!(reduce(&ico, &compact).expect("closed").passed());
    assert!(reduce(&ico, &r).expect("closed").passed());
    // A compacted output whose vertex moved: no input vertex there.
    let mut moved = compact.clone();
    if let Some(p) = moved.positions.as_mut() {
        p[1][0] += 1e-9;
    }
    let v = reduce(&ico, &moved).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::UnknownVertex]);
    assert_eq!(v.failures[0].vertex, Some(1));
    // −0 for +0 is no move, by id or by position (every icosahedron vertex has a zero
    // coordinate).
    for mesh in [r.clone(), compact.clone()] {
        let mut signed = mesh.clone();
        let mut flipped = 0;
        for p in signed.positions.as_mut().expect("positions") {
            for x in p.iter_mut().filter(|x| **x == 0.0) {
                *x = -0.0;
                flipped += 1;
            }
        }
        assert!(flipped >= 4);
        assert!(reduce(&ico, &signed).expect("closed").passed());
    }
    // The input's vertex list with one position changed: moved.
    let mut same = r.clone();
    let used = same.faces[0][0] as usize;
    if let Some(p) = same.positions.as_mut() {
        p[used][2] = 7.0;
    }
    let v = reduce(&ico, &same).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::MovedVertex]);
    assert_eq!(v.failures[0].vertex, Some(used as u32));
    // Two objects at the same positions (as trimesh's two_objects): each output
    // component goes to its own input component, whichever comes first in the file.
    let oct = gen::octahedron();
    let two = union(&oct, &oct);
    let p = oct.positions.clone().expect("positions");
    let mut positions = p.clone();
    positions.extend(p.iter().copied());
    positions.push([9.0, 9.0, 9.0]);
    let faces: Vec<[u32; 3]> = oct
        .faces
        .iter()
        .map(|f| f.map(|v| v + 6))
        .chain(oct.faces.iter().copied())
        .collect();
    let swapped = TriMesh::with_positions(positions, faces);
    let v = reduce(&two, &swapped).expect("closed");
    // Both octahedra are reducible; the matching itself is not what fails.
    assert_eq!(kinds(&v), [FailureKind::ContractibleEdge], "{v:?}");
    let r2 = reduced(&two);
    let (c2, _) = r2.compacted().expect("consistent");
    assert!(reduce(&two, &c2).expect("closed").passed());
    // Without positions and with more vertices than the input: nothing to match by.
    let bare = TriMesh::combinatorial(40, compact.faces.clone());
    let bare_in = TriMesh::combinatorial(12, ico.faces.clone());
    let v = reduce(&bare_in, &bare).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::UnknownVertex]);
}

#[test]
fn an_input_that_is_no_closed_surface_is_an_error() {
    let ico = gen::icosahedron();
    let open = TriMesh::combinatorial(12, ico.faces[1..].to_vec());
    assert!(matches!(
        reduce(&open, &ico),
        Err(Error::NotClosed {
            boundary_loops: Some(1),
            ..
        })
    ));
    let mut bad = ico.faces.clone();
    bad.push(ico.faces[0]);
    assert!(matches!(
        reduce(&TriMesh::combinatorial(12, bad), &ico),
        Err(Error::Mesh(_))
    ));
}

#[test]
fn the_surface_analysis_agrees_with_the_core() {
    for (name, mesh) in surfaces() {
        let a =
            analyse(mesh.vertex_count, &mesh.faces, "input").unwrap_or_else(|_| panic!("{name}"));
        let s = crate::Surfaces::from_mesh(&mesh).expect("closed");
        assert_eq!(a.parts.len(), s.components.len(), "{name}");
        for (p, c) in a.parts.iter().zip(&s.components) {
            let t = &c.tri;
            assert_eq!(p.euler(), t.euler_characteristic(), "{name}");
            assert_eq!(p.orientable, t.orientation().is_some(), "{name}");
            assert_eq!(p.boundary_loops, 0, "{name}");
        }
    }
    // A disc and an annulus: loops counted.
    let ico = gen::icosahedron();
    let a = analyse(12, &ico.faces[1..], "x").unwrap_or_else(|_| panic!("disc"));
    assert_eq!((a.parts[0].euler(), a.parts[0].boundary_loops), (1, 1));
    let far = ico
        .faces
        .iter()
        .position(|f| !f.iter().any(|v| ico.faces[0].contains(v)))
        .expect("a face away from face 0");
    let annulus: Vec<[u32; 3]> = ico
        .faces
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != 0 && i != far)
        .map(|(_, f)| *f)
        .collect();
    let a = analyse(12, &annulus, "x").unwrap_or_else(|_| panic!("annulus"));
    assert_eq!((a.parts[0].euler(), a.parts[0].boundary_loops), (0, 2));
}

#[test]
fn failure_kind_names_are_distinct_snake_case() {
    let names: Vec<&str> = FailureKind::ALL.iter().map(|k| k.name()).collect();
    for (k, n) in FailureKind::ALL.iter().zip(&names) {
        // The Debug form in snake case.
        let mut snake = String::new();
        for (i, ch) in format!("{k:?}").chars().enumerate() {
            if ch.is_ascii_uppercase() && i > 0 {
                snake.push('_');
            }
            snake.push(ch.to_ascii_lowercase());
        }
        assert_eq!(*n, snake);
    }
    let mut sorted = names.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), names.len());
}

/// A tetrahedron inscribed in a cube, on four of its corners, as two components; the
/// tetrahedron's vertices first (ids 0..4) or the cube's.
fn tetrahedron_in_a_cube(tetrahedron_first: bool) -> TriMesh {
    let corners: Vec<[f64; 3]> = (0..8)
        .map(|i| [f64::from(i & 1), f64::from((i >> 1) & 1), f64::from(i >> 2)])
        .collect();
    let cube: Vec<[u32; 3]> = vec![
        [0, 2, 3],
        [0, 3, 1],
        [4, 5, 7],
        [4, 7, 6],
        [0, 1, 5],
        [0, 5, 4],
        [2, 6, 7],
        [2, 7, 3],
        [0, 4, 6],
        [0, 6, 2],
        [1, 3, 7],
        [1, 7, 5],
    ];
    // Corners 0, 3, 5, 6: no two on an edge of the cube.
    let tet_at = [0usize, 3, 5, 6];
    let tet: Vec<[u32; 3]> = vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]];
    let tet_pos: Vec<[f64; 3]> = tet_at.iter().map(|&c| corners[c]).collect();
    let (first, second, first_faces, second_faces) = if tetrahedron_first {
        (tet_pos, corners, tet, cube)
    } else {
        (corners, tet_pos, cube, tet)
    };
    let shift = first.len() as u32;
    let mut positions = first;
    positions.extend(second);
    let mut faces = first_faces;
    faces.extend(second_faces.iter().map(|f| f.map(|v| v + shift)));
    TriMesh::with_positions(positions, faces)
}

#[test]
fn coincident_positions_go_to_the_component_most_vertices_agree_on() {
    for tetrahedron_first in [false, true] {
        let input = tetrahedron_in_a_cube(tetrahedron_first);
        let n = input.vertex_count;
        for reversed in [false, true] {
            // The input as its own answer, its vertex list reversed (so matched by
            // position) and its components in either order.
            let pos = input.positions.clone().expect("positions");
            let mut positions: Vec<[f64; 3]> = pos.iter().rev().copied().collect();
            positions.push([7.0, 7.0, 7.0]);
            let mut faces: Vec<[u32; 3]> = input
                .faces
                .iter()
                .map(|f| f.map(|v| (n - 1) as u32 - v))
                .collect();
            if reversed {
                faces.reverse();
            }
            let answer = TriMesh::with_positions(positions, faces);
            let v = reduce(&input, &answer).expect("closed");
            // The cube is reducible; nothing else is wrong.
            assert_eq!(
                kinds(&v),
                [FailureKind::ContractibleEdge],
                "tetrahedron first {tetrahedron_first}, reversed {reversed}: {v:?}"
            );
        }
    }
}

#[test]
fn an_unused_input_vertex_at_a_used_ones_position_is_not_matched() {
    let oct = gen::octahedron();
    let mut positions = oct.positions.clone().expect("positions");
    // An unused vertex 0 at the position of (used) vertex 1 + 1 = the old vertex 0.
    positions.insert(0, positions[0]);
    let faces: Vec<[u32; 3]> = oct.faces.iter().map(|f| f.map(|v| v + 1)).collect();
    let input = TriMesh::with_positions(positions, faces);
    let (answer, _) = input.compacted().expect("consistent");
    let v = reduce(&input, &answer).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::ContractibleEdge], "{v:?}");
}

#[test]
fn the_component_most_vertices_agree_on_wins_even_unclaimed() {
    // A tetrahedron on four of an octahedron's vertices (component 0) and the
    // octahedron (component 1), answered by both, the octahedron first: the
    // octahedron's four shared vertices must go to component 1,
    // which six of its vertices agree on, though component 0 is free and first.
    let oct = gen::octahedron();
    let op = oct.positions.clone().expect("positions");
    let tet: Vec<[u32; 3]> = vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]];
    let mut positions: Vec<[f64; 3]> = op[..4].to_vec();
    positions.extend(op.iter().copied());
    let mut faces = tet;
    faces.extend(oct.faces.iter().map(|f| f.map(|v| v + 4)));
    let input = TriMesh::with_positions(positions.clone(), faces.clone());
    // One vertex more than the input (matched by position), the octahedron's faces
    // first; its shared vertices have the smaller ids, so they are tallied first.
    let mut answer_pos = positions.clone();
    answer_pos.push([7.0, 7.0, 7.0]);
    let mut answer_faces = faces.clone();
    answer_faces.rotate_left(4);
    let v = reduce(&input, &TriMesh::with_positions(answer_pos, answer_faces)).expect("closed");
    assert_eq!(kinds(&v), [FailureKind::ContractibleEdge], "{v:?}");
}

#[test]
fn an_output_vertex_at_an_unused_input_vertex_is_named_so() {
    let oct = gen::octahedron();
    let mut positions = oct.positions.clone().expect("positions");
    positions.push([5.0, 5.0, 5.0]);
    let input = TriMesh::with_positions(positions, oct.faces.clone());
    let mut moved = oct.clone();
    moved.positions.as_mut().expect("positions")[2] = [5.0, 5.0, 5.0];
    let v = reduce(&input, &moved).expect("closed");
    let f = v
        .failures
        .iter()
        .find(|f| f.kind == FailureKind::UnknownVertex)
        .expect("an unknown vertex");
    assert_eq!(f.vertex, Some(2));
    assert!(f.message.contains("no input face uses"), "{}", f.message);
}

#[test]
fn absorbed_reasons_add_to_the_counts_of_their_kind() {
    let mut v = Verdict::new("quad");
    v.fail(Failure::new(FailureKind::RepeatedFace, "one".into()));
    let failures = vec![
        Failure::new(FailureKind::RepeatedFace, "two".into()),
        Failure::new(FailureKind::DegenerateFace, "three".into()),
    ];
    v.absorb(
        failures,
        vec![
            (FailureKind::RepeatedFace, 5),
            (FailureKind::DegenerateFace, 2),
        ],
    );
    assert_eq!(
        v.counts,
        vec![
            (FailureKind::RepeatedFace, 6),
            (FailureKind::DegenerateFace, 2)
        ]
    );
    let messages: Vec<&str> = v.failures.iter().map(|f| f.message.as_str()).collect();
    assert_eq!(messages, ["one", "two", "three"]);
}

#[test]
fn minus_zero_and_zero_are_one_position() {
    // The output keeps the input's vertex list, with -0.0 where the input has 0.0 (and
    // the reverse): the same positions, no vertex moved.
    let input = gen::icosahedron();
    let out = reduced(&input);
    let mut flipped = out.clone();
    let positions = flipped.positions.as_mut().expect("positions");
    let mut zeros = 0;
    for p in positions.iter_mut() {
        for x in p.iter_mut() {
            if *x == 0.0 {
                *x = if x.is_sign_negative() { 0.0 } else { -0.0 };
                zeros += 1;
            }
        }
    }
    assert!(zeros > 0, "the icosahedron has zero coordinates");
    assert_eq!(reduce(&input, &out).unwrap().failures, vec![]);
    assert_eq!(reduce(&input, &flipped).unwrap().failures, vec![]);
    // The input with -0.0, the output with 0.0.
    let minus_input = TriMesh {
        positions: flipped.positions.clone(),
        ..input.clone()
    };
    assert_eq!(reduce(&minus_input, &out).unwrap().failures, vec![]);
    // A real move is still one.
    positions_of(&mut flipped)[out.faces[0][0] as usize][0] += 1e-12;
    assert_eq!(
        kinds(&reduce(&input, &flipped).unwrap()),
        vec![FailureKind::MovedVertex]
    );
}

fn positions_of(m: &mut TriMesh) -> &mut Vec<[f64; 3]> {
    m.positions.as_mut().expect("positions")
}

#[test]
fn a_vertex_only_another_component_still_has_is_read_as_that_component_s() {
    // Two tetrahedra touching at one point: vertex 0 of the first and vertex 4 of the
    // second share a position. The answer, a bipyramid on the first's positions with
    // both apexes at that point, has two vertices there; the first component has one
    // vertex there, so the second apex is the second component's vertex: the answer
    // joins the two components (and leaves the second without an output of its own).
    let p = |x: f64, y: f64, z: f64| [x, y, z];
    let tet = |o: u32| {
        [
            [o, o + 1, o + 2],
            [o, o + 3, o + 1],
            [o + 1, o + 3, o + 2],
            [o, o + 2, o + 3],
        ]
    };
    let mut faces = tet(0).to_vec();
    faces.extend(tet(4));
    let input = TriMesh::with_positions(
        vec![
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, 0.0, 1.0),
            p(0.0, 0.0, 0.0),
            p(-1.0, 0.0, 0.0),
            p(0.0, -1.0, 0.0),
            p(0.0, 0.0, -1.0),
        ],
        faces,
    );
    // Bipyramid: apexes 0 and 1 (both at the shared point), equator 2, 3, 4.
    let output = TriMesh::with_positions(
        vec![
            p(0.0, 0.0, 0.0),
            p(0.0, 0.0, 0.0),
            p(1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, 0.0, 1.0),
        ],
        vec![
            [0, 2, 3],
            [0, 3, 4],
            [0, 4, 2],
            [1, 3, 2],
            [1, 4, 3],
            [1, 2, 4],
        ],
    );
    let v = reduce(&input, &output).unwrap();
    assert!(
        kinds(&v).contains(&FailureKind::ComponentsMerged),
        "{:?}",
        v.failures
    );
}
