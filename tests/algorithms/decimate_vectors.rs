//! The decimation conformance vectors `spec/vectors/decimate.jsonl` (format:
//! `spec/vectors/README.md`, section "Decimation vectors"):
//!
//! 1. **Exactly**: `decimate` on each stored input and options gives the stored output
//!    positions (bit for bit), faces, maps, stop reason and statistics. Regenerate with
//!    `cargo run --release -p contractible-tools --bin make_decimate_vectors` only for an
//!    intended change.
//! 2. **Independently** of the decimator, from the stored data alone: every stored output,
//!    with its maps and statistics, passes the checks of `decimate.rs` (topology per
//!    component, provenance, locks, the stop rule by the link condition decided from
//!    the face list, the error recomputed from the input's planes).

use std::collections::BTreeSet;

use contractible::decimate::{
    ComponentStats, Placement, Refusals, Schedule, Stats, Stopped, NO_VERTEX,
};
use contractible::{decimate, DecimateOptions, MaxError, TriMesh};
use serde_json::Value;

use crate::common;

/// Vectors in the file, runs per vector.
const VECTORS: usize = 10;

/// The options of the runs, in order: (placement, guard off, lock_boundary, locks,
/// target kind, schedule).
const RUNS: [(&str, bool, bool, bool, &str, &str); 11] = [
    ("optimal", false, false, false, "keep", "exact"),
    ("midpoint", false, false, false, "faces", "exact"),
    ("endpoint", true, false, false, "faces", "exact"),
    ("optimal", true, false, false, "none", "exact"),
    ("midpoint", false, false, false, "relative", "exact"),
    ("endpoint", false, true, false, "keep+absolute", "exact"),
    ("optimal", false, false, true, "faces", "exact"),
    ("midpoint", false, false, false, "none", "exact"),
    ("optimal", false, false, false, "faces", "passes"),
    ("optimal", false, false, false, "none", "passes"),
    ("endpoint", false, true, true, "relative", "passes"),
];

fn all() -> Vec<Value> {
    common::read_vector_groups(&[("decimate", VECTORS)])
}

fn num(v: &Value, key: &str) -> usize {
    v[key]
        .as_u64()
        .unwrap_or_else(|| panic!("missing number {key}")) as usize
}

fn positions(v: &Value) -> Vec<[f64; 3]> {
    v.as_array()
        .expect("positions")
        .iter()
        .map(|p| {
            let p = p.as_array().expect("triple");
            assert_eq!(p.len(), 3);
            [0, 1, 2].map(|k| p[k].as_f64().expect("coordinate"))
        })
        .collect()
}

fn ids(v: &Value) -> Vec<u32> {
    v.as_array()
        .expect("id list")
        .iter()
        .map(|x| x.as_u64().map_or(NO_VERTEX, |x| x as u32))
        .collect()
}

fn input_mesh(v: &Value) -> TriMesh {
    let mesh = TriMesh::with_positions(positions(&v["positions"]), common::json_faces(&v["faces"]));
    assert_eq!(mesh.vertex_count, num(v, "vertex_count"), "{}", v["name"]);
    mesh
}

fn options(o: &Value) -> DecimateOptions {
    DecimateOptions {
        faces: o["faces"].as_u64().map(|f| f as usize),
        keep: o["keep"].as_f64(),
        max_error: match &o["max_error"] {
            Value::Null => None,
            m => Some(match (m["absolute"].as_f64(), m["relative"].as_f64()) {
                (Some(e), None) => MaxError::Absolute(e),
                (None, Some(r)) => MaxError::Relative(r),
                _ => panic!("max_error {m}"),
            }),
        },
        placement: o["placement"]
            .as_str()
            .expect("placement")
            .parse()
            .expect("a placement name"),
        schedule: o["schedule"]
            .as_str()
            .expect("schedule")
            .parse()
            .expect("a schedule name"),
        allow_foldover: o["allow_foldover"].as_bool().expect("allow_foldover"),
        lock_boundary: o["lock_boundary"].as_bool().expect("lock_boundary"),
        locked: ids(&o["locked"]),
        ..DecimateOptions::default()
    }
}

fn refusals(v: &Value) -> Refusals {
    Refusals {
        lock: num(v, "lock"),
        boundary: num(v, "boundary"),
        error: num(v, "error"),
        link_condition: num(v, "link_condition"),
        foldover: num(v, "foldover"),
    }
}

fn stopped(v: &Value) -> Stopped {
    match v.as_str().expect("stopped") {
        "target" => Stopped::Target,
        "error" => Stopped::Error,
        "blocked" => Stopped::Blocked,
        s => panic!("stopped {s}"),
    }
}

/// The stored statistics, with what the vectors leave out (`refused`, `seconds`) taken
/// from `like`.
fn stats(v: &Value, like: &Stats) -> Stats {
    Stats {
        faces_in: num(v, "faces_in"),
        faces_out: num(v, "faces_out"),
        vertices_in: num(v, "vertices_in"),
        vertices_out: num(v, "vertices_out"),
        components: num(v, "components"),
        boundary_loops: num(v, "boundary_loops"),
        target_faces: v["target_faces"].as_u64().map(|t| t as usize),
        max_error_cap: v["max_error_cap"].as_f64(),
        stopped: stopped(&v["stopped"]),
        collapses: num(v, "collapses"),
        passes: num(v, "passes"),
        max_error: v["max_error"].as_f64().expect("max_error"),
        refused: like.refused,
        remaining: refusals(&v["remaining"]),
        component_list: v["component_list"]
            .as_array()
            .expect("component_list")
            .iter()
            .map(|c| ComponentStats {
                faces_in: num(c, "faces_in"),
                faces_out: num(c, "faces_out"),
                vertices_in: num(c, "vertices_in"),
                vertices_out: num(c, "vertices_out"),
                boundary_loops: num(c, "boundary_loops"),
                remaining: refusals(&c["remaining"]),
            })
            .collect(),
        seconds: like.seconds,
    }
}

fn bits(p: &[[f64; 3]]) -> Vec<[u64; 3]> {
    p.iter().map(|p| p.map(f64::to_bits)).collect()
}

#[test]
fn decimate_vector_file_holds_the_documented_runs() {
    let all = all();
    let names: BTreeSet<&str> = all
        .iter()
        .map(|v| v["name"].as_str().expect("name"))
        .collect();
    assert_eq!(names.len(), all.len(), "duplicate names");
    for v in &all {
        let name = v["name"].as_str().expect("name");
        assert_eq!(v["group"], "decimate", "{name}");
        let mesh = input_mesh(v);
        // Every input coordinate a multiple of 2^-10 below 16 in magnitude.
        for x in mesh
            .positions
            .as_deref()
            .expect("positions")
            .iter()
            .flatten()
        {
            assert!((x * 1024.0).fract() == 0.0 && x.abs() < 16.0, "{name}: {x}");
        }
        let runs = v["runs"].as_array().expect("runs");
        assert_eq!(runs.len(), RUNS.len(), "{name}");
        for (r, &(placement, foldover, lock_boundary, locks, target, schedule)) in
            runs.iter().zip(&RUNS)
        {
            let o = options(&r["options"]);
            assert_eq!(o.placement.name(), placement, "{name}");
            assert_eq!(o.schedule.name(), schedule, "{name}");
            assert_eq!(o.allow_foldover, foldover, "{name}");
            assert_eq!(o.lock_boundary, lock_boundary, "{name}");
            assert_eq!(!o.locked.is_empty(), locks, "{name}");
            let kind = match (o.faces, o.keep, o.max_error) {
                (None, Some(_), None) => "keep",
                (Some(_), None, None) => "faces",
                (None, None, None) => "none",
                (None, None, Some(MaxError::Relative(_))) => "relative",
                (None, Some(_), Some(MaxError::Absolute(_))) => "keep+absolute",
                other => panic!("{name}: {other:?}"),
            };
            assert_eq!(kind, target, "{name}");
            assert_eq!(
                num(r, "faces_out"),
                common::json_faces(&r["output_faces"]).len()
            );
            assert_eq!(r["stopped"], r["stats"]["stopped"], "{name}");
        }
    }
    assert!(Placement::ALL
        .iter()
        .all(|p| RUNS.iter().any(|r| r.0 == p.name())));
    assert!(Schedule::ALL
        .iter()
        .all(|s| RUNS.iter().any(|r| r.5 == s.name())));
}

#[test]
fn library_reproduces_every_decimate_vector_exactly() {
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let mesh = input_mesh(&v);
        for (k, r) in v["runs"].as_array().expect("runs").iter().enumerate() {
            let o = options(&r["options"]);
            let label = format!("{name} run {k} {o:?}");
            let got = decimate(&mesh, &o).unwrap_or_else(|e| panic!("{label}: {e}"));
            assert!(
                bits(got.mesh.positions.as_deref().expect("positions"))
                    == bits(&positions(&r["output_positions"])),
                "{label}: output positions"
            );
            assert_eq!(
                got.mesh.faces,
                common::json_faces(&r["output_faces"]),
                "{label}: faces"
            );
            assert_eq!(got.vertex_map, ids(&r["vertex_map"]), "{label}: vertex_map");
            assert_eq!(
                got.collapse_map,
                ids(&r["collapse_map"]),
                "{label}: collapse_map"
            );
            assert_eq!(
                got.face_origin,
                ids(&r["face_origin"]),
                "{label}: face_origin"
            );
            assert_eq!(
                got.stats.stopped,
                stopped(&r["stopped"]),
                "{label}: stopped"
            );
            assert_eq!(got.mesh.faces.len(), num(r, "faces_out"), "{label}");
            let want = stats(&r["stats"], &got.stats);
            assert_eq!(
                got.stats.max_error.to_bits(),
                want.max_error.to_bits(),
                "{label}: max_error"
            );
            assert_eq!(got.stats, want, "{label}: stats");
        }
    }
}

#[test]
fn stored_decimate_outputs_are_valid_independently() {
    let mut runs = 0;
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let mesh = input_mesh(&v);
        for (k, r) in v["runs"].as_array().expect("runs").iter().enumerate() {
            let o = options(&r["options"]);
            let label = format!("stored {name} run {k}");
            // A result of the call only for its shape; every field checked is replaced by
            // the stored one.
            let mut stored = decimate(&mesh, &o).unwrap_or_else(|e| panic!("{label}: {e}"));
            stored.mesh = TriMesh::with_positions(
                positions(&r["output_positions"]),
                common::json_faces(&r["output_faces"]),
            );
            stored.vertex_map = ids(&r["vertex_map"]);
            stored.collapse_map = ids(&r["collapse_map"]);
            stored.face_origin = ids(&r["face_origin"]);
            stored.stats = stats(&r["stats"], &stored.stats);
            crate::decimate::check(&mesh, &o, &stored, &label);
            runs += 1;
        }
    }
    assert_eq!(runs, VECTORS * RUNS.len());
}

#[test]
fn stored_decimate_outputs_pass_the_conformance_checker() {
    // `contractible::check::decimate` (shares no code with the decimator) on every
    // stored run, with its options and its three maps: every one passes; with the
    // vertex map shifted by one, none does.
    let mut judged = 0;
    for v in all() {
        let input = input_mesh(&v);
        for run in v["runs"].as_array().expect("runs") {
            let o = options(&run["options"]);
            let out = TriMesh::with_positions(
                positions(&run["output_positions"]),
                common::json_faces(&run["output_faces"]),
            );
            let (vm, cm, fo) = (
                ids(&run["vertex_map"]),
                ids(&run["collapse_map"]),
                ids(&run["face_origin"]),
            );
            let c = contractible::check::DecimateCheck {
                vertex_map: Some(&vm),
                collapse_map: Some(&cm),
                face_origin: Some(&fo),
                ..contractible::check::DecimateCheck::of_run(&o)
            };
            let verdict = contractible::check::decimate(&input, &out, &c).expect("judged");
            assert!(verdict.passed(), "{}: {:?}", v["name"], verdict.failures);
            if vm.len() > 1 {
                let mut shifted = vm.clone();
                shifted.rotate_left(1);
                let wrong = contractible::check::DecimateCheck {
                    vertex_map: Some(&shifted),
                    ..c.clone()
                };
                let verdict = contractible::check::decimate(&input, &out, &wrong).expect("judged");
                assert!(
                    !verdict.passed(),
                    "{}: a shifted vertex map passes",
                    v["name"]
                );
            }
            judged += 1;
        }
    }
    assert_eq!(judged, VECTORS * RUNS.len());
}
