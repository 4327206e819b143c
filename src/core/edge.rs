//! Edge identities: [`Edge`] (an edge of the current state, named by its canonical
//! corner, [`Triangulation::edge_at`]) and [`EdgeNumbering`] (dense edge numbers that
//! survive contractions and flips). Everything else about an edge is asked by its
//! endpoints or an opposite corner: [`Triangulation::edges`], [`Triangulation::find_edge`],
//! [`Triangulation::edge_corners`], [`Triangulation::edge_endpoints`],
//! [`Triangulation::edge_link`].
//!
//! The core has no edge array: an edge is the pair of corners opposite it, one in each of
//! its two faces. [`Edge`] picks the smaller of the two, so equal handles mean equal
//! edges *within one state*. A contraction or a flip re-pairs corners, so handles are not
//! stable across changes; [`EdgeNumbering`] is the structure for identities that must
//! survive them (pairings under flips, edge queues under contraction, the ε counter).

use super::contract::ContractionRecord;
use super::flip::FlipRecord;
use super::ids::{Corner, NONE};
use super::tri::Triangulation;
use std::fmt;

/// An edge of a [`Triangulation`] in its current state, named by the smaller of its two
/// opposite corners. Two handles of the same state are equal iff they name the same
/// edge; a contraction or flip may change which corner is canonical.
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Edge(Corner);

impl Edge {
    /// The canonical corner: the smaller of the two corners opposite the edge.
    #[inline]
    pub fn corner(self) -> Corner {
        self.0
    }
}

impl fmt::Debug for Edge {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "e{}", self.0 .0)
    }
}

impl Triangulation {
    /// The edge opposite corner `c` (a live corner). O(1).
    #[inline]
    pub fn edge_at(&self, c: Corner) -> Edge {
        Edge(c.min(self.opposite(c)))
    }
}

/// A dense edge number, `0..`[`EdgeNumbering::capacity`].
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct EdgeId(pub u32);

impl EdgeId {
    /// The number as an array index.
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl fmt::Debug for EdgeId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{}", self.0)
    }
}

/// Dense edge numbers that stay attached to "the same edge" across contractions and
/// flips, for per-edge arrays (`Vec<T>` indexed by [`EdgeId`]) instead of hash maps.
///
/// # Identity (the DCEL of the RS paper, Alg. 4.7)
/// - Numbers are assigned `0, 1, …` in [`Triangulation::edges`] order at construction.
/// - Contracting `[u, v]` (keeping `u`, link `{x, y}`): every edge `[v, z]` renamed
///   `[u, z]` keeps its number; the merged edge `[u, x]` keeps the number of the old
///   `[u, x]` (likewise for `y`); the numbers of `[u, v]`, `[v, x]` and `[v, y]` die.
/// - Flipping `[a, b]` into `[c, d]`: the new edge takes the number of the old one (the
///   same dual edge between the same two face ids); every other edge keeps its number.
///
/// - Undoing a contraction ([`crate::History::undo`], the vertex split of the tri-quad
///   expansion) revives the three numbers it killed; undoing a flip swaps back.
///
/// Dead numbers are never reused. The caller reports every change, in order, through
/// [`Self::contracted`], [`Self::flipped`], [`Self::uncontracted`] and
/// [`Self::unflipped`]; the numbering is then exact, and [`Self::check`] verifies it from
/// scratch.
///
/// # Cost
/// 4 bytes per corner plus 4 bytes per edge number; O(1) per operation.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeNumbering {
    ids: EdgeIds,
    corner_of: Vec<u32>,
    live: usize,
}

/// The per-corner half of [`EdgeNumbering`]: each corner's edge number, following
/// contractions with the same identity rules, without the live-corner table. For
/// counters that only ever ask "which edge is opposite this corner" (the ε counter of
/// the irreducible algorithms): 4 bytes per corner, and a contraction touches only the
/// two corners it glues.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct EdgeIds {
    of_corner: Vec<u32>,
    count: usize,
}

impl EdgeIds {
    /// Numbers the edges of `tri` in [`Triangulation::edges`] order. O(F).
    pub fn new(tri: &Triangulation) -> Self {
        // The order of `Triangulation::edges` (faces in id order, corners in slot order,
        // each edge at its smaller corner), as a flat loop: this runs once per reduction
        // with ε counting, over millions of corners.
        let nc = 3 * tri.face_capacity();
        let mut of_corner = vec![NONE; nc];
        let mut count = 0u32;
        for c in 0..nc {
            let o = tri.opposite[c];
            if o != NONE && (c as u32) < o {
                of_corner[c] = count;
                of_corner[o as usize] = count;
                count += 1;
            }
        }
        EdgeIds {
            of_corner,
            count: count as usize,
        }
    }

    /// One more than the largest number given.
    #[inline]
    pub fn capacity(&self) -> usize {
        self.count
    }

    /// The number of the edge opposite live corner `c`. O(1).
    #[inline]
    pub fn id(&self, c: Corner) -> EdgeId {
        EdgeId(self.of_corner[c.index()])
    }

    /// Updates the numbers after `rec` (see [`EdgeNumbering`] for the identity rules):
    /// the corner that faced `[v, x]` takes the number of `[u, x]` (likewise for `y`).
    /// Returns the numbers of `[u, v]`, `[v, x]`, `[v, y]`, which died. O(1).
    #[inline]
    pub fn contracted(&mut self, rec: &ContractionRecord) -> [EdgeId; 3] {
        let uv = EdgeId(self.of_corner[rec.corner_opposite_uv().index()]);
        let mut dead = [uv; 3];
        for (k, (dying, kept)) in rec.glued().into_iter().enumerate() {
            dead[k + 1] = EdgeId(self.of_corner[dying.index()]);
            self.of_corner[dying.index()] = self.of_corner[kept.index()];
        }
        dead
    }

    /// Updates the numbers after the exact undo of `rec` ([`crate::History::undo`]), the
    /// newest contraction reported to [`Self::contracted`] and not yet undone: the
    /// corner outside `[v, x]` (resp. `[v, y]`), which had taken the merged number,
    /// gets the number of `[v, x]` back from the revived face. The revived faces'
    /// corners kept their numbers while the faces were dead. O(1).
    #[inline]
    pub fn uncontracted(&mut self, rec: &ContractionRecord) {
        let (saved_vertex, saved_opposite) = (rec.saved_vertex(), rec.saved_opposite());
        for (k, f) in rec.faces.into_iter().enumerate() {
            for s in 0..3 {
                if saved_vertex[3 * k + s] == rec.u.0 {
                    let c = f.corner(s as u32);
                    let across = saved_opposite[3 * k + s] as usize;
                    self.of_corner[across] = self.of_corner[c.index()];
                }
            }
        }
    }

    /// Updates the numbers after the flip `rec` was applied: the new edge takes the
    /// flipped edge's number; `[a, d]` and `[b, c]` move to the corners that now face
    /// them. Returns the numbers of the flipped edge, `[a, d]` and `[b, c]`. O(1).
    #[inline]
    pub fn flipped_corners(&mut self, moved: [Corner; 2], new_corners: [Corner; 2]) -> [u32; 3] {
        let [k1, k2] = moved;
        let [n1, n2] = new_corners;
        let old = self.of_corner[k1.index()];
        let bc = self.of_corner[n1.index()];
        let ad = self.of_corner[n2.index()];
        self.of_corner[n1.index()] = old;
        self.of_corner[n2.index()] = old;
        self.of_corner[k1.index()] = ad;
        self.of_corner[k2.index()] = bc;
        [old, ad, bc]
    }
}

impl EdgeNumbering {
    /// The full numbering (with the corner of every live number) from its per-corner
    /// half `ids`, which must number `tri`'s edges: made by [`EdgeIds::new`] on an
    /// earlier state and told every change since. One pass over the corners, O(F): for
    /// a caller that needs [`Self::corner`] only at the end of a long run of changes
    /// (the tri-quad expansion) and so keeps only `ids` meanwhile. Each live number
    /// holds the smaller of its edge's two corners, as [`Self::new`] gives (the
    /// expansion's flips, and so its output, follow this choice). Checked against `tri`
    /// ([`Self::check`]) in debug builds.
    pub fn from_ids(ids: EdgeIds, tri: &Triangulation) -> Self {
        let mut corner_of = vec![NONE; ids.capacity()];
        let mut live = 0;
        for f in tri.faces() {
            for c in f.corners() {
                let o = tri.opposite(c);
                if c < o {
                    if let Some(slot) = corner_of.get_mut(ids.id(c).index()) {
                        *slot = c.0;
                        live += 1;
                    }
                }
            }
        }
        let numbering = EdgeNumbering {
            ids,
            corner_of,
            live,
        };
        debug_assert_eq!(numbering.check(tri), Ok(()));
        numbering
    }

    /// Numbers the edges of `tri` in [`Triangulation::edges`] order. O(F).
    pub fn new(tri: &Triangulation) -> Self {
        let ids = EdgeIds::new(tri);
        let mut corner_of = vec![NONE; ids.capacity()];
        for (_, _, c) in tri.edges() {
            corner_of[ids.id(c).index()] = c.0;
        }
        let live = corner_of.len();
        EdgeNumbering {
            ids,
            corner_of,
            live,
        }
    }

    /// One more than the largest number ever given (live or dead).
    #[inline]
    pub fn capacity(&self) -> usize {
        self.corner_of.len()
    }

    /// Number of live edges.
    #[inline]
    pub fn live_count(&self) -> usize {
        self.live
    }

    /// The number of the edge opposite live corner `c`. O(1).
    #[inline]
    pub fn id(&self, c: Corner) -> EdgeId {
        EdgeId(self.ids.of_corner[c.index()])
    }

    /// A live corner opposite edge `e`, or `None` if `e` died. O(1).
    #[inline]
    pub fn corner(&self, e: EdgeId) -> Option<Corner> {
        match self.corner_of.get(e.index()) {
            Some(&c) if c != NONE => Some(Corner(c)),
            _ => None,
        }
    }

    /// Whether edge `e` is alive.
    #[inline]
    pub fn is_alive(&self, e: EdgeId) -> bool {
        self.corner(e).is_some()
    }

    /// Updates the numbers after `rec` was applied to the triangulation (which must have
    /// been numbered before it). Returns the three numbers that died: `[u, v]`, `[v, x]`,
    /// `[v, y]`. O(1).
    ///
    /// The removed faces' corners keep their numbers: their slots stay dead until an
    /// exact undo revives those very faces, and then they are what
    /// [`Self::uncontracted`] reads back, so undo support costs no memory.
    pub fn contracted(&mut self, rec: &ContractionRecord) -> [EdgeId; 3] {
        let dead = self.ids.contracted(rec);
        for e in dead {
            self.kill(e);
        }
        // The merged edges keep [u, x]'s and [u, y]'s numbers; the corner each number
        // held may have been in a removed face, so point it at the outer one.
        for (_, kept) in rec.glued() {
            self.corner_of[self.ids.id(kept).index()] = kept.0;
        }
        dead
    }

    /// Updates the numbers after the exact undo of `rec` ([`crate::History::undo`], the
    /// vertex split of the tri-quad expansion), which must be the newest contraction
    /// reported to [`Self::contracted`] and not yet undone: `[u, v]`, `[v, x]` and
    /// `[v, y]` get their numbers back; the merged edges split again, keeping their
    /// numbers on `[u, x]` and `[u, y]`. O(1).
    ///
    /// The numbering must have seen `rec` through [`Self::contracted`]: the revived
    /// numbers are read back from the removed faces' corners, which a numbering made
    /// afterwards (by [`Self::new`] on the contracted surface) never numbered. To number
    /// the edges of a replayed history, number the input and feed it every record.
    pub fn uncontracted(&mut self, rec: &ContractionRecord) {
        let (saved_vertex, saved_opposite) = (rec.saved_vertex(), rec.saved_opposite());
        for (k, f) in rec.faces.into_iter().enumerate() {
            for s in 0..3 {
                let c = f.corner(s as u32);
                let w = saved_vertex[3 * k + s];
                let id = self.ids.of_corner[c.index()];
                if w == rec.u.0 {
                    // c faces [v, x] (resp. [v, y]), the edge that died; its outer corner
                    // had taken the merged number and gets this one back.
                    let across = saved_opposite[3 * k + s] as usize;
                    self.ids.of_corner[across] = id;
                    self.revive(id, c);
                } else if w == rec.v.0 {
                    // c faces [u, x] (resp. [u, y]), the merged edge: its number may hold
                    // the corner that now faces [v, x] again, so point it at the outer
                    // corner that faced [u, x] before and after.
                    let across = saved_opposite[3 * k + s];
                    self.corner_of[id as usize] = across;
                } else if k == 0 {
                    self.revive(id, c); // c faces [u, v]
                }
            }
        }
    }

    /// Updates the numbers after the flip `rec` was applied. O(1).
    pub fn flipped(&mut self, rec: &FlipRecord) {
        self.flipped_corners(rec.moved, rec.new_corners);
    }

    /// [`Self::flipped`] given the flip's `moved` and `new_corners` (as in
    /// [`FlipRecord`]), for flips made without a record. O(1).
    pub fn flipped_corners(&mut self, moved: [Corner; 2], new_corners: [Corner; 2]) {
        // Before the flip: `new[0]` faced [b, c] and `new[1]` faced [a, d]; afterwards
        // they face the new edge [c, d], and `moved[0]` / `moved[1]` face [a, d] / [b, c].
        let [k1, k2] = moved;
        let [n1, _] = new_corners;
        let [old, ad, bc] = self.ids.flipped_corners(moved, new_corners);
        self.corner_of[old as usize] = n1.0;
        self.corner_of[ad as usize] = k1.0;
        self.corner_of[bc as usize] = k2.0;
    }

    /// Updates the numbers after [`crate::Triangulation::unflip`]`(rec)`. O(1).
    pub fn unflipped(&mut self, rec: &FlipRecord) {
        let [k1, k2] = rec.moved;
        let [n1, n2] = rec.new_corners;
        let flipped = self.ids.of_corner[n1.index()];
        let ad = self.ids.of_corner[k1.index()];
        let bc = self.ids.of_corner[k2.index()];
        self.ids.of_corner[k1.index()] = flipped;
        self.ids.of_corner[k2.index()] = flipped;
        self.ids.of_corner[n1.index()] = bc;
        self.ids.of_corner[n2.index()] = ad;
        self.corner_of[flipped as usize] = k1.0;
        self.corner_of[bc as usize] = n1.0;
        self.corner_of[ad as usize] = n2.0;
    }

    fn revive(&mut self, e: u32, c: Corner) {
        debug_assert_eq!(
            self.corner_of[e as usize], NONE,
            "revived edge {e} is alive"
        );
        self.corner_of[e as usize] = c.0;
        self.live += 1;
    }

    fn kill(&mut self, e: EdgeId) {
        if self.corner_of[e.index()] != NONE {
            self.corner_of[e.index()] = NONE;
            self.live -= 1;
        }
    }

    /// Checks the numbering against `tri` from scratch: both corners of every live edge
    /// carry one number, distinct edges carry distinct numbers, every live number's corner
    /// is one of its edge's corners, and the live count matches. O(F). For tests.
    pub fn check(&self, tri: &Triangulation) -> Result<(), String> {
        if self.live != tri.edge_count() {
            return Err(format!(
                "{} live numbers, {} edges",
                self.live,
                tri.edge_count()
            ));
        }
        let mut owner = vec![NONE; self.corner_of.len()];
        for (_, _, c) in tri.edges() {
            let o = tri.opposite(c);
            let (e, eo) = (self.ids.of_corner[c.index()], self.ids.of_corner[o.index()]);
            if e != eo {
                return Err(format!("edge at {c}/{o} has numbers {e} and {eo}"));
            }
            let Some(slot) = owner.get_mut(e as usize) else {
                return Err(format!("edge at {c} has number {e} out of range"));
            };
            if *slot != NONE {
                return Err(format!("number {e} on two edges ({slot} and {c})"));
            }
            *slot = c.0;
            let held = self.corner_of[e as usize];
            if held != c.0 && held != o.0 {
                return Err(format!("number {e} holds corner {held}, not {c} or {o}"));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::History;
    use crate::core::SurfaceKind;
    use crate::gen::{self, RandomParams};

    fn surface() -> Triangulation {
        gen::random(&RandomParams {
            surface: SurfaceKind::NonOrientable(3),
            min_faces: 300,
            flip_percent: 30,
            seed: 7,
        })
        .expect("a small random surface")
    }

    /// Every live number of `n` holds the smaller corner of its edge, and the count of
    /// live numbers is the number of edges.
    fn assert_canonical(n: &EdgeNumbering, tri: &Triangulation) {
        assert_eq!(n.check(tri), Ok(()));
        assert_eq!(n.live_count(), tri.edge_count());
        for (_, _, c) in tri.edges() {
            let smaller = c.min(tri.opposite(c));
            assert_eq!(n.corner(n.id(c)), Some(smaller), "edge at {c}");
        }
    }

    #[test]
    fn from_ids_gives_the_numbering_new_gives_and_follows_contractions() {
        let mut tri = surface();
        let fresh = EdgeNumbering::from_ids(EdgeIds::new(&tri), &tri);
        assert_canonical(&fresh, &tri);
        let new = EdgeNumbering::new(&tri);
        for e in 0..new.capacity() as u32 {
            assert_eq!(fresh.corner(EdgeId(e)), new.corner(EdgeId(e)));
        }
        // After contractions told to the per-corner half only, and to a full numbering.
        let mut ids = EdgeIds::new(&tri);
        let mut full = new;
        let mut dead = Vec::new();
        let mut history = History::new();
        for _ in 0..120 {
            let Some((u, v, _)) = tri
                .edges()
                .find(|&(u, v, _)| tri.link_condition_naive(u, v))
            else {
                break;
            };
            let rec = tri.contract_tested(u, v, &mut history);
            let died = full.contracted(&rec);
            assert_eq!(ids.contracted(&rec), died);
            dead.extend(died);
        }
        assert_eq!(history.len(), 120);
        let after = EdgeNumbering::from_ids(ids, &tri);
        assert_canonical(&after, &tri);
        assert_eq!(after.capacity(), full.capacity());
        assert_eq!(full.live_count(), tri.edge_count());
        for e in (0..full.capacity() as u32).map(EdgeId) {
            let canonical = full.corner(e).map(|c| c.min(tri.opposite(c)));
            assert_eq!(after.corner(e), canonical, "{e:?}");
            assert_eq!(full.is_alive(e), !dead.contains(&e), "{e:?}");
        }
        // Undoing every contraction gives every number back to its edge.
        while let Some(rec) = history.undo(&mut tri) {
            full.uncontracted(&rec);
        }
        assert_eq!(full.check(&tri), Ok(()));
        assert_eq!(full.live_count(), tri.edge_count());
        let again = EdgeNumbering::new(&tri);
        for e in (0..full.capacity() as u32).map(EdgeId) {
            // Any corner of the edge (only new() and from_ids choose the smaller).
            let held = full.corner(e).map(|c| c.min(tri.opposite(c)));
            assert_eq!(held, again.corner(e), "{e:?}");
        }
    }

    #[test]
    fn debug_forms_name_the_corner_and_the_number() {
        let tri = surface();
        let c = Corner(7);
        let e = tri.edge_at(c);
        assert_eq!(format!("{e:?}"), format!("e{}", e.corner().0));
        assert_eq!(format!("{:?}", EdgeId(12)), "#12");
    }
}
