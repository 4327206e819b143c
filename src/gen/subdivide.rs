//! Loop-style 1-to-4 midpoint subdivision (topology only; no smoothing).

use super::GenError;
use crate::mesh::TriMesh;

/// Numbers the undirected edges of `faces` in order of first appearance.
///
/// Faces are scanned in order and each face `[a, b, c]` contributes its edges
/// `(a, b), (b, c), (c, a)` in that order; the first time an edge is seen it gets the
/// next id. Returns, for each face, the ids of its three edges in that order, and the
/// number of distinct edges. The edge of each face is looked up in a compressed
/// per-vertex adjacency (CSR) bucket of its smaller endpoint, so the cost is
/// `O(F + Σ_v d_v²)` with `d_v` the number of edges whose smaller endpoint is `v`
/// (linear for bounded degree), and no hashing or sorting.
fn number_edges(vertex_count: usize, faces: &[[u32; 3]]) -> (Vec<[u32; 3]>, usize) {
    // Bucket sizes: an upper bound (each face side counted once) on the number of
    // distinct edges whose smaller endpoint is v.
    let mut start = vec![0u32; vertex_count + 1];
    for f in faces {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            start[a.min(b) as usize + 1] += 1;
        }
    }
    for v in 0..vertex_count {
        start[v + 1] += start[v];
    }
    let mut fill = vec![0u32; vertex_count];
    let mut other = vec![0u32; 3 * faces.len()];
    let mut id = vec![0u32; 3 * faces.len()];
    let mut next = 0u32;
    let mut face_edges = Vec::with_capacity(faces.len());
    for f in faces {
        let mut e = [0u32; 3];
        for (k, slot) in e.iter_mut().enumerate() {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            let (lo, hi) = (a.min(b) as usize, a.max(b));
            let s = start[lo] as usize;
            let n = fill[lo] as usize;
            *slot = match other[s..s + n].iter().position(|&o| o == hi) {
                Some(p) => id[s + p],
                None => {
                    other[s + n] = hi;
                    id[s + n] = next;
                    fill[lo] += 1;
                    next += 1;
                    next - 1
                }
            };
        }
        face_edges.push(e);
    }
    (face_edges, next as usize)
}

/// Applies `levels` rounds of 1-to-4 midpoint subdivision.
///
/// One round maps a mesh with `V` vertices, `E` distinct edges and `F` faces to one with
/// `V' = V + E`, `F' = 4F` and (on a closed surface) `E' = 2E + 3F`. On a closed
/// triangulated surface the result is a closed triangulated surface of the same
/// topology (Euler characteristic and orientability preserved; a consistent
/// orientation is preserved). Works on any triangle mesh (no surface requirement); a
/// face with a repeated corner produces degenerate children.
///
/// Numbering (per round): original vertices keep their ids; the vertex of the `e`-th
/// distinct edge is `V + e`, edges numbered by first appearance scanning faces in order
/// and each face `[a, b, c]`'s edges in the order `(a, b), (b, c), (c, a)`. With `ab`,
/// `bc`, `ca` the midpoint vertices, face `i` becomes faces `4i..4i+4`:
/// `[a, ab, ca]`, `[ab, b, bc]`, `[ca, bc, c]`, `[ab, bc, ca]` (all with the parent's
/// orientation). A midpoint's position is the average of its edge's endpoints when
/// positions exist. `levels = 0` returns a copy.
///
/// Complexity: `O(F_out)` time and memory for bounded vertex degree (see the edge
/// numbering, which uses per-vertex CSR buckets; no hashing, no sorting).
///
/// # Errors
/// [`GenError::VertexOutOfRange`] if a face refers to a vertex `>= vertex_count`,
/// [`GenError::PositionCount`] if the positions are not one per vertex, and
/// [`GenError::TooLarge`] if the output would have more faces or vertices than the
/// core holds (checked before anything is allocated: faces grow 4× per level).
pub fn subdivide(mesh: &TriMesh, levels: u32) -> Result<TriMesh, GenError> {
    for (face, f) in mesh.faces.iter().enumerate() {
        if let Some(&vertex) = f.iter().find(|&&v| v as usize >= mesh.vertex_count) {
            return Err(GenError::VertexOutOfRange {
                face,
                vertex,
                vertex_count: mesh.vertex_count,
            });
        }
    }
    if let Some(p) = &mesh.positions {
        if p.len() != mesh.vertex_count {
            return Err(GenError::PositionCount {
                vertices: mesh.vertex_count,
                positions: p.len(),
            });
        }
    }
    // F·4^L faces and at most V + F·(4^L − 1) vertices: level i adds one vertex per edge,
    // at most 3·F·4^i, and these sum to F·(4^L − 1) over the L levels.
    let growth = 4u128.checked_pow(levels).unwrap_or(u128::MAX);
    let faces = (mesh.faces.len() as u128).saturating_mul(growth);
    let vertices = (mesh.vertex_count as u128).saturating_add(faces);
    GenError::check_size("subdivide", faces, vertices)?;
    let mut cur = mesh.clone();
    for _ in 0..levels {
        cur = subdivide_once(&cur);
    }
    Ok(cur)
}

/// One level; the caller checked every index and that the output's ids fit `u32`.
fn subdivide_once(mesh: &TriMesh) -> TriMesh {
    let v = mesh.vertex_count;
    let (face_edges, edge_count) = number_edges(v, &mesh.faces);
    let base = v as u32;
    let mut faces = Vec::with_capacity(4 * mesh.faces.len());
    for (f, e) in mesh.faces.iter().zip(&face_edges) {
        let [a, b, c] = *f;
        let (ab, bc, ca) = (base + e[0], base + e[1], base + e[2]);
        faces.push([a, ab, ca]);
        faces.push([ab, b, bc]);
        faces.push([ca, bc, c]);
        faces.push([ab, bc, ca]);
    }
    let positions = mesh.positions.as_ref().map(|pos| {
        let mut out = Vec::with_capacity(v + edge_count);
        out.extend_from_slice(pos);
        out.resize(v + edge_count, [0.0; 3]);
        for (f, e) in mesh.faces.iter().zip(&face_edges) {
            for k in 0..3 {
                let (p, q) = (pos[f[k] as usize], pos[f[(k + 1) % 3] as usize]);
                out[v + e[k] as usize] = [
                    0.5 * (p[0] + q[0]),
                    0.5 * (p[1] + q[1]),
                    0.5 * (p[2] + q[2]),
                ];
            }
        }
        out
    });
    TriMesh {
        vertex_count: v + edge_count,
        positions,
        faces,
    }
}
