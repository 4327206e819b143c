//! Regenerates the tri-quad conformance vectors `spec/vectors/quad-*.jsonl` (format:
//! `spec/vectors/README.md`, section "Tri-quad vectors").
//!
//! `cargo run -p contractible-tools --bin make_quad_vectors [OUT_DIR]` (default
//! `spec/vectors` of this checkout). Reads
//! `tests/data/irreducible/surfaces-upto-8-vertices.txt`, generates eight small random
//! surfaces, and runs every tri-quad algorithm (`quad::Algorithm::ALL`) with seeds 0 and
//! 1 on each: the initial pairing (`quad::{lrs, pulli_segal, greedy, matching}::
//! initial_pairing`, or Frink's perfect matching with the algorithm's strategy), then the
//! completion (`quad::augment::complete`, which finds nothing to do after Frink's), and
//! checks that `quad::convert` gives the same `K`, pairs and counters. `tests/algorithms/quad_qfuzz.rs` checks that the
//! library still reproduces them.

use std::fmt::Write as _;
use std::path::PathBuf;

use contractible::gen::{self, RandomParams, SurfaceKind};
use contractible::quad::{self, Algorithm, Options, Pairing};
use contractible::Triangulation;
use serde_json::{json, Value};

/// The seeds of every algorithm in the vectors.
const SEEDS: [u64; 2] = [0, 1];

/// The algorithms, in the order of a vector's `runs`: every one of them, in the order of
/// `Algorithm::ALL` (lrs, ps, sg, matching, ds, bbdl, frink-lct, ds-naive).
const ALGORITHMS: [Algorithm; 8] = Algorithm::ALL;

/// The generated random surfaces: (surface, min_faces, flip_percent, seed). The last
/// one makes LRS take every branch of Alg. 3.1–3.4, a degree-4 split with exactly one
/// of `[x, z]`, `[y, z]` flagged (Alg. 3.4, not 3.3) included.
const RANDOM: [(SurfaceKind, usize, u32, u64); 8] = [
    (SurfaceKind::Orientable(0), 40, 30, 11),
    (SurfaceKind::Orientable(1), 60, 30, 12),
    (SurfaceKind::Orientable(2), 80, 30, 13),
    (SurfaceKind::Orientable(3), 100, 30, 14),
    (SurfaceKind::NonOrientable(1), 40, 30, 15),
    (SurfaceKind::NonOrientable(2), 60, 30, 16),
    (SurfaceKind::NonOrientable(3), 80, 30, 17),
    (SurfaceKind::Orientable(0), 40, 30, 0),
];

struct Input {
    name: String,
    source: Value,
    vertex_count: usize,
    faces: Vec<[u32; 3]>,
}

fn pairs_json(p: &Pairing) -> Value {
    json!(p.pairs().map(|(f, g)| [f.0, g.0]).collect::<Vec<_>>())
}

/// One run: the initial step, then the completion, compared with `quad::convert`.
fn run_json(tri: &Triangulation, alg: Algorithm, seed: u64, name: &str) -> Value {
    let opts = Options { seed };
    let (k, initial) = match alg {
        Algorithm::Lrs => {
            let e = quad::lrs::initial_pairing(tri.clone());
            (e.tri, e.pairing)
        }
        Algorithm::PulliSegal => (tri.clone(), quad::pulli_segal::initial_pairing(tri, &opts)),
        Algorithm::SimpleGreedy => (tri.clone(), quad::greedy::initial_pairing(tri, &opts)),
        Algorithm::Matching => (tri.clone(), quad::matching::initial_pairing(tri)),
        Algorithm::DsNaive => (
            tri.clone(),
            quad::frink::perfect_matching(tri).expect("a closed triangulation"),
        ),
        Algorithm::FrinkLct => (tri.clone(), frink(tri, &mut quad::frink::CoverTree::new())),
        Algorithm::DiksStanczyk => (
            tri.clone(),
            frink(tri, &mut quad::frink::DiksStanczyk::new()),
        ),
        Algorithm::BiedlBoseDemaineLubiw => (
            tri.clone(),
            frink(tri, &mut quad::frink::BiedlBoseDemaineLubiw::new()),
        ),
    };
    let mut full = initial.clone();
    let work = quad::augment::complete(&k, &mut full).expect("a closed triangulation");
    let q = quad::convert(tri.clone(), alg, &opts).expect("a closed triangulation");
    let label = format!("{name} {} seed {seed}", alg.name());
    assert!(q.tri == k, "{label}: convert's K differs");
    assert_eq!(q.pairing, full, "{label}: convert's pairs differ");
    assert_eq!(
        (q.stats.augmenting_paths, q.stats.phases),
        (work.augmenting_paths, work.phases),
        "{label}: convert's counters differ"
    );
    assert_eq!(
        q.stats.initial_unpaired,
        k.face_count() - 2 * initial.len(),
        "{label}"
    );
    assert!(full.is_perfect(&k), "{label}: not perfect");
    let mut v = json!({
        "algorithm": alg.name(),
        "seed": seed,
        "initial_pairs": pairs_json(&initial),
        "pairs": pairs_json(&full),
        "stats": {
            "faces": q.stats.faces,
            "initial_unpaired": q.stats.initial_unpaired,
            "flips": q.stats.flips,
            "augmenting_paths": q.stats.augmenting_paths,
            "phases": q.stats.phases,
        },
    });
    if alg == Algorithm::Lrs {
        // Face ids of K are the input's (exact undo and flips keep them), none removed.
        assert_eq!(k.face_capacity(), k.face_count(), "{label}: holes in K");
        v.as_object_mut()
            .expect("object")
            .insert("k_faces".into(), json!(k.face_list()));
    }
    v
}

fn vector(input: &Input, group: &str) -> Value {
    let tri = Triangulation::from_faces(input.vertex_count, &input.faces)
        .unwrap_or_else(|e| panic!("{}: {e}", input.name));
    let runs: Vec<Value> = ALGORITHMS
        .iter()
        .flat_map(|&alg| SEEDS.map(|seed| run_json(&tri, alg, seed, &input.name)))
        .collect();
    json!({
        "name": input.name,
        "group": group,
        "source": input.source,
        "vertex_count": input.vertex_count,
        "faces": input.faces,
        "euler_characteristic": tri.euler_characteristic(),
        "orientable": tri.is_orientable(),
        "runs": runs,
    })
}

fn generated() -> Vec<Input> {
    RANDOM
        .iter()
        .map(|&(surface, min_faces, flip_percent, seed)| {
            let tri = gen::random(&RandomParams {
                surface,
                min_faces,
                flip_percent,
                seed,
            })
            .expect("a random surface within the limits");
            let (kind, tag, n) = match surface {
                SurfaceKind::Orientable(g) => ("orientable", "S", g),
                SurfaceKind::NonOrientable(h) => ("non_orientable", "N", h),
            };
            Input {
                name: format!("quad_random_{tag}{n}_f{min_faces}_p{flip_percent}_s{seed}"),
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
            }
        })
        .collect()
}

fn main() {
    let root = contractible_tools::repo_root();
    let out_dir = std::env::args()
        .nth(1)
        .map_or_else(|| root.join("spec/vectors"), PathBuf::from);
    std::fs::create_dir_all(&out_dir).expect("create output directory");
    let list = root.join("tests/data/irreducible/surfaces-upto-8-vertices.txt");
    let small: Vec<Input> = contractible::io::list::read_surface_list(&list)
        .unwrap_or_else(|e| panic!("{e}"))
        .into_iter()
        .map(|s| Input {
            name: s.name,
            source: json!({ "file": "tests/data/irreducible/surfaces-upto-8-vertices.txt" }),
            vertex_count: s.vertex_count,
            faces: s.faces,
        })
        .collect();
    let groups = [
        ("quad-surfaces-upto-8-vertices", small),
        ("quad-generated", generated()),
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

/// The perfect matching of Frink's reduction with `strategy`.
fn frink(tri: &Triangulation, strategy: &mut impl quad::frink::Strategy) -> quad::Pairing {
    let (p, _) = quad::frink::perfect_matching_with(tri, strategy).expect("a closed triangulation");
    p
}
