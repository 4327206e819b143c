//! Plain indexed polygon meshes: what files hold and generators produce.
//!
//! A [`Mesh`] is *data*, not a surface: it may be a soup, have unused vertices, several
//! components or non-manifold edges. [`crate::Triangulation`] is built from a
//! [`TriMesh`] after full validation; the writers take a [`TriMesh`] or a [`QuadMesh`].
//!
//! The conversions between meshes live here, written once for the command line, the
//! examples and library users: [`Mesh::compacted`] (drop unused vertices),
//! [`Mesh::welded`] (merge vertices at bitwise-equal positions, as STL needs) and
//! [`Mesh::welded_within`] (within a distance). This module knows no surface: the core
//! builds from a mesh and converts back (its module `to_mesh`:
//! [`crate::Triangulation::to_mesh`], [`crate::Component::carry`],
//! [`crate::Component::to_mesh`], [`TriMesh::reassemble`]).

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

/// A borrowed indexed mesh: the fields of a [`Mesh`] as slices, so arrays a caller
/// already holds (a C program's flat arrays, another library's buffers) are read in
/// place. The tasks that take `impl Into<TriMeshRef>` ([`crate::reduce`],
/// [`crate::quadrangulate`]) accept a `&TriMesh` or one of these, with the same results.
///
/// # Example
/// ```
/// use contractible::mesh::TriMeshRef;
/// let octahedron = contractible::gen::octahedron();
/// let view = TriMeshRef {
///     vertex_count: 6,
///     positions: octahedron.positions.as_deref(),
///     faces: &octahedron.faces,
/// };
/// let r = contractible::reduce(view, &Default::default())?;
/// assert_eq!(r.mesh.faces.len(), 4);
/// assert_eq!(view.to_mesh(), octahedron);
/// # Ok::<(), contractible::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshRef<'a, const N: usize> {
    /// Number of vertices (the length of `positions` when positions are present).
    pub vertex_count: usize,
    /// Vertex coordinates, if any.
    pub positions: Option<&'a [[f64; 3]]>,
    /// Faces as vertex indices.
    pub faces: &'a [[u32; N]],
}

/// A borrowed triangle mesh.
pub type TriMeshRef<'a> = MeshRef<'a, 3>;

impl<const N: usize> MeshRef<'_, N> {
    /// The owned mesh with the same fields (copies the slices).
    pub fn to_mesh(&self) -> Mesh<N> {
        Mesh {
            vertex_count: self.vertex_count,
            positions: self.positions.map(<[_]>::to_vec),
            faces: self.faces.to_vec(),
        }
    }
}

impl<'a, const N: usize> From<&'a Mesh<N>> for MeshRef<'a, N> {
    fn from(m: &'a Mesh<N>) -> Self {
        MeshRef {
            vertex_count: m.vertex_count,
            positions: m.positions.as_deref(),
            faces: &m.faces,
        }
    }
}

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

impl<const N: usize> Mesh<N> {
    /// The mesh restricted to the vertices its faces use, renumbered `0..k` in increasing
    /// index order (so relative order is kept), with the positions of the kept vertices
    /// and the faces in the same order; and the number of vertices dropped.
    ///
    /// `None` if a face refers to a vertex `>= vertex_count` or `positions` has a length
    /// other than `vertex_count`. O(V + F).
    pub fn compacted(&self) -> Option<(Self, usize)> {
        const UNUSED: u32 = u32::MAX;
        if self
            .positions
            .as_ref()
            .is_some_and(|p| p.len() != self.vertex_count)
        {
            return None;
        }
        let mut new_id = vec![UNUSED; self.vertex_count];
        for f in &self.faces {
            for &v in f {
                *new_id.get_mut(v as usize)? = 0;
            }
        }
        let mut kept = 0usize;
        let mut positions = self.positions.as_ref().map(|_| Vec::new());
        for (v, id) in new_id.iter_mut().enumerate() {
            if *id != UNUSED {
                // At most one new id per distinct u32 face index, so `kept` fits a u32.
                *id = kept as u32;
                kept += 1;
                if let (Some(out), Some(p)) = (&mut positions, &self.positions) {
                    out.push(p[v]);
                }
            }
        }
        let faces = self
            .faces
            .iter()
            .map(|f| f.map(|v| new_id[v as usize]))
            .collect();
        let mesh = Mesh {
            vertex_count: kept,
            positions,
            faces,
        };
        Some((mesh, self.vertex_count - kept))
    }
}

impl<const N: usize> Mesh<N> {
    /// The mesh with vertices at bitwise-equal positions merged (all three coordinates
    /// equal bit for bit, so `0.0` and `-0.0` stay apart and NaNs merge only with the
    /// same NaN), and the number of vertices merged away.
    ///
    /// Deterministic: each group of equal positions becomes the vertex of its first
    /// occurrence (lowest index); the kept vertices keep their relative order, renumbered
    /// `0..k`; faces keep their order with their corners mapped (a face whose corners
    /// merge keeps the repeated vertex, for validation to report). Unused vertices are
    /// kept. A mesh without positions is returned unchanged with a count of 0.
    ///
    /// `None` if a face refers to a vertex `>= vertex_count` or `positions` has a length
    /// other than `vertex_count`. O(V + F) expected (hashing).
    pub fn welded(&self) -> Option<(Self, usize)> {
        self.welded_within(0.0)
    }

    /// [`Self::welded`] with a distance: with `tolerance > 0`, vertices closer than or
    /// at `tolerance` (Euclidean) are merged, transitively (a chain of close vertices
    /// becomes one vertex even if its ends are farther apart); `tolerance == 0` is
    /// exactly [`Self::welded`] (bitwise-equal positions). See [`weld_map`] for the
    /// rule and its cost.
    ///
    /// Deterministic: each group becomes its lowest-index vertex, at that vertex's
    /// position; kept vertices keep their relative order, renumbered `0..k`; faces keep
    /// their order with their corners mapped (a face whose corners merge keeps the
    /// repeated vertex, for validation to report: nothing is dropped). Unused vertices
    /// are kept. A mesh without positions is returned unchanged with a count of 0.
    ///
    /// `None` if a face refers to a vertex `>= vertex_count`, `positions` has a length
    /// other than `vertex_count`, or `tolerance` is negative or not finite.
    pub fn welded_within(&self, tolerance: f64) -> Option<(Self, usize)> {
        let Some(positions) = &self.positions else {
            return self
                .faces
                .iter()
                .flatten()
                .all(|&v| (v as usize) < self.vertex_count)
                .then(|| (self.clone(), 0));
        };
        if positions.len() != self.vertex_count {
            return None;
        }
        let w = weld_map(positions, tolerance)?;
        let kept: Vec<[f64; 3]> = w.kept.iter().map(|&v| positions[v as usize]).collect();
        let faces = self
            .faces
            .iter()
            .map(|f| {
                let mut g = *f;
                for v in &mut g {
                    *v = *w.new_id.get(*v as usize)?;
                }
                Some(g)
            })
            .collect::<Option<Vec<_>>>()?;
        let merged = self.vertex_count - kept.len();
        Some((Mesh::with_positions(kept, faces), merged))
    }

    /// How many vertices share their position (bitwise, as in [`Self::welded`]) with a
    /// vertex of lower index: what welding would merge away. 0 without positions.
    pub fn coincident_vertex_count(&self) -> usize {
        let Some(positions) = &self.positions else {
            return 0;
        };
        let mut seen = std::collections::HashSet::with_capacity(positions.len());
        positions
            .iter()
            .filter(|p| !seen.insert(p.map(f64::to_bits)))
            .count()
    }
}

/// Which vertex each vertex becomes when positions are welded: see [`weld_map`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WeldMap {
    /// `new_id[v]` is the new index of vertex `v` (`0..kept.len()`).
    pub new_id: Vec<u32>,
    /// The kept vertices (one per group, its lowest index), in increasing order:
    /// `kept[new_id[v]]` is the representative of `v`'s group.
    pub kept: Vec<u32>,
}

/// A power of two `s` with `x · s` roughly in `[1, 2)` (`x` a finite magnitude; 1 for 0
/// or a non-finite `x`), within `2^±1000` so that `s` and `1 / s` are normal numbers:
/// multiplying by it rounds nothing unless a result is subnormal, so it brings squares
/// and products of values near `x` away from overflow and underflow without changing
/// any comparison of them.
pub(crate) fn power_of_two_scale(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return 1.0;
    }
    // `floor(log2)` may be off by one next to a power of two: any nearby power will do.
    let e = (x.abs().log2().floor() as i32).clamp(-1000, 1000);
    2f64.powi(-e)
}

/// Groups the vertices at `positions` for welding.
///
/// - `tolerance == 0`: vertices whose three coordinates are bitwise equal form a group
///   (so `0.0` and `-0.0` stay apart). O(V) expected (hashing).
/// - `tolerance > 0`: the groups are the connected components of the graph joining two
///   vertices at Euclidean distance `<= tolerance` (union–find, so merging is
///   transitive), the distance compared as `Σ ((pᵢ − qᵢ)·s)² <= (tolerance·s)²` in
///   `f64`, where `s` is the power of two that brings the tolerance near 1: exactly the
///   plain `Σ (pᵢ − qᵢ)² <= tolerance²` wherever that neither overflows nor underflows,
///   and the true comparison where it would (a pair 10²⁶⁰ apart is not within 10²⁴⁸,
///   though both plain squares overflow to infinity).
///   Vertices are hashed into a grid of cells of side `2 · tolerance`; each vertex is
///   compared with the earlier vertices of its own and the 26 neighbouring cells. Twice
///   the tolerance, so that the rounding of the cell coordinates never puts two vertices
///   that pass the comparison two cells apart (with cells of side `tolerance`, a pair
///   exactly `tolerance` apart by the rounded comparison could straddle two cell
///   boundaries and not be compared at all). O(V + number of pairs in neighbouring
///   cells), expected O(V) when few vertices share a cell.
///
/// Deterministic whatever the order of the work: a group's representative is its lowest
/// index, and the kept vertices keep their relative order.
///
/// `None` if `tolerance` is negative or not finite, or there are more than `u32::MAX`
/// vertices.
pub fn weld_map(positions: &[[f64; 3]], tolerance: f64) -> Option<WeldMap> {
    if !(tolerance >= 0.0 && tolerance.is_finite()) {
        return None;
    }
    u32::try_from(positions.len()).ok()?;
    // parent[v] <= v always, so a root is the lowest index of its group.
    let mut parent: Vec<u32> = (0..positions.len() as u32).collect();
    fn find(parent: &mut [u32], mut v: u32) -> u32 {
        while parent[v as usize] != v {
            let p = parent[v as usize];
            parent[v as usize] = parent[p as usize];
            v = p;
        }
        v
    }
    if tolerance == 0.0 {
        let mut first: std::collections::HashMap<[u64; 3], u32> =
            std::collections::HashMap::with_capacity(positions.len());
        for (v, p) in positions.iter().enumerate() {
            let r = *first.entry(p.map(f64::to_bits)).or_insert(v as u32);
            parent[v] = r;
        }
    } else {
        let side = 2.0 * tolerance;
        let cell = |p: &[f64; 3]| p.map(|x| (x / side).floor() as i64);
        let s = power_of_two_scale(tolerance);
        let t2 = (tolerance * s).powi(2);
        let mut grid: std::collections::HashMap<[i64; 3], Vec<u32>> =
            std::collections::HashMap::with_capacity(positions.len());
        for (v, p) in positions.iter().enumerate() {
            let c = cell(p);
            for dx in -1i64..=1 {
                for dy in -1i64..=1 {
                    for dz in -1i64..=1 {
                        let key = [
                            c[0].saturating_add(dx),
                            c[1].saturating_add(dy),
                            c[2].saturating_add(dz),
                        ];
                        let Some(others) = grid.get(&key) else {
                            continue;
                        };
                        for &u in others {
                            let q = &positions[u as usize];
                            let d2 = ((p[0] - q[0]) * s).powi(2)
                                + ((p[1] - q[1]) * s).powi(2)
                                + ((p[2] - q[2]) * s).powi(2);
                            if d2 <= t2 {
                                let (a, b) = (find(&mut parent, u), find(&mut parent, v as u32));
                                let (lo, hi) = (a.min(b), a.max(b));
                                parent[hi as usize] = lo;
                            }
                        }
                    }
                }
            }
            grid.entry(c).or_default().push(v as u32);
        }
    }
    let mut new_id = vec![0u32; positions.len()];
    let mut kept = Vec::new();
    for v in 0..positions.len() {
        let r = find(&mut parent, v as u32);
        if r as usize == v {
            new_id[v] = kept.len() as u32;
            kept.push(r);
        } else {
            // r < v, so its new id is already set.
            new_id[v] = new_id[r as usize];
        }
    }
    Some(WeldMap { new_id, kept })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;

    #[test]
    fn welded_merges_bitwise_equal_positions_in_first_occurrence_order() {
        // Two triangles of a soup sharing an edge by position, an unused vertex, and
        // 0.0 / -0.0 kept apart.
        let p = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 0.0],
            [-0.0, 0.0, 0.0],
        ];
        let m = TriMesh::with_positions(p, vec![[0, 1, 2], [3, 5, 4]]);
        assert_eq!(m.coincident_vertex_count(), 2);
        let (w, merged) = m.welded().unwrap();
        assert_eq!(merged, 2);
        assert_eq!(w.vertex_count, 5);
        assert_eq!(w.faces, vec![[0, 1, 2], [1, 3, 2]]);
        let wp = w.positions.as_ref().unwrap();
        assert_eq!(wp[3], [1.0, 1.0, 0.0]);
        assert_eq!(wp[4][0].to_bits(), (-0.0f64).to_bits());
        // Idempotent; a face whose corners merge keeps its repeated vertex.
        assert_eq!(w.welded().unwrap(), (w.clone(), 0));
        let d = TriMesh::with_positions(vec![[0.0; 3], [0.0; 3], [1.0; 3]], vec![[0, 1, 2]]);
        assert_eq!(d.welded().unwrap().0.faces, vec![[0, 0, 1]]);
        // No positions: unchanged; inconsistent meshes: None.
        let c = TriMesh::combinatorial(3, vec![[0, 1, 2]]);
        assert_eq!(c.welded().unwrap(), (c.clone(), 0));
        assert_eq!(TriMesh::combinatorial(2, vec![[0, 1, 2]]).welded(), None);
        let bad = TriMesh::with_positions(vec![[0.0; 3]], vec![[0, 1, 2]]);
        assert_eq!(bad.welded(), None);
    }

    #[test]
    fn welded_within_merges_chains_to_their_lowest_index() {
        // 0 -- 1 -- 2 are 0.6 apart (0 and 2 are 1.2 apart), 3 is far, 4 sits on 1.
        let p = vec![
            [0.0, 0.0, 0.0],
            [0.6, 0.0, 0.0],
            [1.2, 0.0, 0.0],
            [9.0, 0.0, 0.0],
            [0.6, 0.0, 0.0],
        ];
        let m = TriMesh::with_positions(p.clone(), vec![[0, 3, 2], [4, 3, 1]]);
        let (w, merged) = m.welded_within(0.7).unwrap();
        assert_eq!(merged, 3);
        assert_eq!(w.positions, Some(vec![p[0], p[3]]));
        assert_eq!(w.faces, vec![[0, 1, 0], [0, 1, 0]]);
        // Below the spacing only the exact copy merges; 0 is the bitwise rule.
        assert_eq!(m.welded_within(0.5).unwrap().1, 1);
        assert_eq!(m.welded_within(0.0), m.welded());
        assert_eq!(m.welded_within(-1.0), None);
        assert_eq!(m.welded_within(f64::NAN), None);
    }

    #[test]
    fn weld_map_matches_all_pairs_union_find() {
        // Independent check: the groups are the components of the all-pairs graph.
        let mut state = 12345u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 33) as f64) / f64::from(1u32 << 31)
        };
        for tol in [0.02, 0.05, 0.1] {
            let p: Vec<[f64; 3]> = (0..300).map(|_| [next(), next(), next() * 0.1]).collect();
            let w = weld_map(&p, tol).unwrap();
            let mut label: Vec<usize> = (0..p.len()).collect();
            // Repeated relaxation to the minimum label over close pairs.
            loop {
                let mut changed = false;
                for i in 0..p.len() {
                    for j in 0..p.len() {
                        let d2: f64 = (0..3).map(|k| (p[i][k] - p[j][k]).powi(2)).sum();
                        if d2 <= tol * tol && label[j] < label[i] {
                            label[i] = label[j];
                            changed = true;
                        }
                    }
                }
                if !changed {
                    break;
                }
            }
            for (v, &l) in label.iter().enumerate() {
                assert_eq!(w.kept[w.new_id[v] as usize] as usize, l, "tol {tol}");
            }
            assert!(
                w.kept.len() < p.len(),
                "tol {tol}: nothing merged, weak test"
            );
        }
    }

    /// Pairs whose rounded squared distance is exactly `tolerance²` are merged wherever
    /// they sit on the grid: `-3.06e-32` and `1.0` (tolerance 1) are 1 apart by the
    /// comparison, but lay in cells -1 and 1 when the cells had side `tolerance`, so
    /// they were never compared (found by fuzzing an STL file); the same pair shifted
    /// to `3.06e-32` was merged.
    #[test]
    fn pairs_at_exactly_the_tolerance_are_merged_wherever_they_sit() {
        for (y, z) in [(-3.062228611575705e-32, 1.0), (3.062228611575705e-32, 1.0)] {
            let p: Vec<[f64; 3]> = vec![[1.0, y, 1.0], [5.0, 5.0, 5.0], [1.0, z, 1.0]];
            let d2: f64 = (0..3).map(|k| (p[0][k] - p[2][k]).powi(2)).sum();
            assert_eq!(d2, 1.0, "the comparison rounds to the tolerance");
            let w = weld_map(&p, 1.0).unwrap();
            assert_eq!(w.new_id, vec![0, 1, 0], "y = {y}");
        }
        // Far from the origin and at small tolerances alike.
        for (base, tol) in [(1e15, 0.75), (-3e10, 1e-3), (2.0f64.powi(60), 4096.0f64)] {
            let p = vec![
                [base, 0.0, 0.0],
                [base + tol, 0.0, 0.0],
                [base + 3.0 * tol, 0.0, 0.0],
            ];
            let close = |a: usize, b: usize| (p[a][0] - p[b][0]).powi(2) <= tol * tol;
            let w = weld_map(&p, tol).unwrap();
            assert_eq!(w.new_id[0] == w.new_id[1], close(0, 1), "{base} {tol}");
            assert_eq!(w.new_id[1] == w.new_id[2], close(1, 2), "{base} {tol}");
        }
    }

    /// Tolerances whose square overflows or underflows compare true distances: a pair
    /// 10²⁶⁰ apart is not within 1.1·10²⁴⁸ (both plain squares are infinite, so the
    /// plain comparison welded them; found by fuzzing), one 10²⁴⁸ apart is; at a
    /// subnormal tolerance of 2·10⁻³²⁰ a pair 3·10⁻³²⁰ apart stays apart (both plain
    /// squares are 0) and one 10⁻³²⁰ apart is welded.
    #[test]
    fn tolerances_near_the_ends_of_the_range_compare_true_distances() {
        let cases = [
            (1.1e248, 1.1e260, false),
            (1.1e248, 1e248, true),
            (2e-320, 3e-320, false),
            (2e-320, 1e-320, true),
            (f64::MAX, f64::MAX, true),
        ];
        for (tol, z, welded) in cases {
            let p = vec![[0.0, 1.0, 0.0], [0.0, 1.0, z]];
            let w = weld_map(&p, tol).unwrap();
            assert_eq!(w.new_id == [0, 0], welded, "{z:e} within {tol:e}");
        }
    }

    fn pos(i: usize) -> [f64; 3] {
        [i as f64, 0.5 * i as f64, -(i as f64)]
    }

    #[test]
    fn compacted_drops_unused_vertices_in_order() {
        // Vertices 0, 2 and 5 unused; the tetrahedron lives on 1, 3, 4, 6.
        let faces = vec![[1, 3, 4], [3, 6, 4], [6, 1, 4], [1, 6, 3]];
        let m = TriMesh::with_positions((0..7).map(pos).collect(), faces);
        let (c, dropped) = m.compacted().expect("indices in range");
        assert_eq!(dropped, 3);
        assert_eq!(c.vertex_count, 4);
        assert_eq!(c.faces, vec![[0, 1, 2], [1, 3, 2], [3, 0, 2], [0, 3, 1]]);
        assert_eq!(c.positions, Some(vec![pos(1), pos(3), pos(4), pos(6)]));
        // Without positions, and already compact: unchanged.
        let t = gen::tetrahedron();
        let plain = TriMesh::combinatorial(t.vertex_count, t.faces.clone());
        assert_eq!(plain.compacted(), Some((plain.clone(), 0)));
    }

    #[test]
    fn compacted_rejects_inconsistent_meshes() {
        let out_of_range = TriMesh::combinatorial(3, vec![[0, 1, 3]]);
        assert_eq!(out_of_range.compacted(), None);
        let short = TriMesh {
            vertex_count: 4,
            positions: Some(vec![pos(0); 3]),
            faces: vec![[0, 1, 2]],
        };
        assert_eq!(short.compacted(), None);
        let quads = QuadMesh::combinatorial(6, vec![[5, 4, 2, 1]]);
        let (q, dropped) = quads.compacted().expect("in range");
        assert_eq!((q.faces, dropped), (vec![[3, 2, 1, 0]], 2));
    }
}
