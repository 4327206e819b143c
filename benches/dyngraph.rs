//! The dynamic graph structures of `contractible::dyngraph` alone, on synthetic
//! workloads (no surface involved): HDT connectivity and the 2-edge structure under
//! deletion and reinsertion of every edge of a random cubic multigraph, the link–cut
//! tree under path updates and queries with links and cuts, and the value-free link–cut
//! tree under re-rooted LCA walks. Inputs are deterministic (SplitMix64 from fixed
//! seeds) and built outside the timed region.
//!
//! Run: `cargo bench --bench dyngraph`. Divan reports medians.

use contractible::dyngraph::{ForestChange, Hdt, Lct, PlainLct, TwoEdge};

fn main() {
    divan::main();
}

/// SplitMix64: a small deterministic generator for the workloads.
struct Gen(u64);

impl Gen {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn below(&mut self, k: usize) -> usize {
        (self.next() % k as u64) as usize
    }

    fn shuffle<T>(&mut self, v: &mut [T]) {
        for i in (1..v.len()).rev() {
            v.swap(i, self.below(i + 1));
        }
    }
}

/// A connected bridgeless cubic multigraph on `n` (even) vertices: a ring plus a random
/// perfect matching (parallel edges possible, no loops), as `[id, a, b]`.
fn ring_plus_matching(n: usize, seed: u64) -> Vec<[u32; 3]> {
    let mut g = Gen(seed);
    let mut edges: Vec<[u32; 2]> = (0..n as u32).map(|i| [i, (i + 1) % n as u32]).collect();
    let mut perm: Vec<u32> = (0..n as u32).collect();
    g.shuffle(&mut perm);
    edges.extend(perm.chunks_exact(2).map(|c| [c[0], c[1]]));
    edges
        .into_iter()
        .enumerate()
        .map(|(e, [a, b])| [e as u32, a, b])
        .collect()
}

/// The edge ids of `edges` in a random order.
fn shuffled_ids(edges: &[[u32; 3]], seed: u64) -> Vec<u32> {
    let mut ids: Vec<u32> = edges.iter().map(|t| t[0]).collect();
    Gen(seed).shuffle(&mut ids);
    ids
}

/// A random forest on `n` nodes as a parent array (`u32::MAX`: a root; about one node
/// in 64 a root), parents earlier in a random order.
fn random_parents(n: usize, seed: u64) -> Vec<u32> {
    let mut g = Gen(seed);
    let mut order: Vec<u32> = (0..n as u32).collect();
    g.shuffle(&mut order);
    let mut parent = vec![u32::MAX; n];
    for k in 1..n {
        if g.below(64) != 0 {
            parent[order[k] as usize] = order[g.below(k)];
        }
    }
    parent
}

/// HDT (and under it the Euler-tour trees): every edge of a cubic multigraph on `n`
/// vertices deleted and reinserted at once, in random order, on the loaded graph
/// (`3n/2` deletions, each of a tree edge needing a replacement search about two times
/// in three, and as many insertions).
#[divan::bench(args = [1 << 12, 1 << 16], sample_count = 10, sample_size = 1)]
fn hdt_delete_reinsert(b: divan::Bencher, n: usize) {
    let edges = ring_plus_matching(n, 1);
    let order = shuffled_ids(&edges, 2);
    let mut loaded = Hdt::new(n);
    loaded.load(&edges, &mut Vec::new());
    b.with_inputs(|| loaded.clone())
        .bench_local_values(|mut hdt: Hdt| {
            let mut changes: Vec<ForestChange> = Vec::new();
            for &e in &order {
                let [_, a, c] = edges[e as usize];
                changes.clear();
                hdt.delete(e, &mut changes);
                hdt.insert(e, a, c, &mut changes);
            }
            hdt
        });
}

/// HDT: one-by-one insertion of a cubic multigraph on `n` vertices into the edgeless
/// structure, with `n` connectivity queries between random vertices.
#[divan::bench(args = [1 << 12, 1 << 16], sample_count = 10, sample_size = 1)]
fn hdt_insert_and_query(b: divan::Bencher, n: usize) {
    let mut edges = ring_plus_matching(n, 3);
    Gen(4).shuffle(&mut edges);
    let mut g = Gen(5);
    let queries: Vec<[u32; 2]> = (0..n)
        .map(|_| [g.below(n) as u32, g.below(n) as u32])
        .collect();
    b.with_inputs(|| Hdt::new(n))
        .bench_local_values(|mut hdt: Hdt| {
            let mut changes = Vec::new();
            for &[e, a, c] in &edges {
                hdt.insert(e, a, c, &mut changes);
            }
            let connected = queries
                .iter()
                .filter(|&&[x, y]| hdt.connected(x, y))
                .count();
            (hdt, connected)
        });
}

/// Link–cut tree with values: `n` rounds on a random forest of `n` nodes, each a cut of
/// a random node from its parent and a link to a random node of another tree (else the
/// old parent back), a path addition and a path minimum between random nodes.
#[divan::bench(args = [1 << 12, 1 << 16], sample_count = 10, sample_size = 1)]
fn lct_link_cut_path(b: divan::Bencher, n: usize) {
    let parent = random_parents(n, 6);
    let vals: Vec<i32> = (0..n as i32).map(|i| i % 97).collect();
    let mut g = Gen(7);
    let rounds: Vec<[u32; 4]> = (0..n)
        .map(|_| [0, 0, 0, 0].map(|_: u32| g.below(n) as u32))
        .collect();
    b.with_inputs(|| (Lct::with_parents(&vals, &parent), parent.clone()))
        .bench_local_values(|(mut lct, mut parent): (Lct, Vec<u32>)| {
            let mut sum = 0i64;
            for &[x, y, p, q] in &rounds {
                let old = parent[x as usize];
                if old != u32::MAX {
                    lct.cut(x, old);
                    if lct.connected(x, y) {
                        lct.link(x, old);
                    } else {
                        lct.link(x, y);
                        parent[x as usize] = y;
                    }
                }
                if lct.connected(p, q) {
                    lct.path_add(p, q, 1);
                    sum += i64::from(lct.path_min(q, p));
                }
            }
            (lct, sum)
        });
}

/// Value-free link–cut tree: `n` walks on a random tree of `n` nodes, each a re-rooting
/// at a random node and the LCAs along a walk over three random nodes (`make_root`, then
/// four `walk_to`).
#[divan::bench(args = [1 << 12, 1 << 16], sample_count = 10, sample_size = 1)]
fn plain_lct_walks(b: divan::Bencher, n: usize) {
    // One tree: every walk stays inside it.
    let mut parent = random_parents(n, 8);
    let root = (0..n).find(|&x| parent[x] == u32::MAX).unwrap_or(0);
    for (x, p) in parent.iter_mut().enumerate() {
        if *p == u32::MAX && x != root {
            *p = root as u32;
        }
    }
    let mut g = Gen(9);
    let walks: Vec<[u32; 4]> = (0..n)
        .map(|_| [0, 0, 0, 0].map(|_: u32| g.below(n) as u32))
        .collect();
    b.with_inputs(|| PlainLct::with_parents(&parent))
        .bench_local_values(|mut lct: PlainLct| {
            let mut sum = 0u64;
            for &[r, x, y, z] in &walks {
                lct.make_root(r);
                lct.walk_to(x);
                sum += u64::from(lct.walk_to(y));
                sum += u64::from(lct.walk_to(z));
                sum += u64::from(lct.walk_to(x));
            }
            (lct, sum)
        });
}

/// The 2-edge structure: a cubic multigraph on `n` vertices inserted edge by edge,
/// `n` 2-edge-connectivity queries, then every edge deleted and reinserted at once in
/// random order (its tree-edge deletions scan the smaller side of the cut: the larger
/// size is kept small).
#[divan::bench(args = [1 << 10, 1 << 12], sample_count = 10, sample_size = 1)]
fn two_edge_churn(b: divan::Bencher, n: usize) {
    let edges = ring_plus_matching(n, 10);
    let order = shuffled_ids(&edges, 11);
    let mut g = Gen(12);
    let queries: Vec<[u32; 2]> = (0..n)
        .map(|_| [g.below(n) as u32, g.below(n) as u32])
        .collect();
    b.with_inputs(|| TwoEdge::new(n))
        .bench_local_values(|mut te: TwoEdge| {
            for &[e, a, c] in &edges {
                te.insert(e, a, c);
            }
            let two = queries
                .iter()
                .filter(|&&[x, y]| te.two_edge_connected(x, y))
                .count();
            for &e in &order {
                let [_, a, c] = edges[e as usize];
                te.delete(e);
                te.insert(e, a, c);
            }
            (te, two)
        });
}
