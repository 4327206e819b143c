//! Construction of a [`Triangulation`] from a face list, with full validation.

use super::ids::{Corner, FaceId, VertexId, MAX_FACES, MAX_VERTICES, NONE};
use super::tri::{StateStamp, Triangulation};
use crate::mesh::TriMesh;

#[cfg(feature = "parallel")]
mod parallel;

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
    /// The vertex union-find of the edges (see [`union`]), when the classification
    /// made one; empty otherwise. Either a parent is never larger than its child or
    /// every parent is a root (so one increasing pass flattens it either way).
    parent: Vec<u32>,
}

impl Checked {
    /// Number of connected components. O(V) from the union-find, else O(F).
    pub(super) fn component_count(&self) -> usize {
        if self.parent.is_empty() {
            return face_components(&self.tri).1;
        }
        let mut roots = 0;
        for (v, &p) in self.parent.iter().enumerate() {
            roots += usize::from(p == v as u32 && self.used[v]);
        }
        roots
    }

    /// The connected components of the face graph: `label[f]` (numbered in order of
    /// each component's smallest face) and their count. O(F + V).
    pub(super) fn face_components(&self) -> (Vec<u32>, usize) {
        if self.parent.is_empty() {
            return face_components(&self.tri);
        }
        // A closed surface's faces are connected exactly when its vertices are: each
        // vertex's faces form one fan (phase 4 checked it), and an edge's two faces
        // contain both its endpoints.
        let mut root = self.parent.clone();
        for v in 0..root.len() {
            root[v] = root[root[v] as usize];
        }
        let mut id = vec![NONE; root.len()];
        let mut count = 0u32;
        let label = self
            .tri
            .corner_vertex
            .chunks_exact(3)
            .map(|f| {
                let r = root[f[0] as usize] as usize;
                if id[r] == NONE {
                    id[r] = count;
                    count += 1;
                }
                id[r]
            })
            .collect();
        (label, count as usize)
    }
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

/// What is wrong with input face `face`, which has an index out of range or a
/// repeated vertex: the first index out of range, else the repetition.
fn face_problem(vertex_count: usize, face: usize, vertices: [u32; 3]) -> BuildError {
    match vertices.iter().find(|&&v| v as usize >= vertex_count) {
        Some(&vertex) => BuildError::VertexOutOfRange {
            face,
            vertex,
            vertex_count,
        },
        None => BuildError::DegenerateFace { face, vertices },
    }
}

/// Whether face `f` has an index out of `0..n` or a repeated vertex ([`face_problem`]
/// says which). One test for both problems: valid faces (nearly all) take a single
/// branch.
#[inline]
fn face_is_bad(f: [u32; 3], n: usize) -> bool {
    let [a, b, c] = f.map(|v| v as usize);
    (a >= n) | (b >= n) | (c >= n) | (a == b) | (b == c) | (a == c)
}

/// Where each vertex's corners start in the corners grouped by vertex: the running sum
/// of the degrees before it.
fn run_starts(degree: &[u32]) -> Vec<u32> {
    let mut start = Vec::with_capacity(degree.len());
    let mut sum = 0u32;
    for &d in degree {
        start.push(sum);
        sum += d;
    }
    start
}

/// Phase 1 output: the corner-to-vertex array (the faces, flattened) and the number of
/// corners at each vertex.
#[cfg_attr(test, derive(Clone))]
struct Scanned {
    corner_vertex: Vec<u32>,
    degree: Vec<u32>,
}

/// Phase 1: sizes, every index in range, no repeated vertex (the first face with a
/// problem is the error); the corners per vertex; the corner-to-vertex array. O(F + V).
fn scan_faces(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Scanned, BuildError> {
    check_sizes(vertex_count, faces)?;
    let mut degree = vec![0u32; vertex_count];
    let n = degree.len();
    for (i, &f) in faces.iter().enumerate() {
        if face_is_bad(f, n) {
            return Err(face_problem(vertex_count, i, f));
        }
        let [a, b, c] = f.map(|v| v as usize);
        degree[a] += 1;
        degree[b] += 1;
        degree[c] += 1;
    }
    let corner_vertex = faces.as_flattened().to_vec();
    Ok(Scanned {
        corner_vertex,
        degree,
    })
}

/// Phase 2 output: the corners at each vertex, increasing. Vertex `v`'s corners are
/// `corners[end[v - 1]..end[v]]` (from 0 for `v = 0`).
struct VertexCorners {
    end: Vec<u32>,
    corners: Vec<u32>,
}

/// Phase 2: the corners grouped by vertex, by a counting sort on the vertex (the
/// degrees are the counts). O(F + V).
fn vertex_corners(corner_vertex: &[u32], degree: &[u32]) -> VertexCorners {
    let mut end = run_starts(degree);
    // `end[v]` starts as the beginning of `v`'s run and, after each corner of `v` is
    // placed, is its end.
    let mut corners = vec![0u32; corner_vertex.len()];
    for (c, &v) in corner_vertex.iter().enumerate() {
        let slot = &mut end[v as usize];
        corners[*slot as usize] = c as u32;
        *slot += 1;
    }
    VertexCorners { end, corners }
}

#[cfg(feature = "parallel")]
impl VertexCorners {
    /// The corners at `v`, increasing.
    fn corners_of(&self, v: u32) -> &[u32] {
        let v = v as usize;
        let begin = if v == 0 { 0 } else { self.end[v - 1] as usize };
        &self.corners[begin..self.end[v] as usize]
    }
}

/// What is wrong with one pair of endpoints held by other than two faces, as phase 3
/// classifies it (two faces, an interior edge, is glued on the spot and never
/// classified).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum EdgeClass {
    /// One face: a boundary edge (an error for closed surfaces; the classified case a
    /// surface-with-boundary builder keeps).
    Boundary,
    /// An odd number ≥ 3 of faces: non-manifold.
    NonManifold,
    /// An even number ≥ 4 of faces: several edges with the same endpoints.
    Multiple,
}

impl EdgeClass {
    /// The class of an endpoint pair held by `faces` faces, `faces` ≠ 2.
    fn of(faces: usize) -> Self {
        match faces {
            1 => EdgeClass::Boundary,
            n if n % 2 == 1 => EdgeClass::NonManifold,
            _ => EdgeClass::Multiple,
        }
    }
}

/// Phase 3 output: the gluing of interior edges, the corners of boundary edges, the
/// first problem of each kind (reported in a fixed order of precedence by the caller),
/// and the vertex union-find of the edges (for the connected components).
struct Classified {
    opposite: Vec<u32>,
    /// Corners opposite a boundary edge (their `opposite` entry is `NONE`), in
    /// edge order (smaller endpoint, then larger endpoint).
    boundary: Vec<u32>,
    duplicate: Option<BuildError>,
    bad_edge: Option<BuildError>,
    first_boundary: Option<BuildError>,
    /// The first vertex-link problem in vertex order; only meaningful (and only
    /// looked for) while every edge so far lies in exactly two faces. Read only when
    /// there is no boundary edge: with one, which links were looked at before it
    /// depends on the visiting order, and the renumbered order may differ here.
    first_link: Option<BuildError>,
    /// Every edge met so far lies in exactly two faces.
    clean: bool,
    /// The union-find of the vertices joined by edges ([`union`]).
    parent: Vec<u32>,
    /// The smallest corner at each vertex (`NONE` if unused).
    vertex_corner: Vec<u32>,
}

/// Phase 3, one vertex at a time in increasing order: the edges from `v` to larger
/// neighbours (each pair of endpoints once, as its smaller endpoint's), sorted and
/// grouped by the larger endpoint; interior edges are glued and the rest classified
/// ([`EdgeClass`]); duplicate faces are two faces on one edge with the same third
/// vertex. Once `v`'s own edges are glued, every edge at `v` is (the others belong to
/// smaller vertices), so while the surface is clean so far, `v`'s star walk checks its
/// link there and then, while its faces are in cache. O(F + V) plus sorting each
/// vertex's edges (about three on a typical surface).
fn classify_edges(scanned: &Scanned, by_vertex: &VertexCorners, faces: &[[u32; 3]]) -> Classified {
    let corner_vertex = &scanned.corner_vertex[..];
    let vertex_count = scanned.degree.len();
    let mut out = Classified {
        // Zeroed, not filled: the allocation comes from the system already zeroed, and
        // every entry is written below (glued, or `NONE` on a boundary edge) unless an
        // edge error discards the whole table.
        opposite: vec![0; corner_vertex.len()],
        boundary: Vec::new(),
        duplicate: None,
        bad_edge: None,
        first_boundary: None,
        first_link: None,
        clean: true,
        parent: (0..vertex_count as u32).collect(),
        vertex_corner: vec![NONE; vertex_count],
    };
    let mut bucket: Vec<u64> = Vec::new();
    // The link edge [a, b] of each face at the vertex (its other two vertices).
    let mut ends: Vec<(u32, u32)> = Vec::new();
    let mut begin = 0usize;
    for (v, &end) in by_vertex.end.iter().enumerate() {
        let corners = &by_vertex.corners[begin..end as usize];
        begin = end as usize;
        if corners.is_empty() {
            continue;
        }
        let lo = v as u32;
        out.vertex_corner[v] = corners[0];
        gather_edges(corner_vertex, lo, corners, &mut bucket, &mut ends);
        // The runs of equal larger endpoints by hand, not by [`edge_runs`] as on the
        // pool: here `chunk_by` measured 6-11 % slower (`build_b0_threads/1`).
        let b = &bucket[..];
        let mut i = 0;
        while i < b.len() {
            let hi = b[i] >> 32;
            let mut j = i + 1;
            while j < b.len() && b[j] >> 32 == hi {
                j += 1;
            }
            let (run, hi) = (&b[i..j], hi as u32);
            i = j;
            union(&mut out.parent, lo, hi);
            if let [p, q] = *run {
                // The common case, an interior edge, without `classify_run`'s general
                // bookkeeping (same checks, same order).
                let (p, q) = ((p & 0xffff_ffff) as usize, (q & 0xffff_ffff) as usize);
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
            } else {
                out.clean = false;
                classify_run(run, (lo, hi), corner_vertex, faces, &mut out);
            }
        }
        if out.clean && out.first_link.is_none() {
            let cycles = if ends.len() <= SMALL_LINK {
                link_cycles(&ends)
            } else {
                fans(corner_vertex, &out.opposite, lo, corners)
            };
            out.first_link = link_problem(lo, cycles, ends.len());
        }
    }
    out
}

/// The edges from `lo` to larger neighbours, each as `(larger endpoint << 32) | corner
/// opposite the edge` (so that the bucket sorts without indirection), sorted into
/// `bucket`; and into `ends` the link edge of each face at `lo` (its other two
/// vertices), in the order of `corners`, `lo`'s corners.
#[inline]
fn gather_edges(
    corner_vertex: &[u32],
    lo: u32,
    corners: &[u32],
    bucket: &mut Vec<u64>,
    ends: &mut Vec<(u32, u32)>,
) {
    bucket.clear();
    ends.clear();
    for &c in corners {
        let (next, prev) = (Corner(c).next().0, Corner(c).prev().0);
        let (a, b) = (corner_vertex[next as usize], corner_vertex[prev as usize]);
        ends.push((a, b));
        // The edge [lo, a] is opposite the corner at b, and [lo, b] opposite a's.
        if a > lo {
            bucket.push(((a as u64) << 32) | prev as u64);
        }
        if b > lo {
            bucket.push(((b as u64) << 32) | next as u64);
        }
    }
    sort_bucket(bucket);
}

/// The runs of a sorted bucket ([`gather_edges`]) with the same larger endpoint: the
/// corners opposite one pair of endpoints each.
#[cfg(feature = "parallel")]
#[inline]
fn edge_runs(bucket: &[u64]) -> impl Iterator<Item = &[u64]> {
    bucket.chunk_by(|x, y| x >> 32 == y >> 32)
}

/// Phase 1 on rayon's pool where the `parallel` feature is on and the pool and the
/// surface are large enough ([`parallel::scan_faces`]), else [`scan_faces`]: the same
/// result either way.
fn scan_faces_on_pool(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Scanned, BuildError> {
    #[cfg(feature = "parallel")]
    if let Some(scanned) = parallel::scan_faces(vertex_count, faces) {
        return scanned;
    }
    scan_faces(vertex_count, faces)
}

/// Phase 2 on rayon's pool where the `parallel` feature is on and the pool and the
/// surface are large enough ([`parallel::vertex_corners`]), else [`vertex_corners`]:
/// the same result either way.
fn vertex_corners_on_pool(corner_vertex: &[u32], degree: &[u32]) -> VertexCorners {
    #[cfg(feature = "parallel")]
    if let Some(by_vertex) = parallel::vertex_corners(corner_vertex, degree) {
        return by_vertex;
    }
    vertex_corners(corner_vertex, degree)
}

/// Phase 3 on rayon's pool where the `parallel` feature is on and the pool and the
/// surface are large enough ([`parallel::classify_edges`]), else (or where it leaves the
/// surface's problem to this pass) [`classify_edges`]: the same result either way.
fn classify_edges_on_pool(
    scanned: &Scanned,
    by_vertex: &VertexCorners,
    faces: &[[u32; 3]],
) -> Classified {
    #[cfg(feature = "parallel")]
    if let Some(classified) = parallel::classify_edges(scanned, by_vertex, faces) {
        return classified;
    }
    classify_edges(scanned, by_vertex, faces)
}

/// Joins the sets of `x` and `y` (Rem's union-find with splicing: a parent is never
/// larger than its child, so one increasing pass afterwards flattens every path).
fn union(parent: &mut [u32], mut x: u32, mut y: u32) {
    while parent[x as usize] != parent[y as usize] {
        if parent[x as usize] < parent[y as usize] {
            std::mem::swap(&mut x, &mut y);
        }
        let px = parent[x as usize];
        let py = parent[y as usize];
        if px == x {
            parent[x as usize] = py;
            return;
        }
        parent[x as usize] = py;
        x = px;
    }
}

/// Phase 4 for one vertex with `cycles` separate cycles of faces around it, `faces` in
/// all: its link must be one cycle, and there must be at least 3 faces.
fn link_problem(v: u32, cycles: usize, faces: usize) -> Option<BuildError> {
    if cycles != 1 {
        return Some(BuildError::VertexLinkNotCycle {
            vertex: v,
            cycles,
            faces,
        });
    }
    if faces < 3 {
        return Some(BuildError::VertexDegreeTooLow {
            vertex: v,
            degree: faces,
        });
    }
    None
}

/// Vertices with at most this many faces have their link checked on the link edges
/// gathered for the classification ([`link_cycles`], quadratic in the degree but
/// without a memory access), larger ones by star walks ([`fans`]).
const SMALL_LINK: usize = 32;

/// The number of cycles formed by the link edges `ends` (one per face at a vertex),
/// when each link vertex lies on exactly two of them (every edge at the vertex is in two
/// faces): the number of fans of faces around the vertex. Otherwise (a link vertex on
/// three or more of them) it still returns, with a count that means nothing: only the
/// parallel classification calls it there, and discards it (the edge in three or more
/// faces fails that pass). O(len²).
fn link_cycles(ends: &[(u32, u32)]) -> usize {
    debug_assert!(ends.len() <= SMALL_LINK);
    let mut visited = 0u64;
    let mut cycles = 0;
    for s in 0..ends.len() {
        if visited & (1 << s) != 0 {
            continue;
        }
        // `s` itself is not marked: the outer loop has passed it, and the walk stops
        // when it is back at `s` without reading `visited`.
        cycles += 1;
        let (mut at, mut through) = (s, ends[s].1);
        // The other link edge with the link vertex `through`, until back at `s`. A
        // cycle has at most `len` edges; the bound stops the walk where a link vertex
        // lies on three or more link edges, which the parallel classification may meet
        // (an edge in three faces glued by another range): the count is then not 1.
        let mut steps = 0;
        while let Some(next) =
            (0..ends.len()).find(|&j| j != at && (ends[j].0 == through || ends[j].1 == through))
        {
            if next == s {
                break;
            }
            steps += 1;
            if steps > ends.len() {
                return usize::MAX;
            }
            visited |= 1 << next;
            through = if ends[next].0 == through {
                ends[next].1
            } else {
                ends[next].0
            };
            at = next;
        }
    }
    cycles
}

/// The number of fans of faces around `v` (whose edges are all glued), by star walks
/// from each of its `corners` not yet visited; one walk when the first fan holds them all.
fn fans(corner_vertex: &[u32], opposite: &[u32], v: u32, corners: &[u32]) -> usize {
    if fan_len(corner_vertex, opposite, v, corners[0]) == corners.len() {
        return 1;
    }
    let mut in_fan = std::collections::HashSet::new();
    let mut cycles = 0;
    for &c in corners {
        if !in_fan.contains(&c) {
            cycles += 1;
            fan_corners(corner_vertex, opposite, v, c, &mut in_fan);
        }
    }
    cycles
}

/// The corner at `centre` following `c` in a star walk that leaves `c`'s face by the
/// edge opposite `exit`: the same step as [`Triangulation::star`], on the bare arrays
/// (the triangulation does not exist yet). Returns the corner and the next exit.
#[inline]
fn fan_step(corner_vertex: &[u32], opposite: &[u32], centre: u32, exit: u32) -> (u32, u32) {
    let o = Corner(opposite[exit as usize]);
    let n = o.next();
    // Leave the new face by its other edge at the centre: the one opposite the corner
    // that is neither the centre's nor `o`.
    if corner_vertex[n.index()] == centre {
        (n.0, o.prev().0)
    } else {
        (o.prev().0, n.0)
    }
}

/// Number of corners on the fan of `centre` through corner `c` (a closed walk: every
/// edge at `centre` is glued).
fn fan_len(corner_vertex: &[u32], opposite: &[u32], centre: u32, c: u32) -> usize {
    let mut len = 1;
    let (mut at, mut exit) = fan_step(corner_vertex, opposite, centre, Corner(c).next().0);
    while at != c {
        len += 1;
        (at, exit) = fan_step(corner_vertex, opposite, centre, exit);
    }
    len
}

/// Records in `seen` the corners of the fan of `centre` through corner `c` (the error
/// path only).
fn fan_corners(
    corner_vertex: &[u32],
    opposite: &[u32],
    centre: u32,
    c: u32,
    seen: &mut std::collections::HashSet<u32>,
) {
    seen.insert(c);
    let (mut at, mut exit) = fan_step(corner_vertex, opposite, centre, Corner(c).next().0);
    while at != c {
        seen.insert(at);
        (at, exit) = fan_step(corner_vertex, opposite, centre, exit);
    }
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

/// Phase 3 for one endpoint pair `[a, b]` held by the corners of `run`, which are not
/// two (an interior edge takes the fast path in [`classify_edges`]).
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
        EdgeClass::Boundary => {
            out.opposite[corner(0)] = NONE;
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

/// Phase 4 on a fully glued corner table built some other way (the coned surfaces of
/// module `boundary`): with every edge in exactly two faces, each used vertex's star
/// walk must visit all its corners (its link is one cycle) and there must be at least
/// 3. O(F).
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

/// Phases 1-3 on a face list: sizes and faces, corners by vertex, edge classification
/// (with the vertex links while the surface is clean). The first face error, duplicate
/// face or non-manifold / multiple edge is an error here (in that precedence); boundary
/// edges and vertex links are left to the caller.
fn classify(vertex_count: usize, faces: &[[u32; 3]]) -> Result<(Scanned, Classified), BuildError> {
    let mut scanned = scan_faces_on_pool(vertex_count, faces)?;
    if scattered(faces) {
        if let Some(classified) = classify_renumbered(&mut scanned, faces) {
            return Ok((scanned, classified));
        }
    }
    let classified = classify_in_id_order(faces, &scanned)?;
    Ok((scanned, classified))
}

/// Phases 2-3 in vertex id order, the order that defines which problem is reported.
fn classify_in_id_order(faces: &[[u32; 3]], scanned: &Scanned) -> Result<Classified, BuildError> {
    let by_vertex = vertex_corners_on_pool(&scanned.corner_vertex, &scanned.degree);
    let mut classified = classify_edges_on_pool(scanned, &by_vertex, faces);
    if let Some(e) = classified.duplicate.take().or(classified.bad_edge.take()) {
        return Err(e);
    }
    Ok(classified)
}

/// Ids this far apart (or more) at the same slot of consecutive faces are *far*: the
/// per-vertex data between them spans more than the caches hold.
const FAR_IDS: u32 = 1 << 16;

/// Whether the vertex ids are scattered over the face list: at more than a quarter of
/// the slots of a sample of consecutive faces (every eighth pair, O(F/8)), the ids are
/// [`FAR_IDS`] apart. Then [`classify_renumbered`] pays for its two passes several times
/// over (B0 with shuffled ids: 0.73 of the pairs far, build 4.4× faster renumbered);
/// where they are not, it would cost 10-15 % (B0 in the generator's order: 0.02; every
/// closed mesh of the shared corpus, 10k-200k faces: 0, none has ids that far apart).
fn scattered(faces: &[[u32; 3]]) -> bool {
    let (mut far, mut slots) = (0usize, 0usize);
    for pair in faces.windows(2).step_by(8) {
        for (a, b) in pair[0].iter().zip(&pair[1]) {
            far += usize::from(a.abs_diff(*b) >= FAR_IDS);
        }
        slots += 3;
    }
    4 * far > slots
}

/// Phases 2-3 with the vertices numbered in order of first appearance in the face list,
/// mapped back to the input's ids: the same result as [`classify_in_id_order`], array
/// for array, when there is nothing to report. Why: phase 3 visits each vertex's corners
/// and their neighbours, which lie together in the face list when the ids follow it and
/// all over it when they do not (ids from scans and modelling tools); on B0 with its ids
/// shuffled the build was 7× slower (docs/benchmarks.md). Renumbering costs one pass
/// over the corners and one back, which [`scattered`] decides are worth paying.
///
/// `None`, with `scanned` as it was, when the ids already are in that order, or when
/// the surface has a problem (a duplicate face, an edge not in exactly two faces except
/// where a boundary is fine, a vertex link), which is then found and reported in id
/// order, its documented precedence. Boundary edges are kept, in the id order of their
/// endpoints, as [`classify_in_id_order`] lists them.
fn classify_renumbered(scanned: &mut Scanned, faces: &[[u32; 3]]) -> Option<Classified> {
    let n = scanned.degree.len();
    let mut new_id = vec![NONE; n];
    let mut old_id: Vec<u32> = Vec::new();
    let mut identity = true;
    for v in scanned.corner_vertex.iter_mut() {
        let mut k = new_id[*v as usize];
        if k == NONE {
            k = old_id.len() as u32;
            new_id[*v as usize] = k;
            old_id.push(*v);
            identity &= k == *v;
        }
        *v = k;
    }
    if identity {
        // Every corner kept its id: `scanned` is unchanged.
        return None;
    }
    let renumbered = Scanned {
        corner_vertex: std::mem::take(&mut scanned.corner_vertex),
        degree: old_id.iter().map(|&v| scanned.degree[v as usize]).collect(),
    };
    let by_vertex = vertex_corners_on_pool(&renumbered.corner_vertex, &renumbered.degree);
    let mut classified = classify_edges_on_pool(&renumbered, &by_vertex, faces);
    drop(by_vertex);
    let mut corner_vertex = renumbered.corner_vertex;
    for v in corner_vertex.iter_mut() {
        *v = old_id[*v as usize];
    }
    scanned.corner_vertex = corner_vertex;
    let closed_and_sound = classified.clean && classified.first_link.is_none();
    let bounded_and_sound = classified.duplicate.is_none()
        && classified.bad_edge.is_none()
        && !classified.boundary.is_empty();
    if !closed_and_sound && !bounded_and_sound {
        return None;
    }
    let corner_vertex = &scanned.corner_vertex;
    // The endpoints of the edge opposite corner `c`, smaller first.
    let edge = |c: u32| {
        let (a, b) = (
            corner_vertex[Corner(c).next().index()],
            corner_vertex[Corner(c).prev().index()],
        );
        (a.min(b), a.max(b))
    };
    // In id order the boundary edges come by smaller, then larger endpoint, and the
    // first of them is the one [`check`] reports.
    classified.boundary.sort_unstable_by_key(|&c| edge(c));
    classified.first_boundary = classified.boundary.first().map(|&c| {
        let (a, b) = edge(c);
        BuildError::BoundaryEdge {
            a,
            b,
            face: c as usize / 3,
        }
    });
    let mut vertex_corner = vec![NONE; n];
    for (k, &v) in old_id.iter().enumerate() {
        vertex_corner[v as usize] = classified.vertex_corner[k];
    }
    classified.vertex_corner = vertex_corner;
    // The union-find, flattened (one increasing pass suffices, see [`union`]) and
    // carried to the input's ids; unused vertices are their own roots.
    let parent = &mut classified.parent;
    for k in 0..parent.len() {
        parent[k] = parent[parent[k] as usize];
    }
    classified.parent = new_id
        .iter()
        .enumerate()
        .map(|(v, &k)| {
            if k == NONE {
                v as u32
            } else {
                old_id[parent[k as usize] as usize]
            }
        })
        .collect();
    Some(classified)
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
    Ok(Checked {
        tri,
        used,
        parent: Vec::new(),
    })
}

/// The closed surface classified without problems: its corner table, with the link
/// problem found on the way (if any) as the error.
fn finish_closed(
    faces: usize,
    scanned: Scanned,
    classified: Classified,
) -> Result<Checked, BuildError> {
    if let Some(e) = classified.first_link {
        return Err(e);
    }
    let Scanned {
        corner_vertex,
        degree,
    } = scanned;
    let used: Vec<bool> = degree.iter().map(|&d| d != 0).collect();
    let tri = Triangulation {
        corner_vertex,
        opposite: classified.opposite,
        vertex_corner: classified.vertex_corner,
        degree,
        live_vertices: used.iter().filter(|&&u| u).count(),
        live_faces: faces,
        state: StateStamp::fresh(),
        stamps: Default::default(),
    };
    Ok(Checked {
        tri,
        used,
        parent: classified.parent,
    })
}

/// Validates a face list as a possibly disconnected closed surface and builds its corner
/// table, in four phases: sizes and faces, corners by vertex, edge classification
/// (gluing), vertex links (the last two in one pass over the vertices). Errors are
/// reported in a fixed precedence: the first face error, then duplicate faces, then
/// non-manifold or multiple edges, then boundary edges, then vertex links (the first
/// in vertex order).
pub(super) fn check(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Checked, BuildError> {
    let (scanned, classified) = classify(vertex_count, faces)?;
    if let Some(e) = classified.first_boundary {
        return Err(e);
    }
    debug_assert!(classified.boundary.is_empty());
    finish_closed(faces.len(), scanned, classified)
}

/// Phases 1-3 for a surface that may have boundary: the face and edge errors of
/// [`check`] except boundary edges, which are returned as the corners opposite them
/// (in edge order). If there are none, the closed surface is finished too (phase 4),
/// so that a closed mesh costs what [`check`] costs.
pub(super) fn check_open(vertex_count: usize, faces: &[[u32; 3]]) -> Result<OpenCheck, BuildError> {
    let (scanned, classified) = classify(vertex_count, faces)?;
    if classified.boundary.is_empty() {
        let checked = finish_closed(faces.len(), scanned, classified)?;
        return Ok(OpenCheck::Closed(checked));
    }
    Ok(OpenCheck::Open {
        corner_vertex: scanned.corner_vertex,
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
        let checked = check(vertex_count, faces)?;
        if let Some(v) = checked.used.iter().position(|&u| !u) {
            return Err(BuildError::UnusedVertex { vertex: v as u32 });
        }
        let components = checked.component_count();
        if components != 1 {
            return Err(BuildError::Disconnected { components });
        }
        Ok(checked.tri)
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
        let checked = check(vertex_count, faces)?;
        let dropped_vertices = unused_vertices(&checked.used);
        let components = if checked.component_count() == 1 && dropped_vertices.is_empty() {
            vec![Component {
                vertex_origin: (0..vertex_count as u32).collect(),
                face_origin: (0..faces.len() as u32).collect(),
                tri: checked.tri,
            }]
        } else {
            let (label, count) = checked.face_components();
            split(&checked.tri, &label, count)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::random::{random, RandomParams, SurfaceKind};
    use crate::rng::Rng;

    /// Everything [`classify`] hands on, with the union-find as the smallest vertex of
    /// each vertex's set (the partition, whatever the tree).
    type Outcome = (
        Vec<u32>,
        Vec<u32>,
        Vec<u32>,
        Vec<u32>,
        Vec<u32>,
        Option<BuildError>,
        Option<BuildError>,
    );

    fn outcome(scanned: Scanned, c: Classified) -> Outcome {
        let mut root = c.parent;
        for v in 0..root.len() {
            root[v] = root[root[v] as usize];
        }
        let mut least = vec![NONE; root.len()];
        for (v, &r) in root.iter().enumerate() {
            least[r as usize] = least[r as usize].min(v as u32);
        }
        let set = root.iter().map(|&r| least[r as usize]).collect();
        // Unread when there is a boundary (see `Classified::first_link`).
        let first_link = c.first_link.filter(|_| c.boundary.is_empty());
        (
            scanned.corner_vertex,
            c.opposite,
            c.boundary,
            c.vertex_corner,
            set,
            c.first_boundary,
            first_link,
        )
    }

    /// The renumbered phases, where they answer (`None` where they hand over to the
    /// id order).
    fn renumbered_outcome(n: usize, faces: &[[u32; 3]]) -> Option<Outcome> {
        let mut scanned = scan_faces(n, faces).expect("faces in range");
        let c = classify_renumbered(&mut scanned, faces)?;
        Some(outcome(scanned, c))
    }

    /// The phases in id order only.
    fn in_id_order(n: usize, faces: &[[u32; 3]]) -> Result<Outcome, BuildError> {
        let scanned = scan_faces(n, faces)?;
        let c = classify_in_id_order(faces, &scanned)?;
        Ok(outcome(scanned, c))
    }

    /// Round `round` of the build tests' surfaces: random closed surfaces of 20-80
    /// faces (spheres, orientable and non-orientable of genus up to 3), with by round
    /// modulo 6: a disjoint second copy and an unused vertex between (1), a hole or two
    /// (2), a repeated face (3), two vertices identified (4, a pinched vertex or a
    /// non-manifold edge). Returns the vertex count and the faces.
    fn test_surface(round: u64, rng: &mut Rng) -> (usize, Vec<[u32; 3]>) {
        let surface = match round % 3 {
            0 => SurfaceKind::Orientable(0),
            1 => SurfaceKind::Orientable(1 + (round % 2) as u32),
            _ => SurfaceKind::NonOrientable(1 + (round % 3) as u32),
        };
        let tri = random(&RandomParams {
            surface,
            min_faces: 20 + rng.index(60),
            flip_percent: 30,
            seed: round,
        })
        .expect("random surface");
        let mut faces = tri.face_list();
        let mut n = tri.vertex_capacity();
        match round % 6 {
            1 => {
                let shift = n as u32 + 1;
                let copy: Vec<[u32; 3]> = faces.iter().map(|f| f.map(|v| v + shift)).collect();
                faces.extend(copy);
                n = 2 * n + 1;
            }
            2 => {
                for _ in 0..1 + rng.index(2) {
                    faces.swap_remove(rng.index(faces.len()));
                }
            }
            3 => faces.push(faces[rng.index(faces.len())]),
            4 => {
                let (a, b) = (rng.index(n) as u32, rng.index(n) as u32);
                for f in faces.iter_mut() {
                    for v in f.iter_mut() {
                        if *v == b {
                            *v = a;
                        }
                    }
                }
                faces.retain(|f| f[0] != f[1] && f[1] != f[2] && f[0] != f[2]);
            }
            _ => {}
        }
        (n, faces)
    }

    /// Numbering the vertices in order of first appearance changes only the order in
    /// which they are visited: on closed surfaces, bounded ones, several components with
    /// unused vertices, and faulty ones (duplicate faces, non-manifold edges, pinched
    /// vertices), each with shuffled ids, every array, the boundary list and its first
    /// edge, the link verdict, the components and the error are those of the id order.
    #[test]
    fn renumbering_changes_nothing_but_the_visiting_order() {
        let mut rng = Rng::new(11);
        let mut taken = [0usize; 2];
        for round in 0..300u64 {
            let (n, faces) = test_surface(round, &mut rng);
            let mut id: Vec<u32> = (0..n as u32).collect();
            rng.shuffle(&mut id);
            let shuffled: Vec<[u32; 3]> = faces.iter().map(|f| f.map(|v| id[v as usize])).collect();
            match renumbered_outcome(n, &shuffled) {
                Some(r) => {
                    assert_eq!(
                        Ok(r),
                        in_id_order(n, &shuffled),
                        "round {round}: {shuffled:?}"
                    );
                    taken[1] += 1;
                }
                None => taken[0] += 1,
            }
        }
        // The renumbered phases answered for the sound inputs and handed the faulty
        // ones (and those with unused vertices in id order) over.
        assert!(taken[0] >= 50 && taken[1] >= 100, "{taken:?}");
    }

    /// Where a link vertex lies on three link edges (an edge in three faces, which the
    /// parallel classification may meet in another range), the walk from an edge off the
    /// triangle of the other three would circle that triangle for ever; it stops, with a
    /// count other than 1. A cycle is counted as one.
    #[test]
    fn link_cycles_stops_where_a_link_vertex_has_three_edges() {
        assert_eq!(link_cycles(&[(1, 2), (2, 3), (3, 1)]), 1);
        assert_ne!(link_cycles(&[(1, 2), (2, 3), (3, 1), (9, 1)]), 1);
    }

    /// Two cones over an `m`-gon glued along it (a sphere whose two apexes have `m`
    /// faces each); with `pinched`, a second such sphere sharing the first's north apex
    /// (a vertex whose link is two cycles of `m` faces).
    fn double_cones(m: u32, pinched: bool) -> (usize, Vec<[u32; 3]>) {
        let mut faces = Vec::new();
        let mut sphere = |ring: u32, north: u32, south: u32| {
            for i in 0..m {
                let (a, b) = (ring + i, ring + (i + 1) % m);
                faces.push([north, a, b]);
                faces.push([south, b, a]);
            }
        };
        sphere(0, m, m + 1);
        if pinched {
            sphere(m + 2, m, 2 * m + 2);
        }
        let n = if pinched { 2 * m + 3 } else { m + 2 };
        (n as usize, faces)
    }

    /// A rayon pool of `threads` threads.
    #[cfg(feature = "parallel")]
    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
    }

    /// The classification on the pool answers exactly as the sequential pass wherever it
    /// answers, and answers for every sound surface, closed or bounded: the build tests'
    /// surfaces (each also with shuffled ids) and double cones with apexes of 20, 40 and
    /// 70 faces (links checked in the range, and walked after the join), pinched or not,
    /// split into 1 to 9 ranges on pools of 2 and 3 threads.
    #[cfg(feature = "parallel")]
    #[test]
    fn the_classification_on_the_pool_is_the_sequential_one() {
        let pools = [pool(2), pool(3)];
        let mut rng = Rng::new(5);
        let mut inputs = Vec::new();
        for round in 0..300u64 {
            let (n, faces) = test_surface(round, &mut rng);
            let mut id: Vec<u32> = (0..n as u32).collect();
            rng.shuffle(&mut id);
            let shuffled = faces.iter().map(|f| f.map(|v| id[v as usize])).collect();
            inputs.push((n, faces));
            inputs.push((n, shuffled));
        }
        for m in [20, 40, 70] {
            inputs.push(double_cones(m, false));
            inputs.push(double_cones(m, true));
        }
        let mut answered = [0usize; 2];
        for (i, (n, faces)) in inputs.iter().enumerate() {
            let Ok(scanned) = scan_faces(*n, faces) else {
                continue;
            };
            let by_vertex = vertex_corners(&scanned.corner_vertex, &scanned.degree);
            let sequential = classify_edges(&scanned, &by_vertex, faces);
            let sound = sequential.duplicate.is_none()
                && sequential.bad_edge.is_none()
                && (!sequential.boundary.is_empty() || sequential.first_link.is_none());
            let expected = outcome(scanned.clone(), sequential);
            let ranges = 1 + i % 9;
            let pool = &pools[i % 2];
            match pool.install(|| parallel::classify_edges_in(&scanned, &by_vertex, ranges)) {
                Some(c) => {
                    assert!(sound, "input {i}: answered for a faulty surface");
                    assert_eq!(
                        outcome(scanned.clone(), c),
                        expected,
                        "input {i}: {faces:?}"
                    );
                    answered[1] += 1;
                }
                None => {
                    assert!(!sound, "input {i}: no answer for a sound surface");
                    answered[0] += 1;
                }
            }
        }
        // Both kinds were met in numbers.
        assert!(answered[0] >= 100 && answered[1] >= 300, "{answered:?}");
    }

    /// The face scan and the grouping by vertex on the pool give the sequential phases'
    /// results: the corner array, the degrees, each vertex's corners, and the first bad
    /// face (out of range or degenerate, or both, or two ids out of range; one or two bad
    /// faces anywhere in the list), in 1 to 7 runs with vertex ranges of 1 to 5 vertices
    /// and of all of them, on pools of 2 and 3 threads.
    #[cfg(feature = "parallel")]
    #[test]
    fn the_scan_and_grouping_on_the_pool_are_the_sequential_ones() {
        let pools = [pool(2), pool(3)];
        let mut rng = Rng::new(9);
        let mut errors = 0;
        for round in 0..300u64 {
            let (n, mut faces) = test_surface(round, &mut rng);
            if round % 4 == 1 {
                for _ in 0..1 + rng.index(2) {
                    let (f, k) = (rng.index(faces.len()), rng.index(3));
                    let [x, y, _] = faces[f];
                    let out = n as u32;
                    match rng.index(3) {
                        0 => faces[f][k] = (n + rng.index(3)) as u32,
                        1 => faces[f][k] = faces[f][(k + 1) % 3],
                        // Two problems in one face, each pairing of the checks in turn:
                        // two ids out of range, or a repeated id and one out of range.
                        _ => {
                            faces[f] = [[out, out + 1, x], [x, out, x], [out, y, y], [x, x, out]]
                                [(round as usize / 4) % 4]
                        }
                    }
                }
            }
            let runs = 1 + round as usize % 7;
            let range = if round % 6 == 5 {
                n.max(1)
            } else {
                1 + round as usize % 5
            };
            let pool = &pools[round as usize % 2];
            let sequential = scan_faces(n, &faces);
            let on_pool = pool.install(|| parallel::scan_faces_in(n, &faces, runs, range));
            match (sequential, on_pool) {
                (Ok(s), Ok(p)) => {
                    assert_eq!(
                        (&s.corner_vertex, &s.degree),
                        (&p.corner_vertex, &p.degree),
                        "round {round}"
                    );
                    let by_vertex = vertex_corners(&s.corner_vertex, &s.degree);
                    let grouped = pool.install(|| {
                        parallel::vertex_corners_in(&s.corner_vertex, &s.degree, runs, range)
                    });
                    assert_eq!(
                        (&by_vertex.end, &by_vertex.corners),
                        (&grouped.end, &grouped.corners),
                        "round {round}"
                    );
                }
                (s, p) => {
                    assert_eq!(s.err(), p.err(), "round {round}");
                    errors += 1;
                }
            }
        }
        assert!(errors >= 60, "{errors} faulty face lists");
    }

    /// From [`parallel::MIN_FACES`] faces on a pool of two threads the build's phases run
    /// on the pool (not on one thread, nor below), and the build is the build on one:
    /// the corner table, the components and each error, on a subdivided torus of
    /// about 290k faces, two copies of it, and the torus with a repeated face, a hole, a
    /// pinched vertex, and a degenerate face before a face out of range.
    #[cfg(feature = "parallel")]
    #[test]
    fn a_large_build_on_two_threads_is_the_build_on_one() {
        let (one, two) = (pool(1), pool(2));
        let tri = random(&RandomParams {
            surface: SurfaceKind::Orientable(1),
            min_faces: parallel::MIN_FACES / 256 + 100,
            flip_percent: 30,
            seed: 3,
        })
        .expect("random surface");
        let coarse = TriMesh::combinatorial(tri.vertex_capacity(), tri.face_list());
        let fine = crate::gen::subdivide(&coarse, 4).expect("a subdivided torus");
        let (n, faces) = (fine.vertex_count, fine.faces);
        assert!(faces.len() > parallel::MIN_FACES);
        // The pool's phases answer on two threads from `MIN_FACES` faces, not on one
        // thread nor below (where the sequential phases run).
        let on = |pool: &rayon::ThreadPool, faces: &[[u32; 3]]| {
            pool.install(|| {
                let scanned = parallel::scan_faces(n, faces).map(|s| s.expect("in range"));
                let corners = faces.as_flattened();
                let degree = scan_faces(n, faces).expect("in range").degree;
                let grouped = parallel::vertex_corners(corners, &degree);
                let classified = scanned
                    .as_ref()
                    .zip(grouped.as_ref())
                    .and_then(|(s, g)| parallel::classify_edges(s, g, faces));
                [scanned.is_some(), grouped.is_some(), classified.is_some()]
            })
        };
        assert_eq!(on(&two, &faces), [true; 3]);
        assert_eq!(on(&one, &faces), [false; 3]);
        let short = &faces[..parallel::MIN_FACES - 1];
        assert_eq!(on(&two, short), [false; 3]);
        assert_eq!(on(&two, &faces[..parallel::MIN_FACES])[..2], [true; 2]);
        let twice: Vec<[u32; 3]> = faces
            .iter()
            .copied()
            .chain(faces.iter().map(|f| f.map(|v| v + n as u32)))
            .collect();
        let mut repeated = faces.clone();
        repeated.push(faces[faces.len() / 2]);
        let mut holed = faces.clone();
        holed.swap_remove(faces.len() / 3);
        // A degenerate face before a face out of range, in different runs.
        let mut bad = faces.clone();
        bad[faces.len() * 3 / 4][1] = n as u32;
        bad[faces.len() / 3][2] = bad[faces.len() / 3][0];
        let pinched: Vec<[u32; 3]> = faces
            .iter()
            .map(|f| f.map(|v| if v == n as u32 - 1 { 0 } else { v }))
            .filter(|f| f[0] != f[1] && f[1] != f[2] && f[0] != f[2])
            .collect();
        let summary = |n: usize, faces: &[[u32; 3]]| {
            check(n, faces).map(|c| {
                let (label, count) = c.face_components();
                (
                    c.tri.corner_vertex,
                    c.tri.opposite,
                    c.tri.vertex_corner,
                    c.tri.degree,
                    label,
                    count,
                )
            })
        };
        for (what, n, faces) in [
            ("torus", n, &faces),
            ("two tori", 2 * n, &twice),
            ("repeated face", n, &repeated),
            ("hole", n, &holed),
            ("pinched", n, &pinched),
            ("bad faces", n, &bad),
        ] {
            let expected = one.install(|| summary(n, faces));
            assert_eq!(two.install(|| summary(n, faces)), expected, "{what}");
            assert_eq!(expected.is_ok(), what.contains("tor"), "{what}");
        }
    }

    /// Ids far apart at consecutive faces' slots make a face list scattered when they
    /// are more than a quarter of the sampled slots, not before.
    #[test]
    fn scattered_ids_are_told_from_local_ones() {
        let far = |k: u32| {
            [
                (k + 2) * FAR_IDS,
                (k + 2) * FAR_IDS + 1,
                (k + 2) * FAR_IDS + 2,
            ]
        };
        let near = |k: u32| [3 * k, 3 * k + 1, 3 * k + 2];
        // 81 faces: 80 consecutive pairs, every eighth sampled (10 pairs, 30 slots).
        let local: Vec<[u32; 3]> = (0..81).map(near).collect();
        assert!(!scattered(&local));
        let spread: Vec<[u32; 3]> = (0..81).map(far).collect();
        assert!(scattered(&spread));
        // Far at the sampled pairs (0, 1), (8, 9), (16, 17): 3 of 10 pairs, 9 of 30
        // slots, more than a quarter; 2 of 10 pairs are not.
        let some = |far_pairs: u32| -> Vec<[u32; 3]> {
            (0..81u32)
                .map(|i| {
                    if i % 8 == 0 && i / 8 < far_pairs {
                        far(i + 1)
                    } else {
                        near(i)
                    }
                })
                .collect()
        };
        assert!(scattered(&some(3)));
        assert!(!scattered(&some(2)));
    }

    /// `e` with its vertex ids `v` written as `k * v` (face indices unchanged).
    fn spread_error(e: BuildError, k: u32) -> BuildError {
        use BuildError::*;
        match e {
            DegenerateFace { face, vertices } => DegenerateFace {
                face,
                vertices: vertices.map(|v| k * v),
            },
            DuplicateFace {
                face,
                first,
                vertices,
            } => DuplicateFace {
                face,
                first,
                vertices: vertices.map(|v| k * v),
            },
            BoundaryEdge { a, b, face } => BoundaryEdge {
                a: k * a,
                b: k * b,
                face,
            },
            NonManifoldEdge { a, b, faces, face } => NonManifoldEdge {
                a: k * a,
                b: k * b,
                faces,
                face,
            },
            MultipleEdges {
                a,
                b,
                edges,
                faces,
                face,
            } => MultipleEdges {
                a: k * a,
                b: k * b,
                edges,
                faces,
                face,
            },
            VertexLinkNotCycle {
                vertex,
                cycles,
                faces,
            } => VertexLinkNotCycle {
                vertex: k * vertex,
                cycles,
                faces,
            },
            VertexDegreeTooLow { vertex, degree } => VertexDegreeTooLow {
                vertex: k * vertex,
                degree,
            },
            other => other,
        }
    }

    /// Through the public builder, on inputs that take the renumbered path: with every
    /// id `v` written as `2^16 · v` (an increasing map, so the id order and with it the
    /// error precedence are kept, and the ids scattered), [`Surfaces::from_faces`] gives
    /// the same components (the same local triangulations and face origins, vertex
    /// origins spread) or the same error (its vertex ids spread), on sound and faulty
    /// surfaces.
    #[test]
    fn scattered_ids_build_what_compact_ids_build() {
        let k = FAR_IDS;
        let mut rng = Rng::new(12);
        let mut renumbered = 0;
        for round in 0..40u64 {
            let tri = random(&RandomParams {
                surface: [SurfaceKind::Orientable(0), SurfaceKind::NonOrientable(1)]
                    [round as usize % 2],
                min_faces: 16 + rng.index(20),
                flip_percent: 30,
                seed: round,
            })
            .expect("random surface");
            let mut faces = tri.face_list();
            let n = tri.vertex_capacity();
            match round % 4 {
                1 => faces.push(faces[rng.index(faces.len())]),
                2 => {
                    faces.swap_remove(rng.index(faces.len()));
                }
                3 => {
                    let shift = n as u32;
                    let copy: Vec<[u32; 3]> = faces.iter().map(|f| f.map(|v| v + shift)).collect();
                    faces.extend(copy);
                }
                _ => {}
            }
            let n = 2 * n;
            let spread: Vec<[u32; 3]> = faces.iter().map(|f| f.map(|v| k * v)).collect();
            let spread_n = k as usize * n;
            if scattered(&spread) {
                renumbered += 1;
            }
            match (
                Surfaces::from_faces(n, &faces),
                Surfaces::from_faces(spread_n, &spread),
            ) {
                (Ok(a), Ok(b)) => {
                    assert_eq!(a.components.len(), b.components.len(), "round {round}");
                    for (x, y) in a.components.iter().zip(&b.components) {
                        assert_eq!(x.tri, y.tri, "round {round}");
                        assert_eq!(x.face_origin, y.face_origin, "round {round}");
                        let origin: Vec<u32> = x.vertex_origin.iter().map(|&v| k * v).collect();
                        assert_eq!(origin, y.vertex_origin, "round {round}");
                    }
                }
                (Err(a), Err(b)) => assert_eq!(spread_error(a, k), b, "round {round}"),
                (a, b) => panic!("round {round}: {:?} against {:?}", a.err(), b.err()),
            }
        }
        assert!(renumbered >= 30, "{renumbered} of 40 scattered");
    }

    /// Ids already in order of first appearance are not renumbered.
    #[test]
    fn ids_in_order_of_first_appearance_are_left_alone() {
        let tri = random(&RandomParams {
            surface: SurfaceKind::Orientable(1),
            min_faces: 50,
            flip_percent: 30,
            seed: 3,
        })
        .expect("random surface");
        let faces = tri.face_list();
        let mut id = vec![NONE; tri.vertex_capacity()];
        let mut next = 0;
        for &v in faces.as_flattened() {
            if id[v as usize] == NONE {
                id[v as usize] = next;
                next += 1;
            }
        }
        let in_order: Vec<[u32; 3]> = faces.iter().map(|f| f.map(|v| id[v as usize])).collect();
        assert!(renumbered_outcome(next as usize, &in_order).is_none());
        assert!(faces == in_order || renumbered_outcome(tri.vertex_capacity(), &faces).is_some());
    }

    #[test]
    fn the_size_limits_accept_their_bounds_and_refuse_one_more() {
        assert_eq!(check_counts(MAX_VERTICES, MAX_FACES), Ok(()));
        assert_eq!(
            check_counts(MAX_VERTICES, MAX_FACES + 1),
            Err(BuildError::TooLarge {
                what: "faces",
                count: MAX_FACES + 1,
                max: MAX_FACES,
            })
        );
        assert_eq!(
            check_counts(MAX_VERTICES + 1, MAX_FACES),
            Err(BuildError::TooLarge {
                what: "vertices",
                count: MAX_VERTICES + 1,
                max: MAX_VERTICES,
            })
        );
        assert_eq!(check_counts(3, 0), Err(BuildError::Empty));
        assert_eq!(check_counts(0, 1), Ok(()));
    }
}
