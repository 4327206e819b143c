//! From-scratch structural validation of a [`Triangulation`].

use super::ids::{Corner, FaceId, VertexId, NONE};
use super::tri::Triangulation;

/// A violated structural invariant of a [`Triangulation`], naming the element involved
/// (corner, face and vertex numbers are ids of the triangulation).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ValidationError {
    /// The flat arrays have inconsistent lengths.
    #[error("invalid triangulation: {array} has {len} entries, expected {expected}")]
    ArrayShape {
        /// Which array.
        array: &'static str,
        /// Its length.
        len: usize,
        /// The length the other arrays imply.
        expected: usize,
    },
    /// A removed face still has vertices or gluings.
    #[error("invalid triangulation: removed face {face} has live data")]
    RemovedFaceHasData {
        /// The face id.
        face: usize,
    },
    /// A face names a vertex id beyond the vertex arrays.
    #[error("invalid triangulation: face {face}: vertex {vertex} out of range")]
    VertexOutOfRange {
        /// The face id.
        face: usize,
        /// The vertex id.
        vertex: u32,
    },
    /// A live face uses a removed vertex.
    #[error("invalid triangulation: face {face}: vertex {vertex} is removed")]
    RemovedVertexInFace {
        /// The face id.
        face: usize,
        /// The vertex id.
        vertex: u32,
    },
    /// A face repeats a vertex.
    #[error("invalid triangulation: face {face} is degenerate: {vertices:?}")]
    DegenerateFace {
        /// The face id.
        face: usize,
        /// Its vertices.
        vertices: [u32; 3],
    },
    /// The stored live face or vertex count disagrees with the arrays.
    #[error("invalid triangulation: live {what} count {recorded} but {actual} are live")]
    LiveCount {
        /// `"face"` or `"vertex"`.
        what: &'static str,
        /// The stored count.
        recorded: usize,
        /// The count in the arrays.
        actual: usize,
    },
    /// No live face.
    #[error("invalid triangulation: no faces")]
    NoFaces,
    /// `opposite` is not a fixed-point-free involution on live corners of other faces,
    /// or a corner and its opposite see different edges.
    #[error("invalid triangulation: corner {corner}: {problem}")]
    Gluing {
        /// The corner.
        corner: usize,
        /// What is wrong with its opposite.
        problem: GluingProblem,
    },
    /// An edge (endpoint pair) lies in a number of faces other than two.
    #[error("invalid triangulation: edge {edge:?} lies in {faces} faces")]
    EdgeFaceCount {
        /// The endpoints, smaller first.
        edge: [u32; 2],
        /// The number of faces.
        faces: u32,
    },
    /// A removed vertex is still used by faces.
    #[error("invalid triangulation: removed vertex {vertex} is used by {faces} faces")]
    RemovedVertexUsed {
        /// The vertex id.
        vertex: usize,
        /// The faces using it.
        faces: u32,
    },
    /// A vertex's stored corner is not at it.
    #[error("invalid triangulation: vertex {vertex}: its corner {corner} is not at it")]
    VertexCorner {
        /// The vertex id.
        vertex: usize,
        /// Its stored corner.
        corner: u32,
    },
    /// A stored degree disagrees with the faces, or is below 3.
    #[error("invalid triangulation: vertex {vertex}: degree {degree} but {faces} faces")]
    Degree {
        /// The vertex id.
        vertex: usize,
        /// The stored degree.
        degree: u32,
        /// The faces at it.
        faces: u32,
    },
    /// A vertex's link is not one simple cycle through all its faces.
    #[error("invalid triangulation: vertex {vertex}: link is not one simple cycle ({problem})")]
    Link {
        /// The vertex id.
        vertex: usize,
        /// How the star walk failed.
        problem: LinkProblem,
    },
    /// The dual graph is not connected.
    #[error(
        "invalid triangulation: not connected: {reached} of {faces} faces reachable from {from}"
    )]
    Disconnected {
        /// Faces reached.
        reached: usize,
        /// Live faces.
        faces: usize,
        /// The start face.
        from: FaceId,
    },
}

/// What is wrong with a corner's `opposite` entry ([`ValidationError::Gluing`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GluingProblem {
    /// The opposite is not a live corner.
    NotLive {
        /// The opposite entry.
        opposite: u32,
    },
    /// The opposite is in the same face.
    SameFace {
        /// The opposite entry.
        opposite: u32,
    },
    /// `opposite[opposite[c]] != c`.
    NotInvolution {
        /// The opposite entry.
        opposite: u32,
        /// Its opposite.
        back: u32,
    },
    /// The two corners see different edges.
    DifferentEdges {
        /// The edge seen from the corner.
        edge: [u32; 2],
        /// The edge seen from its opposite.
        other: [u32; 2],
    },
}

impl std::fmt::Display for GluingProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GluingProblem::NotLive { opposite } => {
                write!(f, "opposite {opposite} is not a live corner")
            }
            GluingProblem::SameFace { opposite } => {
                write!(f, "opposite {opposite} in the same face")
            }
            GluingProblem::NotInvolution { opposite, back } => {
                write!(f, "opposite({opposite}) = {back} is not the corner")
            }
            GluingProblem::DifferentEdges { edge, other } => {
                write!(
                    f,
                    "it and its opposite see different edges {edge:?} / {other:?}"
                )
            }
        }
    }
}

/// How a vertex's star walk failed ([`ValidationError::Link`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkProblem {
    /// The walk did not come back within the vertex's face count.
    DoesNotClose,
    /// The link visits a vertex twice.
    Repeats(VertexId),
    /// The walk closed after `walked` of the vertex's `faces` faces.
    Short {
        /// Faces walked.
        walked: u32,
        /// Faces at the vertex.
        faces: u32,
    },
}

impl std::fmt::Display for LinkProblem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            LinkProblem::DoesNotClose => write!(f, "the star walk does not close"),
            LinkProblem::Repeats(w) => write!(f, "it repeats {w}"),
            LinkProblem::Short { walked, faces } => write!(f, "{walked} of {faces} faces"),
        }
    }
}

macro_rules! ensure {
    ($cond:expr, $err:expr) => {
        if !$cond {
            return Err($err);
        }
    };
}

impl Triangulation {
    /// Re-checks every structural invariant from scratch, sharing no code with the fast
    /// paths beyond the star walk: array shapes, live counts, the `opposite` involution
    /// and its edge endpoints, every edge in exactly two faces, degrees, each link a
    /// simple cycle of length ≥ 3 (which together exclude duplicate faces),
    /// connectivity. O(V + F) time and memory, no hashing: edges are bucketed by their
    /// smaller endpoint (a counting sort), and repeated neighbours are found with
    /// per-vertex stamps. The
    /// error reported, when there are several, is deterministic (the first in the order
    /// of the checks, then of vertex or face ids). Used by the tests after every
    /// operation and by the command line's independent checks of large outputs.
    pub fn validate(&self) -> Result<(), ValidationError> {
        let nc = self.corner_vertex.len();
        let nv = self.vertex_corner.len();
        ensure!(
            nc % 3 == 0,
            ValidationError::ArrayShape {
                array: "corner_vertex",
                len: nc,
                expected: nc / 3 * 3,
            }
        );
        ensure!(
            self.opposite.len() == nc,
            ValidationError::ArrayShape {
                array: "opposite",
                len: self.opposite.len(),
                expected: nc,
            }
        );
        ensure!(
            self.degree.len() == nv,
            ValidationError::ArrayShape {
                array: "degree",
                len: self.degree.len(),
                expected: nv,
            }
        );

        let mut live_faces = 0;
        let mut corners_at = vec![0u32; nv];
        for f in 0..nc / 3 {
            let vs = &self.corner_vertex[3 * f..3 * f + 3];
            if vs[0] == NONE {
                ensure!(
                    vs.iter().all(|&v| v == NONE)
                        && self.opposite[3 * f..3 * f + 3].iter().all(|&o| o == NONE),
                    ValidationError::RemovedFaceHasData { face: f }
                );
                continue;
            }
            live_faces += 1;
            for &v in vs {
                ensure!(
                    (v as usize) < nv,
                    ValidationError::VertexOutOfRange { face: f, vertex: v }
                );
                ensure!(
                    self.vertex_corner[v as usize] != NONE,
                    ValidationError::RemovedVertexInFace { face: f, vertex: v }
                );
                corners_at[v as usize] += 1;
            }
            ensure!(
                vs[0] != vs[1] && vs[1] != vs[2] && vs[0] != vs[2],
                ValidationError::DegenerateFace {
                    face: f,
                    vertices: [vs[0], vs[1], vs[2]],
                }
            );
        }
        ensure!(
            live_faces == self.live_faces,
            ValidationError::LiveCount {
                what: "face",
                recorded: self.live_faces,
                actual: live_faces,
            }
        );
        ensure!(live_faces > 0, ValidationError::NoFaces);

        let endpoints = |c: usize| {
            let a = self.corner_vertex[Corner(c as u32).next().index()];
            let b = self.corner_vertex[Corner(c as u32).prev().index()];
            [a.min(b), a.max(b)]
        };
        let gluing = |corner: usize, problem| ValidationError::Gluing { corner, problem };
        for c in 0..nc {
            if self.corner_vertex[c] == NONE {
                continue;
            }
            let o = self.opposite[c] as usize;
            let opposite = o as u32;
            ensure!(
                o < nc && self.corner_vertex[o] != NONE,
                gluing(c, GluingProblem::NotLive { opposite })
            );
            ensure!(
                o / 3 != c / 3,
                gluing(c, GluingProblem::SameFace { opposite })
            );
            ensure!(
                self.opposite[o] as usize == c,
                gluing(
                    c,
                    GluingProblem::NotInvolution {
                        opposite,
                        back: self.opposite[o]
                    }
                )
            );
            ensure!(
                endpoints(c) == endpoints(o),
                gluing(
                    c,
                    GluingProblem::DifferentEdges {
                        edge: endpoints(c),
                        other: endpoints(o)
                    }
                )
            );
        }
        // Edges per vertex pair: the gluing is now known to pair the live corners two
        // by two on equal endpoints, so each edge is bucketed once (from its smaller
        // corner) as `[a, b]` (`a < b`) under `a`, and the `b`s of each bucket are
        // counted with stamped counters. A pair's faces are twice its edges.
        let (start, others) = buckets(
            nv,
            (0..nc)
                .filter(|&c| self.corner_vertex[c] != NONE && c < self.opposite[c] as usize)
                .map(|c| {
                    let [a, b] = endpoints(c);
                    (a, b)
                }),
        );
        let mut stamp = vec![NONE; nv];
        let mut count = vec![0u32; nv];
        for a in 0..nv {
            let bucket = &others[start[a] as usize..start[a + 1] as usize];
            for &b in bucket {
                let b = b as usize;
                if stamp[b] != a as u32 {
                    stamp[b] = a as u32;
                    count[b] = 0;
                }
                count[b] += 2;
            }
            for &b in bucket {
                let faces = count[b as usize];
                ensure!(
                    faces == 2,
                    ValidationError::EdgeFaceCount {
                        edge: [a as u32, b],
                        faces
                    }
                );
            }
        }
        drop(others);

        stamp.fill(NONE);
        let mut live_vertices = 0;
        for (v, &c) in self.vertex_corner.iter().enumerate() {
            if c == NONE {
                ensure!(
                    corners_at[v] == 0,
                    ValidationError::RemovedVertexUsed {
                        vertex: v,
                        faces: corners_at[v]
                    }
                );
                continue;
            }
            live_vertices += 1;
            ensure!(
                (c as usize) < nc && self.corner_vertex[c as usize] == v as u32,
                ValidationError::VertexCorner {
                    vertex: v,
                    corner: c
                }
            );
            let degree_error = ValidationError::Degree {
                vertex: v,
                degree: self.degree[v],
                faces: corners_at[v],
            };
            ensure!(self.degree[v] == corners_at[v], degree_error);
            ensure!(self.degree[v] >= 3, degree_error);
            let link = |problem| ValidationError::Link { vertex: v, problem };
            let mut walked = 0u32;
            for s in self.star(VertexId(v as u32)) {
                walked += 1;
                ensure!(walked <= corners_at[v], link(LinkProblem::DoesNotClose));
                let n = s.neighbour.index();
                ensure!(
                    n < nv && stamp[n] != v as u32,
                    link(LinkProblem::Repeats(s.neighbour))
                );
                stamp[n] = v as u32;
            }
            ensure!(
                walked == corners_at[v],
                link(LinkProblem::Short {
                    walked,
                    faces: corners_at[v]
                })
            );
        }
        ensure!(
            live_vertices == self.live_vertices,
            ValidationError::LiveCount {
                what: "vertex",
                recorded: self.live_vertices,
                actual: live_vertices,
            }
        );

        // No duplicate-face check is needed: two faces on the same three vertices
        // would be the only two faces on each of their edges (checked above), so glued
        // to each other along all three, and each of their vertices would have a link
        // of two edges, which the link checks above refuse (degree below 3, or a star
        // walk that closes before visiting all of a vertex's faces).

        // Connectivity over the dual graph.
        let first = self.faces().next().expect("live_faces > 0");
        let mut seen = vec![false; nc / 3];
        let mut stack = vec![first];
        seen[first.index()] = true;
        let mut reached = 1;
        while let Some(f) = stack.pop() {
            for g in self.face_neighbours(f) {
                if !seen[g.index()] {
                    seen[g.index()] = true;
                    reached += 1;
                    stack.push(g);
                }
            }
        }
        ensure!(
            reached == live_faces,
            ValidationError::Disconnected {
                reached,
                faces: live_faces,
                from: first,
            }
        );
        Ok(())
    }
}

/// A counting sort of `(key, value)` pairs by key (`key < n`): `start[k]..start[k + 1]`
/// is the range of key `k`'s values in the second vector, in input order. O(n + pairs).
fn buckets<T: Copy + Default>(
    n: usize,
    pairs: impl Iterator<Item = (u32, T)> + Clone,
) -> (Vec<u32>, Vec<T>) {
    let mut start = vec![0u32; n + 1];
    for (k, _) in pairs.clone() {
        start[k as usize + 1] += 1;
    }
    for k in 0..n {
        start[k + 1] += start[k];
    }
    let mut fill = start.clone();
    let mut values = vec![T::default(); start[n] as usize];
    for (k, v) in pairs {
        values[fill[k as usize] as usize] = v;
        fill[k as usize] += 1;
    }
    (start, values)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::octahedron;

    fn octa() -> Triangulation {
        let m = octahedron();
        Triangulation::from_faces(m.vertex_count, &m.faces).expect("octahedron")
    }

    #[test]
    fn the_octahedron_is_valid() {
        assert_eq!(octa().validate(), Ok(()));
    }

    #[test]
    fn each_corruption_is_named_with_its_element() {
        let mut t = octa();
        t.degree[2] += 1;
        assert!(matches!(
            t.validate(),
            Err(ValidationError::Degree { vertex: 2, .. })
        ));

        let mut t = octa();
        t.live_faces += 1;
        assert!(matches!(
            t.validate(),
            Err(ValidationError::LiveCount { what: "face", .. })
        ));

        let mut t = octa();
        let o = t.opposite[0];
        t.opposite[o as usize] = 1; // opposite[opposite[0]] != 0
        assert!(matches!(
            t.validate(),
            Err(ValidationError::Gluing {
                corner: 0,
                problem: GluingProblem::NotInvolution { .. }
            }) | Err(ValidationError::Gluing {
                problem: GluingProblem::SameFace { .. },
                ..
            })
        ));

        let mut t = octa();
        t.corner_vertex[0] = t.corner_vertex[1];
        assert!(matches!(
            t.validate(),
            Err(ValidationError::DegenerateFace { face: 0, .. })
        ));

        let mut t = octa();
        t.vertex_corner[3] = 0;
        if t.corner_vertex[0] != 3 {
            assert!(matches!(
                t.validate(),
                Err(ValidationError::VertexCorner {
                    vertex: 3,
                    corner: 0
                })
            ));
        }

        // Merging the two poles keeps every gluing consistent but puts each edge from
        // the equator to the merged pole in four faces.
        let mut t = octa();
        let (top, bottom) = (4, 5);
        assert!(t.faces().all(|f| {
            let vs = t.face_vertices(f);
            vs.contains(&VertexId(top)) != vs.contains(&VertexId(bottom))
        }));
        for v in t.corner_vertex.iter_mut() {
            if *v == top {
                *v = bottom;
            }
        }
        assert!(matches!(
            t.validate(),
            Err(ValidationError::EdgeFaceCount { faces: 4, edge }) if edge[1] == bottom
        ));

        let mut t = octa();
        t.opposite.pop();
        assert!(matches!(
            t.validate(),
            Err(ValidationError::ArrayShape {
                array: "opposite",
                ..
            })
        ));
    }

    /// A triangulation glued naively from a face list in which every edge lies in
    /// exactly two faces: no check of links or connectivity, so that pinched vertices and
    /// disconnected surfaces can be written down.
    fn glued(vertex_count: usize, faces: &[[u32; 3]]) -> Triangulation {
        let mut sides = std::collections::BTreeMap::<[u32; 2], Vec<u32>>::new();
        let mut vertex_corner = vec![NONE; vertex_count];
        let mut degree = vec![0u32; vertex_count];
        let mut corner_vertex = Vec::new();
        for (f, vs) in faces.iter().enumerate() {
            for i in 0..3 {
                let c = (3 * f + i) as u32;
                let (a, b) = (vs[(i + 1) % 3], vs[(i + 2) % 3]);
                sides.entry([a.min(b), a.max(b)]).or_default().push(c);
                let v = vs[i] as usize;
                if vertex_corner[v] == NONE {
                    vertex_corner[v] = c;
                }
                degree[v] += 1;
                corner_vertex.push(vs[i]);
            }
        }
        let mut opposite = vec![NONE; corner_vertex.len()];
        for corners in sides.values() {
            let &[c, o] = corners.as_slice() else {
                panic!("an edge in {} faces", corners.len())
            };
            opposite[c as usize] = o;
            opposite[o as usize] = c;
        }
        Triangulation {
            corner_vertex,
            opposite,
            live_vertices: vertex_corner.iter().filter(|&&c| c != NONE).count(),
            vertex_corner,
            degree,
            live_faces: faces.len(),
            state: crate::core::StateStamp::fresh(),
            stamps: Default::default(),
        }
    }

    /// Every problem the validation can see is reported exactly: the variant, the
    /// element and the numbers, for one corruption at a time of a valid triangulation,
    /// itself accepted fresh and with removed faces and vertices.
    #[test]
    fn every_problem_is_reported_with_its_element_and_numbers() {
        use ValidationError as E;
        let octahedron = octahedron();
        let fresh = octa();
        assert_eq!(
            glued(6, &octahedron.faces),
            fresh,
            "the naive gluing is the build's"
        );
        // Contracting [0, 2] removes vertex 2 and faces 0 = [0, 2, 4] and 4 = [2, 0, 5].
        let mut contracted = fresh.clone();
        contracted
            .contract(VertexId(0), VertexId(2), &mut crate::History::new())
            .expect("an octahedron edge is contractible");
        assert!(!contracted.is_vertex(VertexId(2)));
        assert!(!contracted.is_face(FaceId(0)) && !contracted.is_face(FaceId(4)));
        assert_eq!(fresh.validate(), Ok(()));
        assert_eq!(contracted.validate(), Ok(()));

        type Corrupt = fn(&mut Triangulation);
        let fresh_cases: Vec<(Corrupt, ValidationError)> = vec![
            (
                |t| t.corner_vertex.push(0),
                E::ArrayShape {
                    array: "corner_vertex",
                    len: 25,
                    expected: 24,
                },
            ),
            (
                |t| {
                    t.opposite.pop();
                },
                E::ArrayShape {
                    array: "opposite",
                    len: 23,
                    expected: 24,
                },
            ),
            (
                |t| {
                    t.degree.pop();
                },
                E::ArrayShape {
                    array: "degree",
                    len: 5,
                    expected: 6,
                },
            ),
            (
                |t| t.corner_vertex[3] = NONE,
                E::RemovedFaceHasData { face: 1 },
            ),
            (
                |t| t.corner_vertex[7] = 6,
                E::VertexOutOfRange { face: 2, vertex: 6 },
            ),
            (
                |t| t.corner_vertex[6] = 3,
                E::DegenerateFace {
                    face: 2,
                    vertices: [3, 3, 4],
                },
            ),
            (
                |t| t.corner_vertex[7] = 4,
                E::DegenerateFace {
                    face: 2,
                    vertices: [1, 4, 4],
                },
            ),
            (
                |t| t.corner_vertex[8] = 1,
                E::DegenerateFace {
                    face: 2,
                    vertices: [1, 3, 1],
                },
            ),
            (
                |t| t.live_faces += 1,
                E::LiveCount {
                    what: "face",
                    recorded: 9,
                    actual: 8,
                },
            ),
            (
                |t| {
                    t.corner_vertex.fill(NONE);
                    t.opposite.fill(NONE);
                    t.live_faces = 0;
                },
                E::NoFaces,
            ),
            (
                |t| t.opposite[0] = 24,
                E::Gluing {
                    corner: 0,
                    problem: GluingProblem::NotLive { opposite: 24 },
                },
            ),
            (
                |t| t.opposite[0] = 2,
                E::Gluing {
                    corner: 0,
                    problem: GluingProblem::SameFace { opposite: 2 },
                },
            ),
            (
                // Corner 0 (vertex 0 of [0, 2, 4]) faces [2, 4], glued to corner 4 of
                // [2, 1, 4]; pointed at corner 3, whose partner is corner 7 of [1, 3, 4].
                |t| t.opposite[0] = 3,
                E::Gluing {
                    corner: 0,
                    problem: GluingProblem::NotInvolution {
                        opposite: 3,
                        back: 7,
                    },
                },
            ),
            (
                // Corners 0 ([2, 4]) and 1 ([4, 0]) swap their partners: still an
                // involution, but across different edges.
                |t| {
                    let (o0, o1) = (t.opposite[0], t.opposite[1]);
                    t.opposite[0] = o1;
                    t.opposite[1] = o0;
                    t.opposite[o1 as usize] = 0;
                    t.opposite[o0 as usize] = 1;
                },
                E::Gluing {
                    corner: 0,
                    problem: GluingProblem::DifferentEdges {
                        edge: [2, 4],
                        other: [0, 4],
                    },
                },
            ),
            (
                // The poles merged: every edge from the equator to pole 5 lies in four
                // faces, the first of them from vertex 0.
                |t| {
                    for v in t.corner_vertex.iter_mut().filter(|v| **v == 4) {
                        *v = 5;
                    }
                },
                E::EdgeFaceCount {
                    edge: [0, 5],
                    faces: 4,
                },
            ),
            (
                |t| t.vertex_corner[3] = 0,
                E::VertexCorner {
                    vertex: 3,
                    corner: 0,
                },
            ),
            (
                |t| t.vertex_corner[3] = 24,
                E::VertexCorner {
                    vertex: 3,
                    corner: 24,
                },
            ),
            (
                |t| t.degree[2] += 1,
                E::Degree {
                    vertex: 2,
                    degree: 5,
                    faces: 4,
                },
            ),
            (
                |t| t.live_vertices += 1,
                E::LiveCount {
                    what: "vertex",
                    recorded: 7,
                    actual: 6,
                },
            ),
        ];
        // On the contracted octahedron: vertex 2 and faces 0 and 4 are removed.
        let contracted_cases: Vec<(Corrupt, ValidationError)> = vec![
            (|t| t.opposite[12] = 0, E::RemovedFaceHasData { face: 4 }),
            (
                |t| t.corner_vertex[3] = 2,
                E::RemovedVertexInFace { face: 1, vertex: 2 },
            ),
            (
                |t| {
                    let c = t.opposite[3];
                    t.opposite[3] = 0;
                    t.opposite[c as usize] = NONE;
                },
                E::Gluing {
                    corner: 3,
                    problem: GluingProblem::NotLive { opposite: 0 },
                },
            ),
            (
                |t| t.live_faces += 1,
                E::LiveCount {
                    what: "face",
                    recorded: 7,
                    actual: 6,
                },
            ),
            (
                |t| t.live_vertices -= 1,
                E::LiveCount {
                    what: "vertex",
                    recorded: 4,
                    actual: 5,
                },
            ),
        ];
        for (base, cases) in [(&fresh, fresh_cases), (&contracted, contracted_cases)] {
            for (k, (corrupt, expected)) in cases.into_iter().enumerate() {
                let mut t = base.clone();
                corrupt(&mut t);
                assert_eq!(t.validate(), Err(expected), "case {k}");
            }
        }

        // Two tetrahedra sharing vertex 0: the star walk from vertex 0 sees one of its
        // two fans.
        let tetrahedron = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
        let other = tetrahedron.map(|f| f.map(|v| if v == 0 { 0 } else { v + 3 }));
        let pinched = glued(7, &[tetrahedron, other].concat());
        assert_eq!(
            pinched.validate(),
            Err(E::Link {
                vertex: 0,
                problem: LinkProblem::Short {
                    walked: 3,
                    faces: 6
                }
            })
        );
        // Two disjoint tetrahedra.
        let apart = tetrahedron.map(|f| f.map(|v| v + 4));
        let two = glued(8, &[tetrahedron, apart].concat());
        assert_eq!(
            two.validate(),
            Err(E::Disconnected {
                reached: 4,
                faces: 8,
                from: FaceId(0)
            })
        );
        assert_eq!(glued(4, &tetrahedron).validate(), Ok(()));
    }

    /// The pillow (two triangles on the same three vertices, glued along all three
    /// edges), which mesh libraries that collapse a tetrahedron make, is refused at its
    /// first vertex: its link is a 2-cycle. Any two faces on the same vertices put the
    /// same edge twice into the link of each of those vertices, so the link checks refuse
    /// every duplicate face before the duplicate check is reached (which stays as a
    /// second line).
    #[test]
    fn the_pillow_is_refused_by_its_links() {
        // Face 0 = [0, 1, 2], face 1 = [0, 2, 1]; corner 3k + i is vertex i of face k,
        // glued to the corner of the other face at the same vertex.
        let pillow = Triangulation {
            corner_vertex: vec![0, 1, 2, 0, 2, 1],
            opposite: vec![3, 5, 4, 0, 2, 1],
            vertex_corner: vec![0, 1, 2],
            degree: vec![2, 2, 2],
            live_vertices: 3,
            live_faces: 2,
            state: crate::core::StateStamp::fresh(),
            stamps: Default::default(),
        };
        assert_eq!(
            pillow.validate(),
            Err(ValidationError::Degree {
                vertex: 0,
                degree: 2,
                faces: 2
            })
        );
    }

    /// The problems' messages say what went wrong, with the numbers involved.
    #[test]
    fn problems_display_what_went_wrong() {
        let shown = [
            (
                GluingProblem::NotLive { opposite: 7 }.to_string(),
                "opposite 7 is not a live corner",
            ),
            (
                GluingProblem::SameFace { opposite: 4 }.to_string(),
                "opposite 4 in the same face",
            ),
            (
                GluingProblem::NotInvolution {
                    opposite: 4,
                    back: 9,
                }
                .to_string(),
                "opposite(4) = 9 is not the corner",
            ),
            (
                GluingProblem::DifferentEdges {
                    edge: [1, 2],
                    other: [3, 4],
                }
                .to_string(),
                "it and its opposite see different edges [1, 2] / [3, 4]",
            ),
            (
                LinkProblem::DoesNotClose.to_string(),
                "the star walk does not close",
            ),
            (
                LinkProblem::Repeats(VertexId(5)).to_string(),
                "it repeats 5",
            ),
            (
                LinkProblem::Short {
                    walked: 2,
                    faces: 5,
                }
                .to_string(),
                "2 of 5 faces",
            ),
        ];
        for (got, want) in shown {
            assert_eq!(got, want);
        }
    }
}
