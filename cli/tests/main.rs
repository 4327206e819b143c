//! Integration tests that run the `contractible` binary: one test target, so that the
//! test binary is linked once, not once per file. They read the repository's data
//! (`tests/data/`, the documents they rerun) from the workspace's root, and share
//! `tests/common` with the library's tests.

mod cli_common;
#[path = "../../tests/common/mod.rs"]
mod common;

mod cli_batch;
mod cli_boundary;
mod cli_check;
mod cli_conformance;
mod cli_decimate;
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
