//! Frink's reduction: `frink::solve` on the dual graph of the paper's bricks
//! B9…B0 (16k to 4.2M triangles, genus 0; `gen::paper_family`, see `docs/benchmarks.md`)
//! with the Diks–Stańczyk strategy (`ds`, O(F log² F)), the Biedl–Bose–Demaine–Lubiw
//! strategy (`bbdl`, B9…B5 only: its 2-edge structure is not polylogarithmic), the
//! link–cut cover-count
//! strategy (`lct`), and with the naive DFS strategy (`naive`, O(F²)) on the small
//! members only. The dual graph is built outside the timed
//! region (and cloned outside it: `solve` consumes it).
//!
//! Run: `cargo bench --bench frink > frink.txt` (about 10 minutes at load 5-10 on the
//! shared 2-core machine). `FRINK_BENCH_C=1` adds C9…C0 (genus 3,500) to `ds` and `lct`.

use contractible::gen::paper_family;
use contractible::quad::frink::{
    self, BiedlBoseDemaineLubiw, CoverTree, Cubic, DiksStanczyk, Naive,
};
use contractible::Surfaces;
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

fn main() {
    divan::main();
}

fn lct_inputs() -> Vec<&'static str> {
    let mut v = vec!["B9", "B8", "B7", "B6", "B5", "B4", "B3", "B2", "B1", "B0"];
    if std::env::var_os("FRINK_BENCH_C").is_some() {
        v.extend(["C9", "C8", "C7", "C6", "C5", "C4", "C3", "C2", "C1", "C0"]);
    }
    v
}

const NAIVE_INPUTS: &[&str] = &["B9", "B8", "B7"];

/// BBDL's 2-edge structure is not polylogarithmic (module `dyngraph::two_edge`): the
/// smaller members only.
const BBDL_INPUTS: &[&str] = &["B9", "B8", "B7", "B6", "B5"];

/// The dual graph of the biggest component of a family member, built once per process.
fn dual(name: &str) -> Cubic {
    static CACHE: OnceLock<Mutex<HashMap<String, Cubic>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    let mut map = cache.lock().expect("cache");
    map.entry(name.to_string())
        .or_insert_with(|| {
            let mut c = name.chars();
            let group = c.next().expect("group letter");
            let mesh = paper_family(group, c.as_str().parse().expect("member index"))
                .expect("valid brick parameters");
            let s = Surfaces::from_mesh(&mesh).expect("closed surface");
            let t = s
                .components
                .into_iter()
                .max_by_key(|c| c.tri.face_count())
                .expect("a component")
                .tri;
            eprintln!("{name}: {} triangles", t.face_count());
            frink::dual_graph(&t).expect("dual graph").0
        })
        .clone()
}

#[divan::bench(args = lct_inputs(), sample_count = 3, sample_size = 1)]
fn ds(b: divan::Bencher, name: &str) {
    let g = dual(name);
    b.with_inputs(|| g.clone())
        .bench_local_values(|g| frink::solve(g, &mut DiksStanczyk::new()).expect("bridgeless"));
}

#[divan::bench(args = BBDL_INPUTS, sample_count = 3, sample_size = 1)]
fn bbdl(b: divan::Bencher, name: &str) {
    let g = dual(name);
    b.with_inputs(|| g.clone()).bench_local_values(|g| {
        frink::solve(g, &mut BiedlBoseDemaineLubiw::new()).expect("bridgeless")
    });
}

#[divan::bench(args = lct_inputs(), sample_count = 3, sample_size = 1)]
fn lct(b: divan::Bencher, name: &str) {
    let g = dual(name);
    b.with_inputs(|| g.clone())
        .bench_local_values(|g| frink::solve(g, &mut CoverTree::new()).expect("bridgeless"));
}

#[divan::bench(args = NAIVE_INPUTS, sample_count = 3, sample_size = 1)]
fn naive(b: divan::Bencher, name: &str) {
    let g = dual(name);
    b.with_inputs(|| g.clone())
        .bench_local_values(|g| frink::solve(g, &mut Naive::new()).expect("bridgeless"));
}
