//! Random surfaces by splits and flips, then RS, Schipper and brute force checked against
//! independent oracles (see `contractible_fuzz::check_reductions`).
#![no_main]
use contractible_fuzz::{check_reductions, SurfaceInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: SurfaceInput| {
    check_reductions(&input);
});
