//! Random surfaces by splits and flips, converted to quadrangulations by every tri-quad
//! algorithm (LRS, PS, SG, matching) with the input's seed, each result checked against
//! independent oracles (see `contractible_fuzz::check_quads`).
#![no_main]
use contractible_fuzz::{check_quads, SurfaceInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: SurfaceInput| {
    check_quads(&input);
});
