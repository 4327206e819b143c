//! The tri-quad conversion (`quad::convert`, every algorithm) checked through the fuzz
//! harness (`fuzz/src/lib.rs`, `check_quad_algorithm` / `check_quadrangulation`: code that
//! reads only face lists, pairs and quads), and the conformance vectors
//! `spec/vectors/quad-*.jsonl`:
//!
//! 1. **Vectors, exactly**: the library reproduces every stored run of every algorithm
//!    (`K`'s faces for LRS, the pairs before and after the completion, the counters);
//!    the algorithms without randomness give the same run with both seeds. Regenerate with
//!    `cargo run --release -p contractible-tools --bin make_quad_vectors` only for an intended change.
//! 2. **Vectors, independently**: from the stored data alone, the initial pairs are a
//!    pairing and the final pairs a perfect pairing of `K` (pairs share exactly two
//!    vertices), their quads (built here) form a closed quadrangulation of the input's χ
//!    and orientability, the counters agree with the pairs, LRS leaves exactly the face
//!    count of RS's irreducible output unpaired, only LRS flips, and Frink's reduction
//!    (ds, bbdl, frink-lct, ds-naive) pairs every face in its initial step.
//! 3. **Exhaustive twins** of the `quad_ops` fuzz target: every algorithm with seeds
//!    0..4 on every surface of the small published lists and on random vertex splits of
//!    them ([`check_every_algorithm`], called from
//!    `quad_lrs::every_small_surface_and_random_splits_of_it`, which already walks those
//!    surfaces and splits for LRS alone).
//! 4. The harness's checks reject broken conversions (they can fail).

use std::collections::BTreeSet;
use std::panic::{catch_unwind, AssertUnwindSafe};

use crate::harness;
use contractible::irreducible::{rs, Options as ReduceOptions};
use contractible::quad::{self, Algorithm, Options, Pairing};
use contractible::{FaceId, Triangulation};
use serde_json::Value;

use crate::common;

/// The quad vector files and their number of vectors.
const GROUPS: [(&str, usize); 2] = [("quad-surfaces-upto-8-vertices", 57), ("quad-generated", 8)];

/// Seeds of the exhaustive twins.
const TWIN_SEEDS: std::ops::Range<u64> = 0..5;

/// The face count of RS's irreducible output of `t` (what LRS must leave unpaired).
fn reduced_faces(t: &Triangulation) -> usize {
    rs::reduce(
        t.clone(),
        &ReduceOptions {
            seed: 0,
            count_retests: false,
            keep_history: true,
        },
    )
    .tri
    .face_count()
}

/// Every algorithm with seeds 0..4 on `t`, each checked by the harness; LRS and matching
/// take no randomness, so their `K` and pairs must not depend on the seed. Returns the
/// number of conversions checked.
pub(crate) fn check_every_algorithm(t: &Triangulation, label: &str) -> usize {
    let reduced = reduced_faces(t);
    let mut n = 0;
    for alg in harness::QUAD_ALGORITHMS {
        let mut first: Option<(Triangulation, Pairing)> = None;
        for seed in TWIN_SEEDS {
            let q = std::panic::catch_unwind(AssertUnwindSafe(|| {
                harness::check_quad_algorithm(t, alg, seed, reduced)
            }))
            .unwrap_or_else(|_| panic!("{label}: {} seed {seed} failed", alg.name()));
            n += 1;
            if matches!(alg, Algorithm::Lrs | Algorithm::Matching) {
                match &first {
                    None => first = Some((q.tri, q.pairing)),
                    Some((k, p)) => {
                        assert!(*k == q.tri, "{label}: {} K depends on the seed", alg.name());
                        assert_eq!(
                            *p,
                            q.pairing,
                            "{label}: {} pairs depend on the seed",
                            alg.name()
                        );
                    }
                }
            }
        }
    }
    n
}

fn vectors(group: &str) -> Vec<Value> {
    common::read_vectors(group)
}

fn all() -> Vec<Value> {
    common::read_vector_groups(&GROUPS)
}

fn num(v: &Value, key: &str) -> u64 {
    v[key]
        .as_u64()
        .unwrap_or_else(|| panic!("missing number {key}"))
}

fn pairs_of(v: &Value) -> Vec<[u32; 2]> {
    v.as_array()
        .expect("pair array")
        .iter()
        .map(|p| {
            let p = p.as_array().expect("pair");
            assert_eq!(p.len(), 2);
            [0, 1].map(|k| p[k].as_u64().expect("face id") as u32)
        })
        .collect()
}

fn pairs_json(p: &Pairing) -> Vec<[u32; 2]> {
    p.pairs().map(|(f, g)| [f.0, g.0]).collect()
}

/// The run names of a vector, in order (`spec/vectors/README.md`): every algorithm, each
/// with seed 0 then seed 1.
const RUN_ALGORITHMS: [&str; 8] = [
    "lrs",
    "ps",
    "sg",
    "matching",
    "ds",
    "bbdl",
    "frink-lct",
    "ds-naive",
];

/// The runs whose algorithm takes no randomness: seed 0 and seed 1 must agree.
const SEEDLESS: [&str; 6] = ["lrs", "matching", "ds", "bbdl", "frink-lct", "ds-naive"];

/// Frink's reduction: the initial step pairs every face, no completion runs.
const PERFECT_DIRECTLY: [&str; 4] = ["ds", "bbdl", "frink-lct", "ds-naive"];

fn algorithm(name: &str) -> Algorithm {
    name.parse()
        .unwrap_or_else(|e| panic!("unknown algorithm {name}: {e}"))
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

#[test]
fn quad_vector_files_cover_every_algorithm_and_both_seeds() {
    let all = all();
    let names: BTreeSet<&str> = all
        .iter()
        .map(|v| v["name"].as_str().expect("name"))
        .collect();
    assert_eq!(names.len(), all.len(), "duplicate names");
    for v in &all {
        let runs: Vec<(String, u64)> = v["runs"]
            .as_array()
            .expect("runs")
            .iter()
            .map(|r| {
                (
                    r["algorithm"].as_str().expect("algorithm").to_string(),
                    num(r, "seed"),
                )
            })
            .collect();
        let expected: Vec<(String, u64)> = RUN_ALGORITHMS
            .iter()
            .flat_map(|a| [0, 1].map(|s| (a.to_string(), s)))
            .collect();
        assert_eq!(runs, expected, "{}", v["name"]);
        // An algorithm without randomness gives the same run with either seed.
        for pair in v["runs"].as_array().expect("runs").chunks(2) {
            let alg = pair[0]["algorithm"].as_str().expect("algorithm");
            if SEEDLESS.contains(&alg) {
                for key in ["k_faces", "initial_pairs", "pairs", "stats"] {
                    assert_eq!(
                        pair[0].get(key),
                        pair[1].get(key),
                        "{} {alg}: {key} depends on the seed",
                        v["name"]
                    );
                }
            }
        }
    }
}

#[test]
fn library_reproduces_every_quad_vector_exactly() {
    for v in all() {
        let (name, tri) = input(&v);
        for r in v["runs"].as_array().expect("runs") {
            let alg = algorithm(r["algorithm"].as_str().expect("algorithm"));
            let seed = num(r, "seed");
            let label = format!("{name} {} seed {seed}", alg.name());
            let opts = Options { seed };
            let initial = match alg {
                Algorithm::Lrs => quad::lrs::initial_pairing(tri.clone()).pairing,
                Algorithm::PulliSegal => quad::pulli_segal::initial_pairing(&tri, &opts),
                Algorithm::SimpleGreedy => quad::greedy::initial_pairing(&tri, &opts),
                Algorithm::Matching => quad::matching::initial_pairing(&tri),
                Algorithm::DsNaive => {
                    quad::frink::perfect_matching(&tri).expect("a closed triangulation")
                }
                Algorithm::FrinkLct => {
                    let mut s = quad::frink::CoverTree::new();
                    let (p, _) = quad::frink::perfect_matching_with(&tri, &mut s)
                        .expect("a closed triangulation");
                    p
                }
                Algorithm::DiksStanczyk => {
                    let mut s = quad::frink::DiksStanczyk::new();
                    let (p, _) = quad::frink::perfect_matching_with(&tri, &mut s)
                        .expect("a closed triangulation");
                    p
                }
                Algorithm::BiedlBoseDemaineLubiw => {
                    let mut s = quad::frink::BiedlBoseDemaineLubiw::new();
                    let (p, _) = quad::frink::perfect_matching_with(&tri, &mut s)
                        .expect("a closed triangulation");
                    p
                }
            };
            assert_eq!(
                pairs_json(&initial),
                pairs_of(&r["initial_pairs"]),
                "{label}: initial pairs"
            );
            let q = quad::convert(tri.clone(), alg, &opts).expect("a closed triangulation");
            assert_eq!(
                pairs_json(&q.pairing),
                pairs_of(&r["pairs"]),
                "{label}: pairs"
            );
            if alg == Algorithm::Lrs {
                assert_eq!(
                    q.tri.face_list(),
                    common::json_faces(&r["k_faces"]),
                    "{label}: K"
                );
            } else {
                assert!(
                    r.get("k_faces").is_none(),
                    "{label}: K stored for a non-LRS run"
                );
            }
            let s = &r["stats"];
            assert_eq!(
                [
                    q.stats.faces,
                    q.stats.initial_unpaired,
                    q.stats.flips,
                    q.stats.augmenting_paths,
                    q.stats.phases
                ]
                .map(|x| x as u64),
                [
                    num(s, "faces"),
                    num(s, "initial_unpaired"),
                    num(s, "flips"),
                    num(s, "augmenting_paths"),
                    num(s, "phases")
                ],
                "{label}: stats"
            );
        }
    }
}

/// The vertex lists of `faces` by id, checked to form a pairing: distinct faces, each
/// in at most one pair, sharing exactly two vertices. Returns how many faces are paired.
fn check_stored_pairing(faces: &[[u32; 3]], pairs: &[[u32; 2]], label: &str) -> usize {
    let mut used = vec![false; faces.len()];
    for &[f, g] in pairs {
        assert!(f < g, "{label}: pair ({f}, {g}) not in increasing order");
        for h in [f, g] {
            let slot = used
                .get_mut(h as usize)
                .unwrap_or_else(|| panic!("{label}: face {h} out of range"));
            assert!(!*slot, "{label}: face {h} in two pairs");
            *slot = true;
        }
        let (a, b) = (faces[f as usize], faces[g as usize]);
        let shared = a.iter().filter(|v| b.contains(v)).count();
        assert_eq!(
            shared, 2,
            "{label}: pair ({f}, {g}) shares {shared} vertices"
        );
    }
    2 * pairs.len()
}

/// The quad of two triangles sharing an edge, built here: `f`'s third vertex, then `f`'s
/// slot order around the quad (`[c, a, d, b]` for `f = (c, a, b)` and `d` the third
/// vertex of `g`).
fn quad(f: [u32; 3], g: [u32; 3]) -> [u32; 4] {
    let k = (0..3)
        .find(|&k| !g.contains(&f[k]))
        .expect("a vertex of f not in g");
    let d = *g
        .iter()
        .find(|v| !f.contains(v))
        .expect("a vertex of g not in f");
    [f[k], f[(k + 1) % 3], d, f[(k + 2) % 3]]
}

#[test]
fn stored_quad_vectors_are_valid_independently() {
    let rs_outputs: std::collections::HashMap<String, usize> = vectors("surfaces-upto-8-vertices")
        .iter()
        .map(|v| {
            (
                v["name"].as_str().expect("name").to_string(),
                v["output_faces"].as_array().expect("output").len(),
            )
        })
        .collect();
    let mut cross_checked = 0;
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let faces = common::json_faces(&v["faces"]);
        let (chi, orientable) =
            contractible::spec::oracle::euler_and_orientability(&faces).expect("closed surface");
        assert_eq!(v["euler_characteristic"].as_i64(), Some(chi), "{name}");
        assert_eq!(v["orientable"].as_bool(), Some(orientable), "{name}");
        let in_edges = edge_set(&faces);
        for r in v["runs"].as_array().expect("runs") {
            let label = format!("{name} {} seed {}", r["algorithm"], r["seed"]);
            let k = if r["algorithm"] == "lrs" {
                common::json_faces(&r["k_faces"])
            } else {
                faces.clone()
            };
            assert_eq!(k.len(), faces.len(), "{label}: face count of K");
            assert_eq!(
                contractible::spec::oracle::euler_and_orientability(&k),
                Some((chi, orientable)),
                "{label}: K's surface"
            );
            let s = &r["stats"];
            let k_edges = edge_set(&k);
            let changed = in_edges.difference(&k_edges).count();
            assert!(
                changed as u64 <= num(s, "flips"),
                "{label}: K differs in {changed} edges"
            );
            let initial = check_stored_pairing(&k, &pairs_of(&r["initial_pairs"]), &label);
            let full_pairs = pairs_of(&r["pairs"]);
            let full = check_stored_pairing(&k, &full_pairs, &label);
            assert_eq!(full, k.len(), "{label}: not perfect");
            assert_eq!(num(s, "faces") as usize, k.len(), "{label}");
            assert_eq!(
                num(s, "initial_unpaired") as usize,
                k.len() - initial,
                "{label}"
            );
            assert_eq!(
                num(s, "augmenting_paths") as usize,
                (full - initial) / 2,
                "{label}: one augmenting path per added pair"
            );
            let alg = r["algorithm"].as_str().expect("algorithm");
            if alg != "lrs" {
                assert_eq!(num(s, "flips"), 0, "{label}: flips without LRS");
            }
            if PERFECT_DIRECTLY.contains(&alg) {
                // Frink's reduction pairs every face itself: nothing left to complete.
                assert_eq!(initial, k.len(), "{label}: initial step not perfect");
                assert_eq!(
                    [num(s, "augmenting_paths"), num(s, "phases")],
                    [0, 0],
                    "{label}: a completion ran"
                );
            }
            if alg == "lrs" {
                if let Some(&reduced) = rs_outputs.get(name) {
                    assert_eq!(k.len() - initial, reduced, "{label}: n'_f");
                    cross_checked += 1;
                }
            }
            let quads: Vec<[u32; 4]> = full_pairs
                .iter()
                .map(|&[f, g]| quad(k[f as usize], k[g as usize]))
                .collect();
            let (quad_chi, quad_orientable) = harness::check_closed_quad_surface(&quads, &label);
            assert_eq!(
                (quad_chi, quad_orientable),
                (chi, orientable),
                "{label}: quad surface"
            );
        }
    }
    assert_eq!(
        cross_checked,
        2 * 57,
        "LRS runs cross-checked with the RS vectors"
    );
}

fn edge_set(faces: &[[u32; 3]]) -> BTreeSet<(u32, u32)> {
    faces
        .iter()
        .flat_map(|&[a, b, c]| [(a, b), (b, c), (c, a)])
        .map(|(x, y)| (x.min(y), x.max(y)))
        .collect()
}

/// A conversion of the octahedron and a broken copy of it, for the tests below.
fn octahedron_conversion(alg: Algorithm) -> (Triangulation, quad::Quadrangulation) {
    let m = contractible::gen::octahedron();
    let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("octahedron");
    let q = quad::convert(t.clone(), alg, &Options { seed: 3 }).expect("a closed triangulation");
    harness::check_quadrangulation(&t, &q, "octahedron");
    (t, q)
}

/// Asserts that the harness rejects `q` for the reason `because` (a substring of its
/// panic message), not for an unrelated failure.
fn rejects(t: &Triangulation, q: &quad::Quadrangulation, what: &str, because: &str) {
    let r = catch_unwind(AssertUnwindSafe(|| {
        harness::check_quadrangulation(t, q, what)
    }));
    let err = r
        .err()
        .unwrap_or_else(|| panic!("the harness accepted {what}"));
    let msg = err
        .downcast_ref::<String>()
        .cloned()
        .unwrap_or_else(|| "non-string panic".into());
    assert!(
        msg.contains(because),
        "{what}: rejected for another reason: {msg}"
    );
}

#[test]
fn the_harness_rejects_broken_conversions() {
    let mut flipped = 0;
    for alg in harness::QUAD_ALGORITHMS {
        let (t, q) = octahedron_conversion(alg);
        // A pair removed: not perfect.
        let mut b = q.clone();
        b.pairing.unpair(FaceId(0));
        rejects(&t, &b, "a pairing with two faces unpaired", "in 0 pairs");
        // An unreported flip in K.
        let mut b = q.clone();
        // An edge of the input too, so the flip cannot undo one of LRS's flips.
        let c = b.tri.edges().map(|(_, _, c)| c).find(|&c| {
            let [x, y] = b.tri.edge_endpoints(c);
            b.tri.is_flippable(x, y) && t.edge_link(x, y).is_some()
        });
        if let Some(c) = c {
            b.tri.flip_at(c).expect("flippable");
            b.stats.flips = 0;
            b.pairing = Pairing::new(b.tri.face_capacity());
            quad::augment::complete(&b.tri, &mut b.pairing).expect("a closed triangulation");
            b.stats.augmenting_paths = b.pairing.len();
            b.stats.initial_unpaired = b.tri.face_count();
            b.stats.initial_paired_percent = 0.0;
            rejects(&t, &b, "K with an unreported flip", "K differs in");
            flipped += 1;
        }
        // Counters that disagree.
        let mut b = q.clone();
        b.stats.augmenting_paths += 1;
        rejects(
            &t,
            &b,
            "an augmenting path count off by one",
            "each augmenting path pairs two faces",
        );
    }
    assert_eq!(
        flipped,
        harness::QUAD_ALGORITHMS.len(),
        "an unreported flip tried for every algorithm"
    );
}

#[test]
fn the_quad_surface_check_rejects_non_manifolds_and_finds_non_orientable_ones() {
    let r = |quads: Vec<[u32; 4]>| {
        catch_unwind(AssertUnwindSafe(|| {
            harness::check_closed_quad_surface(&quads, "bad")
        }))
        .is_err()
    };
    // The cube: closed, orientable, χ = 2.
    let cube = vec![
        [0, 3, 2, 1],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    assert_eq!(harness::check_closed_quad_surface(&cube, "cube"), (2, true));
    // One face reversed: still a closed orientable surface (the check orients it).
    let mut flipped = cube.clone();
    flipped[0] = [0, 1, 2, 3];
    assert_eq!(
        harness::check_closed_quad_surface(&flipped, "cube"),
        (2, true)
    );
    // A face missing: an edge in one quad.
    assert!(r(cube[1..].to_vec()));
    // A repeated vertex.
    let mut rep = cube.clone();
    rep[0] = [0, 3, 0, 1];
    assert!(r(rep));
    // Two cubes glued at a vertex: edges fine, the link of the vertex is two cycles.
    let mut pinched = cube.clone();
    pinched.extend(
        cube.iter()
            .map(|q| q.map(|v| if v == 0 { 0 } else { v + 10 })),
    );
    assert!(r(pinched));
    // The 4x4 grid with the Klein bottle's identifications: non-orientable, χ = 0.
    let n = 4u32;
    let id = |i: u32, j: u32| -> u32 {
        let (i, j) = if i == n { (0, n - j) } else { (i, j) };
        let (i, j) = (i % n, j % n);
        i * n + j
    };
    let klein: Vec<[u32; 4]> = (0..n)
        .flat_map(|i| (0..n).map(move |j| (i, j)))
        .map(|(i, j)| [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)])
        .collect();
    assert_eq!(
        harness::check_closed_quad_surface(&klein, "klein"),
        (0, false)
    );
}
