//! The initial pairing of the LRS tri-quad conversion (tri-quad paper, Sec. 3.3): the
//! *contraction* step (the RS algorithm) followed by the *expansion* step (Sec. 3.3.1,
//! Algorithms 3.1–3.4), which replays the contractions backwards by vertex splits,
//! flags some edges as flipped and builds a set `M` of primal edges whose duals pair the
//! triangles each split creates.
//!
//! **Guarantee.** [`initial_pairing`] returns `K`, the input with the flagged edges
//! flipped (same vertex ids, same vertex, edge and face counts; every flip is a flip of
//! the then-current `K`, so `K` is a triangulation of the same surface), and a pairing
//! of `K` ([`Pairing`]: disjoint pairs of edge-adjacent faces of `K`) that leaves exactly
//! `n'_f` triangles unpaired, `n'_f` being the face count of the irreducible `T'` found
//! by RS (Claim 3.1 / Prop. 3.3: every split adds one edge to `M`, and `M*` is a
//! matching of the dual of `K`). So genus 0 leaves exactly 4 (T' is the tetrahedron),
//! an orientable surface of genus `g > 0` at most `56g − 12`, and a non-orientable one
//! of Euler genus `h` at most `n'_f = 2n'_v − 2χ ≤ 2(13h − 4) + 2h − 4 = 28h − 12`
//! (Joret–Wood: `n'_v ≤ 13h − 4`; `3n'_f = 2n'_e`, `n'_v − n'_e + n'_f = 2 − h`). The
//! completion to a perfect pairing is [`crate::quad`]'s business, not this module's.
//!
//! **Complexity.** The contraction step is RS: O(g² + g·n). The expansion is O(n): each
//! split is one exact undo (O(d_v)) plus O(1) work for Alg. 3.1–3.4 (at most two flags
//! set or one cleared, one edge added to `M`); `K` is materialised with one O(1) flip per
//! flagged edge (the flippability re-check of [`Triangulation::flip_at`] costs
//! O(min degree)), in place of `T`. Memory on top of RS's history: per edge number two
//! flags and a `u32` (flag time), per flag a `u32` (the flag log); when the
//! specification runs (and in unit tests), also per vertex two `u32`s and a flag and per
//! face a flag, which only the checks read.
//!
//! **Determinism.** No randomness: the output is a function of the input (face list and
//! vertex ids), because RS is deterministic (vertices processed in id order) and every
//! step below is.
//!
//! # Order of the expansion (Sec. 3.3.1) and the history
//! The paper numbers the vertices of `T'` in *reverse* processing order, `u_m` (processed
//! first) … `u_1` (processed last), calls `v_{ij}` the `(n_i − j + 1)`-th vertex
//! contracted into `u_i`, and expands `u_1` first, then `u_2`, …; within `u_i`, `v_{i1}`
//! first. RS processes one vertex at a time and contracts only edges `[u, z]` at the
//! vertex `u` it processes, keeping `u` ([`crate::irreducible::rs`]), so the RS
//! [`History`] is the concatenation of the contractions of `u_m`, then `u_{m−1}`, …,
//! `u_1`, each block in contraction order. Reading it newest first (the only order exact
//! undo allows) therefore gives `u_1`'s block first, and inside a block the last
//! contraction first, which is `v_{i1}`: the paper's order exactly. The specification
//! checks that the blocks are contiguous (a vertex `u_i` has no split left when the next
//! block starts) and that a split never lands on a `T'` vertex processed before `u_i`.
//!
//! # Data (the paper's design)
//! The working triangulation `T` changes only by exact undo of the RS history
//! (`History::undo`, guarded by the state stamp). Edges carry dense numbers
//! ([`EdgeNumbering`]) kept in lockstep (`uncontracted` after every undo); `M` and the
//! `flipped` flags are `Vec<bool>` over those numbers, as the paper keeps a flag in each
//! DCEL edge record. Since a fresh numbering of `T'` knows nothing of the contracted
//! edges (their numbers must be revived by `uncontracted`), the numbering is made on the
//! input and driven through the history's contractions (`contracted`) before the
//! expansion starts.
//!
//! # Choices where the paper is silent
//! - **Order of the flips in `K`.** The flags do not commute: Alg. 3.1 l.15 sends a
//!   degree-4 split whose `[x, z]` (or `[y, z]`) is flagged to Alg. 3.4, which flags
//!   `[v, x]`; `[v, x]` and `[x, z]` share the face `[v, x, z]` of `T`, and flipping them
//!   in the two orders gives different triangulations. The paper's proof (Case 2.2, "v
//!   has degree greater than 4 in K") means the flips applied to the *current* `K`, in
//!   the order the algorithm makes them. We record, per flag, the time it was set, and
//!   materialise `K` by flipping the flagged edges of the final `T` in that order (an
//!   edge flagged again after an unflip counts at its latest time). A vertex split and a
//!   flip of an edge that is not a split edge commute (the split moves the flipped
//!   edge's faces with the wedge they lie in), which is why the flips can be replayed on
//!   the final `T` instead of being interleaved with the splits; the tests compare the
//!   result with the independent definition (paired faces adjacent in `K`, exactly
//!   `flips` edges changed).
//! - **Which corner a flip starts from.** A flip keeps its two face ids and rewrites
//!   their slots from the corner it is given; where the two faces are not consistently
//!   oriented (non-orientable surfaces, or inconsistent input), the two corners of the
//!   edge give the two new triangles to different ids. Each flagged edge is flipped
//!   from its canonical corner (the smaller of its two opposite corners, [`crate::Edge`])
//!   in the `K` of that moment.
//! - **Unflip (Alg. 3.2 l.2–4)** clears the flag: `K` then never contained the flip.
//! - **Which split edge is `x`.** `x` and `y` are the history record's link in its
//!   order (`link[0]`, `link[1]`); the paper's choices are symmetric ("the case of
//!   `[u, y] ∈ M` is symmetric").
//! - **`M*` into a [`Pairing`].** Each edge of `M` is unflagged (Claim 3.1 (ii)), so it
//!   is an edge of `K`; its two faces in `K` are paired, in increasing edge-number
//!   order. Should two edges of `M` claim one face (impossible by Claim 3.1, checked by
//!   the specification in checked builds), the second claim is skipped, so the output
//!   is always a valid pairing of `K`.
//! - **Flips trust Prop. 3.3.** Every flagged edge is flippable when its turn comes
//!   (Prop. 3.3), so `K` is materialised by flips without the flippability test (a link
//!   walk per flip, a fifth of the expansion's time on B0). Whenever the specification
//!   runs (debug builds, the `invariants` feature, so every test run), L7 first
//!   materialises `K` on its own copy with the test, and the unchecked flip itself
//!   asserts flippability; the tests also check `K` against the definition
//!   independently.
//! - **Numbers without corners.** The expansion reads edge numbers of corners only
//!   ([`EdgeIds`]); the corner of each number is needed only to materialise `K`, when
//!   `T` is the input again, so it is made then in one pass instead of being kept in
//!   step through 2 × 2.1 M contractions and splits on B0.
//!
//! The runtime checks of Claim 3.1 / Prop. 3.3 are in the child module `spec`.

use crate::core::{
    ContractionRecord, EdgeId, EdgeIds, EdgeNumbering, FaceId, History, Triangulation, VertexId,
};
use crate::irreducible::{rs, Options as ReduceOptions};

use super::Pairing;

mod spec;

/// The result of the initial step: the triangulation `K` that is paired and the pairing.
#[derive(Clone, Debug)]
pub struct Expansion {
    /// `K`: the input with the flagged edges flipped (same vertex ids, same counts).
    pub tri: Triangulation,
    /// `M*` as a pairing of `K`'s faces; exactly [`Self::reduced_faces`] faces unpaired.
    pub pairing: Pairing,
    /// Edges of the input replaced in `K` (the flips made to materialise `K`).
    pub flips: usize,
    /// `n'_f`: faces of the irreducible triangulation `T'` of the contraction step.
    pub reduced_faces: usize,
    /// How often each branch of Alg. 3.1–3.4 ran.
    pub cases: Cases,
}

/// How often each branch of Alg. 3.1–3.4 ran, for tests and reports.
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
pub struct Cases {
    /// Vertex splits (= contractions of the RS step = edges in `M`).
    pub splits: usize,
    /// Alg. 3.1 l.7: neither split edge in `M`.
    pub line7: usize,
    /// Alg. 3.2 (degree 3).
    pub degree3: usize,
    /// Alg. 3.2 l.3: unflips.
    pub unflips: usize,
    /// Alg. 3.3 (degree 4, neither `[x, z]` nor `[y, z]` flagged).
    pub degree4: usize,
    /// Alg. 3.4 reached from Alg. 3.1 l.15 (degree 4 with a flagged `[x, z]`/`[y, z]`).
    pub degree4_flagged: usize,
    /// Alg. 3.4 reached from Alg. 3.1 l.18 (degree > 4).
    pub degree_greater_than4: usize,
    /// Flags set (flips made by Alg. 3.3 and 3.4).
    pub flags_set: usize,
}

crate::spec::mutation_switches! {
/// Deliberate deviations from Alg. 3.1–3.4, to show that the specification catches
/// them (mutation tests). The default is the algorithm as specified.
pub struct Variant {
    /// Mutation: Alg. 3.2 skips the unflip of `[x, y]` (l.2–4).
    pub skip_unflip: bool,
    /// Mutation: Alg. 3.1 l.12 ignores the flags (degree 4 always goes to Alg. 3.3).
    pub degree4_ignores_flags: bool,
    /// Mutation: `K` is materialised by flipping the flagged edges in the reverse of the
    /// order the flags were set (as if "T plus the flags" determined `K`).
    pub materialise_reversed: bool,
}
}

/// Runs the contraction step (RS) and the expansion step (Alg. 3.1–3.4) on `tri`
/// (consumed) and returns `K` with the pairing `M*`; see the module documentation for
/// the guarantee.
pub fn initial_pairing(tri: Triangulation) -> Expansion {
    initial_pairing_with(tri, Variant::SPECIFIED)
}

/// [`initial_pairing`] with a deliberate [`Variant`] (mutation tests).
#[cfg(feature = "mutation-tests")]
#[doc(hidden)]
pub fn initial_pairing_variant(tri: Triangulation, variant: Variant) -> Expansion {
    initial_pairing_with(tri, variant)
}

fn initial_pairing_with(tri: Triangulation, variant: Variant) -> Expansion {
    let mut ex = Expander::new(tri, variant);
    while ex.step().is_some() {}
    ex.finish()
}

/// Whether the state only the specification reads (`remaining`, `reduced`,
/// `reduced_face`, `expanded_from`, `group_*`) is kept: when the checks run, and in unit
/// tests (which corrupt it to show the checks fail); otherwise those fields stay empty.
const SPEC_STATE: bool = crate::spec::ENABLED || cfg!(test);

/// No time / no group.
const NONE: u32 = u32::MAX;

/// What one split did (for the specification hooks).
#[derive(Copy, Clone, Debug)]
struct Split {
    rec: ContractionRecord,
    /// The edge inserted into `M`.
    inserted: EdgeId,
    /// Edges flagged by this split (Alg. 3.3 l.5/l.8, Alg. 3.4 l.3/l.6).
    flagged: [Option<EdgeId>; 2],
    /// `|M|` before the split.
    m_before: usize,
    /// Alg. 3.2 ran with both split edges in `M` and `[x, y]` not flagged.
    case21_both_unflipped: bool,
}

/// The edges around a split that Alg. 3.1–3.4 read (numbers in `T_ij`).
#[derive(Copy, Clone, Debug)]
struct Around {
    ux: EdgeId,
    uy: EdgeId,
    uv: EdgeId,
    vx: EdgeId,
    vy: EdgeId,
    /// The edge opposite `v` in the face across `[v, x]`: `[x, y]` at degree 3, else
    /// `[x, z]`.
    x_far: EdgeId,
    /// The edge opposite `v` in the face across `[v, y]`: `[x, y]` or `[y, z]`.
    y_far: EdgeId,
    /// `[v, z]` (meaningful at degree ≥ 4).
    vz: EdgeId,
    degree: usize,
}

/// The state of Alg. 3.1 between splits.
#[derive(Clone, Debug)]
struct Expander {
    /// `T_ij`: changes only by exact undo of `history`.
    t: Triangulation,
    history: History,
    /// The edge number of every corner, kept in lockstep with `t`; the corner of each
    /// number (the other half of an [`EdgeNumbering`]) is needed only once `T` is the
    /// input again, and is then made in one pass ([`EdgeNumbering::from_ids`]).
    numbers: EdgeIds,
    /// The full numbering kept through every change, for the specification's edge
    /// lookups only (empty unless `SPEC_STATE`).
    spec_numbers: EdgeNumbering,
    /// `e ∈ M`.
    in_m: Vec<bool>,
    /// `flipped(e)`.
    flipped: Vec<bool>,
    /// When `e` was last flagged (an index into `flag_log`), or [`NONE`].
    flag_time: Vec<u32>,
    /// Every flag set, in order (entries whose `flag_time` no longer points back are
    /// stale: unflipped, or flagged again later).
    flag_log: Vec<EdgeId>,
    m_len: usize,
    // The next four fields and `group_*` are read by the specification only, and are
    // kept (non-empty) only if `SPEC_STATE`.
    /// Splits still to come from each vertex (non-zero only for pending `T'` vertices).
    remaining: Vec<u32>,
    /// Whether the vertex is a vertex of `T'`.
    reduced: Vec<bool>,
    /// Whether the face id is a face of `T'` (exact undo revives the other ids).
    reduced_face: Vec<bool>,
    /// For a vertex split off `u_i`, the id of `u_i`; [`NONE`] for `T'` vertices and
    /// vertices not yet split off.
    expanded_from: Vec<u32>,
    /// `u_i`, the vertex being expanded.
    current: Option<VertexId>,
    /// Flags set and `M` edges added while `current` is expanded (for bounded checks).
    group_flags: Vec<EdgeId>,
    group_m: Vec<EdgeId>,
    reduced_faces: usize,
    cases: Cases,
    /// See [`Split::case21_both_unflipped`] (set by the current split).
    case21_both_unflipped: bool,
    variant: Variant,
}

impl Expander {
    /// Runs RS on `tri` and prepares the expansion of `T'`.
    fn new(tri: Triangulation, variant: Variant) -> Self {
        let mut spec_numbers = EdgeNumbering::default();
        if SPEC_STATE {
            spec_numbers = EdgeNumbering::new(&tri);
        }
        let numbers = EdgeIds::new(&tri);
        let (red, numbers) = rs::reduce_numbered(tri, &ReduceOptions::default(), numbers);
        if SPEC_STATE {
            for rec in red.history.records() {
                spec_numbers.contracted(rec);
            }
        }
        let t = red.tri;
        // The state only the specification reads is kept only when it runs.
        let (mut remaining, mut reduced, mut reduced_face, mut expanded_from) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        if SPEC_STATE {
            let nv = t.vertex_capacity();
            remaining = vec![0u32; nv];
            for rec in red.history.records() {
                remaining[rec.u.index()] += 1;
            }
            reduced = (0..nv).map(|v| t.is_vertex(VertexId(v as u32))).collect();
            reduced_face = (0..t.face_capacity())
                .map(|f| t.is_face(FaceId(f as u32)))
                .collect();
            expanded_from = vec![NONE; nv];
        }
        let ne = numbers.capacity();
        Expander {
            reduced_faces: t.face_count(),
            t,
            history: red.history,
            numbers,
            spec_numbers,
            in_m: vec![false; ne],
            flipped: vec![false; ne],
            flag_time: vec![NONE; ne],
            flag_log: Vec::new(),
            m_len: 0,
            remaining,
            reduced,
            reduced_face,
            expanded_from,
            current: None,
            group_flags: Vec::new(),
            group_m: Vec::new(),
            cases: Cases::default(),
            case21_both_unflipped: false,
            variant,
        }
    }

    fn insert(&mut self, e: EdgeId) {
        if !self.in_m[e.index()] {
            self.in_m[e.index()] = true;
            self.m_len += 1;
        }
        if SPEC_STATE {
            self.group_m.push(e);
        }
    }

    fn flag(&mut self, e: EdgeId) {
        self.flipped[e.index()] = true;
        self.flag_time[e.index()] = self.flag_log.len() as u32;
        self.flag_log.push(e);
        if SPEC_STATE {
            self.group_flags.push(e);
        }
        self.cases.flags_set += 1;
    }

    fn unflag(&mut self, e: EdgeId) {
        self.flipped[e.index()] = false;
        self.flag_time[e.index()] = NONE;
        self.cases.unflips += 1;
    }

    /// One split: the newest contraction undone (`T_{i(j−1)}` → `T_ij`) and Alg. 3.1
    /// l.6–18 applied. `None` when the history is exhausted.
    fn step(&mut self) -> Option<Split> {
        let next_u = self.history.records().last()?.u;
        if self.current != Some(next_u) {
            if let Some(prev) = self.current {
                spec::after_vertex(self, prev);
            }
            self.current = Some(next_u);
            self.group_flags.clear();
            self.group_m.clear();
        }
        let rec = self.history.undo(&mut self.t)?;
        self.numbers.uncontracted(&rec);
        if SPEC_STATE {
            self.spec_numbers.uncontracted(&rec);
            self.remaining[rec.u.index()] -= 1;
            self.expanded_from[rec.v.index()] = rec.u.0;
        }
        self.cases.splits += 1;
        let m_before = self.m_len;
        let flags_before = self.cases.flags_set;
        self.case21_both_unflipped = false;
        let inserted = self.expand_match(&rec);
        let mut flagged = [None; 2];
        let new_flags = self.cases.flags_set - flags_before;
        for (k, &e) in self.flag_log[self.flag_log.len() - new_flags..]
            .iter()
            .enumerate()
        {
            if let Some(slot) = flagged.get_mut(k) {
                *slot = Some(e);
            }
        }
        let split = Split {
            rec,
            inserted,
            flagged,
            m_before,
            case21_both_unflipped: self.case21_both_unflipped,
        };
        spec::after_split(self, &split, new_flags);
        if self.history.is_empty() {
            spec::after_vertex(self, rec.u);
        }
        Some(split)
    }

    /// The numbers of the edges Alg. 3.1–3.4 look at around the split `rec` (`T` is
    /// `T_ij`), and `v`'s degree. O(1).
    fn around(&self, rec: &ContractionRecord) -> Around {
        let (u, v) = (rec.u, rec.v);
        let t = &self.t;
        let id = |c| self.numbers.id(c);
        // f1 = [u, v, x], f2 = [u, v, y] (the record's faces, in the order of its link).
        let [f1, f2] = rec.faces;
        let v1 = t.corner_at(f1.corner(0), v); // faces [u, x]
        let u1 = t.corner_at(f1.corner(0), u); // faces [v, x]
        let x1 = t.corner_at(f1.corner(0), rec.link[0]); // faces [u, v]
        let v2 = t.corner_at(f2.corner(0), v); // faces [u, y]
        let u2 = t.corner_at(f2.corner(0), u); // faces [v, y]
                                               // Across [v, x] from f1: [v, x, y] (degree 3) or [v, x, z] (degree 4, z the
                                               // fourth neighbour); across [v, y] from f2: the same face, or [v, y, z].
        let ox = t.opposite(u1);
        let oy = t.opposite(u2);
        Around {
            ux: id(v1),
            uy: id(v2),
            uv: id(x1),
            vx: id(u1),
            vy: id(u2),
            x_far: id(t.corner_at(ox, v)),
            y_far: id(t.corner_at(oy, v)),
            vz: id(t.corner_at(ox, rec.link[0])),
            degree: t.degree(v),
        }
    }

    /// Alg. 3.1 l.4–18 for the split `rec` of `v` from `u` along `[u, x]`, `[u, y]`
    /// (`T` is `T_ij`). Returns the edge inserted into `M`.
    fn expand_match(&mut self, rec: &ContractionRecord) -> EdgeId {
        let a = self.around(rec);
        let (ux_in, uy_in) = (self.in_m[a.ux.index()], self.in_m[a.uy.index()]);
        if !ux_in && !uy_in {
            // l.6–7.
            self.cases.line7 += 1;
            self.insert(a.uv);
            return a.uv;
        }
        if a.degree == 3 {
            // Alg. 3.2; `x_far` is [x, y] (the face across [v, x] is [v, x, y]).
            self.cases.degree3 += 1;
            let xy = a.x_far;
            // The proof of Prop. 3.3 (Case 2.1) says both split edges are in M only if
            // [x, y] is flipped in K_{i(j-1)}; the specification checks it.
            self.case21_both_unflipped = ux_in && uy_in && !self.flipped[xy.index()];
            if self.flipped[xy.index()] && !self.variant.skip_unflip() {
                self.unflag(xy); // l.2–4
            }
            let e = if ux_in && uy_in {
                xy // l.6
            } else if ux_in {
                a.vy // l.8
            } else {
                a.vx // l.10
            };
            self.insert(e);
            return e;
        }
        if a.degree == 4 {
            // l.11–12: `x_far` is [x, z], `y_far` is [y, z].
            let flagged = self.flipped[a.x_far.index()] || self.flipped[a.y_far.index()];
            if !flagged || self.variant.degree4_ignores_flags() {
                // Alg. 3.3.
                self.cases.degree4 += 1;
                if ux_in && uy_in {
                    self.insert(a.vz); // l.3
                    return a.vz;
                }
                self.flag(if ux_in { a.vx } else { a.vy }); // l.5 / l.8
                self.insert(a.uv); // l.6 / l.9
                return a.uv;
            }
            self.cases.degree4_flagged += 1; // l.15
        } else {
            self.cases.degree_greater_than4 += 1; // l.18
        }
        // Alg. 3.4.
        if ux_in {
            self.flag(a.vx); // l.3
        }
        if uy_in {
            self.flag(a.vy); // l.6
        }
        self.insert(a.uv); // l.8
        a.uv
    }

    /// The flagged edges in the order their flags were set (latest setting counts).
    fn flags_in_order(&self) -> Vec<EdgeId> {
        let mut order: Vec<EdgeId> = self
            .flag_log
            .iter()
            .enumerate()
            .filter(|&(k, e)| self.flipped[e.index()] && self.flag_time[e.index()] == k as u32)
            .map(|(_, &e)| e)
            .collect();
        if self.variant.materialise_reversed() {
            order.reverse();
        }
        order
    }

    /// `K` from `T` and the flags, as a copy: see [`flip_in_order`].
    fn materialise(&self) -> (Triangulation, EdgeNumbering, usize, Option<String>) {
        let mut k = self.t.clone();
        let mut kn = EdgeNumbering::from_ids(self.numbers.clone(), &k);
        let (flips, error) = flip_in_order(&self.flags_in_order(), &mut k, &mut kn, true);
        (k, kn, flips, error)
    }

    /// `M*` on `K`: see [`pair_edges`].
    fn pair_m(&self, k: &Triangulation, kn: &EdgeNumbering) -> (Pairing, Option<String>) {
        pair_edges(&self.in_m, &self.flipped, k, kn)
    }

    /// Materialises `K` in place of `T` (no copy) and pairs `M*` on it. The
    /// specification checks the same state first, on its own copy (L7).
    fn finish(self) -> Expansion {
        spec::at_end(&self);
        let order = self.flags_in_order();
        let Expander {
            t: mut k,
            numbers,
            in_m,
            flipped,
            reduced_faces,
            cases,
            ..
        } = self;
        let mut kn = EdgeNumbering::from_ids(numbers, &k);
        let (flips, _) = flip_in_order(&order, &mut k, &mut kn, false);
        let (pairing, _) = pair_edges(&in_m, &flipped, &k, &kn);
        Expansion {
            tri: k,
            pairing,
            flips,
            reduced_faces,
            cases,
        }
    }
}

/// Turns `k` (numbered by `kn`) into `K` by flipping the edges of `order` in turn. Returns
/// the flips made and an error naming the first edge that is dead or (if `checked`)
/// could not be flipped; that flip is skipped.
///
/// `checked` tests each flip's flippability ([`Triangulation::flip_at`]: a link walk);
/// unchecked flips trust Prop. 3.3 ([`Triangulation::flip_at_proved`]), which the
/// specification verifies on its own checked copy (L7) whenever it runs.
fn flip_in_order(
    order: &[EdgeId],
    k: &mut Triangulation,
    kn: &mut EdgeNumbering,
    checked: bool,
) -> (usize, Option<String>) {
    let mut flips = 0;
    let mut error = None;
    for &e in order {
        let Some(c) = kn.corner(e) else {
            error.get_or_insert_with(|| format!("flagged edge {e:?} is dead"));
            continue;
        };
        // A flip rewrites the slots of its two faces from the corner it is given, and on
        // a surface whose faces are not consistently oriented the two corners of an edge
        // give the two faces' triangles to different face ids: flip from the edge's
        // canonical (smaller) corner, a rule a port can reproduce.
        let c = k.edge_at(c).corner();
        if !checked {
            let (moved, new_corners) = k.flip_at_proved(c);
            kn.flipped_corners(moved, new_corners);
            flips += 1;
            continue;
        }
        match k.flip_at(c) {
            Ok(rec) => {
                kn.flipped(&rec);
                flips += 1;
            }
            Err(err) => {
                error.get_or_insert_with(|| format!("flagged edge {e:?}: {err}"));
            }
        }
    }
    (flips, error)
}

/// `M*` on `K`: the two faces of each edge of `M` (`in_m`), in edge-number order. The
/// error names the first edge of `M` that is dead, flagged or claims a paired face (that
/// edge is then skipped, so the pairing stays valid).
fn pair_edges(
    in_m: &[bool],
    flipped: &[bool],
    k: &Triangulation,
    kn: &EdgeNumbering,
) -> (Pairing, Option<String>) {
    let mut p = Pairing::new(k.face_capacity());
    let mut error = None;
    for (i, _) in in_m.iter().enumerate().filter(|&(_, &b)| b) {
        let e = EdgeId(i as u32);
        let Some(c) = kn.corner(e) else {
            error.get_or_insert_with(|| format!("edge {e:?} of M is dead"));
            continue;
        };
        if flipped[i] {
            error.get_or_insert_with(|| format!("edge {e:?} of M is flagged"));
            continue;
        }
        let (f, g) = (c.face(), k.opposite(c).face());
        if p.is_paired(f) || p.is_paired(g) {
            let [a, b] = k.edge_endpoints(c);
            error.get_or_insert_with(|| {
                format!("edge {e:?} = [{a}, {b}] of M claims an already paired face")
            });
            continue;
        }
        p.pair(f, g);
    }
    (p, error)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::{random, RandomParams, SurfaceKind};

    /// The branch of Alg. 3.1 a split took, re-derived from the paper's rule on the
    /// state after the split: the split changes none of what the rule reads (it inserts
    /// `[u, v]` or `[v, z]`, flags `[v, x]` or `[v, y]`, and unflags only at degree 3,
    /// where the flags take no part in the choice).
    fn branch(ex: &Expander, rec: &ContractionRecord) -> &'static str {
        let a = ex.around(rec);
        let (ux_in, uy_in) = (ex.in_m[a.ux.index()], ex.in_m[a.uy.index()]);
        if !ux_in && !uy_in {
            "line 7"
        } else if a.degree == 3 {
            "degree 3"
        } else if a.degree == 4 {
            if ex.flipped[a.x_far.index()] || ex.flipped[a.y_far.index()] {
                "degree 4 flagged"
            } else {
                "degree 4"
            }
        } else {
            "degree > 4"
        }
    }

    /// Each split is counted under the branch the paper's rule selects, and the flags
    /// and unflips it counts are those it made; every branch occurs, a degree-4 split
    /// with exactly one of `[x, z]`, `[y, z]` flagged included.
    #[test]
    fn every_split_is_counted_under_the_branch_the_rule_selects() {
        let mut seen: std::collections::BTreeMap<&str, usize> = Default::default();
        let mut one_far_flag = 0;
        for seed in 0..8 {
            let t = random(&RandomParams {
                surface: SurfaceKind::Orientable(seed as u32 % 3),
                min_faces: 200,
                flip_percent: 30,
                seed,
            })
            .expect("a random surface within the limits");
            let mut ex = Expander::new(t, Variant::SPECIFIED);
            let mut before = ex.cases;
            while let Some(s) = ex.step() {
                let after = ex.cases;
                let name = branch(&ex, &s.rec);
                let counted = [
                    ("line 7", after.line7 - before.line7),
                    ("degree 3", after.degree3 - before.degree3),
                    ("degree 4", after.degree4 - before.degree4),
                    (
                        "degree 4 flagged",
                        after.degree4_flagged - before.degree4_flagged,
                    ),
                    (
                        "degree > 4",
                        after.degree_greater_than4 - before.degree_greater_than4,
                    ),
                ];
                for (what, n) in counted {
                    assert_eq!(
                        n,
                        usize::from(what == name),
                        "seed {seed}: {what} for {name}"
                    );
                }
                assert_eq!(after.splits - before.splits, 1, "seed {seed}");
                let flags = s.flagged.iter().flatten().count();
                assert_eq!(after.flags_set - before.flags_set, flags, "seed {seed}");
                let a = ex.around(&s.rec);
                if name == "degree 4 flagged"
                    && ex.flipped[a.x_far.index()] != ex.flipped[a.y_far.index()]
                {
                    one_far_flag += 1;
                }
                *seen.entry(name).or_default() += 1;
                before = after;
            }
        }
        assert_eq!(seen.len(), 5, "{seen:?}");
        assert!(one_far_flag > 0, "{seen:?}");
    }
}
