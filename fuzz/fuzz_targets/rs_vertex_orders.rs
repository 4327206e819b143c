//! RS on small surfaces under many vertex orders, checked by the oracles (the space in
//! which erratum E4 of spec/ERRATA.md showed; see `check_vertex_orders`).
#![no_main]
use contractible_fuzz::{check_vertex_orders, SurfaceInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: SurfaceInput| {
    check_vertex_orders(&input);
});
