//! Hunts for erratum E4 (spec/ERRATA.md): RS with the printed `until lue = ∅` loop exit
//! must still give an irreducible triangulation; a crash here is evidence for E4.
#![no_main]
use contractible_fuzz::{check_printed_loop_exit, SurfaceInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: SurfaceInput| {
    check_printed_loop_exit(&input);
});
