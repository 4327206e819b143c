//! `ctr_quadrangulate`: a quad mesh on the same vertices, by a perfect pairing of the
//! triangles of every component (`contractible::quadrangulate`).

use std::ffi::c_char;

use contractible::quad::Algorithm;
use contractible::{QuadMesh, QuadOptions, QuadResult};

use crate::error::{ctr_error, guard, object, path, read_options, sized_out, status, Failure};
use crate::mesh::ctr_mesh;

/// Lemos–Ramaswami–Siqueira: contraction, expansion with flips, completion (the
/// default).
pub const CTR_QUAD_LRS: u32 = 0;
/// Pulli–Segal greedy, then completion by augmenting paths.
pub const CTR_QUAD_PULLI_SEGAL: u32 = 1;
/// Simple greedy, then completion.
pub const CTR_QUAD_SIMPLE_GREEDY: u32 = 2;
/// Edmonds' matching on the whole dual graph.
pub const CTR_QUAD_MATCHING: u32 = 3;
/// Frink's reduction, Diks–Stańczyk strategy.
pub const CTR_QUAD_DIKS_STANCZYK: u32 = 4;
/// Frink's reduction, Biedl–Bose–Demaine–Lubiw strategy.
pub const CTR_QUAD_BBDL: u32 = 5;
/// Frink's reduction, link–cut cover-count strategy.
pub const CTR_QUAD_FRINK_LCT: u32 = 6;
/// Frink's reduction, naive DFS strategy (quadratic: refused above 100,000 faces per
/// component).
pub const CTR_QUAD_DS_NAIVE: u32 = 7;

/// Options of [`ctr_quadrangulate`]; start from [`ctr_quad_options_default`].
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_quad_options {
    /// `sizeof(ctr_quad_options)` as the caller was compiled.
    pub size: u32,
    /// One of `CTR_QUAD_*`.
    pub algorithm: u32,
    /// Seed of the randomised orders of the greedy algorithms (the library's documented
    /// random stream).
    pub seed: u64,
    /// Check every pairing independently (on by default); a failure is `CTR_FAILURE`
    /// with kind `unverified`.
    pub verify: bool,
}

/// The default options: LRS, seed 0, outputs verified.
#[no_mangle]
pub extern "C" fn ctr_quad_options_default() -> ctr_quad_options {
    ctr_quad_options {
        size: std::mem::size_of::<ctr_quad_options>() as u32,
        algorithm: CTR_QUAD_LRS,
        seed: 0,
        verify: true,
    }
}

/// What a conversion did (the totals over the components).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_quad_stats {
    /// `sizeof(ctr_quad_stats)` as the caller was compiled (set by
    /// [`ctr_quad_stats_default`]).
    pub size: u32,
    /// Triangles of the input.
    pub faces: u64,
    /// Quads of the output (half the triangles).
    pub quads: u64,
    /// Connected components.
    pub components: u64,
    /// χ of the input, summed over the components.
    pub euler_characteristic: i64,
    /// Whether every component is orientable.
    pub orientable: bool,
    /// Triangles the initial step left unpaired.
    pub initial_unpaired: u64,
    /// Edge flips (LRS only).
    pub flips: u64,
    /// Augmenting paths applied by the completion.
    pub augmenting_paths: u64,
}

/// A `ctr_quad_stats` of zeros with its `size` set.
#[no_mangle]
pub extern "C" fn ctr_quad_stats_default() -> ctr_quad_stats {
    ctr_quad_stats {
        size: std::mem::size_of::<ctr_quad_stats>() as u32,
        faces: 0,
        quads: 0,
        components: 0,
        euler_characteristic: 0,
        orientable: false,
        initial_unpaired: 0,
        flips: 0,
        augmenting_paths: 0,
    }
}

/// The result of [`ctr_quadrangulate`]: the quads, the paired triangulation, the pairs
/// and the statistics. Opaque; freed by [`ctr_quad_result_free`].
pub struct ctr_quad_result {
    mesh: QuadMesh,
    triangles: Vec<[u32; 3]>,
    pairs: Vec<[u32; 2]>,
    stats: ctr_quad_stats,
}

/// The algorithm named by `CTR_QUAD_*`.
pub(crate) fn algorithm(a: u32) -> Result<Algorithm, Failure> {
    Ok(match a {
        CTR_QUAD_LRS => Algorithm::Lrs,
        CTR_QUAD_PULLI_SEGAL => Algorithm::PulliSegal,
        CTR_QUAD_SIMPLE_GREEDY => Algorithm::SimpleGreedy,
        CTR_QUAD_MATCHING => Algorithm::Matching,
        CTR_QUAD_DIKS_STANCZYK => Algorithm::DiksStanczyk,
        CTR_QUAD_BBDL => Algorithm::BiedlBoseDemaineLubiw,
        CTR_QUAD_FRINK_LCT => Algorithm::FrinkLct,
        CTR_QUAD_DS_NAIVE => Algorithm::DsNaive,
        other => {
            return Err(Failure::argument(format!(
                "options->algorithm is {other}: one of CTR_QUAD_LRS (0) … CTR_QUAD_DS_NAIVE (7)"
            )))
        }
    })
}

/// Pairs the triangles of every component of the closed surface `mesh` into quads, as
/// `contractible::quadrangulate`: every triangle of the paired triangulation K (the
/// input's faces, except where LRS flipped an edge) in exactly one quad. NULL on
/// failure: `CTR_INPUT` for a mesh that is no closed surface (the first defect,
/// located) or an odd face count (kind `odd_faces`), `CTR_INVALID_ARGUMENT` for an
/// unknown algorithm.
///
/// # Safety
/// `mesh` is a live mesh; `options` is NULL (the defaults) or from
/// `ctr_quad_options_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_quadrangulate(
    mesh: *const ctr_mesh,
    options: *const ctr_quad_options,
    err: *mut ctr_error,
) -> *mut ctr_quad_result {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises a live mesh.
        let m = unsafe { object(mesh, "mesh") }?;
        // SAFETY: NULL or a valid options struct of its stated size.
        let o = unsafe { read_options(options, ctr_quad_options_default(), "options") }?;
        let options = QuadOptions {
            algorithm: algorithm(o.algorithm)?,
            seed: o.seed,
            verify: o.verify,
            ..QuadOptions::default()
        };
        let r: QuadResult =
            contractible::quadrangulate(m.view(), &options).map_err(Failure::from)?;
        let t = &r.totals;
        let mut stats = ctr_quad_stats_default();
        stats.faces = t.faces as u64;
        stats.quads = t.quads as u64;
        stats.components = r.components.len() as u64;
        stats.euler_characteristic = t.euler_characteristic;
        stats.orientable = t.orientable;
        stats.initial_unpaired = t.initial_unpaired as u64;
        stats.flips = t.flips as u64;
        stats.augmenting_paths = t.augmenting_paths as u64;
        Ok(Box::into_raw(Box::new(ctr_quad_result {
            mesh: r.mesh,
            triangles: r.triangles,
            pairs: r.pairs,
            stats,
        })))
    })
}

/// Writes `ptr.len()` to `count` when it is writable.
///
/// # Safety
/// `count` is NULL or points to a writable `size_t`.
unsafe fn set_count(count: *mut usize, n: usize) {
    if !count.is_null() && count.is_aligned() {
        // SAFETY: non-null, aligned, writable by the caller's promise.
        unsafe { count.write(n) };
    }
}

/// The quads, `4 * *count` vertex ids of the input (each quad the cycle around its two
/// triangles, so consistently oriented triangles give consistently oriented quads), per
/// component one quad per pair in increasing order of the pair's smaller face. NULL
/// (and `*count` 0) for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result; `count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn ctr_quad_result_quads(
    result: *const ctr_quad_result,
    count: *mut usize,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    let r = unsafe { object(result, "result") }.ok();
    // SAFETY: NULL or writable, by the caller's promise.
    unsafe { set_count(count, r.map_or(0, |r| r.mesh.faces.len())) };
    r.map_or(std::ptr::null(), |r| r.mesh.faces.as_ptr().cast::<u32>())
}

/// The paired triangulation K, `3 * *count` vertex ids, one row per input face: the
/// input's faces, except those LRS's flips changed. NULL (and `*count` 0) for a NULL
/// result.
///
/// # Safety
/// `result` is NULL or a live result; `count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn ctr_quad_result_triangles(
    result: *const ctr_quad_result,
    count: *mut usize,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    let r = unsafe { object(result, "result") }.ok();
    // SAFETY: NULL or writable, by the caller's promise.
    unsafe { set_count(count, r.map_or(0, |r| r.triangles.len())) };
    r.map_or(std::ptr::null(), |r| r.triangles.as_ptr().cast::<u32>())
}

/// The pairs, `2 * *count` rows of the triangulation K, in the order of the quads. NULL
/// (and `*count` 0) for a NULL result.
///
/// # Safety
/// `result` is NULL or a live result; `count` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn ctr_quad_result_pairs(
    result: *const ctr_quad_result,
    count: *mut usize,
) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    let r = unsafe { object(result, "result") }.ok();
    // SAFETY: NULL or writable, by the caller's promise.
    unsafe { set_count(count, r.map_or(0, |r| r.pairs.len())) };
    r.map_or(std::ptr::null(), |r| r.pairs.as_ptr().cast::<u32>())
}

/// Copies the statistics into `*out` (made by `ctr_quad_stats_default`): `CTR_OK`, or
/// `CTR_INVALID_ARGUMENT` for a NULL result or an `out` of another size.
///
/// # Safety
/// `result` is NULL or a live result; `out` points to a `ctr_quad_stats` from
/// `ctr_quad_stats_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_quad_result_stats(
    result: *const ctr_quad_result,
    out: *mut ctr_quad_stats,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: NULL or live, by the caller's promise.
        let r = unsafe { object(result, "result") }?;
        // SAFETY: the caller promises a `ctr_quad_stats` from its default function.
        *unsafe { sized_out(out, "ctr_quad_stats_default") }? = r.stats;
        Ok(())
    })
}

/// Writes the quad mesh (the input's vertices and positions, the quads) to a file in the
/// format of its extension (`.off`, `.obj`, `.ply`, optionally `.gz`; STL holds
/// triangles only and is refused), atomically. `CTR_OK` or the error's code.
///
/// # Safety
/// `result` is a live result; `path` a NUL-terminated UTF-8 string; `err` NULL or set up
/// by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_quad_result_write(
    result: *const ctr_quad_result,
    path: *const c_char,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: NULL or live, by the caller's promise.
        let r = unsafe { object(result, "result") }?;
        // SAFETY: the caller promises a NUL-terminated string.
        let p = unsafe { self::path(path) }?;
        contractible::io::write_mesh(p, &r.mesh).map_err(|e| {
            let mut f = Failure::from(contractible::Error::from(e));
            f.message = format!("{}: {}", p.display(), f.message);
            f
        })?;
        Ok(())
    })
}

/// Frees a result (NULL is ignored).
///
/// # Safety
/// `result` is NULL or a result of `ctr_quadrangulate` not freed yet.
#[no_mangle]
pub unsafe extern "C" fn ctr_quad_result_free(result: *mut ctr_quad_result) {
    if !result.is_null() {
        // SAFETY: made by Box::into_raw in ctr_quadrangulate, freed once.
        drop(unsafe { Box::from_raw(result) });
    }
}
