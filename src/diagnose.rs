//! Every problem of a mesh at once: what keeps a face list from being a surface, counted
//! per kind with the first few located examples of each, and the counts (V, E, F, χ,
//! components, orientability, boundary loops) of what is there.
//!
//! [`crate::Surfaces::from_mesh`] stops at the first problem, which is what an algorithm
//! needs; a person repairing a file needs all of them. This module is that second view,
//! written independently of the builder (it never builds a corner table) and for faces
//! with any number of corners, so it also describes polygon (e.g. quad) meshes.
//!
//! The kinds, in report order ([`ProblemKind`]): no faces, a corner that refers to a
//! missing vertex, a degenerate face (a vertex repeated in one face), a duplicate face
//! (the same vertex set as an earlier face), a non-manifold edge (in 3 or more faces), a
//! pinched vertex (the faces around it form 2 or more separate fans, "sheets", while no
//! non-manifold edge passes through it), and the boundary (edges in exactly one face,
//! grouped into loops: the connected components of the boundary edges). Faces with an
//! out-of-range or repeated vertex are left out of the edge, sheet and orientation
//! analyses (their problem is reported once, as theirs).
//!
//! Guarantees: deterministic (examples in face order, edge order `(a, b)` with `a < b`,
//! or vertex order); no panic for any input, out-of-range indices included. Cost
//! O(C log C) time and O(C) memory for C corners (one sort of the edges and one of the
//! face keys).

use crate::io::PolyMesh;
use crate::mesh::TriMesh;

/// A face list the diagnosis can read: [`TriMesh`] and [`PolyMesh`].
pub trait FaceList {
    /// Number of vertices (indices `>=` it are out of range).
    fn vertex_count(&self) -> usize;
    /// Number of faces.
    fn face_count(&self) -> usize;
    /// The corners of face `i < face_count()`.
    fn corners(&self, i: usize) -> &[u32];
}

impl FaceList for TriMesh {
    fn vertex_count(&self) -> usize {
        self.vertex_count
    }
    fn face_count(&self) -> usize {
        self.faces.len()
    }
    fn corners(&self, i: usize) -> &[u32] {
        self.faces.get(i).map_or(&[], |f| f.as_slice())
    }
}

impl FaceList for PolyMesh {
    fn vertex_count(&self) -> usize {
        self.vertex_count
    }
    fn face_count(&self) -> usize {
        PolyMesh::face_count(self)
    }
    fn corners(&self, i: usize) -> &[u32] {
        self.face(i)
    }
}

/// The kinds of problems, in the order reports list them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum ProblemKind {
    /// The mesh has no faces.
    NoFaces,
    /// A face refers to a vertex that does not exist.
    IndexOutOfRange,
    /// A face repeats a vertex.
    DegenerateFace,
    /// A face has the same vertex set as an earlier face.
    DuplicateFace,
    /// An edge lies in 3 or more faces.
    NonManifoldEdge,
    /// The faces around a vertex form several separate fans.
    PinchedVertex,
    /// Edges in exactly one face (counted in loops).
    Boundary,
}

impl ProblemKind {
    /// A stable snake_case name (for JSON).
    pub fn name(self) -> &'static str {
        match self {
            ProblemKind::NoFaces => "no_faces",
            ProblemKind::IndexOutOfRange => "index_out_of_range",
            ProblemKind::DegenerateFace => "degenerate_face",
            ProblemKind::DuplicateFace => "duplicate_face",
            ProblemKind::NonManifoldEdge => "non_manifold_edge",
            ProblemKind::PinchedVertex => "pinched_vertex",
            ProblemKind::Boundary => "boundary",
        }
    }
}

/// One located problem. Faces and vertices are 0-based indices into the mesh given.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Problem {
    /// The mesh has no faces.
    NoFaces,
    /// Face `face` refers to vertex `vertex >= vertex_count`.
    IndexOutOfRange {
        /// The face.
        face: usize,
        /// The first out-of-range index in it.
        vertex: u32,
    },
    /// Face `face` uses `vertex` more than once.
    DegenerateFace {
        /// The face.
        face: usize,
        /// The first repeated vertex (smallest id).
        vertex: u32,
    },
    /// Face `face` has the vertex set of the earlier face `first`.
    DuplicateFace {
        /// The later face.
        face: usize,
        /// The first face with that vertex set.
        first: usize,
    },
    /// Edge `[a, b]` lies in `faces >= 3` faces, the first of which is `first_face`.
    NonManifoldEdge {
        /// Smaller endpoint.
        a: u32,
        /// Larger endpoint.
        b: u32,
        /// How many faces contain it.
        faces: usize,
        /// The first of them.
        first_face: usize,
    },
    /// `sheets >= 2` separate fans of faces meet at `vertex`.
    PinchedVertex {
        /// The vertex.
        vertex: u32,
        /// How many fans.
        sheets: usize,
    },
    /// A boundary loop of `edges` edges, one of which is `[a, b]` in face `face` (the
    /// loop's smallest edge).
    BoundaryLoop {
        /// Smaller endpoint of the loop's smallest edge.
        a: u32,
        /// Larger endpoint.
        b: u32,
        /// The face containing that edge.
        face: usize,
        /// Number of edges in the loop.
        edges: usize,
    },
}

/// All problems of one kind: how many, and the first few.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProblemGroup {
    /// The kind.
    pub kind: ProblemKind,
    /// How many problems of this kind (faces, edges, vertices or loops).
    pub count: usize,
    /// The first `max_examples` of them, in the module's order.
    pub examples: Vec<Problem>,
}

/// What [`diagnose`] finds.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnosis {
    /// Vertices used by some face (in range).
    pub vertices: usize,
    /// Vertices in `0..vertex_count` used by no face.
    pub unused_vertices: usize,
    /// Distinct edges of the faces without an out-of-range or repeated vertex.
    pub edges: usize,
    /// All faces.
    pub faces: usize,
    /// Connected components (faces sharing a vertex are connected).
    pub components: usize,
    /// `vertices - edges + faces`.
    pub euler_characteristic: i64,
    /// Whether the faces can be oriented consistently (every edge traversed in opposite
    /// directions by its two faces); `None` when a non-manifold edge makes the question
    /// meaningless.
    pub orientable: Option<bool>,
    /// Whether the faces are consistently oriented as given.
    pub consistently_oriented: Option<bool>,
    /// Edges in exactly one face.
    pub boundary_edges: usize,
    /// Connected components of the boundary edges.
    pub boundary_loops: usize,
    /// One group per kind found, in [`ProblemKind`] order (the boundary included).
    pub groups: Vec<ProblemGroup>,
}

impl Diagnosis {
    /// Whether the mesh is a union of surfaces, possibly with boundary: no problem of
    /// any kind but [`ProblemKind::Boundary`].
    pub fn is_surface(&self) -> bool {
        self.groups.iter().all(|g| g.kind == ProblemKind::Boundary)
    }

    /// Whether the mesh is a union of closed surfaces (no problem at all).
    pub fn is_closed_surface(&self) -> bool {
        self.groups.is_empty()
    }

    /// The group of `kind`, if any problem of that kind was found.
    pub fn group(&self, kind: ProblemKind) -> Option<&ProblemGroup> {
        self.groups.iter().find(|g| g.kind == kind)
    }
}

fn find(parent: &mut [u32], mut v: u32) -> u32 {
    while parent[v as usize] != v {
        let p = parent[v as usize];
        parent[v as usize] = parent[p as usize];
        v = p;
    }
    v
}

fn union(parent: &mut [u32], a: u32, b: u32) {
    let (a, b) = (find(parent, a), find(parent, b));
    if a != b {
        let (lo, hi) = (a.min(b), a.max(b));
        parent[hi as usize] = lo;
    }
}

/// A use of an undirected edge by a face.
#[derive(Clone, Copy)]
struct Use {
    key: u64,
    face: u32,
    /// Global corner index at the smaller endpoint, and at the larger.
    at_lo: u32,
    at_hi: u32,
    /// Whether the face runs from the smaller endpoint to the larger.
    forward: bool,
}

/// Finds every problem of `mesh` (see the module docs), keeping at most `max_examples`
/// examples per kind.
pub fn diagnose(mesh: &impl FaceList, max_examples: usize) -> Diagnosis {
    let declared = mesh.vertex_count();
    let nf = mesh.face_count();
    // Only vertices up to the largest index a face uses need room: a larger declared
    // count (even one no machine could allocate) adds unused vertices, nothing else.
    let max_used = (0..nf)
        .flat_map(|f| mesh.corners(f).iter().copied())
        .map(|v| v as usize + 1)
        .max()
        .unwrap_or(0);
    let nv = declared.min(max_used);
    let mut groups: Vec<ProblemGroup> = Vec::new();
    let mut add = |kind: ProblemKind, p: Problem| {
        let g = match groups.iter_mut().position(|g| g.kind == kind) {
            Some(i) => &mut groups[i],
            None => {
                groups.push(ProblemGroup {
                    kind,
                    count: 0,
                    examples: Vec::new(),
                });
                groups.last_mut().expect("just pushed")
            }
        };
        g.count += 1;
        if g.examples.len() < max_examples {
            g.examples.push(p);
        }
    };
    if nf == 0 {
        add(ProblemKind::NoFaces, Problem::NoFaces);
    }

    // Per face: sorted corners (for degeneracy and duplicates); good = in range and no
    // repeated vertex. Corner ids are global positions in face order.
    let mut sorted: Vec<u32> = Vec::new();
    let mut starts: Vec<usize> = Vec::with_capacity(nf + 1);
    let mut good = vec![false; nf];
    let mut used = vec![false; nv];
    for (f, ok) in good.iter_mut().enumerate() {
        let c = mesh.corners(f);
        starts.push(sorted.len());
        let s0 = sorted.len();
        sorted.extend_from_slice(c);
        sorted[s0..].sort_unstable();
        if let Some(&v) = c.iter().find(|&&v| v as usize >= declared) {
            add(
                ProblemKind::IndexOutOfRange,
                Problem::IndexOutOfRange { face: f, vertex: v },
            );
        } else if let Some(w) = sorted[s0..].windows(2).find(|w| w[0] == w[1]) {
            add(
                ProblemKind::DegenerateFace,
                Problem::DegenerateFace {
                    face: f,
                    vertex: w[0],
                },
            );
        } else {
            *ok = true;
        }
        for &v in c {
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    starts.push(sorted.len());
    let key_of = |f: usize| &sorted[starts[f]..starts[f + 1]];

    // Duplicates: good faces ordered by vertex set, then index.
    let mut order: Vec<u32> = (0..nf as u32).filter(|&f| good[f as usize]).collect();
    order.sort_unstable_by(|&a, &b| key_of(a as usize).cmp(key_of(b as usize)).then(a.cmp(&b)));
    let mut dups: Vec<(usize, usize)> = Vec::new();
    for w in order.chunk_by(|&a, &b| key_of(a as usize) == key_of(b as usize)) {
        for &f in &w[1..] {
            dups.push((f as usize, w[0] as usize));
        }
    }
    dups.sort_unstable();
    for (face, first) in dups {
        add(
            ProblemKind::DuplicateFace,
            Problem::DuplicateFace { face, first },
        );
    }

    // Edge uses of the good faces, sorted by edge then face.
    let mut uses: Vec<Use> = Vec::new();
    let mut corner_base = 0usize;
    let mut corner_vertex: Vec<u32> = Vec::new();
    for (f, &ok) in good.iter().enumerate() {
        let c = mesh.corners(f);
        corner_vertex.extend_from_slice(c);
        if ok {
            let k = c.len();
            for i in 0..k {
                let (x, y) = (c[i], c[(i + 1) % k]);
                let (cx, cy) = ((corner_base + i) as u32, (corner_base + (i + 1) % k) as u32);
                let forward = x < y;
                let (lo, hi, at_lo, at_hi) = if forward {
                    (x, y, cx, cy)
                } else {
                    (y, x, cy, cx)
                };
                uses.push(Use {
                    key: (u64::from(lo) << 32) | u64::from(hi),
                    face: f as u32,
                    at_lo,
                    at_hi,
                    forward,
                });
            }
        }
        corner_base += c.len();
    }
    uses.sort_unstable_by_key(|u| (u.key, u.face, u.at_lo));
    let edge_groups: Vec<&[Use]> = uses.chunk_by(|a, b| a.key == b.key).collect();
    let edges = edge_groups.len();

    let ends = |key: u64| ((key >> 32) as u32, key as u32);
    let mut on_nonmanifold = vec![false; nv];
    let mut boundary: Vec<(u32, u32, usize)> = Vec::new();
    // Corners joined across manifold edges: the fans around each vertex.
    let mut corner_parent: Vec<u32> = (0..corner_vertex.len() as u32).collect();
    // Face adjacency across manifold edges, with whether the two faces agree.
    let mut adjacency: Vec<(u32, u32, bool)> = Vec::new();
    for g in &edge_groups {
        let (a, b) = ends(g[0].key);
        match g.len() {
            1 => boundary.push((a, b, g[0].face as usize)),
            2 => {
                union(&mut corner_parent, g[0].at_lo, g[1].at_lo);
                union(&mut corner_parent, g[0].at_hi, g[1].at_hi);
                // Consistent when the two faces run along the edge in opposite directions.
                let agree = g[0].forward != g[1].forward;
                adjacency.push((g[0].face, g[1].face, agree));
                adjacency.push((g[1].face, g[0].face, agree));
            }
            n => {
                on_nonmanifold[a as usize] = true;
                on_nonmanifold[b as usize] = true;
                add(
                    ProblemKind::NonManifoldEdge,
                    Problem::NonManifoldEdge {
                        a,
                        b,
                        faces: n,
                        first_face: g[0].face as usize,
                    },
                );
            }
        }
    }

    // Sheets per vertex: distinct fan roots among the corners of good faces.
    let mut fans: Vec<(u32, u32)> = Vec::new();
    let mut base = 0usize;
    for (f, &ok) in good.iter().enumerate() {
        let k = mesh.corners(f).len();
        if ok {
            for (c, &v) in corner_vertex.iter().enumerate().skip(base).take(k) {
                if !on_nonmanifold[v as usize] {
                    fans.push((v, find(&mut corner_parent, c as u32)));
                }
            }
        }
        base += k;
    }
    fans.sort_unstable();
    fans.dedup();
    for g in fans.chunk_by(|x, y| x.0 == y.0) {
        if g.len() >= 2 {
            add(
                ProblemKind::PinchedVertex,
                Problem::PinchedVertex {
                    vertex: g[0].0,
                    sheets: g.len(),
                },
            );
        }
    }

    // Boundary loops: components of the boundary edges, ordered by their smallest edge
    // (boundary is in edge order already).
    let mut vparent: Vec<u32> = (0..nv).map(|v| v as u32).collect();
    for &(a, b, _) in &boundary {
        union(&mut vparent, a, b);
    }
    let mut loops: Vec<(u32, u32, u32, usize, usize)> = Vec::new(); // root, a, b, face, edges
    let mut loop_of_root: std::collections::HashMap<u32, usize> = std::collections::HashMap::new();
    for &(a, b, face) in &boundary {
        let r = find(&mut vparent, a);
        match loop_of_root.get(&r) {
            Some(&i) => loops[i].4 += 1,
            None => {
                loop_of_root.insert(r, loops.len());
                loops.push((r, a, b, face, 1));
            }
        }
    }
    for &(_, a, b, face, edges) in &loops {
        add(
            ProblemKind::Boundary,
            Problem::BoundaryLoop { a, b, face, edges },
        );
    }

    // Components: vertices joined by good faces (an out-of-range or degenerate face still
    // joins its in-range vertices).
    let mut cparent: Vec<u32> = (0..nv).map(|v| v as u32).collect();
    for f in 0..nf {
        let c = mesh.corners(f);
        let inr: Vec<u32> = c.iter().copied().filter(|&v| (v as usize) < nv).collect();
        for w in inr.windows(2) {
            union(&mut cparent, w[0], w[1]);
        }
    }
    let components = (0..nv)
        .filter(|&v| used[v] && find(&mut cparent, v as u32) == v as u32)
        .count();

    // Orientation, when every edge is in at most two faces.
    let has_nonmanifold = groups
        .iter()
        .any(|g| g.kind == ProblemKind::NonManifoldEdge);
    let (orientable, consistently_oriented) = if has_nonmanifold {
        (None, None)
    } else {
        adjacency.sort_unstable();
        let consistent = adjacency.iter().all(|a| a.2);
        let mut start = vec![0usize; nf + 1];
        for a in &adjacency {
            start[a.0 as usize + 1] += 1;
        }
        for i in 0..nf {
            start[i + 1] += start[i];
        }
        // side[f]: 0 unvisited, 1 as given, 2 flipped.
        let mut side = vec![0u8; nf];
        let mut ok = true;
        let mut stack = Vec::new();
        for s in 0..nf {
            if side[s] != 0 || !good[s] {
                continue;
            }
            side[s] = 1;
            stack.push(s);
            while let Some(f) = stack.pop() {
                for &(_, g, agree) in &adjacency[start[f]..start[f + 1]] {
                    let want = if agree { side[f] } else { 3 - side[f] };
                    let g = g as usize;
                    if side[g] == 0 {
                        side[g] = want;
                        stack.push(g);
                    } else if side[g] != want {
                        ok = false;
                    }
                }
            }
        }
        (Some(ok), Some(consistent))
    };

    let vertices = used.iter().filter(|&&u| u).count();
    groups.sort_by_key(|g| g.kind);
    Diagnosis {
        vertices,
        unused_vertices: declared - vertices,
        edges,
        faces: nf,
        components,
        euler_characteristic: vertices as i64 - edges as i64 + nf as i64,
        orientable,
        consistently_oriented,
        boundary_edges: boundary.len(),
        boundary_loops: loops.len(),
        groups,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;

    fn kinds(d: &Diagnosis) -> Vec<(ProblemKind, usize)> {
        d.groups.iter().map(|g| (g.kind, g.count)).collect()
    }

    #[test]
    fn closed_surfaces_have_no_problem_and_their_counts() {
        let oct = gen::octahedron();
        let d = diagnose(&TriMesh::combinatorial(oct.vertex_count, oct.faces), 5);
        assert!(d.is_closed_surface());
        assert_eq!((d.vertices, d.edges, d.faces), (6, 12, 8));
        assert_eq!((d.euler_characteristic, d.components), (2, 1));
        assert_eq!(d.orientable, Some(true));
        let rp2 = gen::projective_plane6();
        let d = diagnose(&TriMesh::combinatorial(rp2.vertex_count, rp2.faces), 5);
        assert!(d.is_closed_surface());
        assert_eq!((d.euler_characteristic, d.orientable), (1, Some(false)));
    }

    #[test]
    fn every_problem_is_found_at_once() {
        // Tetrahedron 0..3 with face 0 duplicated, a degenerate face, an out-of-range
        // face, and two triangles 4,5,6 / 4,7,8 pinched at 4.
        let faces = vec![
            [0, 1, 2],
            [0, 3, 1],
            [1, 3, 2],
            [2, 3, 0],
            [2, 1, 0],
            [0, 0, 1],
            [0, 1, 99],
            [4, 5, 6],
            [4, 7, 8],
        ];
        let d = diagnose(&TriMesh::combinatorial(9, faces), 1);
        assert_eq!(
            kinds(&d),
            vec![
                (ProblemKind::IndexOutOfRange, 1),
                (ProblemKind::DegenerateFace, 1),
                (ProblemKind::DuplicateFace, 1),
                (ProblemKind::NonManifoldEdge, 3),
                (ProblemKind::PinchedVertex, 1),
                (ProblemKind::Boundary, 1),
            ]
        );
        assert_eq!(
            d.group(ProblemKind::DuplicateFace).unwrap().examples,
            vec![Problem::DuplicateFace { face: 4, first: 0 }]
        );
        assert_eq!(
            d.group(ProblemKind::NonManifoldEdge).unwrap().examples,
            vec![Problem::NonManifoldEdge {
                a: 0,
                b: 1,
                faces: 3,
                first_face: 0
            }]
        );
        assert_eq!(
            d.group(ProblemKind::PinchedVertex).unwrap().examples,
            vec![Problem::PinchedVertex {
                vertex: 4,
                sheets: 2
            }]
        );
        // The two pinched triangles form one boundary component of 6 edges.
        assert_eq!(d.boundary_edges, 6);
        assert_eq!(d.orientable, None);
        assert!(!d.is_surface());
        let empty = diagnose(&TriMesh::combinatorial(0, vec![]), 3);
        assert_eq!(kinds(&empty), vec![(ProblemKind::NoFaces, 1)]);
    }

    /// Cross-check with the independent builder on random small face lists: the builder
    /// accepts exactly what the diagnosis calls a surface (up to the builder's extra
    /// degree rule), and then both agree on V, E, F, χ, components, orientability and
    /// boundary loops.
    #[test]
    fn agrees_with_the_surface_builder_on_random_face_lists() {
        let mut state = 7u64;
        let mut next = |n: u64| {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 33) % n
        };
        let mut accepted = 0;
        for _ in 0..20000 {
            let nv = 3 + next(5) as u32;
            let nf = 1 + next(9) as usize;
            let faces: Vec<[u32; 3]> = (0..nf)
                .map(|_| {
                    [
                        next(nv.into()) as u32,
                        next(nv.into()) as u32,
                        next(nv.into()) as u32,
                    ]
                })
                .collect();
            let mesh = TriMesh::combinatorial(nv as usize, faces);
            let d = diagnose(&mesh, 3);
            match crate::Surfaces::from_mesh_with_boundary(&mesh) {
                Ok(s) => {
                    accepted += 1;
                    assert!(d.is_surface(), "{:?}: {d:?}", mesh.faces);
                    let t: Vec<_> = s.components.iter().map(|c| c.surface_type()).collect();
                    let counts = s.components.iter().map(|c| c.open_counts());
                    let (v, e, f) =
                        counts.fold((0, 0, 0), |a, c| (a.0 + c.0, a.1 + c.1, a.2 + c.2));
                    assert_eq!(
                        (d.vertices, d.edges, d.faces),
                        (v, e, f),
                        "{:?}",
                        mesh.faces
                    );
                    assert_eq!(d.components, s.components.len());
                    assert_eq!(
                        d.euler_characteristic,
                        t.iter().map(|x| x.euler_characteristic()).sum::<i64>()
                    );
                    assert_eq!(d.orientable, Some(t.iter().all(|x| x.is_orientable())));
                    assert_eq!(
                        d.boundary_loops,
                        t.iter().map(|x| x.boundary_loops()).sum::<usize>()
                    );
                }
                Err(e) => assert!(
                    !d.is_surface() || matches!(e, crate::BuildError::VertexDegreeTooLow { .. }),
                    "{:?}: builder says {e}, diagnosis {d:?}",
                    mesh.faces
                ),
            }
        }
        assert!(accepted > 100, "only {accepted} surfaces drawn: weak test");
    }

    #[test]
    fn quads_of_a_cube_are_a_closed_orientable_surface() {
        let cube: Vec<[u32; 4]> = vec![
            [0, 3, 2, 1],
            [4, 5, 6, 7],
            [0, 1, 5, 4],
            [1, 2, 6, 5],
            [2, 3, 7, 6],
            [3, 0, 4, 7],
        ];
        let m = PolyMesh::from_faces(8, None, &cube).unwrap();
        let d = diagnose(&m, 5);
        assert!(d.is_closed_surface(), "{d:?}");
        assert_eq!((d.vertices, d.edges, d.faces), (8, 12, 6));
        assert_eq!(d.euler_characteristic, 2);
        assert_eq!(
            (d.orientable, d.consistently_oriented),
            (Some(true), Some(true))
        );
        // One face reversed: still orientable, no longer consistently oriented; one
        // face removed: one boundary loop of 4 edges.
        let mut flipped = cube.clone();
        flipped[0].reverse();
        let d = diagnose(&PolyMesh::from_faces(8, None, &flipped).unwrap(), 5);
        assert_eq!(
            (d.orientable, d.consistently_oriented),
            (Some(true), Some(false))
        );
        let d = diagnose(&PolyMesh::from_faces(8, None, &cube[1..]).unwrap(), 5);
        assert!(d.is_surface() && !d.is_closed_surface());
        assert_eq!(
            d.group(ProblemKind::Boundary).unwrap().examples,
            vec![Problem::BoundaryLoop {
                a: 0,
                b: 1,
                face: 1,
                edges: 4
            }]
        );
    }
}
