//! Plain indexed polygon meshes: what files hold and generators produce.
//!
//! A [`Mesh`] is *data*, not a surface: it may be a soup, have unused vertices, several
//! components or non-manifold edges. [`crate::Triangulation`] is built from a
//! [`TriMesh`] after full validation; the writers take a [`TriMesh`] or a [`QuadMesh`].

/// An indexed mesh whose faces all have `N` corners (`N = 3`: triangles, `N = 4`: quads).
///
/// Guarantees nothing beyond its field types; validation happens when a
/// [`crate::Triangulation`] is built from it. Indices are 0-based into `0..vertex_count`.
#[derive(Clone, Debug, PartialEq)]
pub struct Mesh<const N: usize> {
    /// Number of vertices (the length of `positions` when positions are present).
    pub vertex_count: usize,
    /// Vertex coordinates, if the source has any. The combinatorial algorithms need none.
    pub positions: Option<Vec<[f64; 3]>>,
    /// Faces as vertex indices, in file order.
    pub faces: Vec<[u32; N]>,
}

/// A triangle mesh.
pub type TriMesh = Mesh<3>;
/// A quadrilateral mesh (the output of the tri-quad conversion).
pub type QuadMesh = Mesh<4>;

impl<const N: usize> Mesh<N> {
    /// A mesh with positions; `vertex_count` is `positions.len()`.
    pub fn with_positions(positions: Vec<[f64; 3]>, faces: Vec<[u32; N]>) -> Self {
        Mesh {
            vertex_count: positions.len(),
            positions: Some(positions),
            faces,
        }
    }

    /// A purely combinatorial mesh on `vertex_count` vertices.
    pub fn combinatorial(vertex_count: usize, faces: Vec<[u32; N]>) -> Self {
        Mesh {
            vertex_count,
            positions: None,
            faces,
        }
    }
}
