//! Deterministic generators of closed triangulated surfaces.
//!
//! Every generator returns a [`crate::mesh::TriMesh`] that is a closed triangulated
//! surface in the strict (simplicial) sense: every edge in exactly two triangles, every
//! vertex link a single cycle, no duplicate or degenerate triangles, no parallel edges,
//! every vertex used, one connected component. Same inputs give identical outputs.

mod brick;
mod standard;
mod subdivide;

pub use brick::{
    brick, brick_counts, brick_shape_counts, brick_shaped, brick_target_shape, brick_with_target,
    paper_entry, paper_family, paper_family_shape, BrickParams, BrickShape, PaperEntry,
    PAPER_TABLE,
};
pub use standard::{icosahedron, klein_bottle, octahedron, projective_plane6, tetrahedron, torus7};
pub use subdivide::subdivide;
