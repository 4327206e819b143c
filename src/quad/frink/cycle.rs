//! Case (iv) of the lifting step (tri-quad paper, Appendix A): an alternating cycle
//! through a matched edge `p = st` of a perfect matching `M` of a bridgeless cubic
//! multigraph, flipped, so that `p` leaves the matching.
//!
//! An `M`-alternating cycle through `p` is `p` plus an `(M − p)`-augmenting path from `s`
//! to `t` in `G − p` (the only two nodes `M − p` leaves free). One exists: every
//! bridgeless cubic graph has a perfect matching avoiding any given edge (Schönberger;
//! Biedl–Bose–Demaine–Lubiw, Sec. 2, the form the paper quotes), so `M − p` is not
//! maximum in `G − p` (Berge), and an augmenting path can only join its two free nodes.
//! Found by one single-source Edmonds search with blossoms from `s` (BFS alternating
//! tree, blossom bases by union–find, the compact "flower" links of `augment.rs`, here
//! holding *edge ids*, so that parallel edges are told apart). Flipping the path and
//! dropping `p` is flipping the cycle. O(k·α(n)) for the `k` nodes the search labels
//! (at most all live nodes); only those are reset afterwards.

use super::graph::{Cubic, NONE};

const UNREACHED: u8 = 0;
const EVEN: u8 = 1;
const ODD: u8 = 2;

/// Scratch of the search, reused between calls (every record is reset after use).
#[derive(Clone, Debug, Default)]
pub(crate) struct CycleSearch {
    label: Vec<u8>,
    /// Union–find parent over blossom bases.
    base: Vec<u32>,
    /// Flower link: the edge to the tree parent (odd nodes) or the cross edge recorded
    /// when a blossom is shrunk (even nodes turned from odd).
    link: Vec<u32>,
    mark: Vec<u32>,
    stamp: u32,
    touched: Vec<u32>,
    queue: Vec<u32>,
    /// Blossoms shrunk in all searches (for the statistics and tests).
    pub(crate) blossoms: u64,
}

impl CycleSearch {
    fn ensure(&mut self, n: usize) {
        if self.label.len() < n {
            self.label.resize(n, UNREACHED);
            self.base.resize(n, NONE);
            self.link.resize(n, NONE);
            self.mark.resize(n, 0);
        }
    }

    fn touch(&mut self, x: u32) {
        if self.base[x as usize] == NONE {
            self.base[x as usize] = x;
            self.touched.push(x);
        }
    }

    fn find(&mut self, mut x: u32) -> u32 {
        while self.base[x as usize] != x {
            let up = self.base[self.base[x as usize] as usize];
            self.base[x as usize] = up;
            x = up;
        }
        x
    }

    /// Flips an `M`-alternating cycle through the matched edge `p` of the perfect
    /// matching `mate` (per node: its matched edge id) of the live part of `g`. Returns
    /// the nodes whose mate changed (the cycle's, `p`'s ends included), or `None` (and
    /// `mate` unchanged) if there is no such cycle, which cannot happen when `g` is
    /// bridgeless.
    pub(crate) fn flip_cycle_through(
        &mut self,
        g: &Cubic,
        mate: &mut [u32],
        p: u32,
    ) -> Option<Vec<u32>> {
        let [s, t] = g.ends(p);
        debug_assert!(s != t && mate[s as usize] == p && mate[t as usize] == p);
        self.ensure(g.node_capacity());
        mate[s as usize] = NONE;
        mate[t as usize] = NONE;
        let path = self.search(g, mate, p, s);
        for x in std::mem::take(&mut self.touched) {
            let i = x as usize;
            self.label[i] = UNREACHED;
            self.base[i] = NONE;
            self.link[i] = NONE;
        }
        if path.is_none() {
            mate[s as usize] = p;
            mate[t as usize] = p;
        }
        path
    }

    /// The Edmonds search from the free node `s`, never using edge `skip`; on reaching
    /// the other free node, flips the augmenting path and returns its nodes.
    fn search(&mut self, g: &Cubic, mate: &mut [u32], skip: u32, s: u32) -> Option<Vec<u32>> {
        self.queue.clear();
        self.touch(s);
        self.label[s as usize] = EVEN;
        self.queue.push(s);
        let mut head = 0;
        while head < self.queue.len() {
            let x = self.queue[head];
            head += 1;
            for e in g.incident(x) {
                if e == skip || e == mate[x as usize] {
                    continue;
                }
                let w = g.other(e, x);
                if w == x {
                    continue; // a loop (never in a bridgeless graph) offers nothing
                }
                self.touch(w);
                match self.label[w as usize] {
                    UNREACHED => {
                        self.label[w as usize] = ODD;
                        self.link[w as usize] = e;
                        let m = mate[w as usize];
                        if m == NONE {
                            return Some(self.augment(g, mate, w));
                        }
                        let z = g.other(m, w);
                        self.touch(z);
                        self.label[z as usize] = EVEN;
                        self.queue.push(z);
                    }
                    EVEN => {
                        let (bx, bw) = (self.find(x), self.find(w));
                        if bx != bw {
                            self.blossoms += 1;
                            let l = self.lca(g, mate, bx, bw);
                            self.shrink(g, mate, x, e, l);
                            self.shrink(g, mate, w, e, l);
                        }
                    }
                    _ => {}
                }
            }
        }
        None
    }

    /// The base of the blossom that the even-even edge between blossoms `x` and `y`
    /// closes: walk both up the tree alternately, marking bases.
    fn lca(&mut self, g: &Cubic, mate: &[u32], mut x: u32, mut y: u32) -> u32 {
        self.stamp = self.stamp.wrapping_add(1);
        if self.stamp == 0 {
            self.mark.iter_mut().for_each(|m| *m = 0);
            self.stamp = 1;
        }
        loop {
            if x != NONE {
                x = self.find(x);
                if self.mark[x as usize] == self.stamp {
                    return x;
                }
                self.mark[x as usize] = self.stamp;
                let m = mate[x as usize];
                x = if m == NONE {
                    NONE // the root
                } else {
                    let odd = g.other(m, x);
                    g.other(self.link[odd as usize], odd)
                };
            }
            std::mem::swap(&mut x, &mut y);
        }
    }

    /// Shrinks one side of a blossom: from `x` (entered through edge `e`) up to base `l`.
    fn shrink(&mut self, g: &Cubic, mate: &[u32], mut x: u32, mut e: u32, l: u32) {
        while self.find(x) != l {
            self.link[x as usize] = e;
            let m = mate[x as usize];
            let y = g.other(m, x);
            if self.label[y as usize] == ODD {
                self.label[y as usize] = EVEN;
                self.queue.push(y);
            }
            if self.find(x) == x {
                self.base[x as usize] = l;
            }
            if self.find(y) == y {
                self.base[y as usize] = l;
            }
            e = self.link[y as usize];
            x = g.other(e, y);
        }
    }

    /// Flips the augmenting path ending at the free odd node `w` (its link set).
    fn augment(&mut self, g: &Cubic, mate: &mut [u32], w: u32) -> Vec<u32> {
        let mut nodes = Vec::new();
        let mut x = w;
        loop {
            let e = self.link[x as usize];
            let y = g.other(e, x);
            let next = mate[y as usize];
            mate[x as usize] = e;
            mate[y as usize] = e;
            nodes.push(x);
            nodes.push(y);
            if next == NONE {
                break;
            }
            x = g.other(next, y);
        }
        nodes
    }
}
