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
//! 2. **Phases**, until no face is unpaired. The roots of a phase are the unpaired faces
//!    in increasing id. Every root is an even vertex of its own tree and enters a FIFO
//!    queue in that order (a multi-source BFS, so trees grow level by level). An even
//!    vertex `u` taken from the queue examines its neighbours `v` in slot order:
//!    - `v` unreached (then `v` is paired: all unpaired faces are roots): `v` becomes odd
//!      and its mate `w` even in `u`'s tree, `w` is queued;
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
//!    are per root of the phase, so no phase costs O(F) beyond its own search.
//!
//! # Determinism
//! The output is a function of the triangulation (its face ids and slot order) and the
//! input pairing alone: no randomness, no hashing; all choices are the id/slot orders
//! stated above. A port that follows the rules above reproduces the pairs exactly.
//!
//! # Complexity
//! Memory: one 32-byte record per face slot (`face_capacity`: the three neighbours, the
//! mate and the search state of a face in one aligned record, so that a visit costs one
//! cache miss), plus the list of live faces, the queue and the list of re-paired faces:
//! about 40–50 bytes per face, about 200 MB at 4.2M triangles. Face ids must stay below 2^30 (the BFS depth shares a word
//! with the label). The mates are copied in and written back, O(F) each. Time: the
//! linear pass is O(F). Each phase scans every vertex at most once as an even vertex (3
//! edge visits) plus blossom work that is linear up to the inverse Ackermann factor, so a
//! phase is O(F·α(F)); every phase augments at least once (if it found no path the
//! matching would be maximum, contradicting Petersen), so the worst case is
//! O(K·F·α(F)) for K unpaired input faces (O(F²·α(F)) from empty). In practice the
//! phases grow all trees at once and close almost all pairs in the first one or two,
//! so the work is a few edge visits per triangle in total, i.e. near-linear.
//! [`Completion::edge_visits`] counts it exactly (one per adjacency slot examined,
//! linear pass included). Measured (test `c0_greedy_leftovers…` in
//! `tests/algorithms/quad_augment.rs`, release build, shared 2-core machine):
//!
//! | input | unpaired | linear pass | roots per phase | visits / triangle | CPU |
//! |---|---:|---:|---|---:|---:|
//! | C0 (4,221,420 triangles, genus 3,500), random edge-order greedy | 511,218 (12.1%) | 164,603 paths | 182,012 → 14,064 → 60 → 0 | 4.68 | 1.2 s |
//! | C0 from empty | 4,221,420 | 2,082,913 paths | 55,594 → 21,302 → 5,320 → 2 → 0 | 6.26 | 1.3 s |
//! | the 99 shared closed meshes, greedy starts | | | | 4.44 | |
//!
//! C0 needs about 0.22 blossoms per triangle. One visit costs about 60 ns there, against 7 ns for a plain single-source BFS
//! sweep of the same dual (0.09 s): the search records (32 MB per million faces) do not
//! fit in cache, and the multi-source queue interleaves all trees, so most visits miss.
//!
//! # Where the sources are silent
//! The paper (Lemos–Ramaswami–Siqueira §3.1) runs one BFS augmenting-path search per pair
//! (Θ(F) each); the multi-source phases, the freezing, the linear pre-pass and all
//! orders above are this module's choices (the notes' measured design), not the paper's.

use super::Pairing;
use crate::core::{FaceId, Triangulation};

/// Counters of one completion.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Completion {
    /// Augmenting paths applied (each adds one pair), the linear pass's included.
    pub augmenting_paths: usize,
    /// Phases of the multi-source search (the linear pass is not counted).
    pub phases: usize,
    /// Adjacency slots examined, linear pass included.
    pub edge_visits: u64,
}

/// Makes `pairing` a perfect pairing of `tri` by augmenting paths (see the module
/// documentation for the algorithm, its determinism and complexity). Existing pairs may
/// be re-paired. Returns the counters.
///
/// # Panics
/// If `pairing` is not a pairing of `tri` (what [`Pairing::check`] verifies; checked
/// while the search records are built, in O(F)): completing it would otherwise read
/// faces that are not there. If `tri.face_capacity() >= 2^30`.
pub fn complete(tri: &Triangulation, pairing: &mut Pairing) -> Completion {
    run(tri, pairing).0
}

/// [`complete`], also returning the number of blossoms shrunk (for tests).
pub(crate) fn run(tri: &Triangulation, pairing: &mut Pairing) -> (Completion, u64) {
    let mut search = match Search::new(tri, pairing) {
        Ok(s) => s,
        Err(e) => panic!("augment::complete: {e}"),
    };
    search.linear_pass();
    let mut roots: Vec<u32> = search.unpaired();
    while !roots.is_empty() {
        let paths = search.phase(&roots);
        roots.retain(|&r| search.node[r as usize].mate == NONE);
        if paths == 0 {
            // A maximum matching that is not perfect: impossible on a closed
            // triangulation (Petersen), so only a broken input could get here; stop
            // rather than loop.
            debug_assert!(false, "a phase found no augmenting path");
            break;
        }
    }
    search.write_back(pairing);
    debug_assert!(pairing.check(tri).is_ok());
    (search.counters, search.blossoms)
}

/// No vertex / no link / no mate.
const NONE: u32 = u32::MAX;
/// Labels of the alternating forest (the low two bits of [`Node::dl`]).
const UNREACHED: u32 = 0;
const EVEN: u32 = 1;
const ODD: u32 = 2;
const LABEL: u32 = 3;

/// Everything the search reads or writes about one dual vertex (face), in one 32-byte
/// cache-line-aligned record, so that a visit costs one cache miss rather than one per
/// array (the dual of a 4M-triangle mesh does not fit in cache):
/// - `adj`: the three neighbouring faces (a copy of `face_neighbours`), `mate`: the
///   current mate or `NONE` (the search works on this copy, written back at the end);
/// - `link`: the flower link (the even parent of an odd vertex, or the cross edge
///   recorded when a blossom is shrunk); `base`: the union–find parent over blossom
///   bases; `dl`: BFS depth × 4 + label (the depth is set for odd vertices too: a vertex
///   turned even by a blossom passes it on); `tree`: the index of its root in the phase's
///   root list. Those four are meaningful only while the label is not `UNREACHED`, and
///   all are written when the vertex is labelled.
#[derive(Clone, Copy)]
#[repr(C, align(32))]
struct Node {
    adj: [u32; 3],
    mate: u32,
    link: u32,
    base: u32,
    dl: u32,
    tree: u32,
}

impl Node {
    #[inline]
    fn label(&self) -> u32 {
        self.dl & LABEL
    }
    #[inline]
    fn dep(&self) -> u32 {
        self.dl >> 2
    }
}

struct Search {
    node: Vec<Node>,
    /// Live faces in increasing id.
    live: Vec<u32>,
    /// `frozen[tree]`: that tree augmented in this phase (indexed by root position).
    frozen: Vec<bool>,
    /// BFS queue of even vertices (reused across phases; also the list of the even
    /// vertices to reset).
    queue: Vec<u32>,
    /// Odd vertices labelled in this phase (to reset).
    odd: Vec<u32>,
    /// Faces whose mate was set by the search (with repetitions): the only ones the
    /// write-back has to look at.
    changed: Vec<u32>,
    counters: Completion,
    blossoms: u64,
}

impl Search {
    /// Copies the dual graph and the mates into the search records, checking on the way
    /// that `pairing` is a pairing of `tri` (what [`Pairing::check`] checks, at no extra
    /// pass).
    fn new(tri: &Triangulation, pairing: &Pairing) -> Result<Self, String> {
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
        let blank = Node {
            adj: [NONE; 3],
            mate: NONE,
            link: NONE,
            base: NONE,
            dl: UNREACHED,
            tree: NONE,
        };
        // One pass writes every record once (a blank for dead ids), in increasing id,
        // so the first violation reported is the same as a scan of `tri.faces()`.
        let mut node = Vec::with_capacity(n);
        let mut live = Vec::with_capacity(tri.face_count());
        let mut paired = 0usize;
        for f in (0..n as u32).map(FaceId) {
            if !tri.is_face(f) {
                node.push(blank);
                continue;
            }
            let adj = tri.face_neighbours(f).map(|g| g.0);
            let mate = match pairing.mate(f) {
                Some(g) => {
                    if !adj.contains(&g.0) {
                        return Err(format!(
                            "not a pairing of the triangulation: {f} and {g} share no edge"
                        ));
                    }
                    paired += 1;
                    g.0
                }
                None => NONE,
            };
            node.push(Node { adj, mate, ..blank });
            live.push(f.0);
        }
        // Live faces pair only with live neighbours (above) and mates are symmetric
        // (Pairing's invariant), so this catches pairs holding removed faces.
        if paired != 2 * pairing.len() {
            return Err(format!(
                "not a pairing of the triangulation: {} pairs recorded, {paired} live faces paired",
                pairing.len()
            ));
        }
        Ok(Search {
            node,
            live,
            frozen: Vec::new(),
            queue: Vec::new(),
            odd: Vec::new(),
            changed: Vec::new(),
            counters: Completion::default(),
            blossoms: 0,
        })
    }

    /// Makes `pairing` hold the search's mates: first unpairs every changed face whose
    /// mate differs, then pairs the new pairs (a face left unpaired by the first pass has
    /// a new mate that was changed too, hence also unpaired). Linear in the changes.
    fn write_back(&self, pairing: &mut Pairing) {
        for &f in &self.changed {
            let m = self.node[f as usize].mate;
            if pairing.mate(FaceId(f)).map_or(NONE, |g| g.0) != m {
                pairing.unpair(FaceId(f));
            }
        }
        for &f in &self.changed {
            let m = self.node[f as usize].mate;
            if m != NONE && !pairing.is_paired(FaceId(f)) {
                pairing.pair(FaceId(f), FaceId(m));
            }
        }
    }

    /// The live unpaired faces, in increasing id.
    fn unpaired(&self) -> Vec<u32> {
        self.live
            .iter()
            .copied()
            .filter(|&f| self.node[f as usize].mate == NONE)
            .collect()
    }

    #[inline]
    fn set_pair(&mut self, a: u32, b: u32) {
        self.node[a as usize].mate = b;
        self.node[b as usize].mate = a;
        self.changed.push(a);
        self.changed.push(b);
    }

    /// Augmenting paths of length 1 and 3 from every unpaired face, in one scan (module
    /// documentation, step 1).
    fn linear_pass(&mut self) {
        for i in 0..self.live.len() {
            let f = self.live[i];
            if self.node[f as usize].mate != NONE {
                continue;
            }
            let nb = self.node[f as usize].adj;
            let mut done = false;
            for &g in &nb {
                self.counters.edge_visits += 1;
                if self.node[g as usize].mate == NONE {
                    self.set_pair(f, g);
                    done = true;
                    break;
                }
            }
            if !done {
                'three: for &v in &nb {
                    let w = self.node[v as usize].mate;
                    for x in self.node[w as usize].adj {
                        self.counters.edge_visits += 1;
                        if x != f && self.node[x as usize].mate == NONE {
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
    }

    /// Union–find root (path halving) of `x`'s blossom: its base.
    #[inline]
    fn find(&mut self, mut x: u32) -> u32 {
        loop {
            let p = self.node[x as usize].base;
            if p == x {
                return x;
            }
            let gp = self.node[p as usize].base;
            self.node[x as usize].base = gp;
            x = gp;
        }
    }

    /// Labels `v` odd (child of `u`) and its mate `w` even; queues `w`.
    #[inline]
    fn grow(&mut self, u: u32, v: u32, w: u32) {
        let Node { dl, tree, .. } = self.node[u as usize];
        let dep = dl >> 2;
        let nv = &mut self.node[v as usize];
        nv.link = u;
        nv.base = v;
        nv.dl = ((dep + 1) << 2) | ODD;
        nv.tree = tree;
        let nw = &mut self.node[w as usize];
        nw.link = NONE;
        nw.base = w;
        nw.dl = ((dep + 2) << 2) | EVEN;
        nw.tree = tree;
        self.odd.push(v);
        self.queue.push(w);
    }

    /// One phase from `roots` (all unpaired faces): module documentation, step 2.
    /// Returns the number of augmenting paths found.
    fn phase(&mut self, roots: &[u32]) -> usize {
        self.counters.phases += 1;
        let mut paths = 0;
        self.queue.clear();
        self.odd.clear();
        self.frozen.clear();
        self.frozen.resize(roots.len(), false);
        for (k, &r) in roots.iter().enumerate() {
            let nr = &mut self.node[r as usize];
            nr.link = NONE;
            nr.base = r;
            nr.dl = EVEN;
            nr.tree = k as u32;
            self.queue.push(r);
        }
        let mut head = 0;
        while head < self.queue.len() {
            let u = self.queue[head];
            head += 1;

            let Node { adj, tree: tu, .. } = self.node[u as usize];
            if self.frozen[tu as usize] {
                continue;
            }
            for v in adj {
                self.counters.edge_visits += 1;
                let nv = self.node[v as usize];
                match nv.label() {
                    UNREACHED => {
                        if nv.mate == NONE {
                            // Unreachable (every unpaired face is a root), but a free
                            // unreached face would just end an augmenting path.
                            self.augment(u, v);
                            paths += 1;
                            break;
                        }
                        self.grow(u, v, nv.mate);
                    }
                    EVEN if !self.frozen[nv.tree as usize] => {
                        if nv.tree != tu {
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
            self.node[x as usize].dl = UNREACHED;
        }
        for i in 0..self.odd.len() {
            let x = self.odd[i];
            self.node[x as usize].dl = UNREACHED;
        }
        paths
    }

    /// The base of the smallest blossom containing the bases `a` and `b` of one tree:
    /// walk up from the deeper base (a base's parent blossom is that of the even parent
    /// of its odd mate, strictly shallower) until the two meet.
    fn lca(&mut self, mut a: u32, mut b: u32) -> u32 {
        let mut steps = 0usize;
        while a != b {
            if self.node[a as usize].dep() < self.node[b as usize].dep() {
                std::mem::swap(&mut a, &mut b);
            }
            let m = self.node[a as usize].mate;
            debug_assert!(m != NONE, "a root is never deeper than another base");
            let up = self.node[m as usize].link;
            a = self.find(up);
            steps += 1;
            debug_assert!(steps <= self.node.len(), "lca does not terminate");
        }
        a
    }

    /// Shrinks the half of the blossom from `x` up to base `p`, recording the flower links
    /// towards `y` (the other end of the closing edge) and queueing the odd vertices,
    /// which become even. Only set representatives are re-pointed to `p`.
    fn shrink(&mut self, mut x: u32, mut y: u32, p: u32) {
        let mut steps = 0usize;
        while self.find(x) != p {
            self.node[x as usize].link = y;
            y = self.node[x as usize].mate;
            let ny = &mut self.node[y as usize];
            if ny.label() == ODD {
                ny.dl = (ny.dl & !LABEL) | EVEN;
                self.queue.push(y);
            }
            if self.find(x) == x {
                self.node[x as usize].base = p;
            }
            if self.find(y) == y {
                self.node[y as usize].base = p;
            }
            x = self.node[y as usize].link;
            steps += 1;
            debug_assert!(steps <= self.node.len(), "shrink does not terminate");
        }
    }

    /// Pairs the even `u` with `v` (even in another tree, or unpaired) and flips the
    /// alternating paths from both back to their roots; freezes both trees.
    fn augment(&mut self, u: u32, v: u32) {
        let (mu, mv) = (self.node[u as usize].mate, self.node[v as usize].mate);
        self.set_pair(u, v);
        if mu != NONE {
            self.flip(mu);
        }
        if mv != NONE {
            self.flip(mv);
        }
        let (tu, nv) = (self.node[u as usize].tree, self.node[v as usize]);
        self.frozen[tu as usize] = true;
        if nv.label() != UNREACHED {
            self.frozen[nv.tree as usize] = true;
        }
        self.counters.augmenting_paths += 1;
    }

    /// Flips the alternating path that starts at `x` (whose former mate was just
    /// re-paired, so `x` is momentarily unpaired) and follows flower links to its root.
    fn flip(&mut self, mut x: u32) {
        let mut steps = 0usize;
        loop {
            let y = self.node[x as usize].link;
            let t = self.node[y as usize].mate;
            self.set_pair(x, y);
            if t == NONE {
                break;
            }
            x = t;
            steps += 1;
            debug_assert!(steps <= self.node.len(), "flip does not terminate");
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
            let c = complete(&t, &mut p);
            assert!(p.is_perfect(&t));
            assert_eq!(p.check(&t), Ok(()));
            assert_eq!(c.augmenting_paths, t.face_count() / 2);
        }
    }

    #[test]
    fn a_completed_pairing_is_left_alone() {
        let t = tri(&icosahedron());
        let mut p = Pairing::new(t.face_capacity());
        complete(&t, &mut p);
        let before = p.clone();
        let c = complete(&t, &mut p);
        assert_eq!(p, before);
        assert_eq!(c, Completion::default());
    }

    #[test]
    #[should_panic(expected = "not a pairing")]
    fn a_pairing_of_non_adjacent_faces_is_refused() {
        let t = tri(&octahedron());
        let f = FaceId(0);
        let far = t
            .faces()
            .find(|&g| g != f && !t.face_neighbours(f).contains(&g))
            .expect("the octahedron has faces not adjacent to face 0");
        let mut p = Pairing::new(t.face_capacity());
        p.pair(f, far);
        complete(&t, &mut p);
    }

    #[test]
    #[should_panic(expected = "not a pairing")]
    fn a_pairing_too_small_for_the_triangulation_is_refused() {
        let t = tri(&octahedron());
        complete(&t, &mut Pairing::new(t.face_capacity() - 1));
    }

    #[test]
    #[should_panic(expected = "not a pairing")]
    fn a_pair_of_removed_faces_is_refused() {
        let t = random(&RandomParams {
            surface: SurfaceKind::Orientable(1),
            min_faces: 200,
            flip_percent: 30,
            seed: 1,
        });
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
        complete(&t, &mut p);
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
            surfaces.push(random(&RandomParams {
                surface: kind,
                min_faces: 18,
                flip_percent: 30,
                seed: k as u64,
            }));
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
                        let (c, blossoms) = run(t, &mut p);
                        assert!(p.is_perfect(t) && p.check(t).is_ok());
                        assert_eq!(c.augmenting_paths, 1);
                        assert!(blossoms > 0, "a path was found without a blossom");
                    }
                }
            }
        }
        assert!(
            needing_blossoms > 0,
            "no configuration needing a blossom was generated"
        );
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
            });
            let mut p = Pairing::new(t.face_capacity());
            let (c, _) = run(&t, &mut p);
            assert!(p.is_perfect(&t) && p.check(&t).is_ok());
            assert_eq!(c.augmenting_paths, t.face_count() / 2);
        }
    }
}
