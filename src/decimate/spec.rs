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
//! - **M4, current entries** (the exact schedule): every entry the queue hands out as
//!   current names a live real edge that no guard has refused since the last collapse
//!   next to it, at its cost now (recomputed from the endpoints' quadrics; not below it
//!   where the fold-over guard refused the placement's position).
//!
//! M1 and the blocked half of M3 examine every edge, so they run in full on meshes of at
//! most [`FULL_CHECK_FACES`] live faces (the tests' sizes) and are skipped above.

use super::run::{pair, Candidate, Decimator};
use super::Stopped;
use crate::core::ids::NONE;
use crate::core::VertexId;
use crate::simplify::geometry::{fan_move_ok, Quadric};
use crate::spec::ENABLED;

/// Live faces up to which the checks over every edge run.
pub(crate) const FULL_CHECK_FACES: usize = 1500;

/// Whether `[p, q]` may be collapsed now, decided without the decimator's own walk: its
/// key when it may. The position is the placement's if the guard accepts it, else the
/// first of the decimator's alternatives it accepts (their list is the definition; the
/// guard's verdict on each is decided here), at the larger of the two costs.
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
    let cost = if !d.opts.guard || guard_ok(d, &c) {
        c.cost
    } else {
        let alt = d.alternatives(&c).into_iter().find(|a| guard_ok(d, a))?;
        alt.cost.max(c.cost)
    };
    let (a, b) = if p < q { (p, q) } else { (q, p) };
    Some((cost, a.0, b.0))
}

/// The fold-over guard over the faces found here: every real face with exactly one of
/// the two endpoints, whose corner there moves, passes the guard's test
/// (`fan_move_ok`, with the face rotated to start at the moving corner: the same
/// arithmetic as the decimator's, so that both decide alike on any scale; the test
/// itself is checked against its reference form `moved_triangle_ok` in
/// `simplify::geometry`'s tests). The faces are enumerated from the stars of both
/// endpoints, sorted and deduplicated, without the decimator's walk.
fn guard_ok(d: &Decimator<'_>, c: &Candidate) -> bool {
    let pos = |v: VertexId| d.vert[v.index()].pos;
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
        let k = vs.iter().position(|&v| v == moved).unwrap_or(0);
        let (p1, p2) = (vs[(k + 1) % 3], vs[(k + 2) % 3]);
        if !fan_move_ok(pos(moved), c.position, pos(p1), pos(p2)) {
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
    let key = allowed(d, VertexId(p), VertexId(q));
    assert!(
        key.is_some_and(|k| k.0.to_bits() == cost.to_bits()),
        "specification violated: M1 (priority): collapse {}: [{p}, {q}] at cost {cost} \
         (position {:?}) is not allowed at that cost now ({key:?})",
        d.collapses,
        c.position
    );
    for (p, q) in real_edges(d) {
        if let Some(key) = allowed(d, p, q) {
            assert!(
                key.0
                    .total_cmp(&chosen.0)
                    .then((key.1, key.2).cmp(&(chosen.1, chosen.2)))
                    != std::cmp::Ordering::Less,
                "specification violated: M1 (priority): collapse {}: [{}, {}] (cost {}) is allowed and cheaper than the chosen \
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

/// P1 (the pass schedule's M1), before the collapse of the edge `chosen` (its key in
/// the pass's list; candidate `c`) in the current pass, `previous` the key of the pass's
/// last collapse, `limit` the pass's first cost limit: the key is current (its cost is
/// the placement's cost now), the edge passes every guard, the pass takes keys in
/// increasing order, and no edge that passes every guard at a cost within `limit` has a
/// smaller key among those whose endpoints are neither merged in this pass nor next to
/// a vertex merged in it (only a collapse next to an edge can change its verdict, so
/// the pass met each of those with its verdict of now, and took it).
pub(super) fn before_pass_collapse(
    d: &Decimator<'_>,
    chosen: (f64, u32, u32),
    previous: Option<u128>,
    limit: f64,
    c: &Candidate,
) {
    if !ENABLED {
        return;
    }
    let (cost, p, q) = chosen;
    let (vp, vq) = (VertexId(p), VertexId(q));
    let now = d.candidate(vp, vq).ok().map(|c| c.cost);
    assert!(
        now.is_some_and(|now| now.to_bits() == cost.to_bits()) && allowed(d, vp, vq).is_some(),
        "specification violated: P1 (pass order): collapse {}: [{p}, {q}] at cost {cost} \
         (position {:?}) is not allowed at that cost now (its cost now: {now:?})",
        d.collapses,
        c.position
    );
    let k = super::queue::key(cost, p, q);
    assert!(
        previous.is_none_or(|prev| prev < k),
        "specification violated: P1 (pass order): collapse {}: [{p}, {q}] at cost {cost} \
         comes after a dearer key in pass {}",
        d.collapses,
        d.passes
    );
    if d.tri.face_count() > FULL_CHECK_FACES {
        return;
    }
    let pass = d.passes as u32;
    let n = d.pass_mark.len();
    let mut near = vec![false; n];
    for v in 0..n {
        if d.pass_mark[v] != pass {
            continue;
        }
        near[v] = true;
        let v = VertexId(v as u32);
        if d.tri.is_vertex(v) {
            for w in d.tri.link(v) {
                near[w.index()] = true;
            }
        }
    }
    for (a, b) in real_edges(d) {
        if near[a.index()] || near[b.index()] || allowed(d, a, b).is_none_or(|k| k.0 > limit) {
            continue;
        }
        let Ok(e) = d.candidate(a, b) else { continue };
        let (x, y) = if a < b { (a.0, b.0) } else { (b.0, a.0) };
        assert!(
            super::queue::key(e.cost, x, y) >= k,
            "specification violated: P1 (pass order): collapse {}: [{x}, {y}] (cost {}) is \
             allowed, away from this pass's collapses and cheaper than the chosen [{p}, {q}] \
             (cost {cost})",
            d.collapses,
            e.cost
        );
    }
}

/// M4, when the queue hands out the entry `(cost, p, q)` as current, before it is
/// resolved: `[p, q]` is a live real edge, not refused by a guard since the last collapse
/// next to it (only such a collapse can change the verdict, so a second verdict would
/// count one refusal twice), at its cost now: the placement's cost recomputed from the
/// endpoints' quadrics, or, where the fold-over guard refused the placement's position
/// and the edge was queued again at an alternative's cost, not below it (a stale cost
/// would order the edge among the others wrongly).
pub(super) fn current_entry(d: &Decimator<'_>, cost: f64, p: VertexId, q: VertexId) {
    if !ENABLED {
        return;
    }
    let n = d.collapses;
    assert!(
        !d.is_virtual(p) && !d.is_virtual(q) && d.tri.find_edge(p, q).is_some(),
        "specification violated: M4 (current entries): collapse {n}: the queue handed out [{p}, {q}], which is not a real edge"
    );
    let adjusted = d.adjusted.get(&pair(p, q)).copied();
    assert!(
        adjusted != Some(true),
        "specification violated: M4 (current entries): collapse {n}: the queue handed out [{p}, {q}], refused since the last collapse next to it"
    );
    let now = d.candidate(p, q).map(|c| c.cost);
    let current = match now {
        Ok(c) if adjusted.is_none() => c.to_bits() == cost.to_bits(),
        Ok(c) => cost >= c,
        Err(_) => false,
    };
    assert!(
        current,
        "specification violated: M4 (current entries): collapse {n}: the queue handed out [{p}, {q}] at cost {cost}; its cost now: {now:?}"
    );
}

/// M3, when the queue is empty short of the target: the sweep found `missed` allowed
/// edges; there must be none.
pub(super) fn nothing_missed(d: &Decimator<'_>, missed: usize) {
    if !ENABLED {
        return;
    }
    assert!(
        missed == 0,
        "specification violated: M3 (stop rule): the queue ran out with {missed} edges that pass every guard (collapse {})",
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
    assert!(
        real == d.real_faces,
        "specification violated: M3 (stop rule): {} faces kept, {real} in the triangulation",
        d.real_faces
    );
    match stopped {
        Stopped::Target => {
            assert!(
                d.real_faces <= d.target,
                "specification violated: M3 (stop rule): stopped at the target with {} faces, above the target {}",
                d.real_faces,
                d.target
            );
            assert!(
                d.collapses == 0 || d.real_faces + 2 > d.target,
                "specification violated: M3 (stop rule): {} faces, the target {} was passed by more than one collapse",
                d.real_faces,
                d.target
            );
        }
        Stopped::Error | Stopped::Blocked => {
            assert!(
                d.real_faces > d.target,
                "specification violated: M3 (stop rule): {stopped} with {} faces, at the target {}",
                d.real_faces,
                d.target
            );
            if d.tri.face_count() <= FULL_CHECK_FACES {
                for (p, q) in real_edges(d) {
                    assert!(
                        allowed(d, p, q).is_none(),
                        "specification violated: M3 (stop rule): stopped ({stopped}) with [{p}, {q}] allowed"
                    );
                }
            }
        }
    }
    // M2: each live vertex's quadric is the sum of its class's initial quadrics (summed
    // here in id order, so equal up to rounding).
    let n = d.vert.len();
    let mut sum = vec![(Quadric::default(), 0.0f64); n];
    for v in 0..d.first_virtual as usize {
        if d.vert[v].merged_into == NONE && !d.tri.is_vertex(VertexId(v as u32)) {
            continue;
        }
        let mut r = v;
        while d.vert[r].merged_into != NONE {
            r = d.vert[r].merged_into as usize;
        }
        let (q, w) = d.initial[v];
        sum[r].0.add(&q);
        sum[r].1 += w;
    }
    for (v, &(q, w)) in sum.iter().enumerate().take(d.first_virtual as usize) {
        if !d.tri.is_vertex(VertexId(v as u32)) {
            continue;
        }
        let (have, have_w) = (d.vert[v].quadric, d.vert[v].weight);
        let tol = 1e-9 * w.abs().max(1e-300);
        assert!(
            (have_w - w).abs() <= tol,
            "specification violated: M2 (quadric sums): vertex {v}'s weight {have_w} is not its class's sum {w}"
        );
        // The quadrics compared at the vertex and at the corners of its class's box.
        let p = d.vert[v].pos;
        for probe in [p, [p[0] + 1.0, p[1], p[2]], [p[0], p[1] - 1.0, p[2] + 1.0]] {
            let (a, b) = (have.error(probe), q.error(probe));
            let scale = a.abs().max(b.abs()).max(w);
            assert!(
                (a - b).abs() <= 1e-8 * scale,
                "specification violated: M2 (quadric sums): vertex {v}'s quadric gives {a} at {probe:?}, its class's sum {b}"
            );
        }
    }
}

/// Corrupted-state tests of M1–M3, compiled only where the checks are (elsewhere every
/// check returns at once and nothing would be tested).
#[cfg(all(test, any(debug_assertions, feature = "invariants")))]
mod tests {
    use super::*;
    use crate::core::ConedSurfaces;
    use crate::decimate::{Options, Placement, Schedule};
    use crate::gen;
    use crate::simplify::Point;
    use crate::spec::testing::assert_fails;

    fn options(target_faces: usize) -> Options {
        Options {
            target_faces,
            max_error: None,
            placement: Placement::Optimal,
            schedule: crate::decimate::Schedule::Exact,
            guard: true,
            lock_boundary: false,
            locked: Vec::new(),
        }
    }

    fn sphere() -> crate::TriMesh {
        gen::isosurface(&gen::IsoParams::new(
            gen::Implicit::Sphere { radius: 1.0 },
            gen::Tessellation::SixTetrahedra,
            6,
        ))
        .expect("a sphere")
    }

    fn decimator<'o>(mesh: &crate::TriMesh, opts: &'o Options) -> Decimator<'o> {
        let whole = ConedSurfaces::whole(mesh.vertex_count, &mesh.faces).expect("a surface");
        let positions = mesh.positions.as_deref().expect("positions");
        Decimator::new(whole, positions, opts)
    }

    /// The `m × n` grid of squares, each split along a diagonal, with vertex `(i, j)` at
    /// `at(i, j)`; with `wrap`, opposite sides are identified (a torus).
    fn grid(m: u32, n: u32, wrap: bool, at: impl Fn(u32, u32) -> Point) -> crate::TriMesh {
        let (vm, vn) = if wrap { (m, n) } else { (m + 1, n + 1) };
        let id = |i: u32, j: u32| (i % vm) * vn + j % vn;
        let mut faces = Vec::new();
        for i in 0..m {
            for j in 0..n {
                let (a, b, c, e) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
                faces.push([a, b, c]);
                faces.push([a, c, e]);
            }
        }
        let positions = (0..vm)
            .flat_map(|i| (0..vn).map(move |j| (i, j)))
            .map(|(i, j)| at(i, j))
            .collect();
        crate::TriMesh::with_positions(positions, faces)
    }

    /// A flat square grid on integer points: every edge whose collapse keeps the vertex
    /// in the plane costs exactly 0, so many allowed edges tie on cost and only their
    /// endpoints order them.
    fn flat() -> crate::TriMesh {
        grid(5, 5, false, |i, j| [f64::from(i), f64::from(j), 0.0])
    }

    /// Among the allowed edges of cost 0, two with the same smallest endpoint `p`: the
    /// edge to its smallest allowed neighbour, and the edge to the next one, with its
    /// candidate. No allowed edge of cost 0 has an endpoint below `p`. (The keys are
    /// made here from the edge list, which gives each edge as `(u, v)` with `u < v`.)
    fn tied(d: &Decimator<'_>) -> ((f64, u32, u32), (f64, u32, u32), Candidate) {
        let mut zero: Vec<_> = real_edges(d)
            .into_iter()
            .filter(|&(p, q)| allowed(d, p, q).is_some_and(|k| k.0 == 0.0))
            .map(|(p, q)| (0.0, p.0, q.0))
            .collect();
        zero.sort_by_key(|k| (k.1, k.2));
        let (first, second) = (zero[0], zero[1]);
        assert_eq!(
            first.1, second.1,
            "two allowed edges of cost 0 at {}",
            first.1
        );
        let c = d
            .candidate(VertexId(second.1), VertexId(second.2))
            .expect("allowed");
        (first, second, c)
    }

    /// The cheapest and the dearest allowed edge with their candidates.
    fn extremes(d: &Decimator<'_>) -> [((f64, u32, u32), Candidate); 2] {
        let mut all: Vec<_> = real_edges(d)
            .into_iter()
            .filter_map(|(p, q)| Some((allowed(d, p, q)?, d.candidate(p, q).ok()?)))
            .collect();
        all.sort_by(|a, b| {
            a.0 .0
                .total_cmp(&b.0 .0)
                .then((a.0 .1, a.0 .2).cmp(&(b.0 .1, b.0 .2)))
        });
        let last = all.len() - 1;
        assert!(
            all[0].0 .0 < all[last].0 .0,
            "costs differ on a curved sphere"
        );
        [all[0], all[last]]
    }

    /// The pass orders by the placement's cost: the cheapest and the dearest allowed
    /// edge by that cost, among those the guard takes at the placement's position.
    fn pass_extremes(d: &Decimator<'_>) -> [((f64, u32, u32), Candidate); 2] {
        let mut all: Vec<_> = real_edges(d)
            .into_iter()
            .filter_map(|(p, q)| {
                let k = allowed(d, p, q)?;
                let c = d.candidate(p, q).ok()?;
                (k.0 == c.cost).then_some((k, c))
            })
            .collect();
        all.sort_by(|a, b| a.0 .0.total_cmp(&b.0 .0));
        [all[0], all[all.len() - 1]]
    }

    #[test]
    fn m1_accepts_the_cheapest_edge_and_fails_on_a_dearer_one() {
        let mesh = sphere();
        let opts = options(0);
        let d = decimator(&mesh, &opts);
        let [(cheap, c), (dear, e)] = extremes(&d);
        before_collapse(&d, cheap, &c);
        assert_fails("M1", || before_collapse(&d, dear, &e));
        // The right edge with a cost that is not its own.
        let wrong = (cheap.0 + 1.0, cheap.1, cheap.2);
        assert_fails("M1", || before_collapse(&d, wrong, &c));
    }

    #[test]
    fn p1_accepts_the_cheapest_edge_and_fails_on_a_dearer_one_a_stale_key_or_a_step_back() {
        let mesh = sphere();
        let opts = Options {
            schedule: crate::decimate::Schedule::Passes,
            ..options(0)
        };
        let mut d = decimator(&mesh, &opts);
        d.passes = 1;
        let [(cheap, c), (dear, e)] = pass_extremes(&d);
        assert!(cheap.0 < dear.0);
        let k = |x: (f64, u32, u32)| super::super::queue::key(x.0, x.1, x.2);
        before_pass_collapse(&d, cheap, None, f64::INFINITY, &c);
        assert_fails("P1", || {
            before_pass_collapse(&d, dear, None, f64::INFINITY, &e)
        });
        assert_fails("P1", || {
            before_pass_collapse(&d, dear, Some(k(cheap)), f64::INFINITY, &e)
        });
        // A dearer edge is fine when every cheaper one is beyond the first limit, or next
        // to a collapse of the pass.
        before_pass_collapse(&d, dear, None, -1.0, &e);
        let n = d.pass_mark.len();
        for v in 0..n {
            if v as u32 != dear.1 && v as u32 != dear.2 {
                d.pass_mark[v] = 1;
            }
        }
        before_pass_collapse(&d, dear, None, f64::INFINITY, &e);
        d.pass_mark.fill(0);
        // A stale cost; a key below the pass's previous one.
        let wrong = (cheap.0 + 1.0, cheap.1, cheap.2);
        assert_fails("P1", || {
            before_pass_collapse(&d, wrong, None, f64::INFINITY, &c)
        });
        assert_fails("P1", || {
            before_pass_collapse(&d, cheap, Some(k(dear)), f64::INFINITY, &c)
        });
    }

    #[test]
    fn m2_fails_on_a_quadric_that_is_not_its_class_sum() {
        let mesh = sphere();
        let opts = options(mesh.faces.len() / 2);
        let mut d = decimator(&mesh, &opts);
        assert!(d.run(&mut crate::progress::ignore, &|| false));
        at_end(&d, Stopped::Target);
        let v = (0..d.first_virtual as usize)
            .find(|&v| d.tri.is_vertex(VertexId(v as u32)))
            .expect("a live vertex");
        let extra = d.initial[v].0;
        d.vert[v].quadric.add(&extra);
        assert_fails("M2", || at_end(&d, Stopped::Target));
    }

    #[test]
    fn m4_accepts_a_current_entry_and_fails_on_a_stale_cost_a_non_edge_and_a_refused_edge() {
        let mesh = sphere();
        let opts = options(0);
        let mut d = decimator(&mesh, &opts);
        let [(cheap, _), _] = extremes(&d);
        let (cost, p, q) = (cheap.0, VertexId(cheap.1), VertexId(cheap.2));
        current_entry(&d, cost, p, q);
        assert_fails("M4", || current_entry(&d, cost * 2.0 + 1.0, p, q));
        let far = (0..d.first_virtual)
            .map(VertexId)
            .find(|&v| v != p && d.tri.is_vertex(v) && d.tri.find_edge(p, v).is_none())
            .expect("a vertex not next to p");
        assert_fails("M4", || current_entry(&d, cost, p, far));
        // Queued again above the placement's cost: accepted there, not below it.
        d.adjusted.insert(pair(p, q), false);
        current_entry(&d, cost * 2.0 + 1.0, p, q);
        if cost > 0.0 {
            assert_fails("M4", || current_entry(&d, cost / 2.0, p, q));
        }
        d.adjusted.insert(pair(p, q), true);
        assert_fails("M4", || current_entry(&d, cost, p, q));
    }

    #[test]
    fn m3_fails_on_a_wrong_count_a_missed_target_and_an_allowed_edge_left() {
        let mesh = sphere();
        let opts = options(mesh.faces.len() / 2);
        let mut d = decimator(&mesh, &opts);
        assert!(d.run(&mut crate::progress::ignore, &|| false));
        at_end(&d, Stopped::Target);
        // Said to be blocked while at the target; said to be blocked with edges left.
        assert_fails("M3", || at_end(&d, Stopped::Blocked));
        d.target = 0;
        assert_fails("M3", || at_end(&d, Stopped::Blocked));
        assert_fails("M3", || at_end(&d, Stopped::Target));
        d.target = opts.target_faces;
        d.real_faces += 2;
        assert_fails("M3", || at_end(&d, Stopped::Target));
        assert_fails("M3", || nothing_missed(&d, 1));
    }

    /// P1 orders the edges away from the pass's collapses by their keys, so at equal cost
    /// by their endpoints, smaller first.
    #[test]
    fn p1_breaks_cost_ties_by_the_endpoints() {
        let mesh = flat();
        let opts = Options {
            schedule: Schedule::Passes,
            ..options(0)
        };
        let mut d = decimator(&mesh, &opts);
        d.passes = 1;
        let (first, second, c) = tied(&d);
        let cf = d
            .candidate(VertexId(first.1), VertexId(first.2))
            .expect("allowed");
        before_pass_collapse(&d, first, None, f64::INFINITY, &cf);
        assert_fails("cheaper than the chosen", || {
            before_pass_collapse(&d, second, None, f64::INFINITY, &c)
        });
    }

    /// P1's limit includes its bound: with the limit at the smallest cost of an allowed
    /// edge, the edges at that cost are within it, and a dearer choice fails.
    #[test]
    fn p1_holds_the_edges_at_the_limit_itself() {
        let mesh = sphere();
        let opts = Options {
            schedule: Schedule::Passes,
            ..options(0)
        };
        let mut d = decimator(&mesh, &opts);
        d.passes = 1;
        let [_, (dear, e)] = pass_extremes(&d);
        let limit = real_edges(&d)
            .into_iter()
            .filter_map(|(p, q)| allowed(&d, p, q))
            .map(|k| k.0)
            .fold(f64::INFINITY, f64::min);
        assert!(limit < dear.0);
        assert_fails("cheaper than the chosen", || {
            before_pass_collapse(&d, dear, None, limit, &e)
        });
        // Just below the smallest cost no edge is held (costs are never negative).
        let below = if limit > 0.0 {
            f64::from_bits(limit.to_bits() - 1)
        } else {
            -1.0
        };
        before_pass_collapse(&d, dear, None, below, &e);
    }

    /// The checks over every edge run on a mesh of exactly [`FULL_CHECK_FACES`] faces
    /// (a closed torus grid, every face real): M1 and P1 fail on the dearest allowed
    /// edge there.
    #[test]
    fn the_full_checks_run_at_their_face_bound() {
        let (m, n) = (FULL_CHECK_FACES as u32 / 60, 30);
        let torus = grid(m, n, true, |i, j| {
            let (u, v) = (
                std::f64::consts::TAU * f64::from(i) / f64::from(m),
                std::f64::consts::TAU * f64::from(j) / f64::from(n),
            );
            let r = 3.0 + v.cos();
            [r * u.cos(), r * u.sin(), v.sin()]
        });
        assert_eq!(torus.faces.len(), FULL_CHECK_FACES);
        let opts = options(0);
        let d = decimator(&torus, &opts);
        assert_eq!(d.tri.face_count(), FULL_CHECK_FACES);
        let [(cheap, c), (dear, e)] = extremes(&d);
        before_collapse(&d, cheap, &c);
        assert_fails("cheaper than the chosen", || before_collapse(&d, dear, &e));
        let opts = Options {
            schedule: Schedule::Passes,
            ..options(0)
        };
        let mut d = decimator(&torus, &opts);
        d.passes = 1;
        let [(cheap, c), (dear, e)] = pass_extremes(&d);
        before_pass_collapse(&d, cheap, None, f64::INFINITY, &c);
        assert_fails("cheaper than the chosen", || {
            before_pass_collapse(&d, dear, None, f64::INFINITY, &e)
        });
    }

    /// M2 compares the quadrics at three points: the vertex `p`, `p + x̂` and
    /// `p − ŷ + ẑ`. A difference `u (u ± 1)` in one coordinate `u` measured from `p`
    /// (zero at `u = 0` and at `u = ∓1`, 2 at `u = ±1`) is seen at exactly one of them,
    /// and must fail the check: along x at the second point, along y and along z at the
    /// third.
    #[test]
    fn m2_fails_on_a_difference_seen_at_one_of_its_points() {
        let mesh = sphere();
        let opts = options(mesh.faces.len() / 2);
        let mut d = decimator(&mesh, &opts);
        assert!(d.run(&mut crate::progress::ignore, &|| false));
        let v = (0..d.first_virtual as usize)
            .find(|&v| d.tri.is_vertex(VertexId(v as u32)))
            .expect("a live vertex");
        let p = d.vert[v].pos;
        let kept = d.vert[v].quadric;
        for (axis, sign) in [(0, 1.0), (1, -1.0), (2, 1.0)] {
            let mut normal = [0.0; 3];
            normal[axis] = 1.0;
            let at = |t: f64| {
                let mut x = p;
                x[axis] += t;
                x
            };
            // u (u + s) = ¼ (u + s)² + u² − ¼ (u − s)², each square a plane's quadric.
            let mut bump = Quadric::plane(normal, at(-sign), 0.25);
            bump.add(&Quadric::plane(normal, p, 1.0));
            bump.add(&Quadric::plane(normal, at(sign), -0.25));
            assert!(bump.error(p).abs() < 1e-12 && bump.error(at(-sign)).abs() < 1e-12);
            assert!((bump.error(at(sign)) - 2.0).abs() < 1e-12);
            d.vert[v].quadric.add(&bump);
            assert_fails("quadric gives", || at_end(&d, Stopped::Target));
            d.vert[v].quadric = kept;
            at_end(&d, Stopped::Target);
        }
    }

    /// M2 holds a weight to a relative rounding error of 1e-9: off by 1e-12 of itself it
    /// passes, off by 1e-8 of itself it fails. The vertex is a light one (weight below
    /// 0.25), where a tolerance that grew with the weight plus a constant, or shrank as
    /// the weight grew, would let the second through.
    #[test]
    fn m2_holds_weights_to_a_relative_tolerance() {
        let mesh = sphere();
        let opts = options(mesh.faces.len());
        let mut d = decimator(&mesh, &opts);
        at_end(&d, Stopped::Target);
        let v = (0..d.first_virtual as usize)
            .filter(|&v| d.tri.is_vertex(VertexId(v as u32)))
            .min_by(|&a, &b| d.vert[a].weight.total_cmp(&d.vert[b].weight))
            .expect("a live vertex");
        let w = d.vert[v].weight;
        assert!(0.0 < w && w < 0.25, "a light vertex: {w}");
        d.vert[v].weight = w * (1.0 + 1e-12);
        at_end(&d, Stopped::Target);
        d.vert[v].weight = w * (1.0 + 1e-8);
        assert_fails("weight", || at_end(&d, Stopped::Target));
    }
}
