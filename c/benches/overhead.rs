//! The C interface's cost over the Rust call: `reduce` on B0 (the RS paper's largest
//! genus-0 brick, 4,193,392 triangles) through `contractible::reduce`, and through the C
//! ABI as a C program calls it (a mesh over its flat arrays, `ctr_reduce`, reading the
//! output's arrays, both freed): with `ctr_mesh_borrow` (the arrays read in place) and
//! with `ctr_mesh_new` (copied first). All in one run, so the ratios of the medians are
//! like-for-like; docs/c.md quotes them.
//!
//! Run: `cargo bench -p contractible-c --bench overhead`. Divan reports medians.

use contractible::{ReduceOptions, TriMesh};
use contractible_c::*;
use std::sync::OnceLock;

fn main() {
    divan::main();
}

fn b0() -> &'static TriMesh {
    static MESH: OnceLock<TriMesh> = OnceLock::new();
    MESH.get_or_init(|| contractible::gen::paper_family('B', 0).expect("B0"))
}

/// B0 as the flat arrays a C caller holds (made once, outside the timed calls).
fn flat() -> &'static (Vec<f64>, Vec<u32>) {
    static FLAT: OnceLock<(Vec<f64>, Vec<u32>)> = OnceLock::new();
    FLAT.get_or_init(|| {
        let m = b0();
        let p = m.positions.as_ref().expect("positions");
        (
            p.iter().flatten().copied().collect(),
            m.faces.iter().flatten().copied().collect(),
        )
    })
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn rust_reduce() -> usize {
    let r = contractible::reduce(
        b0(),
        &ReduceOptions {
            keep_history: false,
            ..ReduceOptions::default()
        },
    )
    .expect("reduces");
    r.mesh.faces.len()
}

/// `ctr_reduce` on a mesh made by `make` over B0's flat arrays.
fn c_reduce(
    make: unsafe extern "C" fn(
        *const f64,
        usize,
        *const u32,
        usize,
        *mut ctr_error,
    ) -> *mut ctr_mesh,
) -> usize {
    let m = b0();
    let (positions, faces) = flat();
    // SAFETY: the arrays have the stated lengths and outlive the calls (a borrowing mesh
    // is freed before them); every handle is freed once.
    unsafe {
        let mut err = std::mem::MaybeUninit::<ctr_error>::uninit();
        ctr_error_init(err.as_mut_ptr());
        let err = err.as_mut_ptr();
        let mesh = make(
            positions.as_ptr(),
            m.vertex_count,
            faces.as_ptr(),
            m.faces.len(),
            err,
        );
        let r = ctr_reduce(mesh, std::ptr::null(), err);
        let out = ctr_reduce_result_mesh(r);
        let n = ctr_mesh_face_count(out);
        divan::black_box(ctr_mesh_faces(out));
        ctr_reduce_result_free(r);
        ctr_mesh_free(mesh);
        n
    }
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn c_reduce_borrowed() -> usize {
    c_reduce(ctr_mesh_borrow)
}

#[divan::bench(sample_count = 10, sample_size = 1)]
fn c_reduce_copied() -> usize {
    c_reduce(ctr_mesh_new)
}
