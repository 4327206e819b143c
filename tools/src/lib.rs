//! What the maintenance tools (`src/bin/`) share: the repository's root, where they read
//! the test data and write the conformance vectors, and the CPU time of the calling
//! thread, which means more than wall time on a shared machine.
#![deny(unsafe_code)]
#![warn(missing_docs)]

use std::path::PathBuf;

// The algorithm tests report CPU time with the same function.
#[path = "../../tests/common/cpu.rs"]
mod cpu_time;

pub use cpu_time::cpu;

/// The root of the repository this package sits in (the parent of `tools/`).
pub fn repo_root() -> PathBuf {
    let tools = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    tools.parent().map_or(tools.clone(), PathBuf::from)
}
