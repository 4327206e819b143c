//! The triangulation core: compact-index corner table, validation, local operations.
//!
//! One module per concern: [`ids`] (newtype indices), `tri` (the structure and its
//! traversals), `build` (construction and validation from face lists, components),
//! `link` (the link condition, naive and marked), `contract` (contraction and its exact
//! undo), `split` (the general vertex split), `flip` (edge flips), `validate`.

mod build;
mod contract;
mod flip;
pub mod ids;
mod link;
mod split;
mod tri;
mod validate;

pub use build::{BuildError, Component, Surfaces};
pub use contract::{ContractError, ContractionRecord, History};
pub use flip::FlipError;
pub use ids::{Corner, FaceId, VertexId, MAX_FACES, MAX_VERTICES};
pub use link::LinkTester;
pub use split::SplitError;
pub use tri::{Star, StarStep, Triangulation};
pub use validate::ValidationError;
