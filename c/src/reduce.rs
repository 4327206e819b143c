//! `ctr_reduce`: the irreducible triangulation of every component.

use contractible::irreducible::Algorithm;
use contractible::{ReduceOptions, ReduceResult};

use crate::error::{ctr_error, guard, object, read_options, Failure};
use crate::mesh::ctr_mesh;

/// Ramaswami–Siqueira's algorithm (the default).
pub const CTR_REDUCE_RS: u32 = 0;
/// Schipper's algorithm.
pub const CTR_REDUCE_SCHIPPER: u32 = 1;
/// The randomised brute force (its order from `seed`).
pub const CTR_REDUCE_BRUTE: u32 = 2;

/// Options of `ctr_reduce`; start from `ctr_reduce_options_default`.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_reduce_options {
    /// `sizeof(ctr_reduce_options)` as the caller was compiled.
    pub size: u32,
    /// `CTR_REDUCE_RS`, `CTR_REDUCE_SCHIPPER` or `CTR_REDUCE_BRUTE`.
    pub algorithm: u32,
    /// Seed of the brute force's shuffle (the library's documented random stream).
    pub seed: u64,
    /// Check every output independently (on by default); a failure is
    /// `CTR_FAILURE` with kind `unverified`.
    pub verify: bool,
    /// Keep the contractions (`ctr_reduce_result_contractions`); off, they cost no
    /// memory (about 44 bytes per input triangle).
    pub keep_history: bool,
}

/// The default options: RS, seed 0, outputs verified, no history.
#[no_mangle]
pub extern "C" fn ctr_reduce_options_default() -> ctr_reduce_options {
    ctr_reduce_options {
        size: std::mem::size_of::<ctr_reduce_options>() as u32,
        algorithm: CTR_REDUCE_RS,
        seed: 0,
        verify: true,
        keep_history: false,
    }
}

/// The result of `ctr_reduce`: the irreducible triangulations (one mesh), the input
/// vertex of each output vertex, the contractions when kept. Opaque; freed by
/// `ctr_reduce_result_free`.
pub struct ctr_reduce_result {
    mesh: ctr_mesh,
    vertex_map: Vec<u32>,
    contractions: Vec<[u32; 2]>,
    components: usize,
}

/// Reduces every component of the closed surface `mesh` to an irreducible triangulation
/// (no edge passes the link condition), as `contractible::reduce`. NULL on failure:
/// `CTR_INPUT` for a mesh that is no closed surface (the first defect, located)
/// or a bad option, `CTR_INVALID_ARGUMENT` for an unknown algorithm.
///
/// # Safety
/// `mesh` is a live mesh; `options` is NULL (the defaults) or from
/// `ctr_reduce_options_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_reduce(
    mesh: *const ctr_mesh,
    options: *const ctr_reduce_options,
    err: *mut ctr_error,
) -> *mut ctr_reduce_result {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises a live mesh.
        let m = unsafe { object(mesh, "mesh") }?;
        // SAFETY: NULL or a valid options struct of its stated size.
        let o = unsafe { read_options(options, ctr_reduce_options_default(), "options") }?;
        let algorithm = match o.algorithm {
            CTR_REDUCE_RS => Algorithm::Rs,
            CTR_REDUCE_SCHIPPER => Algorithm::Schipper,
            CTR_REDUCE_BRUTE => Algorithm::Brute,
            other => {
                return Err(Failure::argument(format!(
                    "options->algorithm is {other}: CTR_REDUCE_RS (0), CTR_REDUCE_SCHIPPER (1) \
                     or CTR_REDUCE_BRUTE (2)"
                )))
            }
        };
        let options = ReduceOptions {
            algorithm,
            seed: o.seed,
            verify: o.verify,
            keep_history: o.keep_history,
            ..ReduceOptions::default()
        };
        let r: ReduceResult = contractible::reduce(m.view(), &options).map_err(Failure::from)?;
        let contractions = r.contractions();
        Ok(Box::into_raw(Box::new(ctr_reduce_result {
            components: r.components.len(),
            vertex_map: r.vertex_map,
            contractions,
            mesh: ctr_mesh::owned(r.mesh),
        })))
    })
}

/// The output mesh: the survivors (renumbered in increasing input order, with their
/// input positions) and the faces, component by component. Owned by the result: valid
/// until it is freed, not to be passed to `ctr_mesh_free`. NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_reduce_result_mesh(
    result: *const ctr_reduce_result,
) -> *const ctr_mesh {
    // SAFETY: NULL or live, by the caller's promise.
    match unsafe { object(result, "result") } {
        Ok(r) => &r.mesh,
        Err(_) => std::ptr::null(),
    }
}

/// The input vertex of each output vertex (`ctr_mesh_vertex_count` of the output
/// entries). NULL for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_reduce_result_vertex_map(
    result: *const ctr_reduce_result,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    match unsafe { object(result, "result") } {
        Ok(r) => r.vertex_map.as_ptr(),
        Err(_) => std::ptr::null(),
    }
}

/// The contractions, `2 * *count` input vertex ids (`kept, removed` each, oldest first,
/// component by component), as `contractible check reduce --history` replays them; `*count`
/// is 0 unless the options kept the history. NULL (and `*count` 0) for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result; `count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn ctr_reduce_result_contractions(
    result: *const ctr_reduce_result,
    count: *mut usize,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    let r = unsafe { object(result, "result") }.ok();
    if !count.is_null() && count.is_aligned() {
        // SAFETY: non-null, aligned, writable by the caller's promise.
        unsafe { count.write(r.map_or(0, |r| r.contractions.len())) };
    }
    r.map_or(std::ptr::null(), |r| r.contractions.as_ptr().cast::<u32>())
}

/// The number of connected components reduced (0 for a NULL result).
///
/// # Safety
/// `result` is NULL or a live result.
#[no_mangle]
pub unsafe extern "C" fn ctr_reduce_result_component_count(
    result: *const ctr_reduce_result,
) -> usize {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(result, "result") }.map_or(0, |r| r.components)
}

/// Frees a result and the mesh it owns (NULL is ignored).
///
/// # Safety
/// `result` is NULL or a result of `ctr_reduce` not freed yet.
#[no_mangle]
pub unsafe extern "C" fn ctr_reduce_result_free(result: *mut ctr_reduce_result) {
    if !result.is_null() {
        // SAFETY: made by Box::into_raw in ctr_reduce, freed once.
        drop(unsafe { Box::from_raw(result) });
    }
}
