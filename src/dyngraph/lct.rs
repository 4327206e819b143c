//! A link–cut tree (Sleator–Tarjan 1983, splay-based) on flat arrays with `u32` indices:
//! a forest of rooted-at-will trees supporting link, cut, re-rooting, and on the path
//! between two nodes "add `d` to every value" and "minimum value"; and [`PlainLct`], the
//! same without values (link, cut, re-rooting, LCAs), for the Diks–Stańczyk strategy.
//!
//! # Guarantees
//! Every operation keeps the represented forest and the node values exactly as a naive
//! forest would (tested against one in the unit tests below, exhaustively on random
//! operation sequences). [`Lct::link`] and [`Lct::cut`] assume their preconditions (the
//! nodes in different trees; an existing edge) and check them with `debug_assert!`.
//!
//! # Complexity
//! O(log n) amortised per operation (splay trees with the access lemma, on the shared
//! core of module `splay`, with path-parents and lazy tags); memory 28 bytes per node (25
//! bytes of fields, padded to 4-byte alignment; 16 for [`PlainLct`]). No recursion:
//! push-downs along a splay path use an explicit stack.

use super::splay::{Splay, SplayNode, NIL};

/// One node: splay children, splay parent or path-parent (told apart by
/// [`Splay::is_root`]), its value, the minimum over its splay subtree (its part of the
/// preferred path), and the pending addition / reversal of that subtree (already applied
/// to this node). Packed in one record so that a node costs one cache line.
#[derive(Clone, Copy, Debug)]
struct Node {
    ch: [u32; 2],
    par: u32,
    val: i32,
    min: i32,
    add: i32,
    rev: bool,
}

/// A node of a link–cut forest: a splay node ([`SplayNode`], with path-parents and lazy
/// tags) whose subtree can be reversed. The link–cut operations below (access,
/// re-rooting, link, cut) are shared by [`Lct`] and [`PlainLct`] and monomorphised for
/// each.
trait LinkCutNode: SplayNode {
    /// Swaps the children and toggles the pending reversal of the subtree.
    fn reverse(&mut self);
}

/// Reverses the subtree of `x` (none for `NIL`).
#[inline]
fn apply_rev<N: LinkCutNode>(t: &mut [N], x: u32) {
    if x != NIL {
        t[x as usize].reverse();
    }
}

/// Makes the root-to-`x` path preferred; afterwards `x` is the root of its splay tree,
/// which holds exactly that path. Returns the last node at which the walk joined the
/// previously preferred root path (the LCA of a walk's step).
fn access<N: LinkCutNode>(s: &mut Splay<N>, x: u32) -> u32 {
    let mut last = NIL;
    let mut y = x;
    while y != NIL {
        s.splay(y);
        s[y].ch_mut()[1] = last;
        s.pull(y);
        last = y;
        y = s[y].par();
    }
    s.splay(x);
    last
}

/// Makes `x` the root of its tree.
fn make_root<N: LinkCutNode>(s: &mut Splay<N>, x: u32) {
    access(s, x);
    apply_rev(&mut s.t, x);
}

/// Adds the edge `x`–`y` (`x` made its tree's root, then hung below `y`); they must be
/// in different trees.
fn link<N: LinkCutNode>(s: &mut Splay<N>, x: u32, y: u32) {
    make_root(s, x);
    *s[x].par_mut() = y;
}

/// Removes the edge `x`–`y`, which must exist; `y`'s aggregate is left for the caller
/// to recompute ([`SplayNode::pull`]).
fn cut<N: LinkCutNode>(s: &mut Splay<N>, x: u32, y: u32) {
    make_root(s, x);
    access(s, y);
    debug_assert!(
        s[y].ch()[0] == x && s[x].ch()[1] == NIL,
        "cut of a non-edge"
    );
    s[y].ch_mut()[0] = NIL;
    *s[x].par_mut() = NIL;
}

/// The [`SplayNode`] constants and accessors of a link–cut node type over its `ch` and
/// `par` fields (both node types name them alike).
macro_rules! splay_fields {
    () => {
        const PATH_PARENTS: bool = true;
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
    };
}

impl SplayNode for Node {
    splay_fields!();

    /// Pushes `x`'s pending addition and reversal down to its children.
    fn push(t: &mut [Node], x: u32) {
        let n = &mut t[x as usize];
        let [a, b] = n.ch;
        let (d, r) = (n.add, n.rev);
        n.add = 0;
        n.rev = false;
        if d != 0 {
            apply_add(t, a, d);
            apply_add(t, b, d);
        }
        if r {
            apply_rev(t, a);
            apply_rev(t, b);
        }
    }

    /// `x`'s minimum from its value and its children's minima.
    fn pull(t: &mut [Node], x: u32) {
        let [a, b] = t[x as usize].ch;
        let mut m = t[x as usize].val;
        if a != NIL {
            m = m.min(t[a as usize].min);
        }
        if b != NIL {
            m = m.min(t[b as usize].min);
        }
        t[x as usize].min = m;
    }
}

impl LinkCutNode for Node {
    fn reverse(&mut self) {
        self.ch.swap(0, 1);
        self.rev ^= true;
    }
}

/// Adds `d` to the values of the subtree of `x` (none for `NIL`): to `x`'s value and
/// minimum now, to its descendants' when pushed.
#[inline]
fn apply_add(t: &mut [Node], x: u32, d: i32) {
    if x != NIL {
        let n = &mut t[x as usize];
        n.val += d;
        n.min += d;
        n.add += d;
    }
}

/// Bytes of one [`Lct`] node as allocated (its fields take 25; alignment pads it to 28).
pub(crate) const NODE_BYTES: usize = std::mem::size_of::<Node>();

impl Node {
    fn single(v: i32, par: u32) -> Node {
        Node {
            ch: [NIL; 2],
            par,
            val: v,
            min: v,
            add: 0,
            rev: false,
        }
    }
}

/// Link–cut forest over nodes `0..n` with an `i32` value per node.
#[derive(Clone, Debug, Default)]
pub struct Lct {
    s: Splay<Node>,
}

impl Lct {
    /// `n` single-node trees, node `i` with value `vals[i]`.
    pub fn new(vals: &[i32]) -> Self {
        Lct {
            s: Splay::from_nodes(vals.iter().map(|&v| Node::single(v, NIL)).collect()),
        }
    }

    /// The forest whose tree edges are `x`–`parent[x]` (`u32::MAX`: a root), node `i`
    /// with value `vals[i]`; `parent` must describe a forest. O(n): every node starts as
    /// its own preferred path, with its tree parent as path-parent.
    pub fn with_parents(vals: &[i32], parent: &[u32]) -> Self {
        debug_assert_eq!(parent.len(), vals.len());
        Lct {
            s: Splay::from_nodes(
                vals.iter()
                    .zip(parent)
                    .map(|(&v, &p)| Node::single(v, p))
                    .collect(),
            ),
        }
    }

    /// The value of `x` once it is cut off (a single-node tree).
    pub fn isolated_value(&self, x: u32) -> i32 {
        self.s[x].val
    }

    fn apply_add(&mut self, x: u32, d: i32) {
        apply_add(&mut self.s.t, x, d);
    }

    /// Makes the root-to-`x` path preferred; afterwards `x` is the root of its splay
    /// tree, which holds exactly that path. Returns the last node at which the walk
    /// joined the previously preferred root path (the LCA of a walk's step).
    fn access(&mut self, x: u32) -> u32 {
        access(&mut self.s, x)
    }

    /// The lowest common ancestor of `x` and `y` for the current root of their tree (set
    /// by [`Lct::make_root`]); they must be connected. O(log n) amortised: after
    /// `access(x)` the root–`x` path is one preferred path, and the last node at which
    /// `access(y)` joins it is where the root–`y` path leaves the root–`x` path.
    #[cfg(test)]
    fn lca(&mut self, x: u32, y: u32) -> u32 {
        debug_assert!(self.connected(x, y), "lca of two trees");
        self.access(x);
        self.access(y)
    }

    /// Makes the root–`x` path preferred and returns the LCA of `x` and the node last
    /// passed to `walk_to` (same tree, same root since; after a `make_root` or any other
    /// operation the result means nothing, as the root's preferred path is then not a
    /// root–node path). O(log n)
    /// amortised: one access, where an LCA query from scratch takes two, so the pairwise
    /// LCAs along a walk over several nodes cost one access each. (Used in the tests;
    /// DS walks a [`PlainLct`].)
    #[cfg(test)]
    fn walk_to(&mut self, x: u32) -> u32 {
        self.access(x)
    }

    /// Makes `x` the root of its tree.
    pub fn make_root(&mut self, x: u32) {
        make_root(&mut self.s, x);
    }

    /// The root of `x`'s tree (its current root: re-rooting moves it). O(log n)
    /// amortised.
    pub fn find_root(&mut self, x: u32) -> u32 {
        self.access(x);
        self.s.extreme(x, 0)
    }

    /// Whether `x` and `y` are in the same tree.
    pub fn connected(&mut self, x: u32, y: u32) -> bool {
        x == y || self.find_root(x) == self.find_root(y)
    }

    /// Adds the edge `x`–`y`; they must be in different trees.
    pub fn link(&mut self, x: u32, y: u32) {
        debug_assert!(!self.connected(x, y), "link inside one tree");
        link(&mut self.s, x, y);
    }

    /// Removes the edge `x`–`y`, which must exist.
    pub fn cut(&mut self, x: u32, y: u32) {
        cut(&mut self.s, x, y);
        self.s.pull(y);
        // Leave x's own value exact (its subtree tags are pushed on the next splay).
        self.s.push(x);
    }

    /// Replaces the tree path `y`…`z` (`y ≠ z`, not adjacent) by `y`–`k`–`z`: every node
    /// strictly between them becomes a single-node tree (keeping its value) and `k`, a
    /// single-node tree before, gets the value of `copy_from`, one of those interior
    /// nodes. The interior nodes must have no tree neighbours off the path (they would
    /// be cut off with it). O(log n) amortised plus the path length.
    pub fn replace_path(&mut self, y: u32, z: u32, k: u32, copy_from: u32) {
        self.make_root(y);
        self.access(z);
        // z's splay tree now holds exactly the path y…z, and y is the tree root, so the
        // splay root z has no path-parent. Push every tag down, collect the interior.
        let mut todo = std::mem::take(&mut self.s.stack);
        let mut interior: Vec<u32> = Vec::new();
        todo.clear();
        todo.push(z);
        while let Some(a) = todo.pop() {
            self.s.push(a);
            for c in self.s[a].ch {
                if c != NIL {
                    todo.push(c);
                }
            }
            if a != y && a != z {
                interior.push(a);
            }
        }
        self.s.stack = todo;
        debug_assert!(
            interior.contains(&copy_from),
            "copy_from not inside the path"
        );
        let v = self.s[copy_from].val;
        for a in interior {
            let val = self.s[a].val;
            self.s[a] = Node::single(val, NIL);
        }
        debug_assert!(self.s[k].par == NIL && self.s[k].ch == [NIL; 2]);
        for end in [y, z] {
            let n = &mut self.s[end];
            n.ch = [NIL; 2];
            n.par = k;
            n.min = n.val;
        }
        self.s[k] = Node {
            ch: [y, z],
            ..Node::single(v, NIL)
        };
        self.s.pull(k);
    }

    /// Exposes the `x`–`y` path as one splay tree rooted at `y`; they must be connected.
    fn expose(&mut self, x: u32, y: u32) {
        self.make_root(x);
        self.access(y);
    }

    /// Adds `d` to the value of every node on the `x`–`y` path (both included).
    pub fn path_add(&mut self, x: u32, y: u32, d: i32) {
        self.expose(x, y);
        self.apply_add(y, d);
    }

    /// Minimum value on the `x`–`y` path (both included).
    pub fn path_min(&mut self, x: u32, y: u32) -> i32 {
        self.expose(x, y);
        self.s[y].min
    }
}

/// One node of [`PlainLct`]: splay children, splay parent or path-parent, and the
/// pending reversal of its subtree (already applied to this node). 16 bytes.
#[derive(Clone, Copy, Debug)]
struct PlainNode {
    ch: [u32; 2],
    par: u32,
    rev: bool,
}

impl SplayNode for PlainNode {
    splay_fields!();

    /// Pushes `x`'s pending reversal down to its children.
    fn push(t: &mut [PlainNode], x: u32) {
        let n = &mut t[x as usize];
        if n.rev {
            n.rev = false;
            let [a, b] = n.ch;
            apply_rev(t, a);
            apply_rev(t, b);
        }
    }

    /// No aggregate to keep.
    fn pull(_: &mut [PlainNode], _: u32) {}
}

impl LinkCutNode for PlainNode {
    fn reverse(&mut self) {
        self.ch.swap(0, 1);
        self.rev ^= true;
    }
}

/// A link–cut forest without node values: link, cut, re-rooting and the LCAs of a walk
/// ([`PlainLct::walk_to`]), which is all the Diks–Stańczyk strategy asks. Same
/// guarantees and O(log n) amortised bounds as [`Lct`], in 16-byte nodes with no
/// aggregate to keep up (tested against the same naive forest); in DS it replaced
/// [`Lct`], whose values DS never read.
#[derive(Clone, Debug, Default)]
pub struct PlainLct {
    s: Splay<PlainNode>,
}

impl PlainLct {
    /// The forest whose tree edges are `x`–`parent[x]` (`u32::MAX`: a root); `parent`
    /// must describe a forest. O(n): every node starts as its own preferred path.
    pub fn with_parents(parent: &[u32]) -> Self {
        PlainLct {
            s: Splay::from_nodes(
                parent
                    .iter()
                    .map(|&p| PlainNode {
                        ch: [NIL; 2],
                        par: p,
                        rev: false,
                    })
                    .collect(),
            ),
        }
    }

    /// As [`Lct`]'s access: the root–`x` path preferred, `x` its splay root; returns
    /// the node at which the walk joined the previously preferred root path.
    fn access(&mut self, x: u32) -> u32 {
        access(&mut self.s, x)
    }

    /// The LCA of `x` and the node last passed to `walk_to` (same
    /// tree, same root since; meaningless after any other operation). O(log n)
    /// amortised.
    pub fn walk_to(&mut self, x: u32) -> u32 {
        self.access(x)
    }

    /// Makes `x` the root of its tree.
    pub fn make_root(&mut self, x: u32) {
        make_root(&mut self.s, x);
    }

    /// Adds the edge `x`–`y`; they must be in different trees.
    pub fn link(&mut self, x: u32, y: u32) {
        link(&mut self.s, x, y);
    }

    /// Removes the edge `x`–`y`, which must exist.
    pub fn cut(&mut self, x: u32, y: u32) {
        cut(&mut self.s, x, y);
    }
}

#[cfg(test)]
mod tests {
    use super::Lct;

    /// The node sizes the documentation states.
    #[test]
    fn node_sizes() {
        assert_eq!(std::mem::size_of::<super::Node>(), 28);
        assert_eq!(std::mem::size_of::<super::PlainNode>(), 16);
    }

    /// The naive forest: adjacency sets and values; path by BFS.
    struct Naive {
        adj: Vec<Vec<u32>>,
        val: Vec<i32>,
    }

    impl Naive {
        fn link(&mut self, x: u32, y: u32) {
            self.adj[x as usize].push(y);
            self.adj[y as usize].push(x);
        }

        fn cut(&mut self, a: u32, b: u32) {
            self.adj[a as usize].retain(|&c| c != b);
            self.adj[b as usize].retain(|&c| c != a);
        }

        fn path(&self, x: u32, y: u32) -> Option<Vec<u32>> {
            let n = self.adj.len();
            let mut prev = vec![u32::MAX; n];
            let mut seen = vec![false; n];
            let mut queue = std::collections::VecDeque::from([x]);
            seen[x as usize] = true;
            while let Some(a) = queue.pop_front() {
                for &b in &self.adj[a as usize] {
                    if !seen[b as usize] {
                        seen[b as usize] = true;
                        prev[b as usize] = a;
                        queue.push_back(b);
                    }
                }
            }
            if !seen[y as usize] {
                return None;
            }
            let mut p = vec![y];
            let mut c = y;
            while c != x {
                c = prev[c as usize];
                p.push(c);
            }
            Some(p)
        }
    }

    /// A small deterministic generator (xorshift), so the test needs no dependency.
    fn next(s: &mut u64) -> u64 {
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        *s
    }

    #[test]
    fn agrees_with_a_naive_forest_on_random_operations() {
        let mut replaced = 0;
        for seed in 1..=60u64 {
            let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
            let n = 2 + (next(&mut s) % 14) as usize;
            let vals: Vec<i32> = (0..n).map(|_| (next(&mut s) % 20) as i32).collect();
            let mut lct = Lct::new(&vals);
            let mut naive = Naive {
                adj: vec![Vec::new(); n],
                val: vals,
            };
            let mut edges: Vec<(u32, u32)> = Vec::new();
            for _ in 0..400 {
                let x = (next(&mut s) % n as u64) as u32;
                let y = (next(&mut s) % n as u64) as u32;
                let path = naive.path(x, y);
                assert_eq!(lct.connected(x, y), path.is_some(), "seed {seed}");
                match next(&mut s) % 6 {
                    0 if path.is_none() => {
                        lct.link(x, y);
                        naive.link(x, y);
                        edges.push((x, y));
                    }
                    1 if !edges.is_empty() => {
                        let k = (next(&mut s) % edges.len() as u64) as usize;
                        let (a, b) = edges.swap_remove(k);
                        if next(&mut s) % 2 == 0 {
                            lct.cut(a, b);
                        } else {
                            lct.cut(b, a);
                        }
                        naive.cut(a, b);
                    }
                    3 if path.as_ref().is_some_and(|p| {
                        p.len() >= 3
                            && p[1..p.len() - 1]
                                .iter()
                                .all(|&c| naive.adj[c as usize].len() == 2)
                    }) =>
                    {
                        // Replace the chain x…y by x–k–y, k an isolated node.
                        let p = path.as_ref().expect("checked");
                        let Some(k) = (0..n as u32).find(|&k| naive.adj[k as usize].is_empty())
                        else {
                            continue;
                        };
                        let from = p[1 + (next(&mut s) as usize) % (p.len() - 2)];
                        lct.replace_path(x, y, k, from);
                        replaced += 1;
                        let v = naive.val[from as usize];
                        for w in p.windows(2) {
                            let (a, b) = (w[0], w[1]);
                            naive.cut(a, b);
                            edges.retain(|&e| e != (a, b) && e != (b, a));
                        }
                        naive.val[k as usize] = v;
                        for (a, b) in [(x, k), (k, y)] {
                            naive.adj[a as usize].push(b);
                            naive.adj[b as usize].push(a);
                            edges.push((a, b));
                        }
                    }
                    2 if path.is_some() => {
                        let d = (next(&mut s) % 7) as i32 - 3;
                        lct.path_add(x, y, d);
                        for &c in path.as_ref().into_iter().flatten() {
                            naive.val[c as usize] += d;
                        }
                    }
                    _ => {
                        if let Some(p) = &path {
                            let m = p.iter().map(|&c| naive.val[c as usize]).min();
                            assert_eq!(Some(lct.path_min(x, y)), m, "seed {seed}");
                        }
                    }
                }
            }
            // Every node's own value, read as the minimum of its one-node path.
            for x in 0..n as u32 {
                assert_eq!(lct.path_min(x, x), naive.val[x as usize], "seed {seed}");
            }
        }
        assert!(replaced > 50, "replace_path exercised {replaced} times");
    }

    /// `lca` (and `walk_to`) after `make_root` is the last common node of the naive root–`x` and
    /// root–`y` paths, on random forests changed by links and cuts between queries.
    #[test]
    fn lca_agrees_with_naive_paths() {
        let mut queries = 0;
        for seed in 1..=80u64 {
            let mut s = seed.wrapping_mul(0x2545_F491_4F6C_DD1D) | 1;
            let n = 2 + (next(&mut s) % 20) as usize;
            let mut lct = Lct::new(&vec![0; n]);
            let mut naive = Naive {
                adj: vec![Vec::new(); n],
                val: vec![0; n],
            };
            let mut edges: Vec<(u32, u32)> = Vec::new();
            for _ in 0..300 {
                let x = (next(&mut s) % n as u64) as u32;
                let y = (next(&mut s) % n as u64) as u32;
                let r = (next(&mut s) % n as u64) as u32;
                match next(&mut s) % 4 {
                    0 if naive.path(x, y).is_none() => {
                        lct.link(x, y);
                        naive.link(x, y);
                        edges.push((x, y));
                    }
                    1 if !edges.is_empty() => {
                        let k = (next(&mut s) % edges.len() as u64) as usize;
                        let (a, b) = edges.swap_remove(k);
                        lct.cut(a, b);
                        naive.cut(a, b);
                    }
                    _ => {
                        let (Some(px), Some(py)) = (naive.path(r, x), naive.path(r, y)) else {
                            continue;
                        };
                        // Paths come back target-first: reverse to root-first.
                        let (px, py): (Vec<u32>, Vec<u32>) = (
                            px.into_iter().rev().collect(),
                            py.into_iter().rev().collect(),
                        );
                        let common = px.iter().zip(&py).take_while(|(a, b)| a == b).count();
                        lct.make_root(r);
                        // Half by `lca`, half by a walk x, y, r: each `walk_to` answers
                        // the LCA with the node before (x, then y).
                        let got = if queries % 2 == 0 {
                            lct.lca(x, y)
                        } else {
                            lct.walk_to(x);
                            let got = lct.walk_to(y);
                            assert_eq!(lct.walk_to(r), r, "seed {seed}");
                            got
                        };
                        assert_eq!(got, px[common - 1], "seed {seed}");
                        queries += 1;
                    }
                }
            }
        }
        assert!(queries > 1000, "{queries} lca queries");
    }

    /// Random links, cuts and walk-LCA queries (rooted at random nodes) on `lct`, checked
    /// against `naive`, which holds the same forest with the edges `edges`; returns the
    /// number of walks checked.
    fn random_plain_walks(
        lct: &mut super::PlainLct,
        naive: &mut Naive,
        edges: &mut Vec<(u32, u32)>,
        s: &mut u64,
        seed: u64,
    ) -> usize {
        let n = naive.adj.len() as u64;
        let mut queries = 0;
        for _ in 0..300 {
            let x = (next(s) % n) as u32;
            let y = (next(s) % n) as u32;
            let z = (next(s) % n) as u32;
            let r = (next(s) % n) as u32;
            match next(s) % 4 {
                0 if naive.path(x, y).is_none() => {
                    lct.link(x, y);
                    naive.link(x, y);
                    edges.push((x, y));
                }
                1 if !edges.is_empty() => {
                    let k = (next(s) % edges.len() as u64) as usize;
                    let (a, b) = edges.swap_remove(k);
                    lct.cut(a, b);
                    naive.cut(a, b);
                }
                _ => {
                    let lca = |a: u32, b: u32| {
                        let pa: Vec<u32> = naive.path(r, a)?.into_iter().rev().collect();
                        let pb: Vec<u32> = naive.path(r, b)?.into_iter().rev().collect();
                        let common = pa.iter().zip(&pb).take_while(|(p, q)| p == q).count();
                        Some(pa[common - 1])
                    };
                    let (Some(xy), Some(yz), Some(zx)) = (lca(x, y), lca(y, z), lca(z, x)) else {
                        continue;
                    };
                    lct.make_root(r);
                    lct.walk_to(x);
                    assert_eq!(lct.walk_to(y), xy, "seed {seed}");
                    assert_eq!(lct.walk_to(z), yz, "seed {seed}");
                    assert_eq!(lct.walk_to(x), zx, "seed {seed}");
                    queries += 1;
                }
            }
        }
        queries
    }

    /// `PlainLct`'s walk LCAs against the naive forest, on random forests changed by
    /// links and cuts between queries (as `lca_agrees_with_naive_paths` for `Lct`).
    #[test]
    fn plain_walk_agrees_with_naive_paths() {
        let mut queries = 0;
        for seed in 1..=80u64 {
            let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
            let n = 2 + (next(&mut s) % 20) as usize;
            let mut lct = super::PlainLct::with_parents(&vec![u32::MAX; n]);
            let mut naive = Naive {
                adj: vec![Vec::new(); n],
                val: vec![0; n],
            };
            queries += random_plain_walks(&mut lct, &mut naive, &mut Vec::new(), &mut s, seed);
        }
        assert!(queries > 1000, "{queries} walks");
    }

    /// The chain from the root of `x`'s tree in a parent array (`u32::MAX`: a root)
    /// down to `x`.
    fn root_path(parent: &[u32], mut x: u32) -> Vec<u32> {
        let mut chain = vec![x];
        while parent[x as usize] != u32::MAX {
            x = parent[x as usize];
            chain.push(x);
        }
        chain.reverse();
        chain
    }

    /// `Lct::with_parents` represents the forest of its parent array with its values:
    /// on random forests, connectivity and path minima are those of the parent array's
    /// ancestor chains.
    #[test]
    fn with_parents_is_the_parent_array_forest() {
        const NONE: u32 = u32::MAX;
        let mut asked = 0;
        for seed in 1..=60u64 {
            let mut s = seed.wrapping_mul(0x2545_F491_4F6C_DD1D) | 1;
            let n = 1 + (next(&mut s) % 30) as usize;
            let vals: Vec<i32> = (0..n).map(|_| (next(&mut s) % 50) as i32 - 10).collect();
            let mut parent = vec![NONE; n];
            for (x, p) in parent.iter_mut().enumerate().skip(1) {
                if next(&mut s) % 5 != 0 {
                    *p = (next(&mut s) % x as u64) as u32;
                }
            }
            let ancestors = |x: u32| root_path(&parent, x);
            let mut lct = super::Lct::with_parents(&vals, &parent);
            for _ in 0..40 {
                let x = (next(&mut s) % n as u64) as u32;
                let y = (next(&mut s) % n as u64) as u32;
                let (ax, ay) = (ancestors(x), ancestors(y));
                assert_eq!(lct.connected(x, y), ax[0] == ay[0], "seed {seed}");
                if ax[0] != ay[0] {
                    continue;
                }
                let common = ax.iter().zip(&ay).take_while(|(p, q)| p == q).count();
                let min = ax[common - 1..]
                    .iter()
                    .chain(&ay[common..])
                    .map(|&v| vals[v as usize])
                    .min();
                assert_eq!(Some(lct.path_min(x, y)), min, "seed {seed}: {x} {y}");
                asked += 1;
            }
        }
        assert!(asked > 500, "{asked} paths");
    }

    /// `replace_path` leaves `y`–`k`–`z` with `k` valued as `copy_from`, and every
    /// interior node alone with its value, pending additions included.
    #[test]
    fn replace_path_splices_in_one_node() {
        for m in 4..12u32 {
            // The path 0 - 1 - ... - (m - 1), and k = m alone.
            let vals: Vec<i32> = (0..=m as i32).map(|v| 100 - 7 * v).collect();
            let mut lct = super::Lct::new(&vals);
            for x in 1..m {
                lct.link(x - 1, x);
            }
            lct.path_add(0, m - 1, 5);
            let copy_from = m / 2;
            lct.replace_path(0, m - 1, m, copy_from);
            assert!(lct.connected(0, m) && lct.connected(m, m - 1));
            let ends = [0, m - 1, copy_from].map(|v| vals[v as usize] + 5);
            let min = ends.into_iter().min();
            assert_eq!(Some(lct.path_min(0, m - 1)), min, "{m}");
            assert_eq!(lct.path_min(m, m), vals[copy_from as usize] + 5);
            for x in 1..m - 1 {
                assert!(!lct.connected(x, 0), "{m}: {x} is cut off");
                assert_eq!(lct.isolated_value(x), vals[x as usize] + 5, "{m}: {x}");
            }
        }
    }

    /// `PlainLct::with_parents` represents the forest of its parent array, rooted as the
    /// array roots it: on random forests (random parents in a random node order, about a
    /// fifth of the nodes roots), the walk LCAs before any re-rooting are those of the
    /// parent array's ancestor chains (and two nodes of different trees are never asked);
    /// the same forest then takes random links, cuts and re-rooted walks as the naive one.
    #[test]
    fn plain_with_parents_is_the_parent_array_forest() {
        const NONE: u32 = u32::MAX;
        let (mut rooted, mut walks) = (0, 0);
        for seed in 1..=80u64 {
            let mut s = seed.wrapping_mul(0x2545_F491_4F6C_DD1D) | 1;
            let n = 1 + (next(&mut s) % 40) as usize;
            let mut order: Vec<u32> = (0..n as u32).collect();
            for i in (1..n).rev() {
                order.swap(i, (next(&mut s) % (i as u64 + 1)) as usize);
            }
            let mut parent = vec![NONE; n];
            for k in 1..n {
                if next(&mut s) % 5 != 0 {
                    parent[order[k] as usize] = order[(next(&mut s) % k as u64) as usize];
                }
            }
            let ancestors = |x: u32| root_path(&parent, x);
            let mut lct = super::PlainLct::with_parents(&parent);
            for _ in 0..60 {
                let x = (next(&mut s) % n as u64) as u32;
                let y = (next(&mut s) % n as u64) as u32;
                let (ax, ay) = (ancestors(x), ancestors(y));
                if ax[0] != ay[0] {
                    continue;
                }
                let common = ax.iter().zip(&ay).take_while(|(p, q)| p == q).count();
                lct.walk_to(x);
                assert_eq!(lct.walk_to(y), ax[common - 1], "seed {seed}: {x} {y}");
                rooted += 1;
            }
            let mut naive = Naive {
                adj: vec![Vec::new(); n],
                val: vec![0; n],
            };
            let mut edges = Vec::new();
            for (x, &p) in parent.iter().enumerate() {
                if p != NONE {
                    naive.adj[x].push(p);
                    naive.adj[p as usize].push(x as u32);
                    edges.push((x as u32, p));
                }
            }
            walks += random_plain_walks(&mut lct, &mut naive, &mut edges, &mut s, seed);
        }
        assert!(
            rooted > 2000 && walks > 1000,
            "{rooted} rooted, {walks} walks"
        );
    }
}
