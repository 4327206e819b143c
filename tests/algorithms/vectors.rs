//! The conformance vectors of `spec/vectors/` (format: `spec/vectors/README.md`).
//!
//! 1. The current library reproduces every vector exactly (RS, Schipper and the brute
//!    force with the vector's seed: output faces, history, counters), so any behaviour
//!    change shows up here (regenerate with `cargo run -p contractible-tools --bin make_vectors` only if the
//!    change is intended, and say so in the commit).
//! 2. Independently of the algorithms, each stored output is irreducible by the naive
//!    link test, with the input's χ and orientability (computed from the face lists), and
//!    replaying the stored history with `Triangulation::contract` from the input gives the
//!    stored output and the stored `x`, `y`, `faces` of every step.

use std::collections::BTreeSet;
use std::path::PathBuf;

use contractible::irreducible::{reduce, Algorithm, Options, Reduction};
use contractible::{History, Surfaces, Triangulation, VertexId};
use serde_json::Value;

use crate::common;

const GROUPS: [(&str, usize); 4] = [
    ("surfaces-upto-8-vertices", 57),
    ("torus", 21),
    ("projective-plane", 2),
    ("generated", 11),
];

fn all() -> Vec<Value> {
    common::read_vector_groups(&GROUPS)
}

fn num(v: &Value, key: &str) -> u64 {
    v[key]
        .as_u64()
        .unwrap_or_else(|| panic!("missing number {key}"))
}

fn input(v: &Value) -> (String, Triangulation) {
    let name = v["name"].as_str().expect("name").to_string();
    let tri = Triangulation::from_faces(
        num(v, "vertex_count") as usize,
        &common::json_faces(&v["faces"]),
    )
    .unwrap_or_else(|e| panic!("{name}: {e}"));
    (name, tri)
}

/// The stored history as (u, v, x, y, f1, f2).
fn history_of(v: &Value) -> Vec<[u64; 6]> {
    v["history"]
        .as_array()
        .expect("history")
        .iter()
        .map(|h| {
            let f = h["faces"].as_array().expect("faces");
            assert_eq!(f.len(), 2);
            [
                num(h, "u"),
                num(h, "v"),
                num(h, "x"),
                num(h, "y"),
                f[0].as_u64().expect("face"),
                f[1].as_u64().expect("face"),
            ]
        })
        .collect()
}

fn history_tuples(h: &History) -> Vec<[u64; 6]> {
    h.records()
        .iter()
        .map(|r| {
            [
                r.u.0,
                r.v.0,
                r.link[0].0,
                r.link[1].0,
                r.faces[0].0,
                r.faces[1].0,
            ]
            .map(u64::from)
        })
        .collect()
}

fn assert_reproduces(name: &str, alg: &str, stored: &Value, r: &Reduction) {
    assert_eq!(
        r.tri.face_list(),
        common::json_faces(&stored["output_faces"]),
        "{name} {alg}: output_faces"
    );
    assert_eq!(
        history_tuples(&r.history),
        history_of(stored),
        "{name} {alg}: history"
    );
    let s = &stored["stats"];
    assert_eq!(
        [
            r.stats.link_tests,
            r.stats.edges_tested_more_than_once,
            r.stats.contractions,
            r.stats.vertices_out as u64,
            r.stats.faces_out as u64,
        ],
        [
            num(s, "link_tests"),
            num(s, "edges_tested_more_than_once"),
            num(s, "contractions"),
            num(s, "vertices_out"),
            num(s, "faces_out"),
        ],
        "{name} {alg}: stats"
    );
}

#[test]
fn vector_files_have_the_expected_groups_and_sizes() {
    let all = all();
    let names: BTreeSet<&str> = all
        .iter()
        .map(|v| v["name"].as_str().expect("name"))
        .collect();
    assert_eq!(names.len(), all.len(), "duplicate names");
    let total: u64 = GROUPS
        .iter()
        .map(|(g, _)| {
            let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
                .join("spec/vectors")
                .join(format!("{g}.jsonl"));
            std::fs::metadata(p).expect("file").len()
        })
        .sum();
    assert!(total < 2_000_000, "vectors take {total} bytes");
    // Every group of spec/vectors together (tri-quad, simplification and marching
    // tetrahedra too) stays a few MB.
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("spec/vectors");
    let all: u64 = std::fs::read_dir(&dir)
        .expect("spec/vectors")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "jsonl"))
        .map(|p| std::fs::metadata(p).expect("file").len())
        .sum();
    assert!(all < 3_000_000, "spec/vectors takes {all} bytes");
}

#[test]
fn library_reproduces_every_vector_exactly() {
    for v in all() {
        let (name, tri) = input(&v);
        let opts = |seed| Options {
            seed,
            count_retests: true,
            keep_history: true,
        };
        let rs = reduce(tri.clone(), Algorithm::Rs, &opts(0));
        assert_reproduces(&name, "rs", &v, &rs);
        let s = reduce(tri.clone(), Algorithm::Schipper, &opts(0));
        assert_reproduces(&name, "schipper", &v["schipper"], &s);
        let seed = num(&v["brute"], "seed");
        let b = reduce(tri.clone(), Algorithm::Brute, &opts(seed));
        assert_reproduces(&name, "brute", &v["brute"], &b);
    }
}

#[test]
fn stored_outputs_are_irreducible_surfaces_of_the_input() {
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let input_faces = common::json_faces(&v["faces"]);
        let (chi, orientable) = closed_surface_invariants(&input_faces);
        assert_eq!(
            v["euler_characteristic"].as_i64(),
            Some(chi),
            "{name}: stored χ"
        );
        assert_eq!(v["orientable"].as_bool(), Some(orientable), "{name}");
        for (alg, stored) in [
            ("rs", &v),
            ("schipper", &v["schipper"]),
            ("brute", &v["brute"]),
        ] {
            let out = common::json_faces(&stored["output_faces"]);
            assert_eq!(
                closed_surface_invariants(&out),
                (chi, orientable),
                "{name} {alg}: output surface"
            );
            // Output ids are the input's (some unused): build on the used ones.
            let s = Surfaces::from_faces(num(&v, "vertex_count") as usize, &out)
                .unwrap_or_else(|e| panic!("{name} {alg}: {e}"));
            assert_eq!(s.components.len(), 1, "{name} {alg}: connected");
            let t = &s.components[0].tri;
            assert!(t.is_irreducible_naive(), "{name} {alg}: output reducible");
            let h = 2 - chi;
            if h == 0 {
                assert!(t.is_tetrahedron(), "{name} {alg}");
            } else {
                assert!(t.vertex_count() as i64 <= 13 * h - 4, "{name} {alg}");
            }
            let st = &stored["stats"];
            assert_eq!(num(st, "vertices_out") as usize, t.vertex_count());
            assert_eq!(num(st, "faces_out") as usize, out.len());
            assert_eq!(
                num(st, "contractions") as usize,
                stored["history"].as_array().expect("history").len()
            );
        }
        // RS counters: ε = 0 and ℓ ≤ E (Sec. 4.7).
        let edges = 3 * input_faces.len() as u64 / 2;
        assert_eq!(num(&v["stats"], "edges_tested_more_than_once"), 0, "{name}");
        assert!(num(&v["stats"], "link_tests") <= edges, "{name}: ℓ > E");
    }
}

#[test]
fn replaying_each_stored_history_gives_the_stored_output() {
    for v in all() {
        let (name, tri0) = input(&v);
        for (alg, stored) in [
            ("rs", &v),
            ("schipper", &v["schipper"]),
            ("brute", &v["brute"]),
        ] {
            let mut tri = tri0.clone();
            let mut h = History::new();
            for (k, [u, w, x, y, f1, f2]) in history_of(stored).into_iter().enumerate() {
                let (u, w) = (VertexId(u as u32), VertexId(w as u32));
                let rec = tri
                    .contract(u, w, &mut h)
                    .unwrap_or_else(|e| panic!("{name} {alg} step {k}: {e}"));
                assert_eq!(
                    [rec.link[0].0, rec.link[1].0, rec.faces[0].0, rec.faces[1].0],
                    [x, y, f1, f2].map(|a| a as u32),
                    "{name} {alg} step {k}: link/faces"
                );
            }
            assert_eq!(
                tri.face_list(),
                common::json_faces(&stored["output_faces"]),
                "{name} {alg}: replayed output"
            );
            h.undo_all(&mut tri);
            assert!(tri == tri0, "{name} {alg}: undo of the replay");
        }
    }
}

/// χ and orientability by the face-list oracle; panics if the faces are not a closed surface.
fn closed_surface_invariants(faces: &[[u32; 3]]) -> (i64, bool) {
    contractible::spec::oracle::euler_and_orientability(faces).expect("a closed surface")
}
