//! `ctr_mesh`: a triangle mesh (positions optional), made from arrays or read from a
//! file, and written.

use std::borrow::Cow;
use std::ffi::c_char;

use contractible::mesh::TriMeshRef;
use contractible::TriMesh;

use crate::error::{ctr_error, guard, object, path, slice, status, Failure};

/// A triangle mesh: `vertex_count` vertices (with a position each, or none) and faces of
/// three vertex indices (0-based). Opaque: made by `ctr_mesh_new`, `ctr_mesh_borrow` or
/// `ctr_mesh_read` (or returned by a result's accessor, then owned by that result),
/// freed by `ctr_mesh_free`.
pub struct ctr_mesh {
    store: Store,
}

/// Where a mesh's arrays live.
enum Store {
    Owned(TriMesh),
    /// The caller's arrays, read in place (`ctr_mesh_borrow`): non-null, aligned, of
    /// the lengths stated, valid and unchanged until the mesh is freed.
    Borrowed {
        vertex_count: usize,
        positions: Option<(*const [f64; 3], usize)>,
        faces: *const [u32; 3],
        face_count: usize,
    },
}

impl ctr_mesh {
    /// A mesh that owns `mesh`.
    pub(crate) fn owned(mesh: TriMesh) -> Self {
        ctr_mesh {
            store: Store::Owned(mesh),
        }
    }

    /// The mesh's arrays, read in place.
    pub(crate) fn view(&self) -> TriMeshRef<'_> {
        match &self.store {
            Store::Owned(m) => m.into(),
            &Store::Borrowed {
                vertex_count,
                positions,
                faces,
                face_count,
            } => TriMeshRef {
                vertex_count,
                // SAFETY: `ctr_mesh_borrow` checked the pointers (non-null, aligned,
                // lengths that fit), and its caller promised the arrays valid and
                // unchanged until this mesh is freed, which outlives `&self`.
                positions: positions.map(|(p, n)| unsafe { std::slice::from_raw_parts(p, n) }),
                // SAFETY: as for the positions.
                faces: unsafe { std::slice::from_raw_parts(faces, face_count) },
            },
        }
    }

    /// The mesh as the tasks that take a `&TriMesh` read it: the owned mesh, or a copy
    /// of borrowed arrays.
    pub(crate) fn mesh(&self) -> Cow<'_, TriMesh> {
        match &self.store {
            Store::Owned(m) => Cow::Borrowed(m),
            Store::Borrowed { .. } => Cow::Owned(self.view().to_mesh()),
        }
    }
}

/// The caller's flat arrays as a borrowed mesh: `3 * vertex_count` coordinates (none for
/// NULL) and `3 * face_count` indices, refused when a count cannot exist or an array is
/// NULL or misaligned with a nonzero count.
///
/// # Safety
/// `positions` (when not NULL) and `faces` point to arrays of the stated lengths, valid
/// and unchanged for `'a`.
unsafe fn triples<'a>(
    positions: *const f64,
    vertex_count: usize,
    faces: *const u32,
    face_count: usize,
) -> Result<TriMeshRef<'a>, Failure> {
    let corners = face_count
        .checked_mul(3)
        .ok_or_else(|| Failure::argument(format!("{face_count} faces cannot exist")))?;
    // SAFETY: the caller promises `3 * face_count` readable indices.
    let f = unsafe { slice(faces, corners, "faces") }?;
    // SAFETY: `[u32; 3]` has `u32`'s alignment and three times its size: the checked
    // slice of `3 * face_count` indices is one of `face_count` triples.
    let f = unsafe { std::slice::from_raw_parts(f.as_ptr().cast::<[u32; 3]>(), face_count) };
    let mut mesh = TriMeshRef {
        vertex_count,
        positions: None,
        faces: f,
    };
    if positions.is_null() {
        return Ok(mesh);
    }
    let coords = vertex_count
        .checked_mul(3)
        .ok_or_else(|| Failure::argument(format!("{vertex_count} vertices cannot exist")))?;
    // SAFETY: the caller promises `3 * vertex_count` readable coordinates.
    let p = unsafe { slice(positions, coords, "positions") }?;
    // SAFETY: as for the faces, with `f64`.
    let p = unsafe { std::slice::from_raw_parts(p.as_ptr().cast::<[f64; 3]>(), vertex_count) };
    mesh.positions = Some(p);
    Ok(mesh)
}

/// A mesh from flat arrays, copied: `positions` holds `3 * vertex_count` coordinates
/// (x, y, z per vertex; NULL for a mesh without positions), `faces` holds `3 *
/// face_count` vertex indices. The faces are not checked here: each task checks them
/// and reports the first defect with its face or vertex. NULL on failure
/// (`CTR_INVALID_ARGUMENT` for a NULL or misaligned array with a nonzero count).
///
/// # Safety
/// `positions` (when not NULL) and `faces` point to arrays of the stated lengths; `err`
/// is NULL or a `ctr_error` set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_new(
    positions: *const f64,
    vertex_count: usize,
    faces: *const u32,
    face_count: usize,
    err: *mut ctr_error,
) -> *mut ctr_mesh {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises arrays of the stated lengths.
        let view = unsafe { triples(positions, vertex_count, faces, face_count) }?;
        Ok(Box::into_raw(Box::new(ctr_mesh::owned(view.to_mesh()))))
    })
}

/// A mesh over the caller's flat arrays, read in place: as `ctr_mesh_new` but without
/// the copy, for large meshes (the copy costs about a tenth of a `ctr_reduce` on 4 million
/// triangles). `ctr_reduce` and `ctr_quadrangulate` read the arrays where they are;
/// the other functions copy them for the call. The arrays must stay valid and
/// unchanged until the mesh is freed. NULL on failure (`CTR_INVALID_ARGUMENT` for a
/// NULL or misaligned array with a nonzero count).
///
/// # Safety
/// `positions` (when not NULL) and `faces` point to arrays of the stated lengths that
/// stay valid and unchanged until `ctr_mesh_free`; `err` is NULL or set up by
/// `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_borrow(
    positions: *const f64,
    vertex_count: usize,
    faces: *const u32,
    face_count: usize,
    err: *mut ctr_error,
) -> *mut ctr_mesh {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises arrays of the stated lengths.
        let view = unsafe { triples(positions, vertex_count, faces, face_count) }?;
        Ok(Box::into_raw(Box::new(ctr_mesh {
            store: Store::Borrowed {
                vertex_count,
                positions: view.positions.map(|p| (p.as_ptr(), p.len())),
                // An empty slice's pointer is dangling but aligned and non-null, as
                // `from_raw_parts` needs.
                faces: view.faces.as_ptr(),
                face_count,
            },
        })))
    })
}

/// The mesh of a file (`.off`, `.obj`, `.ply`, `.stl`, optionally gzip-compressed as
/// `.gz`; by the extension, else by the content): triangles only, as written. NULL on
/// failure: `CTR_INPUT` for a file that cannot be opened or parsed (kind `io` or
/// `read`, with its line when known).
///
/// # Safety
/// `path` is a NUL-terminated UTF-8 string; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_read(path: *const c_char, err: *mut ctr_error) -> *mut ctr_mesh {
    guard(err, std::ptr::null_mut(), || {
        // SAFETY: the caller promises a NUL-terminated string.
        let p = unsafe { self::path(path) }?;
        let mesh = contractible::io::read_tri_mesh(p)
            .map_err(|e| Failure::from(contractible::Error::from(e)))?;
        Ok(Box::into_raw(Box::new(ctr_mesh::owned(mesh))))
    })
}

/// Writes `mesh` to a file in the format of its extension (`.off`, `.obj`, `.ply`,
/// `.stl`, optionally `.gz`), atomically: on failure nothing is left at `path`. Returns
/// `CTR_OK` (0) or the error's code (`CTR_FAILURE` when the file cannot be written).
///
/// # Safety
/// `mesh` is a live mesh; `path` a NUL-terminated UTF-8 string; `err` NULL or set up by
/// `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_write(
    mesh: *const ctr_mesh,
    path: *const c_char,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: the caller promises a live mesh.
        let m = unsafe { object(mesh, "mesh") }?;
        // SAFETY: the caller promises a NUL-terminated string.
        let p = unsafe { self::path(path) }?;
        contractible::io::write_mesh(p, &m.mesh()).map_err(|e| {
            let mut f = Failure::from(contractible::Error::from(e));
            // The library's write errors do not name the file.
            f.message = format!("{}: {}", p.display(), f.message);
            f
        })?;
        Ok(())
    })
}

/// The number of vertices (0 for NULL).
///
/// # Safety
/// `mesh` is NULL or a live mesh.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_vertex_count(mesh: *const ctr_mesh) -> usize {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(mesh, "mesh") }.map_or(0, |m| m.view().vertex_count)
}

/// The number of faces (0 for NULL).
///
/// # Safety
/// `mesh` is NULL or a live mesh.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_face_count(mesh: *const ctr_mesh) -> usize {
    // SAFETY: NULL or live, by the caller's promise.
    unsafe { object(mesh, "mesh") }.map_or(0, |m| m.view().faces.len())
}

/// The positions, `3 * vertex_count` coordinates, or NULL when the mesh has none (or is
/// NULL). Valid until the mesh (or the result that owns it) is freed.
///
/// # Safety
/// `mesh` is NULL or a live mesh.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_positions(mesh: *const ctr_mesh) -> *const f64 {
    // SAFETY: NULL or live, by the caller's promise.
    match unsafe { object(mesh, "mesh") } {
        Ok(m) => m
            .view()
            .positions
            .map_or(std::ptr::null(), |p| p.as_ptr().cast::<f64>()),
        Err(_) => std::ptr::null(),
    }
}

/// The faces, `3 * face_count` vertex indices (NULL for a NULL mesh; a valid pointer to
/// nothing when there are no faces). Valid until the mesh (or the result that owns it)
/// is freed.
///
/// # Safety
/// `mesh` is NULL or a live mesh.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_faces(mesh: *const ctr_mesh) -> *const u32 {
    // SAFETY: NULL or live, by the caller's promise.
    match unsafe { object(mesh, "mesh") } {
        Ok(m) => m.view().faces.as_ptr().cast::<u32>(),
        Err(_) => std::ptr::null(),
    }
}

/// Frees a mesh made by `ctr_mesh_new`, `ctr_mesh_borrow` or `ctr_mesh_read` (NULL is
/// ignored; the arrays a borrowing mesh reads stay the caller's). A mesh a result owns is
/// freed with its result, not here.
///
/// # Safety
/// `mesh` is NULL or a mesh from `ctr_mesh_new`/`ctr_mesh_borrow`/`ctr_mesh_read` not
/// freed yet.
#[no_mangle]
pub unsafe extern "C" fn ctr_mesh_free(mesh: *mut ctr_mesh) {
    if !mesh.is_null() {
        // SAFETY: made by Box::into_raw in ctr_mesh_new/ctr_mesh_read, freed once.
        drop(unsafe { Box::from_raw(mesh) });
    }
}
