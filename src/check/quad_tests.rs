//! The `quad` checker on right and wrong answers, and against a brute-force reading of
//! its definition (some choice of one diagonal per quad partitions the faces).

use super::tests::{kinds, random};
use super::*;
use crate::gen::{self, SurfaceKind};
use crate::quad::Algorithm;
use crate::rng::Rng;
use crate::{quadrangulate, QuadOptions, QuadResult};

fn surfaces() -> Vec<(&'static str, TriMesh)> {
    vec![
        ("tetrahedron", gen::tetrahedron()),
        ("icosahedron", gen::icosahedron()),
        ("torus", random(SurfaceKind::Orientable(1), 200, 11)),
        ("genus 2", random(SurfaceKind::Orientable(2), 300, 12)),
        (
            "projective plane",
            random(SurfaceKind::NonOrientable(1), 150, 13),
        ),
        (
            "klein bottle",
            random(SurfaceKind::NonOrientable(2), 200, 14),
        ),
    ]
}

fn convert(mesh: &TriMesh, algorithm: Algorithm) -> QuadResult {
    quadrangulate(
        mesh,
        &QuadOptions {
            algorithm,
            ..QuadOptions::default()
        },
    )
    .expect("converts")
}

fn stated(r: &QuadResult) -> QuadCheck<'_> {
    QuadCheck {
        triangles: Some(&r.triangles),
        pairs: Some(&r.pairs),
    }
}

#[test]
fn every_algorithms_answer_passes_with_and_without_its_statements() {
    for (name, mesh) in surfaces() {
        for algorithm in Algorithm::ALL {
            let r = convert(&mesh, algorithm);
            let full = quad(&mesh, &r.mesh, &stated(&r)).expect("a closed input");
            assert!(full.passed(), "{name} {algorithm:?}: {:?}", full.failures);
            let k_only = QuadCheck {
                triangles: Some(&r.triangles),
                pairs: None,
            };
            assert!(quad(&mesh, &r.mesh, &k_only).expect("closed").passed());
            // Without K the quads must be pairs of input faces: true exactly when no
            // edge was flipped.
            let bare = quad(&mesh, &r.mesh, &QuadCheck::default()).expect("closed");
            let flipped = r.triangles != mesh.faces;
            assert_eq!(bare.passed(), !flipped, "{name} {algorithm:?}");
            if flipped {
                assert!(bare
                    .counts
                    .iter()
                    .any(|&(k, _)| k == FailureKind::QuadNotTwoTriangles));
            }
        }
    }
}

#[test]
fn a_flipping_conversion_is_judged_on_its_stated_triangulation() {
    // LRS flips edges on some inputs: find one and show both verdicts.
    let flipped = (0..40u64)
        .map(|seed| {
            random(
                SurfaceKind::Orientable(1 + (seed % 3) as u32),
                120,
                100 + seed,
            )
        })
        .map(|m| {
            let r = convert(&m, Algorithm::Lrs);
            (m, r)
        })
        .find(|(m, r)| r.triangles != m.faces);
    let (mesh, r) = flipped.expect("LRS flips an edge on one of 40 random surfaces");
    assert!(quad(&mesh, &r.mesh, &stated(&r)).expect("closed").passed());
    let v = quad(&mesh, &r.mesh, &QuadCheck::default()).expect("closed");
    assert!(kinds(&v).contains(&FailureKind::QuadNotTwoTriangles));
    assert!(kinds(&v).contains(&FailureKind::TriangleUnused));
}

#[test]
fn a_flipped_edge_whose_two_faces_are_paired_gives_the_input_quad_back() {
    // The octahedron's faces [0 2 4] and [2 1 4] share [2, 4]; flipped, K has [0 2 1] and
    // [0 1 4] instead. Pairing those two gives the cycle 0 2 1 4, which is also the quad
    // of the two input faces: the answer passes with K and without it.
    let mesh = gen::octahedron();
    let find = |t: [u32; 3]| {
        let mut s = t;
        s.sort_unstable();
        mesh.faces.iter().position(|f| {
            let mut g = *f;
            g.sort_unstable();
            g == s
        })
    };
    let (Some(a), Some(b)) = (find([0, 2, 4]), find([1, 2, 4])) else {
        panic!("the octahedron has faces 0 2 4 and 1 2 4");
    };
    let mut k = mesh.faces.clone();
    k[a] = [0, 2, 1];
    k[b] = [0, 1, 4];
    let quads = vec![[0, 2, 1, 4]];
    // Only that quad: the other six faces are unused either way, the flipped pair is not.
    let out = QuadMesh {
        vertex_count: 6,
        positions: None,
        faces: quads,
    };
    let with_k = quad(
        &mesh,
        &out,
        &QuadCheck {
            triangles: Some(&k),
            pairs: None,
        },
    )
    .expect("closed");
    let bare = quad(&mesh, &out, &QuadCheck::default()).expect("closed");
    assert_eq!(with_k.counts, vec![(FailureKind::TriangleUnused, 6)]);
    assert_eq!(bare.counts, vec![(FailureKind::TriangleUnused, 6)]);
}

#[test]
fn any_rotation_or_reversal_of_a_quad_passes() {
    let mesh = gen::icosahedron();
    let r = convert(&mesh, Algorithm::Matching);
    let mut turned = r.mesh.clone();
    for (i, q) in turned.faces.iter_mut().enumerate() {
        q.rotate_left(i % 4);
        if i % 2 == 1 {
            q.reverse();
        }
    }
    assert!(quad(&mesh, &turned, &QuadCheck::default())
        .expect("closed")
        .passed());
    assert!(quad(&mesh, &turned, &stated(&r)).expect("closed").passed());
}

#[test]
fn wrong_answers_are_named() {
    let mesh = random(SurfaceKind::Orientable(1), 200, 21);
    let r = convert(&mesh, Algorithm::Matching);
    let none = QuadCheck::default();
    let verdict = |out: &QuadMesh, s: &QuadCheck<'_>| quad(&mesh, out, s).expect("closed");

    // A quad given twice: its triangles used twice, the replaced quad's unused.
    let mut twice = r.mesh.clone();
    twice.faces[3] = twice.faces[0];
    let v = verdict(&twice, &none);
    assert_eq!(
        kinds(&v),
        vec![FailureKind::TriangleUsedTwice, FailureKind::TriangleUnused]
    );
    assert_eq!(v.counts.len(), 2);
    assert!(v.counts.iter().all(|&(_, n)| n == 2), "{:?}", v.counts);

    // A quad missing: its two triangles unused.
    let mut short = r.mesh.clone();
    let gone = short.faces.remove(5);
    let v = verdict(&short, &none);
    assert_eq!(v.counts, vec![(FailureKind::TriangleUnused, 2)]);
    assert!(v.failures[0].message.contains("is in no quad"));
    let _ = gone;

    // Two corners swapped: not a cycle around two faces any more.
    let mut crossed = r.mesh.clone();
    crossed.faces[7].swap(1, 2);
    let v = verdict(&crossed, &none);
    assert!(
        kinds(&v).contains(&FailureKind::QuadNotTwoTriangles),
        "{v:?}"
    );
    assert_eq!(v.failures[0].face, Some(7));

    // A vertex beyond the list, a repeated vertex.
    let mut beyond = r.mesh.clone();
    beyond.faces[2][0] = mesh.vertex_count as u32 + 5;
    assert_eq!(
        verdict(&beyond, &none).counts,
        vec![(FailureKind::VertexOutOfRange, 1)]
    );
    let mut repeated = r.mesh.clone();
    repeated.faces[2][3] = repeated.faces[2][1];
    assert_eq!(
        verdict(&repeated, &none).counts,
        vec![(FailureKind::DegenerateFace, 1)]
    );

    // Stated pairs that are not the quads' triangles, or not as many.
    let mut pairs = r.pairs.clone();
    pairs.swap(0, 1);
    let s = QuadCheck {
        triangles: None,
        pairs: Some(&pairs),
    };
    let v = verdict(&r.mesh, &s);
    assert_eq!(
        kinds(&v),
        vec![FailureKind::TriangleUnused, FailureKind::WrongPair]
    );
    assert_eq!(v.failures[0].face, Some(0));
    let fewer = &r.pairs[1..];
    let v = verdict(
        &r.mesh,
        &QuadCheck {
            triangles: None,
            pairs: Some(fewer),
        },
    );
    assert!(v.failures[0].message.contains("pairs for"), "{v:?}");
    // A pair out of K's range is a wrong pair, not a panic.
    let mut far = r.pairs.clone();
    far[4] = [u32::MAX, 0];
    let v = verdict(
        &r.mesh,
        &QuadCheck {
            triangles: None,
            pairs: Some(&far),
        },
    );
    assert!(kinds(&v).contains(&FailureKind::WrongPair));
}

#[test]
fn positions_are_matched_by_id_or_by_exact_position() {
    let mesh = gen::icosahedron();
    let r = convert(&mesh, Algorithm::PulliSegal);
    // The same list, a vertex moved.
    let mut moved = r.mesh.clone();
    if let Some(p) = moved.positions.as_mut() {
        p[4][1] += 0.25;
    }
    let v = quad(&mesh, &moved, &QuadCheck::default()).expect("closed");
    assert_eq!(v.counts, vec![(FailureKind::MovedVertex, 1)]);
    assert_eq!(v.failures[0].vertex, Some(4));

    // Vertices renumbered (reversed) and an unused one added: matched by position.
    let positions = mesh.positions.clone().expect("positions");
    let n = positions.len() as u32;
    let mut renumbered: Vec<[f64; 3]> = positions.iter().rev().copied().collect();
    renumbered.push([9.0, 9.0, 9.0]);
    let faces: Vec<[u32; 4]> = r.mesh.faces.iter().map(|q| q.map(|v| n - 1 - v)).collect();
    let out = QuadMesh::with_positions(renumbered.clone(), faces.clone());
    assert!(quad(&mesh, &out, &QuadCheck::default())
        .expect("closed")
        .passed());
    // ... and the stated K in the output's ids.
    let k: Vec<[u32; 3]> = r.triangles.iter().map(|t| t.map(|v| n - 1 - v)).collect();
    let s = QuadCheck {
        triangles: Some(&k),
        pairs: Some(&r.pairs),
    };
    assert!(quad(&mesh, &out, &s).expect("closed").passed());
    // A position that is no input vertex's.
    let mut off = renumbered;
    off[0][2] += 1.0;
    let v = quad(
        &mesh,
        &QuadMesh::with_positions(off, faces),
        &QuadCheck::default(),
    )
    .expect("closed");
    assert!(kinds(&v).contains(&FailureKind::UnknownVertex), "{v:?}");
    // No positions and more vertices than the input: nothing to match by.
    let v = quad(
        &mesh,
        &QuadMesh {
            vertex_count: 20,
            positions: None,
            faces: r.mesh.faces.clone(),
        },
        &QuadCheck::default(),
    )
    .expect("closed");
    assert_eq!(v.counts, vec![(FailureKind::UnknownVertex, 1)]);
}

#[test]
fn a_stated_triangulation_must_be_the_input_surface_on_its_vertices() {
    let mesh = random(SurfaceKind::Orientable(1), 200, 31);
    let r = convert(&mesh, Algorithm::Matching);
    let check_k = |k: &[[u32; 3]]| {
        quad(
            &mesh,
            &r.mesh,
            &QuadCheck {
                triangles: Some(k),
                pairs: None,
            },
        )
        .expect("closed")
    };
    // Not closed: a face removed.
    let mut open = r.triangles.clone();
    open.pop();
    assert!(kinds(&check_k(&open)).contains(&FailureKind::BoundaryEdge));
    // Not a surface: a face repeated.
    let mut rep = r.triangles.clone();
    rep[1] = rep[0];
    assert!(kinds(&check_k(&rep)).contains(&FailureKind::RepeatedFace));
    // A vertex beyond the output's list.
    let mut far = r.triangles.clone();
    far[0][0] = r.mesh.vertex_count as u32;
    assert_eq!(
        check_k(&far).counts,
        vec![(FailureKind::VertexOutOfRange, 1)]
    );
    // Another surface on other vertices: a sphere of the torus's first vertices.
    let ico = gen::icosahedron();
    let v = check_k(&ico.faces);
    assert!(kinds(&v).contains(&FailureKind::MissingVertex), "{v:?}");
    assert!(kinds(&v).contains(&FailureKind::SurfaceChanged), "{v:?}");
}

#[test]
fn the_tetrahedron_may_give_the_same_cycle_twice() {
    let t = gen::tetrahedron();
    let v = |q: Vec<[u32; 4]>| {
        quad(
            &t,
            &QuadMesh {
                vertex_count: 4,
                positions: t.positions.clone(),
                faces: q,
            },
            &QuadCheck::default(),
        )
        .expect("closed")
    };
    // Both quads the cycle 0 1 2 3: one split each, together all four faces.
    assert!(v(vec![[0, 1, 2, 3], [0, 1, 2, 3]]).passed());
    assert!(v(vec![[0, 1, 2, 3], [1, 2, 3, 0]]).passed());
    // One quad only: two faces unused.
    assert_eq!(
        v(vec![[0, 1, 2, 3]]).counts,
        vec![(FailureKind::TriangleUnused, 2)]
    );
    // Three quads: a face used twice at least.
    assert!(kinds(&v(vec![[0, 1, 2, 3]; 3])).contains(&FailureKind::TriangleUsedTwice));
}

#[test]
fn an_open_input_is_refused_as_the_conversion_refuses_it() {
    let mut open = gen::octahedron();
    open.faces.pop();
    let quads = QuadMesh {
        vertex_count: open.vertex_count,
        positions: open.positions.clone(),
        faces: vec![],
    };
    assert!(matches!(
        quad(&open, &quads, &QuadCheck::default()),
        Err(Error::NotClosed { .. })
    ));
}

/// The definition read literally: some choice of a diagonal per quad makes the quads'
/// triangles exactly the faces, each once (2^quads choices).
fn brute_force(faces: &[[u32; 3]], quads: &[[u32; 4]], vertex_count: usize) -> bool {
    if quads
        .iter()
        .any(|q| q.iter().any(|&v| v as usize >= vertex_count))
    {
        return false;
    }
    let mut want: Vec<[u32; 3]> = faces
        .iter()
        .map(|f| {
            let mut s = *f;
            s.sort_unstable();
            s
        })
        .collect();
    want.sort_unstable();
    (0u32..1 << quads.len()).any(|choice| {
        let mut got: Vec<[u32; 3]> = Vec::new();
        for (i, q) in quads.iter().enumerate() {
            let d = ((choice >> i) & 1) as usize;
            for t in [
                [q[d], q[d + 1], q[(d + 2) % 4]],
                [q[d], q[(d + 2) % 4], q[(d + 3) % 4]],
            ] {
                let mut s = t;
                s.sort_unstable();
                got.push(s);
            }
        }
        got.sort_unstable();
        got == want
    })
}

#[test]
fn verdicts_agree_with_the_definition_on_edited_answers() {
    let meshes = [gen::tetrahedron(), gen::octahedron(), gen::icosahedron()];
    let mut rng = Rng::new(7);
    let mut failing = 0;
    for mesh in &meshes {
        let r = convert(mesh, Algorithm::Matching);
        for _ in 0..300 {
            let mut quads = r.mesh.faces.clone();
            for _ in 0..1 + rng.index(2) {
                let i = rng.index(quads.len());
                match rng.index(5) {
                    0 => quads[i].swap(rng.index(4), rng.index(4)),
                    1 => quads[i][rng.index(4)] = rng.index(mesh.vertex_count) as u32,
                    2 => quads[i] = quads[rng.index(quads.len())],
                    3 => quads[i].rotate_left(1 + rng.index(3)),
                    _ => {
                        let j = rng.index(quads.len());
                        let k = rng.index(4);
                        let t = quads[i][k];
                        quads[i][k] = quads[j][k];
                        quads[j][k] = t;
                    }
                }
            }
            let out = QuadMesh {
                vertex_count: mesh.vertex_count,
                positions: mesh.positions.clone(),
                faces: quads.clone(),
            };
            let v = quad(mesh, &out, &QuadCheck::default()).expect("closed");
            let distinct = quads
                .iter()
                .all(|q| (0..4).all(|a| (a + 1..4).all(|b| q[a] != q[b])));
            let expected = distinct && brute_force(&mesh.faces, &quads, mesh.vertex_count);
            assert_eq!(v.passed(), expected, "{quads:?}: {:?}", v.failures);
            failing += usize::from(!expected);
        }
    }
    // The edits make both kinds of answer.
    assert!(failing > 300 && failing < 900, "{failing} of 900 fail");
}
