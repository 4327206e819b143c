//! Integration tests that run the `contractible` binary (needs the `cli` feature). One
//! test target per area, so that the test binaries are linked once, not once per file.

mod cli_common;
#[path = "../common/mod.rs"]
mod common;

mod cli_batch;
mod cli_boundary;
mod cli_docs;
mod cli_gen;
mod cli_info;
mod cli_input;
mod cli_invalid;
mod cli_iso;
mod cli_output;
mod cli_quad;
mod cli_reduce;
mod cli_simplify;
mod cli_stl;
