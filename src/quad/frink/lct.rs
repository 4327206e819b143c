//! A link–cut tree (Sleator–Tarjan 1983, splay-based) on flat arrays with `u32` indices:
//! a forest of rooted-at-will trees supporting link, cut, re-rooting, and on the path
//! between two nodes "add `d` to every value" and "minimum value".
//!
//! # Guarantees
//! Every operation keeps the represented forest and the node values exactly as a naive
//! forest would (tested against one in the unit tests below, exhaustively on random
//! operation sequences). [`Lct::link`] and [`Lct::cut`] assume their preconditions (the
//! nodes in different trees; an existing edge) and check them with `debug_assert!`.
//!
//! # Complexity
//! O(log n) amortised per operation (splay trees with the access lemma); memory 25 bytes
//! per node. No recursion: push-downs along a splay path use an explicit stack.

/// No node.
const NIL: u32 = u32::MAX;

/// Link–cut forest over nodes `0..n` with an `i32` value per node.
#[derive(Clone, Debug, Default)]
pub(crate) struct Lct {
    /// Splay-tree children.
    ch: Vec<[u32; 2]>,
    /// Splay parent, or path-parent when this node is a splay root (the two are told
    /// apart by [`Lct::is_root`]).
    par: Vec<u32>,
    val: Vec<i32>,
    /// Minimum of `val` over this node's splay subtree (its part of the preferred path).
    min: Vec<i32>,
    /// Pending addition to the whole splay subtree (already applied to `val`/`min` here).
    add: Vec<i32>,
    /// Pending reversal of the splay subtree's children (already applied here).
    rev: Vec<bool>,
    stack: Vec<u32>,
}

impl Lct {
    /// `n` single-node trees, node `i` with value `vals[i]`.
    #[cfg(test)]
    pub(crate) fn new(vals: &[i32]) -> Self {
        let n = vals.len();
        Lct {
            ch: vec![[NIL; 2]; n],
            par: vec![NIL; n],
            val: vals.to_vec(),
            min: vals.to_vec(),
            add: vec![0; n],
            rev: vec![false; n],
            stack: Vec::new(),
        }
    }

    /// The forest whose tree edges are `x`–`parent[x]` (`u32::MAX`: a root), node `i`
    /// with value `vals[i]`; `parent` must describe a forest. O(n): every node starts as
    /// its own preferred path, with its tree parent as path-parent.
    pub(crate) fn with_parents(vals: Vec<i32>, parent: Vec<u32>) -> Self {
        let n = vals.len();
        debug_assert_eq!(parent.len(), n);
        Lct {
            ch: vec![[NIL; 2]; n],
            par: parent,
            min: vals.clone(),
            val: vals,
            add: vec![0; n],
            rev: vec![false; n],
            stack: Vec::new(),
        }
    }

    /// Sets the value of `x`, which must be a single-node tree (not linked).
    pub(crate) fn set_isolated(&mut self, x: u32, v: i32) {
        debug_assert!(self.par[x as usize] == NIL && self.ch[x as usize] == [NIL; 2]);
        self.val[x as usize] = v;
        self.min[x as usize] = v;
        self.add[x as usize] = 0;
        self.rev[x as usize] = false;
    }

    /// The value of `x` once it is cut off (a single-node tree).
    pub(crate) fn isolated_value(&self, x: u32) -> i32 {
        self.val[x as usize]
    }

    fn is_root(&self, x: u32) -> bool {
        let p = self.par[x as usize];
        p == NIL || (self.ch[p as usize][0] != x && self.ch[p as usize][1] != x)
    }

    fn apply_add(&mut self, x: u32, d: i32) {
        if x != NIL {
            let i = x as usize;
            self.val[i] += d;
            self.min[i] += d;
            self.add[i] += d;
        }
    }

    fn apply_rev(&mut self, x: u32) {
        if x != NIL {
            let i = x as usize;
            self.ch[i].swap(0, 1);
            self.rev[i] ^= true;
        }
    }

    fn push(&mut self, x: u32) {
        let i = x as usize;
        let [a, b] = self.ch[i];
        if self.add[i] != 0 {
            let d = self.add[i];
            self.apply_add(a, d);
            self.apply_add(b, d);
            self.add[i] = 0;
        }
        if self.rev[i] {
            self.apply_rev(a);
            self.apply_rev(b);
            self.rev[i] = false;
        }
    }

    fn pull(&mut self, x: u32) {
        let i = x as usize;
        let mut m = self.val[i];
        for c in self.ch[i] {
            if c != NIL && self.min[c as usize] < m {
                m = self.min[c as usize];
            }
        }
        self.min[i] = m;
    }

    fn rotate(&mut self, x: u32) {
        let p = self.par[x as usize];
        let g = self.par[p as usize];
        let dir = usize::from(self.ch[p as usize][1] == x);
        let b = self.ch[x as usize][dir ^ 1];
        if !self.is_root(p) {
            let gi = g as usize;
            if self.ch[gi][0] == p {
                self.ch[gi][0] = x;
            } else {
                self.ch[gi][1] = x;
            }
        }
        self.par[x as usize] = g;
        self.ch[x as usize][dir ^ 1] = p;
        self.par[p as usize] = x;
        self.ch[p as usize][dir] = b;
        if b != NIL {
            self.par[b as usize] = p;
        }
        self.pull(p);
        self.pull(x);
    }

    fn splay(&mut self, x: u32) {
        // Push pending tags from the splay root down to x first (iteratively).
        self.stack.clear();
        let mut y = x;
        self.stack.push(y);
        while !self.is_root(y) {
            y = self.par[y as usize];
            self.stack.push(y);
        }
        while let Some(z) = self.stack.pop() {
            self.push(z);
        }
        while !self.is_root(x) {
            let p = self.par[x as usize];
            if !self.is_root(p) {
                let g = self.par[p as usize];
                let zigzig = (self.ch[g as usize][0] == p) == (self.ch[p as usize][0] == x);
                self.rotate(if zigzig { p } else { x });
            }
            self.rotate(x);
        }
    }

    /// Makes the root-to-`x` path preferred; afterwards `x` is the root of its splay
    /// tree, which holds exactly that path.
    fn access(&mut self, x: u32) {
        let mut last = NIL;
        let mut y = x;
        while y != NIL {
            self.splay(y);
            self.ch[y as usize][1] = last;
            self.pull(y);
            last = y;
            y = self.par[y as usize];
        }
        self.splay(x);
    }

    /// Makes `x` the root of its tree.
    pub(crate) fn make_root(&mut self, x: u32) {
        self.access(x);
        self.apply_rev(x);
    }

    fn find_root(&mut self, x: u32) -> u32 {
        self.access(x);
        let mut y = x;
        loop {
            self.push(y);
            let l = self.ch[y as usize][0];
            if l == NIL {
                break;
            }
            y = l;
        }
        self.splay(y);
        y
    }

    /// Whether `x` and `y` are in the same tree.
    pub(crate) fn connected(&mut self, x: u32, y: u32) -> bool {
        x == y || self.find_root(x) == self.find_root(y)
    }

    /// Adds the edge `x`–`y`; they must be in different trees.
    pub(crate) fn link(&mut self, x: u32, y: u32) {
        debug_assert!(!self.connected(x, y), "link inside one tree");
        self.make_root(x);
        self.par[x as usize] = y;
    }

    /// Removes the edge `x`–`y`, which must exist.
    pub(crate) fn cut(&mut self, x: u32, y: u32) {
        self.make_root(x);
        self.access(y);
        debug_assert!(
            self.ch[y as usize][0] == x && self.ch[x as usize][1] == NIL,
            "cut of a non-edge"
        );
        self.ch[y as usize][0] = NIL;
        self.par[x as usize] = NIL;
        self.pull(y);
        // Leave x's own value exact (its subtree tags are pushed on the next splay).
        self.push(x);
    }

    /// Exposes the `x`–`y` path as one splay tree rooted at `y`; they must be connected.
    fn expose(&mut self, x: u32, y: u32) {
        self.make_root(x);
        self.access(y);
    }

    /// Adds `d` to the value of every node on the `x`–`y` path (both included).
    pub(crate) fn path_add(&mut self, x: u32, y: u32, d: i32) {
        self.expose(x, y);
        self.apply_add(y, d);
    }

    /// Minimum value on the `x`–`y` path (both included).
    pub(crate) fn path_min(&mut self, x: u32, y: u32) -> i32 {
        self.expose(x, y);
        self.min[y as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::Lct;

    /// The naive forest: adjacency sets and values; path by BFS.
    struct Naive {
        adj: Vec<Vec<u32>>,
        val: Vec<i32>,
    }

    impl Naive {
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
                match next(&mut s) % 5 {
                    0 if path.is_none() => {
                        lct.link(x, y);
                        naive.adj[x as usize].push(y);
                        naive.adj[y as usize].push(x);
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
                        naive.adj[a as usize].retain(|&c| c != b);
                        naive.adj[b as usize].retain(|&c| c != a);
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
    }
}
