//! `ctr_describe`: what surface a mesh is.

use contractible::task::Description;

use crate::error::{ctr_error, object, sized_out, status, Failure};
use crate::mesh::ctr_mesh;

/// What `ctr_describe` finds: counts and topology summed over the components.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ctr_description {
    /// `sizeof(ctr_description)` as the caller was compiled (set by
    /// `ctr_description_default`); no byte past it is written.
    pub size: u32,
    /// Connected components.
    pub components: u32,
    /// Whether every component is closed (no boundary loop).
    pub closed: bool,
    /// Whether every component is orientable.
    pub orientable: bool,
    /// Vertices the faces use.
    pub vertices: u64,
    /// Edges.
    pub edges: u64,
    /// Faces.
    pub faces: u64,
    /// Vertices no face uses.
    pub dropped_vertices: u64,
    /// χ, summed over the components.
    pub euler_characteristic: i64,
    /// Boundary loops, summed over the components.
    pub boundary_loops: u64,
}

/// A `ctr_description` of zeros with its `size` set: pass it to `ctr_describe`.
#[no_mangle]
pub extern "C" fn ctr_description_default() -> ctr_description {
    ctr_description {
        size: std::mem::size_of::<ctr_description>() as u32,
        components: 0,
        closed: false,
        orientable: false,
        vertices: 0,
        edges: 0,
        faces: 0,
        dropped_vertices: 0,
        euler_characteristic: 0,
        boundary_loops: 0,
    }
}

/// Describes `mesh` into `*out`: `CTR_OK` (0) when its faces form a union of surfaces
/// (closed or with boundary, orientable or not); otherwise `CTR_INPUT` with the first
/// problem the validation meets in `err` (its kind, such as `non_manifold_edge`, and its
/// face or vertex) and `*out` untouched.
///
/// # Safety
/// `mesh` is a live mesh; `out` points to a `ctr_description` from
/// `ctr_description_default`; `err` is NULL or set up by `ctr_error_init`.
#[no_mangle]
pub unsafe extern "C" fn ctr_describe(
    mesh: *const ctr_mesh,
    out: *mut ctr_description,
    err: *mut ctr_error,
) -> i32 {
    status(err, || {
        // SAFETY: the caller promises a live mesh.
        let m = unsafe { object(mesh, "mesh") }?;
        // SAFETY: the caller promises a `ctr_description` from its default function.
        let out = unsafe { sized_out(out, "ctr_description_default") }?;
        let d = contractible::describe(&m.mesh()).map_err(Failure::from)?;
        let (components, dropped) = match d {
            Description::Surfaces {
                components,
                dropped_vertices,
            } => (components, dropped_vertices),
            Description::Problems { first, .. } => {
                return Err(Failure::from(contractible::Error::Mesh(first)));
            }
        };
        let mut v = ctr_description_default();
        v.components = components.len() as u32;
        v.closed = components.iter().all(|c| c.surface.is_closed());
        v.orientable = components.iter().all(|c| c.surface.is_orientable());
        v.vertices = components.iter().map(|c| c.vertices as u64).sum();
        v.edges = components.iter().map(|c| c.edges as u64).sum();
        v.faces = components.iter().map(|c| c.faces as u64).sum();
        v.dropped_vertices = dropped as u64;
        v.euler_characteristic = components
            .iter()
            .map(|c| c.surface.euler_characteristic())
            .sum();
        v.boundary_loops = components
            .iter()
            .map(|c| c.surface.boundary_loops() as u64)
            .sum();
        *out = v;
        Ok(())
    })
}
