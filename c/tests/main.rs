//! The C ABI's tests: the header against the sources, C programs compiled with the
//! system compiler (warnings as errors) against the static library and run, and the
//! seeds of the fuzz target `c_abi` replayed through its check.

mod c_programs;
mod fuzz_seeds;
mod header;

/// The fuzz harness library (`fuzz/src/lib.rs`), which `c_abi`'s check builds its meshes
/// with.
#[allow(dead_code)]
#[path = "../../fuzz/src/lib.rs"]
mod harness;

/// The check of the fuzz target `c_abi`.
#[path = "../../fuzz/src/c_abi.rs"]
mod c_abi;
