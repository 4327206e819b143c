//! `ctr_decimate`: collapse edges, cheapest quadric error first, to a budget, every
//! collapse passing the link condition (`contractible::decimate`).

use contractible::decimate::{Placement, Schedule, Stopped};
use contractible::{DecimateOptions, DecimateResult, MaxError};

use crate::error::{ctr_error, guard, object, read_options, sized_out, slice, status, Failure};
use crate::mesh::ctr_mesh;

/// Placement: the minimiser of the summed quadric (the default; the best of the
/// endpoints and the midpoint where its system is ill-conditioned).
pub const CTR_PLACEMENT_OPTIMAL: u32 = 0;
/// Placement: the edge's midpoint.
pub const CTR_PLACEMENT_MIDPOINT: u32 = 1;
/// Placement: the endpoint with the smaller error (every output position is an input
/// position).
pub const CTR_PLACEMENT_ENDPOINT: u32 = 2;
/// Schedule: one priority queue, always the cheapest edge that passes every guard (the
/// default).
pub const CTR_SCHEDULE_EXACT: u32 = 0;
/// Schedule: passes over a sorted edge list, several times faster, a somewhat larger
/// error.
pub const CTR_SCHEDULE_PASSES: u32 = 1;
/// Why a decimation stopped: a face target was reached.
pub const CTR_STOPPED_TARGET: u32 = 0;
/// Why a decimation stopped: every edge left is over the error cap or refused by a
/// guard, at least one over the cap.
pub const CTR_STOPPED_ERROR: u32 = 1;
/// Why a decimation stopped: every edge left is refused by a guard (`remaining_*` of
/// the statistics say which).
pub const CTR_STOPPED_BLOCKED: u32 = 2;
/// The entry of a collapse map for an input vertex no face uses.
pub const CTR_NO_VERTEX: u32 = u32::MAX;

/// Options of [`ctr_decimate`]; start from [`ctr_decimate_options_default`]. Targets
/// combine (the first reached stops the run); with none, the run goes as far as the
/// guards allow.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_decimate_options {
    /// `sizeof(ctr_decimate_options)` as the caller was compiled.
    pub size: u32,
    /// `CTR_PLACEMENT_OPTIMAL`, `CTR_PLACEMENT_MIDPOINT` or `CTR_PLACEMENT_ENDPOINT`.
    pub placement: u32,
    /// Stop at this many faces (0: no face-count target).
    pub faces: u64,
    /// Stop at this fraction of the faces kept, in (0, 1] (0: no such target).
    pub keep: f64,
    /// Stop before a collapse whose error would exceed this (negative: no cap).
    pub max_error: f64,
    /// `max_error` is a fraction of the bounding-box diagonal, not a distance.
    pub max_error_relative: bool,
    /// Allow collapses that turn a face by 90° or more (the fold-over guard off).
    pub allow_foldover: bool,
    /// Keep every boundary vertex where it is.
    pub lock_boundary: bool,
    /// Check the output independently before returning it (on by default).
    pub verify: bool,
    /// `CTR_SCHEDULE_EXACT` or `CTR_SCHEDULE_PASSES`.
    pub schedule: u32,
    /// Input vertices kept where they are: `locked_count` ids (NULL when 0).
    pub locked: *const u32,
    /// The number of ids at `locked`.
    pub locked_count: usize,
}

/// The default options: no target (as coarse as the guards allow), optimal placement,
/// the exact schedule, the fold-over guard on, nothing locked, the output verified.
#[no_mangle]
pub extern "C" fn ctr_decimate_options_default() -> ctr_decimate_options {
    ctr_decimate_options {
        size: std::mem::size_of::<ctr_decimate_options>() as u32,
        placement: CTR_PLACEMENT_OPTIMAL,
        faces: 0,
        keep: 0.0,
        max_error: -1.0,
        max_error_relative: false,
        allow_foldover: false,
        lock_boundary: false,
        verify: true,
        schedule: CTR_SCHEDULE_EXACT,
        locked: std::ptr::null(),
        locked_count: 0,
    }
}

/// What a decimation did and why it stopped.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_decimate_stats {
    /// `sizeof(ctr_decimate_stats)` as the caller was compiled (set by
    /// [`ctr_decimate_stats_default`]).
    pub size: u32,
    /// `CTR_STOPPED_TARGET`, `CTR_STOPPED_ERROR` or `CTR_STOPPED_BLOCKED`.
    pub stopped: u32,
    /// Faces of the input.
    pub faces_in: u64,
    /// Faces of the output.
    pub faces_out: u64,
    /// Vertices of the input that faces use.
    pub vertices_in: u64,
    /// Vertices of the output.
    pub vertices_out: u64,
    /// Connected components.
    pub components: u64,
    /// Edges collapsed.
    pub collapses: u64,
    /// The largest error of a collapse (0 without collapses).
    pub max_error: f64,
    /// Edges left at the end refused by a lock (all `remaining_*` are 0 when the run
    /// stopped at its target).
    pub remaining_lock: u64,
    /// Edges left on the boundary with the boundary locked.
    pub remaining_boundary: u64,
    /// Edges left whose collapse would exceed the error cap.
    pub remaining_error: u64,
    /// Edges left that fail the link condition: collapsing them would change the
    /// surface.
    pub remaining_link_condition: u64,
    /// Edges left that the fold-over guard refuses.
    pub remaining_foldover: u64,
}

/// A `ctr_decimate_stats` of zeros with its `size` set.
#[no_mangle]
pub extern "C" fn ctr_decimate_stats_default() -> ctr_decimate_stats {
    ctr_decimate_stats {
        size: std::mem::size_of::<ctr_decimate_stats>() as u32,
        stopped: CTR_STOPPED_TARGET,
        faces_in: 0,
        faces_out: 0,
        vertices_in: 0,
        vertices_out: 0,
        components: 0,
        collapses: 0,
        max_error: 0.0,
        remaining_lock: 0,
        remaining_boundary: 0,
        remaining_error: 0,
        remaining_link_condition: 0,
        remaining_foldover: 0,
    }
}

/// The result of [`ctr_decimate`]: the output mesh, the provenance maps and the
/// statistics. Opaque; freed by [`ctr_decimate_result_free`].
pub struct ctr_decimate_result {
    mesh: ctr_mesh,
    vertex_map: Vec<u32>,
    collapse_map: Vec<u32>,
    face_origin: Vec<u32>,
    stats: ctr_decimate_stats,
}

/// The library's options for the C options, or why they are refused.
///
/// # Safety
/// `o.locked` points to `o.locked_count` readable ids (or the count is 0).
pub(crate) unsafe fn decimate_options(
    o: &ctr_decimate_options,
) -> Result<DecimateOptions, Failure> {
    let placement = match o.placement {
        CTR_PLACEMENT_OPTIMAL => Placement::Optimal,
        CTR_PLACEMENT_MIDPOINT => Placement::Midpoint,
        CTR_PLACEMENT_ENDPOINT => Placement::Endpoint,
        other => {
            return Err(Failure::argument(format!(
                "options->placement is {other}: CTR_PLACEMENT_OPTIMAL (0), \
                 CTR_PLACEMENT_MIDPOINT (1) or CTR_PLACEMENT_ENDPOINT (2)"
            )))
        }
    };
    let schedule = match o.schedule {
        CTR_SCHEDULE_EXACT => Schedule::Exact,
        CTR_SCHEDULE_PASSES => Schedule::Passes,
        other => {
            return Err(Failure::argument(format!(
                "options->schedule is {other}: CTR_SCHEDULE_EXACT (0) or \
                 CTR_SCHEDULE_PASSES (1)"
            )))
        }
    };
    // SAFETY: the caller promises `locked_count` readable ids at `locked`.
    let locked = unsafe { slice(o.locked, o.locked_count, "options->locked") }?;
    Ok(DecimateOptions {
        faces: (o.faces > 0).then_some(usize::try_from(o.faces).unwrap_or(usize::MAX)),
        keep: (o.keep != 0.0).then_some(o.keep),
        max_error: (o.max_error >= 0.0 || o.max_error.is_nan()).then_some(
            if o.max_error_relative {
                MaxError::Relative(o.max_error)
            } else {
                MaxError::Absolute(o.max_error)
            },
        ),
        placement,
        schedule,
        allow_foldover: o.allow_foldover,
        lock_boundary: o.lock_boundary,
        locked: locked.to_vec(),
        skip_verify: !o.verify,
        ..DecimateOptions::default()
    })
}

/// Decimates `mesh` (closed or with boundary, orientable or not, several components;
/// positions needed): every component keeps its surface (χ, orientability, boundary
/// loops), checked before returning. NULL on failure: `CTR_INPUT` for a mesh that is no
/// surface (located), no positions, or an option out of range (kind `bad_option`),
/// `CTR_INVALID_ARGUMENT` for an unknown placement or schedule.
///
/// # Safety
/// `mesh` is a live mesh; `options` is NULL (the defaults) or from
/// `ctr_decimate_options_default`, its `locked` pointing to `locked_count` ids; `err` is
/// NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate(
    mesh: *const ctr_mesh,
    options: *const ctr_decimate_options,
    err: *mut ctr_error,
) -> *mut ctr_decimate_result {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises a live mesh.
        let m = unsafe { object(mesh, "mesh") }?;
        // SAFETY: NULL or a valid options struct of its stated size.
        let o = unsafe { read_options(options, ctr_decimate_options_default(), "options") }?;
        // SAFETY: the caller promises `locked_count` readable ids at `locked`.
        let options = unsafe { decimate_options(&o) }?;
        let r: DecimateResult =
            contractible::decimate(&m.mesh(), &options).map_err(Failure::from)?;
        let s = &r.stats;
        let mut stats = ctr_decimate_stats_default();
        stats.stopped = match s.stopped {
            Stopped::Target => CTR_STOPPED_TARGET,
            Stopped::Error => CTR_STOPPED_ERROR,
            Stopped::Blocked => CTR_STOPPED_BLOCKED,
        };
        stats.faces_in = s.faces_in as u64;
        stats.faces_out = s.faces_out as u64;
        stats.vertices_in = s.vertices_in as u64;
        stats.vertices_out = s.vertices_out as u64;
        stats.components = s.components as u64;
        stats.collapses = s.collapses as u64;
        stats.max_error = s.max_error;
        stats.remaining_lock = s.remaining.lock as u64;
        stats.remaining_boundary = s.remaining.boundary as u64;
        stats.remaining_error = s.remaining.error as u64;
        stats.remaining_link_condition = s.remaining.link_condition as u64;
        stats.remaining_foldover = s.remaining.foldover as u64;
        Ok(Box::into_raw(Box::new(ctr_decimate_result {
            mesh: ctr_mesh::owned(r.mesh),
            vertex_map: r.vertex_map,
            collapse_map: r.collapse_map,
            face_origin: r.face_origin,
            stats,
        })))
    })
}

/// The output mesh (owned by the result: valid until it is freed, not to be passed to
/// `ctr_mesh_free`). NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate_result_mesh(
    result: *const ctr_decimate_result,
) -> *const ctr_mesh {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(result, "result") }.map_or(std::ptr::null(), |r| &r.mesh)
}

/// Per output vertex, the input vertex that survives as it (the output's vertex count
/// entries). NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate_result_vertex_map(
    result: *const ctr_decimate_result,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(result, "result") }.map_or(std::ptr::null(), |r| r.vertex_map.as_ptr())
}

/// Per input vertex, the output vertex it went into (`CTR_NO_VERTEX` for a vertex no
/// face uses): the input's vertex count entries, to carry any per-vertex attribute
/// across. NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate_result_collapse_map(
    result: *const ctr_decimate_result,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(result, "result") }.map_or(std::ptr::null(), |r| r.collapse_map.as_ptr())
}

/// Per output face, the input face it descends from (the output's face count entries).
/// NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate_result_face_origin(
    result: *const ctr_decimate_result,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(result, "result") }.map_or(std::ptr::null(), |r| r.face_origin.as_ptr())
}

/// Copies the statistics into `*out` (made by `ctr_decimate_stats_default`): `CTR_OK`,
/// or `CTR_INVALID_ARGUMENT` for a NULL result or an `out` of another size.
///
/// # Safety
/// `result` is NULL or a live result; `out` points to a `ctr_decimate_stats` from
/// `ctr_decimate_stats_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate_result_stats(
    result: *const ctr_decimate_result,
    out: *mut ctr_decimate_stats,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: NULL or live, by the caller's promise.
        let r = unsafe { object(result, "result") }?;
        // SAFETY: the caller promises a `ctr_decimate_stats` from its default function.
        *unsafe { sized_out(out, "ctr_decimate_stats_default") }? = r.stats;
        Ok(())
    })
}

/// Frees a result and the mesh it owns (NULL is ignored).
///
/// # Safety
/// `result` is NULL or a result of `ctr_decimate` not freed yet.
#[no_mangle]
pub unsafe extern "C" fn ctr_decimate_result_free(result: *mut ctr_decimate_result) {
    if !result.is_null() {
        // SAFETY: made by Box::into_raw in ctr_decimate, freed once.
        drop(unsafe { Box::from_raw(result) });
    }
}
