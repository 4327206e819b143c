//! The state of one component being simplified ([`Simplifier`]): the triangulation,
//! positions, marks and scratch that the pass machinery (module `pass`), the two modes
//! (modules `naive` and `nested`) and the specification checks (module `spec`) all read
//! and write; and the small types they share (the edge being examined, why an edge is
//! skipped, the nested mode's per-side regions). Apart from them so that those modules
//! import it and it imports none of them.

use super::geometry::{area_normal, cross, dot, power_of_two_scale, sub, Point, Quadric};
use super::{Options, Position, SkipCounts};
use crate::core::{ConedComponent, Corner, FaceId, SurfaceType, Triangulation, VertexId};
use crate::spec::ENABLED;

/// Why an edge is not processed now (frozen edges are counted before planning).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) enum Skip {
    LinkCondition,
    NonDisc,
    Foldover,
}

/// The totals of one component's run.
#[derive(Clone, Debug, Default)]
pub(super) struct Run {
    pub(super) edges_contracted: usize,
    pub(super) discs_removed: usize,
    pub(super) vertices_removed_inside: usize,
    pub(super) skipped: SkipCounts,
    pub(super) remaining: SkipCounts,
    pub(super) passes: usize,
    pub(super) shortest: Option<f64>,
}

/// The edge being examined: endpoints, opposite vertices, and whether each endpoint is
/// on the boundary. `xs` (in the simplifier) holds the other common neighbours.
#[derive(Copy, Clone, Debug)]
pub(super) struct EdgeInfo {
    /// The corner opposite the edge in the triangle being visited (side "a").
    pub(super) corner: Corner,
    pub(super) p: VertexId,
    pub(super) q: VertexId,
    pub(super) a: VertexId,
    pub(super) b: VertexId,
    pub(super) boundary: [bool; 2],
}

/// A vertex's position and the pass in which it was replaced or frozen (see
/// `Simplifier::vert`).
#[derive(Copy, Clone, Debug)]
pub(super) struct Vertex {
    pub(super) pos: Point,
    pub(super) touched: u32,
}

/// One component being simplified.
pub(crate) struct Simplifier<'o> {
    pub(super) tri: Triangulation,
    /// Per vertex: position and the pass that froze it, side by side, so that the
    /// freezing test of a visit and the position loads that follow it (and the guard's
    /// position loads and the freeze after it) share cache lines.
    pub(super) vert: Vec<Vertex>,
    pub(super) quadric: Vec<Quadric>,
    /// Vertex ids from here on are virtual (cone apexes); they stay last through
    /// compaction since they are never removed.
    pub(super) first_virtual: u32,
    pub(super) loops: usize,
    pub(super) opts: &'o Options,
    /// ε², in the scaled coordinates (see `scale`), at least the smallest positive `f64`.
    pub(super) eps2: f64,
    /// The power of two the positions are multiplied by while the component is
    /// simplified: it brings the component's largest coordinate near 1. Scaling by a
    /// power of two rounds nothing, so every comparison and every computed position is
    /// the one of the unscaled arithmetic whenever that neither overflows nor underflows;
    /// but squared lengths, areas and quadrics of meshes near the ends of the `f64` range
    /// (coordinates beyond about 1e77, or edges below about 1e-77) now stay finite and
    /// non-zero, so such meshes are simplified as their scaled copies are.
    pub(super) scale: f64,
    /// The largest scaled coordinate whose unscaled value is finite (a quadric optimum
    /// beyond it is not used).
    pub(super) max_coordinate: f64,
    pub(super) pass: u32,
    /// Scratch marks (compared with `stamp`).
    pub(super) vmark: Vec<u32>,
    pub(super) fmark: Vec<u32>,
    pub(super) stamp: u32,
    pub(super) scratch: Vec<Corner>,
    pub(super) link: Vec<VertexId>,
    /// A corner at q, then at p, in every face around them (filled by `examine`).
    pub(super) star_pq: Vec<Corner>,
    /// The neighbours of q and of p, in the order of their corners in `star_pq`
    /// (filled by `examine`).
    pub(super) nbr_q: Vec<VertexId>,
    pub(super) nbr_p: Vec<VertexId>,
    /// The common neighbours of the edge other than its opposite vertices, in order
    /// along the link of `p` from `a` to `b`.
    pub(super) xs: Vec<VertexId>,
    pub(super) grow: [Grow; 2],
    pub(super) interior: Vec<VertexId>,
    /// The coned surface's type at the start, recorded only when the specification
    /// checks run (it checks it after every pass; computing it is an O(F) pass).
    pub(super) surface: Option<SurfaceType>,
    /// Whether processEdge (the nested plan) is in use: the nested mode first runs naive
    /// passes to a fixed point, then nested ones (see `run`).
    pub(super) nested_phase: bool,
    pub(super) run: Run,
}

/// A disc claimed by one side: the first `faces` faces of that side's region are the
/// closed disc bounded by `p q x`; `sides` are its corners opposite `[p, q]`, `[q, x]`,
/// `[x, p]`.
#[derive(Copy, Clone, Debug)]
pub(super) struct Claim {
    pub(super) x: VertexId,
    pub(super) faces: usize,
    pub(super) sides: [Corner; 3],
}

/// Where one side's region growth stands.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub(super) enum RegionState {
    /// Not started, or stopped at its last claim by the split.
    #[default]
    Waiting,
    /// Growing towards the cycle through `xs[t]`.
    Active(usize),
    /// Failed the disc test: claims no more.
    Dead,
}

/// One side's region (reused scratch).
#[derive(Clone, Debug, Default)]
pub(super) struct Grow {
    /// The region's faces in discovery order; `queue[head..]` are not expanded yet.
    pub(super) queue: Vec<FaceId>,
    pub(super) head: usize,
    /// Corners of expanded faces opposite an edge of the current cycle.
    pub(super) blocked: Vec<Corner>,
    pub(super) state: RegionState,
    pub(super) started: bool,
    pub(super) claim: Option<Claim>,
    /// Vertices of the region other than `p`, `q` and the `xs`, and how many of them
    /// are virtual.
    pub(super) verts: usize,
    pub(super) virtuals: usize,
    /// This side's mark in `fmark` and `vmark`.
    pub(super) stamp: u32,
}

impl<'o> Simplifier<'o> {
    /// Takes over a component, with the positions of the mesh it came from (indexed by
    /// mesh vertex; the component's `vertex_origin` picks its own).
    pub(crate) fn new(component: ConedComponent, positions: &[Point], opts: &'o Options) -> Self {
        let loops = component.virtual_vertices().count();
        let first_virtual = component.real_vertex_count() as u32;
        let nv = component.tri.vertex_capacity();
        let largest = component
            .vertex_origin
            .iter()
            .flat_map(|&m| positions[m as usize])
            .fold(0.0f64, |a, x| a.max(x.abs()));
        let scale = power_of_two_scale(largest);
        let mut vert = Vec::with_capacity(nv);
        vert.extend(component.vertex_origin.iter().map(|&m| Vertex {
            pos: positions[m as usize].map(|x| x * scale),
            touched: 0,
        }));
        let tri = component.tri;
        let nf = tri.face_capacity();
        vert.resize(
            nv,
            Vertex {
                pos: [0.0; 3],
                touched: 0,
            },
        );
        let surface = ENABLED.then(|| SurfaceType::of(&tri));
        let mut s = Simplifier {
            tri,
            vert,
            quadric: Vec::new(),
            first_virtual,
            loops,
            opts,
            // An ε beyond the scaled range is infinite: every edge is shorter. One whose
            // square underflows is still above 0: an edge of length 0 is shorter.
            eps2: ((opts.eps * scale) * (opts.eps * scale)).max(f64::from_bits(1)),
            scale,
            max_coordinate: f64::MAX * scale,
            pass: 0,
            vmark: vec![0; nv],
            fmark: vec![0; nf],
            stamp: 0,
            scratch: Vec::new(),
            link: Vec::new(),
            star_pq: Vec::new(),
            nbr_q: Vec::new(),
            nbr_p: Vec::new(),
            xs: Vec::new(),
            grow: [Grow::default(), Grow::default()],
            interior: Vec::new(),
            surface,
            nested_phase: false,
            run: Run::default(),
        };
        if opts.position == Position::Quadric {
            s.init_quadrics();
        }
        s
    }

    /// Boundary loops of the component (constant).
    pub(super) fn loop_count(&self) -> usize {
        self.loops
    }

    #[inline]
    pub(super) fn is_virtual(&self, v: VertexId) -> bool {
        v.0 >= self.first_virtual
    }

    /// A stamp no mark holds yet.
    pub(super) fn fresh_stamp(&mut self) -> u32 {
        if self.stamp == u32::MAX {
            self.vmark.fill(0);
            self.fmark.fill(0);
            self.stamp = 0;
        }
        self.stamp += 1;
        self.stamp
    }

    /// Area-weighted plane quadrics of the real faces, plus a plane through every
    /// boundary edge perpendicular to its face (weight: the face's area times
    /// `BOUNDARY_WEIGHT`), so that boundary curves resist moving.
    fn init_quadrics(&mut self) {
        const BOUNDARY_WEIGHT: f64 = 10.0;
        self.quadric = vec![Quadric::default(); self.tri.vertex_capacity()];
        for f in self.tri.faces() {
            let vs = self.tri.face_vertices(f);
            if vs.iter().any(|&v| self.is_virtual(v)) {
                continue;
            }
            let ps = vs.map(|v| self.vert[v.index()].pos);
            let n = area_normal(ps[0], ps[1], ps[2]);
            let twice_area = dot(n, n).sqrt();
            if twice_area == 0.0 {
                continue;
            }
            let unit = n.map(|x| x / twice_area);
            let q = Quadric::plane(unit, ps[0], 0.5 * twice_area);
            for v in vs {
                self.quadric[v.index()].add(&q);
            }
            for c in f.corners() {
                let across = self.tri.vertex(self.tri.opposite(c));
                if !self.is_virtual(across) {
                    continue;
                }
                let [s, t] = self.tri.edge_endpoints(c);
                let (ps_, pt) = (self.vert[s.index()].pos, self.vert[t.index()].pos);
                let m = cross(sub(pt, ps_), unit);
                let len = dot(m, m).sqrt();
                if len == 0.0 {
                    continue;
                }
                let q = Quadric::plane(m.map(|x| x / len), ps_, BOUNDARY_WEIGHT * 0.5 * twice_area);
                self.quadric[s.index()].add(&q);
                self.quadric[t.index()].add(&q);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ConedSurfaces;

    /// The quadrics start as the sum of each real face's plane weighted by its area, plus,
    /// at the ends of every boundary edge, the plane through the edge perpendicular to its
    /// face with ten times that weight. On a 2×2 grid of squares of side 2 in the plane
    /// z = 0 (scaled by 1/4 to side 1/2, so every face has area 1/8): the middle vertex
    /// has six faces, error 6/8 · z²; the boundary vertex (2, 0, 0) has three faces and
    /// two boundary edges on the line y = 0, error 3/8 · z² + 2 · 10/8 · y² (scaled
    /// coordinates).
    #[test]
    fn quadrics_start_from_the_area_weighted_face_and_boundary_planes() {
        let mesh = super::super::testing::grid(3, 2.0);
        let positions = mesh.positions.clone().expect("positions");
        let mut surfaces = ConedSurfaces::from_mesh(&mesh).expect("a disc");
        let component = surfaces.components.remove(0);
        let id_of = |m: u32| {
            let k = component.vertex_origin.iter().position(|&o| o == m);
            k.expect("every mesh vertex is in the component")
        };
        let (middle, edge) = (id_of(4), id_of(1));
        let opts = Options {
            position: super::super::Position::Quadric,
            ..Options::new(0.1)
        };
        let sim = Simplifier::new(component, &positions, &opts);
        assert_eq!(sim.scale, 0.25);
        let q = |v: usize, p: Point| sim.quadric[v].error(p);
        assert_eq!(q(middle, [0.3, 0.7, 0.0]), 0.0);
        assert_eq!(q(middle, [0.3, 0.7, 1.0]), 0.75);
        assert_eq!(q(middle, [0.3, 0.7, 2.0]), 3.0);
        assert_eq!(q(edge, [0.3, 0.0, 1.0]), 0.375);
        assert_eq!(q(edge, [0.3, 2.0, 0.0]), 10.0);
        assert_eq!(q(edge, [0.3, 2.0, 1.0]), 10.375);
    }
}
