//! Small classical triangulations of closed surfaces.
//!
//! Every function here returns a fixed mesh (no parameters, no randomness), in
//! constant time. Each output is a closed triangulated surface in the strict sense
//! (simplicial complex: every edge in exactly two triangles, every vertex link a single
//! cycle, no duplicate triangles or edges, connected). Orientable outputs are
//! consistently oriented.

use crate::mesh::TriMesh;

/// The boundary of a tetrahedron: a sphere.
///
/// V = 4, E = 6, F = 4, χ = 2, orientable (faces oriented outward). Positions are the
/// vertices of a regular tetrahedron inscribed in the cube `[-1, 1]^3`.
pub fn tetrahedron() -> TriMesh {
    let positions = vec![
        [1.0, 1.0, 1.0],
        [1.0, -1.0, -1.0],
        [-1.0, 1.0, -1.0],
        [-1.0, -1.0, 1.0],
    ];
    let faces = vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
    TriMesh::with_positions(positions, faces)
}

/// The boundary of an octahedron: a sphere.
///
/// V = 6, E = 12, F = 8, χ = 2, orientable (faces oriented outward). Vertices are
/// `±e_x` (0, 1), `±e_y` (2, 3), `±e_z` (4, 5).
pub fn octahedron() -> TriMesh {
    let positions = vec![
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
    ];
    let faces = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    TriMesh::with_positions(positions, faces)
}

/// The boundary of a regular icosahedron: a sphere.
///
/// V = 12, E = 30, F = 20, χ = 2, orientable (faces oriented outward). Positions are
/// the cyclic permutations of `(0, ±1, ±φ)` with φ the golden ratio.
pub fn icosahedron() -> TriMesh {
    let p = (1.0 + 5.0_f64.sqrt()) / 2.0;
    let positions = vec![
        [-1.0, p, 0.0],
        [1.0, p, 0.0],
        [-1.0, -p, 0.0],
        [1.0, -p, 0.0],
        [0.0, -1.0, p],
        [0.0, 1.0, p],
        [0.0, -1.0, -p],
        [0.0, 1.0, -p],
        [p, 0.0, -1.0],
        [p, 0.0, 1.0],
        [-p, 0.0, -1.0],
        [-p, 0.0, 1.0],
    ];
    let faces = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    TriMesh::with_positions(positions, faces)
}

/// The 7-vertex Möbius (Császár) torus, the unique minimal triangulation of the torus.
///
/// V = 7, E = 21, F = 14, χ = 0, orientable (consistently oriented). The vertices are
/// `Z/7`; the triangles are `{i, i+1, i+3}` and `{i, i+3, i+2}` for `i` in `0..7`
/// (faces `2i` and `2i + 1`). It is the quotient of the triangular lattice by the
/// sublattice spanned by `(1, 2)` and `(-3, 1)` (lattice point `(a, b)` has label
/// `a + 3b mod 7`), so the complete graph `K_7` is its edge graph.
///
/// Positions are given for visualisation only: vertex `i` sits at angles
/// `(2πi/7, -4πi/7)` on a torus of revolution with radii 2 and 1 (the torus map of the
/// lattice quotient). The straight triangles are *not* an embedding.
pub fn torus7() -> TriMesh {
    let mut faces = Vec::with_capacity(14);
    for i in 0..7u32 {
        faces.push([i, (i + 1) % 7, (i + 3) % 7]);
        faces.push([i, (i + 3) % 7, (i + 2) % 7]);
    }
    let positions = (0..7)
        .map(|i| {
            let theta = 2.0 * std::f64::consts::PI * f64::from(i) / 7.0;
            let phi = -4.0 * std::f64::consts::PI * f64::from(i) / 7.0;
            let rad = 2.0 + phi.cos();
            [rad * theta.cos(), rad * theta.sin(), phi.sin()]
        })
        .collect();
    TriMesh::with_positions(positions, faces)
}

/// The 6-vertex real projective plane RP²₆ (the hemi-icosahedron), its unique minimal
/// triangulation.
///
/// V = 6, E = 15, F = 10, χ = 1, non-orientable. Purely combinatorial (no positions:
/// RP² does not embed in R³). Its edge graph is the complete graph `K_6`; vertex 0's
/// link is the cycle `1 2 3 4 5`.
pub fn projective_plane6() -> TriMesh {
    let faces = vec![
        [0, 1, 2],
        [0, 2, 3],
        [0, 3, 4],
        [0, 4, 5],
        [0, 5, 1],
        [1, 2, 4],
        [2, 3, 5],
        [3, 4, 1],
        [4, 5, 2],
        [5, 1, 3],
    ];
    TriMesh::combinatorial(6, faces)
}

/// A 9-vertex Klein bottle: the 3×3 square grid with the identifications
/// `(i, j+3) ~ (i, j)` and `(3, j) ~ (0, -j mod 3)` (the twist), each square
/// `(i, j)..(i+1, j+1)` split along its `(i, j)–(i+1, j+1)` diagonal.
///
/// V = 9, E = 27, F = 18, χ = 0, non-orientable. Purely combinatorial (no positions:
/// the Klein bottle does not embed in R³). Vertex `(i, j)` has id `3i + j`; square
/// `(i, j)` gives faces `6i + 2j` and `6i + 2j + 1`. This triangulation is irreducible
/// (no edge can be contracted without leaving the class of simplicial surfaces); the
/// minimal Klein bottle has 8 vertices, but this one is the simplest to describe.
pub fn klein_bottle() -> TriMesh {
    const A: u32 = 3;
    const B: u32 = 3;
    let vid = |i: u32, j: u32| -> u32 {
        if i == A {
            (B - j % B) % B
        } else {
            i * B + j % B
        }
    };
    let mut faces = Vec::with_capacity(18);
    for i in 0..A {
        for j in 0..B {
            let p = vid(i, j);
            let q = vid(i + 1, j);
            let r = vid(i + 1, j + 1);
            let s = vid(i, j + 1);
            faces.push([p, q, r]);
            faces.push([p, r, s]);
        }
    }
    TriMesh::combinatorial(9, faces)
}
