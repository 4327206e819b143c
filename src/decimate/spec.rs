//! The decimator's executable specification (catalogue: `spec/decimate.md`), run in
//! debug builds and with the `invariants` feature:
//!
//! - **M1, priority**: every collapse is of the cheapest edge (cost, then endpoint ids)
//!   among the edges that pass every guard at that moment, the guards decided here by
//!   independent predicates (the core's naive link condition, the boundary loops read
//!   from the cone, the reference fold-over test on every moved face).
//! - **M2, quadric sums**: at the end, every live vertex's quadric and weight are the sums
//!   of the initial ones of the input vertices merged into it.
//! - **M3, stop rule**: the run stops at the first face count at or below the target,
//!   or, short of it, only when no edge passes every guard (checked independently), and
//!   the face count it keeps is the true one.
//!
//! M1 and the blocked half of M3 examine every edge, so they run in full on meshes of at
//! most [`FULL_CHECK_FACES`] live faces (the tests' sizes) and are skipped above.

use super::run::{Candidate, Decimator};
use super::Stopped;
use crate::core::ids::NONE;
use crate::core::VertexId;
use crate::simplify::geometry::{area_normal, moved_triangle_ok, Point, Quadric};
use crate::spec::ENABLED;

/// Live faces up to which the checks over every edge run.
pub(crate) const FULL_CHECK_FACES: usize = 1500;

/// Whether `[p, q]` may be collapsed now, decided without the decimator's own walk: its
/// key when it may.
fn allowed(d: &Decimator<'_>, p: VertexId, q: VertexId) -> Option<(f64, u32, u32)> {
    let c = d.candidate(p, q).ok()?;
    if !d.tri.link_condition_naive(p, q) {
        return None;
    }
    let loop_of = |v: VertexId| d.tri.link(v).find(|&n| d.is_virtual(n));
    if let (Some(x), Some(y)) = (loop_of(p), loop_of(q)) {
        if x != y {
            return None;
        }
    }
    if d.opts.guard && !guard_ok(d, &c) {
        return None;
    }
    let (a, b) = if p < q { (p, q) } else { (q, p) };
    Some((c.cost, a.0, b.0))
}

/// The fold-over guard by its definition: every real face with exactly one of the two
/// endpoints, whose corner there moves, keeps an area and turns by less than 90°.
fn guard_ok(d: &Decimator<'_>, c: &Candidate) -> bool {
    let pos = |v: VertexId| d.pos[v.index()];
    let mut faces: Vec<_> = [c.keep, c.gone]
        .iter()
        .flat_map(|&v| d.tri.star(v).map(|s| s.corner.face()))
        .collect();
    faces.sort_unstable();
    faces.dedup();
    for f in faces {
        let vs = d.tri.face_vertices(f);
        if vs.iter().any(|&v| d.is_virtual(v)) {
            continue;
        }
        let has = |v: VertexId| vs.contains(&v);
        if has(c.keep) == has(c.gone) {
            continue;
        }
        let moved = if has(c.keep) { c.keep } else { c.gone };
        if pos(moved) == c.position {
            continue;
        }
        let ps = vs.map(pos);
        let new: [Point; 3] = [0, 1, 2].map(|k| if vs[k] == moved { c.position } else { ps[k] });
        if !moved_triangle_ok(area_normal(ps[0], ps[1], ps[2]), new) {
            return false;
        }
    }
    true
}

fn real_edges(d: &Decimator<'_>) -> Vec<(VertexId, VertexId)> {
    d.tri
        .edges()
        .filter(|&(p, q, _)| !d.is_virtual(p) && !d.is_virtual(q))
        .map(|(p, q, _)| (p, q))
        .collect()
}

/// M1, before the collapse of the edge `chosen` (its queue key: cost, endpoints;
/// candidate `c`): it passes every guard and no allowed edge has a smaller key.
pub(super) fn before_collapse(d: &Decimator<'_>, chosen: (f64, u32, u32), c: &Candidate) {
    if !ENABLED || d.tri.face_count() > FULL_CHECK_FACES {
        return;
    }
    let (cost, p, q) = chosen;
    assert_eq!(
        c.cost.to_bits(),
        cost.to_bits(),
        "M1: [{p}, {q}]'s cost changed in the queue"
    );
    assert!(
        allowed(d, VertexId(p), VertexId(q)).is_some(),
        "M1: collapse {}: [{p}, {q}] does not pass every guard",
        d.collapses
    );
    for (p, q) in real_edges(d) {
        if let Some(key) = allowed(d, p, q) {
            assert!(
                key.0
                    .total_cmp(&chosen.0)
                    .then((key.1, key.2).cmp(&(chosen.1, chosen.2)))
                    != std::cmp::Ordering::Less,
                "M1: collapse {}: [{}, {}] (cost {}) is allowed and cheaper than the chosen \
                 [{}, {}] (cost {})",
                d.collapses,
                key.1,
                key.2,
                key.0,
                chosen.1,
                chosen.2,
                chosen.0
            );
        }
    }
}

/// M3, when the queue is empty short of the target: the sweep found `missed` allowed
/// edges; there must be none.
pub(super) fn nothing_missed(d: &Decimator<'_>, missed: usize) {
    if !ENABLED {
        return;
    }
    assert_eq!(
        missed, 0,
        "M3: the queue ran out with {missed} edges that pass every guard (collapse {})",
        d.collapses
    );
}

/// M2 and M3 at the end of the run.
pub(super) fn at_end(d: &Decimator<'_>, stopped: Stopped) {
    if !ENABLED {
        return;
    }
    // M3: the face count kept is the true one, and the stop is the first at or below
    // the target (a collapse removes at most two faces).
    let real = d
        .tri
        .faces()
        .filter(|&f| d.tri.face_vertices(f).iter().all(|&v| !d.is_virtual(v)))
        .count();
    assert_eq!(
        real, d.real_faces,
        "M3: the face count kept is not the true one"
    );
    match stopped {
        Stopped::Target => {
            assert!(
                d.real_faces <= d.target,
                "M3: stopped at the target above it"
            );
            assert!(
                d.collapses == 0 || d.real_faces + 2 > d.target,
                "M3: {} faces, the target {} was passed by more than one collapse",
                d.real_faces,
                d.target
            );
        }
        Stopped::Error | Stopped::Blocked => {
            assert!(d.real_faces > d.target, "M3: blocked at the target");
            if d.tri.face_count() <= FULL_CHECK_FACES {
                for (p, q) in real_edges(d) {
                    assert!(
                        allowed(d, p, q).is_none(),
                        "M3: stopped ({stopped}) with [{p}, {q}] allowed"
                    );
                }
            }
        }
    }
    // M2: each live vertex's quadric is the sum of its class's initial quadrics (summed
    // here in id order, so equal up to rounding).
    let n = d.merged_into.len();
    let mut sum = vec![(Quadric::default(), 0.0f64); n];
    for v in 0..d.first_virtual as usize {
        if d.merged_into[v] == NONE && !d.tri.is_vertex(VertexId(v as u32)) {
            continue;
        }
        let mut r = v;
        while d.merged_into[r] != NONE {
            r = d.merged_into[r] as usize;
        }
        let (q, w) = d.initial[v];
        sum[r].0.add(&q);
        sum[r].1 += w;
    }
    for (v, &(q, w)) in sum.iter().enumerate().take(d.first_virtual as usize) {
        if !d.tri.is_vertex(VertexId(v as u32)) {
            continue;
        }
        let (have, have_w) = (d.quadric[v], d.weight[v]);
        let tol = 1e-9 * w.abs().max(1e-300);
        assert!(
            (have_w - w).abs() <= tol,
            "M2: vertex {v}'s weight {have_w} is not its class's sum {w}"
        );
        // The quadrics compared at the vertex and at the corners of its class's box.
        let p = d.pos[v];
        for probe in [p, [p[0] + 1.0, p[1], p[2]], [p[0], p[1] - 1.0, p[2] + 1.0]] {
            let (a, b) = (have.error(probe), q.error(probe));
            let scale = a.abs().max(b.abs()).max(w);
            assert!(
                (a - b).abs() <= 1e-8 * scale,
                "M2: vertex {v}'s quadric gives {a} at {probe:?}, its class's sum {b}"
            );
        }
    }
}
