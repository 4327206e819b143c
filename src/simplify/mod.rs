//! Topology-preserving short-edge simplification (Pepko–Borisenko, Sec. 5), on closed
//! surfaces and surfaces with boundary, orientable or not.
//!
//! **Guarantee.** [`simplify`] returns a mesh whose every component is a 2-manifold of
//! the same topological type as the input's (Euler characteristic, orientability,
//! boundary loop count: the same [`crate::SurfaceType`]), whatever the positions and ε.
//! Every change is a contraction that passes the link condition of the surface with
//! boundary (module [`crate::core`]'s `boundary`), possibly preceded, in the
//! [`Mode::Nested`] mode, by replacing closed discs bounded by 3-cycles through the edge
//! with single triangles (checked to be discs: Euler characteristic 1, the 3-cycle as
//! the whole boundary, no boundary loop inside). Passes repeat until one contracts
//! nothing, so at the end every edge shorter than ε is one the chosen mode cannot
//! contract, and [`Stats::remaining`] says why for each.
//!
//! **Method.** One pass visits the triangles in id order; for each it tries its edges
//! shorter than ε, shortest first, skipping an edge with an endpoint already replaced,
//! removed or frozen in this pass; the first edge it can process is processed and the
//! triangle is done. Processing creates the new vertex ([`Position`]) and freezes every
//! neighbour of it for the rest of the pass, so the contractions of a pass touch
//! disjoint neighbourhoods (the paper's scheme). At the end of a pass the arrays are
//! compacted (re-indexed densely, order kept). The paper tries only each triangle's
//! shortest edge; trying the next short edge when the shortest cannot be processed is
//! our change (recorded in `spec/simplify.md`), so that no short edge is left untried.
//!
//! Modes, one module each: [`naive`] skips an edge that fails the link condition (what
//! mesh libraries do); [`nested`] is the paper's processEdge: it finds the outermost
//! 3-cycles through the edge on both sides by region growing and removes what lies
//! inside them first. The nested mode runs the naive passes to their fixed point first
//! and processEdge passes after (our order, recorded in `spec/simplify.md`): it then
//! contracts every edge the naive mode contracts, and more, on every input.
//!
//! **Determinism.** The output depends only on the input mesh (its face and vertex
//! order) and the options: no randomness, no hashing, no threads here (the task call
//! [`crate::simplify()`] with `parallel` runs components on several threads; each
//! reads only the shared positions, so the output is the same).
//!
//! **Complexity.** Per pass O(F) plus, per processed edge, O(d_p + d_q) for the link
//! walk and contraction and, in the nested mode, O(size of the regions grown) (two
//! regions grown in lockstep, so about twice the removed part). Memory: the corner table
//! (≈ 28 bytes per triangle) plus ≈ 22 bytes per triangle of positions and marks (plus
//! 40 per triangle for [`Position::Quadric`]'s quadrics).

pub mod geometry;
pub mod naive;
pub mod nested;
mod pass;
mod spec;
mod state;

use std::time::Instant;

use crate::core::{BuildError, ConedSurfaces};
use crate::mesh::TriMesh;

pub use geometry::{bbox_diagonal, Point, Quadric};
pub use pass::SCANNED;

/// Which edges failing the link condition are still contracted.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Mode {
    /// Skip every edge that fails the link condition.
    Naive,
    /// The paper's processEdge: remove the discs inside the outermost 3-cycles through
    /// the edge, then contract it (default).
    #[default]
    Nested,
}

impl Mode {
    /// Every mode.
    pub const ALL: [Mode; 2] = [Mode::Nested, Mode::Naive];

    /// The name used on the command line, in Python and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Naive => "naive",
            Mode::Nested => "nested",
        }
    }

    /// One line on what the mode does (the command line's help).
    pub fn summary(self) -> &'static str {
        match self {
            Mode::Naive => "Skip edges that fail the link condition (what mesh libraries do)",
            Mode::Nested => {
                "The paper's processEdge: remove the discs inside the outermost 3-cycles \
                 through the edge, then contract it"
            }
        }
    }
}

crate::names::named_choice!(Mode, "simplification mode");

/// How the nested mode splits the 3-cycles through an edge between its two sides (the
/// paper's heuristics; every choice is checked, only the amount removed differs).
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Side {
    /// Grow both sides in lockstep, face by face, always extending the smaller one; a
    /// 3-cycle goes to the side that closes it first (default).
    #[default]
    Count,
    /// A 3-cycle goes to the side whose opposite vertex is nearer in edge hops, avoiding
    /// the edge's endpoints.
    Path,
    /// A 3-cycle goes to the side whose opposite vertex is nearer in space.
    Euclidean,
}

impl Side {
    /// Every heuristic.
    pub const ALL: [Side; 3] = [Side::Count, Side::Path, Side::Euclidean];

    /// The name used on the command line, in Python and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Side::Count => "count",
            Side::Path => "path",
            Side::Euclidean => "euclidean",
        }
    }

    /// One line on what the heuristic does (the command line's help).
    pub fn summary(self) -> &'static str {
        match self {
            Side::Count => {
                "Grow both sides in lockstep, face by face; a 3-cycle goes to the side \
                 that closes it first"
            }
            Side::Path => "The side whose opposite vertex is nearer in edge hops",
            Side::Euclidean => "The side whose opposite vertex is nearer in space",
        }
    }
}

crate::names::named_choice!(Side, "side heuristic");

/// Where the vertex that replaces a contracted edge goes.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Default)]
pub enum Position {
    /// The edge's midpoint (the paper), except that an edge with exactly one endpoint
    /// on the boundary contracts to that endpoint, so boundary curves keep their points
    /// (default).
    #[default]
    Midpoint,
    /// The minimiser of the summed Garland–Heckbert quadrics of both endpoints (planes
    /// of the input faces, area-weighted, plus perpendicular planes along boundary
    /// edges); the best of the endpoints and the midpoint when it is ill-conditioned or
    /// beyond the `f64` range.
    Quadric,
}

impl Position {
    /// Every placement.
    pub const ALL: [Position; 2] = [Position::Midpoint, Position::Quadric];

    /// The name used on the command line, in Python and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Position::Midpoint => "midpoint",
            Position::Quadric => "quadric",
        }
    }

    /// One line on the placement (the command line's help).
    pub fn summary(self) -> &'static str {
        match self {
            Position::Midpoint => {
                "The edge's midpoint (an edge with one endpoint on the boundary goes to \
                 that endpoint)"
            }
            Position::Quadric => "The minimiser of the endpoints' summed Garland–Heckbert quadrics",
        }
    }
}

crate::names::named_choice!(Position, "vertex placement");

/// Options of [`simplify`].
#[derive(Copy, Clone, Debug, PartialEq)]
pub struct Options {
    /// Edges strictly shorter than this are contracted. Must be finite and > 0.
    pub eps: f64,
    /// See [`Mode`].
    pub mode: Mode,
    /// See [`Side`].
    pub side: Side,
    /// See [`Position`].
    pub position: Position,
    /// Refuse a contraction that would turn a remaining triangle's normal by 90° or more
    /// or leave it with zero area (on by default; topology is guaranteed either way).
    pub guard: bool,
}

impl Options {
    /// Nested mode, count heuristic, midpoints, guard on, with this ε.
    pub fn new(eps: f64) -> Self {
        Options {
            eps,
            mode: Mode::default(),
            side: Side::default(),
            position: Position::default(),
            guard: true,
        }
    }
}

/// Edges skipped, by reason.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SkipCounts {
    /// The edge fails the link condition of the surface with boundary and the mode
    /// cannot help: the naive mode, or an edge joining two boundary loops, or a surface
    /// that is already the boundary of a tetrahedron around the edge.
    pub link_condition: usize,
    /// Nested mode: a 3-cycle through the edge does not bound a disc on the side chosen
    /// (it goes around a handle, or the side carries genus or a boundary loop).
    pub non_disc: usize,
    /// The geometry guard refused the contraction.
    pub foldover: usize,
    /// Deferred to the next pass by freezing: a short edge with an endpoint replaced,
    /// removed or frozen earlier in the pass, or a triangle visit skipped whole because
    /// two of its vertices were (then every edge has a frozen endpoint; its lengths are
    /// not even read). Never a reason for an edge that remains at the end.
    pub frozen: usize,
}

impl SkipCounts {
    /// The sum of all reasons.
    pub fn total(&self) -> usize {
        self.link_condition + self.non_disc + self.foldover + self.frozen
    }

    fn add(&mut self, o: &SkipCounts) {
        self.link_condition += o.link_condition;
        self.non_disc += o.non_disc;
        self.foldover += o.foldover;
        self.frozen += o.frozen;
    }
}

/// What a run did.
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Stats {
    /// Vertices of the input that faces use.
    pub vertices_in: usize,
    /// Faces of the input.
    pub faces_in: usize,
    /// Vertices of the output.
    pub vertices_out: usize,
    /// Faces of the output.
    pub faces_out: usize,
    /// Connected components (each simplified on its own).
    pub components: usize,
    /// Boundary loops (the same before and after).
    pub boundary_loops: usize,
    /// Edges contracted.
    pub edges_contracted: usize,
    /// Discs inside 3-cycles replaced by one triangle (nested mode).
    pub discs_removed: usize,
    /// Vertices removed inside those discs.
    pub vertices_removed_inside: usize,
    /// Skip events over all passes (an edge skipped in several passes counts in each).
    pub skipped: SkipCounts,
    /// The edges shorter than ε left at the end, by the reason they cannot be processed
    /// (`frozen` is always 0 here).
    pub remaining: SkipCounts,
    /// Number of edges shorter than ε left at the end (`remaining.total()`).
    pub short_edges_remaining: usize,
    /// The shortest edge of the output (`None` for an output without edges).
    pub shortest_remaining_edge: Option<f64>,
    /// Passes run, over the component that needed the most (the last one contracts
    /// nothing).
    pub passes: usize,
    /// Wall-clock seconds of the simplification: from the mesh (validation and building
    /// included) through [`simplify`] / [`simplify_with`], from the built surfaces
    /// through [`simplify_surfaces`]; I/O excluded.
    pub seconds: f64,
}

/// Why [`simplify`] refused its input. Nothing is produced.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SimplifyError {
    /// The mesh has no vertex positions (simplification is geometric).
    #[error("the mesh has no vertex positions; simplification needs coordinates")]
    MissingPositions,
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate {axis} = {value}")]
    NonFiniteCoordinate {
        /// The mesh vertex index.
        vertex: usize,
        /// `x`, `y` or `z`.
        axis: char,
        /// The value.
        value: f64,
    },
    /// The position list does not have one entry per vertex.
    #[error("the mesh has {vertices} vertices but {positions} positions")]
    PositionCount {
        /// Vertex count.
        vertices: usize,
        /// Position count.
        positions: usize,
    },
    /// ε is not a finite number > 0.
    #[error("epsilon must be a finite number > 0, got {0}")]
    BadEpsilon(f64),
    /// The faces are not a 2-manifold (possibly with boundary).
    #[error(transparent)]
    Build(#[from] BuildError),
}

/// The simplified mesh and what was done.
#[derive(Clone, Debug)]
pub struct Simplified {
    /// The output: the live vertices of every component with their positions, component
    /// by component (in the order of their smallest input face), each in vertex id order;
    /// faces likewise. Virtual (cone) vertices and faces are never written.
    pub mesh: TriMesh,
    /// The statistics.
    pub stats: Stats,
}

/// One finished pass, for progress reports.
#[derive(Copy, Clone, Debug)]
pub struct PassReport {
    /// The component (0-based, in output order).
    pub component: usize,
    /// The pass (1-based, within the component).
    pub pass: usize,
    /// Edges contracted in this pass.
    pub contracted: usize,
    /// Faces of the component after the pass (cone faces excluded).
    pub faces: usize,
}

/// Checks positions and ε: the errors [`simplify`] reports before building anything.
pub fn check_input(mesh: &TriMesh, eps: f64) -> Result<&[[f64; 3]], SimplifyError> {
    if !(eps.is_finite() && eps > 0.0) {
        return Err(SimplifyError::BadEpsilon(eps));
    }
    let positions = mesh
        .positions
        .as_deref()
        .ok_or(SimplifyError::MissingPositions)?;
    if positions.len() != mesh.vertex_count {
        return Err(SimplifyError::PositionCount {
            vertices: mesh.vertex_count,
            positions: positions.len(),
        });
    }
    for (vertex, p) in positions.iter().enumerate() {
        for (k, &value) in p.iter().enumerate() {
            if !value.is_finite() {
                return Err(SimplifyError::NonFiniteCoordinate {
                    vertex,
                    axis: ['x', 'y', 'z'][k],
                    value,
                });
            }
        }
    }
    Ok(positions)
}

/// Simplifies `mesh` (see the module documentation for the guarantee). Errors: missing
/// or non-finite positions, a bad ε, or faces that are not a 2-manifold with or without
/// boundary ([`BuildError`], located). Vertices used by no face are dropped.
pub fn simplify(mesh: &TriMesh, options: &Options) -> Result<Simplified, SimplifyError> {
    simplify_with(mesh, options, &mut |_| {})
}

/// [`simplify`], calling `on_pass` after every pass of every component.
pub fn simplify_with(
    mesh: &TriMesh,
    options: &Options,
    on_pass: &mut dyn FnMut(&PassReport),
) -> Result<Simplified, SimplifyError> {
    let start = Instant::now();
    let positions = check_input(mesh, options.eps)?;
    let surfaces = ConedSurfaces::from_mesh(mesh)?;
    let mut out = simplify_surfaces(surfaces, positions, options, on_pass)?;
    out.stats.seconds = start.elapsed().as_secs_f64();
    Ok(out)
}

/// [`simplify_with`] on surfaces the caller has already built (and validated) from a
/// mesh, with that mesh's `positions` (indexed by mesh vertex), so that a caller that
/// needs the built surfaces itself does not build them twice. Checks ε and the positions
/// of the vertices the surfaces use; `Stats::seconds` counts from here.
pub fn simplify_surfaces(
    surfaces: ConedSurfaces,
    positions: &[[f64; 3]],
    options: &Options,
    on_pass: &mut dyn FnMut(&PassReport),
) -> Result<Simplified, SimplifyError> {
    simplify_surfaces_observed(
        surfaces,
        positions,
        options,
        on_pass,
        &mut crate::progress::ignore,
    )
}

/// [`simplify_surfaces`], also reporting progress inside every pass to `observer`: the
/// face slots scanned out of the component's slots (stage "faces scanned in this pass",
/// restarting at 0 with each pass), at most every [`crate::progress::REPORT_EVERY`]
/// slots. Same result as [`simplify_surfaces`].
pub fn simplify_surfaces_observed(
    surfaces: ConedSurfaces,
    positions: &[[f64; 3]],
    options: &Options,
    on_pass: &mut dyn FnMut(&PassReport),
    observer: &mut dyn FnMut(crate::progress::Progress),
) -> Result<Simplified, SimplifyError> {
    let start = Instant::now();
    check_surfaces(&surfaces, positions, options.eps)?;
    let mut stats = input_stats(&surfaces);
    let parts = surfaces
        .components
        .into_iter()
        .enumerate()
        .map(|(k, component)| {
            simplify_component(
                component,
                positions,
                options,
                &mut |pass, contracted, faces| {
                    on_pass(&PassReport {
                        component: k,
                        pass,
                        contracted,
                        faces,
                    })
                },
                observer,
            )
        })
        .collect();
    let mesh = assemble(&mut stats, parts);
    stats.seconds = start.elapsed().as_secs_f64();
    Ok(Simplified { mesh, stats })
}

/// The errors [`simplify_surfaces`] reports before any work: ε not a finite number > 0,
/// a position list of the wrong length, a non-finite coordinate at a vertex the
/// surfaces use.
pub(crate) fn check_surfaces(
    surfaces: &ConedSurfaces,
    positions: &[[f64; 3]],
    eps: f64,
) -> Result<(), SimplifyError> {
    if !(eps.is_finite() && eps > 0.0) {
        return Err(SimplifyError::BadEpsilon(eps));
    }
    if positions.len() != surfaces.mesh_vertex_count {
        return Err(SimplifyError::PositionCount {
            vertices: surfaces.mesh_vertex_count,
            positions: positions.len(),
        });
    }
    for c in &surfaces.components {
        for &m in &c.vertex_origin {
            let p = positions[m as usize];
            if let Some(k) = (0..3).find(|&k| !p[k].is_finite()) {
                return Err(SimplifyError::NonFiniteCoordinate {
                    vertex: m as usize,
                    axis: ['x', 'y', 'z'][k],
                    value: p[k],
                });
            }
        }
    }
    Ok(())
}

/// The statistics of the input, before any component is simplified.
pub(crate) fn input_stats(surfaces: &ConedSurfaces) -> Stats {
    Stats {
        faces_in: surfaces
            .components
            .iter()
            .map(|c| c.real_face_count())
            .sum(),
        vertices_in: surfaces
            .components
            .iter()
            .map(|c| c.real_vertex_count())
            .sum(),
        components: surfaces.components.len(),
        boundary_loops: surfaces.loop_count(),
        ..Stats::default()
    }
}

/// One component simplified by [`simplify_component`]: its faces (vertex ids local to
/// the component, 0-based), their positions and what was done.
pub(crate) struct ComponentOutput {
    faces: Vec<[u32; 3]>,
    points: Vec<Point>,
    run: state::Run,
}

/// Simplifies one component on its own (components share nothing but the read-only
/// `positions`, so they may run on different threads): `on_pass(pass, contracted,
/// faces)` after every pass, `observer` inside the passes. Positions and ε must have
/// passed [`check_surfaces`].
pub(crate) fn simplify_component(
    component: crate::core::ConedComponent,
    positions: &[[f64; 3]],
    options: &Options,
    on_pass: &mut dyn FnMut(usize, usize, usize),
    observer: &mut dyn FnMut(crate::progress::Progress),
) -> ComponentOutput {
    let mut sim = state::Simplifier::new(component, positions, options);
    let run = sim.run(on_pass, observer);
    let (faces, points) = sim.into_mesh();
    ComponentOutput { faces, points, run }
}

/// The output mesh: the components' outputs in order, each one's vertex ids shifted past
/// those before it; their statistics added into `stats` (passes: the most any
/// component needed; the shortest remaining edge: over all).
pub(crate) fn assemble(stats: &mut Stats, parts: Vec<ComponentOutput>) -> TriMesh {
    let mut out_positions = Vec::new();
    let mut out_faces = Vec::new();
    for ComponentOutput { faces, points, run } in parts {
        stats.edges_contracted += run.edges_contracted;
        stats.discs_removed += run.discs_removed;
        stats.vertices_removed_inside += run.vertices_removed_inside;
        stats.skipped.add(&run.skipped);
        stats.remaining.add(&run.remaining);
        stats.passes = stats.passes.max(run.passes);
        stats.shortest_remaining_edge = match (stats.shortest_remaining_edge, run.shortest) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        let base = out_positions.len() as u32;
        out_faces.extend(faces.into_iter().map(|f| f.map(|v| v + base)));
        out_positions.extend(points);
    }
    stats.short_edges_remaining = stats.remaining.total();
    stats.vertices_out = out_positions.len();
    stats.faces_out = out_faces.len();
    TriMesh::with_positions(out_positions, out_faces)
}

/// Test inputs shared by the simplifier's unit tests.
#[cfg(test)]
pub(crate) mod testing {
    use crate::TriMesh;

    /// The flat grid of `n × n` vertices `(side · i, side · j, 0)`, vertex `j n + i`, each
    /// square split along its diagonal from `(i, j)` to `(i + 1, j + 1)`: a disc whose
    /// corner vertex 0 is at the origin.
    pub(crate) fn grid(n: u32, side: f64) -> TriMesh {
        let positions: Vec<[f64; 3]> = (0..n * n)
            .map(|v| [side * f64::from(v % n), side * f64::from(v / n), 0.0])
            .collect();
        let mut faces = Vec::new();
        for j in 0..n - 1 {
            for i in 0..n - 1 {
                let v = j * n + i;
                faces.push([v, v + 1, v + n + 1]);
                faces.push([v, v + n + 1, v + n]);
            }
        }
        TriMesh::with_positions(positions, faces)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The octahedron with a seventh vertex that no face uses.
    fn octahedron_and_a_stray_vertex() -> TriMesh {
        let mut m = crate::gen::octahedron();
        let mut positions = m.positions.take().expect("positions");
        positions.push([5.0, 5.0, 5.0]);
        TriMesh::with_positions(positions, m.faces)
    }

    /// The sum counts every reason once.
    #[test]
    fn skip_counts_total_every_reason() {
        let s = SkipCounts {
            link_condition: 1,
            non_disc: 2,
            foldover: 4,
            frozen: 8,
        };
        assert_eq!(s.total(), 15);
    }

    /// ε must be a finite number > 0, in both entry points: 0, negative, infinite and
    /// NaN are refused before anything is built.
    #[test]
    fn epsilon_must_be_finite_and_positive() {
        let m = crate::gen::octahedron();
        for eps in [0.0, -0.5, f64::INFINITY, f64::NEG_INFINITY, f64::NAN] {
            let is_bad = |r: Result<_, SimplifyError>| matches!(r, Err(SimplifyError::BadEpsilon(e)) if e.to_bits() == eps.to_bits());
            assert!(is_bad(check_input(&m, eps).map(|_| ())), "{eps}");
            assert!(
                is_bad(simplify(&m, &Options::new(eps)).map(|_| ())),
                "{eps}"
            );
            let surfaces = ConedSurfaces::from_mesh(&m).expect("octahedron");
            let positions = m.positions.as_deref().expect("positions");
            let r = simplify_surfaces(surfaces, positions, &Options::new(eps), &mut |_| {});
            assert!(is_bad(r.map(|_| ())), "{eps}");
        }
        assert!(check_input(&m, f64::MIN_POSITIVE).is_ok());
    }

    /// Positions: present, one per mesh vertex, finite where a face uses them; each
    /// error names the vertex and the axis. The surfaces' entry point reads only the
    /// vertices the surfaces use, so a non-finite position of a vertex no face uses is
    /// refused by [`check_input`] and accepted by [`simplify_surfaces`].
    #[test]
    fn positions_are_checked_where_they_are_used() {
        let m = octahedron_and_a_stray_vertex();
        let positions = m.positions.clone().expect("positions");
        let bare = TriMesh {
            positions: None,
            ..m.clone()
        };
        assert_eq!(
            check_input(&bare, 0.1).err(),
            Some(SimplifyError::MissingPositions)
        );
        let surfaces = || ConedSurfaces::from_mesh(&m).expect("octahedron");
        let run = |p: &[[f64; 3]]| {
            simplify_surfaces(surfaces(), p, &Options::new(0.1), &mut |_| {}).map(|_| ())
        };
        let n = positions.len();
        let short = &positions[..n - 1];
        let count = SimplifyError::PositionCount {
            vertices: n,
            positions: n - 1,
        };
        assert_eq!(run(short).err(), Some(count.clone()));
        let shortened = TriMesh::with_positions(short.to_vec(), m.faces.clone());
        let shortened = TriMesh {
            vertex_count: n,
            ..shortened
        };
        assert_eq!(check_input(&shortened, 0.1).err(), Some(count));

        let mut used = positions.clone();
        used[3][1] = f64::NAN;
        match run(&used) {
            Err(SimplifyError::NonFiniteCoordinate {
                vertex: 3,
                axis: 'y',
                value,
            }) if value.is_nan() => {}
            other => panic!("{other:?}"),
        }
        let mut stray = positions.clone();
        stray[n - 1][2] = f64::INFINITY;
        assert!(run(&stray).is_ok());
        let with_stray = TriMesh::with_positions(stray, m.faces.clone());
        assert_eq!(
            check_input(&with_stray, 0.1).err(),
            Some(SimplifyError::NonFiniteCoordinate {
                vertex: n - 1,
                axis: 'z',
                value: f64::INFINITY,
            })
        );
        assert!(run(&positions).is_ok());
    }

    /// The cone apexes closing the boundary loops sit at the origin of the scaled
    /// coordinates, but their faces are never visited: on a grid whose boundary passes
    /// through the origin (a corner at (0, 0, 0), so an apex–corner "edge" of length 0),
    /// with ε below the grid's spacing, nothing is contracted or skipped in any mode.
    #[test]
    fn cone_faces_are_never_visited() {
        let mesh = testing::grid(4, 1.0);
        for mode in [Mode::Naive, Mode::Nested] {
            for position in [Position::Midpoint, Position::Quadric] {
                let opts = Options {
                    mode,
                    position,
                    ..Options::new(0.5)
                };
                let out = simplify(&mesh, &opts).expect("a disc");
                let s = &out.stats;
                assert_eq!(
                    (s.edges_contracted, s.skipped.total(), s.faces_out),
                    (0, 0, 18),
                    "{mode:?} {position:?}"
                );
                assert_eq!(s.shortest_remaining_edge, Some(1.0));
            }
        }
    }

    /// The guard reads only faces that survive the contraction. The short edge `pq`
    /// lies on the non-facial 3-cycle `p q x`, which splits a sphere into a flat cone
    /// over the cycle from `d` (three faces, the side the nested mode removes) and a disc
    /// of five faces with two vertices. Moving `p` to the edge's midpoint flips the
    /// removed face `x p d` (ignored: the contraction is made); with the surviving
    /// vertex `b2` moved next to `d`, it flips the surviving face `p b2 x` (refused).
    #[test]
    fn the_guard_reads_the_faces_that_survive_and_only_those() {
        let (p, q, x, d, b1, b2) = (0, 1, 2, 3, 4, 5);
        let faces = vec![
            [p, q, d],
            [q, x, d],
            [x, p, d],
            [q, p, b1],
            [x, q, b1],
            [b2, x, b1],
            [p, x, b2],
            [b1, p, b2],
        ];
        let run = |b2_at: [f64; 3]| {
            let positions = vec![
                [0.0, 0.0, 0.0],
                [0.1, 0.0, 0.0],
                [0.05, 1.0, 0.0],
                [0.03, 0.3, 0.0],
                [0.05, 0.3, -0.5],
                b2_at,
            ];
            let mesh = TriMesh::with_positions(positions, faces.clone());
            let opts = Options::new(0.2);
            simplify(&mesh, &opts).expect("a sphere").stats
        };
        let s = run([0.0, 0.6, -0.5]);
        assert_eq!(
            (
                s.edges_contracted,
                s.discs_removed,
                s.vertices_removed_inside
            ),
            (1, 1, 1),
            "{s:?}"
        );
        assert_eq!((s.faces_out, s.skipped.foldover), (4, 0));
        let s = run([0.03, 0.3, -0.01]);
        assert_eq!(
            (s.edges_contracted, s.discs_removed, s.faces_out),
            (0, 0, 8)
        );
        assert_eq!(s.remaining.foldover, 1, "{s:?}");
    }

    /// The guard ignores cone faces, whose apex sits at the origin: on a grid with a
    /// boundary along the x axis, the short boundary edge from (1, 0, 0) to (1.1, 0, 0)
    /// is contracted, although each endpoint's cone face would have no area after the
    /// move.
    #[test]
    fn the_guard_ignores_cone_faces() {
        let mut mesh = testing::grid(4, 1.0);
        mesh.positions.as_mut().expect("positions")[2] = [1.1, 0.0, 0.0];
        for mode in [Mode::Naive, Mode::Nested] {
            let opts = Options {
                mode,
                ..Options::new(0.5)
            };
            let out = simplify(&mesh, &opts).expect("a disc");
            assert_eq!(
                (out.stats.edges_contracted, out.stats.skipped.foldover),
                (1, 0),
                "{mode:?}"
            );
            let merged = out.mesh.positions.as_deref().expect("positions");
            assert!(merged.contains(&[1.05, 0.0, 0.0]), "{merged:?}");
        }
    }
}
