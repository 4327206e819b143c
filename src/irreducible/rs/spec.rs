//! Lemma 5, Theorem 3 and Propositions 6–11 of the RS paper as checks on the state of
//! [`super::Rs`], called by the algorithm at the points the statements name (the
//! catalogue is in [`crate::spec`] and `spec/README.md`).
//!
//! A child module of the algorithm, so it reads the state's private fields. Every hook
//! begins with `if !ENABLED { return }`: the checks are type-checked in every build, and
//! with [`ENABLED`] false (release without the `invariants` feature) the optimiser
//! deletes them.

use super::{Rs, LTE, LUE};
use crate::core::{ContractionRecord, VertexId};
use crate::spec::oracle::{contractible_by_theorem_3, critical_cycles_through, is_trapped_naive};
use crate::spec::{fully_checked, ENABLED, FULL_CHECK_DEGREE};

macro_rules! spec_fail {
    ($rs:expr, $stmt:literal, $($fmt:tt)*) => {
        panic!(
            "specification violated: {} (u = {}, ts = {}): {}",
            $stmt,
            $rs.current.map_or_else(|| "none".to_string(), |u| u.to_string()),
            $rs.ts,
            format!($($fmt)*)
        )
    };
}

/// The vertex being processed; every hook runs after Alg. 4.2 l.8 has set it.
fn current(rs: &Rs) -> VertexId {
    rs.current.expect("a vertex is being processed")
}

/// Proposition 8 (1)–(6), at the top of the `while` loop of Alg. 4.2 (l.22): every
/// `[u, w]` in `lue` is an edge of K, degree-3 endpoints come first, `p(w)` is false,
/// `o(w) ≠ −1`, `t(w) = −1`, `c(w) = 0`. (8)(7), "never tested before", is checked by
/// the ε = 0 test over every input.) Also Proposition 9 (2) and 10 on `lte`.
///
/// `prefix` bounds how many list entries are examined: the caller checks a long prefix
/// when the loop is entered and the next two entries after each iteration (each
/// iteration changes the lists only near the front and at the entries it moves).
#[inline]
pub(super) fn at_line_22(rs: &Rs, prefix: usize) {
    if !ENABLED {
        return;
    }
    let u = current(rs);
    let mut seen_big = false;
    for w in rs.lists.iter(LUE).take(prefix) {
        let wi = w.index();
        if !rs.tri.has_edge(u, w) {
            spec_fail!(rs, "Proposition 8(1)", "[{u}, {w}] in lue is not an edge");
        }
        let big = rs.tri.degree(w) > 3;
        if seen_big && !big {
            spec_fail!(
                rs,
                "Proposition 8(2)",
                "degree-3 [{u}, {w}] follows a higher-degree edge in lue"
            );
        }
        seen_big |= big;
        if rs.processed[wi] {
            spec_fail!(
                rs,
                "Proposition 8(3)",
                "p({w}) is true for [{u}, {w}] in lue"
            );
        }
        if !rs.o[wi].is_set() {
            spec_fail!(rs, "Proposition 8(4)", "o({w}) = -1 for [{u}, {w}] in lue");
        }
        if rs.t[wi].is_set() {
            spec_fail!(
                rs,
                "Proposition 8(5)",
                "t({w}) = {} for [{u}, {w}] in lue",
                rs.t[wi]
            );
        }
        if rs.count[wi] != 0 {
            spec_fail!(
                rs,
                "Proposition 8(6)",
                "c({w}) = {} for [{u}, {w}] in lue",
                rs.count[wi]
            );
        }
    }
    check_lte_order(rs, prefix);
}

/// Proposition 9 (2) and Proposition 10 on the first `prefix` entries of `lte`.
fn check_lte_order(rs: &Rs, prefix: usize) {
    let u = current(rs);
    let mut seen_positive = false;
    for w in rs.lists.iter(LTE).take(prefix) {
        let wi = w.index();
        let stamps_ok = match (rs.o[wi].get(), rs.t[wi].get()) {
            (Some(o), Some(t)) => t >= o,
            _ => false,
        };
        if !stamps_ok {
            spec_fail!(
                rs,
                "Proposition 9(2)",
                "[{u}, {w}] in lte has t = {}, o = {}",
                rs.t[wi],
                rs.o[wi]
            );
        }
        let zero = rs.count[wi] == 0;
        if seen_positive && zero {
            spec_fail!(
                rs,
                "Proposition 10",
                "[{u}, {w}] with c = 0 follows an edge with c > 0 in lte"
            );
        }
        seen_positive |= !zero;
    }
}

/// Proposition 11, whenever Alg. 4.2 l.32 is reached: for every `[u, w]` in `lte`,
/// `c(w)` equals the number of critical cycles through `[u, w]` in K (counted by the
/// naive oracle). Also Propositions 9 (2) and 10.
#[inline]
pub(super) fn at_line_32(rs: &Rs) {
    if !ENABLED {
        return;
    }
    let u = current(rs);
    for w in rs.lists.iter(LTE).take(FULL_CHECK_DEGREE) {
        let Some(truth) = critical_cycles_through(&rs.tri, u, w) else {
            spec_fail!(
                rs,
                "Proposition 9 / 8(1)",
                "[{u}, {w}] in lte is not an edge"
            );
        };
        if rs.count[w.index()] as usize != truth {
            spec_fail!(
                rs,
                "Proposition 11",
                "c({w}) = {} but [{u}, {w}] lies on {truth} critical cycles",
                rs.count[w.index()]
            );
        }
    }
    check_lte_order(rs, FULL_CHECK_DEGREE);
}

/// When the processing of `u` ends, `u` is trapped (Def. 4; the loop of Alg. 4.2 ends
/// only when no edge at `u` is contractible).
#[inline]
pub(super) fn vertex_trapped(rs: &Rs, u: VertexId) {
    if !ENABLED {
        return;
    }
    if fully_checked(rs.tri.degree(u)) && !is_trapped_naive(&rs.tri, u) {
        let w = rs.tri.link(u).find(|&w| rs.tri.link_condition_naive(u, w));
        spec_fail!(
            rs,
            "Definition 4 (u trapped after processing)",
            "edge [{u}, {w:?}] is still contractible"
        );
    }
}

/// Lemma 5, locally: after a contraction, every processed (hence trapped) vertex of the
/// affected neighbourhood — `x`, `y` and `u`'s new neighbours — is still trapped.
#[inline]
pub(super) fn after_contraction(rs: &Rs, rec: &ContractionRecord, new_neighbours: &[VertexId]) {
    if !ENABLED {
        return;
    }
    let check = |w: VertexId| {
        // Removed vertices are marked processed too; only live ones are trapped.
        if rs.processed[w.index()]
            && rs.tri.is_vertex(w)
            && Some(w) != rs.current
            && fully_checked(rs.tri.degree(w))
            && !is_trapped_naive(&rs.tri, w)
        {
            spec_fail!(
                rs,
                "Lemma 5",
                "processed vertex {w} is loose after contracting [{}, {}]",
                rec.u,
                rec.v
            );
        }
    };
    check(rec.link[0]);
    check(rec.link[1]);
    for &z in new_neighbours.iter().take(FULL_CHECK_DEGREE) {
        check(z);
    }
}

/// Theorem 3 and Eq. 1 at each link test of Alg. 4.4 (`d(v) > 3`, so K is not T4): the
/// count `c(v)` the algorithm computed equals the number of critical cycles through
/// `[u, v]` (oracle), and `c(v) = 0` iff the link condition holds by definition.
#[inline]
pub(super) fn after_test(rs: &Rs, u: VertexId, v: VertexId, cv: u32) {
    if !ENABLED {
        return;
    }
    if !fully_checked(rs.tri.degree(u)) {
        return;
    }
    let truth = critical_cycles_through(&rs.tri, u, v);
    if truth != Some(cv as usize) {
        spec_fail!(
            rs,
            "Alg. 4.4 / Theorem 3",
            "c({v}) = {cv} but [{u}, {v}] lies on {truth:?} critical cycles"
        );
    }
    let naive = rs.tri.link_condition_naive(u, v);
    if naive != (cv == 0) || naive != contractible_by_theorem_3(&rs.tri, u, v) {
        spec_fail!(
            rs,
            "Theorem 3 / Eq. 1",
            "[{u}, {v}]: link condition {naive}, critical cycles {cv}"
        );
    }
}

/// Proposition 6 on the degree-3 path (Alg. 4.3): with `d(v) = 3`, `[u, v]` is
/// contractible iff K is not T4 (`d(u) = 3`), by the naive link condition.
#[inline]
pub(super) fn degree3(rs: &Rs, u: VertexId, v: VertexId) {
    if !ENABLED {
        return;
    }
    if rs.tri.degree(v) != 3 {
        spec_fail!(
            rs,
            "Proposition 6",
            "degree-3 path taken for [{u}, {v}] with d({v}) = {}",
            rs.tri.degree(v)
        );
    }
    // With d(v) = 3, K is T4 iff d(u) = 3 too (u, v and lk(v) then span a closed
    // tetrahedron), so `t4` is the statement's condition. The naive test costs
    // O(d_u · 3): it runs up to the bound (above it, d(u) > 3 and the output tests check
    // the contraction's consequences).
    let t4 = rs.tri.degree(u) == 3;
    if fully_checked(rs.tri.degree(u)) && rs.tri.link_condition_naive(u, v) == t4 {
        spec_fail!(
            rs,
            "Proposition 6",
            "[{u}, {v}] with d({v}) = 3: T4 = {t4}, link condition disagrees"
        );
    }
}

/// The `lte` edges `[u, w]` that are non-contractible just before a contraction, with
/// their numbers of critical cycles (for [`prop7`]); empty, and never allocated, when the
/// checks are off.
#[derive(Default)]
pub(super) struct Prop7Before(Vec<(VertexId, usize)>);

/// Snapshot for Proposition 7: the edges `[u, w]` in `lte` on at least one critical cycle
/// (Theorem 3: K is not T4 while an edge is being contracted, so these are exactly the
/// non-contractible ones), with their counts.
#[inline]
pub(super) fn prop7_before(rs: &Rs) -> Prop7Before {
    if !ENABLED {
        return Prop7Before::default();
    }
    let u = current(rs);
    if !fully_checked(rs.tri.degree(u)) {
        return Prop7Before::default();
    }
    let w = rs
        .lists
        .iter(LTE)
        .take(FULL_CHECK_DEGREE)
        .filter_map(|w| {
            critical_cycles_through(&rs.tri, u, w)
                .filter(|&c| c > 0)
                .map(|c| (w, c))
        })
        .collect();
    Prop7Before(w)
}

/// Proposition 7, locally, after contracting `f = [u, v]`: a non-contractible edge
/// `[u, w]` of `lte` (snapshot before the contraction, first [`FULL_CHECK_DEGREE`]
/// entries) can have become contractible only if `d(v) = 3`, `w ∈ lk(v)`, and `[u, w]`
/// was on exactly one critical cycle before (the one of `lk(v)`, which is gone).
#[inline]
pub(super) fn prop7(rs: &Rs, before: Prop7Before, rec: &ContractionRecord) {
    if !ENABLED {
        return;
    }
    let u = current(rs);
    for (w, cycles_before) in before.0 {
        if !rs.tri.is_vertex(w) {
            continue;
        }
        if critical_cycles_through(&rs.tri, u, w) == Some(0) {
            // f = [u, v] on a degree-3 v, e = [u, w] an edge of lk(v) (w ∈ {x, y}: the
            // link of [u, v] is the rest of lk(v)), and e was on exactly one critical
            // cycle, lk(v)'s, now gone (the count after is 0).
            let allowed = rec.degree_v == 3 && rec.link.contains(&w);
            if !allowed || cycles_before != 1 {
                spec_fail!(
                    rs,
                    "Proposition 7",
                    "contracting [{}, {}] (d = {}) made [{u}, {w}] (on {cycles_before} critical cycles) contractible",
                    rec.u,
                    rec.v,
                    rec.degree_v
                );
            }
        }
    }
}

/// Before every contraction of RS (Alg. 4.5, whichever path led there): `[u, v]` is
/// contractible. By Theorem 3 (K is not T4: the degree-3 path returns early on T4) this
/// is "no critical cycle through `[u, v]`", counted by the oracle from `v`'s side at any
/// degree; the naive link condition is compared too when `d(u)` is at most
/// [`FULL_CHECK_DEGREE`]. (The core's `contract_tested` asserts the link condition only
/// in debug builds; this check also runs under `--features invariants`.)
#[inline]
pub(super) fn before_contraction(rs: &Rs, u: VertexId, v: VertexId) {
    if !ENABLED {
        return;
    }
    let cycles = critical_cycles_through(&rs.tri, u, v);
    let naive_fails = fully_checked(rs.tri.degree(u)) && !rs.tri.link_condition_naive(u, v);
    if cycles != Some(0) || rs.tri.is_tetrahedron() || naive_fails {
        spec_fail!(
            rs,
            "Theorem 3 (contraction of a contractible edge)",
            "contracting [{u}, {v}] on {cycles:?} critical cycles (T4: {})",
            rs.tri.is_tetrahedron()
        );
    }
}

/// Alg. 4.2 when the queue is exhausted: the vertices left are exactly the processed
/// ones, each processed once. (A processed vertex is trapped, Def. 4, and stays trapped,
/// Lemma 5, so no contraction removes it; every other vertex the queue reaches is
/// processed.)
#[inline]
pub(super) fn at_end(rs: &Rs) {
    if !ENABLED {
        return;
    }
    let live = rs.tri.vertex_count() as u64;
    if rs.processed_count != live {
        spec_fail!(
            rs,
            "Alg. 4.2 (every remaining vertex processed once)",
            "{} vertices processed, {live} remain",
            rs.processed_count
        );
    }
}

/// Alg. 4.6 l.12: when the front edge `[u, v]` of `lte` is contracted because `c(v) = 0`,
/// the counter is still exact (`c(v)` = critical cycles through `[u, v]`). The paper
/// states Proposition 11 at Alg. 4.2 l.32 only; the degree-3 contractions of Alg. 4.6
/// l.1–9 change counters in between, and the algorithm relies on them being right.
#[inline]
pub(super) fn at_alg46_line_12(rs: &Rs, u: VertexId, v: VertexId) {
    if !ENABLED {
        return;
    }
    let truth = critical_cycles_through(&rs.tri, u, v);
    if truth != Some(rs.count[v.index()] as usize) {
        spec_fail!(
            rs,
            "Proposition 11 at Alg. 4.6 l.12",
            "c({v}) = {} but [{u}, {v}] lies on {truth:?} critical cycles",
            rs.count[v.index()]
        );
    }
}

/// Alg. 4.3 decrements (l.8–22): the decremented edge `[u, w]` is in `lte` and its
/// counter is positive (a counter never goes below the true count, Prop. 11).
#[inline]
pub(super) fn decrement(rs: &Rs, w: VertexId) {
    if !ENABLED {
        return;
    }
    let in_lte = rs.lists.contains(LTE, w);
    if !in_lte || rs.count[w.index()] == 0 {
        spec_fail!(
            rs,
            "Alg. 4.3 / Proposition 11 (decrement)",
            "decrementing c({w}) = {} of [{}, {w}] (in lte: {in_lte})",
            rs.count[w.index()],
            current(rs)
        );
    }
}

/// Sec. 4.3 (the time stamps): while `u` is processed, `t(v)` is set at most once — when
/// `[u, v]` leaves `lue` (Alg. 4.2 l.24), so it is still −1 then.
#[inline]
pub(super) fn leaving_lue(rs: &Rs, v: VertexId) {
    if !ENABLED {
        return;
    }
    if rs.t[v.index()].is_set() {
        spec_fail!(
            rs,
            "Sec. 4.3 (t set at most once)",
            "[{}, {v}] leaves lue with t({v}) = {} already set",
            current(rs),
            rs.t[v.index()]
        );
    }
}

/// Sec. 4.3 (the time stamps): `o(z)` changes once while `u` is processed — when `z`
/// becomes a neighbour of `u` (Alg. 4.5 l.8), so `z` was not one before (`n(z) ≠ u`).
#[inline]
pub(super) fn new_neighbour(rs: &Rs, z: VertexId) {
    if !ENABLED {
        return;
    }
    let u = current(rs);
    if rs.nbr[z.index()].is(u) {
        spec_fail!(
            rs,
            "Sec. 4.3 (o set once)",
            "{z} becomes a neighbour of {u} again (o({z}) = {})",
            rs.o[z.index()]
        );
    }
}

/// Sec. 4.3, Alg. 4.3 cases: after contracting a degree-3 `v`, a link vertex `w ∈ {x, y}`
/// with `t(w) = −1` is unprocessed and `[u, w]` is in `lue` (`[v, w]` was contractible by
/// Prop. 6, so `w` was not trapped, hence not processed, by Lemma 5).
#[inline]
pub(super) fn degree3_untested(rs: &Rs, x: VertexId, y: VertexId) {
    if !ENABLED {
        return;
    }
    for w in [x, y] {
        let wi = w.index();
        let in_lue = rs.lists.contains(LUE, w);
        if !rs.t[wi].is_set() && (rs.processed[wi] || !in_lue) {
            spec_fail!(
                rs,
                "Sec. 4.3 (Alg. 4.3, t = -1 case)",
                "untested link vertex {w} of the degree-3 contraction: processed {}, in lue {in_lue}",
                rs.processed[wi]
            );
        }
    }
}

/// Each check fails on a state that violates its statement: a consistent RS state (vertex
/// 0 of a stellar-subdivided octahedron, right after Alg. 4.2 l.8–19) with one attribute
/// corrupted per test. Together with the algorithm mutations of `tests/algorithms/rs_variants.rs`
/// this shows that no check is vacuous. With the checks off ([`ENABLED`] false) the tests
/// still build and run the uncorrupted paths, and skip the expected failures.
/// Corrupted-state tests: each check handed a state that violates its statement. Compiled
/// only where the checks are (elsewhere every hook returns at once and nothing would be
/// tested).
#[cfg(all(test, any(debug_assertions, feature = "invariants")))]
mod tests {
    use crate::spec::testing::assert_fails;

    use super::super::{Stamp, Time, Variant};
    use super::*;
    use crate::core::Triangulation;
    use crate::irreducible::Options;

    fn v(i: u32) -> VertexId {
        VertexId(i)
    }

    /// The octahedron with face [0, 2, 4] subdivided by vertex 6 (degree 3), with vertex
    /// 0 current: `lue = [6, 2, 3, 4, 5]` in some order with 6 first.
    fn state() -> Rs {
        let mut faces: Vec<[u32; 3]> = crate::gen::octahedron()
            .faces
            .into_iter()
            .filter(|f| *f != [0, 2, 4])
            .collect();
        assert_eq!(faces.len(), 7, "octahedron face [0, 2, 4] present");
        faces.extend([[0, 2, 6], [2, 4, 6], [4, 0, 6]]);
        let tri = Triangulation::from_faces(7, &faces).expect("a sphere");
        let mut rs = Rs::new(tri, &Options::default(), Variant::SPECIFIED);
        rs.begin(v(0));
        assert_eq!(rs.lists.front(LUE), Some(v(6)), "degree-3 neighbour first");
        rs
    }

    /// The consistent state passes every check, so each failure below is caused by its
    /// corruption.
    #[test]
    fn the_uncorrupted_state_passes_every_check() {
        let rs = state();
        at_line_22(&rs, FULL_CHECK_DEGREE);
        at_line_32(&rs);
        degree3(&rs, v(0), v(6));
        // [0, 2] lies on exactly one critical cycle, (0, 2, 4).
        after_test(&rs, v(0), v(2), 1);
    }

    #[test]
    fn proposition_8_1_non_edge_in_lue() {
        let mut rs = state();
        rs.lists.push_back(LUE, v(1)); // 1 is opposite 0 in the octahedron
        assert_fails("Proposition 8(1)", || at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_8_2_degree_3_edge_behind_a_higher_degree_one() {
        let mut rs = state();
        rs.lists.remove(v(6));
        rs.lists.push_back(LUE, v(6));
        assert_fails("Proposition 8(2)", || at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_8_3_to_8_6_corrupted_attributes() {
        type Corrupt = fn(&mut Rs);
        let cases: [(&str, Corrupt); 4] = [
            ("Proposition 8(3)", |rs| rs.processed[6] = true),
            ("Proposition 8(4)", |rs| rs.o[6] = Stamp::UNSET),
            ("Proposition 8(5)", |rs| rs.t[6] = Stamp::at(Time::START)),
            ("Proposition 8(6)", |rs| rs.count[6] = 1),
        ];
        for (statement, corrupt) in cases {
            let mut rs = state();
            corrupt(&mut rs);
            assert_fails(statement, || at_line_22(&rs, FULL_CHECK_DEGREE));
        }
    }

    /// Moves `w` from `lue` to the back of `lte` as Alg. 4.2 l.24–28 does after a failed
    /// test at the current time stamp.
    fn to_lte(rs: &mut Rs, w: u32, c: u32) {
        rs.lists.remove(v(w));
        rs.t[w as usize] = Stamp::at(rs.ts);
        rs.count[w as usize] = c;
        rs.lists.push_back(LTE, v(w));
    }

    #[test]
    fn proposition_9_2_untested_edge_in_lte() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        rs.t[2] = Stamp::UNSET;
        assert_fails("Proposition 9(2)", || at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_10_zero_counter_behind_a_positive_one() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        to_lte(&mut rs, 3, 0);
        assert_fails("Proposition 10", || at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_11_wrong_counter_at_line_32() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        at_line_32(&rs); // the true count
        rs.count[2] = 3;
        assert_fails("Proposition 11", || at_line_32(&rs));
    }

    #[test]
    fn definition_4_loose_vertex_after_processing() {
        let rs = state();
        assert_fails("Definition 4", || vertex_trapped(&rs, v(0)));
    }

    #[test]
    fn theorem_3_wrong_critical_cycle_count_at_a_link_test() {
        let rs = state();
        assert_fails("Alg. 4.4 / Theorem 3", || after_test(&rs, v(0), v(2), 0));
    }

    #[test]
    fn proposition_6_degree_3_path_on_a_higher_degree_vertex() {
        let rs = state();
        assert_fails("Proposition 6", || degree3(&rs, v(0), v(2)));
    }

    /// Contracts `[0, 3]` (contractible: its link {4, 5} is every common neighbour).
    fn contract_0_3(rs: &mut Rs) -> ContractionRecord {
        assert!(rs.tri.link_condition_naive(v(0), v(3)));
        rs.processed[3] = true;
        rs.tri.contract_tested(v(0), v(3), &mut rs.history)
    }

    #[test]
    fn lemma_5_processed_vertex_loose_after_a_contraction() {
        let mut rs = state();
        rs.processed[4] = true; // wrongly: 4 is not trapped
        let rec = contract_0_3(&mut rs);
        assert!(rec.link.contains(&v(4)));
        assert!(!is_trapped_naive(&rs.tri, v(4)));
        assert_fails("Lemma 5", || after_contraction(&rs, &rec, &[]));
    }

    #[test]
    fn proposition_7_edge_made_contractible_by_a_degree_4_contraction() {
        let mut rs = state();
        let rec = contract_0_3(&mut rs);
        assert_eq!(rec.degree_v, 4);
        // Claim (falsely) that [0, 6] was non-contractible before: it is contractible now,
        // and a degree-4 contraction cannot have made it so.
        assert_eq!(critical_cycles_through(&rs.tri, v(0), v(6)), Some(0));
        let before = Prop7Before(vec![(v(6), 1)]);
        assert_fails("Proposition 7", || prop7(&rs, before, &rec));
    }

    #[test]
    fn theorem_3_contraction_of_a_non_contractible_edge() {
        let rs = state();
        before_contraction(&rs, v(0), v(6)); // contractible: passes
        assert_fails("Theorem 3 (contraction of a contractible edge)", || {
            before_contraction(&rs, v(0), v(2))
        });
    }

    /// Above the degree bound the naive half is skipped; the critical-cycle count alone
    /// still refuses a non-contractible edge.
    #[test]
    fn theorem_3_contraction_of_a_non_contractible_edge_at_a_high_degree_vertex() {
        // The bipyramid over the cycle 2, 3, …, k + 1 with apexes 0 and 1, its face
        // [0, 2, 3] subdivided by x: (0, 2, 3) is a critical cycle.
        let k = FULL_CHECK_DEGREE as u32 + 2;
        let ring = |i: u32| 2 + i % k;
        let mut faces = Vec::new();
        for i in 0..k {
            if i != 0 {
                faces.push([0, ring(i), ring(i + 1)]);
            }
            faces.push([1, ring(i + 1), ring(i)]);
        }
        let x = k + 2;
        faces.extend([[0, 2, x], [2, 3, x], [3, 0, x]]);
        let tri = Triangulation::from_faces(x as usize + 1, &faces).expect("a sphere");
        let rs = Rs::new(tri, &Options::default(), Variant::SPECIFIED);
        assert!(!fully_checked(rs.tri.degree(v(0))));
        before_contraction(&rs, v(0), v(4)); // contractible: passes
        assert_fails("Theorem 3 (contraction of a contractible edge)", || {
            before_contraction(&rs, v(0), v(2))
        });
    }

    #[test]
    fn proposition_11_stale_counter_at_alg_4_6_line_12() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        at_alg46_line_12(&rs, v(0), v(2));
        rs.count[2] = 0;
        assert_fails("Proposition 11 at Alg. 4.6 l.12", || {
            at_alg46_line_12(&rs, v(0), v(2))
        });
    }

    #[test]
    fn decrement_of_a_zero_counter_or_outside_lte() {
        let mut rs = state();
        assert_fails("(decrement)", || decrement(&rs, v(2))); // 2 is in lue
        to_lte(&mut rs, 2, 1);
        decrement(&rs, v(2));
        rs.count[2] = 0;
        assert_fails("(decrement)", || decrement(&rs, v(2)));
    }

    #[test]
    fn proposition_7_edge_that_was_on_two_critical_cycles() {
        let mut rs = state();
        // Contract the degree-3 vertex 6: [0, 2] (in lk(6)) loses the cycle (0, 2, 4).
        assert!(rs.tri.link_condition_naive(v(0), v(6)));
        let rec = rs.tri.contract_tested(v(0), v(6), &mut rs.history);
        assert_eq!(rec.degree_v, 3);
        assert!(rec.link.contains(&v(2)));
        prop7(&rs, Prop7Before(vec![(v(2), 1)]), &rec); // as Prop. 7 says: passes
        assert_fails("Proposition 7", || {
            prop7(&rs, Prop7Before(vec![(v(2), 2)]), &rec)
        });
        // [0, 3] is contractible after the contraction, but 3 is not in lk(6): a
        // degree-3 contraction cannot have made it so.
        assert_eq!(critical_cycles_through(&rs.tri, v(0), v(3)), Some(0));
        assert!(!rec.link.contains(&v(3)));
        assert_fails("Proposition 7", || {
            prop7(&rs, Prop7Before(vec![(v(3), 1)]), &rec)
        });
    }

    /// The snapshot holds exactly the `lte` edges on a critical cycle, with their counts,
    /// so a contraction Proposition 7 forbids is seen from the algorithm's own lists.
    #[test]
    fn proposition_7_snapshot_of_the_non_contractible_lte_edges() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1); // on the critical cycle (0, 2, 4)
        to_lte(&mut rs, 3, 0); // contractible
        let before = prop7_before(&rs);
        assert_eq!(before.0, vec![(v(2), 1)]);
        let rec = rs.tri.contract_tested(v(0), v(6), &mut rs.history);
        let mut forged = rec;
        prop7(&rs, before, &rec); // d(6) = 3, 2 in lk(6): allowed
                                  // The same change after a contraction that was not at a degree-3 vertex.
        forged.degree_v = 4;
        let before = Prop7Before(vec![(v(2), 1)]);
        assert_fails("Proposition 7", || prop7(&rs, before, &forged));
    }

    #[test]
    fn every_remaining_vertex_processed_once_at_the_end() {
        let mut rs = state();
        rs.processed_count = rs.tri.vertex_count() as u64;
        at_end(&rs);
        rs.processed_count -= 1;
        assert_fails("Alg. 4.2 (every remaining vertex processed once)", || {
            at_end(&rs)
        });
    }

    #[test]
    fn stamps_set_twice() {
        let mut rs = state();
        leaving_lue(&rs, v(6));
        new_neighbour(&rs, v(1)); // 1 is not a neighbour of 0
        rs.t[6] = Stamp::at(Time::START);
        assert_fails("Sec. 4.3 (t set at most once)", || leaving_lue(&rs, v(6)));
        assert_fails("Sec. 4.3 (o set once)", || new_neighbour(&rs, v(2)));
    }

    #[test]
    fn untested_link_vertex_of_a_degree_3_contraction_already_processed() {
        let mut rs = state();
        rs.lists.remove(v(6));
        let rec = rs.tri.contract_tested(v(0), v(6), &mut rs.history);
        let [x, y] = rec.link;
        degree3_untested(&rs, x, y); // both untested, unprocessed, in lue
        rs.processed[x.index()] = true;
        assert_fails("Sec. 4.3 (Alg. 4.3, t = -1 case)", || {
            degree3_untested(&rs, x, y)
        });
    }
}
