//! Completion of any pairing into a perfect one by augmenting paths with blossoms
//! (Edmonds), searched from all unpaired triangles at once, on flat arrays.
//!
//! # Guarantee
//! [`complete`] turns any pairing of a closed triangulation (one that passes
//! [`Pairing::check`]) into a *perfect* one: afterwards [`Pairing::is_perfect`] holds.
//! The dual graph of a closed triangulation is cubic and bridgeless (every edge lies on
//! the cycle of faces around either endpoint), so by Petersen's theorem it has a perfect
//! matching, and by Berge's theorem every non-perfect matching has an augmenting path;
//! Edmonds' search with blossom shrinking finds one whenever one exists. Pairs of the
//! input may be re-paired: an augmenting path flips every pair along it, so the output
//! need not contain the input. The number of pairs grows by exactly one per path.
//!
//! # Algorithm (design of `papers/matching-notes.md` §3–§4)
//! 1. **Linear pass** (augmenting paths of length 1 and 3): for each unpaired face `f` in
//!    increasing id, pair it with its first unpaired neighbour in slot order
//!    (`face_neighbours` order); failing that, for its neighbours `v` in slot order and
//!    the neighbours `x` of `w = mate(v)` in slot order, the first unpaired `x ≠ f`
//!    re-pairs `(v, w)` as `(f, v)`, `(w, x)`. From the empty pairing this is a greedy
//!    maximal matching in id order followed by the same local repairs.
//! 2. **Sparse pass** (only when the linear pass leaves at least [`SPARSE_MIN_ROOTS`]
//!    unpaired faces and at most one per [`SPARSE_FACES`] faces, as PS does): one
//!    *single-root* search per unpaired face `r`, in increasing id, if `r` is still
//!    unpaired: the search of step 3 with `r` as its only root, ended by the first
//!    unpaired face it reaches (which it pairs by flipping the path: an augmentation) or
//!    *aborted* once it has made more than `F /` [`SINGLE_BUDGET`] edge visits (its
//!    labels are reset, nothing is re-paired). After an abort the pass stops and the
//!    phases take every face still unpaired (the aborted root included).
//!    Why: far-apart leftovers make the phases' trees cover most of the surface before
//!    they meet, and the trees that augmented first wall the others in (on the genus-0
//!    brick B0, PS's leftovers needed 2–3 phases and 4.6–17.9 M edge visits depending on
//!    the seed), whereas most single-root searches stop within a small ball around their
//!    root (4.3–6.9 M visits on the same inputs). The budget bounds what an expensive
//!    search can cost before the phases take over. It is not a uniform gain: on the
//!    genus-3,500 brick C0 the last single-root searches are expensive, and PS's
//!    leftovers take 10.8 M visits at seed 1 against 6.1 M by phases alone (8.1 M
//!    against 10.2 M at seed 0; `docs/benchmarks.md`, tri-quad conversion).
//! 3. **Phases**, until no face is unpaired. The roots of a phase are the unpaired faces
//!    in increasing id. Every root is an even vertex of its own tree and enters a FIFO
//!    queue in that order (a multi-source BFS, so trees grow level by level). An even
//!    vertex `u` taken from the queue examines its neighbours `v` other than its mate in
//!    slot order (the mate of an even vertex is its odd parent or lies in its blossom,
//!    so examining it would do nothing):
//!    - `v` unreached and unpaired (only in a single-root search: in a phase every
//!      unpaired face is a root): the path root(u) … u v is augmenting; it is flipped and
//!      the search ends;
//!    - `v` unreached and paired: `v` becomes odd and its mate `w` even in `u`'s tree,
//!      `w` is queued;
//!    - `v` even in a *different* live tree: the alternating path root(u) … u v … root(v)
//!      is augmenting; it is flipped at once and both trees are *frozen* for the rest of
//!      the phase (their vertices keep their labels and act as walls: a frozen vertex is
//!      never scanned and never joins a tree, so the rest of the phase is an ordinary
//!      Edmonds search in the dual minus the frozen trees);
//!    - `v` even in the same tree, in another blossom: the blossom is shrunk. Blossoms are
//!      kept by union–find (path halving) on their bases; the base is found by walking up
//!      from the deeper base (every labelled vertex, odd ones included, stores its BFS
//!      depth); the cycle is recorded by the compact "flower" links, so that the flip of
//!      an augmenting path walks through nested blossoms without materialising them.
//!      Odd vertices of the cycle become even and are queued in cycle-walk order (from
//!      `u`'s side first, then `v`'s);
//!    - otherwise (odd, frozen, or same blossom) nothing.
//!
//!    At the end of a phase only the vertices it labelled are reset, and the frozen flags
//!    are per root of the phase, so no phase costs O(F) beyond its own search; the
//!    search records start zeroed (unreached) without an O(F) pass (below).
//!
//! # Determinism
//! The output is a function of the triangulation (its face ids and slot order) and the
//! input pairing alone: no randomness, no hashing; all choices are the id/slot orders
//! stated above, and the sparse pass's switches depend only on counts (unpaired faces,
//! live faces, edge visits). A port that follows the rules above reproduces the pairs exactly.
//!
//! # Complexity
//! Memory: one 16-byte search record per face slot (`face_capacity`; link, blossom
//! base, depth and label, tree), allocated zeroed, which the system maps lazily, so a
//! completion that touches few faces pays for few pages; plus the list of unpaired
//! faces and the queue. The dual graph is read from the triangulation
//! ([`Triangulation::face_neighbours`]) and the mates are changed in the pairing itself:
//! nothing is copied. Face ids must stay below 2^30 (the BFS depth shares a word with
//! the label). Time: one read-only O(F) pass checks the input pairing and lists the
//! unpaired faces; the linear pass is linear in those. Each phase scans every vertex at
//! most once as an even vertex (2 edge visits: its mate is skipped) plus blossom work
//! that is linear up to the inverse Ackermann factor, so a phase is O(F·α(F)); every phase augments at least once (if it found no path the
//! matching would be maximum, contradicting Petersen), so the worst case is
//! O(K·F·α(F)) for K unpaired input faces (O(F²·α(F)) from empty). The sparse pass
//! does not change that bound: each of its searches either augments or is the last
//! (aborted after at most `F / 4` visits plus one vertex's scan), and costs
//! O(F·α(F)) at most. In practice the
//! phases grow all trees at once and close almost all pairs in the first one or two,
//! so the work is a few edge visits per triangle in total, i.e. near-linear.
//! [`Completion::edge_visits`] counts it exactly (one per adjacency slot examined,
//! linear pass included; the figures below predate the skipping of the mate, which
//! removes a third of the phases' visits). Measured (test `c0_greedy_leftovers…` in
//! `tests/algorithms/quad_augment.rs`, release build, shared 2-core machine):
//!
//! | input | unpaired | linear pass | roots per phase | visits / triangle | CPU |
//! |---|---:|---:|---|---:|---:|
//! | C0 (4,221,420 triangles, genus 3,500), random edge-order greedy | 511,218 (12.1%) | 164,603 paths | 182,012 → 14,064 → 60 → 0 | 4.68 | 1.2 s |
//! | C0 from empty | 4,221,420 | 2,082,913 paths | 55,594 → 21,302 → 5,320 → 2 → 0 | 6.26 | 1.3 s |
//! | the 99 shared closed meshes, greedy starts | | | | 4.44 | |
//!
//! C0 needs about 0.22 blossoms per triangle. One visit costs about 60 ns there, against 7 ns for a plain single-source BFS
//! sweep of the same dual (0.09 s): the dual, the mates and the search records (32 MB
//! per million faces) do not fit in cache, and the multi-source queue interleaves all trees, so most visits miss.
//!
//! # Where the sources are silent
//! The paper (Lemos–Ramaswami–Siqueira §3.1) runs one BFS augmenting-path search per pair
//! (Θ(F) each); the multi-source phases, the freezing, the linear pre-pass and all
//! orders above are this module's choices (the notes' measured design), not the paper's.

use super::Pairing;
use crate::core::{FaceId, Triangulation};
use crate::progress::{self, Progress};

/// The sparse pass (module documentation, step 2) runs when the linear pass leaves at
/// most one unpaired face per `SPARSE_FACES` live faces…
pub const SPARSE_FACES: usize = 1000;
/// … and at least `SPARSE_MIN_ROOTS` of them: with few roots the phases' trees meet
/// halfway and few trees wall each other in (measured: LRS's 66 leftovers on botijo,
/// about 20 after the linear pass, took 49.7 k edge visits in one phase against 55.7 k
/// with the sparse pass).
pub const SPARSE_MIN_ROOTS: usize = 32;
/// A single-root search of the sparse pass is aborted after more than
/// `F / SINGLE_BUDGET` edge visits.
pub const SINGLE_BUDGET: usize = 4;

/// The stage the completion reports progress in.
pub const PAIRED: &str = "faces paired";

/// Counters of one completion.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Completion {
    /// Augmenting paths applied (each adds one pair), the linear pass's included.
    pub augmenting_paths: usize,
    /// Searches of the alternating forest: the phases of the multi-source search and
    /// the single-root searches of the sparse pass, an aborted one included (the linear
    /// pass is not counted).
    pub phases: usize,
    /// Adjacency slots examined, linear pass included (a phase does not examine an even
    /// vertex's mate).
    pub edge_visits: u64,
}

/// Makes `pairing` a perfect pairing of `tri` by augmenting paths (see the module
/// documentation for the algorithm, its determinism and complexity). Existing pairs may
/// be re-paired. Returns the counters.
///
/// # Errors
/// [`NotAPairing`] (and `pairing` unchanged) if `pairing` is not a pairing of `tri`
/// (what [`Pairing::check`] verifies; checked first, by one read-only pass in O(F)):
/// completing it would otherwise read faces that are not there; or if
/// `tri.face_capacity() >= 2^30`.
pub fn complete(tri: &Triangulation, pairing: &mut Pairing) -> Result<Completion, NotAPairing> {
    run(tri, pairing, &mut progress::ignore).map(|(c, _)| c)
}

/// Why [`complete`] refused a pairing: it is not a pairing of the triangulation (the
/// message says which pair is wrong), or the triangulation is too large for the search.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("augment::complete: {0}")]
pub struct NotAPairing(pub String);

/// [`complete`], reporting the faces paired out of all faces (stage "faces paired") to
/// `observer` when it starts, after the linear pass and after every phase. Same result
/// as [`complete`].
pub fn complete_observed(
    tri: &Triangulation,
    pairing: &mut Pairing,
    observer: &mut dyn FnMut(Progress),
) -> Result<Completion, NotAPairing> {
    run(tri, pairing, observer).map(|(c, _)| c)
}

/// [`complete_observed`], also returning the number of blossoms shrunk (for tests).
pub(crate) fn run(
    tri: &Triangulation,
    pairing: &mut Pairing,
    observer: &mut dyn FnMut(Progress),
) -> Result<(Completion, u64), NotAPairing> {
    let roots = check_and_roots(tri, pairing).map_err(NotAPairing)?;
    let faces = tri.face_count() as u64;
    let mut report = |unpaired: usize| {
        observer(Progress::new(
            PAIRED,
            faces.saturating_sub(unpaired as u64),
            faces,
        ))
    };
    report(roots.len());
    if roots.is_empty() {
        return Ok((Completion::default(), 0));
    }
    let mut search = Search::new(tri, &mut pairing.mate);
    let mut roots = search.linear_pass(roots);
    report(roots.len());
    if roots.len() >= SPARSE_MIN_ROOTS
        && roots.len().saturating_mul(SPARSE_FACES) <= tri.face_count()
    {
        let budget = (tri.face_count() / SINGLE_BUDGET) as u64;
        roots = search.sparse_pass(roots, budget);
        report(roots.len());
    }
    while !roots.is_empty() {
        let paths = search.phase(&roots, u64::MAX);
        roots.retain(|&r| search.mate[r as usize] == NONE);
        report(roots.len());
        if paths == 0 {
            // A maximum matching that is not perfect: impossible on a closed
            // triangulation (Petersen), so only a broken input could get here; stop
            // rather than loop.
            debug_assert!(false, "a phase found no augmenting path");
            break;
        }
    }
    let (counters, blossoms) = (search.counters, search.blossoms);
    pairing.pairs += counters.augmenting_paths;
    debug_assert!(pairing.check(tri).is_ok());
    Ok((counters, blossoms))
}

/// Checks that `pairing` is a pairing of `tri` (what [`Pairing::check`] checks, reading
/// each live face's neighbours once) and returns the live unpaired faces in increasing
/// id. O(F), reads only.
fn check_and_roots(tri: &Triangulation, pairing: &Pairing) -> Result<Vec<u32>, String> {
    let n = tri.face_capacity();
    if pairing.face_capacity() < n {
        return Err(format!(
            "not a pairing of the triangulation: it holds {} faces, the triangulation {n}",
            pairing.face_capacity()
        ));
    }
    if n >= 1 << 30 {
        // The depth shares a word with the label (module documentation, memory).
        return Err(format!("{n} face ids exceed the 2^30 the search supports"));
    }
    let mut roots = Vec::new();
    let mut paired = 0usize;
    for f in tri.faces() {
        let m = pairing.mate[f.index()];
        if m == NONE {
            roots.push(f.0);
            continue;
        }
        if !tri.face_neighbours(f).contains(&FaceId(m)) {
            return Err(format!(
                "not a pairing of the triangulation: {f} and {} share no edge",
                FaceId(m)
            ));
        }
        paired += 1;
    }
    // Live faces pair only with live neighbours (above) and mates are symmetric
    // (Pairing's invariant), so this catches pairs holding removed faces.
    if paired != 2 * pairing.len() {
        return Err(format!(
            "not a pairing of the triangulation: {} pairs recorded, {paired} live faces paired",
            pairing.len()
        ));
    }
    Ok(roots)
}

/// No vertex / no link / no mate.
const NONE: u32 = u32::MAX;
/// Labels of the alternating forest (the low two bits of the `DL` word).
const UNREACHED: u32 = 0;
const EVEN: u32 = 1;
const ODD: u32 = 2;
const LABEL: u32 = 3;

/// The words of a search record ([`Search::st`]): `LINK`, the flower link (the even
/// parent of an odd vertex, or the cross edge recorded when a blossom is shrunk);
/// `BASE`, the union–find parent over blossom bases; `DL`, BFS depth × 4 + label (the
/// depth is set for odd vertices too: a vertex turned even by a blossom passes it on);
/// `TREE`, the index of its root in the phase's root list. A record of zeros is an
/// unreached vertex; the other words are meaningful only while the label is not
/// `UNREACHED`, and all are written when the vertex is labelled.
const LINK: usize = 0;
const BASE: usize = 1;
const DL: usize = 2;
const TREE: usize = 3;

struct Search<'a> {
    tri: &'a Triangulation,
    /// The pairing's own mate array, changed in place (`NONE` = unpaired).
    mate: &'a mut [u32],
    /// One 16-byte search record per face id, all zero (unreached) between phases: made
    /// by a zeroed allocation, which the system maps lazily, so only the pages a search
    /// touches cost anything.
    st: Vec<[u32; 4]>,
    /// `frozen[tree]`: that tree augmented in this phase (indexed by root position).
    frozen: Vec<bool>,
    /// BFS queue of even vertices (reused across phases; also the list of the even
    /// vertices to reset).
    queue: Vec<u32>,
    /// Odd vertices labelled in this phase (to reset).
    odd: Vec<u32>,
    counters: Completion,
    blossoms: u64,
}

impl<'a> Search<'a> {
    fn new(tri: &'a Triangulation, mate: &'a mut [u32]) -> Self {
        Search {
            st: vec![[0u32; 4]; tri.face_capacity()],
            tri,
            mate,
            frozen: Vec::new(),
            queue: Vec::new(),
            odd: Vec::new(),
            counters: Completion::default(),
            blossoms: 0,
        }
    }

    #[inline]
    fn adj(&self, f: u32) -> [u32; 3] {
        self.tri.face_neighbours(FaceId(f)).map(|g| g.0)
    }

    #[inline]
    fn label(&self, f: u32) -> u32 {
        self.st[f as usize][DL] & LABEL
    }

    #[inline]
    fn dep(&self, f: u32) -> u32 {
        self.st[f as usize][DL] >> 2
    }

    #[inline]
    fn set_pair(&mut self, a: u32, b: u32) {
        self.mate[a as usize] = b;
        self.mate[b as usize] = a;
    }

    /// Augmenting paths of length 1 and 3 from every unpaired face `roots` (in
    /// increasing id), in one scan (module documentation, step 1). Returns the faces
    /// still unpaired, in increasing id.
    fn linear_pass(&mut self, mut roots: Vec<u32>) -> Vec<u32> {
        for &f in &roots {
            if self.mate[f as usize] != NONE {
                continue;
            }
            let nb = self.adj(f);
            let mut done = false;
            for &g in &nb {
                self.counters.edge_visits += 1;
                if self.mate[g as usize] == NONE {
                    self.set_pair(f, g);
                    done = true;
                    break;
                }
            }
            if !done {
                'three: for &v in &nb {
                    let w = self.mate[v as usize];
                    for x in self.adj(w) {
                        self.counters.edge_visits += 1;
                        if x != f && self.mate[x as usize] == NONE {
                            self.set_pair(f, v);
                            self.set_pair(w, x);
                            done = true;
                            break 'three;
                        }
                    }
                }
            }
            if done {
                self.counters.augmenting_paths += 1;
            }
        }
        roots.retain(|&r| self.mate[r as usize] == NONE);
        roots
    }

    /// One single-root search per face of `roots` (increasing id) still unpaired, each
    /// aborted after more than `budget` edge visits; stops at the first abort (module
    /// documentation, step 2). Returns the faces still unpaired, in increasing id.
    fn sparse_pass(&mut self, mut roots: Vec<u32>, budget: u64) -> Vec<u32> {
        for &r in &roots {
            if self.mate[r as usize] == NONE && self.phase(&[r], budget) == 0 {
                break;
            }
        }
        roots.retain(|&r| self.mate[r as usize] == NONE);
        roots
    }

    /// Union–find root (path halving) of `x`'s blossom: its base.
    #[inline]
    fn find(&mut self, mut x: u32) -> u32 {
        loop {
            let p = self.st[x as usize][BASE];
            if p == x {
                return x;
            }
            let gp = self.st[p as usize][BASE];
            self.st[x as usize][BASE] = gp;
            x = gp;
        }
    }

    /// Labels `v` odd (child of `u`) and its mate `w` even; queues `w`.
    #[inline]
    fn grow(&mut self, u: u32, v: u32, w: u32) {
        let [_, _, dl, tree] = self.st[u as usize];
        let dep = dl >> 2;
        self.st[v as usize] = [u, v, ((dep + 1) << 2) | ODD, tree];
        self.st[w as usize] = [NONE, w, ((dep + 2) << 2) | EVEN, tree];
        self.odd.push(v);
        self.queue.push(w);
    }

    /// One search from `roots` (module documentation, step 3: all unpaired faces; or
    /// step 2: a single root), abandoned once it has made more than `limit` edge visits.
    /// Returns the number of augmenting paths found.
    fn phase(&mut self, roots: &[u32], limit: u64) -> usize {
        self.counters.phases += 1;
        let mut paths = 0;
        self.queue.clear();
        self.odd.clear();
        self.frozen.clear();
        self.frozen.resize(roots.len(), false);
        for (k, &r) in roots.iter().enumerate() {
            self.st[r as usize] = [NONE, r, EVEN, k as u32];
            self.queue.push(r);
        }
        let start = self.counters.edge_visits;
        let mut head = 0;
        while head < self.queue.len() && self.counters.edge_visits - start <= limit {
            let u = self.queue[head];
            head += 1;

            let tu = self.st[u as usize][TREE];
            if self.frozen[tu as usize] {
                continue;
            }
            // `u`'s mate is its odd parent or in its blossom (or `u` is a root): scanning
            // it would change nothing.
            let mu = self.mate[u as usize];
            for v in self.adj(u) {
                if v == mu {
                    continue;
                }
                self.counters.edge_visits += 1;
                let sv = self.st[v as usize];
                match sv[DL] & LABEL {
                    UNREACHED => {
                        let w = self.mate[v as usize];
                        if w == NONE {
                            // Only in a single-root search (in a phase every unpaired
                            // face is a root): the path ends here.
                            self.augment(u, v);
                            paths += 1;
                            break;
                        }
                        self.grow(u, v, w);
                    }
                    EVEN if !self.frozen[sv[TREE] as usize] => {
                        if sv[TREE] != tu {
                            self.augment(u, v);
                            paths += 1;
                            break;
                        }
                        let (bu, bv) = (self.find(u), self.find(v));
                        if bu != bv {
                            let p = self.lca(bu, bv);
                            self.shrink(u, v, p);
                            self.shrink(v, u, p);
                            self.blossoms += 1;
                        }
                    }
                    _ => {}
                }
            }
        }
        for i in 0..self.queue.len() {
            let x = self.queue[i];
            self.st[x as usize] = [0; 4];
        }
        for i in 0..self.odd.len() {
            let x = self.odd[i];
            self.st[x as usize] = [0; 4];
        }
        paths
    }

    /// The base of the smallest blossom containing the bases `a` and `b` of one tree:
    /// walk up from the deeper base (a base's parent blossom is that of the even parent
    /// of its odd mate, strictly shallower) until the two meet.
    fn lca(&mut self, mut a: u32, mut b: u32) -> u32 {
        let mut steps = 0usize;
        while a != b {
            if self.dep(a) < self.dep(b) {
                std::mem::swap(&mut a, &mut b);
            }
            let m = self.mate[a as usize];
            debug_assert!(m != NONE, "a root is never deeper than another base");
            let up = self.st[m as usize][LINK];
            a = self.find(up);
            steps += 1;
            debug_assert!(steps <= self.st.len(), "lca does not terminate");
        }
        a
    }

    /// Shrinks the half of the blossom from `x` up to base `p`, recording the flower links
    /// towards `y` (the other end of the closing edge) and queueing the odd vertices,
    /// which become even. Only set representatives are re-pointed to `p`.
    fn shrink(&mut self, mut x: u32, mut y: u32, p: u32) {
        let mut steps = 0usize;
        while self.find(x) != p {
            self.st[x as usize][LINK] = y;
            y = self.mate[x as usize];
            if self.label(y) == ODD {
                let sy = &mut self.st[y as usize];
                sy[DL] = (sy[DL] & !LABEL) | EVEN;
                self.queue.push(y);
            }
            if self.find(x) == x {
                self.st[x as usize][BASE] = p;
            }
            if self.find(y) == y {
                self.st[y as usize][BASE] = p;
            }
            x = self.st[y as usize][LINK];
            steps += 1;
            debug_assert!(steps <= self.st.len(), "shrink does not terminate");
        }
    }

    /// Pairs the even `u` with `v` (even in another tree, or unpaired) and flips the
    /// alternating paths from both back to their roots; freezes both trees.
    fn augment(&mut self, u: u32, v: u32) {
        let (mu, mv) = (self.mate[u as usize], self.mate[v as usize]);
        self.set_pair(u, v);
        if mu != NONE {
            self.flip(mu);
        }
        if mv != NONE {
            self.flip(mv);
        }
        let tu = self.st[u as usize][TREE];
        self.frozen[tu as usize] = true;
        if self.label(v) != UNREACHED {
            let tv = self.st[v as usize][TREE];
            self.frozen[tv as usize] = true;
        }
        self.counters.augmenting_paths += 1;
    }

    /// Flips the alternating path that starts at `x` (whose former mate was just
    /// re-paired, so `x` is momentarily unpaired) and follows flower links to its root.
    fn flip(&mut self, mut x: u32) {
        let mut steps = 0usize;
        loop {
            let y = self.st[x as usize][LINK];
            let t = self.mate[y as usize];
            self.set_pair(x, y);
            if t == NONE {
                break;
            }
            x = t;
            steps += 1;
            debug_assert!(steps <= self.st.len(), "flip does not terminate");
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const UNREACHED: u8 = 0;
    const EVEN: u8 = 1;
    const ODD: u8 = 2;
    use crate::gen::{icosahedron, octahedron, random, tetrahedron, RandomParams, SurfaceKind};

    fn tri(m: &crate::TriMesh) -> Triangulation {
        Triangulation::from_faces(m.vertex_count, &m.faces).expect("valid")
    }

    #[test]
    fn the_tetrahedron_and_octahedron_are_completed_from_empty() {
        for m in [tetrahedron(), octahedron(), icosahedron()] {
            let t = tri(&m);
            let mut p = Pairing::new(t.face_capacity());
            let c = complete(&t, &mut p).expect("a pairing of the triangulation");
            assert!(p.is_perfect(&t));
            assert_eq!(p.check(&t), Ok(()));
            assert_eq!(c.augmenting_paths, t.face_count() / 2);
        }
    }

    #[test]
    fn a_completed_pairing_is_left_alone() {
        let t = tri(&icosahedron());
        let mut p = Pairing::new(t.face_capacity());
        complete(&t, &mut p).expect("a pairing of the triangulation");
        let before = p.clone();
        let c = complete(&t, &mut p).expect("a pairing of the triangulation");
        assert_eq!(p, before);
        assert_eq!(c, Completion::default());
    }

    #[test]
    #[should_panic(expected = "not a pairing")]
    fn a_pairing_of_non_adjacent_faces_is_refused() {
        let t = tri(&octahedron());
        let f = FaceId(0);
        let far = crate::quad::fixtures::face_not_adjacent_to(&t, f);
        let mut p = Pairing::new(t.face_capacity());
        p.pair(f, far);
        complete(&t, &mut p).expect("a pairing of the triangulation");
    }

    #[test]
    fn a_pairing_too_small_for_the_triangulation_is_refused() {
        let t = tri(&octahedron());
        let e = complete(&t, &mut Pairing::new(t.face_capacity() - 1)).unwrap_err();
        assert!(e.to_string().contains("not a pairing"), "{e}");
    }

    #[test]
    fn a_pair_of_removed_faces_is_refused() {
        let t = random(&RandomParams {
            surface: SurfaceKind::Orientable(1),
            min_faces: 200,
            flip_percent: 30,
            seed: 1,
        })
        .expect("a random surface within the limits");
        let t = crate::irreducible::rs::reduce(t, &Default::default()).tri;
        let mut removed = (0..t.face_capacity() as u32)
            .map(FaceId)
            .filter(|&f| !t.is_face(f));
        let (a, b) = (removed.next(), removed.next());
        let (Some(a), Some(b)) = (a, b) else {
            panic!("the reduction removed no faces")
        };
        let mut p = Pairing::new(t.face_capacity());
        p.pair(a, b);
        let before = p.clone();
        let e = complete(&t, &mut p).unwrap_err();
        assert!(e.to_string().contains("not a pairing"), "{e}");
        assert_eq!(p, before, "a refused pairing is left as it was");
    }

    /// Every perfect matching `m` of `t` (as mate arrays), by exhaustive search.
    fn perfect_matchings(t: &Triangulation) -> Vec<Vec<u32>> {
        fn go(t: &Triangulation, mate: &mut Vec<u32>, out: &mut Vec<Vec<u32>>) {
            let Some(f) = t.faces().find(|f| mate[f.index()] == NONE) else {
                out.push(mate.clone());
                return;
            };
            for g in t.face_neighbours(f) {
                if mate[g.index()] == NONE {
                    mate[f.index()] = g.0;
                    mate[g.index()] = f.0;
                    go(t, mate, out);
                    mate[f.index()] = NONE;
                    mate[g.index()] = NONE;
                }
            }
        }
        let mut out = Vec::new();
        go(t, &mut vec![NONE; t.face_capacity()], &mut out);
        out
    }

    /// Whether an augmenting path of length 1 or 3 exists (the linear pass takes those).
    fn short_path_exists(t: &Triangulation, mate: &[u32]) -> bool {
        t.faces().filter(|f| mate[f.index()] == NONE).any(|f| {
            t.face_neighbours(f).into_iter().any(|v| {
                let w = mate[v.index()];
                w == NONE
                    || t.face_neighbours(FaceId(w))
                        .into_iter()
                        .any(|x| x != f && mate[x.index()] == NONE)
            })
        })
    }

    /// Whether an alternating forest *without* blossom shrinking, grown from the unpaired
    /// faces in the same BFS order as the completion (each vertex labelled at most once,
    /// even–even edges inside a tree ignored), finds an augmenting path.
    fn blossom_free_search_finds_a_path(t: &Triangulation, mate: &[u32]) -> bool {
        let n = t.face_capacity();
        let mut label = vec![UNREACHED; n];
        let mut tree = vec![NONE; n];
        let mut queue: Vec<u32> = Vec::new();
        for f in t.faces() {
            if mate[f.index()] == NONE {
                label[f.index()] = EVEN;
                tree[f.index()] = f.0;
                queue.push(f.0);
            }
        }
        let mut head = 0;
        while head < queue.len() {
            let u = queue[head] as usize;
            head += 1;
            for v in t.face_neighbours(FaceId(u as u32)) {
                let v = v.index();
                match label[v] {
                    UNREACHED => {
                        let w = mate[v] as usize;
                        label[v] = ODD;
                        label[w] = EVEN;
                        tree[v] = tree[u];
                        tree[w] = tree[u];
                        queue.push(w as u32);
                    }
                    EVEN if tree[v] != tree[u] => return true,
                    _ => {}
                }
            }
        }
        false
    }

    /// A search returns the number of augmenting paths it applied: one for a single-root
    /// search that reaches an unpaired face, and one per two trees that meet in a phase
    /// whose roots are every face.
    #[test]
    fn a_search_returns_the_paths_it_applied() {
        for m in [tetrahedron(), octahedron(), icosahedron()] {
            let t = tri(&m);
            let mut p = Pairing::new(t.face_capacity());
            let mut s = Search::new(&t, &mut p.mate);
            assert_eq!(s.phase(&[0], u64::MAX), 1);
            assert_eq!(s.counters.augmenting_paths, 1);
            assert_eq!(s.mate.iter().filter(|&&m| m != NONE).count(), 2);

            let mut p = Pairing::new(t.face_capacity());
            let roots: Vec<u32> = t.faces().map(|f| f.0).collect();
            let mut s = Search::new(&t, &mut p.mate);
            let paths = s.phase(&roots, u64::MAX);
            assert!(paths >= 2, "{paths} paths");
            assert_eq!(paths, s.counters.augmenting_paths);
            assert_eq!(s.mate.iter().filter(|&&m| m != NONE).count(), 2 * paths);
        }
    }

    /// Matchings with two unpaired faces whose augmenting path the search can only find
    /// through a blossom (a blossom-free forest finds none, yet Petersen and Berge say a
    /// path exists): obtained from perfect matchings by freeing one pair and shifting one
    /// end along an alternating path, on small surfaces. The completion must find every
    /// such path, and must shrink a blossom to do so.
    #[test]
    fn augmenting_paths_through_blossoms_are_found() {
        let mut surfaces = vec![tri(&octahedron()), tri(&icosahedron())];
        for (k, kind) in [SurfaceKind::Orientable(1), SurfaceKind::NonOrientable(1)]
            .into_iter()
            .enumerate()
        {
            surfaces.push(
                random(&RandomParams {
                    surface: kind,
                    min_faces: 18,
                    flip_percent: 30,
                    seed: k as u64,
                })
                .expect("a random surface within the limits"),
            );
        }
        let mut needing_blossoms = 0;
        for t in &surfaces {
            for m in perfect_matchings(t).into_iter().take(40) {
                // Free the pair (a, b), then shift b's freedom along alternating paths
                // b = x1 – y1 = x2 ... by re-pairing: free faces a and the path's end.
                for (a, b) in t
                    .faces()
                    .map(|f| (f.0, m[f.index()]))
                    .filter(|&(f, g)| f < g)
                {
                    let mut mate = m.clone();
                    mate[a as usize] = NONE;
                    mate[b as usize] = NONE;
                    // Walk: free end e; take a neighbour y ≠ a of e (paired to z), pair
                    // e with y, free z. Deterministic walk of a few steps.
                    let mut e = b;
                    for step in 0..6u32 {
                        let nb = t.face_neighbours(FaceId(e));
                        let y = nb[(step as usize) % 3].0;
                        let z = mate[y as usize];
                        if z == NONE || y == a {
                            break;
                        }
                        mate[y as usize] = e;
                        mate[e as usize] = y;
                        mate[z as usize] = NONE;
                        e = z;
                        if short_path_exists(t, &mate) || blossom_free_search_finds_a_path(t, &mate)
                        {
                            continue;
                        }
                        needing_blossoms += 1;
                        let mut p = Pairing::new(t.face_capacity());
                        for (f, &g) in mate.iter().enumerate() {
                            if g != NONE && (f as u32) < g {
                                p.pair(FaceId(f as u32), FaceId(g));
                            }
                        }
                        assert_eq!(p.check(t), Ok(()));
                        let (c, blossoms) =
                            run(t, &mut p, &mut progress::ignore).expect("a pairing");
                        assert!(p.is_perfect(t) && p.check(t).is_ok());
                        assert_eq!(c.augmenting_paths, 1);
                        assert!(blossoms > 0, "a path was found without a blossom");
                        // Each shrink joins at least three blossoms (two bases and the
                        // odd vertex between) into one, so a search shrinks fewer than
                        // half as many blossoms as there are faces.
                        assert!(
                            2 * blossoms < (c.phases * t.face_count()) as u64,
                            "{blossoms} blossoms in {} searches",
                            c.phases
                        );
                    }
                }
            }
        }
        assert!(
            needing_blossoms > 0,
            "no configuration needing a blossom was generated"
        );
    }

    /// The sparse pass on its own, with a budget that lets every search finish and with
    /// one that aborts the first search: either way the completion ends perfect, the
    /// aborted search leaves the pairing as it was, and the phases finish the job.
    #[test]
    fn the_sparse_pass_completes_or_hands_over_after_an_abort() {
        let t = random(&RandomParams {
            surface: SurfaceKind::Orientable(2),
            min_faces: 3000,
            flip_percent: 30,
            seed: 5,
        })
        .expect("a random surface within the limits");
        // A sparse start: from a perfect pairing, for every 97th face `a` paired with
        // `b`, re-pair `b` with a neighbour `c` and free `a` and `c`'s former mate `d`
        // (so the two free faces of each change are not neighbours).
        let mut p = Pairing::new(t.face_capacity());
        complete(&t, &mut p).expect("a pairing of the triangulation");
        let mut mate: Vec<u32> = (0..t.face_capacity() as u32)
            .map(|f| p.mate(FaceId(f)).map_or(NONE, |g| g.0))
            .collect();
        let adj = |f: u32| t.face_neighbours(FaceId(f)).map(|g| g.0);
        for a in t.faces().step_by(97).map(|f| f.0) {
            let b = mate[a as usize];
            if b == NONE {
                continue;
            }
            let pick = adj(b).into_iter().find(|&c| {
                let d = mate[c as usize];
                c != a && d != NONE && d != a && d != b && !adj(a).contains(&d)
            });
            if let Some(c) = pick {
                let d = mate[c as usize];
                mate[b as usize] = c;
                mate[c as usize] = b;
                mate[a as usize] = NONE;
                mate[d as usize] = NONE;
            }
        }
        let roots: Vec<u32> = t
            .faces()
            .filter(|f| mate[f.index()] == NONE)
            .map(|f| f.0)
            .collect();
        assert!(roots.len() > 20);
        assert!(
            adj(roots[0]).iter().all(|&g| mate[g as usize] != NONE),
            "the first root's own scan finds no unpaired neighbour"
        );
        for budget in [u64::MAX, 0] {
            let mut m = mate.clone();
            let mut search = Search::new(&t, &mut m);
            let left = search.sparse_pass(roots.clone(), budget);
            if budget == 0 {
                assert_eq!(left, roots, "an aborted first search re-pairs nothing");
                assert_eq!(search.counters.augmenting_paths, 0);
            } else {
                assert!(left.is_empty(), "every single-root search augments");
                assert_eq!(search.counters.augmenting_paths, roots.len() / 2);
            }
            let mut left = left;
            while !left.is_empty() {
                assert!(search.phase(&left, u64::MAX) > 0);
                left.retain(|&r| search.mate[r as usize] == NONE);
            }
            drop(search);
            let mut q = Pairing::new(t.face_capacity());
            for (f, &g) in m.iter().enumerate() {
                assert!(g != NONE, "face {f} left unpaired");
                if (f as u32) < g {
                    q.pair(FaceId(f as u32), FaceId(g));
                }
            }
            assert!(q.is_perfect(&t) && q.check(&t).is_ok());
        }
    }

    #[test]
    fn random_surfaces_are_completed_from_every_partial_start() {
        for (k, kind) in [
            SurfaceKind::Orientable(0),
            SurfaceKind::Orientable(3),
            SurfaceKind::NonOrientable(2),
        ]
        .into_iter()
        .enumerate()
        {
            let t = random(&RandomParams {
                surface: kind,
                min_faces: 400,
                flip_percent: 50,
                seed: 7 + k as u64,
            })
            .expect("a random surface within the limits");
            let mut p = Pairing::new(t.face_capacity());
            let (c, _) = run(&t, &mut p, &mut progress::ignore).expect("a pairing");
            assert!(p.is_perfect(&t) && p.check(&t).is_ok());
            assert_eq!(c.augmenting_paths, t.face_count() / 2);
        }
    }
}
