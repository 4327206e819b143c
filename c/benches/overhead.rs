//! The C interface's cost over the Rust call: `reduce` on B0 (the RS paper's largest
//! genus-0 brick, 4,193,392 triangles) through `contractible::reduce`, and through the C
//! ABI as a C program calls it (`ctr_mesh_new` copying the flat arrays, `ctr_reduce`,
//! reading the output's arrays, both freed). Both in one run, so the ratio of the medians
//! is like-for-like; docs/c.md quotes it.
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

#[divan::bench(sample_count = 10, sample_size = 1)]
fn c_reduce() -> usize {
    let m = b0();
    let (positions, faces) = flat();
    // SAFETY: the arrays have the stated lengths and outlive the calls; every handle is
    // freed once.
    unsafe {
        let mut err = std::mem::MaybeUninit::<ctr_error>::uninit();
        ctr_error_init(err.as_mut_ptr());
        let err = err.as_mut_ptr();
        let mesh = ctr_mesh_new(
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
