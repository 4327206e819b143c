//! [`decimate`]: a mesh to a face budget or an error cap without changing its topology.

use std::collections::HashMap;

use crate::core::{ConedSurfaces, Surfaces};
use crate::decimate::{self, Placement, Schedule, Stats, NO_VERTEX};
use crate::mesh::TriMesh;
use crate::simplify::bbox_diagonal;

use super::simplify::{checked_positions, TypeKey};
use super::{Error, Monitor, Step};

/// The error cap of [`DecimateOptions::max_error`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MaxError {
    /// An absolute distance.
    Absolute(f64),
    /// A fraction of the diagonal of the bounding box of the vertices the faces use.
    Relative(f64),
}

/// Options of [`decimate()`]. Targets combine: the run stops at the first one reached
/// (the largest face count asked, or the error cap); with none, it goes as far as the
/// guards allow. The default: no target, optimal placement, the fold-over guard on,
/// boundary vertices free, nothing locked, the output verified.
#[derive(Clone, Debug, Default)]
pub struct DecimateOptions {
    /// Stop at this many faces or fewer.
    pub faces: Option<usize>,
    /// Stop at this fraction of the input's faces *kept* or fewer (`ceil(keep × faces)`;
    /// in `[0, 1]`).
    pub keep: Option<f64>,
    /// Make no collapse whose error exceeds this (see [`crate::decimate`](mod@crate::decimate) for what the
    /// error measures); finite and ≥ 0.
    pub max_error: Option<MaxError>,
    /// See [`Placement`].
    pub placement: Placement,
    /// See [`Schedule`]: [`Schedule::Passes`] is the fast option.
    pub schedule: Schedule,
    /// Allow collapses that turn a face by 90° or more or leave it with zero area (off
    /// by default: the guard refuses them; the topology is kept either way).
    pub allow_foldover: bool,
    /// Keep every boundary vertex where it is: a boundary edge then never collapses, an
    /// interior edge at the boundary only onto its boundary end.
    pub lock_boundary: bool,
    /// Input vertices that must survive at their input positions.
    pub locked: Vec<u32>,
    /// Skip the independent check of the output ([`verify_decimation`]).
    pub skip_verify: bool,
    /// Progress and cancellation.
    pub monitor: Monitor,
}

impl DecimateOptions {
    /// The default options with a face target.
    pub fn faces(n: usize) -> Self {
        DecimateOptions {
            faces: Some(n),
            ..DecimateOptions::default()
        }
    }

    /// The default options keeping a fraction of the faces.
    pub fn keep(fraction: f64) -> Self {
        DecimateOptions {
            keep: Some(fraction),
            ..DecimateOptions::default()
        }
    }
}

/// What [`decimate()`] returns.
#[derive(Clone, Debug)]
pub struct DecimateResult {
    /// The output: the surviving input vertices in increasing input id with their new
    /// positions, and the surviving input faces in increasing input id, each with its
    /// input vertex order.
    pub mesh: TriMesh,
    /// What was done, why it stopped, what refused the rest.
    pub stats: Stats,
    /// Per output vertex: the input vertex that survives as it (increasing).
    pub vertex_map: Vec<u32>,
    /// Per input vertex: the output vertex it went into ([`NO_VERTEX`] for a vertex no
    /// face uses).
    pub collapse_map: Vec<u32>,
    /// Per output face: the input face it descends from (the same slot, its corners
    /// renamed by the collapses; increasing).
    pub face_origin: Vec<u32>,
    /// The diagonal of the bounding box of the vertices the input's faces use.
    pub bbox_diagonal: f64,
    /// Input vertices no face uses (dropped).
    pub dropped_vertices: usize,
    /// Whether the output was checked ([`verify_decimation`]; it passed, or the call
    /// would have failed).
    pub verified: bool,
    /// Seconds checking the positions and validating the faces.
    pub seconds_build: f64,
    /// Seconds of the independent check (`None` when not checked).
    pub seconds_verify: Option<f64>,
}

fn bad(option: &'static str, value: String, expected: &str) -> Error {
    Error::BadOption {
        option,
        value,
        expected: expected.to_string(),
    }
}

/// The options checked and resolved against the mesh: the face target, the absolute
/// error cap and the lock flags per vertex.
fn resolve(
    mesh: &TriMesh,
    options: &DecimateOptions,
    faces_in: usize,
    diagonal: f64,
) -> Result<decimate::Options, Error> {
    if let Some(k) = options.keep {
        if !(k.is_finite() && (0.0..=1.0).contains(&k)) {
            return Err(bad(
                "keep",
                format!("{k:?}"),
                "the fraction of the faces kept must be in [0, 1]",
            ));
        }
    }
    let max_error = match options.max_error {
        None => None,
        Some(MaxError::Absolute(e)) => {
            if !(e.is_finite() && e >= 0.0) {
                return Err(bad(
                    "max_error",
                    format!("{e:?}"),
                    "the error cap must be a finite number ≥ 0",
                ));
            }
            Some(e)
        }
        Some(MaxError::Relative(r)) => {
            if !(r.is_finite() && r >= 0.0) {
                return Err(bad(
                    "max_error",
                    format!("Relative({r:?})"),
                    "the fraction of the bounding-box diagonal must be a finite number ≥ 0",
                ));
            }
            let e = r * diagonal;
            if !e.is_finite() {
                return Err(bad(
                    "max_error",
                    format!("Relative({r:?})"),
                    &format!("{r:?} times the diagonal {diagonal:?} is not finite"),
                ));
            }
            Some(e)
        }
    };
    let mut locked = Vec::new();
    if !options.locked.is_empty() {
        locked = vec![false; mesh.vertex_count];
        for &v in &options.locked {
            match locked.get_mut(v as usize) {
                Some(l) => *l = true,
                None => {
                    return Err(bad(
                        "locked",
                        v.to_string(),
                        &format!(
                            "a locked vertex must be an input vertex (the mesh has {})",
                            mesh.vertex_count
                        ),
                    ))
                }
            }
        }
    }
    let by_fraction = options.keep.map(|k| (k * faces_in as f64).ceil() as usize);
    let target_faces = match (options.faces, by_fraction) {
        (Some(a), Some(b)) => a.max(b),
        (a, b) => a.or(b).unwrap_or(0),
    };
    Ok(decimate::Options {
        target_faces,
        max_error,
        placement: options.placement,
        schedule: options.schedule,
        guard: !options.allow_foldover,
        lock_boundary: options.lock_boundary,
        locked,
    })
}

/// Collapses edges of `mesh`, cheapest quadric error first, until a target of
/// `options` is reached or no edge can go, without changing the topology (see
/// [`crate::decimate`](mod@crate::decimate) for the guarantee, the method and the
/// error): every component keeps its Euler characteristic, orientability and boundary
/// loops. `mesh` is a union of surfaces, closed or with boundary, with finite
/// positions. The output is rebuilt from its faces and checked independently
/// ([`verify_decimation`]) unless `options.skip_verify`.
///
/// Deterministic: the same mesh and options give the same output (no randomness, no
/// hashing, no threads; timings aside).
///
/// # Errors
/// [`Error::MissingPositions`], [`Error::PositionCount`],
/// [`Error::NonFiniteCoordinate`] and [`Error::NoCoordinates`] for unusable positions;
/// [`Error::BadOption`] for a fraction outside `[0, 1]`, a negative or non-finite error
/// cap, or a locked vertex out of range; [`Error::Mesh`] for faces that are not
/// surfaces (located); [`Error::Cancelled`]; [`Error::Unverified`] if the output fails
/// its check.
///
/// # Example
/// ```
/// use contractible::{decimate, gen, DecimateOptions};
/// let sphere = gen::isosurface(&gen::IsoParams::new(
///     gen::Implicit::Sphere { radius: 1.0 },
///     gen::Tessellation::SixTetrahedra,
///     12,
/// ))?;
/// let d = decimate(&sphere, &DecimateOptions::keep(0.1))?;
/// assert!(d.mesh.faces.len() <= (sphere.faces.len() + 9) / 10);
/// assert_eq!(d.stats.stopped.name(), "target");
/// // Every output vertex is an input vertex that survived; every input vertex went
/// // into an output vertex.
/// assert_eq!(d.vertex_map.len(), d.mesh.vertex_count);
/// assert_eq!(d.collapse_map[d.vertex_map[0] as usize], 0);
/// // The fast option: the same guarantees, another order of collapses.
/// let fast = decimate(&sphere, &DecimateOptions {
///     schedule: contractible::decimate::Schedule::Passes,
///     ..DecimateOptions::keep(0.1)
/// })?;
/// assert_eq!(fast.mesh.faces.len(), d.mesh.faces.len());
/// assert!(fast.stats.passes > 0 && d.stats.passes == 0);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn decimate(mesh: &TriMesh, options: &DecimateOptions) -> Result<DecimateResult, Error> {
    let monitor = &options.monitor;
    let started = std::time::Instant::now();
    let (positions, used) = checked_positions(mesh, "decimate")?;
    monitor.step(Step::Build, 0, 0, mesh.faces.len())?;
    let whole = ConedSurfaces::whole(mesh.vertex_count, &mesh.faces)?;
    let diagonal = bbox_diagonal(used.iter().map(|&v| positions[v]));
    drop(used);
    let opts = resolve(mesh, options, mesh.faces.len(), diagonal)?;
    let dropped_vertices = whole.dropped_vertices.len();
    let mut stats = decimate::input_stats(&whole, mesh.vertex_count);
    stats.target_faces =
        (options.faces.is_some() || options.keep.is_some()).then_some(opts.target_faces);
    stats.max_error_cap = opts.max_error;
    let seconds_build = started.elapsed().as_secs_f64();
    let run_started = std::time::Instant::now();
    monitor.step(Step::Run, 0, 1, mesh.faces.len())?;
    let mut d = decimate::Decimator::new(whole, positions, &opts);
    let mut observer = monitor.progress(0);
    let finished = match opts.schedule {
        Schedule::Exact => d.run(&mut observer, &|| monitor.is_cancelled()),
        Schedule::Passes => d.run_passes(&mut observer, &|| monitor.is_cancelled()),
    };
    if !finished {
        return Err(Error::Cancelled);
    }
    let out = d.finish(stats);
    let mut stats = out.stats;
    let result_mesh = TriMesh::with_positions(out.positions, out.faces);
    stats.seconds = run_started.elapsed().as_secs_f64();
    let mut result = DecimateResult {
        mesh: result_mesh,
        stats,
        vertex_map: out.vertex_map,
        collapse_map: out.collapse_map,
        face_origin: out.face_origin,
        bbox_diagonal: diagonal,
        dropped_vertices,
        verified: false,
        seconds_build,
        seconds_verify: None,
    };
    if !options.skip_verify {
        let started = std::time::Instant::now();
        monitor.step(Step::Verify, 0, 1, result.mesh.faces.len())?;
        verify_decimation(mesh, options, &result).map_err(|detail| Error::Unverified {
            task: "decimate",
            components: (0..result.stats.components).collect(),
            detail,
        })?;
        result.verified = true;
        result.seconds_verify = Some(started.elapsed().as_secs_f64());
    }
    Ok(result)
}

/// The independent check of a decimation of `input` made with `options`, from the
/// input, the output mesh and the maps alone (nothing the algorithm kept):
///
/// - the output rebuilt from its faces is a union of surfaces using every vertex, and
///   each of its components descends (through `face_origin`) from exactly one input
///   component, one to one, with the same (χ, orientability, boundary loops);
/// - the maps agree: `vertex_map` increasing over input vertices, `collapse_map` its
///   inverse on them and defined exactly on the vertices faces use, `face_origin`
///   increasing, and every output face is its origin face with each corner renamed
///   by `collapse_map`;
/// - locked vertices (and boundary vertices, when locked) survive at their input
///   positions; with [`Placement::Endpoint`], every output position is its surviving
///   vertex's input position;
/// - a run that says it reached its target has at most that many faces.
///
/// The error says what differs and where.
///
/// # Example
/// ```
/// use contractible::{decimate, gen, verify_decimation, DecimateOptions};
/// let torus = gen::isosurface(&gen::IsoParams::new(
///     gen::Implicit::Torus { major: 1.0, minor: 0.4 },
///     gen::Tessellation::SixTetrahedra,
///     14,
/// ))?;
/// let o = DecimateOptions::faces(200);
/// let mut d = decimate(&torus, &o)?;
/// assert_eq!(verify_decimation(&torus, &o, &d), Ok(()));
/// d.face_origin.swap(0, 1);
/// assert!(verify_decimation(&torus, &o, &d).is_err());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn verify_decimation(
    input: &TriMesh,
    options: &DecimateOptions,
    result: &DecimateResult,
) -> Result<(), String> {
    let out = &result.mesh;
    let nv_in = input.vertex_count;
    let nv_out = out.vertex_count;
    // The maps.
    if result.vertex_map.len() != nv_out {
        return Err(format!(
            "vertex_map has {} entries for {nv_out} output vertices",
            result.vertex_map.len()
        ));
    }
    if result.collapse_map.len() != nv_in {
        return Err(format!(
            "collapse_map has {} entries for {nv_in} input vertices",
            result.collapse_map.len()
        ));
    }
    if result.face_origin.len() != out.faces.len() {
        return Err(format!(
            "face_origin has {} entries for {} output faces",
            result.face_origin.len(),
            out.faces.len()
        ));
    }
    for (o, &i) in result.vertex_map.iter().enumerate() {
        if i as usize >= nv_in {
            return Err(format!("vertex_map[{o}] = {i} is no input vertex"));
        }
        if o > 0 && result.vertex_map[o - 1] >= i {
            return Err(format!("vertex_map is not increasing at {o}"));
        }
        if result.collapse_map[i as usize] != o as u32 {
            return Err(format!(
                "output vertex {o} survives as input vertex {i}, but collapse_map[{i}] = {}",
                result.collapse_map[i as usize]
            ));
        }
    }
    let mut used = vec![false; nv_in];
    for f in &input.faces {
        for &v in f {
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    for (i, &o) in result.collapse_map.iter().enumerate() {
        match (used[i], o) {
            (false, NO_VERTEX) => {}
            (false, _) => {
                return Err(format!(
                    "collapse_map[{i}] = {o} for a vertex no input face uses"
                ))
            }
            (true, o) if o as usize >= nv_out => {
                return Err(format!("collapse_map[{i}] = {o} is no output vertex"))
            }
            _ => {}
        }
    }
    for (k, (&f, face)) in result.face_origin.iter().zip(&out.faces).enumerate() {
        let Some(origin) = input.faces.get(f as usize) else {
            return Err(format!("face_origin[{k}] = {f} is no input face"));
        };
        if k > 0 && result.face_origin[k - 1] >= f {
            return Err(format!("face_origin is not increasing at {k}"));
        }
        let renamed = origin.map(|v| result.collapse_map[v as usize]);
        if renamed != *face {
            return Err(format!(
                "output face {k} {face:?} is not its origin, input face {f} {origin:?}, \
                 renamed by collapse_map ({renamed:?})"
            ));
        }
    }
    // The surfaces, component by component.
    let s_out = Surfaces::from_mesh_with_boundary(out)
        .map_err(|e| format!("the output is not a surface: {e}"))?;
    if !s_out.dropped_vertices.is_empty() {
        return Err(format!(
            "the output has {} unused vertices",
            s_out.dropped_vertices.len()
        ));
    }
    let s_in =
        ConedSurfaces::from_mesh(input).map_err(|e| format!("the input is not a surface: {e}"))?;
    let mut input_component = vec![u32::MAX; input.faces.len()];
    for (k, c) in s_in.components.iter().enumerate() {
        for &f in &c.face_origin {
            input_component[f as usize] = k as u32;
        }
    }
    let key = |c: &crate::core::ConedComponent| -> TypeKey {
        let t = c.surface_type();
        (
            t.euler_characteristic(),
            t.is_orientable(),
            t.boundary_loops(),
        )
    };
    let mut matched = vec![None; s_in.components.len()];
    for (k, c) in s_out.components.iter().enumerate() {
        let mut origin = None;
        for &f in &c.face_origin {
            let from = input_component[result.face_origin[f as usize] as usize];
            match origin {
                None => origin = Some(from),
                Some(o) if o != from => {
                    return Err(format!(
                        "output component {k} descends from input components {o} and {from}"
                    ))
                }
                _ => {}
            }
        }
        let Some(from) = origin else { continue };
        let from = from as usize;
        if let Some(other) = matched[from].replace(k) {
            return Err(format!(
                "output components {other} and {k} both descend from input component {from}"
            ));
        }
        let (want, have) = (key(&s_in.components[from]), key(c));
        if want != have {
            return Err(format!(
                "output component {k} (χ={} {} b={}) differs from input component {from} \
                 (χ={} {} b={})",
                have.0,
                if have.1 {
                    "orientable"
                } else {
                    "non-orientable"
                },
                have.2,
                want.0,
                if want.1 {
                    "orientable"
                } else {
                    "non-orientable"
                },
                want.2
            ));
        }
    }
    if let Some(lost) = matched.iter().position(Option::is_none) {
        return Err(format!("input component {lost} has no output component"));
    }
    // Vertices that must not move.
    let (Some(pin), Some(pout)) = (input.positions.as_deref(), out.positions.as_deref()) else {
        return Err("the input or the output has no positions".to_string());
    };
    if pout.len() != nv_out {
        return Err(format!(
            "the output has {nv_out} vertices but {} positions",
            pout.len()
        ));
    }
    let stays = |i: u32, why: &str| -> Result<(), String> {
        let o = result.collapse_map[i as usize];
        if o == NO_VERTEX {
            return Ok(());
        }
        if result.vertex_map[o as usize] != i {
            return Err(format!(
                "{why} vertex {i} did not survive (it went into output vertex {o})"
            ));
        }
        if pout[o as usize] != pin[i as usize] {
            return Err(format!(
                "{why} vertex {i} moved from {:?} to {:?}",
                pin[i as usize], pout[o as usize]
            ));
        }
        Ok(())
    };
    for &i in &options.locked {
        if (i as usize) < nv_in {
            stays(i, "locked")?;
        }
    }
    if options.lock_boundary {
        let mut count: HashMap<(u32, u32), u32> = HashMap::new();
        for f in &input.faces {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                *count.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            }
        }
        let mut boundary: Vec<u32> = count
            .into_iter()
            .filter(|&(_, n)| n == 1)
            .flat_map(|((a, b), _)| [a, b])
            .collect();
        boundary.sort_unstable();
        boundary.dedup();
        for i in boundary {
            stays(i, "boundary")?;
        }
    }
    if options.placement == Placement::Endpoint {
        for (o, &i) in result.vertex_map.iter().enumerate() {
            if pout[o] != pin[i as usize] {
                return Err(format!(
                    "endpoint placement: output vertex {o} is at {:?}, not at input vertex {i}'s {:?}",
                    pout[o], pin[i as usize]
                ));
            }
        }
    }
    if result.stats.stopped == decimate::Stopped::Target {
        if let Some(t) = result.stats.target_faces {
            if out.faces.len() > t {
                return Err(format!(
                    "stopped at the target, but {} faces are above the target {t}",
                    out.faces.len()
                ));
            }
        }
    }
    Ok(())
}
