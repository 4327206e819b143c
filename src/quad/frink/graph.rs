//! The cubic multigraph of Frink's reduction on flat arrays, the two reconnections of
//! the tri-quad paper's Appendix A and their exact undo, and the iterative DFS lowpoint
//! test (connected and bridgeless) of the naive strategy.

use super::FrinkError;

/// No edge / no node.
pub(crate) const NONE: u32 = u32::MAX;

/// Every edge id that [`super::solve`] on a cubic graph of `n` nodes creates is below
/// this: the `3n/2` input edges, then two new ids per reduction, of which there are at
/// most `n/2 − 1` (a strategy's tentative [`Cubic::reduce`] takes the same two next ids
/// and gives them back by [`Cubic::undo`]): `5n/2 − 2` for `n ≥ 2`, as
/// [`Cubic::reduce`] allocates ids as a stack.
pub(crate) fn edge_ids(n: usize) -> usize {
    // ⌊3n/2⌋ without overflow, saturating.
    let input = (n / 2).saturating_mul(3).saturating_add(n % 2);
    input.saturating_add(n.saturating_sub(2))
}

/// The largest `n` for which every edge id of a run on `n` nodes is below `limit`:
/// [`edge_ids`]`(m) ≤ limit` for every `m ≤` the result ([`edge_ids`] grows with `n`).
pub(crate) fn max_nodes_for_edge_ids(limit: usize) -> usize {
    // 5n/2 − 2 ≤ limit ⇔ n ≤ 2(limit + 2)/5.
    let k = limit.saturating_add(2);
    let n = k / 5 * 2 + k % 5 * 2 / 5;
    debug_assert!(edge_ids(n) <= limit);
    n
}

/// The most nodes [`Cubic::from_edges`] accepts, 1,431,655,764: the `3n/2` edges of a
/// cubic graph on them stay below `2^31 − 1`, so that every edge id a run creates
/// ([`edge_ids`], `5n/2 − 2`) fits below [`NONE`].
pub(crate) const MAX_NODES: usize = (NONE as usize / 2 - 1) * 2 / 3;

/// Whether `n` nodes are within [`MAX_NODES`].
pub(crate) fn fits_ids(n: usize) -> bool {
    n <= MAX_NODES
}

/// A cubic multigraph with stable ids on flat arrays: `ends[e]` are the two end nodes of
/// edge `e` (equal for a loop), `slots[x]` the three edge ids at node `x` (a loop twice).
/// Reductions remove two nodes and five edges and append two new edges; an edge is live
/// iff it is in the slots of a live node. Edge ids are allocated as a stack, so
/// reductions must be undone in reverse order ([`Cubic::undo`]).
///
/// Memory: 8 bytes per edge ever created (at most `3n/2 + n − 2` for `n` nodes), 13
/// bytes per node. Every operation below is O(1) unless stated.
#[derive(Clone, Debug)]
pub struct Cubic {
    pub(crate) ends: Vec<[u32; 2]>,
    pub(crate) slots: Vec<[u32; 3]>,
    pub(crate) alive: Vec<bool>,
    pub(crate) live: usize,
}

/// Which pair of new edges replaces the five removed ones (Appendix A, Fig. A.15):
/// `H1` adds `x1x3` and `x2x4`, `H2` adds `x1x4` and `x2x3`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Reconnection {
    /// `x1x3`, `x2x4`.
    H1,
    /// `x1x4`, `x2x3`.
    H2,
}

/// A reduction edge `e = uv` (simple, no loop at `u` or `v`) with the other edges at its
/// ends: `a = [ux1, ux2]`, `b = [vx3, vx4]` (slot order), `x = [x1, x2, x3, x4]`.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Candidate {
    /// The end kept as `u`.
    pub u: u32,
    /// The other end.
    pub v: u32,
    /// The edge `uv`.
    pub e: u32,
    /// `[ux1, ux2]`.
    pub a: [u32; 2],
    /// `[vx3, vx4]`.
    pub b: [u32; 2],
    /// `[x1, x2, x3, x4]` (not necessarily distinct).
    pub x: [u32; 4],
}

/// An applied reduction: the candidate, the reconnection, the new edges `new = [p, q]`
/// with `p` joining `x1` to `y[0]` and `q` joining `x2` to `y[1]`, where `y[k]` is the
/// end of `bv[k]`, the edge at `v` that `p` (resp. `q`) replaced. So `H1`:
/// `bv = [vx3, vx4]`, `H2`: `bv = [vx4, vx3]`. This is all the lifting step needs.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Reduction {
    /// The reduction edge and its neighbourhood.
    pub cand: Candidate,
    /// Which reconnection was applied.
    pub recon: Reconnection,
    /// `[p, q]`.
    pub new: [u32; 2],
    /// `[bp, bq]`: the edges at `v` that `p`, `q` replaced.
    pub bv: [u32; 2],
    /// `[yp, yq]`: the far ends of `bp`, `bq`.
    pub y: [u32; 2],
}

impl Cubic {
    /// The cubic multigraph on nodes `0..n` with the given edges (loops and parallel
    /// edges allowed). O(n + m). Errors if an end is out of range or a node's degree is
    /// not 3 (a loop counts twice).
    pub fn from_edges(n: usize, edges: &[[u32; 2]]) -> Result<Cubic, FrinkError> {
        // Checked on `n` alone, before any allocation: a longer edge list than `3n/2`
        // fails the degree check below, at an index that still fits in 32 bits.
        if !fits_ids(n) {
            return Err(FrinkError::TooLarge(n));
        }
        let mut slots = vec![[NONE; 3]; n];
        let mut deg = vec![0u8; n];
        for (i, &[a, b]) in edges.iter().enumerate() {
            for x in [a, b] {
                let Some(d) = deg.get_mut(x as usize) else {
                    return Err(FrinkError::NodeOutOfRange { edge: i, node: x });
                };
                if *d >= 3 {
                    return Err(FrinkError::NotCubic { node: x });
                }
                slots[x as usize][*d as usize] = i as u32;
                *d += 1;
            }
        }
        if let Some(x) = deg.iter().position(|&d| d != 3) {
            return Err(FrinkError::NotCubic { node: x as u32 });
        }
        Ok(Cubic {
            ends: edges.to_vec(),
            slots,
            alive: vec![true; n],
            live: n,
        })
    }

    /// Number of live nodes.
    pub fn node_count(&self) -> usize {
        self.live
    }

    /// One more than the largest node id.
    pub fn node_capacity(&self) -> usize {
        self.slots.len()
    }

    /// Whether `x` is a live node.
    pub fn is_alive(&self, x: u32) -> bool {
        self.alive.get(x as usize).copied().unwrap_or(false)
    }

    /// The three edges at live node `x`.
    pub fn incident(&self, x: u32) -> [u32; 3] {
        self.slots[x as usize]
    }

    /// The ends of edge `e`.
    pub fn ends(&self, e: u32) -> [u32; 2] {
        self.ends[e as usize]
    }

    /// The end of edge `e` other than `x` (`x` itself for a loop).
    #[inline]
    pub fn other(&self, e: u32, x: u32) -> u32 {
        let [a, b] = self.ends[e as usize];
        if a == x {
            b
        } else {
            a
        }
    }

    /// A reduction edge at live node `u` (Appendix A: `e = uv` must be simple): the
    /// first slot of `u` whose edge goes to a node that no other slot of `u` reaches.
    /// `None` if there is none, i.e. `u` lies on a triple edge (the base case), or if `u`
    /// or that `v` carries a loop (never in a bridgeless graph). O(1).
    pub fn candidate_at(&self, u: u32) -> Option<Candidate> {
        let s = self.slots[u as usize];
        let w = s.map(|e| self.other(e, u));
        if w.contains(&u) {
            return None;
        }
        let i = (0..3).find(|&i| (0..3).all(|j| j == i || w[j] != w[i]))?;
        self.candidate_for(u, s[i])
    }

    /// The reduction with edge `e` at live node `u` (`e` must be at `u`), if it is a valid
    /// one: `e` simple, no loop at `u` or at its other end. O(1). Same neighbourhood order
    /// as [`Cubic::candidate_at`] (the slots after `e`'s, cyclically).
    pub fn candidate_for(&self, u: u32, e: u32) -> Option<Candidate> {
        let s = self.slots[u as usize];
        let i = s.iter().position(|&f| f == e)?;
        let w = s.map(|f| self.other(f, u));
        let v = w[i];
        if w.contains(&u) || (0..3).any(|j| j != i && w[j] == v) {
            return None;
        }
        let a = [s[(i + 1) % 3], s[(i + 2) % 3]];
        let sv = self.slots[v as usize];
        let j = sv.iter().position(|&f| f == e)?;
        let b = [sv[(j + 1) % 3], sv[(j + 2) % 3]];
        let x = [
            self.other(a[0], u),
            self.other(a[1], u),
            self.other(b[0], v),
            self.other(b[1], v),
        ];
        if x[2] == v || x[3] == v {
            return None;
        }
        Some(Candidate { u, v, e, a, b, x })
    }

    /// Replaces the first occurrence of `old` in the slots of `x` by `new`.
    fn replace_slot(&mut self, x: u32, old: u32, new: u32) {
        let s = &mut self.slots[x as usize];
        match s.iter().position(|&f| f == old) {
            Some(i) => s[i] = new,
            None => unreachable!("edge {old} is not at node {x}"),
        }
    }

    /// Applies the reduction `cand` with `recon`: removes `u`, `v` and their five edges,
    /// adds `p`, `q` (Appendix A). O(1). The result is cubic; it may have loops and
    /// parallel edges (then it is for the strategy to reject it).
    pub fn reduce(&mut self, cand: &Candidate, recon: Reconnection) -> Reduction {
        let [x1, x2, x3, x4] = cand.x;
        let (bv, y) = match recon {
            Reconnection::H1 => (cand.b, [x3, x4]),
            Reconnection::H2 => ([cand.b[1], cand.b[0]], [x4, x3]),
        };
        let p = self.ends.len() as u32;
        let q = p + 1;
        self.ends.push([x1, y[0]]);
        self.ends.push([x2, y[1]]);
        self.replace_slot(x1, cand.a[0], p);
        self.replace_slot(y[0], bv[0], p);
        self.replace_slot(x2, cand.a[1], q);
        self.replace_slot(y[1], bv[1], q);
        self.alive[cand.u as usize] = false;
        self.alive[cand.v as usize] = false;
        self.live -= 2;
        Reduction {
            cand: *cand,
            recon,
            new: [p, q],
            bv,
            y,
        }
    }

    /// Undoes `r`, which must be the last reduction applied and not undone (the new
    /// edges are the last two ids). O(1).
    pub fn undo(&mut self, r: &Reduction) {
        let [p, q] = r.new;
        assert!(
            q as usize + 1 == self.ends.len() && p + 1 == q,
            "Cubic::undo: not the last reduction"
        );
        let c = &r.cand;
        self.replace_slot(r.y[1], q, r.bv[1]);
        self.replace_slot(c.x[1], q, c.a[1]);
        self.replace_slot(r.y[0], p, r.bv[0]);
        self.replace_slot(c.x[0], p, c.a[0]);
        self.ends.truncate(p as usize);
        self.alive[c.u as usize] = true;
        self.alive[c.v as usize] = true;
        self.live += 2;
    }
}

/// Scratch of the DFS lowpoint test, reused between calls: `disc`/`low` are valid for a
/// node iff its `stamp` equals the current one, so no call clears anything.
#[derive(Clone, Debug, Default)]
pub(crate) struct Dfs {
    stamp: Vec<u32>,
    disc: Vec<u32>,
    low: Vec<u32>,
    current: u32,
    /// `(node, edge it was entered by, next slot)`.
    stack: Vec<(u32, u32, u8)>,
    /// Number of runs (for the statistics).
    pub(crate) runs: u64,
}

impl Dfs {
    /// Whether the live part of `g` is connected and has no bridge, by one iterative DFS
    /// from `start` computing lowpoints (Tarjan): a tree edge `(w, x)` is a bridge iff
    /// `low(x) > disc(w)`; the graph is connected iff the DFS reaches every live node.
    /// Parallel edges and loops are handled by skipping only the *edge id* the node was
    /// entered by. O(live nodes).
    pub(crate) fn connected_bridgeless(&mut self, g: &Cubic, start: u32) -> bool {
        self.runs += 1;
        let n = g.node_capacity();
        if self.stamp.len() < n {
            self.stamp.resize(n, 0);
            self.disc.resize(n, 0);
            self.low.resize(n, 0);
        }
        if self.current == u32::MAX {
            self.stamp.iter_mut().for_each(|s| *s = 0);
            self.current = 0;
        }
        self.current += 1;
        let cur = self.current;
        let mut time = 0u32;
        self.stack.clear();
        self.stamp[start as usize] = cur;
        self.disc[start as usize] = time;
        self.low[start as usize] = time;
        time += 1;
        self.stack.push((start, NONE, 0));
        while let Some(top) = self.stack.last_mut() {
            let (x, via, i) = *top;
            if i < 3 {
                top.2 += 1;
                let e = g.slots[x as usize][i as usize];
                if e == via {
                    continue;
                }
                let w = g.other(e, x);
                if self.stamp[w as usize] == cur {
                    let d = self.disc[w as usize];
                    if d < self.low[x as usize] {
                        self.low[x as usize] = d;
                    }
                } else {
                    self.stamp[w as usize] = cur;
                    self.disc[w as usize] = time;
                    self.low[w as usize] = time;
                    time += 1;
                    self.stack.push((w, e, 0));
                }
            } else {
                self.stack.pop();
                if let Some(&(parent, _, _)) = self.stack.last() {
                    let l = self.low[x as usize];
                    if l > self.disc[parent as usize] {
                        return false; // `via` is a bridge
                    }
                    if l < self.low[parent as usize] {
                        self.low[parent as usize] = l;
                    }
                }
            }
        }
        time as usize == g.live
    }
}
