//! `ctr_simplify`: every edge shorter than ε contracted without changing the topology
//! (`contractible::simplify`, Pepko–Borisenko).

use contractible::simplify::{Mode, Position, Side};
use contractible::{Eps, SimplifyOptions, SimplifyResult};

use crate::error::{ctr_error, guard, object, read_options, sized_out, status, Failure};
use crate::mesh::ctr_mesh;

/// Mode: remove the discs inside the outermost 3-cycles through an edge the link
/// condition blocks, then contract it (the paper's processEdge; the default).
pub const CTR_SIMPLIFY_NESTED: u32 = 0;
/// Mode: skip every edge that fails the link condition.
pub const CTR_SIMPLIFY_NAIVE: u32 = 1;
/// Side of a 3-cycle's disc (nested mode): grow both sides face by face, a 3-cycle goes
/// to the side that closes it first (the default).
pub const CTR_SIDE_COUNT: u32 = 0;
/// Side: the side whose opposite vertex is nearer in edge hops.
pub const CTR_SIDE_PATH: u32 = 1;
/// Side: the side whose opposite vertex is nearer in space.
pub const CTR_SIDE_EUCLIDEAN: u32 = 2;
/// Position of a contracted edge's vertex: the midpoint, or the boundary endpoint of an
/// edge with one endpoint on the boundary (the default).
pub const CTR_POSITION_MIDPOINT: u32 = 0;
/// Position: the minimiser of the summed Garland–Heckbert quadrics of both endpoints.
pub const CTR_POSITION_QUADRIC: u32 = 1;

/// Options of [`ctr_simplify`]; start from [`ctr_simplify_options_default`].
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_simplify_options {
    /// `sizeof(ctr_simplify_options)` as the caller was compiled.
    pub size: u32,
    /// Edges strictly shorter than ε are contracted: `eps` is ε, or with `eps_relative`
    /// its fraction of the diagonal of the bounding box of the vertices the faces use.
    pub eps: f64,
    /// `eps` is a fraction of the bounding-box diagonal (on by default).
    pub eps_relative: bool,
    /// `CTR_SIMPLIFY_NESTED` or `CTR_SIMPLIFY_NAIVE`.
    pub mode: u32,
    /// `CTR_SIDE_COUNT`, `CTR_SIDE_PATH` or `CTR_SIDE_EUCLIDEAN`.
    pub side: u32,
    /// `CTR_POSITION_MIDPOINT` or `CTR_POSITION_QUADRIC`.
    pub position: u32,
    /// Allow contractions that turn a remaining triangle by 90° or more (the fold-over
    /// guard off; the topology is kept either way).
    pub allow_foldover: bool,
    /// Check the output independently before returning it (on by default).
    pub verify: bool,
}

/// The default options, those of `contractible::simplify`: ε 1 % of the bounding-box
/// diagonal, the nested mode, the count heuristic, midpoints, the fold-over guard on,
/// the output verified.
#[no_mangle]
pub extern "C" fn ctr_simplify_options_default() -> ctr_simplify_options {
    ctr_simplify_options {
        size: std::mem::size_of::<ctr_simplify_options>() as u32,
        eps: 0.01,
        eps_relative: true,
        mode: CTR_SIMPLIFY_NESTED,
        side: CTR_SIDE_COUNT,
        position: CTR_POSITION_MIDPOINT,
        allow_foldover: false,
        verify: true,
    }
}

/// What a simplification did.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_simplify_stats {
    /// `sizeof(ctr_simplify_stats)` as the caller was compiled (set by
    /// [`ctr_simplify_stats_default`]).
    pub size: u32,
    /// The absolute ε used.
    pub eps: f64,
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
    /// Boundary loops (the same before and after).
    pub boundary_loops: u64,
    /// Edges contracted.
    pub edges_contracted: u64,
    /// Discs inside 3-cycles replaced by one triangle (nested mode).
    pub discs_removed: u64,
    /// Edges shorter than ε left at the end (each one fails the link condition, or its
    /// contraction would fold a face over).
    pub short_edges_remaining: u64,
    /// The shortest edge of the output (-1 for an output without edges).
    pub shortest_remaining_edge: f64,
}

/// A `ctr_simplify_stats` of zeros with its `size` set.
#[no_mangle]
pub extern "C" fn ctr_simplify_stats_default() -> ctr_simplify_stats {
    ctr_simplify_stats {
        size: std::mem::size_of::<ctr_simplify_stats>() as u32,
        eps: 0.0,
        faces_in: 0,
        faces_out: 0,
        vertices_in: 0,
        vertices_out: 0,
        components: 0,
        boundary_loops: 0,
        edges_contracted: 0,
        discs_removed: 0,
        short_edges_remaining: 0,
        shortest_remaining_edge: -1.0,
    }
}

/// The result of [`ctr_simplify`]: the output mesh and the statistics. Opaque; freed by
/// [`ctr_simplify_result_free`].
pub struct ctr_simplify_result {
    mesh: ctr_mesh,
    stats: ctr_simplify_stats,
}

/// The library's options for the C options, or why they are refused.
pub(crate) fn simplify_options(o: &ctr_simplify_options) -> Result<SimplifyOptions, Failure> {
    let mode = match o.mode {
        CTR_SIMPLIFY_NESTED => Mode::Nested,
        CTR_SIMPLIFY_NAIVE => Mode::Naive,
        other => {
            return Err(Failure::argument(format!(
                "options->mode is {other}: CTR_SIMPLIFY_NESTED (0) or CTR_SIMPLIFY_NAIVE (1)"
            )))
        }
    };
    let side = match o.side {
        CTR_SIDE_COUNT => Side::Count,
        CTR_SIDE_PATH => Side::Path,
        CTR_SIDE_EUCLIDEAN => Side::Euclidean,
        other => {
            return Err(Failure::argument(format!(
                "options->side is {other}: CTR_SIDE_COUNT (0), CTR_SIDE_PATH (1) or \
                 CTR_SIDE_EUCLIDEAN (2)"
            )))
        }
    };
    let position = position(o.position)?;
    Ok(SimplifyOptions {
        eps: if o.eps_relative {
            Eps::Relative(o.eps)
        } else {
            Eps::Absolute(o.eps)
        },
        mode,
        side,
        position,
        allow_foldover: o.allow_foldover,
        skip_verify: !o.verify,
        ..SimplifyOptions::default()
    })
}

/// The placement named by `CTR_POSITION_*`.
pub(crate) fn position(p: u32) -> Result<Position, Failure> {
    match p {
        CTR_POSITION_MIDPOINT => Ok(Position::Midpoint),
        CTR_POSITION_QUADRIC => Ok(Position::Quadric),
        other => Err(Failure::argument(format!(
            "options->position is {other}: CTR_POSITION_MIDPOINT (0) or CTR_POSITION_QUADRIC (1)"
        ))),
    }
}

/// Contracts every edge of `mesh` shorter than ε whose contraction keeps the surface
/// (closed or with boundary, orientable or not, several components; positions needed),
/// as `contractible::simplify`; the output keeps every component's surface (χ,
/// orientability, boundary loops), checked before returning. NULL on failure:
/// `CTR_INPUT` for a mesh that is no surface (located), no positions, or an ε that is
/// not a finite positive length (kind `bad_option`), `CTR_INVALID_ARGUMENT` for an
/// unknown mode, side or position.
///
/// # Safety
/// `mesh` is a live mesh; `options` is NULL (the defaults) or from
/// `ctr_simplify_options_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_simplify(
    mesh: *const ctr_mesh,
    options: *const ctr_simplify_options,
    err: *mut ctr_error,
) -> *mut ctr_simplify_result {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises a live mesh.
        let m = unsafe { object(mesh, "mesh") }?;
        // SAFETY: NULL or a valid options struct of its stated size.
        let o = unsafe { read_options(options, ctr_simplify_options_default(), "options") }?;
        let options = simplify_options(&o)?;
        let r: SimplifyResult =
            contractible::simplify(&m.mesh(), &options).map_err(Failure::from)?;
        let s = &r.stats;
        let mut stats = ctr_simplify_stats_default();
        stats.eps = r.eps;
        stats.faces_in = s.faces_in as u64;
        stats.faces_out = s.faces_out as u64;
        stats.vertices_in = s.vertices_in as u64;
        stats.vertices_out = s.vertices_out as u64;
        stats.components = s.components as u64;
        stats.boundary_loops = s.boundary_loops as u64;
        stats.edges_contracted = s.edges_contracted as u64;
        stats.discs_removed = s.discs_removed as u64;
        stats.short_edges_remaining = s.short_edges_remaining as u64;
        stats.shortest_remaining_edge = s.shortest_remaining_edge.unwrap_or(-1.0);
        Ok(Box::into_raw(Box::new(ctr_simplify_result {
            mesh: ctr_mesh::owned(r.mesh),
            stats,
        })))
    })
}

/// The output mesh: the vertices left of every component with their positions,
/// component by component (in the order of their smallest input face), each in input
/// vertex order. Owned by the result: valid until it is freed, not to be passed to
/// `ctr_mesh_free`. NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_simplify_result_mesh(
    result: *const ctr_simplify_result,
) -> *const ctr_mesh {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(result, "result") }.map_or(std::ptr::null(), |r| &r.mesh)
}

/// Copies the statistics into `*out` (made by `ctr_simplify_stats_default`): `CTR_OK`,
/// or `CTR_INVALID_ARGUMENT` for a NULL result or an `out` of another size.
///
/// # Safety
/// `result` is NULL or a live result; `out` points to a `ctr_simplify_stats` from
/// `ctr_simplify_stats_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_simplify_result_stats(
    result: *const ctr_simplify_result,
    out: *mut ctr_simplify_stats,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: NULL or live, by the caller's promise.
        let r = unsafe { object(result, "result") }?;
        // SAFETY: the caller promises a `ctr_simplify_stats` from its default function.
        *unsafe { sized_out(out, "ctr_simplify_stats_default") }? = r.stats;
        Ok(())
    })
}

/// Frees a result and the mesh it owns (NULL is ignored).
///
/// # Safety
/// `result` is NULL or a result of `ctr_simplify` not freed yet.
#[no_mangle]
pub unsafe extern "C" fn ctr_simplify_result_free(result: *mut ctr_simplify_result) {
    if !result.is_null() {
        // SAFETY: made by Box::into_raw in ctr_simplify, freed once.
        drop(unsafe { Box::from_raw(result) });
    }
}
