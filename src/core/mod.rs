//! The triangulation core: compact-index corner table, validation, local operations.
//!
//! One module per concern: [`ids`] (newtype indices), `tri` (the structure and its
//! traversals), `build` (construction and validation from face lists, components),
//! `boundary` (surfaces with boundary, closed by coning each loop to a virtual vertex),
//! `link` (the link condition, naive and marked), `contract` (contraction and its exact,
//! guarded undo), `collapse` (the simplifier's unrecorded operations), `split` (the general vertex split), `flip` (edge flips with exact
//! undo), `edge` (edge handles and dense edge numbers that survive changes), `journal`
//! (undo of interleaved contractions and flips), `validate`, [`topology`] (the
//! topological type of a surface), `to_mesh` (surfaces back to plain meshes).

/// Whether the executable specification's checks run (under `debug_assertions` or the
/// cargo feature `invariants`), the core's own self-checks among them. Defined here and
/// published as [`crate::spec::ENABLED`]: the specification's oracles read
/// triangulations, so the switch sits below them, in the core.
pub(crate) const CHECKS: bool = cfg!(any(debug_assertions, feature = "invariants"));

mod boundary;
mod build;
mod collapse;
mod contract;
mod edge;
mod flip;
pub mod ids;
mod journal;
mod link;
mod split;
mod to_mesh;
pub mod topology;
mod tri;
mod validate;

pub(crate) use boundary::ConedWhole;
pub use boundary::{ConedComponent, ConedSurfaces};
pub use build::{BuildError, Component, Surfaces};
pub use contract::{ContractError, ContractionRecord, History, UndoError};
pub use edge::{Edge, EdgeId, EdgeIds, EdgeNumbering};
pub use flip::{FlipError, FlipRecord};
pub use ids::{Corner, FaceId, VertexId, MAX_FACES, MAX_VERTICES};
pub use journal::{Journal, Op};
pub use link::LinkTester;
pub use split::SplitError;
pub use topology::{SurfaceKind, SurfaceType};
pub use tri::{Star, StarStep, StateStamp, Triangulation};
pub use validate::{GluingProblem, LinkProblem, ValidationError};
