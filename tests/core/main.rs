//! Integration tests of the core, I/O and generators, the bounded exhaustive tests of
//! the Kani harnesses and the fuzz regressions. One test target per area, so that the test
//! binaries are linked once, not once per file.

#[path = "../common/mod.rs"]
mod common;

// The Kani harnesses refer to `crate::surfaces`, so both files sit at the crate root.
#[path = "../../proofs/harnesses.rs"]
mod harnesses;
#[path = "../../proofs/surfaces.rs"]
mod surfaces;

mod build_oracle;
mod core_boundary;
mod core_meshes;
mod core_ops;
mod fuzz_regressions;
mod gen_surfaces;
mod interleave;
mod io_formats;
mod isosurface;
mod module_graph;
mod no_panic;
mod proofs;
mod properties;
