//! Surfaces back to plain meshes: [`Triangulation::to_mesh`] and
//! [`Triangulation::to_mesh_with_positions`] (a surface back to a compact mesh),
//! [`Component::carry`] (per-vertex data of the source mesh, such as positions, into a
//! component), [`Component::to_mesh`], and [`TriMesh::reassemble`] (reduced components
//! back over the source mesh's vertices, with their original coordinates). Here in the
//! core, which builds from [`TriMesh`] (module `build`), so that the dependency runs one
//! way: the mesh module knows no surface.

use super::{Component, Triangulation};
use crate::mesh::TriMesh;

impl TriMesh {
    /// The union of triangulated pieces of one mesh as a mesh over that mesh's vertices,
    /// compacted like [`crate::Mesh::compacted`]: only the vertices some piece still uses, in
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

    fn pos(i: usize) -> [f64; 3] {
        [i as f64, 0.5 * i as f64, -(i as f64)]
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
