//! The splay-tree core shared by the Euler-tour trees (module `ett`) and the link–cut
//! trees (module `lct`): splay trees (Sleator–Tarjan 1985) over nodes in one flat array
//! with `u32` indices, generic over the node type, which brings its own aggregate
//! ([`SplayNode::pull`]) and lazy tags ([`SplayNode::push`]).
//!
//! # Guarantees
//! Every operation keeps the in-order sequence of each splay tree as stated (rotations
//! never change it) and, if the node type's `pull` and `push` are exact, every node's
//! aggregate exact for its subtree up to the tags still pending at its ancestors. The owner
//! decides what the sequence means: an Euler tour (`ett`), a preferred path (`lct`).
//!
//! Two node-type constants select, at compile time, what each owner needs and nothing
//! more: [`SplayNode::PATH_PARENTS`] (a splay root's parent pointer may be a link–cut
//! tree's path-parent, so being a root is "not a child of one's parent" instead of "no
//! parent") and [`SplayNode::LAZY`] (tags to push down before a node's children move).
//! A splay recomputes the aggregate of each rotated-over node and, once at the end, of
//! the splayed node (no rotation reads it). The rotation works on a slice and is inlined
//! into the splay loop: `docs/benchmarks.md` (dynamic graph structures) has the
//! instruction counts against the two implementations this core replaced.
//!
//! # Complexity
//! O(log n) amortised per splay, and so per operation below but `build`, O(len), and
//! `in_order`, O(size) (access lemma; with `LAZY`, the push-downs along the splayed path
//! cost as much as the path). No recursion: push-downs use an explicit stack.

use std::ops::{Index, IndexMut};

/// No node.
pub(super) const NIL: u32 = u32::MAX;

/// A node of a splay forest: its two children and its parent (`NIL` for none), its own
/// aggregate over its subtree and its pending tags.
pub(super) trait SplayNode: Copy {
    /// Whether a splay root's parent pointer may be a path-parent (link–cut trees): a
    /// node is then a splay root iff its parent does not list it as a child. Otherwise a
    /// splay root's parent is `NIL`.
    const PATH_PARENTS: bool;
    /// Whether [`SplayNode::push`] may do anything: then a splay first pushes the tags
    /// down from the splay root to the node, and a descent pushes each node it passes.
    const LAZY: bool;
    /// The children, left then right (`NIL` for none).
    fn ch(&self) -> [u32; 2];
    /// The children, for writing.
    fn ch_mut(&mut self) -> &mut [u32; 2];
    /// The splay parent or path-parent (`NIL` for none).
    fn par(&self) -> u32;
    /// The parent, for writing.
    fn par_mut(&mut self) -> &mut u32;
    /// Applies `t[x]`'s pending tags to its children (already applied to `x` itself).
    fn push(t: &mut [Self], x: u32);
    /// Recomputes `t[x]`'s aggregate from its own value and its children's aggregates.
    fn pull(t: &mut [Self], x: u32);
}

/// A forest of splay trees over the nodes `t` (indexed by `u32` id; the owner allocates
/// them and reads and writes their own fields directly, through `Index` too).
#[derive(Clone, Debug)]
pub(super) struct Splay<N> {
    /// The nodes.
    pub(super) t: Vec<N>,
    /// Scratch of the push-downs, empty between operations (an owner may borrow it).
    pub(super) stack: Vec<u32>,
}

impl<N> Default for Splay<N> {
    fn default() -> Self {
        Splay {
            t: Vec::new(),
            stack: Vec::new(),
        }
    }
}

impl<N> Index<u32> for Splay<N> {
    type Output = N;
    #[inline]
    fn index(&self, x: u32) -> &N {
        &self.t[x as usize]
    }
}

impl<N> IndexMut<u32> for Splay<N> {
    #[inline]
    fn index_mut(&mut self, x: u32) -> &mut N {
        &mut self.t[x as usize]
    }
}

/// Whether `x` is the root of its splay tree.
#[inline]
fn is_root<N: SplayNode>(t: &[N], x: u32) -> bool {
    let p = t[x as usize].par();
    p == NIL || (N::PATH_PARENTS && !t[p as usize].ch().contains(&x))
}

/// One rotation of `x` over its splay parent `p` (whose aggregate is recomputed; `x`'s
/// is left to the caller). `x` takes over `p`'s parent pointer, a path-parent included.
#[inline(always)]
fn rotate<N: SplayNode>(t: &mut [N], x: u32) {
    let p = t[x as usize].par();
    let g = t[p as usize].par();
    // Read before anything moves: with path-parents it looks at `g`'s children.
    let p_was_root = is_root(t, p);
    let dir = usize::from(t[p as usize].ch()[1] == x);
    let b = t[x as usize].ch()[dir ^ 1];
    t[p as usize].ch_mut()[dir] = b;
    if b != NIL {
        *t[b as usize].par_mut() = p;
    }
    t[x as usize].ch_mut()[dir ^ 1] = p;
    *t[p as usize].par_mut() = x;
    *t[x as usize].par_mut() = g;
    if !p_was_root {
        let gc = t[g as usize].ch_mut();
        let side = usize::from(gc[1] == p);
        gc[side] = x;
    }
    N::pull(t, p);
}

impl<N: SplayNode> Splay<N> {
    /// The forest of the nodes `t`, as they are linked.
    pub(super) fn from_nodes(t: Vec<N>) -> Self {
        Splay {
            t,
            stack: Vec::new(),
        }
    }

    /// Whether `x` is the root of its splay tree.
    #[inline]
    pub(super) fn is_root(&self, x: u32) -> bool {
        is_root(&self.t, x)
    }

    /// Recomputes `x`'s aggregate ([`SplayNode::pull`]).
    #[inline]
    pub(super) fn pull(&mut self, x: u32) {
        N::pull(&mut self.t, x);
    }

    /// Applies `x`'s pending tags to its children ([`SplayNode::push`]).
    #[inline]
    pub(super) fn push(&mut self, x: u32) {
        N::push(&mut self.t, x);
    }

    /// Splays `x` to the root of its splay tree (bottom-up: zig-zig and zig-zag steps),
    /// pushing the pending tags down from that root first when the node type has any;
    /// `x`'s aggregate is exact afterwards.
    pub(super) fn splay(&mut self, x: u32) {
        // On a slice, whose length the compiler keeps in a register through the
        // stores (through the vector it would reload it after each).
        let t = self.t.as_mut_slice();
        if N::LAZY {
            let stack = &mut self.stack;
            stack.clear();
            let mut y = x;
            stack.push(y);
            while !is_root(t, y) {
                y = t[y as usize].par();
                stack.push(y);
            }
            while let Some(z) = stack.pop() {
                N::push(t, z);
            }
        }
        while !is_root(t, x) {
            let p = t[x as usize].par();
            if !is_root(t, p) {
                let g = t[p as usize].par();
                let zigzig = (t[g as usize].ch()[0] == p) == (t[p as usize].ch()[0] == x);
                rotate(t, if zigzig { p } else { x });
            }
            rotate(t, x);
        }
        N::pull(t, x);
    }

    /// The first (`side` 0) or last (`side` 1) node of the sequence of the splay tree
    /// rooted at `r`, splayed to its root (tags pushed on the way down).
    pub(super) fn extreme(&mut self, r: u32, side: usize) -> u32 {
        let mut y = r;
        loop {
            if N::LAZY {
                self.push(y);
            }
            let c = self[y].ch()[side];
            if c == NIL {
                break;
            }
            y = c;
        }
        self.splay(y);
        y
    }

    /// Takes both children off the splay root `x` (returned as splay roots, left then
    /// right, `NIL` for none), leaving `x` a single node: the sequence `A x B` becomes
    /// `A`, `x`, `B`.
    pub(super) fn detach(&mut self, x: u32) -> [u32; 2] {
        debug_assert!(self.is_root(x), "detach of a non-root");
        if N::LAZY {
            self.push(x);
        }
        let ch = self[x].ch();
        for c in ch {
            if c != NIL {
                *self[c].par_mut() = NIL;
            }
        }
        *self[x].ch_mut() = [NIL; 2];
        self.pull(x);
        ch
    }

    /// Makes the splay roots `ch` (or `NIL`) the children of `x` in place of its own (for
    /// a single node `x`: the sequences `A`, `x`, `B` become `A x B`, with root `x`).
    pub(super) fn attach(&mut self, x: u32, ch: [u32; 2]) {
        for c in ch {
            if c != NIL {
                *self[c].par_mut() = x;
            }
        }
        *self[x].ch_mut() = ch;
        self.pull(x);
    }

    /// Concatenates the sequences of the splay roots `a` and `b` (either may be `NIL`);
    /// returns the root of the result.
    pub(super) fn concat(&mut self, a: u32, b: u32) -> u32 {
        if a == NIL {
            return b;
        }
        if b == NIL {
            return a;
        }
        let m = self.extreme(a, 1);
        self[m].ch_mut()[1] = b;
        *self[b].par_mut() = m;
        self.pull(m);
        m
    }

    /// Makes the single nodes `seq` one splay tree whose sequence is `seq` in this order,
    /// balanced (depth ⌈log₂(len + 1)⌉); no tags. O(len).
    pub(super) fn build(&mut self, seq: &[u32]) {
        debug_assert!(seq
            .iter()
            .all(|&x| self[x].par() == NIL && self[x].ch() == [NIL; 2]));
        // Midpoints top-down by an explicit stack (no recursion), then the aggregates
        // bottom-up: reverse pre-order has every child before its parent.
        let mut order = Vec::with_capacity(seq.len());
        let mut stack = vec![(0usize, seq.len(), NIL, 0usize)];
        while let Some((lo, hi, par, side)) = stack.pop() {
            if lo >= hi {
                continue;
            }
            let mid = lo + (hi - lo) / 2;
            let x = seq[mid];
            *self[x].par_mut() = par;
            if par != NIL {
                self[par].ch_mut()[side] = x;
            }
            order.push(x);
            stack.push((lo, mid, x, 0));
            stack.push((mid + 1, hi, x, 1));
        }
        for &x in order.iter().rev() {
            self.pull(x);
        }
    }

    /// The splay root of `x`'s tree, without restructuring (for checks).
    pub(super) fn root_of(&self, x: u32) -> u32 {
        let mut r = x;
        while !self.is_root(r) {
            r = self[r].par();
        }
        r
    }

    /// The in-order sequence of the splay tree rooted at `r` (for checks; pending tags
    /// are not applied, so with `LAZY` it is the sequence only without pending
    /// reversals), by an explicit stack.
    pub(super) fn in_order(&self, r: u32) -> Vec<u32> {
        let mut out = Vec::new();
        let mut stack = Vec::new();
        let mut c = r;
        while c != NIL || !stack.is_empty() {
            while c != NIL {
                stack.push(c);
                c = self[c].ch()[0];
            }
            let Some(x) = stack.pop() else { break };
            out.push(x);
            c = self[x].ch()[1];
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::{Splay, SplayNode, NIL};

    /// A test node: subtree size and a lazy reversal, under either root convention.
    #[derive(Clone, Copy, Debug)]
    struct Node<const PP: bool> {
        ch: [u32; 2],
        par: u32,
        size: u32,
        rev: bool,
    }

    impl<const PP: bool> SplayNode for Node<PP> {
        const PATH_PARENTS: bool = PP;
        const LAZY: bool = true;
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
        fn push(t: &mut [Self], x: u32) {
            let n = &mut t[x as usize];
            if n.rev {
                n.rev = false;
                for c in n.ch {
                    if c != NIL {
                        let m = &mut t[c as usize];
                        m.ch.swap(0, 1);
                        m.rev ^= true;
                    }
                }
            }
        }
        fn pull(t: &mut [Self], x: u32) {
            let [a, b] = t[x as usize].ch;
            let size = |c: u32| if c == NIL { 0 } else { t[c as usize].size };
            t[x as usize].size = 1 + size(a) + size(b);
        }
    }

    fn single<const PP: bool>() -> Node<PP> {
        Node {
            ch: [NIL; 2],
            par: NIL,
            size: 1,
            rev: false,
        }
    }

    /// The node at position `k` of the sequence of root `r`, splayed.
    fn select<const PP: bool>(s: &mut Splay<Node<PP>>, r: u32, mut k: u32) -> u32 {
        let mut y = r;
        loop {
            s.push(y);
            let l = s[y].ch[0];
            let ls = if l == NIL { 0 } else { s[l].size };
            if k < ls {
                y = l;
            } else if k == ls {
                break;
            } else {
                k -= ls + 1;
                y = s[y].ch[1];
            }
        }
        s.splay(y);
        y
    }

    /// The sequence of root `r` with every pending reversal applied.
    fn sequence<const PP: bool>(s: &mut Splay<Node<PP>>, r: u32) -> Vec<u32> {
        let mut todo = vec![r];
        while let Some(x) = todo.pop() {
            s.push(x);
            todo.extend(s[x].ch.into_iter().filter(|&c| c != NIL));
        }
        s.in_order(r)
    }

    /// Random splits (at a selected node), concatenations, whole-sequence reversals and
    /// extreme-node queries on a few sequences, against `Vec`s; sizes and the parent
    /// links checked throughout.
    fn random_sequences<const PP: bool>() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = |k: usize| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % k as u64) as usize
        };
        let n = 60u32;
        let mut s = Splay::from_nodes(vec![single::<PP>(); n as usize]);
        // Four sequences, built balanced.
        let mut model: Vec<Vec<u32>> = (0..4)
            .map(|i| (0..n).filter(|x| x % 4 == i).collect())
            .collect();
        let mut roots: Vec<u32> = model
            .iter()
            .map(|seq| {
                s.build(seq);
                s.root_of(seq[0])
            })
            .collect();
        for step in 0..4000 {
            let i = next(model.len());
            match next(4) {
                0 if model[i].len() > 1 => {
                    // Split sequence i before position k (k ≥ 1).
                    let k = 1 + next(model[i].len() - 1);
                    let x = select(&mut s, roots[i], k as u32);
                    let [l, r] = s.detach(x);
                    s.attach(x, [NIL, r]);
                    roots[i] = l;
                    roots.push(x);
                    let tail = model[i].split_off(k);
                    model.push(tail);
                }
                1 if model.len() > 1 => {
                    let mut j = next(model.len() - 1);
                    if j >= i {
                        j += 1;
                    }
                    roots[i] = s.concat(roots[i], roots[j]);
                    let tail = model.remove(j);
                    model[if j < i { i - 1 } else { i }].extend(tail);
                    roots.remove(j);
                }
                2 => {
                    let r = roots[i];
                    s[r].ch.swap(0, 1);
                    s[r].rev ^= true;
                    model[i].reverse();
                }
                _ => {
                    let side = next(2);
                    let want = if side == 0 {
                        model[i][0]
                    } else {
                        model[i][model[i].len() - 1]
                    };
                    roots[i] = s.extreme(roots[i], side);
                    assert_eq!(roots[i], want, "step {step}");
                }
            }
            for (seq, &r) in model.iter().zip(&roots) {
                assert!(s.is_root(r));
                assert_eq!(s[r].size as usize, seq.len(), "step {step}");
                assert_eq!(&sequence(&mut s, r), seq, "step {step}");
                for &x in seq {
                    assert_eq!(s.root_of(x), r, "step {step}");
                }
            }
        }
    }

    #[test]
    fn sequence_operations_agree_with_vectors() {
        random_sequences::<false>();
        random_sequences::<true>();
    }
}
