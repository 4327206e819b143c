//! Construction of a [`Triangulation`] from a face list, with full validation.

use super::ids::{Corner, FaceId, VertexId, MAX_FACES, MAX_VERTICES, NONE};
use super::tri::{StateStamp, Triangulation};
use crate::mesh::TriMesh;

/// Why a face list is not a closed surface triangulation. Every variant says where:
/// face indices are positions in the input face list, vertex ids are input vertex ids.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum BuildError {
    /// The face list is empty.
    #[error("the mesh has no faces")]
    Empty,
    /// More vertices or faces than the 32-bit index type can address.
    #[error("too many {what}: {count} (at most {max})")]
    TooLarge {
        /// `"vertices"` or `"faces"`.
        what: &'static str,
        /// The count given.
        count: usize,
        /// The largest supported count.
        max: usize,
    },
    /// A face refers to a vertex id outside `0..vertex_count`.
    #[error("face {face}: vertex index {vertex} out of range (vertex count {vertex_count})")]
    VertexOutOfRange {
        /// Input face index.
        face: usize,
        /// The offending index.
        vertex: u32,
        /// The declared vertex count.
        vertex_count: usize,
    },
    /// A face repeats a vertex.
    #[error("face {face} is degenerate: vertices {vertices:?}")]
    DegenerateFace {
        /// Input face index.
        face: usize,
        /// Its vertices.
        vertices: [u32; 3],
    },
    /// Two faces have the same three vertices.
    #[error("face {face} duplicates face {first} (vertices {vertices:?})")]
    DuplicateFace {
        /// The later input face index.
        face: usize,
        /// The earlier input face index with the same vertex set.
        first: usize,
        /// The shared vertices (as in the later face).
        vertices: [u32; 3],
    },
    /// An edge lies in exactly one face: the surface has a boundary.
    #[error("edge [{a}, {b}] is a boundary edge: it lies only in face {face}")]
    BoundaryEdge {
        /// Edge endpoint (the smaller id).
        a: u32,
        /// Edge endpoint (the larger id).
        b: u32,
        /// The one face containing it.
        face: usize,
    },
    /// An edge lies in an odd number (at least 3) of faces.
    #[error("edge [{a}, {b}] is non-manifold, shared by {faces} faces (first: face {face})")]
    NonManifoldEdge {
        /// Edge endpoint (the smaller id).
        a: u32,
        /// Edge endpoint (the larger id).
        b: u32,
        /// How many faces contain it.
        faces: usize,
        /// The first input face containing it.
        face: usize,
    },
    /// An even number (at least 4) of faces contain the same endpoints: two or more
    /// distinct edges with the same endpoints, which a triangulation does not allow.
    #[error("edge [{a}, {b}] is non-manifold, shared by {faces} faces (first: face {face})")]
    MultipleEdges {
        /// Endpoint (the smaller id).
        a: u32,
        /// Endpoint (the larger id).
        b: u32,
        /// Number of edges (faces / 2).
        edges: usize,
        /// Number of faces containing both.
        faces: usize,
        /// The first input face containing both.
        face: usize,
    },
    /// The faces around a vertex form several fans (a pinched, non-manifold vertex).
    #[error(
        "vertex {vertex}: its link is not one cycle but {cycles} cycles (faces around it: {faces})"
    )]
    VertexLinkNotCycle {
        /// The vertex id.
        vertex: u32,
        /// Number of separate cycles of faces around it.
        cycles: usize,
        /// Number of faces containing it.
        faces: usize,
    },
    /// A vertex of a surface with boundary where more than two boundary edges meet: its
    /// faces form several fans (two boundary loops touch there, or one loop passes
    /// through it twice), so the surface is pinched at this vertex.
    #[error(
        "vertex {vertex} is pinched: {boundary_edges} boundary edges meet there (a manifold boundary vertex has 2)"
    )]
    PinchedBoundaryVertex {
        /// The vertex id.
        vertex: u32,
        /// Number of boundary edges containing it.
        boundary_edges: usize,
    },
    /// A vertex has fewer than 3 incident edges.
    #[error("vertex {vertex} has degree {degree} (at least 3 required)")]
    VertexDegreeTooLow {
        /// The vertex id.
        vertex: u32,
        /// Its degree.
        degree: usize,
    },
    /// A vertex in `0..vertex_count` is used by no face (only [`Triangulation::from_faces`]
    /// reports this; [`Surfaces::from_mesh`] drops such vertices instead).
    #[error("vertex {vertex} is used by no face")]
    UnusedVertex {
        /// The vertex id.
        vertex: u32,
    },
    /// The faces form several connected surfaces (only [`Triangulation::from_faces`]
    /// reports this; [`Surfaces::from_mesh`] splits them instead).
    #[error("the faces form {components} connected components, not one")]
    Disconnected {
        /// Number of components.
        components: usize,
    },
}

/// Result of the shared validation: a possibly disconnected, possibly sparse corner table.
pub(super) struct Checked {
    pub(super) tri: Triangulation,
    pub(super) used: Vec<bool>,
}

fn check_sizes(vertex_count: usize, faces: &[[u32; 3]]) -> Result<(), BuildError> {
    check_counts(vertex_count, faces.len())
}

/// [`check_sizes`] on the counts alone.
pub(super) fn check_counts(vertex_count: usize, faces: usize) -> Result<(), BuildError> {
    if faces == 0 {
        return Err(BuildError::Empty);
    }
    if faces > MAX_FACES {
        return Err(BuildError::TooLarge {
            what: "faces",
            count: faces,
            max: MAX_FACES,
        });
    }
    if vertex_count > MAX_VERTICES {
        return Err(BuildError::TooLarge {
            what: "vertices",
            count: vertex_count,
            max: MAX_VERTICES,
        });
    }
    Ok(())
}

/// Phase 1, per face: every index in range, no repeated vertex. O(F).
fn check_faces(vertex_count: usize, faces: &[[u32; 3]]) -> Result<(), BuildError> {
    for (i, f) in faces.iter().enumerate() {
        for &v in f {
            if v as usize >= vertex_count {
                return Err(BuildError::VertexOutOfRange {
                    face: i,
                    vertex: v,
                    vertex_count,
                });
            }
        }
        if f[0] == f[1] || f[1] == f[2] || f[0] == f[2] {
            return Err(BuildError::DegenerateFace {
                face: i,
                vertices: *f,
            });
        }
    }
    Ok(())
}

/// Phase 2 output: the edge opposite each corner, bucketed under its smaller endpoint.
/// Bucket `lo` is `entries[start[lo]..start[lo + 1]]`; each entry packs
/// `(larger endpoint << 32) | corner` so a bucket sorts without indirection.
struct EdgeBuckets {
    start: Vec<u32>,
    entries: Vec<u64>,
}

/// Phase 2: buckets every corner's opposite edge (a counting sort by smaller endpoint).
/// O(F + V).
fn bucket_edges(vertex_count: usize, corner_vertex: &[u32]) -> EdgeBuckets {
    // The edge opposite slot s of a face joins its slots s + 1 and s + 2 (mod 3): read
    // per face, so no corner arithmetic is needed.
    let edges = |f: &[u32]| {
        let ordered = |a: u32, b: u32| if a < b { (a, b) } else { (b, a) };
        [
            ordered(f[1], f[2]),
            ordered(f[2], f[0]),
            ordered(f[0], f[1]),
        ]
    };
    let mut start = vec![0u32; vertex_count + 1];
    for f in corner_vertex.chunks_exact(3) {
        for (lo, _) in edges(f) {
            start[lo as usize + 1] += 1;
        }
    }
    for i in 0..vertex_count {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut entries = vec![0u64; corner_vertex.len()];
    for (face, f) in corner_vertex.chunks_exact(3).enumerate() {
        for (s, (lo, hi)) in edges(f).into_iter().enumerate() {
            let slot = &mut fill[lo as usize];
            entries[*slot as usize] = ((hi as u64) << 32) | (3 * face + s) as u64;
            *slot += 1;
        }
    }
    EdgeBuckets { start, entries }
}

/// How many faces hold one pair of endpoints, as phase 3 classifies it.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum EdgeClass {
    /// Two faces: an interior edge of a surface (glued in `opposite`).
    Interior,
    /// One face: a boundary edge (an error for closed surfaces; the classified case a
    /// surface-with-boundary builder keeps).
    Boundary,
    /// An odd number ≥ 3 of faces: non-manifold.
    NonManifold,
    /// An even number ≥ 4 of faces: several edges with the same endpoints.
    Multiple,
}

impl EdgeClass {
    fn of(faces: usize) -> Self {
        match faces {
            2 => EdgeClass::Interior,
            1 => EdgeClass::Boundary,
            n if n % 2 == 1 => EdgeClass::NonManifold,
            _ => EdgeClass::Multiple,
        }
    }
}

/// Phase 3 output: the gluing of interior edges, the corners of boundary edges, and the
/// first problem of each kind (reported in a fixed order of precedence by the caller).
struct Classified {
    opposite: Vec<u32>,
    /// Corners opposite a boundary edge (their `opposite` entry stays `NONE`), in
    /// bucket order.
    boundary: Vec<u32>,
    duplicate: Option<BuildError>,
    bad_edge: Option<BuildError>,
    first_boundary: Option<BuildError>,
}

/// Phase 3: sorts each bucket, groups equal endpoint pairs, glues interior edges and
/// classifies the rest ([`EdgeClass`]); also detects duplicate faces (two faces on one
/// edge with the same third vertex). O(F) plus sorting the buckets (each ~degree).
fn classify_edges(buckets: EdgeBuckets, corner_vertex: &[u32], faces: &[[u32; 3]]) -> Classified {
    let EdgeBuckets { start, mut entries } = buckets;
    let mut out = Classified {
        opposite: vec![NONE; corner_vertex.len()],
        boundary: Vec::new(),
        duplicate: None,
        bad_edge: None,
        first_boundary: None,
    };
    for lo in 0..start.len() - 1 {
        let b = &mut entries[start[lo] as usize..start[lo + 1] as usize];
        sort_bucket(b);
        let mut i = 0;
        while i < b.len() {
            let hi = b[i] >> 32;
            let mut j = i + 1;
            while j < b.len() && b[j] >> 32 == hi {
                j += 1;
            }
            if j == i + 2 {
                // The common case, an interior edge, without `classify_run`'s general
                // bookkeeping (same checks, same order).
                let (p, q) = (
                    (b[i] & 0xffff_ffff) as usize,
                    (b[i + 1] & 0xffff_ffff) as usize,
                );
                if out.duplicate.is_none() && corner_vertex[p] == corner_vertex[q] {
                    let (first, face) = (p / 3, q / 3);
                    out.duplicate = Some(BuildError::DuplicateFace {
                        face,
                        first,
                        vertices: faces[face],
                    });
                }
                out.opposite[p] = q as u32;
                out.opposite[q] = p as u32;
                i = j;
                continue;
            }
            classify_run(
                &b[i..j],
                (lo as u32, hi as u32),
                corner_vertex,
                faces,
                &mut out,
            );
            i = j;
        }
    }
    out
}

/// Sorts one edge bucket (a vertex's edges to larger neighbours: about three on a
/// typical surface, so an insertion sort beats the general sort's set-up).
fn sort_bucket(b: &mut [u64]) {
    if b.len() > 16 {
        b.sort_unstable();
        return;
    }
    for i in 1..b.len() {
        let x = b[i];
        let mut j = i;
        while j > 0 && b[j - 1] > x {
            b[j] = b[j - 1];
            j -= 1;
        }
        b[j] = x;
    }
}

/// Phase 3 for one endpoint pair `[a, b]` held by the corners of `run`.
fn classify_run(
    run: &[u64],
    (a, b): (u32, u32),
    corner_vertex: &[u32],
    faces: &[[u32; 3]],
    out: &mut Classified,
) {
    let corner = |k: usize| (run[k] & 0xffff_ffff) as usize;
    if out.duplicate.is_none() {
        'dup: for p in 0..run.len() {
            for q in p + 1..run.len() {
                if corner_vertex[corner(p)] == corner_vertex[corner(q)] {
                    let (f1, f2) = (corner(p) / 3, corner(q) / 3);
                    let (first, face) = (f1.min(f2), f1.max(f2));
                    out.duplicate = Some(BuildError::DuplicateFace {
                        face,
                        first,
                        vertices: faces[face],
                    });
                    break 'dup;
                }
            }
        }
    }
    let first_face = (0..run.len()).map(|k| corner(k) / 3).min().unwrap_or(0);
    match EdgeClass::of(run.len()) {
        EdgeClass::Interior => {
            let (p, q) = (corner(0), corner(1));
            out.opposite[p] = q as u32;
            out.opposite[q] = p as u32;
        }
        EdgeClass::Boundary => {
            out.boundary.push(corner(0) as u32);
            if out.first_boundary.is_none() {
                out.first_boundary = Some(BuildError::BoundaryEdge {
                    a,
                    b,
                    face: first_face,
                });
            }
        }
        EdgeClass::NonManifold => {
            if out.bad_edge.is_none() {
                out.bad_edge = Some(BuildError::NonManifoldEdge {
                    a,
                    b,
                    faces: run.len(),
                    face: first_face,
                });
            }
        }
        EdgeClass::Multiple => {
            if out.bad_edge.is_none() {
                out.bad_edge = Some(BuildError::MultipleEdges {
                    a,
                    b,
                    edges: run.len() / 2,
                    faces: run.len(),
                    face: first_face,
                });
            }
        }
    }
}

/// Phase 4: with every edge in exactly two faces, each used vertex's star walk must
/// visit all its corners (its link is one cycle) and there must be at least 3. O(F).
fn check_vertex_links(tri: &Triangulation, used: &[bool]) -> Result<(), BuildError> {
    for (v, &is_used) in used.iter().enumerate() {
        if !is_used {
            continue;
        }
        let walked = tri.star(VertexId(v as u32)).count();
        let total = tri.degree[v] as usize;
        if walked != total {
            return Err(BuildError::VertexLinkNotCycle {
                vertex: v as u32,
                cycles: count_fans(tri, v as u32),
                faces: total,
            });
        }
        if total < 3 {
            return Err(BuildError::VertexDegreeTooLow {
                vertex: v as u32,
                degree: total,
            });
        }
    }
    Ok(())
}

/// Phases 1-3 on a face list: sizes and faces, edge bucketing, edge classification.
/// Returns the corner-to-vertex array and the classification; the first face error,
/// duplicate face or non-manifold / multiple edge is an error here (in that
/// precedence), boundary edges are left to the caller.
fn classify(vertex_count: usize, faces: &[[u32; 3]]) -> Result<(Vec<u32>, Classified), BuildError> {
    check_sizes(vertex_count, faces)?;
    check_faces(vertex_count, faces)?;
    let mut corner_vertex: Vec<u32> = Vec::with_capacity(3 * faces.len());
    for f in faces {
        corner_vertex.extend_from_slice(f);
    }
    let buckets = bucket_edges(vertex_count, &corner_vertex);
    let mut classified = classify_edges(buckets, &corner_vertex, faces);
    if let Some(e) = classified.duplicate.take().or(classified.bad_edge.take()) {
        return Err(e);
    }
    Ok((corner_vertex, classified))
}

/// Phase 4 on a fully glued corner table (every edge interior): per-vertex corners and
/// degrees, then the vertex-link check.
pub(super) fn assemble(
    vertex_count: usize,
    faces: usize,
    corner_vertex: Vec<u32>,
    opposite: Vec<u32>,
) -> Result<Checked, BuildError> {
    let mut corner_count = vec![0u32; vertex_count];
    let mut vertex_corner = vec![NONE; vertex_count];
    for (c, &v) in corner_vertex.iter().enumerate() {
        corner_count[v as usize] += 1;
        if vertex_corner[v as usize] == NONE {
            vertex_corner[v as usize] = c as u32;
        }
    }
    let used: Vec<bool> = vertex_corner.iter().map(|&c| c != NONE).collect();
    let tri = Triangulation {
        corner_vertex,
        opposite,
        vertex_corner,
        degree: corner_count,
        live_vertices: used.iter().filter(|&&u| u).count(),
        live_faces: faces,
        state: StateStamp::fresh(),
        stamps: Default::default(),
    };
    check_vertex_links(&tri, &used)?;
    Ok(Checked { tri, used })
}

/// Validates a face list as a possibly disconnected closed surface and builds its corner
/// table, in four phases: sizes and faces, edge bucketing, edge classification (gluing),
/// vertex links. Errors are reported in a fixed precedence: the first face error, then
/// duplicate faces, then non-manifold or multiple edges, then boundary edges, then
/// vertex links.
pub(super) fn check(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Checked, BuildError> {
    let (corner_vertex, classified) = classify(vertex_count, faces)?;
    if let Some(e) = classified.first_boundary {
        return Err(e);
    }
    debug_assert!(classified.boundary.is_empty());
    assemble(
        vertex_count,
        faces.len(),
        corner_vertex,
        classified.opposite,
    )
}

/// Phases 1-3 for a surface that may have boundary: the face and edge errors of
/// [`check`] except boundary edges, which are returned as the corners opposite them
/// (in bucket order). If there are none, the closed surface is finished too (phase 4),
/// so that a closed mesh costs what [`check`] costs.
pub(super) fn check_open(vertex_count: usize, faces: &[[u32; 3]]) -> Result<OpenCheck, BuildError> {
    let (corner_vertex, classified) = classify(vertex_count, faces)?;
    if classified.boundary.is_empty() {
        let checked = assemble(
            vertex_count,
            faces.len(),
            corner_vertex,
            classified.opposite,
        )?;
        return Ok(OpenCheck::Closed(checked));
    }
    Ok(OpenCheck::Open {
        corner_vertex,
        opposite: classified.opposite,
        boundary: classified.boundary,
    })
}

/// What [`check_open`] found.
pub(super) enum OpenCheck {
    /// No boundary edge: the finished closed surface.
    Closed(Checked),
    /// Boundary edges: the corner-to-vertex array, the gluing of the interior edges
    /// (`NONE` at the corners opposite boundary edges) and those corners.
    Open {
        corner_vertex: Vec<u32>,
        opposite: Vec<u32>,
        boundary: Vec<u32>,
    },
}

/// Number of separate face cycles around `v` (only called on the error path).
fn count_fans(tri: &Triangulation, v: u32) -> usize {
    let corners: Vec<u32> = (0..tri.corner_vertex.len() as u32)
        .filter(|&c| tri.corner_vertex[c as usize] == v)
        .collect();
    let mut seen = std::collections::HashSet::new();
    let mut cycles = 0;
    for &c in &corners {
        if seen.contains(&c) {
            continue;
        }
        cycles += 1;
        for s in tri.star_from(Corner(c)) {
            seen.insert(s.corner.0);
        }
    }
    cycles
}

/// The indices whose `used` flag is false, in increasing order (the mesh vertices no
/// face uses, which the builders drop). O(V).
pub(super) fn unused_vertices(used: &[bool]) -> Vec<u32> {
    used.iter()
        .enumerate()
        .filter(|(_, &u)| !u)
        .map(|(i, _)| i as u32)
        .collect()
}

/// Connected components of the face graph: `label[f]` and the component count. O(F).
pub(super) fn face_components(tri: &Triangulation) -> (Vec<u32>, usize) {
    let nf = tri.face_capacity();
    let mut label = vec![NONE; nf];
    let mut count = 0u32;
    let mut stack = Vec::new();
    for f0 in 0..nf {
        if label[f0] != NONE {
            continue;
        }
        label[f0] = count;
        stack.push(f0 as u32);
        while let Some(f) = stack.pop() {
            for g in tri.face_neighbours(FaceId(f)) {
                if label[g.index()] == NONE {
                    label[g.index()] = count;
                    stack.push(g.0);
                }
            }
        }
        count += 1;
    }
    (label, count as usize)
}

impl Triangulation {
    /// Builds the triangulation of one connected closed surface from `faces` over vertices
    /// `0..vertex_count`, checking everything [`BuildError`] lists. Vertex ids and face ids
    /// are the input indices. O(F) (plus sorting each vertex's edge bucket).
    ///
    /// Strict: unused vertices and several components are errors here; use
    /// [`Surfaces::from_mesh`] to drop or split them.
    pub fn from_faces(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Self, BuildError> {
        let Checked { tri, used } = check(vertex_count, faces)?;
        if let Some(v) = used.iter().position(|&u| !u) {
            return Err(BuildError::UnusedVertex { vertex: v as u32 });
        }
        let (_, components) = face_components(&tri);
        if components != 1 {
            return Err(BuildError::Disconnected { components });
        }
        Ok(tri)
    }
}

/// One connected surface of a mesh, with the map back to the mesh's ids.
#[derive(Clone, Debug)]
pub struct Component {
    /// The surface, with vertices and faces renumbered densely from 0.
    pub tri: Triangulation,
    /// `vertex_origin[v]` is the mesh vertex index of local vertex `v`.
    pub vertex_origin: Vec<u32>,
    /// `face_origin[f]` is the mesh face index of local face `f`.
    pub face_origin: Vec<u32>,
}

/// A mesh validated as a disjoint union of closed surfaces.
#[derive(Clone, Debug)]
pub struct Surfaces {
    /// The connected components, ordered by their smallest mesh face index.
    pub components: Vec<Component>,
    /// Mesh vertices used by no face (dropped; callers should warn).
    pub dropped_vertices: Vec<u32>,
    /// The mesh's vertex count.
    pub mesh_vertex_count: usize,
}

impl Surfaces {
    /// Validates `mesh` (every check of [`Triangulation::from_faces`] except connectivity
    /// and unused vertices), drops unused vertices, and splits it into connected surfaces.
    /// Local ids follow mesh order, so the result is deterministic. O(F).
    pub fn from_mesh(mesh: &TriMesh) -> Result<Self, BuildError> {
        Self::from_faces(mesh.vertex_count, &mesh.faces)
    }

    /// [`Self::from_mesh`] on a bare face list.
    pub fn from_faces(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Self, BuildError> {
        let Checked { tri, used } = check(vertex_count, faces)?;
        let dropped_vertices = unused_vertices(&used);
        let (label, count) = face_components(&tri);
        let components = if count == 1 && dropped_vertices.is_empty() {
            vec![Component {
                vertex_origin: (0..vertex_count as u32).collect(),
                face_origin: (0..faces.len() as u32).collect(),
                tri,
            }]
        } else {
            split(&tri, &label, count)
        };
        Ok(Surfaces {
            components,
            dropped_vertices,
            mesh_vertex_count: vertex_count,
        })
    }

    /// Total vertices, edges, faces over all components.
    pub fn counts(&self) -> (usize, usize, usize) {
        self.components.iter().fold((0, 0, 0), |(v, e, f), c| {
            (
                v + c.tri.vertex_count(),
                e + c.tri.edge_count(),
                f + c.tri.face_count(),
            )
        })
    }
}

/// Extracts each component with dense local ids, in mesh order.
pub(super) fn split(tri: &Triangulation, label: &[u32], count: usize) -> Vec<Component> {
    let nf = tri.face_capacity();
    let mut local_face = vec![NONE; nf];
    let mut face_origin: Vec<Vec<u32>> = vec![Vec::new(); count];
    for f in 0..nf {
        let k = label[f] as usize;
        local_face[f] = face_origin[k].len() as u32;
        face_origin[k].push(f as u32);
    }
    let mut local_vertex = vec![NONE; tri.vertex_capacity()];
    let mut out = Vec::with_capacity(count);
    for origin in face_origin {
        let mut vertex_origin = Vec::new();
        let mut corner_vertex = Vec::with_capacity(3 * origin.len());
        let mut opposite = Vec::with_capacity(3 * origin.len());
        for &f in &origin {
            for c in FaceId(f).corners() {
                let v = tri.corner_vertex[c.index()] as usize;
                if local_vertex[v] == NONE {
                    local_vertex[v] = vertex_origin.len() as u32;
                    vertex_origin.push(v as u32);
                }
                corner_vertex.push(local_vertex[v]);
                let o = tri.opposite(c);
                opposite.push(3 * local_face[o.face().index()] + o.slot());
            }
        }
        let nv = vertex_origin.len();
        let mut vertex_corner = vec![NONE; nv];
        let mut degree = vec![0u32; nv];
        for (c, &v) in corner_vertex.iter().enumerate() {
            degree[v as usize] += 1;
            if vertex_corner[v as usize] == NONE {
                vertex_corner[v as usize] = c as u32;
            }
        }
        let live_faces = origin.len();
        out.push(Component {
            tri: Triangulation {
                corner_vertex,
                opposite,
                vertex_corner,
                degree,
                live_vertices: nv,
                live_faces,
                state: StateStamp::fresh(),
                stamps: Default::default(),
            },
            vertex_origin,
            face_origin: origin,
        });
    }
    out
}
