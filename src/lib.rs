//! `contractible`: topology-preserving edge contraction on triangulated closed surfaces.
//!
//! The core ([`Triangulation`]) is a corner table over flat `u32` arrays that supports
//! orientable and non-orientable surfaces alike. On it: the link condition (two
//! independent implementations), contraction with exact undo, vertex splits and flips.
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod core;
pub mod diagnose;
pub mod dyngraph;
pub mod gen;
pub mod io;
pub mod irreducible;
pub mod mesh;
pub mod progress;
pub mod quad;
pub mod rng;
pub mod simplify;
pub mod spec;

pub use crate::core::topology;
pub use crate::core::{
    BuildError, Component, ConedComponent, ConedSurfaces, ContractError, ContractionRecord, Corner,
    Edge, EdgeId, EdgeNumbering, FaceId, FlipError, FlipRecord, History, Journal, LinkTester,
    SplitError, Surfaces, Triangulation, UndoError, ValidationError, VertexId,
};
pub use mesh::{Mesh, QuadMesh, TriMesh};
pub use topology::SurfaceType;
