//! The conformance checker (`contractible::check`): an independent verdict on an output
//! produced by any implementation, judged by its properties, not its bytes.

use std::ffi::{c_char, CString};

use contractible::check::{self, DecimateCheck, QuadCheck, SimplifyCheck, Verdict};
use contractible::{Eps, QuadMesh};

use crate::decimate::{ctr_decimate_options, ctr_decimate_options_default, decimate_options};
use crate::error::{ctr_error, guard, object, read_options, sized_out, slice, status, Failure};
use crate::mesh::ctr_mesh;
use crate::simplify::{ctr_simplify_options, ctr_simplify_options_default, position};

/// One reason an output fails: what, a sentence saying what and where, and the output
/// face, edge, vertex or input component involved (-1 where none is).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_check_failure {
    /// `sizeof(ctr_check_failure)` as the caller was compiled (set by
    /// [`ctr_check_failure_default`]).
    pub size: u32,
    /// The kind, a NUL-terminated name (`contractible_edge`, `surface_changed`, … as
    /// `contractible check --json` prints them); owned by the verdict.
    pub kind: *const c_char,
    /// The sentence, NUL-terminated; owned by the verdict.
    pub message: *const c_char,
    /// An output face, or -1.
    pub face: i64,
    /// The smaller end of an output edge, or -1.
    pub edge_from: i64,
    /// The larger end of that edge, or -1.
    pub edge_to: i64,
    /// An output vertex, or -1.
    pub vertex: i64,
    /// An input component (numbered in the order of their smallest face), or -1.
    pub component: i64,
}

/// A `ctr_check_failure` with its `size` set, NULL strings and no location.
#[no_mangle]
pub extern "C" fn ctr_check_failure_default() -> ctr_check_failure {
    ctr_check_failure {
        size: std::mem::size_of::<ctr_check_failure>() as u32,
        kind: std::ptr::null(),
        message: std::ptr::null(),
        face: -1,
        edge_from: -1,
        edge_to: -1,
        vertex: -1,
        component: -1,
    }
}

/// A verdict: passed, or the reasons the output fails (at most 20 of a kind, in the
/// order found). Opaque; freed by [`ctr_verdict_free`].
pub struct ctr_verdict {
    failures: Vec<(CString, CString, ctr_check_failure)>,
}

fn c_string(s: &str) -> CString {
    // A NUL inside cannot come from the checker's names and sentences; cut there if so.
    let bytes = s.as_bytes();
    let end = bytes.iter().position(|&b| b == 0).unwrap_or(bytes.len());
    CString::new(&bytes[..end]).unwrap_or_default()
}

fn located(v: Option<impl Into<i64>>) -> i64 {
    v.map_or(-1, Into::into)
}

fn verdict(v: Verdict) -> *mut ctr_verdict {
    let failures = v
        .failures
        .iter()
        .map(|f| {
            let mut c = ctr_check_failure_default();
            c.face = f.face.map_or(-1, |x| i64::try_from(x).unwrap_or(i64::MAX));
            c.edge_from = located(f.edge.map(|e| e[0]));
            c.edge_to = located(f.edge.map(|e| e[1]));
            c.vertex = located(f.vertex);
            c.component = f
                .component
                .map_or(-1, |x| i64::try_from(x).unwrap_or(i64::MAX));
            (c_string(f.kind.name()), c_string(&f.message), c)
        })
        .collect();
    Box::into_raw(Box::new(ctr_verdict { failures }))
}

/// Judges `output` as an irreducible triangulation of `input` (the task `reduce`), as
/// `contractible::check::reduce`: a closed 2-manifold of the input's surface per
/// component, on the input's vertices at their positions, no edge passing the link
/// condition. With `history` (not NULL), `2 * history_count` input vertex ids (`kept,
/// removed` per contraction, as `ctr_reduce_result_contractions` gives them), each
/// contraction must also be valid in turn and replaying them must give the output
/// (`check::reduce_history`). The verdict, or NULL on failure: `CTR_INPUT` when `input`
/// is no closed surface (which `reduce` must refuse).
///
/// # Safety
/// `input` and `output` are live meshes; `history` is NULL or points to `2 *
/// history_count` ids; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_check_reduce(
    input: *const ctr_mesh,
    output: *const ctr_mesh,
    history: *const u32,
    history_count: usize,
    err: *mut ctr_error,
) -> *mut ctr_verdict {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises live meshes.
        let (i, o) = unsafe { (object(input, "input")?, object(output, "output")?) };
        let v = if history.is_null() {
            check::reduce(&i.mesh(), &o.mesh())
        } else {
            let ids = history_count.checked_mul(2).ok_or_else(|| {
                Failure::argument(format!("{history_count} contractions cannot exist"))
            })?;
            // SAFETY: the caller promises `2 * history_count` readable ids.
            let h = unsafe { slice(history, ids, "history") }?;
            let pairs: Vec<[u32; 2]> = h.chunks_exact(2).map(|c| [c[0], c[1]]).collect();
            check::reduce_history(&i.mesh(), &o.mesh(), &pairs)
        };
        Ok(verdict(v.map_err(Failure::from)?))
    })
}

/// Judges `output` as a simplification of `input` by a run with `options` (the options
/// given to `ctr_simplify`: ε, the position and the fold-over guard are read; NULL: the
/// defaults), as `contractible::check::simplify`: the input's surface per component
/// (boundary loops included), a 2-manifold, and no edge shorter than ε left that the
/// run could have contracted. The verdict, or NULL on failure: `CTR_INPUT` when `input`
/// is no surface or ε is no positive length, `CTR_INVALID_ARGUMENT` for an unknown
/// position.
///
/// # Safety
/// `input` and `output` are live meshes; `options` is NULL or from
/// `ctr_simplify_options_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_check_simplify(
    input: *const ctr_mesh,
    output: *const ctr_mesh,
    options: *const ctr_simplify_options,
    err: *mut ctr_error,
) -> *mut ctr_verdict {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises live meshes.
        let (i, o) = unsafe { (object(input, "input")?, object(output, "output")?) };
        // SAFETY: NULL or a valid options struct of its stated size.
        let opts = unsafe { read_options(options, ctr_simplify_options_default(), "options") }?;
        let c = SimplifyCheck {
            eps: if opts.eps_relative {
                Eps::Relative(opts.eps)
            } else {
                Eps::Absolute(opts.eps)
            },
            position: position(opts.position)?,
            allow_foldover: opts.allow_foldover,
        };
        Ok(verdict(
            check::simplify(&i.mesh(), &o.mesh(), &c).map_err(Failure::from)?,
        ))
    })
}

/// Judges `quads` (`4 * quad_count` vertex ids of the input) as a tri-quad conversion of
/// `input` (the task `quad`), as `contractible::check::quad`: every quad two triangles of
/// the paired triangulation K split along a diagonal, every triangle of K in exactly one
/// quad, the quad mesh a closed polygon surface of the input's χ per component. K is
/// `triangles` (`3 * triangle_count` ids: an algorithm that flips edges must state it),
/// or the input's faces when NULL; `pairs` (NULL: inferred) gives per quad the two rows
/// of K it joins (`2 * quad_count` ids). The verdict, or NULL on failure: `CTR_INPUT`
/// when `input` is no closed surface.
///
/// # Safety
/// `input` is a live mesh; `quads` points to `4 * quad_count` ids; `triangles` is NULL
/// or points to `3 * triangle_count` ids; `pairs` is NULL or points to `2 * quad_count`
/// ids; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_check_quad(
    input: *const ctr_mesh,
    quads: *const u32,
    quad_count: usize,
    triangles: *const u32,
    triangle_count: usize,
    pairs: *const u32,
    err: *mut ctr_error,
) -> *mut ctr_verdict {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises a live mesh.
        let i = unsafe { object(input, "input") }?;
        let ids = |count: usize, k: usize, what: &str| {
            count
                .checked_mul(k)
                .ok_or_else(|| Failure::argument(format!("{what}: {count} rows cannot exist")))
        };
        // SAFETY: the caller promises `4 * quad_count` readable ids.
        let q = unsafe { slice(quads, ids(quad_count, 4, "quads")?, "quads") }?;
        let k: Option<Vec<[u32; 3]>> = if triangles.is_null() {
            None
        } else {
            let n = ids(triangle_count, 3, "triangles")?;
            // SAFETY: the caller promises `3 * triangle_count` readable ids.
            let t = unsafe { slice(triangles, n, "triangles") }?;
            Some(t.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect())
        };
        let p: Option<Vec<[u32; 2]>> = if pairs.is_null() {
            None
        } else {
            // SAFETY: the caller promises `2 * quad_count` readable ids.
            let t = unsafe { slice(pairs, ids(quad_count, 2, "pairs")?, "pairs") }?;
            Some(t.chunks_exact(2).map(|c| [c[0], c[1]]).collect())
        };
        let output = QuadMesh {
            vertex_count: i.view().vertex_count,
            positions: i.view().positions.map(<[_]>::to_vec),
            faces: q
                .chunks_exact(4)
                .map(|c| [c[0], c[1], c[2], c[3]])
                .collect(),
        };
        let stated = QuadCheck {
            triangles: k.as_deref(),
            pairs: p.as_deref(),
        };
        Ok(verdict(
            check::quad(&i.mesh(), &output, &stated).map_err(Failure::from)?,
        ))
    })
}

/// Judges `output` as a decimation of `input` by a run with `options` (the options given
/// to `ctr_decimate`: its targets, cap, placement, guard and locks; NULL: the defaults),
/// as `contractible::check::decimate`: the input's surface per component, a face count
/// the target explains, locked vertices in place, and the provenance maps where given
/// (NULL: not stated) consistent with each other and with the faces: `vertex_map` (per
/// output vertex, the input vertex that survives as it), `collapse_map` (per input
/// vertex, the output vertex it went into), `face_origin` (per output face, the input
/// face it descends from). The verdict, or NULL on failure: `CTR_INPUT` when `input` is
/// no surface, has no positions or an option is out of range.
///
/// # Safety
/// `input` and `output` are live meshes; `options` is NULL or from
/// `ctr_decimate_options_default` (its `locked` pointing to `locked_count` ids); each
/// map is NULL or holds the count stated; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_check_decimate(
    input: *const ctr_mesh,
    output: *const ctr_mesh,
    options: *const ctr_decimate_options,
    vertex_map: *const u32,
    collapse_map: *const u32,
    face_origin: *const u32,
    err: *mut ctr_error,
) -> *mut ctr_verdict {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises live meshes.
        let (i, o) = unsafe { (object(input, "input")?, object(output, "output")?) };
        // SAFETY: NULL or a valid options struct of its stated size.
        let opts = unsafe { read_options(options, ctr_decimate_options_default(), "options") }?;
        // SAFETY: the caller promises `locked_count` readable ids at `locked`.
        let run = unsafe { decimate_options(&opts) }?;
        let map = |ptr: *const u32, len: usize, what: &str| {
            if ptr.is_null() {
                Ok(None)
            } else {
                // SAFETY: the caller promises `len` readable ids at a non-NULL map.
                unsafe { slice(ptr, len, what) }.map(Some)
            }
        };
        let c = DecimateCheck {
            vertex_map: map(vertex_map, o.view().vertex_count, "vertex_map")?,
            collapse_map: map(collapse_map, i.view().vertex_count, "collapse_map")?,
            face_origin: map(face_origin, o.view().faces.len(), "face_origin")?,
            ..DecimateCheck::of_run(&run)
        };
        Ok(verdict(
            check::decimate(&i.mesh(), &o.mesh(), &c).map_err(Failure::from)?,
        ))
    })
}

/// Whether the output passed (false for NULL).
///
/// # Safety
/// `verdict` is NULL or a live verdict.
#[no_mangle]
pub unsafe extern "C" fn ctr_verdict_passed(verdict: *const ctr_verdict) -> bool {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(verdict, "verdict") }.is_ok_and(|v| v.failures.is_empty())
}

/// The number of reasons listed (0 when the output passed, or for NULL).
///
/// # Safety
/// `verdict` is NULL or a live verdict.
#[no_mangle]
pub unsafe extern "C" fn ctr_verdict_failure_count(verdict: *const ctr_verdict) -> usize {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(verdict, "verdict") }.map_or(0, |v| v.failures.len())
}

/// Copies reason `index` (0-based, in the order found) into `*out` (made by
/// `ctr_check_failure_default`; its strings stay valid until the verdict is freed):
/// `CTR_OK`, or `CTR_INVALID_ARGUMENT` for a NULL verdict, an index past the count or an
/// `out` of another size.
///
/// # Safety
/// `verdict` is NULL or a live verdict; `out` points to a `ctr_check_failure` from
/// `ctr_check_failure_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_verdict_failure(
    verdict: *const ctr_verdict,
    index: usize,
    out: *mut ctr_check_failure,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: NULL or live, by the caller's promise.
        let v = unsafe { object(verdict, "verdict") }?;
        let (kind, message, f) = v.failures.get(index).ok_or_else(|| {
            Failure::argument(format!(
                "index {index}: the verdict lists {} reasons",
                v.failures.len()
            ))
        })?;
        // SAFETY: the caller promises a `ctr_check_failure` from its default function.
        let o = unsafe { sized_out(out, "ctr_check_failure_default") }?;
        *o = *f;
        o.kind = kind.as_ptr();
        o.message = message.as_ptr();
        Ok(())
    })
}

/// Frees a verdict and its strings (NULL is ignored).
///
/// # Safety
/// `verdict` is NULL or a verdict of a `ctr_check_*` function not freed yet.
#[no_mangle]
pub unsafe extern "C" fn ctr_verdict_free(verdict: *mut ctr_verdict) {
    if !verdict.is_null() {
        // SAFETY: made by Box::into_raw in `verdict`, freed once.
        drop(unsafe { Box::from_raw(verdict) });
    }
}
