//! Deterministic generators of closed triangulated surfaces.
//!
//! Every generator returns a closed triangulated surface in the strict (simplicial)
//! sense: every edge in exactly two triangles, every vertex link a single cycle, no
//! duplicate or degenerate triangles, no parallel edges, every vertex used, one connected
//! component. Same inputs (and seed) give identical outputs.
//!
//! - [`standard`](tetrahedron): the small classics (T4, octahedron, icosahedron, the
//!   7-vertex torus, the 6-vertex projective plane, a 9-vertex Klein bottle);
//! - [`brick`](fn@brick): the RS paper's benchmark surfaces (Tables 3–5);
//! - [`subdivide`](fn@subdivide): 1-to-4 subdivision, to scale any input up;
//! - [`isosurface`](fn@isosurface): marching tetrahedra on implicit surfaces (sphere, torus, genus g,
//!   and the two-sheeted hyperboloid, which is *open*: the one generator whose output
//!   has boundary where the sampling box cuts it);
//! - [`random`](fn@random): random triangulations of any surface by vertex splits (a
//!   [`crate::Triangulation`], seeded by the documented [`crate::rng`]).

mod brick;
mod isosurface;
pub mod random;
mod standard;
mod subdivide;

pub use brick::{
    brick, brick_counts, brick_shape_counts, brick_shaped, brick_target_shape, brick_with_target,
    paper_entry, paper_family, paper_family_shape, BrickParams, BrickShape, PaperEntry,
    PAPER_TABLE,
};
pub use isosurface::{
    isosurface, large_hyperboloid, large_torus, paper_hyperboloid, paper_torus, Implicit, IsoError,
    IsoParams, Tessellation, CLAMP, MAX_GENUS,
};
pub use random::{random, seed_surface, RandomParams, SurfaceKind};
pub use standard::{icosahedron, klein_bottle, octahedron, projective_plane6, tetrahedron, torus7};
pub use subdivide::subdivide;

/// Why a generator produced nothing: the parameters ask for more than the 32-bit ids of
/// the core can hold, or the mesh given to transform is not what it needs.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum GenError {
    /// The output would have more vertices or faces than the core's ids hold
    /// ([`crate::core::MAX_VERTICES`], [`crate::core::MAX_FACES`]).
    #[error("{what}: {count} {unit} requested, at most {max} are supported")]
    TooLarge {
        /// Which generator.
        what: &'static str,
        /// `"faces"` or `"vertices"`.
        unit: &'static str,
        /// The count the parameters imply.
        count: u128,
        /// The most supported.
        max: usize,
    },
    /// A parameter is out of its range.
    #[error("{what}: {reason}")]
    BadParameter {
        /// Which generator.
        what: &'static str,
        /// What is wrong.
        reason: &'static str,
    },
    /// A face of the input mesh refers to a vertex outside `0..vertex_count`.
    #[error("face {face}: vertex index {vertex} out of range (vertex count {vertex_count})")]
    VertexOutOfRange {
        /// The face.
        face: usize,
        /// The index.
        vertex: u32,
        /// The mesh's vertex count.
        vertex_count: usize,
    },
    /// The input mesh's positions are not one per vertex.
    #[error("the mesh has {vertices} vertices but {positions} positions")]
    PositionCount {
        /// Vertex count.
        vertices: usize,
        /// Position count.
        positions: usize,
    },
}

impl GenError {
    /// `Ok` when `faces` and `vertices` fit the core's limits, else the
    /// [`GenError::TooLarge`] of `what` naming the first count that does not (faces
    /// first). Every generator checks its output's size with it before allocating.
    pub(crate) fn check_size(what: &'static str, faces: u128, vertices: u128) -> Result<(), Self> {
        use crate::core::{MAX_FACES, MAX_VERTICES};
        for (unit, count, max) in [
            ("faces", faces, MAX_FACES),
            ("vertices", vertices, MAX_VERTICES),
        ] {
            if count > max as u128 {
                return Err(GenError::TooLarge {
                    what,
                    unit,
                    count,
                    max,
                });
            }
        }
        Ok(())
    }
}
