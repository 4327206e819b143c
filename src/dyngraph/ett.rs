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
//! trees, access lemma; re-rooting is a rotation of the sequence: one split and one
//! concatenation). No lazy tags (no reversal is ever needed), no recursion. Memory: 24
//! bytes per node, freed nodes reused (two free lists, single vertex nodes and arc pairs).

/// No node / no item.
pub(crate) const NIL: u32 = u32::MAX;

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

/// The node pool: all Euler-tour forests of one owner.
#[derive(Clone, Debug, Default)]
pub(crate) struct Pool {
    t: Vec<Node>,
    free_vertex: u32,
    free_pair: u32,
}

impl Pool {
    /// An empty pool with room for `cap` nodes before it grows.
    pub(crate) fn with_capacity(cap: usize) -> Self {
        Pool {
            t: Vec::with_capacity(cap),
            free_vertex: NIL,
            free_pair: NIL,
        }
    }

    /// Nodes ever allocated (live and free).
    pub(crate) fn len(&self) -> usize {
        self.t.len()
    }

    /// Bytes of the nodes ever allocated (live or free).
    pub(crate) fn bytes(&self) -> usize {
        self.t.len() * std::mem::size_of::<Node>()
    }

    /// Appends `k` nodes, growing by a quarter rather than doubling: the pool is the
    /// largest array of `hdt` (about three nodes per vertex) and doubling it would
    /// reserve up to twice what is used.
    fn push_nodes(&mut self, k: usize, node: Node) -> u32 {
        if self.t.len() + k > self.t.capacity() {
            let extra = (self.t.capacity() / 4).max(k).max(64);
            self.t.reserve_exact(extra);
        }
        let id = self.t.len();
        assert!(
            id + k <= NIL as usize,
            "Euler-tour node pool exceeds u32 ids"
        );
        for _ in 0..k {
            self.t.push(node);
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
            self.free_vertex = self.t[x as usize].a;
            self.t[x as usize] = node;
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
            self.free_pair = self.t[p as usize].a;
            self.t[p as usize] = node;
            self.t[p as usize + 1] = node;
            p
        } else {
            self.push_nodes(2, node)
        }
    }

    /// Frees a vertex node that is a single-vertex tree.
    pub(crate) fn free_vertex(&mut self, x: u32) {
        debug_assert!(self.is_singleton(x) && self.is_vertex(x));
        self.t[x as usize].a = self.free_vertex;
        self.free_vertex = x;
    }

    /// Frees an arc pair that [`Pool::cut`] has detached.
    pub(crate) fn free_pair(&mut self, p: u32) {
        debug_assert!(self.is_singleton(p) && self.is_singleton(p + 1));
        self.t[p as usize].a = self.free_pair;
        self.free_pair = p;
    }

    /// Caller word `a` of `x`.
    pub(crate) fn a(&self, x: u32) -> u32 {
        self.t[x as usize].a
    }
    /// Caller word `b` of `x`.
    pub(crate) fn b(&self, x: u32) -> u32 {
        self.t[x as usize].b
    }
    pub(crate) fn set_a(&mut self, x: u32, v: u32) {
        self.t[x as usize].a = v;
    }
    pub(crate) fn set_b(&mut self, x: u32, v: u32) {
        self.t[x as usize].b = v;
    }

    /// Whether `x` is a vertex node.
    pub(crate) fn is_vertex(&self, x: u32) -> bool {
        self.t[x as usize].w & VERTEX != 0
    }

    /// Whether `x` is alone in its tree (no splay parent, no children).
    pub(crate) fn is_singleton(&self, x: u32) -> bool {
        let n = &self.t[x as usize];
        n.par == NIL && n.ch == [NIL; 2]
    }

    /// Whether own flag `f` of `x` is set.
    pub(crate) fn has(&self, x: u32, f: Flag) -> bool {
        self.t[x as usize].w & f.own() != 0
    }

    /// Sets own flag `f` of `x` to `on`, keeping the aggregates of its tree exact.
    pub(crate) fn set_flag(&mut self, x: u32, f: Flag, on: bool) {
        if self.has(x, f) == on {
            return;
        }
        self.splay(x);
        self.t[x as usize].w ^= f.own();
        self.update(x);
    }

    /// Number of vertex nodes in the tree of `x`.
    pub(crate) fn tree_size(&mut self, x: u32) -> u32 {
        self.splay(x);
        self.t[x as usize].w & CNT_MASK
    }

    /// Whether `x` and `y` are in the same tree.
    pub(crate) fn same_tree(&mut self, x: u32, y: u32) -> bool {
        if x == y {
            return true;
        }
        // After splaying y, x (the previous root) has a parent exactly if y's splay
        // tree is x's.
        self.splay(x);
        self.splay(y);
        self.t[x as usize].par != NIL
    }

    /// The first node (in sequence order) of `x`'s tree whose own flag `f` is set, if
    /// any; splayed, which pays for the descent.
    pub(crate) fn first_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.splay(x);
        self.leftmost_flagged(x, f)
    }

    /// The first node after `x` in its tree's sequence whose own flag `f` is set, if any;
    /// splayed.
    pub(crate) fn next_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.splay(x);
        let r = self.t[x as usize].ch[1];
        if r == NIL {
            return None;
        }
        self.extreme_flagged(r, f, 0)
    }

    /// The last node (in sequence order) of `x`'s tree whose own flag `f` is set, if any;
    /// splayed.
    pub(crate) fn last_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.splay(x);
        self.extreme_flagged(x, f, 1)
    }

    /// The last node before `x` in its tree's sequence whose own flag `f` is set, if any;
    /// splayed.
    pub(crate) fn prev_flagged(&mut self, x: u32, f: Flag) -> Option<u32> {
        self.splay(x);
        let l = self.t[x as usize].ch[0];
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
        if self.t[y as usize].w & f.agg() == 0 {
            return None;
        }
        loop {
            let n = self.t[y as usize];
            let near = n.ch[side];
            if near != NIL && self.t[near as usize].w & f.agg() != 0 {
                y = near;
            } else if n.w & f.own() != 0 {
                break;
            } else {
                y = n.ch[side ^ 1];
                debug_assert!(y != NIL, "aggregate flag without a flagged node");
            }
        }
        self.splay(y);
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
        self.splay(y);
        let [l, r] = self.detach(y);
        let c = self.concat(r, l);
        self.attach(y, [p, c]);
        self.splay(x);
        let b = self.t[x as usize].ch[1];
        self.t[x as usize].ch[1] = NIL;
        if b != NIL {
            self.t[b as usize].par = NIL;
        }
        self.attach(q, [y, b]);
        self.attach(x, [self.t[x as usize].ch[0], q]);
    }

    /// Makes the detached nodes `seq` (each a single-node tree, own flags already set)
    /// one tree whose sequence is `seq` in this order, as a balanced splay tree. O(len),
    /// against O(len log len) for the same tree built by [`Pool::link`]s; the caller
    /// makes `seq` a valid Euler tour (`hdt`'s bulk load).
    pub(crate) fn build(&mut self, seq: &[u32]) {
        debug_assert!(seq.iter().all(|&x| self.is_singleton(x)));
        // Midpoints top-down by an explicit stack (no recursion), then the counts and
        // aggregates bottom-up: reverse pre-order has every child before its parent.
        let mut order = Vec::with_capacity(seq.len());
        let mut stack = vec![(0usize, seq.len(), NIL, 0usize)];
        while let Some((lo, hi, par, side)) = stack.pop() {
            if lo >= hi {
                continue;
            }
            let mid = lo + (hi - lo) / 2;
            let x = seq[mid];
            self.t[x as usize].par = par;
            if par != NIL {
                self.t[par as usize].ch[side] = x;
            }
            order.push(x);
            stack.push((lo, mid, x, 0));
            stack.push((mid + 1, hi, x, 1));
        }
        for &x in order.iter().rev() {
            self.update(x);
        }
    }

    /// Makes the splay roots `ch` (or `NIL`) the children of `x` and updates `x`.
    fn attach(&mut self, x: u32, ch: [u32; 2]) {
        for c in ch {
            if c != NIL {
                self.t[c as usize].par = x;
            }
        }
        self.t[x as usize].ch = ch;
        self.update(x);
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
        self.splay(first);
        let [a, rest] = self.detach(first);
        debug_assert!(rest != NIL);
        // `second` lies in `rest`, whose root is now a splay root.
        self.splay(second);
        let [b, c] = self.detach(second);
        debug_assert!(b != NIL, "each side of a tree edge has a vertex");
        self.concat(c, a);
    }

    /// Whether `x` comes before `y` in their (common) sequence.
    fn precedes(&mut self, x: u32, y: u32) -> bool {
        self.splay(y);
        self.splay(x);
        // Splaying x moves the previous root y down by at most two levels (y only takes
        // part in the last zig, zig-zig or zig-zag step), so this walk is O(1).
        let mut c = y;
        loop {
            let p = self.t[c as usize].par;
            debug_assert!(p != NIL, "precedes: different trees");
            if p == x {
                return self.t[x as usize].ch[1] == c;
            }
            c = p;
        }
    }

    /// Detaches both children of the splay root `x` (returned as roots `[left, right]`),
    /// leaving `x` alone.
    fn detach(&mut self, x: u32) -> [u32; 2] {
        debug_assert_eq!(self.t[x as usize].par, NIL);
        let ch = self.t[x as usize].ch;
        for c in ch {
            if c != NIL {
                self.t[c as usize].par = NIL;
            }
        }
        self.t[x as usize].ch = [NIL; 2];
        self.update(x);
        ch
    }

    /// Concatenates the sequences of splay roots `a` and `b` (either may be `NIL`);
    /// returns the new root.
    fn concat(&mut self, a: u32, b: u32) -> u32 {
        if a == NIL {
            return b;
        }
        if b == NIL {
            return a;
        }
        let mut m = a;
        loop {
            let r = self.t[m as usize].ch[1];
            if r == NIL {
                break;
            }
            m = r;
        }
        self.splay(m);
        self.t[m as usize].ch[1] = b;
        self.t[b as usize].par = m;
        self.update(m);
        m
    }

    /// Recomputes the count and the aggregate flags of `x` from its children.
    fn update(&mut self, x: u32) {
        let n = self.t[x as usize];
        let own = n.w & (VERTEX | OWN0 | OWN1);
        let mut w = own | (own >> 31) | ((own & (OWN0 | OWN1)) << 2);
        for c in n.ch {
            if c != NIL {
                let cw = self.t[c as usize].w;
                w += cw & CNT_MASK;
                w |= cw & (AGG0 | AGG1);
            }
        }
        self.t[x as usize].w = w;
    }

    /// One rotation of `x` over its parent; updates the parent (not `x`).
    fn rotate(&mut self, x: u32) {
        let p = self.t[x as usize].par;
        let g = self.t[p as usize].par;
        let dir = usize::from(self.t[p as usize].ch[1] == x);
        let b = self.t[x as usize].ch[dir ^ 1];
        self.t[p as usize].ch[dir] = b;
        if b != NIL {
            self.t[b as usize].par = p;
        }
        self.t[x as usize].ch[dir ^ 1] = p;
        self.t[p as usize].par = x;
        self.t[x as usize].par = g;
        if g != NIL {
            let gi = usize::from(self.t[g as usize].ch[1] == p);
            self.t[g as usize].ch[gi] = x;
        }
        self.update(p);
    }

    /// Splays `x` to the root of its splay tree (bottom-up, no recursion).
    fn splay(&mut self, x: u32) {
        loop {
            let p = self.t[x as usize].par;
            if p == NIL {
                break;
            }
            let g = self.t[p as usize].par;
            if g != NIL {
                let zigzig = (self.t[g as usize].ch[0] == p) == (self.t[p as usize].ch[0] == x);
                self.rotate(if zigzig { p } else { x });
            }
            self.rotate(x);
        }
        self.update(x);
    }

    /// The splay root of `x`'s tree, without restructuring (for checks).
    pub(crate) fn root_of(&self, x: u32) -> u32 {
        let mut r = x;
        while self.t[r as usize].par != NIL {
            r = self.t[r as usize].par;
        }
        r
    }

    /// The in-order sequence of the tree with splay root `r` (for checks), by an explicit
    /// stack; also checks that the stored counts and aggregates are exact.
    pub(crate) fn sequence(&self, r: u32) -> Vec<u32> {
        let mut out = Vec::new();
        let mut stack = Vec::new();
        let mut c = r;
        while c != NIL || !stack.is_empty() {
            while c != NIL {
                stack.push(c);
                c = self.t[c as usize].ch[0];
            }
            let Some(x) = stack.pop() else { break };
            out.push(x);
            c = self.t[x as usize].ch[1];
        }
        out
    }

    /// Every node's caller words and own bits (for tests comparing two pools).
    #[cfg(test)]
    pub(crate) fn words(&self) -> impl Iterator<Item = (u32, u32, u32)> + '_ {
        self.t
            .iter()
            .map(|n| (n.a, n.b, n.w & (VERTEX | OWN0 | OWN1)))
    }

    /// Whether the stored count and aggregate flags of `x` are those recomputed from its
    /// children (for checks).
    pub(crate) fn node_consistent(&self, x: u32) -> bool {
        let n = self.t[x as usize];
        let own = n.w & (VERTEX | OWN0 | OWN1);
        let mut w = own | (own >> 31) | ((own & (OWN0 | OWN1)) << 2);
        for c in n.ch {
            if c != NIL {
                if self.t[c as usize].par != x {
                    return false;
                }
                let cw = self.t[c as usize].w;
                w += cw & CNT_MASK;
                w |= cw & (AGG0 | AGG1);
            }
        }
        w == n.w
    }
}

#[cfg(test)]
mod tests {
    /// The node size the documentation states.
    #[test]
    fn node_size() {
        assert_eq!(std::mem::size_of::<super::Node>(), 24);
    }
}
