//! Integration tests of the irreducible-triangulation algorithms: outputs, the RS
//! specification and its variants, independent oracles and the conformance vectors. One
//! test target per area, so that the test binaries are linked once, not once per file.

#[path = "../common/mod.rs"]
mod common;

// CPU time of the calling thread, shared with the profiling tools (tools/).
#[path = "../common/cpu.rs"]
mod cpu;

// The fuzz harness (`fuzz/src/lib.rs`): the quad tests reuse its checks.
#[allow(dead_code)]
#[path = "../../fuzz/src/lib.rs"]
mod harness;

mod closed_inputs;
mod decimate;
mod decimate_vectors;
mod irreducible_algorithms;
mod irreducible_meshes;
mod iso_vectors;
mod oracles;
mod progress;
mod quad_augment;
mod quad_convert;
mod quad_frink;
mod quad_greedy;
mod quad_lrs;
mod quad_qbench;
mod quad_qfuzz;
mod rs_algorithm;
mod rs_variants;
mod simplify;
mod simplify_vectors;
mod tasks;
mod vectors;
