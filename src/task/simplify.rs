//! [`simplify`]: every edge shorter than ε contracted without changing the topology.

use crate::core::{ConedSurfaces, Surfaces};
use crate::mesh::TriMesh;
use crate::simplify::{self, bbox_diagonal, Mode, PassReport, Position, Side, Stats};

use super::{Error, Event, Monitor, Step};

/// The length below which edges are contracted.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Eps {
    /// An absolute length.
    Absolute(f64),
    /// A fraction of the diagonal of the bounding box of the vertices the faces use.
    Relative(f64),
}

impl Default for Eps {
    /// 1 % of the bounding-box diagonal.
    fn default() -> Self {
        Eps::Relative(0.01)
    }
}

/// Options of [`simplify()`]. The default: ε 1 % of the bounding-box diagonal, the nested
/// mode, the count heuristic, midpoints, the fold-over guard on, output verified.
#[derive(Clone, Debug, Default)]
pub struct SimplifyOptions {
    /// Edges strictly shorter than this are contracted.
    pub eps: Eps,
    /// See [`Mode`].
    pub mode: Mode,
    /// See [`Side`].
    pub side: Side,
    /// See [`Position`].
    pub position: Position,
    /// Allow contractions that turn a remaining triangle's normal by 90° or more or
    /// leave it with zero area (off by default: the guard refuses them; the topology is
    /// kept either way).
    pub allow_foldover: bool,
    /// Skip the independent check of the output ([`verify_simplification`]).
    pub skip_verify: bool,
    /// Simplify the components on rayon's current thread pool (the crate's `parallel`
    /// feature; ignored without it). The result is the sequential run's, errors
    /// included; only the order of the monitor's events differs.
    pub parallel: bool,
    /// Progress and cancellation.
    pub monitor: Monitor,
}

impl SimplifyOptions {
    /// The default options with ε a fraction of the bounding-box diagonal.
    pub fn relative(fraction: f64) -> Self {
        SimplifyOptions {
            eps: Eps::Relative(fraction),
            ..SimplifyOptions::default()
        }
    }

    /// The default options with an absolute ε.
    pub fn absolute(eps: f64) -> Self {
        SimplifyOptions {
            eps: Eps::Absolute(eps),
            ..SimplifyOptions::default()
        }
    }
}

/// What [`simplify()`] returns.
#[derive(Clone, Debug)]
pub struct SimplifyResult {
    /// The output: the live vertices of every component with their positions, component
    /// by component (in the order of their smallest input face), each in vertex id order.
    pub mesh: TriMesh,
    /// What was done (the command line's `simplify --json` keys).
    pub stats: Stats,
    /// The absolute ε used.
    pub eps: f64,
    /// The fraction given, for [`Eps::Relative`].
    pub eps_rel: Option<f64>,
    /// The diagonal of the bounding box of the vertices the input's faces use.
    pub bbox_diagonal: f64,
    /// Input vertices no face uses (dropped).
    pub dropped_vertices: usize,
    /// Whether the output was checked ([`verify_simplification`]; it passed, or the call
    /// would have failed).
    pub verified: bool,
    /// Seconds checking the positions, validating the faces and splitting them into
    /// components.
    pub seconds_build: f64,
    /// Seconds of the independent check (`None` when not checked).
    pub seconds_verify: Option<f64>,
}

/// A component's topological type as a sortable key: (χ, orientable, boundary loops).
pub type TypeKey = (i64, bool, usize);

/// The topological types of the components of `s`, sorted (a multiset).
pub fn component_types(s: &ConedSurfaces) -> Vec<TypeKey> {
    let mut v: Vec<TypeKey> = s
        .components
        .iter()
        .map(|c| {
            let t = c.surface_type();
            (
                t.euler_characteristic(),
                t.is_orientable(),
                t.boundary_loops(),
            )
        })
        .collect();
    v.sort_unstable();
    v
}

/// The independent check of a simplification's output: rebuilt from its face list (not
/// from anything the algorithm kept), it must be a union of surfaces possibly with
/// boundary, use every vertex, and have exactly the components `input` lists (as a
/// multiset of types). The error says what differs.
pub fn verify_simplification(input: &[TypeKey], out: &TriMesh) -> Result<(), String> {
    let s = Surfaces::from_mesh_with_boundary(out)
        .map_err(|e| format!("the output is not a surface: {e}"))?;
    if !s.dropped_vertices.is_empty() {
        return Err(format!(
            "the output has {} unused vertices",
            s.dropped_vertices.len()
        ));
    }
    let output = component_types(&s);
    if output != input {
        let show = |v: &[TypeKey]| {
            v.iter()
                .map(|(chi, o, b)| {
                    format!(
                        "χ={chi} {} b={b}",
                        if *o { "orientable" } else { "non-orientable" }
                    )
                })
                .collect::<Vec<_>>()
                .join("; ")
        };
        return Err(format!(
            "the output's components ({}: {}) differ from the input's ({}: {})",
            output.len(),
            show(&output),
            input.len(),
            show(input)
        ));
    }
    Ok(())
}

fn check_eps(option: &'static str, v: f64, what: &str) -> Result<(), Error> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(Error::BadOption {
            option,
            value: format!("{v:?}"),
            expected: format!("{what} must be a finite number > 0"),
        })
    }
}

/// The positions of `mesh` and the vertices its faces use, checked: present, one per
/// vertex, finite, and not all at one point.
pub(super) fn checked_positions<'m>(
    mesh: &'m TriMesh,
    task: &'static str,
) -> Result<(&'m [[f64; 3]], Vec<usize>), Error> {
    let positions = mesh
        .positions
        .as_deref()
        .ok_or(Error::MissingPositions { task })?;
    if positions.len() != mesh.vertex_count {
        return Err(Error::PositionCount {
            vertices: mesh.vertex_count,
            positions: positions.len(),
        });
    }
    for (vertex, p) in positions.iter().enumerate() {
        if let Some(k) = (0..3).find(|&k| !p[k].is_finite()) {
            return Err(Error::NonFiniteCoordinate {
                vertex,
                axis: ['x', 'y', 'z'][k],
                value: p[k],
            });
        }
    }
    let mut used = vec![false; mesh.vertex_count];
    for f in &mesh.faces {
        for &v in f {
            // Out-of-range indices are the validation's to report.
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    let used: Vec<usize> = (0..mesh.vertex_count).filter(|&v| used[v]).collect();
    if let Some(&first) = used.first() {
        let point = positions[first];
        if used.len() > 1 && used.iter().all(|&v| positions[v] == point) {
            return Err(Error::NoCoordinates {
                vertices: used.len(),
                point,
            });
        }
    }
    Ok((positions, used))
}

/// Contracts every edge of `mesh` shorter than ε without changing its topology
/// (Pepko–Borisenko; see [`crate::simplify`](mod@crate::simplify) for the guarantee and the method): every
/// component keeps its Euler characteristic, orientability and boundary loops. `mesh` is
/// a union of surfaces, closed or with boundary, with finite positions. The output is
/// rebuilt from its faces and checked to have the input's components unless
/// `options.skip_verify`.
///
/// Deterministic for a given mesh and options (timings aside): no randomness, no
/// hashing; with `options.parallel`, the components run on several threads but each
/// only reads the shared positions, so the output is the same.
///
/// # Errors
/// [`Error::MissingPositions`], [`Error::PositionCount`],
/// [`Error::NonFiniteCoordinate`] and [`Error::NoCoordinates`] for unusable positions;
/// [`Error::BadOption`] for an ε that is not a finite number > 0 (or a relative one that
/// gives none); [`Error::Mesh`] for faces that are not surfaces (located);
/// [`Error::Cancelled`]; [`Error::Unverified`] if the output fails its check.
///
/// # Example
/// ```
/// use contractible::{gen, simplify, SimplifyOptions};
/// let sphere = gen::isosurface(&gen::IsoParams::new(
///     gen::Implicit::Sphere { radius: 1.0 },
///     gen::Tessellation::SixTetrahedra,
///     12,
/// ))?;
/// let s = simplify(&sphere, &SimplifyOptions::relative(0.1))?;
/// assert!(s.mesh.faces.len() < sphere.faces.len());
/// assert_eq!(s.stats.components, 1);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn simplify(mesh: &TriMesh, options: &SimplifyOptions) -> Result<SimplifyResult, Error> {
    let monitor = &options.monitor;
    if let Eps::Absolute(e) = options.eps {
        check_eps("eps", e, "ε")?;
    }
    if let Eps::Relative(r) = options.eps {
        check_eps("eps", r, "the fraction of the bounding-box diagonal")?;
    }
    let started = std::time::Instant::now();
    let (positions, used) = checked_positions(mesh, "simplify")?;
    monitor.step(Step::Build, 0, 0, mesh.faces.len())?;
    let surfaces = ConedSurfaces::from_mesh(mesh)?;
    let dropped_vertices = surfaces.dropped_vertices.len();
    let input_types = component_types(&surfaces);
    let diagonal = bbox_diagonal(used.iter().map(|&v| positions[v]));
    drop(used);
    let (eps, eps_rel) = match options.eps {
        Eps::Absolute(e) => (e, None),
        Eps::Relative(r) => {
            let e = r * diagonal;
            if !(e.is_finite() && e > 0.0) {
                return Err(Error::BadOption {
                    option: "eps",
                    value: format!("Relative({r:?})"),
                    expected: format!(
                        "{r:?} times the bounding-box diagonal {diagonal:?} gives ε = {e:?}, \
                         not a finite number > 0"
                    ),
                });
            }
            (e, Some(r))
        }
    };
    let algo = simplify::Options {
        eps,
        mode: options.mode,
        side: options.side,
        position: options.position,
        guard: !options.allow_foldover,
    };
    let seconds_build = started.elapsed().as_secs_f64();
    let n = surfaces.components.len();
    let run_started = std::time::Instant::now();
    // `checked_positions` and the ε checks above refuse everything
    // `simplify::check_surfaces` would (the position count, every coordinate, ε), each
    // with the task's own error, so its O(V) scan is not repeated here.
    debug_assert!(simplify::check_surfaces(&surfaces, positions, eps).is_ok());
    let mut stats = simplify::input_stats(&surfaces);
    let items: Vec<_> = surfaces
        .components
        .into_iter()
        .map(|c| (c.real_face_count(), c))
        .collect();
    let parts = monitor.each_component(
        Step::Run,
        options.parallel,
        items,
        |k, component, progress| {
            Ok(simplify::simplify_component(
                component,
                positions,
                &algo,
                &mut |pass, contracted, faces| {
                    monitor.report(&Event::Pass(PassReport {
                        component: k,
                        pass,
                        contracted,
                        faces,
                    }))
                },
                progress,
            ))
        },
    )?;
    let mesh = simplify::assemble(&mut stats, parts);
    stats.seconds = run_started.elapsed().as_secs_f64();
    let out = simplify::Simplified { mesh, stats };
    let mut seconds_verify = None;
    if !options.skip_verify {
        let started = std::time::Instant::now();
        monitor.step(Step::Verify, 0, 1, out.mesh.faces.len())?;
        verify_simplification(&input_types, &out.mesh).map_err(|detail| Error::Unverified {
            task: "simplify",
            components: (0..n).collect(),
            detail,
        })?;
        seconds_verify = Some(started.elapsed().as_secs_f64());
    }
    Ok(SimplifyResult {
        mesh: out.mesh,
        stats: out.stats,
        eps,
        eps_rel,
        bbox_diagonal: diagonal,
        dropped_vertices,
        verified: !options.skip_verify,
        seconds_build,
        seconds_verify,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;

    fn err(mesh: &TriMesh, options: &SimplifyOptions) -> Error {
        match simplify(mesh, options) {
            Err(e) => e,
            Ok(_) => panic!("accepted"),
        }
    }

    #[test]
    fn positions_are_required_finite_and_not_all_at_one_point() {
        let faces = gen::tetrahedron().faces;
        let o = SimplifyOptions::default();
        let none = TriMesh::combinatorial(4, faces.clone());
        assert_eq!(
            err(&none, &o).to_string(),
            "the mesh has no vertex positions; simplify needs coordinates"
        );
        let pts = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let mut nan = pts.clone();
        nan[2][1] = f64::NAN;
        assert_eq!(
            err(&TriMesh::with_positions(nan, faces.clone()), &o).to_string(),
            "vertex 2 has a non-finite coordinate y = NaN"
        );
        let short = TriMesh {
            vertex_count: 4,
            positions: Some(pts[..3].to_vec()),
            faces: faces.clone(),
        };
        assert_eq!(
            err(&short, &o).to_string(),
            "the mesh has 4 vertices but 3 positions"
        );
        let same = TriMesh::with_positions(vec![[2.0, 3.0, 4.0]; 4], faces.clone());
        assert!(err(&same, &o)
            .to_string()
            .starts_with("all 4 vertices are at the same point (2, 3, 4)"));
        let ok = TriMesh::with_positions(pts, faces);
        for bad in [
            Eps::Absolute(0.0),
            Eps::Relative(f64::NAN),
            Eps::Absolute(-1.0),
        ] {
            let e = err(
                &ok,
                &SimplifyOptions {
                    eps: bad,
                    ..SimplifyOptions::default()
                },
            );
            assert_eq!(e.kind(), "bad_option", "{bad:?}");
        }
        let r = simplify(&ok, &SimplifyOptions::absolute(0.5)).expect("valid");
        assert_eq!(r.mesh.faces.len(), 4, "the tetrahedron stays");
    }

    #[test]
    fn the_output_check_can_fail() {
        let types_of =
            |m: &TriMesh| component_types(&ConedSurfaces::from_mesh(m).expect("a surface"));
        let torus = gen::torus7();
        let tetra = gen::tetrahedron();
        assert_eq!(verify_simplification(&types_of(&torus), &torus), Ok(()));
        let e = verify_simplification(&types_of(&torus), &tetra).unwrap_err();
        assert_eq!(
            e,
            "the output's components (1: χ=2 orientable b=0) differ from the input's \
             (1: χ=0 orientable b=0)"
        );
        let mut two = tetra.faces.clone();
        two.extend(tetra.faces.iter().map(|f| f.map(|v| v + 4)));
        let two = TriMesh::combinatorial(8, two);
        assert!(verify_simplification(&types_of(&tetra), &two).is_err());
        assert!(verify_simplification(&types_of(&two), &tetra).is_err());
        let open = TriMesh::combinatorial(4, tetra.faces[1..].to_vec());
        let e = verify_simplification(&types_of(&tetra), &open).unwrap_err();
        assert!(e.contains("χ=1 orientable b=1"), "{e}");
        let bowtie = TriMesh::combinatorial(5, vec![[0, 1, 2], [0, 3, 4]]);
        let e = verify_simplification(&types_of(&tetra), &bowtie).unwrap_err();
        assert!(e.starts_with("the output is not a surface: "), "{e}");
        let unused = TriMesh::combinatorial(5, tetra.faces.clone());
        assert_eq!(
            verify_simplification(&types_of(&tetra), &unused),
            Err("the output has 1 unused vertices".to_string())
        );
    }
}
