//! Random surfaces (closed or opened, orientable or not, one or two components, unused
//! vertices beside them) with degenerate and extreme positions, decimated with random
//! targets, caps, placements, guard and locks; every refusal of the documented kind,
//! every output checked from its face lists and maps by the harness (see
//! `contractible_fuzz::check_decimate_input`).
#![no_main]
use contractible_fuzz::{check_decimate_input, DecimateInput};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|input: DecimateInput| {
    check_decimate_input(&input);
});
