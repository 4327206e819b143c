//! The compact-index triangulation: a corner table that does not assume orientability.

use super::ids::{Corner, FaceId, VertexId, NONE};

/// A triangulation of one connected closed surface, orientable or not.
///
/// # Representation (a corner table, Rossignac's "Corner Table" without orientation)
/// Four flat arrays, nothing else:
/// - `corner_vertex[c]`: the vertex at corner `c` (`3 * face + slot`); a removed face has
///   `NONE` in its three slots;
/// - `opposite[c]`: the corner on the other side of the edge opposite `c`;
/// - `vertex_corner[v]`: one corner at `v`, or `NONE` if `v` was removed;
/// - `degree[v]`: the number of edges (= faces) at `v`, kept up to date by every operation.
///
/// That is 24 bytes per face plus 8 bytes per vertex (about 28 bytes per face, since a
/// closed surface has about half as many vertices as faces).
///
/// # No orientation assumed
/// The two faces of an edge may list its endpoints in the same order (that is what a
/// non-orientable surface forces somewhere). Every traversal therefore looks at the
/// vertices, never at slot parity: see [`Triangulation::star`].
///
/// # Invariants (checked from scratch by [`Triangulation::validate`])
/// Every live face has three distinct live vertices; `opposite` is a fixed-point-free
/// involution on live corners, and `c`, `opposite[c]` see the same two edge endpoints;
/// each vertex link is one simple cycle of length `degree[v] >= 3`; no two faces have the
/// same vertex set; no two edges have the same endpoints; the surface is connected.
///
/// # State stamp
/// Besides the arrays, a triangulation carries a *state stamp* ([`Self::state`]): a
/// process-unique number that every mutating operation replaces with a fresh one (and
/// that [`crate::History::undo`] sets back to the stamp of the state it restores). Slot-
/// exact undo records compare it to refuse a triangulation that changed in between. It is
/// not part of the surface: `==` compares the arrays only.
#[derive(Clone, Debug)]
pub struct Triangulation {
    pub(crate) corner_vertex: Vec<u32>,
    pub(crate) opposite: Vec<u32>,
    pub(crate) vertex_corner: Vec<u32>,
    pub(crate) degree: Vec<u32>,
    pub(crate) live_vertices: usize,
    pub(crate) live_faces: usize,
    pub(crate) state: StateStamp,
    pub(crate) stamps: StampSource,
}

/// Identifies one state of one [`Triangulation`]: see [`Triangulation::state`].
///
/// Stamps come from one process-wide counter, so two states that were not reached from
/// each other by exact undo never share a stamp (not even states of two different
/// triangulations); a clone shares its original's stamp until either changes.
#[derive(Copy, Clone, PartialEq, Eq, Hash, Debug)]
pub struct StateStamp(u64);

/// The process-wide source of stamps: every value is handed out at most once, singly by
/// [`StateStamp::fresh`] or in blocks by [`StampSource`].
static NEXT_STAMP: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);

impl StateStamp {
    /// A stamp no other state has had in this process.
    pub(crate) fn fresh() -> Self {
        // Relaxed: only uniqueness matters, not ordering with other memory.
        StateStamp(NEXT_STAMP.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
    }
}

/// A triangulation's private block of fresh stamps, so that a mutation takes its new
/// stamp without an atomic read-modify-write: on x86 that is a locked instruction,
/// which waits for every pending store, and in the cache-missing loops of RS and the
/// LRS expansion it cost about a quarter of the expansion's own time (perf, B0).
/// Guarantees the same uniqueness as [`StateStamp::fresh`]: each block is reserved
/// from the process-wide counter and a clone starts with an empty block, so no two
/// triangulations ever take the same value.
#[derive(Debug, Default)]
pub(crate) struct StampSource {
    next: u64,
    end: u64,
}

impl Clone for StampSource {
    /// An empty block: the clone reserves its own on its first mutation.
    fn clone(&self) -> Self {
        StampSource::default()
    }
}

impl StampSource {
    /// Stamps reserved at a time: one atomic operation per 65,536 mutations.
    const BLOCK: u64 = 1 << 16;

    /// A stamp no other state has had in this process.
    #[inline]
    pub(crate) fn take(&mut self) -> StateStamp {
        if self.next == self.end {
            self.refill();
        }
        let s = self.next;
        self.next += 1;
        StateStamp(s)
    }

    #[cold]
    fn refill(&mut self) {
        let base = NEXT_STAMP.fetch_add(Self::BLOCK, std::sync::atomic::Ordering::Relaxed);
        self.next = base;
        self.end = base + Self::BLOCK;
    }
}

impl PartialEq for Triangulation {
    /// Equal arrays and counts: the same surface with the same ids and corner slots. The
    /// state stamp is bookkeeping and takes no part.
    fn eq(&self, other: &Self) -> bool {
        self.corner_vertex == other.corner_vertex
            && self.opposite == other.opposite
            && self.vertex_corner == other.vertex_corner
            && self.degree == other.degree
            && self.live_vertices == other.live_vertices
            && self.live_faces == other.live_faces
    }
}
impl Eq for Triangulation {}

/// Which of the two other corners of a face is opposite the edge a star walk leaves by.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub(crate) enum Exit {
    Next,
    Prev,
}

/// One step of a walk around a vertex: the corner at the centre vertex and the link
/// vertex across the edge the walk leaves the face by.
#[derive(Copy, Clone, PartialEq, Eq, Debug)]
pub struct StarStep {
    /// A corner at the centre vertex.
    pub corner: Corner,
    /// The neighbour on the edge through which the walk leaves `corner`'s face.
    pub neighbour: VertexId,
}

/// Iterator over the faces around a vertex in cyclic order (see [`Triangulation::star`]).
pub struct Star<'a> {
    tri: &'a Triangulation,
    centre: u32,
    start: u32,
    corner: u32,
    exit: Exit,
    done: bool,
}

impl Iterator for Star<'_> {
    type Item = StarStep;
    #[inline(always)]
    fn next(&mut self) -> Option<StarStep> {
        if self.done {
            return None;
        }
        let c = Corner(self.corner);
        let (exit_corner, neighbour_corner) = match self.exit {
            Exit::Next => (c.next(), c.prev()),
            Exit::Prev => (c.prev(), c.next()),
        };
        let step = StarStep {
            corner: c,
            neighbour: VertexId(self.tri.corner_vertex[neighbour_corner.index()]),
        };
        let (c2, exit2) = self
            .tri
            .turn(self.centre, Corner(self.tri.opposite[exit_corner.index()]));
        self.corner = c2.0;
        self.exit = exit2;
        if self.corner == self.start {
            self.done = true;
        }
        Some(step)
    }
}

impl Triangulation {
    /// Number of live vertices.
    #[inline]
    pub fn vertex_count(&self) -> usize {
        self.live_vertices
    }
    /// Number of live faces.
    #[inline]
    pub fn face_count(&self) -> usize {
        self.live_faces
    }
    /// Number of edges (`3F/2` on a closed surface).
    #[inline]
    pub fn edge_count(&self) -> usize {
        3 * self.live_faces / 2
    }
    /// One more than the largest vertex id ever used (live or removed).
    #[inline]
    pub fn vertex_capacity(&self) -> usize {
        self.vertex_corner.len()
    }
    /// One more than the largest face id ever used (live or removed).
    #[inline]
    pub fn face_capacity(&self) -> usize {
        self.corner_vertex.len() / 3
    }
    /// Whether `v` names a live vertex.
    #[inline]
    pub fn is_vertex(&self, v: VertexId) -> bool {
        self.vertex_corner
            .get(v.index())
            .is_some_and(|&c| c != NONE)
    }
    /// Whether `f` names a live face.
    #[inline]
    pub fn is_face(&self, f: FaceId) -> bool {
        self.corner_vertex
            .get(3 * f.index())
            .is_some_and(|&v| v != NONE)
    }
    /// Live vertex ids in increasing order.
    pub fn vertices(&self) -> impl Iterator<Item = VertexId> + '_ {
        self.vertex_corner
            .iter()
            .enumerate()
            .filter(|(_, &c)| c != NONE)
            .map(|(i, _)| VertexId(i as u32))
    }
    /// Live face ids in increasing order.
    pub fn faces(&self) -> impl Iterator<Item = FaceId> + '_ {
        self.corner_vertex
            .chunks_exact(3)
            .enumerate()
            .filter(|(_, c)| c[0] != NONE)
            .map(|(i, _)| FaceId(i as u32))
    }
    /// The vertex at corner `c`. O(1).
    #[inline]
    pub fn vertex(&self, c: Corner) -> VertexId {
        VertexId(self.corner_vertex[c.index()])
    }
    /// The corner across the edge opposite `c`. O(1).
    #[inline]
    pub fn opposite(&self, c: Corner) -> Corner {
        Corner(self.opposite[c.index()])
    }
    /// The three vertices of face `f` in slot order. O(1).
    #[inline]
    pub fn face_vertices(&self, f: FaceId) -> [VertexId; 3] {
        let i = 3 * f.index();
        let cv = &self.corner_vertex;
        [VertexId(cv[i]), VertexId(cv[i + 1]), VertexId(cv[i + 2])]
    }
    /// The three neighbouring faces of `f`: entry `i` is across the edge opposite slot `i`.
    #[inline]
    pub fn face_neighbours(&self, f: FaceId) -> [FaceId; 3] {
        let i = 3 * f.index();
        let o = &self.opposite;
        [
            Corner(o[i]).face(),
            Corner(o[i + 1]).face(),
            Corner(o[i + 2]).face(),
        ]
    }
    /// The degree of `v` (number of incident edges, equal to incident faces). O(1).
    #[inline]
    pub fn degree(&self, v: VertexId) -> usize {
        self.degree[v.index()] as usize
    }
    /// One corner at `v`.
    #[inline]
    pub fn corner_of(&self, v: VertexId) -> Corner {
        Corner(self.vertex_corner[v.index()])
    }

    /// The stamp of the current state: replaced by a fresh one by every change
    /// (contraction, flip, split), restored by exact undo. O(1).
    #[inline]
    pub fn state(&self) -> StateStamp {
        self.state
    }

    /// The `corner_vertex` and `opposite` entries of two faces, for slot-exact undo
    /// records ([`Self::restore_faces`] writes them back).
    pub(crate) fn save_faces(&self, faces: [FaceId; 2]) -> ([u32; 6], [u32; 6]) {
        let mut vertex = [0u32; 6];
        let mut opposite = [0u32; 6];
        for (k, f) in faces.iter().enumerate() {
            for s in 0..3 {
                let c = f.corner(s as u32).index();
                vertex[3 * k + s] = self.corner_vertex[c];
                opposite[3 * k + s] = self.opposite[c];
            }
        }
        (vertex, opposite)
    }

    /// Writes back what [`Self::save_faces`] saved, re-gluing each saved opposite corner
    /// to its face's corner (the neighbours' side of each gluing too).
    pub(crate) fn restore_faces(
        &mut self,
        faces: [FaceId; 2],
        vertex: &[u32; 6],
        opposite: &[u32; 6],
    ) {
        for (k, f) in faces.iter().enumerate() {
            for s in 0..3 {
                let c = f.corner(s as u32).index();
                self.corner_vertex[c] = vertex[3 * k + s];
                let o = opposite[3 * k + s];
                self.opposite[c] = o;
                self.opposite[o as usize] = c as u32;
            }
        }
    }

    /// Marks the triangulation as changed (a fresh [`StateStamp`]).
    #[inline]
    pub(crate) fn touch(&mut self) {
        self.state = self.stamps.take();
    }

    /// The corner of `c`'s face that faces edge `[vertex(c), z]`: given a corner at `w`
    /// whose face also contains `z`, the third corner of that face, opposite the edge
    /// `[w, z]`. O(1).
    ///
    /// This is the one place that decides between `next` and `prev` by looking at the
    /// vertices: on a non-orientable surface the two faces of an edge may list it in the
    /// same order, so slot parity says nothing (see the type's documentation).
    ///
    /// Debug builds assert that `z` is in the face and is not `vertex(c)`.
    #[inline]
    pub fn corner_facing(&self, c: Corner, z: VertexId) -> Corner {
        if self.corner_vertex[c.next().index()] == z.0 {
            c.prev()
        } else {
            debug_assert_eq!(
                self.corner_vertex[c.prev().index()],
                z.0,
                "{z} not in {c}'s face"
            );
            c.next()
        }
    }

    /// The corner of `c`'s face at vertex `w` (which must be one of its three vertices;
    /// debug builds assert it). O(1).
    #[inline]
    pub fn corner_at(&self, c: Corner, w: VertexId) -> Corner {
        if self.corner_vertex[c.index()] == w.0 {
            c
        } else if self.corner_vertex[c.next().index()] == w.0 {
            c.next()
        } else {
            debug_assert_eq!(
                self.corner_vertex[c.prev().index()],
                w.0,
                "{w} not in {c}'s face"
            );
            c.prev()
        }
    }

    /// Given the corner `o` entered across an edge at `centre`, the corner at `centre` in
    /// `o`'s face and which side the walk leaves that face by.
    #[inline]
    pub(crate) fn turn(&self, centre: u32, o: Corner) -> (Corner, Exit) {
        // The entry edge is opposite `o`; the centre is one of its endpoints, and the walk
        // leaves through the other edge at the centre, the one opposite the third corner.
        let n = o.next();
        if self.corner_vertex[n.index()] == centre {
            (n, Exit::Next)
        } else {
            (o.prev(), Exit::Prev)
        }
    }

    /// The faces around `v` in cyclic order, as corners at `v`, each with the link vertex
    /// shared with the next face of the walk. Starts at [`Self::corner_of`]`(v)`.
    ///
    /// The `neighbour`s, in order, are the link of `v` as a cycle. O(1) per step; the walk
    /// visits exactly `degree(v)` faces. Works the same on non-orientable surfaces.
    pub fn star(&self, v: VertexId) -> Star<'_> {
        self.star_from(self.corner_of(v))
    }

    /// Like [`Self::star`], starting at corner `c` (which must be a live corner).
    pub fn star_from(&self, c: Corner) -> Star<'_> {
        Star {
            tri: self,
            centre: self.corner_vertex[c.index()],
            start: c.0,
            corner: c.0,
            exit: Exit::Next,
            done: false,
        }
    }

    /// The link of `v` as a cycle of vertices. O(degree).
    pub fn link(&self, v: VertexId) -> impl Iterator<Item = VertexId> + '_ {
        self.star(v).map(|s| s.neighbour)
    }

    /// A corner at `u` whose face contains `v` (so `v` is at its `next()` or `prev()`),
    /// or `None` if `[u, v]` is not an edge. O(degree(u)).
    pub fn find_edge(&self, u: VertexId, v: VertexId) -> Option<Corner> {
        // Only `u` needs a guard: a live vertex's link holds neither itself nor a
        // removed or unknown vertex, so the search below finds no such `v`.
        if !self.is_vertex(u) {
            return None;
        }
        self.star(u).find(|s| s.neighbour == v).map(|s| s.corner)
    }

    /// Whether `[u, v]` is an edge. O(min(degree(u), degree(v))).
    pub fn has_edge(&self, u: VertexId, v: VertexId) -> bool {
        if !self.is_vertex(u) || !self.is_vertex(v) || u == v {
            return false;
        }
        let (a, b) = if self.degree(u) <= self.degree(v) {
            (u, v)
        } else {
            (v, u)
        };
        self.link(a).any(|w| w == b)
    }

    /// The two corners opposite edge `[u, v]` (one in each face of the edge), or `None`.
    pub fn edge_corners(&self, u: VertexId, v: VertexId) -> Option<[Corner; 2]> {
        let c = self.find_edge(u, v)?;
        let opp = self.corner_facing(c, v);
        Some([opp, self.opposite(opp)])
    }

    /// The endpoints of the edge opposite corner `c`.
    #[inline]
    pub fn edge_endpoints(&self, c: Corner) -> [VertexId; 2] {
        [self.vertex(c.next()), self.vertex(c.prev())]
    }

    /// Every edge once, as `(u, v)` with `u < v`, and a corner opposite it. O(F).
    pub fn edges(&self) -> impl Iterator<Item = (VertexId, VertexId, Corner)> + '_ {
        self.faces().flat_map(move |f| {
            f.corners().into_iter().filter_map(move |c| {
                let o = self.opposite(c);
                // Each edge has two opposite corners; report it from the smaller one.
                if c < o {
                    let [a, b] = self.edge_endpoints(c);
                    Some(if a < b { (a, b, c) } else { (b, a, c) })
                } else {
                    None
                }
            })
        })
    }

    /// The live faces as vertex triples (ids as they are, not compacted).
    pub fn face_list(&self) -> Vec<[u32; 3]> {
        self.faces()
            .map(|f| self.face_vertices(f).map(|v| v.0))
            .collect()
    }

    /// Euler characteristic `V - E + F`.
    pub fn euler_characteristic(&self) -> i64 {
        self.live_vertices as i64 - self.edge_count() as i64 + self.live_faces as i64
    }

    /// Euler genus `2 - χ` (twice the genus if orientable, the number of cross-caps if not).
    pub fn euler_genus(&self) -> i64 {
        2 - self.euler_characteristic()
    }

    /// Whether the faces can be oriented consistently. O(F), by a walk over the dual graph
    /// unless they already are.
    pub fn is_orientable(&self) -> bool {
        self.is_coherent() || self.orientation_by_walk().is_some()
    }

    /// Whether the faces as stored are consistently oriented: every edge is listed in
    /// opposite directions by its two faces. O(F), one pass over the corners; most
    /// meshes of orientable surfaces come this way, so it spares them the walk.
    pub fn is_coherent(&self) -> bool {
        self.corner_vertex
            .chunks_exact(3)
            .zip(self.opposite.chunks_exact(3))
            .all(|(f, o)| {
                // A removed face has `NONE` everywhere and nothing to check.
                f[0] == NONE
                    || (0..3).all(|k| {
                        // The edge runs next -> prev in this face; the other face must
                        // run it prev -> next, i.e. have this face's `prev` vertex at
                        // the corner after its own opposite corner.
                        let other = Corner(o[k]);
                        self.corner_vertex[other.next().index()] == f[(k + 2) % 3]
                    })
            })
    }

    /// A consistent orientation if one exists: `flip[f]` says whether face `f` must be
    /// reversed (removed faces get `false`). O(F).
    pub fn orientation(&self) -> Option<Vec<bool>> {
        if self.is_coherent() {
            return Some(vec![false; self.face_capacity()]);
        }
        self.orientation_by_walk()
    }

    /// [`Self::orientation`] by a depth-first walk over the dual graph, which fixes each
    /// face's flip from a neighbour's and fails on the first disagreement. O(F).
    fn orientation_by_walk(&self) -> Option<Vec<bool>> {
        let nf = self.face_capacity();
        let mut flip = vec![false; nf];
        let mut seen = vec![false; nf];
        let mut stack = Vec::new();
        for f0 in self.faces() {
            if seen[f0.index()] {
                continue;
            }
            seen[f0.index()] = true;
            stack.push(f0);
            while let Some(f) = stack.pop() {
                for c in f.corners() {
                    let o = self.opposite(c);
                    let g = o.face();
                    // The edge runs next(c) -> prev(c) in f. If g lists it the same way,
                    // the two faces disagree and g must be flipped relative to f.
                    let same = self.corner_vertex[o.next().index()]
                        == self.corner_vertex[c.next().index()];
                    let want = flip[f.index()] ^ same;
                    if seen[g.index()] {
                        if flip[g.index()] != want {
                            return None;
                        }
                    } else {
                        seen[g.index()] = true;
                        flip[g.index()] = want;
                        stack.push(g);
                    }
                }
            }
        }
        Some(flip)
    }

    /// The orientable genus `(2 - χ) / 2`, or `None` on a non-orientable surface.
    pub fn genus(&self) -> Option<i64> {
        self.is_orientable().then(|| self.euler_genus() / 2)
    }

    /// Degree histogram: entry `d` counts the live vertices of degree `d`.
    pub fn degree_histogram(&self) -> Vec<usize> {
        let mut h = Vec::new();
        for v in self.vertices() {
            let d = self.degree(v);
            if h.len() <= d {
                h.resize(d + 1, 0);
            }
            h[d] += 1;
        }
        h
    }

    /// Whether this is (isomorphic to) the tetrahedron boundary T4, the one irreducible
    /// genus-0 triangulation. O(1): a connected closed surface with 4 vertices is T4.
    pub fn is_tetrahedron(&self) -> bool {
        self.live_vertices == 4
    }

    /// Approximate heap bytes held by the four core arrays.
    pub fn heap_bytes(&self) -> usize {
        4 * (self.corner_vertex.capacity()
            + self.opposite.capacity()
            + self.vertex_corner.capacity()
            + self.degree.capacity())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A source hands out its reserved block in order, then reserves a new one: every
    /// stamp lies in the block reserved last (`end - BLOCK <= stamp < end`), one more
    /// than the one before within a block.
    #[test]
    fn stamps_come_from_the_reserved_block_in_order() {
        let mut source = StampSource::default();
        let mut previous: Option<u64> = None;
        let mut blocks = 0;
        for _ in 0..StampSource::BLOCK + 2 {
            let end_before = source.end;
            let StateStamp(s) = source.take();
            assert!(
                source.end >= StampSource::BLOCK
                    && (source.end - StampSource::BLOCK..source.end).contains(&s),
                "stamp {s} outside the block ending at {}",
                source.end
            );
            assert_eq!(source.next, s + 1);
            if source.end != end_before {
                blocks += 1;
                assert_eq!(
                    s,
                    source.end - StampSource::BLOCK,
                    "a block starts at its base"
                );
            } else {
                assert_eq!(Some(s), previous.map(|p| p + 1), "in order within a block");
            }
            previous = Some(s);
        }
        assert_eq!(blocks, 2, "one reservation per block, and only then");
        // A clone starts without a block (so no two sources share one).
        let clone = source.clone();
        assert_eq!((clone.next, clone.end), (0, 0));
    }

    /// The queries read from the arrays agree with the same facts read naively from the
    /// face list (vertices, edges, directed edges, degrees), on orientable and
    /// non-orientable surfaces, stored coherently and with faces reversed, fresh and with
    /// removed faces and vertices after contractions.
    #[test]
    fn queries_agree_with_the_face_list() {
        use crate::gen;
        use std::collections::{BTreeMap, BTreeSet};
        // (name, faces, Euler genus, orientable)
        let surfaces = [
            ("tetrahedron", gen::tetrahedron(), 0, true),
            ("octahedron", gen::octahedron(), 0, true),
            (
                "torus",
                gen::subdivide(&gen::torus7(), 1).expect("subdivision"),
                2,
                true,
            ),
            ("projective plane", gen::projective_plane6(), 1, false),
            (
                "Klein bottle",
                gen::subdivide(&gen::klein_bottle(), 1).expect("subdivision"),
                2,
                false,
            ),
        ];
        let mut cases = 0;
        let mut tetrahedra = 0;
        for (name, mesh, euler_genus, orientable) in surfaces {
            let n = mesh.vertex_count;
            let mut reversed = mesh.faces.clone();
            for f in reversed.iter_mut().step_by(3) {
                f.swap(1, 2);
            }
            for (order, faces) in [("as stored", &mesh.faces), ("reversed", &reversed)] {
                let fresh = Triangulation::from_faces(n, faces).expect("a closed surface");
                assert_eq!(
                    &fresh.face_list(),
                    faces,
                    "{name}: face_list keeps the input"
                );
                let mut contracted = fresh.clone();
                let mut history = crate::History::new();
                for [a, b, _] in faces.iter().step_by(5) {
                    // Errors (the edge is gone or fails the link condition) change nothing.
                    let _ = contracted.contract(VertexId(*a), VertexId(*b), &mut history);
                }
                for (stage, t) in [("fresh", &fresh), ("contracted", &contracted)] {
                    let what = format!("{name}, {order}, {stage}");
                    check_queries(t, &what, euler_genus, orientable, &mut tetrahedra);
                    cases += 1;
                }
                if !matches!(name, "tetrahedron" | "projective plane") {
                    assert!(contracted.vertex_count() < fresh.vertex_count(), "{name}");
                }
            }
        }
        assert_eq!(cases, 20);
        // The tetrahedron's four cases, and the octahedron contracted to it in one order.
        assert_eq!(tetrahedra, 5);

        fn check_queries(
            t: &Triangulation,
            what: &str,
            euler_genus: i64,
            orientable: bool,
            tetrahedra: &mut usize,
        ) {
            let faces = t.face_list();
            assert_eq!(faces.len(), t.face_count(), "{what}");
            let live: BTreeSet<u32> = faces.iter().flatten().copied().collect();
            let mut edges = BTreeSet::new();
            let mut directed = BTreeMap::<(u32, u32), usize>::new();
            let mut degree = BTreeMap::<u32, usize>::new();
            for f in &faces {
                for k in 0..3 {
                    let (a, b) = (f[k], f[(k + 1) % 3]);
                    edges.insert((a.min(b), a.max(b)));
                    *directed.entry((a, b)).or_default() += 1;
                    *degree.entry(a).or_default() += 1;
                }
            }
            // Faces: each live face's corners name its vertices; the other two
            // vertices of a corner are the endpoints of the edge opposite it.
            for (f, fv) in t.faces().zip(&faces) {
                for (s, c) in f.corners().into_iter().enumerate() {
                    assert_eq!(t.vertex(c).0, fv[s], "{what}");
                    let [a, b] = t.edge_endpoints(c);
                    assert_eq!([a.0, b.0], [fv[(s + 1) % 3], fv[(s + 2) % 3]], "{what}");
                }
            }
            let beyond = t.vertex_capacity() as u32 + 1;
            for u in 0..beyond {
                let u_id = VertexId(u);
                assert_eq!(t.is_vertex(u_id), live.contains(&u), "{what}: vertex {u}");
                if live.contains(&u) {
                    let link: BTreeSet<u32> = t.link(u_id).map(|w| w.0).collect();
                    let naive: BTreeSet<u32> = edges
                        .iter()
                        .filter_map(|&(a, b)| (a == u).then_some(b).or((b == u).then_some(a)))
                        .collect();
                    assert_eq!(link, naive, "{what}: link of {u}");
                }
                for v in 0..beyond {
                    let v_id = VertexId(v);
                    let is_edge = edges.contains(&(u.min(v), u.max(v))) && u != v;
                    assert_eq!(t.has_edge(u_id, v_id), is_edge, "{what}: [{u}, {v}]");
                    match t.find_edge(u_id, v_id) {
                        Some(c) => {
                            assert!(is_edge, "{what}: a corner for the non-edge [{u}, {v}]");
                            assert_eq!(t.vertex(c), u_id, "{what}");
                            assert!(
                                t.vertex(c.next()) == v_id || t.vertex(c.prev()) == v_id,
                                "{what}: the corner's face holds [{u}, {v}]"
                            );
                        }
                        None => assert!(!is_edge, "{what}: [{u}, {v}] not found"),
                    }
                    match t.edge_corners(u_id, v_id) {
                        Some([p, q]) => {
                            assert!(is_edge, "{what}");
                            assert_ne!(p.face(), q.face(), "{what}");
                            assert_eq!(t.opposite(p), q, "{what}");
                            for c in [p, q] {
                                let mut ends = t.edge_endpoints(c);
                                ends.sort();
                                assert_eq!(
                                    ends,
                                    {
                                        let mut e = [u_id, v_id];
                                        e.sort();
                                        e
                                    },
                                    "{what}: corner opposite [{u}, {v}]"
                                );
                            }
                        }
                        None => assert!(!is_edge, "{what}: [{u}, {v}] has corners"),
                    }
                }
            }
            // Every edge once, smaller endpoint first, with a corner opposite it.
            let listed: Vec<(u32, u32)> = t
                .edges()
                .map(|(a, b, c)| {
                    let mut ends = t.edge_endpoints(c);
                    ends.sort();
                    assert_eq!(ends, [a, b], "{what}: the corner is opposite its edge");
                    (a.0, b.0)
                })
                .collect();
            assert!(listed.iter().all(|(a, b)| a < b), "{what}");
            assert_eq!(listed.len(), edges.len(), "{what}: each edge once");
            assert_eq!(
                listed.iter().copied().collect::<BTreeSet<_>>(),
                edges,
                "{what}"
            );
            // Counts and the Euler characteristic.
            let chi = live.len() as i64 - edges.len() as i64 + faces.len() as i64;
            assert_eq!(t.euler_characteristic(), chi, "{what}");
            assert_eq!(t.euler_genus(), euler_genus, "{what}");
            assert_eq!(2 - chi, euler_genus, "{what}");
            // Orientation: stored coherently when every directed edge occurs once.
            let coherent = directed.values().all(|&k| k == 1);
            assert_eq!(t.is_coherent(), coherent, "{what}");
            assert_eq!(t.is_orientable(), orientable, "{what}");
            assert_eq!(t.genus(), orientable.then_some(euler_genus / 2), "{what}");
            match t.orientation() {
                None => assert!(!orientable, "{what}: an orientation exists"),
                Some(flip) => {
                    assert!(orientable, "{what}");
                    assert_eq!(flip.len(), t.face_capacity(), "{what}");
                    let mut once = BTreeSet::new();
                    for (f, &flipped) in flip.iter().enumerate() {
                        let f_id = FaceId(f as u32);
                        if !t.is_face(f_id) {
                            assert!(!flipped, "{what}: a removed face is not flipped");
                            continue;
                        }
                        let [a, b, c] = t.face_vertices(f_id).map(|v| v.0);
                        let oriented = if flipped { [a, c, b] } else { [a, b, c] };
                        for k in 0..3 {
                            let e = (oriented[k], oriented[(k + 1) % 3]);
                            assert!(once.insert(e), "{what}: {e:?} twice after flipping");
                        }
                    }
                    assert_eq!(coherent, flip.iter().all(|&x| !x), "{what}");
                }
            }
            // Degrees.
            let histogram = t.degree_histogram();
            let max = degree.values().copied().max().unwrap_or(0);
            assert_eq!(histogram.len(), max + 1, "{what}");
            for (d, &count) in histogram.iter().enumerate() {
                let naive = degree.values().filter(|&&k| k == d).count();
                assert_eq!(count, naive, "{what}: vertices of degree {d}");
            }
            // T4: four vertices, every pair an edge (K4).
            let k4 = live.len() == 4 && edges.len() == 6;
            assert_eq!(t.is_tetrahedron(), k4, "{what}");
            *tetrahedra += usize::from(k4);
            let arrays = 2 * 3 * t.face_capacity() + 2 * t.vertex_capacity();
            assert!(t.heap_bytes() >= 4 * arrays, "{what}");
            // A clone's arrays hold exactly their entries.
            assert_eq!(t.clone().heap_bytes(), 4 * arrays, "{what}");
        }
    }

    /// `==` compares every array and count (each changed alone makes triangulations
    /// unequal) and ignores the state stamp.
    #[test]
    fn triangulations_are_equal_exactly_when_their_arrays_are() {
        let oct = crate::gen::octahedron();
        let t = Triangulation::from_faces(6, &oct.faces).expect("the octahedron");
        let mut same = Triangulation::from_faces(6, &oct.faces).expect("the octahedron");
        same.state = StateStamp::fresh();
        assert_ne!(t.state(), same.state());
        assert_eq!(t, same, "the stamps are not compared");
        type Change = fn(&mut Triangulation);
        let changes: [(&str, Change); 6] = [
            ("corner_vertex", |t| t.corner_vertex[0] ^= 1),
            ("opposite", |t| t.opposite[0] ^= 1),
            ("vertex_corner", |t| t.vertex_corner[0] ^= 1),
            ("degree", |t| t.degree[0] += 1),
            ("live_vertices", |t| t.live_vertices += 1),
            ("live_faces", |t| t.live_faces += 1),
        ];
        for (field, change) in changes {
            let mut other = t.clone();
            change(&mut other);
            assert_ne!(t, other, "{field} differs");
        }
    }
}
