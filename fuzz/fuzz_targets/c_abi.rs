//! The C interface on arbitrary meshes and raw option values: the same outcomes as the
//! Rust calls, bit for bit, never an internal error, and the C checkers pass every
//! output (see `fuzz/src/c_abi.rs`).
#![no_main]
use contractible_fuzz as harness;
use libfuzzer_sys::fuzz_target;

#[path = "../src/c_abi.rs"]
mod c_abi;

fuzz_target!(|input: c_abi::CAbiInput| {
    c_abi::check_c_abi(&input);
});
