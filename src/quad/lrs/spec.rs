//! Claim 3.1 and Proposition 3.3 of the tri-quad paper (Sec. 3.3.1) as checks on the
//! state of the expansion ([`super::Expander`]), called after every split and after
//! every vertex `u_i` is fully expanded.
//!
//! A child module of the algorithm, so it reads the state's private fields. Every hook
//! begins with `if !ENABLED { return }`: type-checked in every build, deleted by the
//! optimiser when [`ENABLED`] is false. A failure panics with
//! `specification violated: <statement> (u = u_i, split = k): …`.
//!
//! | statement | paper | hook |
//! |---|---|---|
//! | L1 one edge into `M` per split | Alg. 3.1 l.7, Alg. 3.2–3.4; Lemma 3.4 | `after_split`, `after_vertex` |
//! | L2 at most two flips per split, each `[v_ij, v_ik]`, flippable in `T_ij` | proof of Prop. 3.3, Lemma 3.2 | `after_split` |
//! | L3 the inserted edge is unflipped and `[u_l or V_l, V_i]`, `l ≤ i` | Prop. 3.3 (ii) | `after_split` |
//! | L4 expansion order: the splits of `u_i` are contiguous, `u_{i+1}` processed before `u_i` | Sec. 3.3.1 | `after_vertex` |
//! | L5 every flagged edge joins two expanded vertices and is flippable in `T_i` | Claim 3.1 (i), Prop. 3.3 (i) | `after_vertex` |
//! | L6 every edge of `M` is unflipped and safe in `T_i` | Claim 3.1 (ii) | `after_vertex` |
//! | L7 `K_i` is `T_i` with the flags flipped (each flip valid), `M*` is a matching of `K_i` leaving exactly `n'_f` faces | Claim 3.1, Prop. 3.3 | `after_vertex` (small `T_i`), `at_end` (always) |
//!
//! Cost: `after_split` is O(d_v). `after_vertex` checks every flag and every edge of `M`
//! while `T_i` has at most [`SMALL_FACES`] faces, and otherwise only those set during
//! `u_i`'s expansion (bounded, as the RS checks bound theirs: O(1) amortised per split);
//! L7 materialises `K_i` (O(F)) only for small `T_i`, and once at the end.

use super::{Expander, Split};
use crate::core::{EdgeId, VertexId};
use crate::spec::ENABLED;

/// Face count up to which `after_vertex` checks the whole state and materialises `K_i`.
pub(super) const SMALL_FACES: usize = 4096;

macro_rules! spec_fail {
    ($ex:expr, $stmt:literal, $($fmt:tt)*) => {
        panic!(
            "specification violated: {} (u = {}, split = {}): {}",
            $stmt,
            $ex.current.map_or_else(|| "none".to_string(), |u| u.to_string()),
            $ex.cases.splits,
            format!($($fmt)*)
        )
    };
}

/// Whether `w` is `u_l` with `l > i` for the vertex `u = u_i` being expanded: a vertex of
/// `T'` processed before `u` (RS processes in id order, so: a smaller id).
fn processed_before(ex: &Expander, w: VertexId, u: VertexId) -> bool {
    ex.reduced[w.index()] && w < u
}

/// The endpoints of live edge `e` in `T`, or `None`.
fn endpoints(ex: &Expander, e: EdgeId) -> Option<[VertexId; 2]> {
    ex.numbers.corner(e).map(|c| ex.t.edge_endpoints(c))
}

/// L1–L3 after the split `s` (which set `new_flags` flags).
pub(super) fn after_split(ex: &Expander, s: &Split, new_flags: usize) {
    if !ENABLED {
        return;
    }
    let (u, v) = (s.rec.u, s.rec.v);
    if ex.m_len != s.m_before + 1 {
        spec_fail!(
            ex,
            "L1 (Alg. 3.1): one new edge in M per split",
            "splitting {v} from {u} took |M| from {} to {}",
            s.m_before,
            ex.m_len
        );
    }
    if new_flags > 2 {
        spec_fail!(
            ex,
            "L2 (Prop. 3.3): at most two flips per split",
            "splitting {v} from {u} flagged {new_flags} edges"
        );
    }
    for e in s.flagged.iter().flatten() {
        let Some([a, b]) = endpoints(ex, *e) else {
            spec_fail!(ex, "L2 (Prop. 3.3)", "flagged edge {e:?} is dead");
        };
        let w = if a == v { b } else { a };
        if (a != v && b != v) || ex.expanded_from[w.index()] != u.0 {
            spec_fail!(
                ex,
                "L2 (Prop. 3.3): a flip is [v_ij, v_ik], k < j",
                "splitting {v} from {u} flagged [{a}, {b}]"
            );
        }
        if !ex.t.is_flippable(a, b) {
            spec_fail!(
                ex,
                "L2 (Lemma 3.2): a flagged edge is flippable in T_ij",
                "[{a}, {b}] flagged when {v} was split from {u}"
            );
        }
    }
    let e = s.inserted;
    let Some([a, b]) = endpoints(ex, e) else {
        spec_fail!(ex, "L3 (Prop. 3.3 (ii))", "inserted edge {e:?} is dead");
    };
    if ex.flipped[e.index()] {
        spec_fail!(
            ex,
            "L3 (Prop. 3.3 (ii)): the inserted edge is not flipped",
            "[{a}, {b}] inserted into M while flagged"
        );
    }
    let in_vi = |w: VertexId| ex.expanded_from[w.index()] == u.0;
    let shape = (a == v || b == v || (in_vi(a) && in_vi(b)))
        && !processed_before(ex, a, u)
        && !processed_before(ex, b, u);
    if !shape {
        spec_fail!(
            ex,
            "L3 (Prop. 3.3 (ii)): the inserted edge is [u_l or V_l, V_i], l <= i",
            "splitting {v} from {u} inserted [{a}, {b}]"
        );
    }
}

/// L4–L7 once `u = u_i` is fully expanded (`T` is `T_i`).
pub(super) fn after_vertex(ex: &Expander, u: VertexId) {
    if !ENABLED {
        return;
    }
    if ex.remaining[u.index()] != 0 || !ex.reduced[u.index()] {
        spec_fail!(
            ex,
            "L4 (Sec. 3.3.1): the splits of u_i are contiguous",
            "{u} has {} splits left (vertex of T': {})",
            ex.remaining[u.index()],
            ex.reduced[u.index()]
        );
    }
    if let Some(next) = ex.history.records().last() {
        if next.u >= u {
            spec_fail!(
                ex,
                "L4 (Sec. 3.3.1): u_(i+1) was processed before u_i",
                "{} is expanded after {u}",
                next.u
            );
        }
    }
    if ex.m_len != ex.cases.splits {
        spec_fail!(
            ex,
            "L1 (Alg. 3.1): one new edge in M per split",
            "|M| = {} after {} splits",
            ex.m_len,
            ex.cases.splits
        );
    }
    let small = ex.t.face_count() <= SMALL_FACES;
    let all_edges = || (0..ex.numbers.capacity()).map(|i| EdgeId(i as u32));
    let flags: Box<dyn Iterator<Item = EdgeId>> = if small {
        Box::new(all_edges().filter(|e| ex.flipped[e.index()]))
    } else {
        Box::new(ex.group_flags.iter().copied())
    };
    for e in flags {
        if !ex.flipped[e.index()] {
            continue; // unflipped since
        }
        let Some([a, b]) = endpoints(ex, e) else {
            spec_fail!(ex, "L5 (Claim 3.1 (i))", "flagged edge {e:?} is dead");
        };
        if ex.reduced[a.index()] || ex.reduced[b.index()] {
            spec_fail!(
                ex,
                "L5 (Prop. 3.3 (i)): a flipped edge joins two expanded vertices",
                "[{a}, {b}] is flagged"
            );
        }
        if !ex.t.is_flippable(a, b) {
            spec_fail!(
                ex,
                "L5 (Claim 3.1 (i)): a flagged edge is flippable in T_i",
                "[{a}, {b}] is flagged"
            );
        }
    }
    let m: Box<dyn Iterator<Item = EdgeId>> = if small {
        Box::new(all_edges().filter(|e| ex.in_m[e.index()]))
    } else {
        Box::new(ex.group_m.iter().copied())
    };
    for e in m {
        let Some([a, b]) = endpoints(ex, e) else {
            spec_fail!(ex, "L6 (Claim 3.1 (ii))", "edge {e:?} of M is dead");
        };
        if ex.flipped[e.index()] {
            spec_fail!(
                ex,
                "L6 (Claim 3.1 (ii)): an edge of M is not flipped",
                "[{a}, {b}] is in M and flagged"
            );
        }
        if processed_before(ex, a, u) || processed_before(ex, b, u) {
            spec_fail!(
                ex,
                "L6 (Claim 3.1 (ii)): an edge of M is safe in T_i",
                "[{a}, {b}] is in M"
            );
        }
    }
    if small {
        check_k(ex, None, None);
    }
}

/// L7 on `K_i`, materialised here unless the caller did (`flip_error`, `pair_error`
/// then carry its findings).
fn check_k(ex: &Expander, flip_error: Option<Option<&str>>, pair_error: Option<Option<&str>>) {
    let (k, kn, _, own_flip) = ex.materialise();
    let flip_error = flip_error.unwrap_or(own_flip.as_deref());
    if let Some(err) = flip_error {
        spec_fail!(
            ex,
            "L7 (Claim 3.1 (i)): K_i is T_i with flippable edges flipped",
            "{err}"
        );
    }
    let (p, own_pair) = ex.pair_m(&k, &kn);
    let pair_error = pair_error.unwrap_or(own_pair.as_deref());
    if let Some(err) = pair_error {
        spec_fail!(ex, "L7 (Claim 3.1 (ii)): M* is a matching of K_i", "{err}");
    }
    let unpaired = k.face_count() - 2 * p.len();
    if unpaired != ex.reduced_faces {
        spec_fail!(
            ex,
            "L7 (Prop. 3.3): M* matches all expanded triangles",
            "{unpaired} faces unpaired, T' has {}",
            ex.reduced_faces
        );
    }
}

/// L7 on the final `K` (the caller's materialisation and pairing errors).
pub(super) fn at_end(ex: &Expander, flip_error: Option<&str>, pair_error: Option<&str>) {
    if !ENABLED {
        return;
    }
    check_k(ex, Some(flip_error), Some(pair_error));
}
