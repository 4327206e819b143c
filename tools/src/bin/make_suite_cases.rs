//! Regenerates the conformance suite's own case files (format: `spec/conformance.md`,
//! section "The suite"): `spec/suite/invalid.jsonl`, inputs an implementation must
//! refuse, and `spec/suite/wrong-answers.jsonl`, wrong answers the checker must reject
//! with a stated reason.
//!
//! `cargo run --release -p contractible-tools --bin make_suite_cases [OUT_DIR]` (default
//! `spec/suite` of this checkout). The inputs are the library's generators and small
//! edits of them; each wrong answer is this library's correct answer with one defect
//! put in. The command line's tests (`cli/tests/cli_conformance.rs`) check that the
//! library refuses every invalid input with the stated kind and that the checker
//! rejects every wrong answer with the stated kind.

use std::fmt::Write as _;
use std::path::PathBuf;

use contractible::{gen, quadrangulate, reduce, simplify, QuadOptions, SimplifyOptions, TriMesh};
use serde_json::{json, Map, Value};

/// The suite version written in every line.
const SUITE: u32 = 1;

fn input_fields(mesh: &TriMesh) -> Map<String, Value> {
    let Value::Object(m) = json!({
        "vertex_count": mesh.vertex_count,
        "faces": mesh.faces,
        "positions": mesh.positions,
    }) else {
        unreachable!("a JSON object literal")
    };
    m
}

fn line(fields: Value, mesh: &TriMesh) -> String {
    let mut m = match fields {
        Value::Object(m) => m,
        _ => Map::new(),
    };
    m.insert("suite".into(), json!(SUITE));
    m.extend(input_fields(mesh));
    // Keys sorted (serde_json's map), one line.
    Value::Object(m).to_string()
}

fn invalid(id: &str, task: &str, options: Value, mesh: &TriMesh, kind: &str, why: &str) -> String {
    line(
        json!({"id": format!("invalid/{task}/{id}"), "task": task, "class": "invalid",
               "options": options, "kind": kind, "why": why}),
        mesh,
    )
}

fn wrong(
    id: &str,
    task: &str,
    options: Value,
    mesh: &TriMesh,
    answer: Value,
    kind: &str,
) -> String {
    line(
        json!({"id": format!("wrong/{task}/{id}"), "task": task, "class": "wrong_answer",
               "options": options, "answer": answer, "kind": kind}),
        mesh,
    )
}

fn open_octahedron() -> TriMesh {
    let mut m = gen::octahedron();
    m.faces.pop();
    m
}

/// The octahedron with a third face on its edge [0, 2] (a new vertex 6).
fn non_manifold_edge() -> TriMesh {
    let mut m = gen::octahedron();
    if let Some(p) = m.positions.as_mut() {
        p.push([0.5, 0.5, 0.5]);
    }
    m.vertex_count += 1;
    let [a, b, _] = m.faces[0];
    m.faces.push([a, b, 6]);
    m
}

/// Two tetrahedra sharing vertex 0 only.
fn pinched_vertex() -> TriMesh {
    let t = gen::tetrahedron();
    let mut faces = t.faces.clone();
    faces.extend(
        t.faces
            .iter()
            .map(|f| f.map(|v| if v == 0 { 0 } else { v + 3 })),
    );
    let mut positions = t.positions.clone().unwrap_or_default();
    for p in t.positions.clone().unwrap_or_default().iter().skip(1) {
        positions.push([p[0] + 3.0, p[1], p[2]]);
    }
    TriMesh::with_positions(positions, faces)
}

/// Four triangles, each on its own three vertices at the positions of a tetrahedron's
/// faces: an unwelded soup.
fn soup() -> TriMesh {
    let t = gen::tetrahedron();
    let p = t.positions.clone().unwrap_or_default();
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for f in &t.faces {
        let base = positions.len() as u32;
        positions.extend(f.iter().map(|&v| p[v as usize]));
        faces.push([base, base + 1, base + 2]);
    }
    TriMesh::with_positions(positions, faces)
}

fn main() {
    let out = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("spec/suite"), PathBuf::from);
    std::fs::create_dir_all(&out).expect("the output folder");
    let none = json!({});
    let eps = json!({"eps": 0.5});

    let mut inv = Vec::new();
    let repeated = {
        let mut m = gen::octahedron();
        m.faces[0][1] = m.faces[0][0];
        m
    };
    let beyond = {
        let mut m = gen::octahedron();
        m.faces[3][2] = 6;
        m
    };
    let keep = json!({"keep": 0.5});
    for (task, options) in [
        ("reduce", &none),
        ("quad", &none),
        ("simplify", &eps),
        ("decimate", &keep),
    ] {
        inv.push(invalid(
            "non-manifold-edge",
            task,
            options.clone(),
            &non_manifold_edge(),
            "non_manifold_edge",
            "an edge in three faces: no surface",
        ));
        inv.push(invalid(
            "pinched-vertex",
            task,
            options.clone(),
            &pinched_vertex(),
            "pinched_vertex",
            "two tetrahedra sharing one vertex: its faces form two fans",
        ));
        inv.push(invalid(
            "degenerate-face",
            task,
            options.clone(),
            &repeated,
            "degenerate_face",
            "a face repeats a vertex",
        ));
        inv.push(invalid(
            "vertex-out-of-range",
            task,
            options.clone(),
            &beyond,
            "vertex_out_of_range",
            "a face names vertex 6 of 6 vertices",
        ));
    }
    for task in ["reduce", "quad"] {
        inv.push(invalid(
            "open-surface",
            task,
            json!({}),
            &open_octahedron(),
            "boundary_edge",
            "the octahedron without a face: the task takes closed surfaces",
        ));
        inv.push(invalid(
            "soup",
            task,
            json!({}),
            &soup(),
            "boundary_edge",
            "an unwelded triangle soup: every edge is a boundary edge",
        ));
    }
    let mut no_positions = gen::octahedron();
    no_positions.positions = None;
    inv.push(invalid(
        "no-positions",
        "simplify",
        eps.clone(),
        &no_positions,
        "missing_positions",
        "simplify measures edge lengths: it needs positions",
    ));
    inv.push(invalid(
        "non-positive-eps",
        "simplify",
        json!({"eps": 0.0}),
        &gen::octahedron(),
        "bad_option",
        "ε must be a finite number > 0",
    ));
    inv.push(invalid(
        "no-positions",
        "decimate",
        keep.clone(),
        &no_positions,
        "missing_positions",
        "decimate measures quadric errors: it needs positions",
    ));
    inv.push(invalid(
        "keep-above-one",
        "decimate",
        json!({"keep": 1.5}),
        &gen::octahedron(),
        "bad_option",
        "the fraction of the faces kept must be in [0, 1]",
    ));
    let mut one_point = gen::octahedron();
    one_point.positions = Some(vec![[1.0, 2.0, 3.0]; 6]);
    inv.push(invalid(
        "all-at-one-point",
        "simplify",
        json!({"eps_rel": 0.1}),
        &one_point,
        "no_coordinates",
        "every vertex at one point: a relative ε is no length",
    ));

    let mut bad = Vec::new();
    // reduce: the input as its own answer; a changed surface; a moved vertex; an open
    // output.
    let torus = gen::subdivide(&gen::torus7(), 1).expect("subdivides");
    let ids = |m: &TriMesh, r: &contractible::ReduceResult| -> Vec<[u32; 3]> {
        let _ = m;
        r.mesh
            .faces
            .iter()
            .map(|f| f.map(|v| r.vertex_map[v as usize]))
            .collect()
    };
    let r = reduce(&torus, &Default::default()).expect("reduces");
    let reduced = ids(&torus, &r);
    bad.push(wrong(
        "not-irreducible",
        "reduce",
        json!({"algorithm": "rs"}),
        &torus,
        json!({"faces": torus.faces, "positions": null}),
        "contractible_edge",
    ));
    bad.push(wrong(
        "surface-changed",
        "reduce",
        json!({"algorithm": "rs"}),
        &torus,
        json!({"faces": [[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]], "positions": null}),
        "surface_changed",
    ));
    let mut moved = torus.positions.clone().expect("positions");
    moved[reduced[0][0] as usize][0] += 0.5;
    bad.push(wrong(
        "moved-vertex",
        "reduce",
        json!({"algorithm": "rs"}),
        &torus,
        json!({"faces": reduced, "positions": moved}),
        "moved_vertex",
    ));
    bad.push(wrong(
        "open-output",
        "reduce",
        json!({"algorithm": "rs"}),
        &torus,
        json!({"faces": reduced[1..], "positions": null}),
        "boundary_edge",
    ));
    // reduce with a history: a step repeated (its removed vertex is gone); the last step
    // left out (the replay ends at another surface).
    let steps = r.contractions();
    let mut repeated = steps.clone();
    repeated.insert(1, steps[0]);
    bad.push(wrong(
        "history-step-repeated",
        "reduce",
        json!({"algorithm": "rs"}),
        &torus,
        json!({"faces": reduced, "positions": null, "history": repeated}),
        "invalid_history",
    ));
    bad.push(wrong(
        "history-stops-short",
        "reduce",
        json!({"algorithm": "rs"}),
        &torus,
        json!({"faces": reduced, "positions": null, "history": steps[..steps.len() - 1]}),
        "history_mismatch",
    ));
    // quad: a quad given twice; two corners swapped; pairs swapped.
    let sphere = gen::icosahedron();
    let q = quadrangulate(
        &sphere,
        &QuadOptions {
            algorithm: contractible::quad::Algorithm::Matching,
            ..QuadOptions::default()
        },
    )
    .expect("pairs");
    let opts = json!({"algorithm": "matching"});
    let mut twice = q.mesh.faces.clone();
    twice[1] = twice[0];
    bad.push(wrong(
        "triangle-paired-twice",
        "quad",
        opts.clone(),
        &sphere,
        json!({"faces": twice, "positions": null}),
        "triangle_used_twice",
    ));
    let mut crossed = q.mesh.faces.clone();
    crossed[2].swap(1, 2);
    bad.push(wrong(
        "not-two-triangles",
        "quad",
        opts.clone(),
        &sphere,
        json!({"faces": crossed, "positions": null}),
        "quad_not_two_triangles",
    ));
    let mut pairs = q.pairs.clone();
    pairs.swap(0, 1);
    bad.push(wrong(
        "wrong-pairs",
        "quad",
        opts.clone(),
        &sphere,
        json!({"faces": q.mesh.faces, "positions": null, "triangles": q.triangles, "pairs": pairs}),
        "wrong_pair",
    ));
    // simplify: a short contractible edge left; a changed surface.
    let ball = gen::isosurface(&gen::IsoParams::new(
        gen::Implicit::Sphere { radius: 1.0 },
        gen::Tessellation::SixTetrahedra,
        6,
    ))
    .expect("a sphere");
    let s = simplify(&ball, &SimplifyOptions::absolute(0.3)).expect("simplifies");
    bad.push(wrong(
        "short-edge-left",
        "simplify",
        json!({"eps": 0.3}),
        &ball,
        json!({"faces": ball.faces, "positions": ball.positions}),
        "short_contractible_edge",
    ));
    bad.push(wrong(
        "hole-made",
        "simplify",
        json!({"eps": 0.3}),
        &ball,
        json!({"faces": s.mesh.faces[1..], "positions": s.mesh.positions}),
        "surface_changed",
    ));

    // decimate: the input as an unguarded run's answer; maps that lie; a locked vertex
    // moved.
    let d = contractible::decimate(&ball, &contractible::DecimateOptions::keep(0.25))
        .expect("decimates");
    let cm: Vec<Option<u32>> = d
        .collapse_map
        .iter()
        .map(|&o| (o != contractible::decimate::NO_VERTEX).then_some(o))
        .collect();
    bad.push(wrong(
        "stopped-early",
        "decimate",
        json!({"keep": 0.25, "guard": false}),
        &ball,
        json!({"faces": ball.faces, "positions": ball.positions}),
        "target_missed",
    ));
    let mut shifted = d.vertex_map.clone();
    shifted.rotate_left(1);
    bad.push(wrong(
        "maps-that-lie",
        "decimate",
        json!({"keep": 0.25}),
        &ball,
        json!({"faces": d.mesh.faces, "positions": d.mesh.positions, "vertex_map": shifted,
               "collapse_map": cm, "face_origin": d.face_origin}),
        "inconsistent_map",
    ));
    let l = contractible::decimate(
        &ball,
        &contractible::DecimateOptions {
            locked: vec![0],
            ..contractible::DecimateOptions::keep(0.25)
        },
    )
    .expect("decimates");
    let mut moved = l.mesh.positions.clone().expect("positions");
    moved[l.collapse_map[0] as usize][2] += 0.125;
    bad.push(wrong(
        "locked-vertex-moved",
        "decimate",
        json!({"keep": 0.25, "locked": [0]}),
        &ball,
        json!({"faces": l.mesh.faces, "positions": moved, "vertex_map": l.vertex_map}),
        "moved_vertex",
    ));

    for (name, lines) in [("invalid.jsonl", &inv), ("wrong-answers.jsonl", &bad)] {
        let mut text = String::new();
        for l in lines.iter() {
            let _ = writeln!(text, "{l}");
        }
        let path = out.join(name);
        std::fs::write(&path, text).expect("writes");
        println!("{}: {} cases", path.display(), lines.len());
    }
}
