//! Tri-quad conversion: LRS, PS, SG and the graph route (Edmonds from empty) on
//! the same inputs in one run, so that every ratio compares medians of one run. Inputs:
//! the paper's bricks (`gen::paper_family`: B0 is the tri-quad paper's A1, C0 its B1; see
//! `docs/benchmarks.md`), a subset of the B and C families, and the biggest component of
//! every real mesh of the corpus (`$CONTRACTIBLE_CORPUS/meshes/closed/`, else
//! `../shared/meshes/closed/`) with at least 80,000 triangles.
//!
//! Groups (filter with the group name, e.g. `cargo bench --bench quad -- total`):
//! - `total` (3 samples): `quad::convert` (initial step + completion, as the CLI runs it;
//!   the input is cloned outside the timed region);
//! - `initial` (3 samples): the initial step alone (for LRS: RS contraction + expansion);
//! - `completion` (3 samples): `augment::complete` on the initial pairing of each
//!   algorithm (computed once, outside the timed region; the pairing is cloned outside
//!   it too);
//! - `petgraph`: the baseline, `petgraph::algo::maximum_matching` on the dual graph,
//!   the dual graph build included (as `total` includes ours); 2 samples (seconds each).
//!
//! Every algorithm uses seed 1. Run: `cargo bench --bench quad > quad.txt` (about
//! 11 minutes at load 5-10 on the shared 2-core machine, an estimated 4 idle; petgraph
//! takes the largest part), then
//! `python3 docs/quad_bench_table.py quad.txt`. The default inputs are B0, B2, B4, C0,
//! C2, C4 and the meshes; `QUAD_BENCH_ALL=1 cargo bench --bench quad` runs every member
//! B0–B9 and C0–C7 (about 3 more minutes idle). Filter as usual, e.g.
//! `cargo bench --bench quad -- total` or `-- petgraph`.

use contractible::gen::paper_family;
use contractible::quad::{self, augment};
use contractible::quad::{Algorithm, Options, Pairing};
use contractible::{Surfaces, Triangulation};
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

fn main() {
    divan::main();
}

const OPTIONS: Options = Options { seed: 1 };

/// The real meshes of the corpus with at least 80,000 triangles.
const MESHES: &[&str] = &[
    "mesh:armadillo",
    "mesh:botijo",
    "mesh:horse_48k",
    "mesh:lucy_100k",
    "mesh:screw_remeshed",
    "mesh:sketched_brunnen",
    "mesh:turbineblade",
    "mesh:venus",
];

/// Every input of the `total`, `initial` and `completion` groups.
fn inputs() -> Vec<&'static str> {
    let all = std::env::var_os("QUAD_BENCH_ALL").is_some();
    let mut v: Vec<&'static str> = if all {
        vec![
            "B0", "B1", "B2", "B3", "B4", "B5", "B6", "B7", "B8", "B9", "C0", "C1", "C2", "C3",
            "C4", "C5", "C6", "C7",
        ]
    } else {
        vec!["B0", "B2", "B4", "C0", "C2", "C4"]
    };
    v.extend_from_slice(MESHES);
    v
}

/// Inputs are built once per process and shared by every algorithm.
fn input(name: &str) -> Triangulation {
    static CACHE: OnceLock<Mutex<HashMap<String, Triangulation>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = cache.lock().expect("cache");
    map.entry(name.to_string())
        .or_insert_with(|| build(name))
        .clone()
}

fn build(name: &str) -> Triangulation {
    let mesh = if let Some(file) = name.strip_prefix("mesh:") {
        // Real meshes come from the corpus (CONTRACTIBLE_CORPUS, else ../shared).
        let corpus = std::env::var("CONTRACTIBLE_CORPUS")
            .unwrap_or_else(|_| format!("{}/../shared", env!("CARGO_MANIFEST_DIR")));
        let path = format!("{corpus}/meshes/closed/{file}.off.gz");
        contractible::io::read_tri_mesh(path.as_ref())
            .unwrap_or_else(|e| panic!("the real-mesh corpus: {e}"))
    } else {
        let mut c = name.chars();
        let group = c.next().expect("group letter");
        paper_family(group, c.as_str().parse().expect("member index"))
            .expect("valid brick parameters")
    };
    let s = Surfaces::from_mesh(&mesh).expect("closed surface");
    s.components
        .into_iter()
        .max_by_key(|c| c.tri.face_count())
        .expect("a component")
        .tri
}

/// The paired triangulation and initial pairing of `alg` on `name`, computed once.
fn initial(name: &str, alg: Algorithm) -> (Triangulation, Pairing) {
    type Key = (String, &'static str);
    static CACHE: OnceLock<Mutex<HashMap<Key, (Triangulation, Pairing)>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    let key = (name.to_string(), alg.name());
    if let Some(v) = cache.lock().expect("cache").get(&key) {
        return v.clone();
    }
    let v = initial_step(input(name), alg);
    cache.lock().expect("cache").insert(key, v.clone());
    v
}

fn initial_step(t: Triangulation, alg: Algorithm) -> (Triangulation, Pairing) {
    let i = contractible::quad::initial_pairing(t, alg, &OPTIONS).expect("a closed triangulation");
    (i.tri, i.pairing)
}

fn total(b: divan::Bencher, name: &str, alg: Algorithm) {
    let t = input(name);
    b.with_inputs(|| t.clone())
        .bench_local_values(|t| quad::convert(t, alg, &OPTIONS).expect("a closed triangulation"));
}

fn init(b: divan::Bencher, name: &str, alg: Algorithm) {
    let t = input(name);
    b.with_inputs(|| t.clone())
        .bench_local_values(|t| initial_step(t, alg));
}

fn completion(b: divan::Bencher, name: &str, alg: Algorithm) {
    let (t, p) = initial(name, alg);
    b.with_inputs(|| p.clone())
        .bench_local_refs(|p| augment::complete(&t, p).expect("a closed triangulation"));
}

/// One bench per algorithm of the group (`$name => $alg`), all on [`inputs`].
macro_rules! group {
    ($group:ident, $run:ident, $samples:expr, [$($name:ident => $alg:ident),*]) => {
        #[divan::bench_group(sample_count = $samples, sample_size = 1)]
        mod $group {
            use super::*;
            $(
                #[divan::bench(args = inputs())]
                fn $name(b: divan::Bencher, name: &str) {
                    $run(b, name, Algorithm::$alg)
                }
            )*
        }
    };
}

// The graph route's initial step is the empty pairing and its completion is its total,
// so it appears in `total` only.
group!(total, total, 3, [lrs => Lrs, ps => PulliSegal, sg => SimpleGreedy, matching => Matching]);
group!(initial, init, 3, [lrs => Lrs, ps => PulliSegal, sg => SimpleGreedy]);
group!(completion, completion, 3, [lrs => Lrs, ps => PulliSegal, sg => SimpleGreedy]);

/// The dual graph as a petgraph `UnGraph` (copied from `tests/common/mod.rs`).
fn dual_graph(t: &Triangulation) -> petgraph::graph::UnGraph<contractible::FaceId, ()> {
    let mut g = petgraph::graph::UnGraph::with_capacity(t.face_count(), t.edge_count());
    let mut node = vec![petgraph::graph::NodeIndex::end(); t.face_capacity()];
    for f in t.faces() {
        node[f.index()] = g.add_node(f);
    }
    for (_, _, c) in t.edges() {
        let o = t.opposite(c);
        g.add_edge(node[c.face().index()], node[o.face().index()], ());
    }
    g
}

/// petgraph's Gabow matching is recursive; it runs on a thread with a 1 GiB stack (the
/// spawn costs microseconds against seconds of matching).
#[divan::bench(args = MESHES, sample_count = 2, sample_size = 1)]
fn petgraph(b: divan::Bencher, name: &str) {
    let t = input(name);
    b.bench_local(|| {
        std::thread::scope(|s| {
            std::thread::Builder::new()
                .stack_size(1 << 30)
                .spawn_scoped(s, || {
                    let g = dual_graph(&t);
                    let m = petgraph::algo::maximum_matching(&g);
                    assert_eq!(2 * m.len(), t.face_count(), "perfect matching");
                    m.len()
                })
                .expect("spawn")
                .join()
                .expect("matching thread")
        })
    });
}
