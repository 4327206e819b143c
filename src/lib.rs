//! `contractible`: topology-preserving edge contraction on triangulated closed surfaces.
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod gen;
pub mod io;
pub mod mesh;

pub use mesh::{Mesh, QuadMesh, TriMesh};
