//! Seeded, deterministic generators of closed triangulated surfaces.

pub mod random;

pub use random::{random, seed_surface, RandomParams, SurfaceKind};
