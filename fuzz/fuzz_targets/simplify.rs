//! Random surfaces (closed, or opened by removing vertex-disjoint faces) with random
//! positions, ε and options, simplified in both modes; every output checked by the
//! harness's independent topology checker and accounting (see
//! `contractible_fuzz::check_simplify_input`).
#![no_main]
use contractible_fuzz::{check_simplify_input, SimplifyInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: SimplifyInput| {
    check_simplify_input(&input);
});
