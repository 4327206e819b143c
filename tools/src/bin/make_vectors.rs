//! Regenerates the conformance vectors in `spec/vectors/` (format: `spec/vectors/README.md`).
//!
//! `cargo run -p contractible-tools --bin make_vectors [OUT_DIR]` (default `spec/vectors`
//! of this checkout). Reads the published small surfaces from
//! `tests/data/irreducible/*.txt`, generates the rest, runs RS, Schipper and the brute
//! force (seed 0) on each and writes one JSON-lines file per group.
//! `tests/algorithms/vectors.rs` checks that the library still reproduces them.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use contractible::gen::{self, RandomParams, SurfaceKind};
use contractible::irreducible::{reduce, Algorithm, Options, Reduction};
use contractible::Triangulation;
use serde_json::{json, Value};

/// The brute force's seed in the vectors.
const BRUTE_SEED: u64 = 0;

/// The generated random surfaces: (surface, min_faces, flip_percent, seed).
const RANDOM: [(SurfaceKind, usize, u32, u64); 7] = [
    (SurfaceKind::Orientable(0), 100, 30, 1),
    (SurfaceKind::Orientable(1), 200, 30, 2),
    (SurfaceKind::Orientable(2), 300, 30, 3),
    (SurfaceKind::Orientable(3), 600, 30, 4),
    (SurfaceKind::NonOrientable(1), 150, 30, 5),
    (SurfaceKind::NonOrientable(2), 300, 30, 6),
    (SurfaceKind::NonOrientable(3), 500, 30, 7),
];

struct Input {
    name: String,
    source: Value,
    vertex_count: usize,
    faces: Vec<[u32; 3]>,
}

fn read_list(path: &Path) -> Vec<Input> {
    let file = path
        .file_name()
        .expect("file")
        .to_string_lossy()
        .to_string();
    contractible::io::list::read_surface_list(path)
        .unwrap_or_else(|e| panic!("{e}"))
        .into_iter()
        .map(|s| Input {
            name: s.name,
            source: json!({ "file": format!("tests/data/irreducible/{file}") }),
            vertex_count: s.vertex_count,
            faces: s.faces,
        })
        .collect()
}

fn generated() -> Vec<Input> {
    let mut out = Vec::new();
    for (surface, min_faces, flip_percent, seed) in RANDOM {
        let tri = gen::random(&RandomParams {
            surface,
            min_faces,
            flip_percent,
            seed,
        })
        .expect("a random surface within the limits");
        let (kind, n) = match surface {
            SurfaceKind::Orientable(g) => ("orientable", g),
            SurfaceKind::NonOrientable(h) => ("non_orientable", h),
        };
        let tag = if kind == "orientable" { "S" } else { "N" };
        out.push(Input {
            name: format!("random_{tag}{n}_f{min_faces}_p{flip_percent}_s{seed}"),
            source: json!({
                "generator": "gen::random",
                "surface": kind,
                "genus": n,
                "min_faces": min_faces,
                "flip_percent": flip_percent,
                "seed": seed,
            }),
            vertex_count: tri.vertex_capacity(),
            faces: tri.face_list(),
        });
    }
    for (name, mesh) in [
        ("torus7", gen::torus7()),
        ("octahedron", gen::octahedron()),
        ("icosahedron", gen::icosahedron()),
        ("klein_bottle", gen::klein_bottle()),
    ] {
        out.push(Input {
            name: name.to_string(),
            source: json!({ "generator": format!("gen::{name}") }),
            vertex_count: mesh.vertex_count,
            faces: mesh.faces,
        });
    }
    out
}

/// The result of one algorithm as stored in a vector.
fn result_json(r: &Reduction) -> Value {
    let history: Vec<Value> = r
        .history
        .records()
        .iter()
        .map(|rec| {
            json!({
                "u": rec.u.0,
                "v": rec.v.0,
                "x": rec.link[0].0,
                "y": rec.link[1].0,
                "faces": [rec.faces[0].0, rec.faces[1].0],
            })
        })
        .collect();
    json!({
        "output_faces": r.tri.face_list(),
        "history": history,
        "stats": {
            "link_tests": r.stats.link_tests,
            "edges_tested_more_than_once": r.stats.edges_tested_more_than_once,
            "contractions": r.stats.contractions,
            "vertices_out": r.stats.vertices_out,
            "faces_out": r.stats.faces_out,
        },
    })
}

fn vector(input: &Input, group: &str) -> Value {
    let tri = Triangulation::from_faces(input.vertex_count, &input.faces)
        .unwrap_or_else(|e| panic!("{}: {e}", input.name));
    let opts = |seed| Options {
        seed,
        count_retests: true,
        keep_history: true,
    };
    let rs = reduce(tri.clone(), Algorithm::Rs, &opts(0));
    let schipper = reduce(tri.clone(), Algorithm::Schipper, &opts(0));
    let brute = reduce(tri.clone(), Algorithm::Brute, &opts(BRUTE_SEED));
    let mut v = result_json(&rs);
    let obj = v.as_object_mut().expect("object");
    obj.insert("name".into(), json!(input.name));
    obj.insert("group".into(), json!(group));
    obj.insert("source".into(), input.source.clone());
    obj.insert("vertex_count".into(), json!(input.vertex_count));
    obj.insert("faces".into(), json!(input.faces));
    obj.insert(
        "euler_characteristic".into(),
        json!(tri.euler_characteristic()),
    );
    obj.insert("orientable".into(), json!(tri.is_orientable()));
    obj.insert("schipper".into(), result_json(&schipper));
    let mut b = result_json(&brute);
    b.as_object_mut()
        .expect("object")
        .insert("seed".into(), json!(BRUTE_SEED));
    obj.insert("brute".into(), b);
    v
}

fn main() {
    let root = contractible_tools::repo_root();
    let out_dir = std::env::args()
        .nth(1)
        .map_or_else(|| root.join("spec/vectors"), PathBuf::from);
    std::fs::create_dir_all(&out_dir).expect("create output directory");
    let lists = root.join("tests/data/irreducible");
    let groups: Vec<(&str, Vec<Input>)> = vec![
        (
            "surfaces-upto-8-vertices",
            read_list(&lists.join("surfaces-upto-8-vertices.txt")),
        ),
        ("torus", read_list(&lists.join("torus.txt"))),
        (
            "projective-plane",
            read_list(&lists.join("projective-plane.txt")),
        ),
        ("generated", generated()),
    ];
    for (group, inputs) in &groups {
        let mut text = String::new();
        for input in inputs {
            let v = vector(input, group);
            writeln!(text, "{}", serde_json::to_string(&v).expect("json")).expect("write");
        }
        let path = out_dir.join(format!("{group}.jsonl"));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        println!("{}: {} vectors", path.display(), inputs.len());
    }
}
