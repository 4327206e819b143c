//! The randomized brute force BF of the RS paper (Sec. 5, l.1016-1024).
//!
//! 1. Put every edge of the input in an array and shuffle it with the documented stream
//!    ([`crate::rng::Rng::new`]`(options.seed)`, [`crate::rng::Rng::shuffle`]).
//! 2. Visit the array in order. An edge removed by an earlier contraction is skipped;
//!    every other edge is tested against the link condition. If it passes it is
//!    contracted, otherwise it goes to an auxiliary array.
//! 3. When the array is exhausted, the auxiliary array (in the order the failures were
//!    found) becomes the array and step 2 repeats. A pass without a contraction ends the
//!    algorithm.
//!
//! # Guarantee
//! The output is irreducible: the last pass tested every edge still alive (all of them
//! were in the array, since an edge is only ever dropped when it dies) and contracted
//! none, and nothing changed during that pass, so every edge fails the link condition.
//! Every contraction passed the link condition, so the surface (χ, orientability) is the
//! input's.
//!
//! # Edge identity
//! Edges are numbered by [`EdgeNumbering`] (in [`Triangulation::edges`] order) and keep
//! their number across contractions as it defines identity: a renamed edge
//! `[v, z] → [u, z]` keeps its number; the merged edge `[u, x]` keeps the number of the
//! old `[u, x]`, while `[u, v]`, `[v, x]` and `[v, y]` die (like the DCEL record removed
//! by Alg. 4.7). The edge stored as number `e` is tested through the live corner
//! [`EdgeNumbering::corner`] gives for it.
//!
//! # Which endpoint survives
//! The edge stored as corner `c` is contracted as [`Triangulation::contract_tested`]`(a,
//! b)` with `[a, b] = `[`Triangulation::edge_endpoints`]`(c)`: `b` is identified with the
//! first endpoint `a`.
//!
//! # Cost
//! One link test is the marked test [`LinkTester::test`], O(d_a + d_b); it is counted as
//! one test in ℓ (the T4 check of Prop. 6 included). A pass over `m` edges costs
//! O(m · d_max); there can be Θ(n) passes, and the brute force may carry out Ω(n²) link
//! tests (the sphere of Fig. 6, if the shuffle puts the non-contractible edges first),
//! so the worst case is O(n² · d_max) time. Space: O(F) beyond the triangulation (edge
//! numbers per corner, two edge arrays).
//!
//! # Determinism
//! The output (triangulation, history, counters except `seconds`) is a function of the
//! input triangulation (including its ids and corner slots) and `options.seed`.

use std::time::Instant;

use super::{Algorithm, Options, Reduction, RetestCounter};
use crate::core::{EdgeId, EdgeNumbering, History, LinkTester, Triangulation};
use crate::progress::{self, Progress, Throttle};
use crate::rng::Rng;

/// Runs BF on `tri` (see the module documentation).
pub fn reduce(tri: Triangulation, options: &Options) -> Reduction {
    reduce_observed(tri, options, &mut progress::ignore)
}

/// [`reduce`], reporting the edges visited in the current pass out of the pass's array
/// to `observer` (each pass starts again from 0), at most every
/// [`progress::REPORT_EVERY`] link tests. Same result as [`reduce`].
pub fn reduce_observed(
    mut tri: Triangulation,
    options: &Options,
    observer: &mut dyn FnMut(Progress),
) -> Reduction {
    const STAGE: &str = "edges visited in this pass";
    let mut throttle = Throttle::new();
    let started = Instant::now();
    let mut stats = super::start_stats(&tri);
    let mut history = History::new();
    let mut contractions = 0u64;
    let mut counter = RetestCounter::new(&tri, options.count_retests);
    let mut tester = LinkTester::new(tri.vertex_capacity());

    let mut numbers = EdgeNumbering::new(&tri);
    let mut current: Vec<u32> = (0..numbers.capacity() as u32).collect();
    Rng::new(options.seed).shuffle(&mut current);
    let mut failed: Vec<u32> = Vec::with_capacity(current.len());

    loop {
        let mut contracted_in_pass = false;
        let pass_len = current.len() as u64;
        observer(Progress::new(STAGE, 0, pass_len));
        for (i, &e) in current.iter().enumerate() {
            if throttle.due(stats.link_tests) {
                observer(Progress::new(STAGE, i as u64, pass_len));
            }
            let Some(c) = numbers.corner(EdgeId(e)) else {
                continue; // removed by an earlier contraction
            };
            debug_assert!(tri.is_face(c.face()), "live edge {e} holds a dead corner");
            let [a, b] = tri.edge_endpoints(c);
            stats.link_tests += 1;
            counter.tested(c);
            if !tester.test(&tri, a, b) {
                failed.push(e);
                continue;
            }
            let rec = tri.contract_tested(a, b, &mut history);
            contractions += 1;
            if !options.keep_history {
                history.forget();
            }
            counter.contracted(&rec);
            numbers.contracted(&rec);
            contracted_in_pass = true;
        }
        observer(Progress::new(STAGE, pass_len, pass_len));
        if !contracted_in_pass {
            break;
        }
        std::mem::swap(&mut current, &mut failed);
        failed.clear();
    }

    stats.edges_tested_more_than_once = counter.more_than_once();
    super::finish(Algorithm::Brute, tri, history, contractions, stats, started)
}
