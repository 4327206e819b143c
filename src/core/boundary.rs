//! Surfaces with boundary, closed by coning each boundary loop to a virtual vertex.
//!
//! **Guarantee.** [`Surfaces::from_mesh_with_boundary`] accepts exactly the meshes whose
//! components are compact surfaces, orientable or not, possibly with boundary: every
//! edge lies in one face (a boundary edge) or two (an interior edge), and the faces
//! around every vertex form one fan: a cycle for an interior vertex, a path for a
//! boundary vertex. Everything else is a located [`BuildError`], as for closed meshes
//! (the same variants, in the same precedence, plus
//! [`BuildError::PinchedBoundaryVertex`]). Each component is returned closed
//! ([`ConedComponent::tri`]): every boundary loop `x_1 … x_L` gets a new **virtual
//! vertex** `w` and the cone faces `[x_{i+1}, x_i, w]`. The coned triangulation is a
//! closed surface with
//!
//! - χ(coned) = χ(open) + (number of loops) (each loop adds 1 vertex, L edges, L faces);
//! - the same orientability (gluing a disc along a boundary loop keeps or loses no
//!   orientation), hence the same genus: the open surface is the closed one minus one
//!   open disc per loop;
//! - the open surface's faces as the faces with no virtual vertex, in the input's order
//!   and with the input's vertex order ([`ConedComponent::open_faces`]).
//!
//! **Decisions on the degenerate cases.**
//! (a) A loop of length 3 gets its own virtual vertex like any other, so its three cone
//! faces never duplicate a real face (each contains `w`), even when the triangle of the
//! loop's three vertices is a face (a component that is one triangle becomes a
//! tetrahedron). Two loops through one vertex, or one loop passing twice through it, is
//! a pinch: [`BuildError::PinchedBoundaryVertex`]. A boundary vertex whose faces form a
//! path and also a separate cycle is caught after coning, where its link is two cycles
//! ([`BuildError::VertexLinkNotCycle`]).
//! (b) A loop of length 2 cannot occur: two boundary edges with the same endpoints would
//! be one endpoint pair in two faces, i.e. an interior edge. Length 1 cannot either (no
//! degenerate faces). So every virtual vertex has degree ≥ 3.
//! (c) A chord (an interior edge joining two boundary vertices) is kept as it is; the
//! cone creates no multiple edge, since every cone edge `[w, x]` has the new vertex `w`
//! as an endpoint and each boundary vertex lies on exactly one loop.
//!
//! **The link condition.** For an edge `[u, v]` with no virtual endpoint, the closed
//! link condition on the coned surface, Lk(u) ∩ Lk(v) = Lk(uv), is the link condition
//! of the surface with boundary when the whole boundary is coned to one vertex ω (Dey,
//! Edelsbrunner, Guha, Nekhayev), *except* for an interior edge joining two different
//! loops: one virtual vertex per loop keeps the coned triangulation a closed surface, but
//! it no longer sees that both endpoints are on the boundary. In detail:
//!
//! - a boundary edge `[a, b]` of loop `w`: `w` is in both links and in Lk(ab), so the
//!   test is the real one; on a loop of length 3 the third loop vertex is a common
//!   neighbour outside Lk(ab), so the edge is refused (the loop would become 2 edges);
//! - a chord `[a, b]` of one loop: `w` is a common neighbour not in Lk(ab), so the chord
//!   is refused, which is right: contracting it would pinch the loop into two loops
//!   touching at one vertex;
//! - an interior edge between two loops: no common virtual neighbour, so the coned test
//!   may pass, but contracting it would make the two loops touch (a pinch). The coned
//!   surface stays a closed surface of the same type, the open one does not.
//!   [`ConedComponent::is_contractible`] adds this one check, so it is exactly the
//!   link condition of the surface with boundary.
//!
//! **Complexity.** O(F) plus the sort of each vertex's edge bucket, as for closed
//! meshes; the edges are classified once, with or without boundary (the cone faces are
//! glued directly). **Determinism.** Loops are numbered by the first corner
//! (in input face order) opposite one of their edges; components, local vertex and face
//! ids follow input order as in [`Surfaces::from_mesh`], real vertices and faces before
//! virtual vertices and cone faces.

use super::build::{
    assemble, check_counts, check_open, split, unused_vertices, BuildError, Checked, Component,
    OpenCheck, Surfaces,
};
use super::ids::{Corner, FaceId, VertexId, NONE};
use super::topology::SurfaceType;
use super::tri::Triangulation;
use crate::mesh::TriMesh;

/// One connected compact surface, possibly with boundary, closed by coning.
///
/// `tri` is a closed surface whose vertices `0..real_vertex_count()` are the surface's
/// own (in mesh order) and whose vertices from `real_vertex_count()` on are the
/// virtual vertices, one per boundary loop (in loop order); its faces
/// `0..real_face_count()` are the surface's own (in mesh order, each with the mesh's
/// vertex order), the cone faces follow. Virtual vertices must never be contracted,
/// split or written. A closed component has none; for a mesh of closed surfaces the
/// components (`tri` and both origin maps) are exactly the [`super::Component`]s that
/// [`Surfaces::from_mesh`] gives.
#[derive(Clone, Debug)]
pub struct ConedComponent {
    /// The coned, closed surface. Private to the crate: its virtual vertices must never
    /// be contracted, split or written, which only this crate's code guarantees; users
    /// read it through [`Self::tri`].
    pub(crate) tri: Triangulation,
    /// `vertex_origin[v]` is the mesh vertex index of real local vertex `v` (virtual
    /// vertices have none; see [`Self::vertex_origin_of`]).
    pub vertex_origin: Vec<u32>,
    /// `face_origin[f]` is the mesh face index of real local face `f` (cone faces have
    /// none; see [`Self::face_origin_of`]).
    pub face_origin: Vec<u32>,
    /// Number of virtual vertices (boundary loops at construction).
    virtual_count: u32,
}

impl ConedComponent {
    /// The coned, closed surface (read-only: see the type's documentation).
    pub fn tri(&self) -> &Triangulation {
        &self.tri
    }

    /// Number of real (non-virtual) vertex ids: the real vertices are exactly the ids
    /// below it.
    pub fn real_vertex_count(&self) -> usize {
        self.vertex_origin.len()
    }

    /// Number of real face ids at construction: the real faces are exactly the ids
    /// below it, the cone faces the ids above.
    pub fn real_face_count(&self) -> usize {
        self.face_origin.len()
    }

    /// Whether `v` is a virtual vertex (a cone apex), not a vertex of the surface.
    pub fn is_virtual(&self, v: VertexId) -> bool {
        let first = self.vertex_origin.len() as u64;
        (first..first + u64::from(self.virtual_count)).contains(&u64::from(v.0))
    }

    /// The live virtual vertices, one per boundary loop, in loop order.
    pub fn virtual_vertices(&self) -> impl Iterator<Item = VertexId> + '_ {
        let first = self.vertex_origin.len() as u32;
        (first..first + self.virtual_count)
            .map(VertexId)
            .filter(|&v| self.tri.is_vertex(v))
    }

    /// Whether the surface is closed (no boundary loop).
    pub fn is_closed(&self) -> bool {
        self.virtual_vertices().next().is_none()
    }

    /// The mesh vertex of local vertex `v`, `None` for a virtual or unknown vertex.
    pub fn vertex_origin_of(&self, v: VertexId) -> Option<u32> {
        self.vertex_origin.get(v.index()).copied()
    }

    /// The mesh face of local face `f`, `None` for a cone face or unknown face.
    pub fn face_origin_of(&self, f: FaceId) -> Option<u32> {
        self.face_origin.get(f.index()).copied()
    }

    /// The boundary loops of the current triangulation, one per virtual vertex in loop
    /// order, each the link of its virtual vertex as a vertex cycle, written from its
    /// smallest vertex id towards the smaller of that vertex's two loop neighbours.
    /// Recomputed from `tri` (so it follows contractions). O(total loop length).
    pub fn boundary_loops(&self) -> Vec<Vec<VertexId>> {
        self.virtual_vertices()
            .map(|w| canonical_cycle(self.tri.link(w).collect()))
            .collect()
    }

    /// The length of each boundary loop (the degree of its virtual vertex), in loop
    /// order. O(number of loops).
    pub fn loop_lengths(&self) -> Vec<usize> {
        self.virtual_vertices()
            .map(|w| self.tri.degree(w))
            .collect()
    }

    /// The virtual vertex of the loop through `v`, or `None` if `v` is not a boundary
    /// vertex (or is virtual). O(degree(v)).
    pub fn loop_of(&self, v: VertexId) -> Option<VertexId> {
        if self.is_virtual(v) || !self.tri.is_vertex(v) {
            return None;
        }
        self.tri.link(v).find(|&x| self.is_virtual(x))
    }

    /// Vertices, edges and faces of the surface with boundary (the coned surface minus
    /// the virtual vertices, their edges and the cone faces). O(number of loops).
    pub fn open_counts(&self) -> (usize, usize, usize) {
        let loops = self.virtual_vertices().count();
        let cone: usize = self.loop_lengths().iter().sum();
        (
            self.tri.vertex_count() - loops,
            self.tri.edge_count() - cone,
            self.tri.face_count() - cone,
        )
    }

    /// The topological type of the surface with boundary: χ(open) = χ(coned) − loops,
    /// the coned surface's orientability, and the number of loops. O(V + F).
    pub fn surface_type(&self) -> SurfaceType {
        SurfaceType::of(&self.tri).with_discs_removed(self.virtual_vertices().count())
    }

    /// The surface's own faces (those with no virtual vertex) in local ids, in face id
    /// order. On a fresh component, entry `i` is mesh face `face_origin[i]` with its
    /// vertices mapped by `vertex_origin`, in the mesh's vertex order. O(F).
    pub fn open_faces(&self) -> Vec<[u32; 3]> {
        self.tri
            .faces()
            .map(|f| self.tri.face_vertices(f))
            .filter(|vs| !vs.iter().any(|&v| self.is_virtual(v)))
            .map(|vs| vs.map(|v| v.0))
            .collect()
    }

    /// [`Self::open_faces`] over mesh vertex indices (through `vertex_origin`). O(F).
    pub fn open_faces_in_mesh(&self) -> Vec<[u32; 3]> {
        self.open_faces()
            .into_iter()
            .map(|f| f.map(|v| self.vertex_origin[v as usize]))
            .collect()
    }

    /// The link condition of the surface with boundary for the edge `[u, v]`: false if
    /// either end is virtual or `[u, v]` is not an edge, otherwise the closed link
    /// condition on the coned surface and, in addition, `u` and `v` not on two
    /// different boundary loops (see the module documentation for why the cone alone
    /// misses that case). O((d_u + d_v) log min(d_u, d_v)).
    pub fn is_contractible(&self, u: VertexId, v: VertexId) -> bool {
        if self.is_virtual(u) || self.is_virtual(v) || !self.tri.is_contractible(u, v) {
            return false;
        }
        match (self.loop_of(u), self.loop_of(v)) {
            (Some(a), Some(b)) => a == b,
            _ => true,
        }
    }
}

/// Rotates a cycle to start at its smallest entry and orients it towards the smaller of
/// that entry's two neighbours.
fn canonical_cycle(mut cycle: Vec<VertexId>) -> Vec<VertexId> {
    if let Some(k) = (0..cycle.len()).min_by_key(|&i| cycle[i]) {
        cycle.rotate_left(k);
    }
    if cycle.len() > 2 && cycle[cycle.len() - 1] < cycle[1] {
        cycle[1..].reverse();
    }
    cycle
}

/// A mesh validated as a disjoint union of compact surfaces (with or without boundary),
/// each closed by coning (see the module documentation).
#[derive(Clone, Debug)]
pub struct ConedSurfaces {
    /// The connected components, ordered by their smallest mesh face index.
    pub components: Vec<ConedComponent>,
    /// Mesh vertices used by no face (dropped; callers should warn).
    pub dropped_vertices: Vec<u32>,
    /// The mesh's vertex count.
    pub mesh_vertex_count: usize,
}

impl ConedSurfaces {
    /// See [`Surfaces::from_mesh_with_boundary`].
    pub fn from_mesh(mesh: &TriMesh) -> Result<Self, BuildError> {
        Self::from_faces(mesh.vertex_count, &mesh.faces)
    }

    /// [`Self::from_mesh`] on a bare face list.
    pub fn from_faces(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Self, BuildError> {
        let checked = checked_coned(vertex_count, faces)?;
        // Cone apexes come after the mesh's vertices and are always used.
        let dropped_vertices = unused_vertices(&checked.used[..vertex_count]);
        let (label, count) = checked.face_components();
        let tri = checked.tri;
        let virtual_count = (tri.vertex_capacity() - vertex_count) as u32;
        let components = if count == 1 && dropped_vertices.is_empty() {
            // As in `Surfaces::from_faces`: the mesh's ids are already dense, real ones
            // first, so the component is the triangulation itself.
            vec![ConedComponent {
                vertex_origin: (0..vertex_count as u32).collect(),
                face_origin: (0..faces.len() as u32).collect(),
                tri,
                virtual_count,
            }]
        } else {
            split(&tri, &label, count)
                .into_iter()
                .map(|c| coned_component(c, vertex_count, faces.len()))
                .collect()
        };
        Ok(ConedSurfaces {
            components,
            dropped_vertices,
            mesh_vertex_count: vertex_count,
        })
    }

    /// The whole mesh closed by coning as one triangulation, not split: vertex ids are
    /// the mesh's (an unused one is not a live vertex) followed by one virtual vertex per
    /// boundary loop, face ids the mesh's followed by the cone faces; `face_label[f]`
    /// numbers the components as [`Self::from_faces`] orders them. For the decimator,
    /// whose queue runs over every component at once and whose provenance is in mesh
    /// ids. The same validation and errors as [`Self::from_faces`]. O(F).
    pub(crate) fn whole(vertex_count: usize, faces: &[[u32; 3]]) -> Result<ConedWhole, BuildError> {
        let checked = checked_coned(vertex_count, faces)?;
        let dropped_vertices = unused_vertices(&checked.used[..vertex_count]);
        let (face_label, components) = checked.face_components();
        Ok(ConedWhole {
            tri: checked.tri,
            face_label,
            components,
            dropped_vertices,
        })
    }
}

/// The unsplit coned triangulation of a mesh (see [`ConedSurfaces::whole`]).
#[derive(Clone, Debug)]
pub(crate) struct ConedWhole {
    pub(crate) tri: Triangulation,
    pub(crate) face_label: Vec<u32>,
    pub(crate) components: usize,
    pub(crate) dropped_vertices: Vec<u32>,
}

/// The coned surface's corner table of `faces`, validated (closed: no cone).
fn checked_coned(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Checked, BuildError> {
    {
        let checked: Checked = match check_open(vertex_count, faces)? {
            OpenCheck::Closed(checked) => checked,
            OpenCheck::Open {
                corner_vertex,
                opposite,
                boundary,
            } => {
                let cones = cone_loops(vertex_count, &corner_vertex, &boundary)?;
                glue_cones(vertex_count, faces.len(), corner_vertex, opposite, &cones).map_err(
                    |e| match e {
                        // Report the faces of the mesh around the vertex, not the cone's.
                        BuildError::VertexLinkNotCycle { vertex, cycles, .. } => {
                            BuildError::VertexLinkNotCycle {
                                vertex,
                                cycles,
                                faces: faces.iter().filter(|f| f.contains(&vertex)).count(),
                            }
                        }
                        e => e,
                    },
                )?
            }
        };
        Ok(checked)
    }
}

impl ConedSurfaces {
    /// Total number of boundary loops over all components.
    pub fn loop_count(&self) -> usize {
        self.components
            .iter()
            .map(|c| c.virtual_vertices().count())
            .sum()
    }

    /// Whether every component is closed.
    pub fn is_closed(&self) -> bool {
        self.components.iter().all(ConedComponent::is_closed)
    }
}

impl Surfaces {
    /// Validates `mesh` as a disjoint union of compact surfaces that may have boundary,
    /// drops unused vertices, splits it into connected components and closes each
    /// boundary loop with a cone to a virtual vertex (module `boundary`'s documentation
    /// states the guarantee). Non-manifold edges, multiple edges, duplicate faces and
    /// non-manifold (pinched) vertices are located errors. O(F).
    pub fn from_mesh_with_boundary(mesh: &TriMesh) -> Result<ConedSurfaces, BuildError> {
        ConedSurfaces::from_mesh(mesh)
    }
}

/// A component of the coned triangulation (as `split` gives it) with the virtual
/// vertices and cone faces told apart from the real ones.
fn coned_component(c: Component, vertex_count: usize, face_count: usize) -> ConedComponent {
    // Real faces precede cone faces in the input of `split`, and every real vertex lies
    // on a real face, so real ids come first in each component.
    let real_vertices = c
        .vertex_origin
        .iter()
        .take_while(|&&v| (v as usize) < vertex_count)
        .count();
    let real_faces = c
        .face_origin
        .iter()
        .take_while(|&&f| (f as usize) < face_count)
        .count();
    let virtual_count = (c.vertex_origin.len() - real_vertices) as u32;
    let mut vertex_origin = c.vertex_origin;
    vertex_origin.truncate(real_vertices);
    let mut face_origin = c.face_origin;
    face_origin.truncate(real_faces);
    ConedComponent {
        tri: c.tri,
        vertex_origin,
        face_origin,
        virtual_count,
    }
}

/// The cone faces of every boundary loop and the number of loops.
struct Cones {
    faces: Vec<[u32; 3]>,
    /// `corners[k]`: the corner opposite the boundary edge that cone face `k` closes.
    corners: Vec<u32>,
    loops: usize,
}

/// The coned surface's corner table, glued directly: the interior edges as the first
/// classification glued them, each boundary edge to its cone face, and the cone faces
/// of each loop to each other around their apex; then per-vertex corners, degrees and
/// the vertex-link check ([`assemble`]). The result is the table that validating the
/// mesh's faces followed by the cone faces from scratch builds (a gluing is determined
/// by its edges), without classifying every edge a second time: the cone faces add no
/// face, edge or duplicate error (each cone face has a new apex, each boundary edge
/// gets one cone face, and each boundary vertex lies on exactly two boundary edges of
/// one loop, which `cone_loops` has checked), so only the sizes and the vertex links
/// are left to check. O(F + V).
fn glue_cones(
    vertex_count: usize,
    face_count: usize,
    mut corner_vertex: Vec<u32>,
    mut opposite: Vec<u32>,
    cones: &Cones,
) -> Result<Checked, BuildError> {
    let all_vertices = vertex_count + cones.loops;
    let all_faces = face_count + cones.faces.len();
    check_counts(all_vertices, all_faces)?;
    corner_vertex.reserve_exact(3 * cones.faces.len());
    opposite.reserve_exact(3 * cones.faces.len());
    // The corner of a cone face opposite `[v, apex]` whose partner is not seen yet.
    let mut pending = vec![NONE; vertex_count];
    for (k, (face, &boundary)) in cones.faces.iter().zip(&cones.corners).enumerate() {
        let base = 3 * (face_count + k) as u32;
        corner_vertex.extend_from_slice(face);
        // The face is [y, x, apex]: the apex's corner faces the boundary edge [y, x].
        opposite.extend_from_slice(&[NONE, NONE, boundary]);
        opposite[boundary as usize] = base + 2;
        // The corner at y faces [x, apex], the corner at x faces [apex, y].
        for (corner, v) in [(base, face[1]), (base + 1, face[0])] {
            let other = std::mem::replace(&mut pending[v as usize], NONE);
            if other == NONE {
                pending[v as usize] = corner;
            } else {
                opposite[corner as usize] = other;
                opposite[other as usize] = corner;
            }
        }
    }
    debug_assert!(pending.iter().all(|&c| c == NONE));
    assemble(all_vertices, all_faces, corner_vertex, opposite)
}

/// Walks the boundary edges (the edges opposite the `boundary` corners) into loops and
/// cones loop `k` to the new vertex `vertex_count + k`. A vertex on other than 0 or 2
/// boundary edges is a pinch. O(V + number of boundary edges · log).
fn cone_loops(
    vertex_count: usize,
    corner_vertex: &[u32],
    boundary: &[u32],
) -> Result<Cones, BuildError> {
    let ends = |c: u32| {
        let c = Corner(c);
        (
            corner_vertex[c.next().index()],
            corner_vertex[c.prev().index()],
        )
    };
    // The (at most two) boundary corners at each vertex, and how many there are.
    let mut at = vec![[NONE; 2]; vertex_count];
    let mut count = vec![0usize; vertex_count];
    for &c in boundary {
        let (a, b) = ends(c);
        for x in [a as usize, b as usize] {
            if count[x] < 2 {
                at[x][count[x]] = c;
            }
            count[x] += 1;
        }
    }
    // Smallest vertex id first, so the reported pinch does not depend on bucket order.
    if let Some(v) = count.iter().position(|&n| n != 0 && n != 2) {
        return Err(BuildError::PinchedBoundaryVertex {
            vertex: v as u32,
            boundary_edges: count[v],
        });
    }
    let mut starts = boundary.to_vec();
    starts.sort_unstable();
    let mut seen = vec![false; corner_vertex.len()];
    let mut out = Cones {
        faces: Vec::with_capacity(boundary.len()),
        corners: Vec::with_capacity(boundary.len()),
        loops: 0,
    };
    for &start in &starts {
        if seen[start as usize] {
            continue;
        }
        let w = (vertex_count + out.loops) as u32;
        let mut c = start;
        let mut from = ends(c).0;
        loop {
            seen[c as usize] = true;
            let (x, y) = ends(c);
            // The face runs x → y along this edge; the cone face runs y → x, so that a
            // consistently oriented surface stays consistently oriented.
            out.faces.push([y, x, w]);
            out.corners.push(c);
            let to = if x == from { y } else { x };
            let [c1, c2] = at[to as usize];
            let next = if c1 == c { c2 } else { c1 };
            if next == NONE || seen[next as usize] {
                break;
            }
            c = next;
            from = to;
        }
        out.loops += 1;
    }
    Ok(out)
}
