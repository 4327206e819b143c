//! Schipper's algorithm S, as the RS paper describes it (Sec. 3, l.326-340; behaviour
//! discussed in Sec. 5.2, l.1290-1330).
//!
//! # The algorithm
//! - Every vertex `u` has a dictionary `D_u` of its neighbours (here a sorted `Vec<u32>`,
//!   looked up by binary search).
//! - The *loose* vertices (not yet found trapped) are kept in a global dictionary ordered
//!   by current degree (a `BTreeSet<(degree, vertex)>`).
//! - Repeat: take a loose vertex `u` of lowest degree (ties: smallest id). Walk its star
//!   ([`Triangulation::star`], so its edges in link order from
//!   [`Triangulation::corner_of`]) and test each edge `[u, w]` against the link
//!   condition, until one passes: then `u` is identified with `w` (the contraction keeps
//!   `w`, see below) and the loop restarts with the new lowest-degree loose vertex. If
//!   none passes, `u` is trapped and leaves the dictionary for good: by Lemma 5 (l.392) a
//!   trapped vertex stays trapped, and a trapped vertex is never an endpoint of a
//!   contracted edge. When no loose vertex remains, every vertex is trapped, so the
//!   output is irreducible.
//!
//! # The link test with dictionaries (l.327-331)
//! `[u, w]` with link `{x, y}` passes iff the surface is not T4 and no `z ∈ lk(u)`,
//! `z ∉ {w, x, y}`, is in `D_w`: O(d_u log d_w), with `u` the low-degree endpoint. Each
//! such test counts once in ℓ, including the ones the T4 check decides (S has no Prop. 6
//! shortcut), and the same edge may be tested many times (ε, via
//! [`super::RetestCounter`]).
//!
//! # Which endpoint survives
//! The contraction of `[u, w]` identifies the lowest-degree loose vertex `u` with its
//! neighbour `w` ([`Triangulation::contract_tested`]`(w, u)`): `w` survives. Since `w`
//! passed the test it is loose, so `d_w >= d_u`; removing the low-degree endpoint keeps
//! the contraction at O(d_u) and the dictionary work small.
//!
//! # Maintenance at a contraction (`u` into `w`, link `{x, y}`)
//! `D_w` gains `lk(u) \ {w, x, y}` and loses `u`; each `z ∈ lk(u) \ {w, x, y}` replaces
//! `u` by `w` in `D_z`; `D_x` and `D_y` lose `u`; `D_u` is freed. In the degree
//! dictionary `w`, `x` and `y` are re-keyed if they are loose (their degrees changed) and
//! `u` leaves.
//!
//! # Cost
//! Schipper's bound is O(n log n + g log n + g⁴) time with balanced-tree dictionaries.
//! This implementation uses sorted vectors, so a lookup is O(log d) but an insertion or
//! removal is O(log d) search plus an O(d) shift (a `memmove` of 4-byte entries). One
//! test costs O(d_u log d_w); one contraction O(d_u + d_w + Σ_{z ∈ lk(u)} d_z) for the
//! dictionaries (one merge into `D_w`, one remove and insert per other neighbour) plus O(log n) per re-keyed vertex; picking the next vertex O(log n). On
//! the usual inputs degrees stay small and this behaves like the balanced-tree version;
//! a vertex whose degree grows to Θ(n) would make contractions into it Θ(n) each.
//! Space: O(n + F).
//!
//! Deterministic: no randomness is used (`options.seed` is ignored).

use std::collections::BTreeSet;
use std::time::Instant;

use super::{Algorithm, Options, Reduction, RetestCounter};
use crate::core::{Corner, History, Triangulation, VertexId};
use crate::progress::{self, Progress, Throttle};

/// Runs S on `tri` (see the module documentation).
pub fn reduce(tri: Triangulation, options: &Options) -> Reduction {
    reduce_observed(tri, options, &mut progress::ignore)
}

/// [`reduce`], reporting the vertices settled (trapped or contracted away: no longer
/// loose) out of the input's vertices to `observer`, at most every
/// [`progress::REPORT_EVERY`] vertices examined. Same result as [`reduce`].
pub fn reduce_observed(
    mut tri: Triangulation,
    options: &Options,
    observer: &mut dyn FnMut(Progress),
) -> Reduction {
    const STAGE: &str = "vertices settled";
    let total = tri.vertex_count() as u64;
    observer(Progress::new(STAGE, 0, total));
    let mut throttle = Throttle::new();
    let mut examined = 0u64;
    let started = Instant::now();
    let mut stats = super::start_stats(&tri);
    let mut history = History::new();
    let mut contractions = 0u64;
    let mut counter = RetestCounter::new(&tri, options.count_retests);

    let n = tri.vertex_capacity();
    let mut dict: Vec<Vec<u32>> = vec![Vec::new(); n];
    // The degree under which a loose vertex is filed in `loose` (u32::MAX: not loose).
    let mut key = vec![u32::MAX; n];
    let mut loose: BTreeSet<(u32, u32)> = BTreeSet::new();
    for v in tri.vertices() {
        let mut d: Vec<u32> = tri.link(v).map(|w| w.0).collect();
        d.sort_unstable();
        dict[v.index()] = d;
        let deg = tri.degree(v) as u32;
        key[v.index()] = deg;
        loose.insert((deg, v.0));
    }

    // Edges of the vertex being examined: (neighbour, corner opposite the edge).
    let mut edges: Vec<(VertexId, Corner)> = Vec::new();
    while let Some(&(_, u_raw)) = loose.first() {
        examined += 1;
        if throttle.due(examined) {
            observer(Progress::new(STAGE, total - loose.len() as u64, total));
        }
        let u = VertexId(u_raw);
        edges.clear();
        for s in tri.star(u) {
            edges.push((s.neighbour, tri.corner_facing(s.corner, s.neighbour)));
        }
        let mut contracted = false;
        for &(w, c) in &edges {
            stats.link_tests += 1;
            counter.tested(c);
            let x = tri.vertex(c);
            let y = tri.vertex(tri.opposite(c));
            if !passes(&tri, &dict, u, w, x, y) {
                continue;
            }
            let rec = tri.contract_tested(w, u, &mut history);
            contractions += 1;
            if !options.keep_history {
                history.forget();
            }
            counter.contracted(&rec);
            update_dictionaries(&mut dict, u, w, x, y);
            loose.remove(&(key[u.index()], u.0));
            key[u.index()] = u32::MAX;
            for z in [w, x, y] {
                let k = key[z.index()];
                if k != u32::MAX {
                    loose.remove(&(k, z.0));
                    let deg = tri.degree(z) as u32;
                    key[z.index()] = deg;
                    loose.insert((deg, z.0));
                }
            }
            contracted = true;
            break;
        }
        if !contracted {
            // Trapped, and trapped for good (Lemma 5).
            loose.remove(&(key[u.index()], u.0));
            key[u.index()] = u32::MAX;
        }
    }

    observer(Progress::new(STAGE, total, total));
    stats.edges_tested_more_than_once = counter.more_than_once();
    super::finish(
        Algorithm::Schipper,
        tri,
        history,
        contractions,
        stats,
        started,
    )
}

/// The dictionary form of the link condition for edge `[u, w]` with link `{x, y}`.
fn passes(
    tri: &Triangulation,
    dict: &[Vec<u32>],
    u: VertexId,
    w: VertexId,
    x: VertexId,
    y: VertexId,
) -> bool {
    if tri.is_tetrahedron() {
        // lk(u) ∩ lk(w) would contain the edge [x, y] (Prop. 6).
        return false;
    }
    let dw = &dict[w.index()];
    !dict[u.index()]
        .iter()
        .any(|&z| z != w.0 && z != x.0 && z != y.0 && dw.binary_search(&z).is_ok())
}

/// Inserts `v` into the sorted vector `d` (it must be absent).
fn insert_sorted(d: &mut Vec<u32>, v: u32) {
    let i = d
        .binary_search(&v)
        .expect_err("neighbour dictionaries out of date");
    d.insert(i, v);
}

/// Removes `v` from the sorted vector `d` (it must be there).
fn remove_sorted(d: &mut Vec<u32>, v: u32) {
    let i = d
        .binary_search(&v)
        .expect("neighbour dictionaries out of date");
    d.remove(i);
}

/// Updates the dictionaries after `u` was identified with `w` (link `{x, y}`).
fn update_dictionaries(dict: &mut [Vec<u32>], u: VertexId, w: VertexId, x: VertexId, y: VertexId) {
    let du = std::mem::take(&mut dict[u.index()]);
    // Π = lk(u) \ {w, x, y}, sorted since D_u is.
    let pi: Vec<u32> = du
        .iter()
        .copied()
        .filter(|&z| z != w.0 && z != x.0 && z != y.0)
        .collect();
    remove_sorted(&mut dict[x.index()], u.0);
    remove_sorted(&mut dict[y.index()], u.0);
    for &z in &pi {
        let dz = &mut dict[z as usize];
        remove_sorted(dz, u.0);
        insert_sorted(dz, w.0);
    }
    // D_w := (D_w \ {u}) ∪ Π by one merge, O(d_u + d_w). Π and D_w are disjoint (a
    // common neighbour other than x and y would have failed the link condition).
    let dw = std::mem::take(&mut dict[w.index()]);
    let mut merged = Vec::with_capacity(dw.len() + pi.len());
    let (mut i, mut j) = (0, 0);
    while i < dw.len() || j < pi.len() {
        if j == pi.len() || (i < dw.len() && dw[i] < pi[j]) {
            if dw[i] != u.0 {
                merged.push(dw[i]);
            }
            i += 1;
        } else {
            debug_assert!(i == dw.len() || dw[i] != pi[j], "Π meets D_w");
            merged.push(pi[j]);
            j += 1;
        }
    }
    dict[w.index()] = merged;
}
