//! What the maintenance tools (`src/bin/`) share: the repository's root, where they read
//! the test data and write the conformance vectors, the CPU time of the calling thread,
//! which means more than wall time on a shared machine, and the topology of a mesh's
//! components as the vectors record it; and the command line's shell completions and man
//! pages as files ([`shell_files`]).
#![deny(unsafe_code)]
#![warn(missing_docs)]

use std::path::PathBuf;

// The algorithm tests report CPU time with the same function.
#[path = "../../tests/common/cpu.rs"]
mod cpu_time;

pub use cpu_time::cpu;

pub mod shell_files;

/// The root of the repository this package sits in (the parent of `tools/`).
pub fn repo_root() -> PathBuf {
    let tools = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    tools.parent().map_or(tools.clone(), PathBuf::from)
}

/// Per component of `mesh` (closed or with boundary), its Euler characteristic,
/// orientability and number of boundary loops, sorted; `None` if the faces are not a
/// union of surfaces.
pub fn component_topology(mesh: &contractible::TriMesh) -> Option<Vec<(i64, bool, usize)>> {
    let surfaces = contractible::ConedSurfaces::from_mesh(mesh).ok()?;
    let mut c: Vec<(i64, bool, usize)> = surfaces
        .components
        .iter()
        .map(|s| {
            let t = s.surface_type();
            (
                t.euler_characteristic(),
                t.is_orientable(),
                t.boundary_loops(),
            )
        })
        .collect();
    c.sort_unstable();
    Some(c)
}
