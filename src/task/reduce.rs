//! [`reduce`]: the irreducible triangulation of every component of a mesh.

use crate::core::{BuildError, Surfaces, Triangulation};
use crate::irreducible::{self, Algorithm, Reduction};
use crate::mesh::{TriMesh, TriMeshRef};
use crate::topology::SurfaceType;

use super::{Error, Monitor, Step};

/// Options of [`reduce`]. The default: RS, seed 0, no ε counter, histories kept,
/// outputs verified.
#[derive(Clone, Debug)]
pub struct ReduceOptions {
    /// The algorithm.
    pub algorithm: Algorithm,
    /// Seed of the documented random stream ([`crate::rng`]): the brute force's shuffle
    /// (RS and Schipper do not use it).
    pub seed: u64,
    /// Count ε, the edges tested more than once ([`ReduceStats::edges_tested_more_than_once`],
    /// 0 without it): 8 bytes per face and a little time.
    pub count_retests: bool,
    /// Keep each component's contraction history (its `reduction.history`), which
    /// undoes the reduction and replays it as vertex splits; without it the histories
    /// are empty and the call needs about 44 bytes less per input triangle.
    pub keep_history: bool,
    /// Check every output independently ([`check_irreducible`]) and fail with
    /// [`Error::Unverified`] if one still has a contractible edge.
    pub verify: bool,
    /// Run the components on rayon's current thread pool (the crate's `parallel`
    /// feature; ignored without it). The result is the sequential run's, errors
    /// included; only the order of the monitor's events differs.
    pub parallel: bool,
    /// Progress and cancellation.
    pub monitor: Monitor,
}

impl Default for ReduceOptions {
    fn default() -> Self {
        ReduceOptions {
            algorithm: Algorithm::default(),
            seed: 0,
            count_retests: false,
            keep_history: true,
            verify: true,
            parallel: false,
            monitor: Monitor::default(),
        }
    }
}

/// Counters of one reduction (one component, or the totals over all of them). The
/// fields are the command line's `reduce --json` keys.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ReduceStats {
    /// The algorithm.
    #[cfg_attr(feature = "serde", serde(rename = "algo"))]
    pub algorithm: Algorithm,
    /// Vertices of the input.
    pub vertices_in: usize,
    /// Edges of the input.
    pub edges_in: usize,
    /// Faces of the input.
    pub faces_in: usize,
    /// χ of the input (summed over components in the totals).
    pub euler_characteristic: i64,
    /// Whether the input is orientable (every component, in the totals).
    pub orientable: bool,
    /// Orientable genus (summed); `None` if a component is non-orientable.
    pub genus: Option<i64>,
    /// `2 - χ` (summed).
    pub euler_genus: i64,
    /// Vertices of the output.
    pub vertices_out: usize,
    /// Edges of the output.
    pub edges_out: usize,
    /// Faces of the output.
    pub faces_out: usize,
    /// ℓ: link-condition tests.
    pub link_tests: u64,
    /// ε: edges tested more than once (0 unless [`ReduceOptions::count_retests`]).
    pub edges_tested_more_than_once: u64,
    /// Contractions.
    pub contractions: u64,
    /// Seconds in the algorithm proper (no validation, no verification).
    pub seconds: f64,
    /// Whether the independent check found no contractible edge (`None`: not checked).
    pub irreducible: Option<bool>,
    /// How the output was checked: `naive` (the link condition by its definition on
    /// every edge), `marked` (the marked-neighbour test on every edge, for outputs above
    /// [`NAIVE_MAX_EDGES`] edges), `naive+marked` in totals mixing both; `None`
    /// when not checked.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub verified_by: Option<&'static str>,
}

impl ReduceStats {
    /// The counters of `r`, the reduction of a surface of type `input` (not checked).
    pub fn of(r: &Reduction, input: SurfaceType) -> Self {
        let s = &r.stats;
        ReduceStats {
            algorithm: r.algorithm,
            vertices_in: s.vertices_in,
            edges_in: s.edges_in,
            faces_in: s.faces_in,
            euler_characteristic: input.euler_characteristic(),
            orientable: input.is_orientable(),
            genus: input.orientable_genus(),
            euler_genus: input.euler_genus(),
            vertices_out: s.vertices_out,
            edges_out: r.tri.edge_count(),
            faces_out: s.faces_out,
            link_tests: s.link_tests,
            edges_tested_more_than_once: s.edges_tested_more_than_once,
            contractions: s.contractions,
            seconds: s.seconds,
            irreducible: None,
            verified_by: None,
        }
    }

    /// The totals of `parts` (sums; genus `None` if any part is non-orientable).
    pub fn total(algorithm: Algorithm, parts: &[ReduceStats]) -> Self {
        let orientable = parts.iter().all(|p| p.orientable);
        let sum = |f: fn(&ReduceStats) -> usize| parts.iter().map(f).sum::<usize>();
        let sum64 = |f: fn(&ReduceStats) -> u64| parts.iter().map(f).sum::<u64>();
        let irreducible = parts
            .iter()
            .map(|p| p.irreducible)
            .try_fold(true, |acc, x| x.map(|b| acc && b));
        ReduceStats {
            algorithm,
            vertices_in: sum(|p| p.vertices_in),
            edges_in: sum(|p| p.edges_in),
            faces_in: sum(|p| p.faces_in),
            euler_characteristic: parts.iter().map(|p| p.euler_characteristic).sum(),
            orientable,
            genus: orientable.then(|| parts.iter().filter_map(|p| p.genus).sum()),
            euler_genus: parts.iter().map(|p| p.euler_genus).sum(),
            vertices_out: sum(|p| p.vertices_out),
            edges_out: sum(|p| p.edges_out),
            faces_out: sum(|p| p.faces_out),
            link_tests: sum64(|p| p.link_tests),
            edges_tested_more_than_once: sum64(|p| p.edges_tested_more_than_once),
            contractions: sum64(|p| p.contractions),
            seconds: parts.iter().map(|p| p.seconds).sum(),
            irreducible,
            verified_by: if irreducible.is_none() {
                None
            } else if parts.iter().all(|p| p.verified_by == Some("naive")) {
                Some("naive")
            } else if parts.iter().all(|p| p.verified_by == Some("marked")) {
                Some("marked")
            } else {
                Some("naive+marked")
            },
        }
    }
}

/// One component's reduction, with its place in the input.
#[derive(Clone, Debug)]
pub struct ReducedComponent {
    /// The reduction: the irreducible triangulation over the component's vertex ids, its
    /// contraction history ([`Reduction::expand`] gives the component back) and counters.
    pub reduction: Reduction,
    /// The input vertex of each component vertex id.
    pub vertex_origin: Vec<u32>,
    /// The input face of each component face id.
    pub face_origin: Vec<u32>,
    /// The component's counters and the verdict of its check.
    pub stats: ReduceStats,
}

/// What [`reduce`] returns.
#[derive(Clone, Debug)]
pub struct ReduceResult {
    /// The union of the irreducible triangulations, over the surviving input vertices
    /// renumbered in increasing input order, with their input positions (if any);
    /// faces component by component, each in increasing face id order.
    pub mesh: TriMesh,
    /// The input vertex of each vertex of `mesh`.
    pub vertex_map: Vec<u32>,
    /// Per component, in the order of their smallest input face.
    pub components: Vec<ReducedComponent>,
    /// The totals.
    pub totals: ReduceStats,
    /// Input vertices no face uses (dropped).
    pub dropped_vertices: usize,
    /// Seconds validating the input and splitting it into components.
    pub seconds_build: f64,
    /// Seconds of the independent check (`None` when not checked).
    pub seconds_verify: Option<f64>,
}

impl ReduceResult {
    /// Every contraction made, as `[u, v]` in input vertex ids (`v` contracted into `u`,
    /// which survives): component by component in the order of [`Self::components`],
    /// each component's oldest first. Replayed on the input, they give [`Self::mesh`]'s
    /// faces ([`crate::check::reduce_history`] checks exactly that); empty without
    /// [`ReduceOptions::keep_history`]. The command line's `reduce --history FILE` writes
    /// them, one per line.
    ///
    /// # Example
    /// ```
    /// use contractible::{gen, reduce};
    /// let octahedron = gen::octahedron();
    /// let r = reduce(&octahedron, &Default::default())?;
    /// // Six vertices down to the tetrahedron's four: two contractions.
    /// let steps = r.contractions();
    /// assert_eq!(steps.len(), 2);
    /// assert!(steps.iter().all(|&[u, v]| u != v && !r.vertex_map.contains(&v)));
    /// # Ok::<(), contractible::Error>(())
    /// ```
    pub fn contractions(&self) -> Vec<[u32; 2]> {
        let mut out = Vec::with_capacity(
            self.components
                .iter()
                .map(|c| c.reduction.history.len())
                .sum(),
        );
        for c in &self.components {
            let origin = |v: crate::VertexId| c.vertex_origin[v.index()];
            for r in c.reduction.history.records() {
                out.push([origin(r.u), origin(r.v)]);
            }
        }
        out
    }
}

/// Outputs with at most this many edges are checked by the link condition's definition
/// (O(Σ d_u·d_v)); larger ones by the marked-neighbour test (O(Σ d_u + d_v)), which is
/// linear where the definition is quadratic in the degrees.
pub const NAIVE_MAX_EDGES: usize = 100_000;

/// The verdict of [`check_irreducible`] and the method used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IrreducibleCheck {
    /// Whether no edge passes the link condition.
    pub irreducible: bool,
    /// `naive` or `marked` (see [`ReduceStats::verified_by`]).
    pub method: &'static str,
}

/// The independent check that `tri` is irreducible (no edge passes the link condition),
/// on `tri` alone: by the definition up to [`NAIVE_MAX_EDGES`] edges, by the
/// marked-neighbour test above.
pub fn check_irreducible(tri: &Triangulation) -> IrreducibleCheck {
    check_irreducible_with(tri, NAIVE_MAX_EDGES)
}

fn check_irreducible_with(tri: &Triangulation, naive_max_edges: usize) -> IrreducibleCheck {
    if tri.edge_count() <= naive_max_edges {
        IrreducibleCheck {
            irreducible: tri.is_irreducible_naive(),
            method: "naive",
        }
    } else {
        IrreducibleCheck {
            irreducible: tri.is_irreducible(),
            method: "marked",
        }
    }
}

/// Positions, when `mesh` has them, must be one per vertex: the combinatorial tasks carry
/// them over to their outputs (reassembled by vertex), so a mesh with too few or too many
/// is the input's fault ([`Error::PositionCount`]), not an output that fails to map back.
pub(crate) fn position_count(mesh: TriMeshRef<'_>) -> Result<(), Error> {
    match mesh.positions {
        Some(p) if p.len() != mesh.vertex_count => Err(Error::PositionCount {
            vertices: mesh.vertex_count,
            positions: p.len(),
        }),
        _ => Ok(()),
    }
}

/// Validates `mesh` as a union of closed surfaces: the error of the first problem,
/// with a boundary edge reported as [`Error::NotClosed`] (naming the mesh's boundary
/// loops when it is a surface with boundary).
pub(crate) fn closed_surfaces(
    mesh: TriMeshRef<'_>,
    task: &'static str,
    monitor: &Monitor,
) -> Result<Surfaces, Error> {
    monitor.step(Step::Build, 0, 0, mesh.faces.len())?;
    Surfaces::from_faces(mesh.vertex_count, mesh.faces).map_err(|e| match e {
        BuildError::BoundaryEdge { a, b, face } => Error::NotClosed {
            task,
            a,
            b,
            face,
            boundary_loops: crate::core::ConedSurfaces::from_faces(mesh.vertex_count, mesh.faces)
                .ok()
                .map(|s| s.loop_count()),
        },
        e => Error::Mesh(e),
    })
}

/// The irreducible triangulation of every component of `mesh`, a union of closed
/// surfaces (orientable or not): contractions under the link condition until none is
/// possible, by `options.algorithm`. The output keeps each component's topology (χ,
/// orientability) and is irreducible, checked independently unless
/// `options.verify` is off.
///
/// Deterministic for a given mesh and options (timings aside).
///
/// # Errors
/// [`Error::PositionCount`] if `mesh` has positions but not one per vertex (checked
/// first); [`Error::Mesh`] or [`Error::NotClosed`] if `mesh` is not a union of closed
/// surfaces (the first problem, located); [`Error::Cancelled`]; [`Error::Unverified`] if
/// an output fails its check (a defect of the library, never an expected outcome).
///
/// # Example
/// ```
/// let octahedron = contractible::gen::octahedron();
/// let r = contractible::reduce(&octahedron, &Default::default())?;
/// // A sphere reduces to the boundary of a tetrahedron.
/// assert_eq!((r.mesh.vertex_count, r.mesh.faces.len()), (4, 4));
/// assert_eq!(r.totals.irreducible, Some(true));
/// # Ok::<(), contractible::Error>(())
/// ```
pub fn reduce<'a>(
    mesh: impl Into<TriMeshRef<'a>>,
    options: &ReduceOptions,
) -> Result<ReduceResult, Error> {
    let mesh: TriMeshRef<'a> = mesh.into();
    let monitor = &options.monitor;
    position_count(mesh)?;
    let started = std::time::Instant::now();
    let surfaces = closed_surfaces(mesh, "reduce", monitor)?;
    let seconds_build = started.elapsed().as_secs_f64();
    let n = surfaces.components.len();
    let dropped_vertices = surfaces.dropped_vertices.len();
    let algo = irreducible::Options {
        seed: options.seed,
        count_retests: options.count_retests,
        keep_history: options.keep_history,
    };
    let items = surfaces
        .components
        .into_iter()
        .map(|c| (c.tri.face_count(), c))
        .collect();
    let mut components =
        monitor.each_component(Step::Run, options.parallel, items, |_, c, observer| {
            let input = SurfaceType::of(&c.tri);
            let reduction = irreducible::reduce_observed(c.tri, options.algorithm, &algo, observer);
            Ok(ReducedComponent {
                stats: ReduceStats::of(&reduction, input),
                reduction,
                vertex_origin: c.vertex_origin,
                face_origin: c.face_origin,
            })
        })?;
    let mut seconds_verify = None;
    if options.verify {
        let started = std::time::Instant::now();
        let items = components
            .iter()
            .map(|c| (c.reduction.tri.face_count(), &c.reduction.tri))
            .collect();
        let checks = monitor.each_component(Step::Verify, options.parallel, items, |_, t, _| {
            Ok(check_irreducible(t))
        })?;
        for (c, check) in components.iter_mut().zip(checks) {
            c.stats.irreducible = Some(check.irreducible);
            c.stats.verified_by = Some(check.method);
        }
        seconds_verify = Some(started.elapsed().as_secs_f64());
        let bad: Vec<usize> = (0..n)
            .filter(|&i| components[i].stats.irreducible == Some(false))
            .collect();
        if !bad.is_empty() {
            return Err(Error::Unverified {
                task: "reduce",
                components: bad,
                detail: "the output still has a contractible edge (independent link test)".into(),
            });
        }
    }
    let stats: Vec<ReduceStats> = components.iter().map(|c| c.stats.clone()).collect();
    let totals = ReduceStats::total(options.algorithm, &stats);
    let out = TriMesh::reassemble(
        mesh.vertex_count,
        mesh.positions,
        components
            .iter()
            .map(|c| (&c.reduction.tri, &c.vertex_origin[..])),
    );
    // Validation guarantees every origin is an input vertex and the positions match.
    let Some(out) = out else {
        return Err(Error::Unverified {
            task: "reduce",
            components: (0..n).collect(),
            detail: "the output does not map onto the input's vertices".into(),
        });
    };
    let mut vertex_map: Vec<u32> = components
        .iter()
        .flat_map(|c| {
            c.reduction
                .tri
                .vertices()
                .map(|v| c.vertex_origin[v.index()])
        })
        .collect();
    vertex_map.sort_unstable();
    Ok(ReduceResult {
        mesh: out,
        vertex_map,
        components,
        totals,
        dropped_vertices,
        seconds_build,
        seconds_verify,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;

    /// Both checks, on irreducible and on reducible surfaces: they agree, and each can
    /// say "no" (the marked one is what large outputs get).
    #[test]
    fn the_naive_and_the_marked_checks_agree_and_can_fail() {
        let cases = [
            ("tetrahedron", gen::tetrahedron(), true),
            ("torus7", gen::torus7(), true),
            ("rp2", gen::projective_plane6(), true),
            ("octahedron", gen::octahedron(), false),
            ("icosahedron", gen::icosahedron(), false),
        ];
        for (name, mesh, irreducible) in cases {
            let s = Surfaces::from_mesh(&mesh).expect("a surface");
            let t = &s.components[0].tri;
            let naive = check_irreducible_with(t, usize::MAX);
            let marked = check_irreducible_with(t, 0);
            assert_eq!(
                (naive.irreducible, naive.method),
                (irreducible, "naive"),
                "{name}"
            );
            assert_eq!(
                (marked.irreducible, marked.method),
                (irreducible, "marked"),
                "{name}"
            );
        }
    }

    /// Two spheres and a torus with an unused vertex: one result over the survivors,
    /// each component irreducible by the naive test on the returned mesh itself.
    #[test]
    fn reduces_every_component_and_maps_the_survivors() {
        let mut faces = gen::icosahedron().faces;
        faces.extend(gen::octahedron().faces.iter().map(|f| f.map(|v| v + 13)));
        let mesh = TriMesh::combinatorial(19, faces);
        let r = reduce(&mesh, &ReduceOptions::default()).expect("closed surfaces");
        assert_eq!(r.components.len(), 2);
        assert_eq!(r.dropped_vertices, 1);
        assert_eq!((r.mesh.vertex_count, r.mesh.faces.len()), (8, 8));
        assert!(r.vertex_map.windows(2).all(|w| w[0] < w[1]));
        let back = Surfaces::from_mesh(&r.mesh).expect("the output is closed surfaces");
        for c in &back.components {
            assert!(c.tri.is_irreducible_naive());
        }
        let open = TriMesh::combinatorial(4, gen::tetrahedron().faces[1..].to_vec());
        let e = reduce(&open, &ReduceOptions::default()).unwrap_err();
        assert!(matches!(
            e,
            Error::NotClosed {
                boundary_loops: Some(1),
                ..
            }
        ));
        assert_eq!(e.kind(), "boundary_edge");
    }

    /// Positions that are not one per vertex are the input's fault, refused before the
    /// faces are looked at (the output, reassembled with them, could not map back).
    #[test]
    fn positions_not_one_per_vertex_are_refused_first() {
        let mut mesh = gen::octahedron();
        mesh.positions.as_mut().expect("positions").pop();
        mesh.faces.push([0, 0, 1]);
        let e = reduce(&mesh, &ReduceOptions::default()).unwrap_err();
        assert!(
            matches!(
                e,
                Error::PositionCount {
                    vertices: 6,
                    positions: 5
                }
            ),
            "{e}"
        );
        assert!(e.is_input());
        let q = crate::task::quadrangulate(&mesh, &Default::default()).unwrap_err();
        assert_eq!(q.kind(), "position_count", "{q}");
    }

    /// The monitor hears the steps in order (build, each component's run, each
    /// component's check) with the algorithm's progress inside the runs; a flag set while
    /// the first component runs cancels the call before the second.
    #[test]
    fn the_monitor_hears_every_step_and_cancels_between_components() {
        use crate::task::{Event, Monitor, Step};
        use std::sync::atomic::{AtomicBool, Ordering};
        use std::sync::{Arc, Mutex};
        let sphere = gen::subdivide(&gen::icosahedron(), 3).expect("small");
        let n = sphere.vertex_count;
        let mut faces = sphere.faces;
        faces.extend(
            gen::octahedron()
                .faces
                .iter()
                .map(|f| f.map(|v| v + n as u32)),
        );
        let mesh = TriMesh::combinatorial(n + 6, faces);
        let steps = Arc::new(Mutex::new(Vec::new()));
        let progress = Arc::new(Mutex::new([0usize; 2]));
        let (s, p) = (Arc::clone(&steps), Arc::clone(&progress));
        let monitor = Monitor::new().observe(move |e| match e {
            Event::Step {
                step, component, ..
            } => s.lock().expect("not poisoned").push((*step, *component)),
            Event::Progress { component, .. } => p.lock().expect("not poisoned")[*component] += 1,
            Event::Pass(_) => {}
        });
        let r = reduce(
            &mesh,
            &ReduceOptions {
                monitor,
                ..ReduceOptions::default()
            },
        )
        .expect("closed surfaces");
        assert_eq!(r.components.len(), 2);
        assert_eq!(
            *steps.lock().expect("not poisoned"),
            vec![
                (Step::Build, 0),
                (Step::Run, 0),
                (Step::Run, 1),
                (Step::Verify, 0),
                (Step::Verify, 1)
            ]
        );
        assert!(
            progress
                .lock()
                .expect("not poisoned")
                .iter()
                .all(|&k| k >= 2),
            "start and end of each run, under its component"
        );

        let flag = Arc::new(AtomicBool::new(false));
        let f = Arc::clone(&flag);
        let monitor = Monitor::new()
            .observe(move |e| {
                if let Event::Step {
                    step: Step::Run, ..
                } = e
                {
                    f.store(true, Ordering::Relaxed);
                }
            })
            .cancel_on(flag);
        let e = reduce(
            &mesh,
            &ReduceOptions {
                monitor,
                ..ReduceOptions::default()
            },
        )
        .unwrap_err();
        assert!(matches!(e, Error::Cancelled), "{e}");
        assert!(!e.is_input());
    }
}
