//! The conformance checker for `decimate` (`contractible::check::decimate`) on the
//! library's own decimations, with and without their maps, and on edited answers:
//! never a panic; the library's answer passes; a passing verdict confirmed by the core
//! (see `contractible_fuzz::check_decimate_check`).
#![no_main]
use contractible_fuzz::{check_decimate_check, CheckDecimateInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: CheckDecimateInput| {
    check_decimate_check(&input);
});
