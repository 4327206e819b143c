//! The conformance checker for the tri-quad conversion (`contractible::check::quad`) on
//! the library's conversions, with and without their statements, and on edited ones:
//! never a panic; the library's answer passes; a passing verdict confirmed by the core
//! (see `contractible_fuzz::check_quad_check`).
#![no_main]
use contractible_fuzz::{check_quad_check, CheckQuadInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: CheckQuadInput| {
    check_quad_check(&input);
});
