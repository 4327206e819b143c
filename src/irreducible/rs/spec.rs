//! Propositions 8–11 and Lemma 5 of the RS paper as checks on the state of
//! [`crate::irreducible::rs`].

#![cfg_attr(not(any(debug_assertions, feature = "invariants")), allow(unused))]

use crate::spec::oracle::{contractible_by_theorem_3, critical_cycles_through, is_trapped_naive};
use crate::spec::FULL_CHECK_DEGREE;
use crate::core::{ContractionRecord, VertexId};
use super::Rs;

const NIL: u32 = u32::MAX;

macro_rules! spec_fail {
    ($rs:expr, $stmt:literal, $($fmt:tt)*) => {
        panic!(
            "specification violated: {} (u = {}, ts = {}): {}",
            $stmt,
            $rs.current,
            $rs.ts,
            format!($($fmt)*)
        )
    };
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
pub(crate) fn rs_at_line_22(rs: &Rs, prefix: usize) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let u = rs.current;
        let mut seen_big = false;
        for w in rs.lists.iter(0).take(prefix) {
            let wi = w as usize;
            if !rs.tri.has_edge(VertexId(u), VertexId(w)) {
                spec_fail!(rs, "Proposition 8(1)", "[{u}, {w}] in lue is not an edge");
            }
            let big = rs.tri.degree(VertexId(w)) > 3;
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
            if rs.o[wi] == NIL {
                spec_fail!(rs, "Proposition 8(4)", "o({w}) = -1 for [{u}, {w}] in lue");
            }
            if rs.t[wi] != NIL {
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
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, prefix);
}

/// Proposition 9 (2) and Proposition 10 on the first `prefix` entries of `lte`.
#[cfg(any(debug_assertions, feature = "invariants"))]
fn check_lte_order(rs: &Rs, prefix: usize) {
    let u = rs.current;
    let mut seen_positive = false;
    for w in rs.lists.iter(1).take(prefix) {
        let wi = w as usize;
        if !(rs.o[wi] != NIL && rs.t[wi] != NIL && rs.t[wi] >= rs.o[wi]) {
            spec_fail!(
                rs,
                "Proposition 9(2)",
                "[{u}, {w}] in lte has t = {}, o = {}",
                rs.t[wi] as i64,
                rs.o[wi] as i64
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
pub(crate) fn rs_at_line_32(rs: &Rs) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let u = rs.current;
        for w in rs.lists.iter(1).take(FULL_CHECK_DEGREE) {
            let truth = critical_cycles_through(&rs.tri, VertexId(u), VertexId(w));
            let Some(truth) = truth else {
                spec_fail!(
                    rs,
                    "Proposition 9 / 8(1)",
                    "[{u}, {w}] in lte is not an edge"
                );
            };
            if rs.count[w as usize] as usize != truth {
                spec_fail!(
                    rs,
                    "Proposition 11",
                    "c({w}) = {} but [{u}, {w}] lies on {truth} critical cycles",
                    rs.count[w as usize]
                );
            }
        }
        check_lte_order(rs, FULL_CHECK_DEGREE);
    }
}

/// When the processing of `u` ends, `u` is trapped (Def. 4; the loop of Alg. 4.2 ends
/// only when no edge at `u` is contractible).
#[inline]
pub(crate) fn rs_vertex_trapped(rs: &Rs, u: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let v = VertexId(u);
        if rs.tri.degree(v) <= FULL_CHECK_DEGREE && !is_trapped_naive(&rs.tri, v) {
            let w = rs
                .tri
                .link(v)
                .find(|&w| rs.tri.link_condition_naive(v, w))
                .map_or(u32::MAX, |w| w.0);
            spec_fail!(
                rs,
                "Definition 4 (u trapped after processing)",
                "edge [{u}, {w}] is still contractible"
            );
        }
    }
}

/// Lemma 5, locally: after a contraction, every processed (hence trapped) vertex of the
/// affected neighbourhood — `x`, `y` and `u`'s new neighbours — is still trapped.
#[inline]
pub(crate) fn rs_after_contraction(rs: &Rs, rec: &ContractionRecord, new_neighbours: &[u32]) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let check = |w: VertexId| {
            let wi = w.index();
            // Removed vertices are marked processed too; only live ones are trapped.
            if rs.processed[wi]
                && rs.tri.is_vertex(w)
                && w.0 != rs.current
                && rs.tri.degree(w) <= FULL_CHECK_DEGREE
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
            check(VertexId(z));
        }
    }
}

/// Theorem 3 and Eq. 1 at each link test of Alg. 4.4 (`d(v) > 3`, so K is not T4): the
/// count `c(v)` the algorithm computed equals the number of critical cycles through
/// `[u, v]` (oracle), and `c(v) = 0` iff the link condition holds by definition.
#[inline]
pub(crate) fn rs_after_test(rs: &Rs, u: u32, v: u32, cv: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let (a, b) = (VertexId(u), VertexId(v));
        if rs.tri.degree(a) > FULL_CHECK_DEGREE {
            return;
        }
        let truth = critical_cycles_through(&rs.tri, a, b).unwrap_or(usize::MAX);
        if truth != cv as usize {
            spec_fail!(
                rs,
                "Alg. 4.4 / Theorem 3",
                "c({v}) = {cv} but [{u}, {v}] lies on {truth} critical cycles"
            );
        }
        let naive = rs.tri.link_condition_naive(a, b);
        if naive != (cv == 0) || naive != contractible_by_theorem_3(&rs.tri, a, b) {
            spec_fail!(
                rs,
                "Theorem 3 / Eq. 1",
                "[{u}, {v}]: link condition {naive}, critical cycles {cv}"
            );
        }
    }
}

/// Proposition 6 on the degree-3 path (Alg. 4.3): with `d(v) = 3`, `[u, v]` is
/// contractible iff K is not T4 (`d(u) = 3`), by the naive link condition.
#[inline]
pub(crate) fn rs_degree3(rs: &Rs, u: u32, v: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let (a, b) = (VertexId(u), VertexId(v));
        if rs.tri.degree(b) != 3 {
            spec_fail!(
                rs,
                "Proposition 6",
                "degree-3 path taken for [{u}, {v}] with d({v}) = {}",
                rs.tri.degree(b)
            );
        }
        let t4 = rs.tri.degree(a) == 3;
        // The naive test costs O(d_u · 3); above the bound only the T4 half is checked.
        let naive_disagrees =
            rs.tri.degree(a) <= FULL_CHECK_DEGREE && rs.tri.link_condition_naive(a, b) == t4;
        if t4 != rs.tri.is_tetrahedron() || naive_disagrees {
            spec_fail!(
                rs,
                "Proposition 6",
                "[{u}, {v}] with d({v}) = 3: T4 = {t4}, link condition disagrees"
            );
        }
    }
}

/// The `lte` edges that are non-contractible just before a contraction, with their
/// numbers of critical cycles (for [`rs_prop7`]); empty when the checks are compiled out.
#[derive(Default)]
pub(crate) struct Prop7Before(#[allow(dead_code)] Vec<(u32, usize)>);

/// Snapshot for Proposition 7: the edges `[u, w]` in `lte` on at least one critical cycle
/// (Theorem 3: K is not T4 while an edge is being contracted, so these are exactly the
/// non-contractible ones), with their counts.
#[inline]
pub(crate) fn rs_prop7_before(rs: &Rs) -> Prop7Before {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let u = rs.current;
        if rs.tri.degree(VertexId(u)) > FULL_CHECK_DEGREE {
            return Prop7Before::default();
        }
        let w: Vec<(u32, usize)> = rs
            .lists
            .iter(1)
            .take(FULL_CHECK_DEGREE)
            .filter_map(|w| {
                critical_cycles_through(&rs.tri, VertexId(u), VertexId(w))
                    .filter(|&c| c > 0)
                    .map(|c| (w, c))
            })
            .collect();
        Prop7Before(w)
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    {
        let _ = rs;
        Prop7Before::default()
    }
}

/// Proposition 7, locally, after contracting `f = [u, v]`: a non-contractible edge
/// `[u, w]` of `lte` (snapshot before the contraction, first [`FULL_CHECK_DEGREE`]
/// entries) can have become contractible only if `d(v) = 3`, `w ∈ lk(v)`, and `[u, w]`
/// was on exactly one critical cycle before (the one of `lk(v)`, which is gone).
#[inline]
pub(crate) fn rs_prop7(rs: &Rs, before: Prop7Before, rec: &ContractionRecord) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let u = rs.current;
        for (w, cycles_before) in before.0 {
            if !rs.tri.is_vertex(VertexId(w)) {
                continue;
            }
            if critical_cycles_through(&rs.tri, VertexId(u), VertexId(w)) == Some(0) {
                // f = [u, v] on a degree-3 v, e = [u, w] an edge of lk(v) (w ∈ {x, y}: the
                // link of [u, v] is the rest of lk(v)), and e was on exactly one critical
                // cycle, lk(v)'s, now gone (the count after is 0).
                let allowed = rec.degree_v == 3 && rec.link.contains(&VertexId(w));
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
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    {
        let _ = (rs, before, rec);
    }
}

/// Before every contraction of RS (Alg. 4.5, whichever path led there): `[u, v]` is
/// contractible. By Theorem 3 (K is not T4: the degree-3 path returns early on T4) this
/// is "no critical cycle through `[u, v]`", counted by the oracle from `v`'s side at any
/// degree; the naive link condition is compared too when `d(u)` is at most
/// [`FULL_CHECK_DEGREE`]. (The core's `contract_tested` asserts the link condition only
/// in debug builds; this check also runs under `--features invariants`.)
#[inline]
pub(crate) fn rs_before_contraction(rs: &Rs, u: u32, v: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let (a, b) = (VertexId(u), VertexId(v));
        let cycles = critical_cycles_through(&rs.tri, a, b);
        let naive_fails =
            rs.tri.degree(a) <= FULL_CHECK_DEGREE && !rs.tri.link_condition_naive(a, b);
        if cycles != Some(0) || rs.tri.is_tetrahedron() || naive_fails {
            spec_fail!(
                rs,
                "Theorem 3 (contraction of a contractible edge)",
                "contracting [{u}, {v}] on {cycles:?} critical cycles (T4: {})",
                rs.tri.is_tetrahedron()
            );
        }
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, u, v);
}

/// Alg. 4.6 l.12: when the front edge `[u, v]` of `lte` is contracted because `c(v) = 0`,
/// the counter is still exact (`c(v)` = critical cycles through `[u, v]`). The paper
/// states Proposition 11 at Alg. 4.2 l.32 only; the degree-3 contractions of Alg. 4.6
/// l.1–9 change counters in between, and the algorithm relies on them being right.
#[inline]
pub(crate) fn rs_at_alg46_line_12(rs: &Rs, u: u32, v: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let truth = critical_cycles_through(&rs.tri, VertexId(u), VertexId(v));
        if truth != Some(rs.count[v as usize] as usize) {
            spec_fail!(
                rs,
                "Proposition 11 at Alg. 4.6 l.12",
                "c({v}) = {} but [{u}, {v}] lies on {truth:?} critical cycles",
                rs.count[v as usize]
            );
        }
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, u, v);
}

/// Alg. 4.3 decrements (l.8–22): the decremented edge `[u, w]` is in `lte` and its
/// counter is positive (a counter never goes below the true count, Prop. 11).
#[inline]
pub(crate) fn rs_decrement(rs: &Rs, w: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    {
        let u = rs.current;
        if !rs.lists.contains(crate::irreducible::rs::LTE, w) || rs.count[w as usize] == 0 {
            spec_fail!(
                rs,
                "Alg. 4.3 / Proposition 11 (decrement)",
                "decrementing c({w}) = {} of [{u}, {w}] (in lte: {})",
                rs.count[w as usize],
                rs.lists.contains(crate::irreducible::rs::LTE, w)
            );
        }
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, w);
}

/// Sec. 4.3 (the time stamps): while `u` is processed, `t(v)` is set at most once — when
/// `[u, v]` leaves `lue` (Alg. 4.2 l.24), so it is still −1 then.
#[inline]
pub(crate) fn rs_leaving_lue(rs: &Rs, v: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    if rs.t[v as usize] != NIL {
        spec_fail!(
            rs,
            "Sec. 4.3 (t set at most once)",
            "[{}, {v}] leaves lue with t({v}) = {} already set",
            rs.current,
            rs.t[v as usize]
        );
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, v);
}

/// Sec. 4.3 (the time stamps): `o(z)` changes once while `u` is processed — when `z`
/// becomes a neighbour of `u` (Alg. 4.5 l.8), so `z` was not one before (`n(z) ≠ u`).
#[inline]
pub(crate) fn rs_new_neighbour(rs: &Rs, z: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    if rs.nbr[z as usize] == rs.current {
        spec_fail!(
            rs,
            "Sec. 4.3 (o set once)",
            "{z} becomes a neighbour of {} again (o({z}) = {})",
            rs.current,
            rs.o[z as usize]
        );
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, z);
}

/// Sec. 4.3, Alg. 4.3 cases: after contracting a degree-3 `v`, a link vertex `w ∈ {x, y}`
/// with `t(w) = −1` is unprocessed and `[u, w]` is in `lue` (`[v, w]` was contractible by
/// Prop. 6, so `w` was not trapped, hence not processed, by Lemma 5).
#[inline]
pub(crate) fn rs_degree3_untested(rs: &Rs, x: u32, y: u32) {
    #[cfg(any(debug_assertions, feature = "invariants"))]
    for w in [x, y] {
        let wi = w as usize;
        if rs.t[wi] == NIL
            && (rs.processed[wi] || !rs.lists.contains(crate::irreducible::rs::LUE, w))
        {
            spec_fail!(
                rs,
                "Sec. 4.3 (Alg. 4.3, t = -1 case)",
                "untested link vertex {w} of the degree-3 contraction: processed {}, in lue {}",
                rs.processed[wi],
                rs.lists.contains(crate::irreducible::rs::LUE, w)
            );
        }
    }
    #[cfg(not(any(debug_assertions, feature = "invariants")))]
    let _ = (rs, x, y);
}

/// Each check fails on a state that violates its statement: a consistent RS state (vertex
/// 0 of a stellar-subdivided octahedron, right after Alg. 4.2 l.8–19) with one attribute
/// corrupted per test. Together with the algorithm mutations of `tests/rs_variants.rs`
/// this shows that no check is vacuous.
#[cfg(all(test, any(debug_assertions, feature = "invariants")))]
mod tests {
    use std::panic::{catch_unwind, AssertUnwindSafe};

    use super::*;
    use crate::core::Triangulation;
    use crate::irreducible::rs::{Variant, LTE, LUE};
    use crate::irreducible::Options;

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
        let mut rs = Rs::new(tri, &Options::default(), Variant::default());
        rs.begin(0);
        assert_eq!(rs.lists.front(LUE), Some(6), "degree-3 neighbour first");
        rs
    }

    /// Runs `check` and returns its panic message (panics if it passed).
    fn failure(check: impl FnOnce()) -> String {
        let err = catch_unwind(AssertUnwindSafe(check)).expect_err("the check must fail");
        err.downcast_ref::<String>()
            .cloned()
            .unwrap_or_else(|| "non-string panic".into())
    }

    fn assert_fails(statement: &str, check: impl FnOnce()) {
        let msg = failure(check);
        assert!(
            msg.starts_with("specification violated: ") && msg.contains(statement),
            "expected {statement}, got {msg}"
        );
    }

    #[test]
    fn the_uncorrupted_state_passes_every_check() {
        let rs = state();
        rs_at_line_22(&rs, FULL_CHECK_DEGREE);
        rs_at_line_32(&rs);
        rs_degree3(&rs, 0, 6);
        // [0, 2] lies on exactly one critical cycle, (0, 2, 4).
        rs_after_test(&rs, 0, 2, 1);
    }

    #[test]
    fn proposition_8_1_non_edge_in_lue() {
        let mut rs = state();
        rs.lists.push_back(LUE, 1); // 1 is opposite 0 in the octahedron
        assert_fails("Proposition 8(1)", || rs_at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_8_2_degree_3_edge_behind_a_higher_degree_one() {
        let mut rs = state();
        rs.lists.remove(6);
        rs.lists.push_back(LUE, 6);
        assert_fails("Proposition 8(2)", || rs_at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_8_3_to_8_6_corrupted_attributes() {
        type Corrupt = fn(&mut Rs);
        let cases: [(&str, Corrupt); 4] = [
            ("Proposition 8(3)", |rs| rs.processed[6] = true),
            ("Proposition 8(4)", |rs| rs.o[6] = NIL),
            ("Proposition 8(5)", |rs| rs.t[6] = 0),
            ("Proposition 8(6)", |rs| rs.count[6] = 1),
        ];
        for (statement, corrupt) in cases {
            let mut rs = state();
            corrupt(&mut rs);
            assert_fails(statement, || rs_at_line_22(&rs, FULL_CHECK_DEGREE));
        }
    }

    /// Moves `w` from `lue` to the back of `lte` as Alg. 4.2 l.24–28 does after a failed
    /// test at the current time stamp.
    fn to_lte(rs: &mut Rs, w: u32, c: u32) {
        rs.lists.remove(w);
        rs.t[w as usize] = rs.ts;
        rs.count[w as usize] = c;
        rs.lists.push_back(LTE, w);
    }

    #[test]
    fn proposition_9_2_untested_edge_in_lte() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        rs.t[2] = NIL;
        assert_fails("Proposition 9(2)", || rs_at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_10_zero_counter_behind_a_positive_one() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        to_lte(&mut rs, 3, 0);
        assert_fails("Proposition 10", || rs_at_line_22(&rs, FULL_CHECK_DEGREE));
    }

    #[test]
    fn proposition_11_wrong_counter_at_line_32() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        rs_at_line_32(&rs); // the true count
        rs.count[2] = 3;
        assert_fails("Proposition 11", || rs_at_line_32(&rs));
    }

    #[test]
    fn definition_4_loose_vertex_after_processing() {
        let rs = state();
        assert_fails("Definition 4", || rs_vertex_trapped(&rs, 0));
    }

    #[test]
    fn theorem_3_wrong_critical_cycle_count_at_a_link_test() {
        let rs = state();
        assert_fails("Alg. 4.4 / Theorem 3", || rs_after_test(&rs, 0, 2, 0));
    }

    #[test]
    fn proposition_6_degree_3_path_on_a_higher_degree_vertex() {
        let rs = state();
        assert_fails("Proposition 6", || rs_degree3(&rs, 0, 2));
    }

    /// Contracts `[0, 3]` (contractible: its link {4, 5} is every common neighbour).
    fn contract_0_3(rs: &mut Rs) -> ContractionRecord {
        assert!(rs.tri.link_condition_naive(VertexId(0), VertexId(3)));
        rs.processed[3] = true;
        rs.tri
            .contract_tested(VertexId(0), VertexId(3), &mut rs.history)
    }

    #[test]
    fn lemma_5_processed_vertex_loose_after_a_contraction() {
        let mut rs = state();
        rs.processed[4] = true; // wrongly: 4 is not trapped
        let rec = contract_0_3(&mut rs);
        assert!(rec.link.contains(&VertexId(4)));
        assert!(!is_trapped_naive(&rs.tri, VertexId(4)));
        assert_fails("Lemma 5", || rs_after_contraction(&rs, &rec, &[]));
    }

    #[test]
    fn proposition_7_edge_made_contractible_by_a_degree_4_contraction() {
        let mut rs = state();
        let rec = contract_0_3(&mut rs);
        assert_eq!(rec.degree_v, 4);
        // Claim (falsely) that [0, 6] was non-contractible before: it is contractible now,
        // and a degree-4 contraction cannot have made it so.
        assert_eq!(
            critical_cycles_through(&rs.tri, VertexId(0), VertexId(6)),
            Some(0)
        );
        let before = Prop7Before(vec![(6, 1)]);
        assert_fails("Proposition 7", || rs_prop7(&rs, before, &rec));
    }
    #[test]
    fn theorem_3_contraction_of_a_non_contractible_edge() {
        let rs = state();
        rs_before_contraction(&rs, 0, 6); // contractible: passes
        assert_fails("Theorem 3 (contraction of a contractible edge)", || {
            rs_before_contraction(&rs, 0, 2)
        });
    }

    #[test]
    fn proposition_11_stale_counter_at_alg_4_6_line_12() {
        let mut rs = state();
        to_lte(&mut rs, 2, 1);
        rs_at_alg46_line_12(&rs, 0, 2);
        rs.count[2] = 0;
        assert_fails("Proposition 11 at Alg. 4.6 l.12", || {
            rs_at_alg46_line_12(&rs, 0, 2)
        });
    }

    #[test]
    fn decrement_of_a_zero_counter_or_outside_lte() {
        let mut rs = state();
        assert_fails("(decrement)", || rs_decrement(&rs, 2)); // 2 is in lue
        to_lte(&mut rs, 2, 1);
        rs_decrement(&rs, 2);
        rs.count[2] = 0;
        assert_fails("(decrement)", || rs_decrement(&rs, 2));
    }

    #[test]
    fn proposition_7_edge_that_was_on_two_critical_cycles() {
        let mut rs = state();
        // Contract the degree-3 vertex 6: [0, 2] (in lk(6)) loses the cycle (0, 2, 4).
        assert!(rs.tri.link_condition_naive(VertexId(0), VertexId(6)));
        let rec = rs
            .tri
            .contract_tested(VertexId(0), VertexId(6), &mut rs.history);
        assert_eq!(rec.degree_v, 3);
        assert!(rec.link.contains(&VertexId(2)));
        rs_prop7(&rs, Prop7Before(vec![(2, 1)]), &rec); // as Prop. 7 says: passes
        assert_fails("Proposition 7", || {
            rs_prop7(&rs, Prop7Before(vec![(2, 2)]), &rec)
        });
    }

    #[test]
    fn stamps_set_twice() {
        let mut rs = state();
        rs_leaving_lue(&rs, 6);
        rs_new_neighbour(&rs, 1); // 1 is not a neighbour of 0
        rs.t[6] = 0;
        assert_fails("Sec. 4.3 (t set at most once)", || rs_leaving_lue(&rs, 6));
        assert_fails("Sec. 4.3 (o set once)", || rs_new_neighbour(&rs, 2));
    }

    #[test]
    fn untested_link_vertex_of_a_degree_3_contraction_already_processed() {
        let mut rs = state();
        rs.lists.remove(6);
        let rec = rs
            .tri
            .contract_tested(VertexId(0), VertexId(6), &mut rs.history);
        let [x, y] = rec.link.map(|w| w.0);
        rs_degree3_untested(&rs, x, y); // both untested, unprocessed, in lue
        rs.processed[x as usize] = true;
        assert_fails("Sec. 4.3 (Alg. 4.3, t = -1 case)", || {
            rs_degree3_untested(&rs, x, y)
        });
    }
}
