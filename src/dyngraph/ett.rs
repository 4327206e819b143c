//! Euler-tour trees (Henzinger–King 1995, as used by Holm–de Lichtenberg–Thorup,
//! JACM 48(4) 2001, Sec. 2) on splay trees in one flat node pool with `u32` indices.
//!
//! # Guarantees
//! A pool holds any number of forests at once (the caller, module `hdt`, keeps one per
//! level; the pool does not know levels). Each tree of a forest is represented by the
//! cyclic sequence of its Euler tour: one *vertex node* per vertex and two *arc nodes* per
//! tree edge (one per direction, allocated as a pair `p`, `p + 1`), every vertex node
//! standing right after an arc entering it (a single vertex: alone). The sequence is kept,
//! in some rotation, as the in-order of a splay tree. [`Pool::link`] and [`Pool::cut`]
//! keep that shape exactly (tested against a naive forest in `hdt`'s tests, which check
//! every level after every operation on small graphs). Each node carries two *own* flags
//! set by the caller and the splay subtree's vertex count and OR of the flags, so that
//! [`Pool::tree_size`] is exact and [`Pool::first_flagged`] finds the first flagged node of
//! a tree (in sequence order) whenever one exists. Every result is a function of the
//! sequences alone, never of the splay trees' shapes (which debug-only checks or a
//! different access order would change), so the owner's choices are reproducible.
//!
//! # Complexity
//! O(log n) amortised per operation, n the number of nodes of the trees involved (splay
//! trees, access lemma, on the shared core of module `splay`; re-rooting is a rotation
//! of the sequence: one split and one concatenation). No lazy tags (no reversal is ever
//! needed) and no path-parents, both compiled out of the core; no recursion. Memory: 24
//! bytes per node, freed nodes reused (two free lists, single vertex nodes and arc pairs).

use super::splay::{Splay, SplayNode};

/// No node / no item.
pub(super) use super::splay::NIL;

/// Bits of [`Node::w`]: the low 27 bits count the vertex nodes of the splay subtree.
const CNT_MASK: u32 = (1 << 27) - 1;
/// Own flag 0 of the node (set by the caller).
const OWN0: u32 = 1 << 27;
/// Own flag 1 of the node.
const OWN1: u32 = 1 << 28;
/// OR of flag 0 over the splay subtree.
const AGG0: u32 = 1 << 29;
/// OR of flag 1 over the splay subtree.
const AGG1: u32 = 1 << 30;
/// The node is a vertex node (counts 1), else an arc node (counts 0).
const VERTEX: u32 = 1 << 31;

/// The largest number of vertex nodes one tree may hold (the count has 27 bits).
pub(crate) const MAX_TREE: usize = CNT_MASK as usize;

/// A caller flag: which of the two own flags.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Flag {
    /// Flag 0 (`hdt`: the vertex has non-tree edges of this level).
    F0,
    /// Flag 1 (`hdt`: the arc is the canonical arc of a tree edge of this level).
    F1,
}

impl Flag {
    fn own(self) -> u32 {
        match self {
            Flag::F0 => OWN0,
            Flag::F1 => OWN1,
        }
    }
    fn agg(self) -> u32 {
        match self {
            Flag::F0 => AGG0,
            Flag::F1 => AGG1,
        }
    }
}

/// One splay node: children, parent (`NIL` at a splay root, which is also the tree's
/// handle: there are no path-parents), the packed count and flags, and two words owned by
/// the caller (`hdt`: for a vertex node its node one level up and its non-tree list; for
/// an arc node the next arc pair down and the edge id). Free nodes chain through `a`.
#[derive(Clone, Copy, Debug)]
struct Node {
    ch: [u32; 2],
    par: u32,
    w: u32,
    a: u32,
    b: u32,
}

impl SplayNode for Node {
    const PATH_PARENTS: bool = false;
    const LAZY: bool = false;
    fn ch(&self) -> [u32; 2] {
        self.ch
    }
    fn ch_mut(&mut self) -> &mut [u32; 2] {
        &mut self.ch
    }
    fn par(&self) -> u32 {
        self.par
    }
    fn par_mut(&mut self) -> &mut u32 {
        &mut self.par
    }
    fn push(_: &mut [Node], _: u32) {}
    /// The count and the aggregate flags of `x` from its own bits and its children.
    fn pull(t: &mut [Node], x: u32) {
        t[x as usize].w = recount(t, x);
    }
}

/// The packed word `x` should hold: its own bits, its vertex count (1 for a vertex node)
/// plus its children's counts, its own flags OR its children's aggregates.
#[inline]
fn recount(t: &[Node], x: u32) -> u32 {
    let n = t[x as usize];
    let own = n.w & (VERTEX | OWN0 | OWN1);
    let mut w = own | (own >> 31) | ((own & (OWN0 | OWN1)) << 2);
    for c in n.ch {
        if c != NIL {
            let cw = t[c as usize].w;
            w += cw & CNT_MASK;
            w |= cw & (AGG0 | AGG1);
        }
    }
    w
}

/// The node pool: all Euler-tour forests of one owner.
#[derive(Clone, Debug, Default)]
pub(crate) struct Pool {
    s: Splay<Node>,
    free_vertex: u32,
    free_pair: u32,
}

impl Pool {
    /// An empty pool with room for `cap` nodes before it grows.
    pub(crate) fn with_capacity(cap: usize) -> Self {
        Pool {
            s: Splay::from_nodes(Vec::with_capacity(cap)),
            free_vertex: NIL,
            free_pair: NIL,
        }
    }

    /// Nodes ever allocated (live and free).
    pub(crate) fn len(&self) -> usize {
        self.s.t.len()
    }

    /// Bytes of the nodes ever allocated (live or free).
    pub(crate) fn bytes(&self) -> usize {
        self.s.t.len() * std::mem::size_of::<Node>()
    }

    /// Appends `k` nodes, growing by a quarter rather than doubling: the pool is the
    /// largest array of `hdt` (about three nodes per vertex) and doubling it would
    /// reserve up to twice what is used.
    fn push_nodes(&mut self, k: usize, node: Node) -> u32 {
        if self.s.t.len() + k > self.s.t.capacity() {
            let extra = (self.s.t.capacity() / 4).max(k).max(64);
            self.s.t.reserve_exact(extra);
        }
        let id = self.s.t.len();
        assert!(
            id + k <= NIL as usize,
            "Euler-tour node pool exceeds u32 ids"
        );
        for _ in 0..k {
            self.s.t.push(node);
        }
        id as u32
    }

    /// A new single-vertex tree; its caller words are `a = b = NIL`.
    pub(crate) fn new_vertex(&mut self) -> u32 {
        let node = Node {
            ch: [NIL; 2],
            par: NIL,
            w: VERTEX | 1,
            a: NIL,
            b: NIL,
        };
        if self.free_vertex != NIL {
            let x = self.free_vertex;
            self.free_vertex = self.s[x].a;
            self.s[x] = node;
            x
        } else {
            self.push_nodes(1, node)
        }
    }

    /// A new pair of (unlinked) arc nodes `p`, `p + 1`, returned as `p`; caller words
    /// `NIL`, no flags.
    pub(crate) fn new_pair(&mut self) -> u32 {
        let node = Node {
            ch: [NIL; 2],
            par: NIL,
            w: 0,
            a: NIL,
            b: NIL,
        };
        if self.free_pair != NIL {
            let p = self.free_pair;
            self.free_pair = self.s[p].a;
            self.s[p] = node;
            self.s[p + 1] = node;
            p
        } else {
            self.push_nodes(2, node)
        }
    }

    /// Frees a vertex node that is a single-vertex tree.
    pub(crate) fn free_vertex(&mut self, x: u32) {
        debug_assert!(self.is_singleton(x) && self.is_vertex(x));
        self.s[x].a = self.free_vertex;
        self.free_vertex = x;
    }

    /// Frees an arc pair that [`Pool::cut`] has detached.
    pub(crate) fn free_pair(&mut self, p: u32) {
        debug_assert!(self.is_singleton(p) && self.is_singleton(p + 1));
        self.s[p].a = self.free_pair;
        self.free_pair = p;
    }

    /// Caller word `a` of `x`.
    pub(crate) fn a(&self, x: u32) -> u32 {
        self.s[x].a
    }
    /// Caller word `b` of `x`.
    pub(crate) fn b(&self, x: u32) -> u32 {
        self.s[x].b
    }
    pub(crate) fn set_a(&mut self, x: u32, v: u32) {
        self.s[x].a = v;
    }
    pub(crate) fn set_b(&mut self, x: u32, v: u32) {
        self.s[x].b = v;
    }

    /// Whether `x` is a vertex node.
    pub(crate) fn is_vertex(&self, x: u32) -> bool {
        self.s[x].w & VERTEX != 0
    }

    /// Whether `x` is alone in its tree (no splay parent, no children).
    pub(crate) fn is_singleton(&self, x: u32) -> bool {
        let n = &self.s[x];
        n.par == NIL && n.ch == [NIL; 2]
    }

    /// Whether own flag `f` of `x` is set.
    pub(crate) fn has(&self, x: u32, f: Flag) -> bool {
        self.s[x].w & f.own() != 0
    }

    /// Sets own flag `f` of `x` to `on`, keeping the aggregates of its tree exact.
    pub(crate) fn set_flag(&mut self, x: u32, f: Flag, on: bool) {
        if self.has(x, f) == on {
            return;
        }
        self.s.splay(x);
        self.s[x].w ^= f.own();
        self.s.pull(x);
    }

    /// Number of vertex nodes in the tree of `x`.
    pub(crate) fn tree_size(&mut self, x: u32) -> u32 {
        self.s.splay(x);
        self.s[x].w & CNT_MASK
    }

    /// Whether `x` and `y` are in the same tree.
    pub(crate) fn same_tree(&mut self, x: u32, y: u32) -> bool {
        if x == y {
            return true;
        }
        // After splaying y, x (the previous root) has a parent exactly if y's splay
        // tree is x's.
        self.s.splay(x);
        self.s.splay(y);
        self.s[x].par != NIL
    }

    /// The first node (in sequence order) of `x`'s tree whose own flag `f` is set, if
    /// any; splayed, which pays for the descent.
    pub(crate) fn first_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.s.splay(x);
        self.leftmost_flagged(x, f)
    }

    /// The first node after `x` in its tree's sequence whose own flag `f` is set, if any;
    /// splayed.
    pub(crate) fn next_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.s.splay(x);
        let r = self.s[x].ch[1];
        if r == NIL {
            return None;
        }
        self.extreme_flagged(r, f, 0)
    }

    /// The last node (in sequence order) of `x`'s tree whose own flag `f` is set, if any;
    /// splayed.
    pub(crate) fn last_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.s.splay(x);
        self.extreme_flagged(x, f, 1)
    }

    /// The last node before `x` in its tree's sequence whose own flag `f` is set, if any;
    /// splayed.
    pub(crate) fn prev_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.s.splay(x);
        let l = self.s[x].ch[0];
        if l == NIL {
            return None;
        }
        self.extreme_flagged(l, f, 1)
    }

    /// The leftmost flagged node of the splay subtree of `y`, splayed to the root.
    fn leftmost_flagged(&mut self, y: u32, f: Flag) -> Option<u32> {
        self.extreme_flagged(y, f, 0)
    }

    /// The leftmost (`side` 0) or rightmost (`side` 1) flagged node of the splay
    /// subtree of `y`, splayed to the root.
    fn extreme_flagged(&mut self, mut y: u32, f: Flag, side: usize) -> Option<u32> {
        if self.s[y].w & f.agg() == 0 {
            return None;
        }
        loop {
            let n = self.s[y];
            let near = n.ch[side];
            if near != NIL && self.s[near].w & f.agg() != 0 {
                y = near;
            } else if n.w & f.own() != 0 {
                break;
            } else {
                y = n.ch[side ^ 1];
                debug_assert!(y != NIL, "aggregate flag without a flagged node");
            }
        }
        self.s.splay(y);
        Some(y)
    }

    /// Joins the trees of vertex nodes `x` and `y` (different trees) by the edge whose
    /// unlinked arc pair is `p` (`p` from `x` to `y`, `p + 1` back): with `x`'s sequence
    /// `A x B` and `y`'s rotated to `y C`, the sequence becomes `A x p y C (p+1) B`, so
    /// that only `y`'s tree is rotated (two splays and one concatenation).
    pub(crate) fn link(&mut self, x: u32, y: u32, p: u32) {
        debug_assert_ne!(self.root_of(x), self.root_of(y), "link: same tree");
        debug_assert!(self.is_singleton(p) && self.is_singleton(p + 1));
        let q = p + 1;
        self.s.splay(y);
        let [l, r] = self.s.detach(y);
        let c = self.s.concat(r, l);
        self.s.attach(y, [p, c]);
        self.s.splay(x);
        let b = self.s[x].ch[1];
        self.s[x].ch[1] = NIL;
        if b != NIL {
            self.s[b].par = NIL;
        }
        self.s.attach(q, [y, b]);
        self.s.attach(x, [self.s[x].ch[0], q]);
    }

    /// Makes the detached nodes `seq` (each a single-node tree, own flags already set)
    /// one tree whose sequence is `seq` in this order, as a balanced splay tree. O(len),
    /// against O(len log len) for the same tree built by [`Pool::link`]s; the caller
    /// makes `seq` a valid Euler tour (`hdt`'s bulk load).
    pub(crate) fn build(&mut self, seq: &[u32]) {
        debug_assert!(seq.iter().all(|&x| self.is_singleton(x)));
        self.s.build(seq);
    }

    /// Removes the edge whose linked arc pair is `p`: with the sequence `A p B (p+1) C`
    /// (or `A (p+1) B p C`), the two trees become `B` and `C A`; `p` and `p + 1` are left
    /// as detached nodes for [`Pool::free_pair`].
    pub(crate) fn cut(&mut self, p: u32) {
        let (first, second) = if self.precedes(p, p + 1) {
            (p, p + 1)
        } else {
            (p + 1, p)
        };
        self.s.splay(first);
        let [a, rest] = self.s.detach(first);
        debug_assert!(rest != NIL);
        // `second` lies in `rest`, whose root is now a splay root.
        self.s.splay(second);
        let [b, c] = self.s.detach(second);
        debug_assert!(b != NIL, "each side of a tree edge has a vertex");
        self.s.concat(c, a);
    }

    /// Whether `x` comes before `y` in their (common) sequence.
    fn precedes(&mut self, x: u32, y: u32) -> bool {
        self.s.splay(y);
        self.s.splay(x);
        // Splaying x moves the previous root y down by at most two levels (y only takes
        // part in the last zig, zig-zig or zig-zag step), so this walk is O(1).
        let mut c = y;
        loop {
            let p = self.s[c].par;
            debug_assert!(p != NIL, "precedes: different trees");
            if p == x {
                return self.s[x].ch[1] == c;
            }
            c = p;
        }
    }

    /// The splay root of `x`'s tree, without restructuring (for checks).
    pub(crate) fn root_of(&self, x: u32) -> u32 {
        self.s.root_of(x)
    }

    /// The in-order sequence of the tree with splay root `r` (for checks).
    pub(crate) fn sequence(&self, r: u32) -> Vec<u32> {
        self.s.in_order(r)
    }

    /// Every node's caller words and own bits (for tests comparing two pools).
    #[cfg(test)]
    pub(crate) fn words(&self) -> impl Iterator<Item = (u32, u32, u32)> + '_ {
        self.s
            .t
            .iter()
            .map(|n| (n.a, n.b, n.w & (VERTEX | OWN0 | OWN1)))
    }

    /// Whether the stored count and aggregate flags of `x` are those recomputed from its
    /// children, and its children's parent is `x` (for checks).
    pub(crate) fn node_consistent(&self, x: u32) -> bool {
        let n = self.s[x];
        n.ch.iter().all(|&c| c == NIL || self.s[c].par == x) && recount(&self.s.t, x) == n.w
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    /// The node size the documentation states.
    #[test]
    fn node_size() {
        assert_eq!(std::mem::size_of::<super::Node>(), 24);
    }

    /// A forest kept naively: tree edges as `(x, y, p)` (vertex nodes and the arc pair),
    /// components by a search over them.
    struct Naive {
        vertices: Vec<u32>,
        edges: Vec<(u32, u32, u32)>,
    }

    impl Naive {
        fn component(&self, x: u32) -> Vec<u32> {
            let mut seen = vec![x];
            let mut k = 0;
            while k < seen.len() {
                let v = seen[k];
                for &(a, b, _) in &self.edges {
                    for (from, to) in [(a, b), (b, a)] {
                        if from == v && !seen.contains(&to) {
                            seen.push(to);
                        }
                    }
                }
                k += 1;
            }
            seen
        }
    }

    /// Checks that the sequence of `x`'s tree is an Euler tour of its naive tree: its
    /// vertex nodes and both arcs of each of its edges once; cyclically, each arc ends
    /// where the next arc starts, and each vertex node stands right after an arc
    /// entering it (or alone). Returns the sequence.
    fn check_tour(pool: &Pool, naive: &Naive, x: u32) -> Vec<u32> {
        let seq = pool.sequence(pool.root_of(x));
        let component = naive.component(x);
        // arc node -> (from, to)
        let mut arcs = std::collections::BTreeMap::new();
        for &(a, b, p) in &naive.edges {
            if component.contains(&a) {
                arcs.insert(p, (a, b));
                arcs.insert(p + 1, (b, a));
            }
        }
        let mut expected: Vec<u32> = component
            .iter()
            .copied()
            .chain(arcs.keys().copied())
            .collect();
        expected.sort();
        let mut sorted = seq.clone();
        sorted.sort();
        assert_eq!(sorted, expected, "the nodes of the tree of {x}");
        if seq.len() == 1 {
            return seq;
        }
        let tour: Vec<(u32, u32)> = seq.iter().filter_map(|n| arcs.get(n).copied()).collect();
        for (k, &(_, to)) in tour.iter().enumerate() {
            assert_eq!(
                to,
                tour[(k + 1) % tour.len()].0,
                "the tour of {x} continues"
            );
        }
        for (k, &n) in seq.iter().enumerate() {
            if pool.is_vertex(n) {
                let before = seq[(k + seq.len() - 1) % seq.len()];
                assert_eq!(
                    arcs.get(&before).map(|a| a.1),
                    Some(n),
                    "{n} after an arc into it"
                );
            }
        }
        seq
    }

    /// Links, cuts, flags and queries on random forests agree with a naive forest: each
    /// tree's sequence is an Euler tour of it, sizes, membership and the flagged-node
    /// searches (read off that sequence) are the naive ones, every node's packed count
    /// and flags are those of its children, freed nodes are reused last-in first-out,
    /// and the byte count is that of the nodes allocated.
    #[test]
    fn operations_agree_with_a_naive_forest() {
        let mut links = 0;
        for seed in 0..40 {
            let mut rng = Rng::new(seed);
            let mut pool = Pool::with_capacity(4);
            let mut naive = Naive {
                vertices: Vec::new(),
                edges: Vec::new(),
            };
            let n = 2 + rng.index(12);
            let mut allocated = 0;
            let mut free_pairs = Vec::new();
            for _ in 0..n {
                naive.vertices.push(pool.new_vertex());
                allocated += 1;
            }
            assert_eq!(naive.vertices, (0..n as u32).collect::<Vec<_>>());
            for step in 0..300 {
                match rng.index(6) {
                    0 | 1 => {
                        let x = naive.vertices[rng.index(n)];
                        let y = naive.vertices[rng.index(n)];
                        if naive.component(x).contains(&y) {
                            assert!(pool.same_tree(x, y), "seed {seed} step {step}");
                            continue;
                        }
                        assert!(!pool.same_tree(x, y), "seed {seed} step {step}");
                        let p = pool.new_pair();
                        // Freed pairs first, last freed first; else two new nodes.
                        if let Some(freed) = free_pairs.pop() {
                            assert_eq!(p, freed, "seed {seed} step {step}");
                        } else {
                            assert_eq!(p as usize, allocated, "seed {seed} step {step}");
                            allocated += 2;
                        }
                        // A pair, reused or not, comes clean: no caller words, no flags.
                        for q in [p, p + 1] {
                            assert_eq!((pool.a(q), pool.b(q)), (NIL, NIL), "seed {seed}");
                            assert!(!pool.is_vertex(q) && !pool.has(q, Flag::F0));
                            assert!(!pool.has(q, Flag::F1), "seed {seed} step {step}");
                        }
                        pool.link(x, y, p);
                        assert!(!pool.is_singleton(x) && !pool.is_singleton(p + 1));
                        naive.edges.push((x, y, p));
                        links += 1;
                        let seq = check_tour(&pool, &naive, x);
                        let at = seq.iter().position(|&v| v == x).expect("x in its tour");
                        assert_eq!(seq[(at + 1) % seq.len()], p, "p right after x");
                    }
                    2 if !naive.edges.is_empty() => {
                        let (x, y, p) = naive.edges.swap_remove(rng.index(naive.edges.len()));
                        pool.cut(p);
                        assert!(pool.is_singleton(p) && pool.is_singleton(p + 1));
                        assert!(!pool.same_tree(x, y), "seed {seed} step {step}");
                        check_tour(&pool, &naive, x);
                        check_tour(&pool, &naive, y);
                        pool.free_pair(p);
                        // The freed pair is the next one handed out.
                        let q = pool.new_pair();
                        assert_eq!(q, p, "seed {seed} step {step}");
                        pool.free_pair(q);
                        free_pairs.push(p);
                    }
                    3 => {
                        let x = rng.index(pool.len()) as u32;
                        let f = if rng.chance(1, 2) { Flag::F0 } else { Flag::F1 };
                        let on = rng.chance(1, 2);
                        pool.set_flag(x, f, on);
                        assert_eq!(pool.has(x, f), on);
                        // Free nodes chain through `a`: only linked arcs get words.
                        if naive.edges.iter().any(|&(_, _, p)| x == p || x == p + 1) {
                            pool.set_a(x, step);
                            pool.set_b(x, step + 1);
                        }
                    }
                    _ => {
                        let x = naive.vertices[rng.index(n)];
                        let component = naive.component(x);
                        assert_eq!(pool.tree_size(x) as usize, component.len());
                        let seq = check_tour(&pool, &naive, x);
                        for f in [Flag::F0, Flag::F1] {
                            let flagged: Vec<u32> =
                                seq.iter().copied().filter(|&v| pool.has(v, f)).collect();
                            assert_eq!(pool.first_flagged(x, f), flagged.first().copied());
                            assert_eq!(pool.last_flagged(x, f), flagged.last().copied());
                            let at = seq.iter().position(|&v| v == x).expect("x in its tour");
                            let after = seq[at + 1..].iter().find(|&&v| pool.has(v, f));
                            let before = seq[..at].iter().rev().find(|&&v| pool.has(v, f));
                            assert_eq!(pool.next_flagged(x, f), after.copied());
                            assert_eq!(pool.prev_flagged(x, f), before.copied());
                            // Splaying does not change the sequence.
                            assert_eq!(pool.sequence(pool.root_of(x)), seq);
                        }
                    }
                }
                for v in 0..pool.len() as u32 {
                    assert!(pool.node_consistent(v), "seed {seed} step {step}: node {v}");
                }
                assert_eq!(pool.len(), allocated, "seed {seed}");
                assert_eq!(pool.bytes(), 24 * allocated, "seed {seed}");
            }
            // Caller words are the caller's; a freed single vertex is handed out again.
            let x = naive.vertices[0];
            pool.set_a(x, 7);
            pool.set_b(x, 9);
            assert_eq!((pool.a(x), pool.b(x)), (7, 9));
            let v = pool.new_vertex();
            assert_eq!((v as usize, pool.tree_size(v)), (pool.len() - 1, 1));
            pool.free_vertex(v);
            assert_eq!(pool.new_vertex(), v);
            assert_eq!((pool.a(v), pool.b(v)), (NIL, NIL));
        }
        assert!(links > 1000, "{links} links");
    }

    /// The pool grows by a quarter of its capacity (at least the nodes asked for, and
    /// 64), only when full, and to exactly that: never by doubling.
    #[test]
    fn the_pool_grows_by_a_quarter_when_full() {
        let mut pool = Pool::with_capacity(10);
        let mut grown = 0;
        for k in 0..5000 {
            let (len, cap) = (pool.len(), pool.s.t.capacity());
            let want = if k % 3 == 0 { 2 } else { 1 };
            if want == 2 {
                pool.new_pair();
            } else {
                pool.new_vertex();
            }
            let expected = if len + want > cap {
                grown += 1;
                len + (cap / 4).max(want).max(64)
            } else {
                cap
            };
            assert_eq!(pool.s.t.capacity(), expected, "after {k} allocations");
        }
        assert!(grown > 10, "{grown} growths");
    }

    /// A bulk build gives the tree whose sequence is the one given, with exact counts.
    #[test]
    fn build_keeps_the_given_order() {
        let mut pool = Pool::with_capacity(0);
        // The path 0 - 1 - 2 as the tour 0 p 1 q 2 (q+1) (p+1).
        let [a, b, c] = [pool.new_vertex(), pool.new_vertex(), pool.new_vertex()];
        let (p, q) = (pool.new_pair(), pool.new_pair());
        pool.set_flag(b, Flag::F0, true);
        pool.set_flag(q + 1, Flag::F1, true);
        let seq = [a, p, b, q, c, q + 1, p + 1];
        pool.build(&seq);
        assert_eq!(pool.sequence(pool.root_of(a)), seq);
        assert_eq!(pool.tree_size(c), 3);
        assert!(pool.same_tree(a, p + 1));
        assert_eq!(pool.first_flagged(c, Flag::F0), Some(b));
        assert_eq!(pool.first_flagged(c, Flag::F1), Some(q + 1));
        for x in seq {
            assert!(pool.node_consistent(x));
        }
        // The check fails on a wrong count, and on a child that names another parent.
        let r = pool.root_of(a);
        pool.s[r].w += 1;
        assert!(!pool.node_consistent(r), "a wrong count");
        pool.s[r].w -= 1;
        let child = pool.s[r]
            .ch
            .into_iter()
            .find(|&c| c != NIL)
            .expect("a child");
        pool.s[child].par = child;
        assert!(!pool.node_consistent(r), "a child with another parent");
    }
}
