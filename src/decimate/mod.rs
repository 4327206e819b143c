//! Decimation to a budget without changing the topology: quadric-error edge collapse
//! (Garland–Heckbert) in which every collapse passes the link condition of the surface
//! with boundary, on closed surfaces and surfaces with boundary, orientable or not,
//! several components at once.
//!
//! **Guarantee.** Every component of the output is a 2-manifold of the same topological
//! type as the input's (Euler characteristic, orientability, boundary loops: the same
//! [`crate::SurfaceType`]), whatever the positions and options: every collapse passes the
//! link condition of the coned surface (module [`crate::core`]'s `boundary`; an edge
//! joining two boundary loops and an edge of a tetrahedron are refused too). Locked
//! vertices survive at their input positions. With the fold-over guard on (the
//! default), no collapse turns the normal of a face that moves by 90° or more or leaves
//! it with zero area. The run stops at the first of its targets reached
//! ([`Stopped::Target`]), or when every edge left is over the error cap
//! ([`Stopped::Error`]) or refused by a guard ([`Stopped::Blocked`]); in the last two
//! cases [`Stats::remaining`] classifies every edge left by the guard that refuses it.
//!
//! **Method.** Each vertex starts with the quadric of the planes of its faces, weighted
//! by their areas, plus, at the ends of every boundary edge, the plane through the edge
//! perpendicular to its face (ten times the face's weight), so that open borders keep
//! their shape. An edge's cost is the summed quadric of its endpoints at the position
//! [`Placement`] chooses. One priority queue over every edge of every component gives the
//! cheapest edge first (ties: the smaller endpoint ids); it is re-checked when it comes
//! out (link condition, fold-over guard), collapsed if it passes, dropped if not. When
//! the guard refuses the placement's position, the endpoints and the midpoint are tried,
//! cheapest first, and the edge goes back into the queue at the cost of the first the
//! guard accepts (never cheaper: the placement's cost is a lower bound). After a
//! collapse the merged vertex's edges enter the queue with their new costs, and so do
//! again the edges next to it that were refused or re-costed, since a collapse next to
//! them is the only thing that can change their verdict. Hence (the specification checks
//! it): **every collapse is of the cheapest edge that passes every guard at that
//! moment**, and the run stops only when the queue holds no such edge.
//!
//! **Schedules.** The above is [`Schedule::Exact`], the default. [`Schedule::Passes`]
//! (module `passes`) walks one sorted edge list in passes instead, each taking the
//! cheapest edges whose neighbourhoods no earlier collapse of the pass changed, up to a
//! cost limit: 1.6–2× faster, with a two-sided Hausdorff distance about the exact
//! schedule's (the median ratio 1.0 on the shared corpus, the largest 1.4). Every other
//! guarantee here holds for both.
//!
//! **The error.** The error of a vertex is `sqrt(Q(x) / W)`: the root mean square
//! distance of its position from the planes its quadric sums (every input face merged
//! into it, and the boundary planes), weighted by their areas. The error cap bounds it
//! for every output vertex; [`Stats::max_error`] is the largest reached.
//!
//! **Determinism.** The output depends only on the input (its face and vertex order)
//! and the options: no randomness, no hashing; the queue's ties are broken by vertex
//! ids. With the `parallel` feature, costing every edge at the start (and, in the pass
//! schedule, between passes) and sorting keys run on rayon's current pool (module
//! `pool`): the same costs and the same sorted lists on any number of threads, so the
//! same output. Output vertices are the surviving input vertices in increasing input
//! id, output faces the surviving input faces in increasing input id, each with the
//! vertex order (and so the orientation) of its input face.
//!
//! **Complexity.** O(F log F) time: each collapse costs O(d²) for the re-checks and
//! queue entries of the merged vertex's neighbourhood (d its degree; the pass schedule:
//! O(d) per collapse and O(E) per pass); memory under 150 bytes per triangle beyond
//! the input (corner table, positions, quadrics, per-corner edge costs or the pass
//! schedule's sorted keys, queue; 142.9 and 148.4 measured on a 4M-triangle sphere,
//! `docs/benchmarks.md`).

mod passes;
mod pool;
mod queue;
mod run;
mod spec;

use crate::core::ids::NONE;
use crate::simplify::Point;

pub use run::REMOVED;
pub(crate) use run::{input_stats, Decimator};

/// Where the vertex that replaces a collapsed edge goes. A locked endpoint overrides
/// every placement: the edge then collapses onto it.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Placement {
    /// The minimiser of the summed quadric; when its 3×3 system is ill-conditioned
    /// (planar or cylindrical regions), the best of the endpoints and the midpoint
    /// (default).
    #[default]
    Optimal,
    /// The edge's midpoint.
    Midpoint,
    /// The endpoint with the smaller quadric error (ties: the smaller id): every output
    /// position is an input position.
    Endpoint,
}

impl Placement {
    /// Every placement.
    pub const ALL: [Placement; 3] = [Placement::Optimal, Placement::Midpoint, Placement::Endpoint];

    /// The name used on the command line, in Python and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Placement::Optimal => "optimal",
            Placement::Midpoint => "midpoint",
            Placement::Endpoint => "endpoint",
        }
    }

    /// One line on the placement (the command line's help).
    pub fn summary(self) -> &'static str {
        match self {
            Placement::Optimal => {
                "The minimiser of the summed quadric (the best of the endpoints and the \
                 midpoint when it is ill-conditioned)"
            }
            Placement::Midpoint => "The edge's midpoint",
            Placement::Endpoint => {
                "The endpoint with the smaller error: every output position is an input position"
            }
        }
    }
}

crate::names::named_choice!(Placement, "placement");

/// The order in which edges are collapsed. Both schedules keep every guarantee of the
/// module (topology, guards, locks, targets, the error cap, the stop rule, determinism);
/// they differ in speed and in how close each collapse is to the cheapest one.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Schedule {
    /// One priority queue: every collapse is of the cheapest edge that passes every
    /// guard at that moment (default).
    #[default]
    Exact,
    /// Passes over a sorted list of the edges: each pass collapses, cheapest first, the
    /// edges whose endpoints no earlier collapse of the same pass merged, up to a cost
    /// limit set from the collapses still needed; only the merged vertices' edges are
    /// costed again between passes. Several times faster, with a somewhat larger error
    /// (`docs/peers.md`); see module `passes`.
    Passes,
}

impl Schedule {
    /// Every schedule.
    pub const ALL: [Schedule; 2] = [Schedule::Exact, Schedule::Passes];

    /// The name used on the command line, in Python and in JSON; it reads back as the
    /// schedule.
    ///
    /// ```
    /// use contractible::decimate::Schedule;
    /// assert_eq!(Schedule::Passes.name(), "passes");
    /// for s in Schedule::ALL {
    ///     assert_eq!(s.name().parse::<Schedule>(), Ok(s));
    /// }
    /// assert!("fast".parse::<Schedule>().is_err());
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Schedule::Exact => "exact",
            Schedule::Passes => "passes",
        }
    }

    /// One line on the schedule (the command line's help).
    ///
    /// ```
    /// use contractible::decimate::Schedule;
    /// assert!(Schedule::Exact.summary().contains("cheapest edge"));
    /// assert!(Schedule::Passes.summary().starts_with("Passes"));
    /// ```
    pub fn summary(self) -> &'static str {
        match self {
            Schedule::Exact => "Always the cheapest edge the guards allow (one priority queue)",
            Schedule::Passes => {
                "Passes of independent collapses over a sorted edge list: faster, somewhat \
                 larger error"
            }
        }
    }
}

crate::names::named_choice!(Schedule, "schedule");

/// Why the run stopped.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Stopped {
    /// A target (face count or fraction kept) was reached.
    #[default]
    Target,
    /// Every edge left is over the error cap or refused by a guard, and at least one is
    /// over the cap.
    Error,
    /// Every edge left is refused by a guard (with no target, this is the goal: as
    /// coarse as the guards allow).
    Blocked,
}

impl Stopped {
    /// The name used in JSON and Python: `"target"`, `"error"` or `"blocked"`.
    pub fn name(self) -> &'static str {
        match self {
            Stopped::Target => "target",
            Stopped::Error => "error",
            Stopped::Blocked => "blocked",
        }
    }
}

impl std::fmt::Display for Stopped {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Serialised as its name.
#[cfg(feature = "serde")]
impl serde::Serialize for Stopped {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

/// Edges refused, by the first guard that refuses them (checked in this order: locks,
/// the error cap, the link condition, the fold-over guard).
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Refusals {
    /// Both endpoints locked, at least one by the caller's list.
    pub lock: usize,
    /// Both endpoints on the boundary with boundary vertices locked.
    pub boundary: usize,
    /// The collapse's error would exceed the cap.
    pub error: usize,
    /// The edge fails the link condition of the surface with boundary (its endpoints
    /// have a common neighbour other than the two opposite vertices, or lie on two
    /// different boundary loops, or the edge is an edge of a tetrahedron): collapsing it
    /// would change the surface.
    pub link_condition: usize,
    /// The fold-over guard: a face would turn by 90° or more or lose its area.
    pub foldover: usize,
}

impl Refusals {
    /// The sum over all guards.
    pub fn total(&self) -> usize {
        self.lock + self.boundary + self.error + self.link_condition + self.foldover
    }

    pub(crate) fn count(&mut self, r: Refusal) {
        match r {
            Refusal::Lock => self.lock += 1,
            Refusal::Boundary => self.boundary += 1,
            Refusal::Error => self.error += 1,
            Refusal::LinkCondition => self.link_condition += 1,
            Refusal::Foldover => self.foldover += 1,
        }
    }
}

/// One guard's refusal of one edge.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum Refusal {
    Lock,
    Boundary,
    Error,
    LinkCondition,
    Foldover,
}

/// One component's part of a run (components in the order of their smallest input
/// face).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ComponentStats {
    /// Faces of the component in the input.
    pub faces_in: usize,
    /// Faces of the component in the output.
    pub faces_out: usize,
    /// Vertices in the input.
    pub vertices_in: usize,
    /// Vertices in the output.
    pub vertices_out: usize,
    /// Boundary loops (the same before and after).
    pub boundary_loops: usize,
    /// The component's edges left at the end, by the guard that refuses them (all zero
    /// when the run stopped at its target).
    pub remaining: Refusals,
}

/// What a run did (the command line's `decimate --json` keys).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Stats {
    /// Faces of the input.
    pub faces_in: usize,
    /// Faces of the output.
    pub faces_out: usize,
    /// Vertices of the input that faces use.
    pub vertices_in: usize,
    /// Vertices of the output.
    pub vertices_out: usize,
    /// Connected components.
    pub components: usize,
    /// Boundary loops (the same before and after).
    pub boundary_loops: usize,
    /// The face count the run aimed for (the larger of the targets given), `None`
    /// without a face target.
    pub target_faces: Option<usize>,
    /// The absolute error cap, `None` without one.
    pub max_error_cap: Option<f64>,
    /// Why it stopped.
    pub stopped: Stopped,
    /// Edges collapsed.
    pub collapses: usize,
    /// Passes made by [`Schedule::Passes`] (0 under [`Schedule::Exact`]).
    pub passes: usize,
    /// The largest error of a collapse (see the module documentation; 0 without
    /// collapses).
    pub max_error: f64,
    /// Refusals while the queue ran (an edge refused several times counts each time).
    pub refused: Refusals,
    /// The edges left at the end, by the guard that refuses them (all zero when the run
    /// stopped at its target; the sum over [`Self::component_list`]).
    pub remaining: Refusals,
    /// Per component.
    pub component_list: Vec<ComponentStats>,
    /// Wall-clock seconds of the decimation proper (quadrics, queue, collapses, output).
    pub seconds: f64,
}

/// The options of one run, resolved by the task call.
#[derive(Clone, Debug)]
pub(crate) struct Options {
    /// Stop when the real faces are at most this many (0: no face target).
    pub(crate) target_faces: usize,
    /// The absolute error cap.
    pub(crate) max_error: Option<f64>,
    pub(crate) placement: Placement,
    pub(crate) schedule: Schedule,
    pub(crate) guard: bool,
    pub(crate) lock_boundary: bool,
    /// Per mesh vertex: locked by the caller (empty: none).
    pub(crate) locked: Vec<bool>,
}

/// The output of one run, in mesh ids.
#[derive(Clone, Debug)]
pub(crate) struct Output {
    /// Faces over output vertex indices.
    pub(crate) faces: Vec<[u32; 3]>,
    /// Output positions.
    pub(crate) positions: Vec<Point>,
    /// Per output vertex: the input vertex that survives as it.
    pub(crate) vertex_map: Vec<u32>,
    /// Per input vertex: the output vertex it went into (`NO_VERTEX` for an unused one).
    pub(crate) collapse_map: Vec<u32>,
    /// Per output face: the input face it descends from.
    pub(crate) face_origin: Vec<u32>,
    pub(crate) stats: Stats,
}

/// The entry of `collapse_map` ([`crate::DecimateResult::collapse_map`]) for an input
/// vertex no face uses.
pub const NO_VERTEX: u32 = NONE;

#[cfg(test)]
mod tests;
