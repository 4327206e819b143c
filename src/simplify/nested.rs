//! The nested mode: the paper's processEdge. An edge `[p, q]` that fails the link
//! condition because of common neighbours `x₁ … x_k` besides its opposite vertices `a`
//! and `b` lies on the 3-cycles `p q xᵢ`. Each such cycle that separates the surface
//! puts `a` on one side and `b` on the other; the cycles are nested, ordered along the
//! link of `p` from `a` to `b`. Removing what lies strictly inside the outermost cycle on
//! `a`'s side and the outermost on `b`'s side leaves `p` and `q` with exactly two common
//! neighbours, and the edge can be contracted (findOuterVertices, findInterVertices,
//! then the contraction).
//!
//! **Guarantee (beyond the paper).** A side is removed only if it is a closed disc
//! bounded by its 3-cycle: the faces reached from the edge's face on that side without
//! crossing the cycle's three edges contain each of those edges exactly once, and their
//! count is `2I + 1` for `I` interior vertices (Euler characteristic 1), none of which is
//! a cone apex (no boundary loop inside). A region that reaches the other side's region
//! (the cycle does not separate: it goes around a handle) or fails the count (the side
//! carries genus) or holds a boundary loop makes the edge skipped, counted as
//! [`super::SkipCounts::non_disc`]. Replacing a disc by a triangle on the same boundary
//! does not change the surface, so the nested mode never changes it either; the
//! specification re-derives every disc independently (`spec::disc`).
//!
//! **How the cycles are split between the sides** ([`super::Side`]). `Count` (default):
//! both sides grow in lockstep, face by face, always extending the smaller region (`a`'s
//! on a tie); a side whose region closes on its current cycle claims it and goes on to
//! the next cycle inwards-out; so the side with fewer vertices inside takes each cycle,
//! and of two that close on the same cycle with as many faces, `a`'s. `Path` and
//! `Euclidean` fix the split first (each cycle to the side whose opposite vertex is
//! nearer, in edge hops avoiding `p` and `q`, or in space; the `a` side takes as many
//! cycles, from `x₁` on, as were assigned to it) and then grow the same way. If a side
//! fails the disc test, the other side may take the remaining cycles.
//!
//! **Complexity.** O(faces of both regions grown), which the lockstep keeps within about
//! twice the part removed when the smaller side is a disc; O(d_p + d_q) on top.

use super::geometry::dist2;
use super::state::{Claim, EdgeInfo, RegionState, Simplifier, Skip};
use super::Side;
use crate::core::{FaceId, VertexId};

/// The two regions met: the cycles do not separate the sides.
struct Meet;

/// The discs to remove before contracting the edge (none if the edge already passes
/// the link condition), or why the edge is skipped.
pub(super) fn plan(sim: &mut Simplifier<'_>, e: &EdgeInfo) -> Result<[Option<Claim>; 2], Skip> {
    let k = sim.xs.len();
    if k == 0 {
        return Ok([None, None]);
    }
    let split = match sim.opts.side {
        Side::Count => None,
        Side::Path => Some(path_split(sim, e)),
        Side::Euclidean => euclidean_split(sim, e),
    };
    let starts = [e.corner.face(), sim.tri.opposite(e.corner).face()];
    for s in 0..2 {
        let stamp = sim.fresh_stamp();
        let g = &mut sim.grow[s];
        g.queue.clear();
        g.blocked.clear();
        g.head = 0;
        g.state = RegionState::Waiting;
        g.started = false;
        g.claim = None;
        g.verts = 0;
        g.virtuals = 0;
        g.stamp = stamp;
    }
    // The unclaimed cycles are xs[lo..hi]: side a claims from the front, b from the back.
    let (mut lo, mut hi) = (0usize, k);
    let mut unlimited = [false; 2];
    let allowed = |s: usize, t: usize, unlimited: &[bool; 2]| {
        unlimited[s] || split.is_none_or(|j| if s == 0 { t < j } else { t >= j })
    };
    for (s, &start) in starts.iter().enumerate() {
        let t = if s == 0 { lo } else { hi - 1 };
        if allowed(s, t, &unlimited) {
            activate(sim, e, s, t, start).map_err(|Meet| Skip::NonDisc)?;
        }
    }
    while lo < hi {
        let mut pick = None;
        for s in 0..2 {
            if matches!(sim.grow[s].state, RegionState::Active(_))
                && pick.is_none_or(|p: usize| sim.grow[s].queue.len() < sim.grow[p].queue.len())
            {
                pick = Some(s);
            }
        }
        let Some(s) = pick else {
            return Err(Skip::NonDisc);
        };
        let RegionState::Active(t) = sim.grow[s].state else {
            unreachable!("picked an active side")
        };
        if sim.grow[s].head < sim.grow[s].queue.len() {
            step(sim, e, s, t).map_err(|Meet| Skip::NonDisc)?;
        }
        if sim.grow[s].head < sim.grow[s].queue.len() {
            continue;
        }
        // The region closed on the cycle through xs[t].
        match check_claim(sim, e, s, t) {
            Some(claim) => {
                sim.grow[s].claim = Some(claim);
                if s == 0 {
                    lo += 1;
                } else {
                    hi -= 1;
                }
                if lo == hi {
                    break;
                }
                let next = if s == 0 { lo } else { hi - 1 };
                if allowed(s, next, &unlimited) {
                    activate(sim, e, s, next, starts[s]).map_err(|Meet| Skip::NonDisc)?;
                } else {
                    sim.grow[s].state = RegionState::Waiting;
                }
            }
            None => {
                sim.grow[s].state = RegionState::Dead;
                let o = 1 - s;
                if sim.grow[o].state == RegionState::Dead {
                    return Err(Skip::NonDisc);
                }
                unlimited[o] = true;
                if sim.grow[o].state == RegionState::Waiting {
                    let next = if o == 0 { lo } else { hi - 1 };
                    activate(sim, e, o, next, starts[o]).map_err(|Meet| Skip::NonDisc)?;
                }
            }
        }
    }
    Ok([sim.grow[0].claim, sim.grow[1].claim])
}

/// Sets side `s` growing towards the cycle through `xs[t]`: from its start face the
/// first time, otherwise across the two edges of its last claimed cycle other than
/// `[p, q]`.
fn activate(
    sim: &mut Simplifier<'_>,
    e: &EdgeInfo,
    s: usize,
    t: usize,
    start: FaceId,
) -> Result<(), Meet> {
    sim.grow[s].state = RegionState::Active(t);
    if !sim.grow[s].started {
        sim.grow[s].started = true;
        return cross(sim, e, s, start);
    }
    let blocked = std::mem::take(&mut sim.grow[s].blocked);
    for &c in &blocked {
        let [s1, s2] = sim.tri.edge_endpoints(c);
        if is_pq(e, s1, s2) {
            sim.grow[s].blocked.push(c);
        } else {
            let g = sim.tri.opposite(c).face();
            cross(sim, e, s, g)?;
        }
    }
    Ok(())
}

#[inline]
fn is_pq(e: &EdgeInfo, s1: VertexId, s2: VertexId) -> bool {
    (s1 == e.p && s2 == e.q) || (s1 == e.q && s2 == e.p)
}

/// Adds face `g` to side `s`'s region unless it is there already; fails if the other
/// side has it.
#[inline]
fn cross(sim: &mut Simplifier<'_>, e: &EdgeInfo, s: usize, g: FaceId) -> Result<(), Meet> {
    let mark = sim.fmark[g.index()];
    if mark == sim.grow[s].stamp {
        return Ok(());
    }
    if mark == sim.grow[1 - s].stamp {
        return Err(Meet);
    }
    let stamp = sim.grow[s].stamp;
    sim.fmark[g.index()] = stamp;
    sim.grow[s].queue.push(g);
    for w in sim.tri.face_vertices(g) {
        if w == e.p || w == e.q || sim.vmark[w.index()] == stamp || sim.xs.contains(&w) {
            continue;
        }
        sim.vmark[w.index()] = stamp;
        sim.grow[s].verts += 1;
        if sim.is_virtual(w) {
            sim.grow[s].virtuals += 1;
        }
    }
    Ok(())
}

/// Expands the next face of side `s`'s region, bounded by the cycle `p q xs[t]`.
fn step(sim: &mut Simplifier<'_>, e: &EdgeInfo, s: usize, t: usize) -> Result<(), Meet> {
    let x = sim.xs[t];
    let f = sim.grow[s].queue[sim.grow[s].head];
    sim.grow[s].head += 1;
    let on_cycle = |w: VertexId| w == e.p || w == e.q || w == x;
    for c in f.corners() {
        let [s1, s2] = sim.tri.edge_endpoints(c);
        if on_cycle(s1) && on_cycle(s2) {
            sim.grow[s].blocked.push(c);
        } else {
            let g = sim.tri.opposite(c).face();
            cross(sim, e, s, g)?;
        }
    }
    Ok(())
}

/// The claim of side `s` on the cycle `p q xs[t]` its region just closed on, if the
/// region is a closed disc bounded by that cycle with no boundary loop inside.
fn check_claim(sim: &Simplifier<'_>, e: &EdgeInfo, s: usize, t: usize) -> Option<Claim> {
    let x = sim.xs[t];
    let g = &sim.grow[s];
    let mut sides = [None; 3];
    for &c in &g.blocked {
        let [s1, s2] = sim.tri.edge_endpoints(c);
        let edge = if is_pq(e, s1, s2) {
            0
        } else if (s1 == e.q && s2 == x) || (s1 == x && s2 == e.q) {
            1
        } else {
            2
        };
        if sides[edge].replace(c).is_some() {
            return None; // an edge of the cycle with both faces in the region
        }
    }
    let sides = [sides[0]?, sides[1]?, sides[2]?];
    // The cycles this side claimed before lie inside; their vertices are interior.
    let inner = if s == 0 { 0..t } else { t + 1..sim.xs.len() };
    if sim.xs[inner.clone()].iter().any(|&w| sim.is_virtual(w)) || g.virtuals > 0 {
        return None;
    }
    let interior = g.verts + inner.len();
    (g.queue.len() == 2 * interior + 1).then_some(Claim {
        x,
        faces: g.queue.len(),
        sides,
    })
}

/// `Side::Path`: the number of cycles side `a` takes, from a lockstep breadth-first
/// search from `a` and `b` avoiding `p` and `q` (a cycle goes to the side that reaches
/// its vertex first, `a` on ties; one reached by neither goes to `a`).
fn path_split(sim: &mut Simplifier<'_>, e: &EdgeInfo) -> usize {
    let k = sim.xs.len();
    let stamps = [sim.fresh_stamp(), sim.fresh_stamp()];
    let mut label = vec![0u8; k];
    let mut left = k;
    let mut frontier = [vec![e.a], vec![e.b]];
    sim.vmark[e.a.index()] = stamps[0];
    sim.vmark[e.b.index()] = stamps[1];
    let mut next = Vec::new();
    while left > 0 && frontier.iter().any(|f| !f.is_empty()) {
        for s in 0..2 {
            next.clear();
            for &v in &frontier[s] {
                for n in sim.tri.link(v) {
                    let m = sim.vmark[n.index()];
                    if n == e.p || n == e.q || m == stamps[0] || m == stamps[1] {
                        continue;
                    }
                    sim.vmark[n.index()] = stamps[s];
                    if let Some(i) = sim.xs.iter().position(|&x| x == n) {
                        label[i] = s as u8;
                        left -= 1;
                    }
                    if !sim.is_virtual(n) {
                        next.push(n);
                    }
                }
            }
            std::mem::swap(&mut frontier[s], &mut next);
        }
    }
    label.iter().filter(|&&l| l == 0).count()
}

/// `Side::Euclidean`: the number of cycles side `a` takes (those whose vertex is at
/// least as near `a` as `b`); `None` (lockstep counting) when a cone apex is involved.
fn euclidean_split(sim: &Simplifier<'_>, e: &EdgeInfo) -> Option<usize> {
    if sim.is_virtual(e.a) || sim.is_virtual(e.b) || sim.xs.iter().any(|&x| sim.is_virtual(x)) {
        return None;
    }
    let (pa, pb) = (sim.vert[e.a.index()].pos, sim.vert[e.b.index()].pos);
    Some(
        sim.xs
            .iter()
            .filter(|&&x| {
                let px = sim.vert[x.index()].pos;
                dist2(px, pa) <= dist2(px, pb)
            })
            .count(),
    )
}
