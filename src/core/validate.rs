//! From-scratch structural validation of a [`Triangulation`].

use std::collections::{HashMap, HashSet};

use super::ids::{Corner, FaceId, VertexId, NONE};
use super::tri::Triangulation;

/// A violated structural invariant, with the element involved.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("invalid triangulation: {0}")]
pub struct ValidationError(pub String);

macro_rules! ensure {
    ($cond:expr, $($fmt:tt)*) => {
        if !$cond {
            return Err(ValidationError(format!($($fmt)*)));
        }
    };
}

impl Triangulation {
    /// Re-checks every structural invariant from scratch, sharing no code with the fast
    /// paths beyond the star walk: array shapes, live counts, the `opposite` involution
    /// and its edge endpoints, degrees, each link a simple cycle of length ≥ 3, no
    /// duplicate faces, every edge in exactly two faces, connectivity. O(F) expected
    /// (hash sets). Used by the tests after every operation.
    pub fn validate(&self) -> Result<(), ValidationError> {
        let nc = self.corner_vertex.len();
        let nv = self.vertex_corner.len();
        ensure!(
            nc % 3 == 0,
            "corner array length {nc} is not a multiple of 3"
        );
        ensure!(
            self.opposite.len() == nc,
            "opposite has {} entries, corners {nc}",
            self.opposite.len()
        );
        ensure!(
            self.degree.len() == nv,
            "degree has {} entries, vertices {nv}",
            self.degree.len()
        );

        let mut live_faces = 0;
        let mut corners_at = vec![0u32; nv];
        for f in 0..nc / 3 {
            let vs = &self.corner_vertex[3 * f..3 * f + 3];
            if vs[0] == NONE {
                ensure!(
                    vs.iter().all(|&v| v == NONE)
                        && self.opposite[3 * f..3 * f + 3].iter().all(|&o| o == NONE),
                    "removed face {f} has live data"
                );
                continue;
            }
            live_faces += 1;
            for &v in vs {
                ensure!((v as usize) < nv, "face {f}: vertex {v} out of range");
                ensure!(
                    self.vertex_corner[v as usize] != NONE,
                    "face {f}: vertex {v} is removed"
                );
                corners_at[v as usize] += 1;
            }
            ensure!(
                vs[0] != vs[1] && vs[1] != vs[2] && vs[0] != vs[2],
                "face {f} is degenerate: {vs:?}"
            );
        }
        ensure!(
            live_faces == self.live_faces,
            "live face count {} but {live_faces} faces are live",
            self.live_faces
        );
        ensure!(live_faces > 0, "no faces");

        let endpoints = |c: usize| {
            let a = self.corner_vertex[Corner(c as u32).next().index()];
            let b = self.corner_vertex[Corner(c as u32).prev().index()];
            (a.min(b), a.max(b))
        };
        let mut edge_faces: HashMap<(u32, u32), u32> = HashMap::new();
        for c in 0..nc {
            if self.corner_vertex[c] == NONE {
                continue;
            }
            let o = self.opposite[c] as usize;
            ensure!(
                o < nc && self.corner_vertex[o] != NONE,
                "corner {c}: opposite {o} is not a live corner"
            );
            ensure!(o / 3 != c / 3, "corner {c}: opposite {o} in the same face");
            ensure!(
                self.opposite[o] as usize == c,
                "corner {c}: opposite({o}) = {} is not {c}",
                self.opposite[o]
            );
            ensure!(
                endpoints(c) == endpoints(o),
                "corner {c} and its opposite {o} see different edges {:?} / {:?}",
                endpoints(c),
                endpoints(o)
            );
            *edge_faces.entry(endpoints(c)).or_insert(0) += 1;
        }
        for (e, n) in &edge_faces {
            ensure!(*n == 2, "edge {e:?} lies in {n} faces");
        }

        let mut live_vertices = 0;
        for (v, &c) in self.vertex_corner.iter().enumerate() {
            if c == NONE {
                ensure!(
                    corners_at[v] == 0,
                    "removed vertex {v} is used by {} faces",
                    corners_at[v]
                );
                continue;
            }
            live_vertices += 1;
            ensure!(
                (c as usize) < nc && self.corner_vertex[c as usize] == v as u32,
                "vertex {v}: its corner {c} is not at it"
            );
            ensure!(
                self.degree[v] == corners_at[v],
                "vertex {v}: degree {} but {} faces",
                self.degree[v],
                corners_at[v]
            );
            ensure!(self.degree[v] >= 3, "vertex {v}: degree {}", self.degree[v]);
            let mut seen = HashSet::new();
            let mut walked = 0u32;
            for s in self.star(VertexId(v as u32)) {
                walked += 1;
                ensure!(
                    walked <= corners_at[v],
                    "vertex {v}: star walk does not close"
                );
                ensure!(
                    seen.insert(s.neighbour),
                    "vertex {v}: link repeats {}",
                    s.neighbour
                );
            }
            ensure!(
                walked == corners_at[v],
                "vertex {v}: link is not one cycle ({walked} of {} faces)",
                corners_at[v]
            );
        }
        ensure!(
            live_vertices == self.live_vertices,
            "live vertex count {} but {live_vertices} vertices are live",
            self.live_vertices
        );

        let mut face_sets = HashSet::new();
        for f in self.faces() {
            let mut k = self.face_vertices(f).map(|v| v.0);
            k.sort_unstable();
            ensure!(
                face_sets.insert(k),
                "face {f} duplicates another face {k:?}"
            );
        }

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
            "not connected: {reached} of {live_faces} faces reachable from {first}"
        );
        let _ = FaceId(0);
        Ok(())
    }
}
