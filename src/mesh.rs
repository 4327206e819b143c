//! Plain indexed polygon meshes: what files hold and generators produce.
//!
//! A [`Mesh`] is *data*, not a surface: it may be a soup, have unused vertices, several
//! components or non-manifold edges. [`crate::Triangulation`] is built from a
//! [`TriMesh`] after full validation; the writers take a [`TriMesh`] or a [`QuadMesh`].
//!
//! The conversions between the two live here, written once for the command line, the
//! examples and library users: [`Mesh::compacted`] (drop unused vertices),
//! [`Mesh::welded`] (merge vertices at bitwise-equal positions, as STL needs) and
//! [`Mesh::welded_within`] (within a distance),
//! [`Triangulation::to_mesh`] and [`Triangulation::to_mesh_with_positions`] (a surface
//! back to a compact mesh), [`Component::carry`] (per-vertex data of the source mesh,
//! such as positions, into a component), [`Component::to_mesh`], and
//! [`TriMesh::reassemble`] (reduced components back over the source mesh's vertices, with
//! their original coordinates).

use crate::core::{Component, Triangulation};

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

/// Groups the vertices at `positions` for welding.
///
/// - `tolerance == 0`: vertices whose three coordinates are bitwise equal form a group
///   (so `0.0` and `-0.0` stay apart). O(V) expected (hashing).
/// - `tolerance > 0`: the groups are the connected components of the graph joining two
///   vertices at Euclidean distance `<= tolerance` (union–find, so merging is
///   transitive). Vertices are hashed into a grid of cells of side `tolerance`; each
///   vertex is compared with the earlier vertices of its own and the 26 neighbouring
///   cells, which contain every vertex within `tolerance`. O(V + number of pairs in
///   neighbouring cells), expected O(V) when few vertices share a cell.
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
        let cell = |p: &[f64; 3]| p.map(|x| (x / tolerance).floor() as i64);
        let t2 = tolerance * tolerance;
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
                            let d2 = (p[0] - q[0]).powi(2)
                                + (p[1] - q[1]).powi(2)
                                + (p[2] - q[2]).powi(2);
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

impl TriMesh {
    /// The union of triangulated pieces of one mesh as a mesh over that mesh's vertices,
    /// compacted like [`Mesh::compacted`]: only the vertices some piece still uses, in
    /// increasing original index order, with their original `positions`.
    ///
    /// Each part is a triangulation with its map to the mesh's vertex indices
    /// (`origin[v]` for vertex id `v`), as in a [`Component`]:
    /// `(&c.tri, &c.vertex_origin[..])`.
    /// The triangulation may have been reduced since (contraction keeps ids), which is how
    /// the command line writes the irreducible components of a mesh with their original
    /// coordinates. Faces come part by part, each in increasing face id order.
    ///
    /// `None` if a vertex has no origin, an origin is `>= vertex_count`, or `positions`
    /// has a length other than `vertex_count`. O(vertex_count + F).
    pub fn reassemble<'a>(
        vertex_count: usize,
        positions: Option<&[[f64; 3]]>,
        parts: impl IntoIterator<Item = (&'a Triangulation, &'a [u32])>,
    ) -> Option<TriMesh> {
        if positions.is_some_and(|p| p.len() != vertex_count) {
            return None;
        }
        let mut faces = Vec::new();
        for (t, origin) in parts {
            for f in t.faces() {
                let [a, b, c] = t.face_vertices(f);
                faces.push([
                    *origin.get(a.index())?,
                    *origin.get(b.index())?,
                    *origin.get(c.index())?,
                ]);
            }
        }
        // Compacted as `Mesh::compacted` does, copying only the kept positions (the
        // source's may be large).
        const UNUSED: u32 = u32::MAX;
        let mut new_id = vec![UNUSED; vertex_count];
        for f in &faces {
            for &v in f {
                *new_id.get_mut(v as usize)? = 0;
            }
        }
        let mut kept = 0u32;
        let mut out = positions.map(|_| Vec::new());
        for (v, id) in new_id.iter_mut().enumerate() {
            if *id != UNUSED {
                *id = kept;
                kept += 1;
                if let (Some(out), Some(p)) = (&mut out, positions) {
                    out.push(p[v]);
                }
            }
        }
        for f in &mut faces {
            *f = f.map(|v| new_id[v as usize]);
        }
        Some(TriMesh {
            vertex_count: kept as usize,
            positions: out,
            faces,
        })
    }
}

impl Triangulation {
    /// The surface as a mesh: its live vertices renumbered `0..V` in increasing id order,
    /// its live faces in increasing id order with their corners as stored; no positions.
    /// [`Triangulation::from_faces`] on the result gives this surface back up to that
    /// renumbering. O(vertex capacity + F).
    pub fn to_mesh(&self) -> TriMesh {
        let (_, faces) = self.compact_faces();
        TriMesh::combinatorial(self.vertex_count(), faces)
    }

    /// [`Self::to_mesh`] with coordinates: `positions[v]` is the position of vertex id `v`
    /// (for instance the source mesh's positions when this triangulation was built from
    /// it directly, or [`Component::carry`] of them for a component).
    ///
    /// `None` if `positions` has no entry for some live vertex.
    pub fn to_mesh_with_positions(&self, positions: &[[f64; 3]]) -> Option<TriMesh> {
        let (live, faces) = self.compact_faces();
        let kept = live
            .iter()
            .map(|&v| positions.get(v as usize).copied())
            .collect::<Option<Vec<_>>>()?;
        Some(TriMesh::with_positions(kept, faces))
    }

    /// The live vertex ids in increasing order, and the live faces over their ranks.
    fn compact_faces(&self) -> (Vec<u32>, Vec<[u32; 3]>) {
        let mut rank = vec![u32::MAX; self.vertex_capacity()];
        let mut live = Vec::with_capacity(self.vertex_count());
        for v in self.vertices() {
            rank[v.index()] = live.len() as u32;
            live.push(v.0);
        }
        let faces = self
            .faces()
            .map(|f| self.face_vertices(f).map(|v| rank[v.index()]))
            .collect();
        (live, faces)
    }
}

impl Component {
    /// Per-vertex data of the source mesh carried into this component: entry `v` is
    /// `per_vertex[vertex_origin[v]]`, so the result is indexed by the component's vertex
    /// ids (positions, colours, labels...). Still valid after the component's
    /// triangulation is reduced, since contraction keeps ids.
    ///
    /// `None` if `per_vertex` has no entry for some vertex of the component. O(V).
    pub fn carry<T: Clone>(&self, per_vertex: &[T]) -> Option<Vec<T>> {
        self.vertex_origin
            .iter()
            .map(|&m| per_vertex.get(m as usize).cloned())
            .collect()
    }

    /// This component's surface as a compact mesh ([`Triangulation::to_mesh`]), with the
    /// source mesh's positions carried along when given (`mesh_positions` is indexed by
    /// mesh vertex).
    ///
    /// `None` if `mesh_positions` has no entry for some vertex of the component.
    pub fn to_mesh(&self, mesh_positions: Option<&[[f64; 3]]>) -> Option<TriMesh> {
        match mesh_positions {
            None => Some(self.tri.to_mesh()),
            Some(p) => self.tri.to_mesh_with_positions(&self.carry(p)?),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::{History, Surfaces, VertexId};
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

    #[test]
    fn to_mesh_renumbers_live_vertices_in_id_order() {
        let oct = gen::octahedron();
        let mut t = Triangulation::from_faces(oct.vertex_count, &oct.faces).expect("surface");
        let m = t.to_mesh();
        assert_eq!(m.faces, oct.faces);
        assert_eq!(m.positions, None);
        // After a contraction, vertex 2 is gone: ids above it shift down by one.
        t.contract(VertexId(0), VertexId(2), &mut History::new())
            .expect("contractible");
        let m = t.to_mesh();
        assert_eq!(m.vertex_count, 5);
        let back = Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface");
        assert_eq!(back.face_count(), t.face_count());
        assert_eq!(back.euler_characteristic(), t.euler_characteristic());
        let p: Vec<_> = (0..6).map(pos).collect();
        let with = t.to_mesh_with_positions(&p).expect("positions for all");
        assert_eq!(with.faces, m.faces);
        assert_eq!(
            with.positions,
            Some(vec![pos(0), pos(1), pos(3), pos(4), pos(5)])
        );
        assert_eq!(t.to_mesh_with_positions(&p[..5]), None);
    }

    /// Two disjoint tetrahedra interleaved in one mesh, plus an unused vertex 8.
    fn two_tetrahedra() -> TriMesh {
        let a = [0u32, 2, 4, 6];
        let b = [1u32, 3, 5, 7];
        let tet = gen::tetrahedron().faces;
        let mut faces = Vec::new();
        for f in &tet {
            faces.push(f.map(|v| a[v as usize]));
            faces.push(f.map(|v| b[v as usize]));
        }
        TriMesh::with_positions((0..9).map(pos).collect(), faces)
    }

    #[test]
    fn components_carry_per_vertex_data() {
        let mesh = two_tetrahedra();
        let s = Surfaces::from_mesh(&mesh).expect("two spheres");
        assert_eq!(s.components.len(), 2);
        let labels: Vec<char> = "abcdefghi".chars().collect();
        for (k, c) in s.components.iter().enumerate() {
            let l = c.carry(&labels).expect("labels for all");
            let expect: Vec<char> = c
                .vertex_origin
                .iter()
                .map(|&m| labels[m as usize])
                .collect();
            assert_eq!(l, expect);
            assert!(l.iter().all(|&ch| (ch as usize - 'a' as usize) % 2 == k));
            // Component 1 uses mesh vertex 7, which the shortened slice lacks.
            assert_eq!(c.carry(&labels[..7]).is_some(), k == 0);
            let m = c.to_mesh(mesh.positions.as_deref()).expect("positions");
            let p = m.positions.as_ref().expect("carried");
            for (f, orig) in m.faces.iter().zip(&c.face_origin) {
                let want = mesh.faces[*orig as usize];
                for i in 0..3 {
                    assert_eq!(p[f[i] as usize], pos(want[i] as usize));
                }
            }
            assert_eq!(c.to_mesh(None).expect("no positions").faces, m.faces);
        }
    }

    #[test]
    fn reassemble_keeps_original_positions_of_survivors() {
        let mesh = two_tetrahedra();
        let s = Surfaces::from_mesh(&mesh).expect("two spheres");
        let parts = || s.components.iter().map(|c| (&c.tri, &c.vertex_origin[..]));
        // Nothing reduced: the mesh minus its unused vertex.
        let whole = TriMesh::reassemble(9, mesh.positions.as_deref(), parts()).expect("ok");
        let (compact, dropped) = mesh.compacted().expect("ok");
        assert_eq!(dropped, 1);
        let mut got = whole.faces.clone();
        let mut want = compact.faces.clone();
        got.sort_unstable();
        want.sort_unstable();
        assert_eq!(got, want);
        assert_eq!(whole.positions, compact.positions);
        // A sphere from the octahedron reduced to T4: 4 survivors keep their coordinates.
        let oct = gen::octahedron();
        let p: Vec<_> = (0..6).map(pos).collect();
        let t = Triangulation::from_faces(6, &oct.faces).expect("surface");
        let r = crate::irreducible::reduce(
            t,
            crate::irreducible::Algorithm::Rs,
            &crate::irreducible::Options::default(),
        );
        let origin: Vec<u32> = (0..6).collect();
        let out = TriMesh::reassemble(6, Some(&p[..]), [(&r.tri, &origin[..])]).expect("ok");
        assert_eq!(out.vertex_count, 4);
        let survivors: Vec<[f64; 3]> = r.tri.vertices().map(|v| p[v.index()]).collect();
        assert_eq!(out.positions, Some(survivors));
        // Inconsistent inputs are refused.
        let far: Vec<u32> = (10..16).collect();
        assert_eq!(TriMesh::reassemble(6, None, [(&r.tri, &far[..])]), None);
        assert_eq!(TriMesh::reassemble(6, None, [(&r.tri, &origin[..3])]), None);
    }
}
