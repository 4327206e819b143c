//! The unrecorded local operations of the simplifier: contraction without an undo
//! record, replacing a disc bounded by a 3-cycle with one triangle, and compaction.
//!
//! **Guarantee.** [`Triangulation::collapse`] makes exactly the change
//! [`Triangulation::contract_tested`] makes (the same faces removed, the same corners
//! renamed), but keeps no record, so a simplifier that never undoes pays O(d_v) time and
//! no memory per contraction. [`Triangulation::replace_disc`] removes the faces of a
//! closed disc whose boundary is a 3-cycle `[p, q, x]` and the disc's interior vertices,
//! and glues one new face `[p, q, x]` in their place: χ, orientability and every vertex
//! outside the disc's interior are unchanged. The caller establishes that the region is
//! such a disc (the simplifier's nested mode checks it, and its specification check
//! re-derives it independently); [`Triangulation::compact`] renumbers live vertices and
//! faces densely, in order.

use super::ids::{Corner, FaceId, VertexId, NONE};
use super::tri::Triangulation;

/// What one walk around `v` finds about the edge `[u, v]` before contracting it.
#[derive(Copy, Clone, Debug)]
pub(crate) struct CollapsePlan {
    /// The two faces of `[u, v]`.
    pub(crate) faces: [FaceId; 2],
    /// Their third vertices.
    pub(crate) link: [VertexId; 2],
}

impl Triangulation {
    /// Pushes onto `renamed` the corners at `v` outside the two faces of `[u, v]`, in star
    /// order, and returns those faces and their third vertices. O(d_v).
    ///
    /// # Panics
    /// If `[u, v]` is not an edge (a caller bug).
    pub(crate) fn plan_collapse(
        &self,
        u: VertexId,
        v: VertexId,
        renamed: &mut Vec<Corner>,
    ) -> CollapsePlan {
        let start = renamed.len();
        let mut at_u = None;
        for (k, s) in self.star(v).enumerate() {
            renamed.push(s.corner);
            if s.neighbour == u {
                at_u = Some(k);
            }
        }
        let d = renamed.len() - start;
        let p = at_u.expect("collapse: [u, v] is not an edge");
        let q = (p + 1) % d;
        // The step whose exit neighbour is u and the step after it are the two faces.
        let first = renamed[start + p];
        let opp1 = self.corner_facing(first, u);
        let opp2 = self.opposite(opp1);
        debug_assert_eq!(renamed[start + q].face(), opp2.face());
        renamed.remove(start + p.max(q));
        renamed.remove(start + p.min(q));
        CollapsePlan {
            faces: [opp1.face(), opp2.face()],
            link: [self.vertex(opp1), self.vertex(opp2)],
        }
    }

    /// Applies a [`CollapsePlan`]: glues the outer neighbours of both faces, renames the
    /// `renamed` corners from `v` to `u`, removes the faces and `v`, and updates degrees
    /// and `vertex_corner`. Changes the state stamp. O(d_v).
    pub(crate) fn apply_collapse(
        &mut self,
        u: VertexId,
        v: VertexId,
        plan: &CollapsePlan,
        renamed: &[Corner],
    ) {
        let [f1, f2] = plan.faces;
        let [x, y] = plan.link;
        // Where x and y keep a corner if theirs is in a removed face: in the face across
        // [u, w] from f, found before the removed faces are cleared.
        let mut keep = [NONE; 2];
        for (k, (w, f)) in [(x, f1), (y, f2)].into_iter().enumerate() {
            if Corner(self.vertex_corner[w.index()]).face() == f {
                // In f = [u, v, w] the corner at v is opposite [u, w].
                let cv = self.corner_at(f.corner(0), v);
                keep[k] = self.corner_at(self.opposite(cv), w).0;
            }
        }
        for f in [f1, f2] {
            // In f the corner at u is opposite [v, w] and the corner at v opposite [u, w]:
            // after the contraction those two edges are one.
            let cu = self.corner_at(f.corner(0), u);
            let cv = self.corner_at(f.corner(0), v);
            let a = self.opposite[cu.index()];
            let b = self.opposite[cv.index()];
            self.opposite[a as usize] = b;
            self.opposite[b as usize] = a;
        }
        for &c in renamed {
            self.corner_vertex[c.index()] = u.0;
        }
        for f in [f1, f2] {
            for c in f.corners() {
                self.corner_vertex[c.index()] = NONE;
                self.opposite[c.index()] = NONE;
            }
        }
        let degree_v = self.degree[v.index()];
        // d_v - 4 may be negative (d_v = 3): add before subtracting.
        self.degree[u.index()] = self.degree[u.index()] + degree_v - 4;
        self.degree[x.index()] -= 1;
        self.degree[y.index()] -= 1;
        self.degree[v.index()] = 0;
        self.vertex_corner[v.index()] = NONE;
        // A renamed corner always exists: d_v - 2 >= 1.
        self.vertex_corner[u.index()] = renamed[0].0;
        for (k, w) in [x, y].into_iter().enumerate() {
            if keep[k] != NONE {
                self.vertex_corner[w.index()] = keep[k];
            }
        }
        self.live_vertices -= 1;
        self.live_faces -= 2;
        self.touch();
    }

    /// Contracts `[u, v]` keeping `u`, for a caller that has established the link
    /// condition and keeps no undo record. Returns the link `{x, y}` of the edge. `scratch`
    /// is cleared and reused (it holds `v`'s corners). O(d_v).
    ///
    /// # Panics
    /// If `[u, v]` is not an edge (a caller bug). Debug builds also assert the link
    /// condition when `d_u · d_v ≤ 4096`, as [`Self::contract_tested`].
    pub fn collapse(
        &mut self,
        u: VertexId,
        v: VertexId,
        scratch: &mut Vec<Corner>,
    ) -> [VertexId; 2] {
        debug_assert!(
            self.degree(u).saturating_mul(self.degree(v)) > 64 * 64
                || self.link_condition_naive(u, v),
            "collapse: [{u}, {v}] fails the link condition"
        );
        scratch.clear();
        let plan = self.plan_collapse(u, v, scratch);
        self.apply_collapse(u, v, &plan, scratch);
        plan.link
    }

    /// [`Self::collapse`] for a caller that has just walked `v`'s star: `star_v[k]` and
    /// `link_v[k]` are the corner and the neighbour of step `k` of [`Self::star`]`(v)`
    /// (any start). Skips the walk; otherwise the same change. `scratch` is cleared and
    /// reused. O(d_v).
    pub(crate) fn collapse_walked(
        &mut self,
        u: VertexId,
        v: VertexId,
        star_v: &[Corner],
        link_v: &[VertexId],
        scratch: &mut Vec<Corner>,
    ) -> [VertexId; 2] {
        debug_assert_eq!(star_v.len(), self.degree(v));
        debug_assert!(
            self.degree(u).saturating_mul(self.degree(v)) > 64 * 64
                || self.link_condition_naive(u, v),
            "collapse: [{u}, {v}] fails the link condition"
        );
        let p = link_v
            .iter()
            .position(|&n| n == u)
            .expect("collapse_walked: [u, v] is not an edge");
        scratch.clear();
        let plan = self.plan_collapse_walked(u, star_v, p, scratch);
        self.apply_collapse(u, v, &plan, scratch);
        plan.link
    }

    /// [`Self::plan_collapse`] from `v`'s star already walked (`star_v`, in the order of
    /// [`Self::star`]`(v)`) with `u` the exit neighbour of step `p`: the same plan and
    /// the same renamed corners in the same order, without walking the star again.
    pub(crate) fn plan_collapse_walked(
        &self,
        u: VertexId,
        star_v: &[Corner],
        p: usize,
        renamed: &mut Vec<Corner>,
    ) -> CollapsePlan {
        let d = star_v.len();
        let q = (p + 1) % d;
        // As in `plan_collapse`: the step whose exit neighbour is u and the next one are
        // the two faces of [u, v].
        let opp1 = self.corner_facing(star_v[p], u);
        let opp2 = self.opposite(opp1);
        debug_assert_eq!(star_v[q].face(), opp2.face());
        renamed.extend(
            star_v
                .iter()
                .enumerate()
                .filter(|&(k, _)| k != p && k != q)
                .map(|(_, &c)| c),
        );
        CollapsePlan {
            faces: [opp1.face(), opp2.face()],
            link: [self.vertex(opp1), self.vertex(opp2)],
        }
    }

    /// Replaces a closed disc bounded by the 3-cycle `[p, q, x]` with the single face
    /// `[p, q, x]` and returns the new face (it reuses the slot of `faces[0]`).
    ///
    /// `faces` are the disc's faces, `interior` its interior vertices (every vertex of
    /// those faces except `p`, `q`, `x`), and `sides` the corners inside the disc opposite
    /// its boundary edges `[p, q]`, `[q, x]`, `[x, p]`, in that order. The new face runs
    /// `p → q` in the direction `sides[0]`'s face does, so a consistently oriented surface
    /// stays consistently oriented. O(|faces| + |interior|).
    ///
    /// The caller guarantees the disc property (see the module documentation); debug
    /// builds check the shape of the arguments (`|faces| = 2 |interior| + 1`).
    pub(crate) fn replace_disc(
        &mut self,
        cycle: [VertexId; 3],
        faces: &[FaceId],
        interior: &[VertexId],
        sides: [Corner; 3],
    ) -> FaceId {
        let [p, q, x] = cycle;
        debug_assert_eq!(faces.len(), 2 * interior.len() + 1);
        debug_assert!(faces.contains(&sides[0].face()));
        // The outside corners across the three boundary edges, before anything changes.
        let outside = sides.map(|c| self.opposite[c.index()]);
        // Does sides[0]'s face run p → q? Its corner opposite [p, q] is followed by p.
        let forward = self.corner_vertex[sides[0].next().index()] == p.0;
        // Faces at p, q and x inside the disc (each loses them and gains the new face).
        let mut lost = [0u32; 3];
        for &f in faces {
            for c in f.corners() {
                let w = self.corner_vertex[c.index()];
                if let Some(k) = cycle.iter().position(|z| z.0 == w) {
                    lost[k] += 1;
                }
                self.corner_vertex[c.index()] = NONE;
                self.opposite[c.index()] = NONE;
            }
        }
        for &v in interior {
            self.vertex_corner[v.index()] = NONE;
            self.degree[v.index()] = 0;
        }
        let f = faces[0];
        let order = if forward { [p, q, x] } else { [q, p, x] };
        for (s, w) in order.into_iter().enumerate() {
            self.corner_vertex[3 * f.index() + s] = w.0;
        }
        // Slot 2 (x) is opposite [p, q]; the slot of p is opposite [q, x], of q [x, p].
        let (slot_p, slot_q) = if forward { (0, 1) } else { (1, 0) };
        let glue = [(2, outside[0]), (slot_p, outside[1]), (slot_q, outside[2])];
        for (s, o) in glue {
            let c = 3 * f.0 + s;
            self.opposite[c as usize] = o;
            self.opposite[o as usize] = c;
        }
        for (k, w) in cycle.into_iter().enumerate() {
            self.degree[w.index()] = self.degree[w.index()] + 1 - lost[k];
            self.vertex_corner[w.index()] = 3 * f.0 + [slot_p, slot_q, 2][k];
        }
        self.live_vertices -= interior.len();
        self.live_faces -= faces.len() - 1;
        self.touch();
        f
    }

    /// Renumbers the live vertices and faces densely, keeping their order, and drops the
    /// removed slots. Returns the new id of every old vertex id (`None` for a removed
    /// one). Corners keep their slot within their face. O(vertex capacity + face
    /// capacity).
    pub fn compact(&mut self) -> Vec<Option<VertexId>> {
        self.compact_ids()
            .into_iter()
            .map(|v| (v != NONE).then_some(VertexId(v)))
            .collect()
    }

    /// [`Self::compact`], returning the new ids as raw ids with `NONE` for a removed
    /// vertex (half the memory, no conversion: the simplifier compacts every few passes).
    pub(crate) fn compact_ids(&mut self) -> Vec<u32> {
        let mut vertex_map = vec![NONE; self.vertex_corner.len()];
        let mut next = 0u32;
        for (m, &c) in vertex_map.iter_mut().zip(&self.vertex_corner) {
            if c != NONE {
                *m = next;
                next += 1;
            }
        }
        // The new first corner of every face (NONE for a removed face).
        let mut next_base = 0u32;
        let face_base: Vec<u32> = self
            .corner_vertex
            .chunks_exact(3)
            .map(|face| {
                if face[0] == NONE {
                    return NONE;
                }
                let base = next_base;
                next_base += 3;
                base
            })
            .collect();
        let remap_corner = |c: u32| face_base[(c / 3) as usize] + c % 3;
        // Face f moves to a slot at or before its own, so one forward sweep rewrites in
        // place.
        for (f, &base) in face_base.iter().enumerate() {
            if base == NONE {
                continue;
            }
            let (r, w) = (3 * f, base as usize);
            let v = [
                self.corner_vertex[r],
                self.corner_vertex[r + 1],
                self.corner_vertex[r + 2],
            ];
            let o = [self.opposite[r], self.opposite[r + 1], self.opposite[r + 2]];
            for s in 0..3 {
                self.corner_vertex[w + s] = vertex_map[v[s] as usize];
                self.opposite[w + s] = remap_corner(o[s]);
            }
        }
        let w = next_base as usize;
        self.corner_vertex.truncate(w);
        self.opposite.truncate(w);
        let mut k = 0usize;
        for v in 0..self.vertex_corner.len() {
            let c = self.vertex_corner[v];
            if c != NONE {
                self.vertex_corner[k] = remap_corner(c);
                self.degree[k] = self.degree[v];
                k += 1;
            }
        }
        self.vertex_corner.truncate(k);
        self.degree.truncate(k);
        self.corner_vertex.shrink_to_fit();
        self.opposite.shrink_to_fit();
        self.vertex_corner.shrink_to_fit();
        self.degree.shrink_to_fit();
        self.touch();
        vertex_map
    }
}

#[cfg(test)]
mod tests {
    use crate::gen;
    use crate::Triangulation;

    fn build(mesh: crate::TriMesh) -> Triangulation {
        Triangulation::from_faces(mesh.vertex_count, &mesh.faces).expect("a closed surface")
    }

    /// The face set a contraction of `[u, v]` must leave, from the face list alone: `v`
    /// renamed `u`, the two faces through the edge dropped.
    fn predicted(t: &Triangulation, u: crate::VertexId, v: crate::VertexId) -> Vec<[u32; 3]> {
        let mut out: Vec<[u32; 3]> = t
            .face_list()
            .into_iter()
            .filter(|f| !(f.contains(&u.0) && f.contains(&v.0)))
            .map(|f| {
                let mut f = f.map(|w| if w == v.0 { u.0 } else { w });
                f.sort_unstable();
                f
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// The cyclic order of a face, rotated to start at its smallest vertex (the
    /// orientation is kept: [0, 2, 4] and [2, 4, 0] agree, [0, 4, 2] does not).
    fn cyclic(f: [u32; 3]) -> [u32; 3] {
        let k = (0..3).min_by_key(|&k| f[k]).unwrap_or(0);
        [f[k], f[(k + 1) % 3], f[(k + 2) % 3]]
    }

    /// The octahedron with its face [0, 2, 4] subdivided by vertex 6, then the disc of
    /// the three faces at 6 replaced by one face: the octahedron again, the new face
    /// running as [0, 2, 4] did, so the surface stays consistently oriented.
    #[test]
    fn replace_disc_restores_the_face_with_its_orientation() {
        use crate::core::{Corner, VertexId};
        let oct = gen::octahedron();
        let at = oct.faces.iter().position(|f| cyclic(*f) == [0, 2, 4]);
        assert!(at.is_some(), "the octahedron lists [0, 2, 4]");
        let mut faces: Vec<[u32; 3]> = oct.faces.clone();
        faces.retain(|f| cyclic(*f) != [0, 2, 4]);
        faces.extend([[0, 2, 6], [2, 4, 6], [4, 0, 6]]);
        for order in [[0, 2, 4], [2, 0, 4]] {
            // Both directions of the cycle as [p, q, x]: the new face follows the disc.
            let mut t = Triangulation::from_faces(7, &faces).expect("a sphere");
            assert_eq!(t.orientation().map(|f| f.contains(&true)), Some(false));
            let [p, q, x] = order.map(VertexId);
            let six = VertexId(6);
            let disc: Vec<_> = t
                .faces()
                .filter(|&f| t.face_vertices(f).contains(&six))
                .collect();
            // The corner at 6 in the disc face through a and b faces the edge [a, b].
            let side = |a: VertexId, b: VertexId| -> Corner {
                let f = disc
                    .iter()
                    .copied()
                    .find(|&f| {
                        let vs = t.face_vertices(f);
                        vs.contains(&a) && vs.contains(&b)
                    })
                    .expect("a disc face on the side");
                f.corners()
                    .into_iter()
                    .find(|&c| t.vertex(c) == six)
                    .expect("the corner at 6")
            };
            let sides = [side(p, q), side(q, x), side(x, p)];
            let mut disc = disc;
            disc.sort_by_key(|&f| f != sides[0].face());
            let new = t.replace_disc([p, q, x], &disc, &[six], sides);
            assert_eq!(t.validate(), Ok(()));
            assert_eq!(t.vertex_count(), 6);
            assert_eq!(
                cyclic(t.face_vertices(new).map(|v| v.0)),
                [0, 2, 4],
                "with the cycle given as {order:?}"
            );
            assert_eq!(t.orientation().map(|f| f.contains(&true)), Some(false));
        }
    }

    fn sorted_faces(t: &Triangulation) -> Vec<[u32; 3]> {
        let mut out: Vec<[u32; 3]> = t
            .face_list()
            .into_iter()
            .map(|mut f| {
                f.sort_unstable();
                f
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// On every contractible edge of a reducible torus (both directions), `collapse` gives
    /// the triangulation `contract_tested` gives and the face set predicted from the face
    /// list; `collapse_walked` from a rotated start gives the same faces.
    #[test]
    fn collapse_matches_contract_tested() {
        let t0 = gen::random(&gen::RandomParams {
            surface: gen::SurfaceKind::Orientable(1),
            min_faces: 60,
            flip_percent: 30,
            seed: 3,
        })
        .expect("a random surface within the limits");
        let mut checked = 0;
        for (a0, b0, _) in t0.edges().collect::<Vec<_>>() {
            for (u, v) in [(a0, b0), (b0, a0)] {
                if !t0.link_condition_naive(u, v) {
                    continue;
                }
                let mut a = t0.clone();
                let mut b = t0.clone();
                let mut c = t0.clone();
                a.contract_tested(u, v, &mut crate::History::new());
                b.collapse(u, v, &mut Vec::new());
                assert_eq!(a, b, "[{u}, {v}]");
                b.validate().unwrap();
                assert_eq!(sorted_faces(&b), predicted(&t0, u, v), "[{u}, {v}]");
                // The walk may start anywhere: start it one step in.
                let steps: Vec<_> = t0.star(v).collect();
                let mut star: Vec<_> = steps.iter().map(|s| s.corner).collect();
                let mut link: Vec<_> = steps.iter().map(|s| s.neighbour).collect();
                star.rotate_left(1);
                link.rotate_left(1);
                c.collapse_walked(u, v, &star, &link, &mut Vec::new());
                c.validate().unwrap();
                assert_eq!(c.face_list(), b.face_list(), "[{u}, {v}]");
                checked += 1;
            }
        }
        assert!(checked >= 20, "only {checked} contractible directed edges");
    }

    #[test]
    fn compact_keeps_the_surface_and_order() {
        let mut t = build(gen::octahedron());
        let mut h = crate::History::new();
        let (u, v, _) = t.edges().next().expect("an edge");
        t.contract(u, v, &mut h)
            .expect("the octahedron's edges are contractible");
        let before: Vec<[u32; 3]> = t.face_list();
        let map = t.compact();
        t.validate().unwrap();
        assert_eq!(t.vertex_capacity(), t.vertex_count());
        assert_eq!(t.face_capacity(), t.face_count());
        let after: Vec<[u32; 3]> = t.face_list();
        let mapped: Vec<[u32; 3]> = before
            .iter()
            .map(|f| f.map(|v| map[v as usize].expect("live").0))
            .collect();
        assert_eq!(after, mapped);
        assert_eq!(map[v.index()], None);
        assert_eq!(map[u.index()], Some(u));
    }
}
