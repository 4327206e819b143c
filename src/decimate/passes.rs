//! The pass schedule ([`super::Schedule::Passes`]): collapses in rounds over one sorted
//! list of edge keys instead of a priority queue updated after every collapse.
//!
//! **Guarantee.** Every guarantee of the module but the global order: every collapse
//! passes the locks, the error cap, the link condition and the fold-over guard at the
//! moment it is made, so the topology is kept; the run stops at the first face count at
//! or below the target, or after a pass over every edge left, with no cost limit, makes
//! no collapse (so no edge passes every guard: the exact schedule's stop rule). The
//! order is a weaker one, which the specification checks (`spec::before_pass_collapse`,
//! P1): **within a pass, collapses come in increasing key order, and none has a cheaper
//! edge passing every guard within the pass's first limit, away from the pass's earlier
//! collapses** (an edge neither merged in the pass nor next to a vertex merged in it).
//!
//! **Method.** The list holds the key (the placement's cost, then the endpoint ids) of
//! every edge its endpoints allow, sorted. A pass aims at a third of the collapses still
//! needed (each removes at most two faces) and sets its cost limit at 1.2 times the key
//! at that place in the list. It walks the list cheapest first: it skips an edge with an
//! endpoint merged earlier in the pass (its key is stale), resolves the others as the
//! exact schedule does (the link condition, then the placement's position or the guard's
//! cheapest alternative), collapses those that pass, and stops at the target or at the
//! first key over the limit. Many cheap edges are skipped because a neighbour went
//! first, so until a sixth of its goal is made the limit rises with the keys it meets;
//! a collapse whose position the guard moved to a dearer one than the limit waits for a
//! later pass. (The shape of the rule follows meshoptimizer's `simplify`; the guards,
//! the costs and the constants are this module's, the constants measured on the shared
//! corpus against the exact schedule's two-sided Hausdorff distance.) Between passes the
//! stale keys are dropped, the keys a pass refused are parked until a collapse next to
//! them (the only thing that can change their verdict), and the kept vertices' edges are
//! costed again, sorted and merged into the list.
//!
//! **Why it is faster.** The exact schedule costs a merged vertex's edges again and
//! re-queues its neighbours' best keys after every collapse, and pops about nine stale
//! entries per collapse from a heap that does not fit in the cache; here an edge is
//! costed at most once per pass, the list is read in order, and the kept vertices are
//! revisited in id order (about their memory order) rather than in cost order.
//!
//! **Complexity.** One O(E log E) sort, then O(E) per pass plus the sort of the new keys
//! (E the edges left); a pass that nothing blocks makes at least a sixth of its goal, so
//! O(log(F / target)) passes in practice (5–25 on the corpus at 10 % and 1 %). Memory:
//! 16 bytes per listed edge, 8 per vertex for the marks.

use super::pool;
use super::queue::unpack;
use super::run::{edge_from, edge_key, Decimator, Reporter};
use super::spec;
use crate::core::{Corner, VertexId};
use crate::progress::Progress;

/// A pass aims at this fraction (1 / this) of the collapses still needed: its limit is
/// set from the key at that place in the list.
const GOAL_SHARE: usize = 3;

/// A pass may take keys up to this many times the key at the place of its goal.
const LIMIT_FACTOR: f64 = 1.2;

/// A pass goes on past its limit, the limit rising with the keys, until it has made
/// this fraction (1 / this) of its goal.
const MIN_SHARE: usize = 6;

impl Decimator<'_> {
    /// The key of every real edge its endpoints allow, sorted. O(E log E).
    fn all_keys(&mut self) -> Vec<u128> {
        // Sized once: grown by doubling, the list would reach twice its length at the
        // call's peak.
        let mut keys: Vec<u128> = Vec::with_capacity(self.tri.edge_count());
        let this = &*self;
        pool::extend_keys(this.tri.corner_vertex.len(), &mut keys, |c, out| {
            let Some((p, q)) = edge_from(&this.tri, Corner(c as u32)) else {
                return;
            };
            if this.is_virtual(p) || this.is_virtual(q) {
                return;
            }
            if let Ok(c) = this.candidate(p, q) {
                out.push(edge_key(p, q, c.cost));
            }
        });
        pool::sort(&mut keys);
        keys
    }

    /// Runs passes to the stop rule; `observer` hears the faces removed. Returns
    /// `false` if `cancelled` said so.
    pub(crate) fn run_passes(
        &mut self,
        observer: &mut dyn FnMut(Progress),
        cancelled: &dyn Fn() -> bool,
    ) -> bool {
        let mut report = Reporter::start(self, observer);
        let mut keys = self.all_keys();
        let mut lists = Lists::default();
        // Set after a pass that made no collapse but left edges the guard moved to dearer
        // positions: the next pass takes every key.
        let mut unlimited = false;
        while self.real_faces > self.target {
            self.passes += 1;
            let pass = self.passes as u32;
            // Each collapse removes at most two faces.
            let needed = (self.real_faces - self.target).div_ceil(2);
            let goal = needed.div_ceil(GOAL_SHARE);
            let mut limit = match keys.get(goal) {
                Some(&k) if !unlimited => LIMIT_FACTOR * unpack(k).0,
                _ => f64::INFINITY,
            };
            let mut deferred = false;
            let min_made = goal.div_ceil(MIN_SHARE);
            let first_limit = limit;
            let made_before = self.collapses;
            let mut previous = None;
            lists.kept.clear();
            lists.refused.clear();
            for &k in &keys {
                if !report.step(self, observer, cancelled) {
                    return false;
                }
                let (cost, p, q) = unpack(k);
                if cost > limit {
                    if self.collapses - made_before >= min_made {
                        break;
                    }
                    // Too few collapses so far: the limit rises with the keys.
                    limit = cost;
                }
                if self.pass_mark[p as usize] == pass || self.pass_mark[q as usize] == pass {
                    continue;
                }
                let (p, q) = (VertexId(p), VertexId(q));
                match self.resolve(p, q) {
                    // The guard moved the collapse to a dearer position than the pass
                    // takes: the edge waits for a pass with a higher limit.
                    Ok((_, at, _)) if at > limit => deferred = true,
                    Ok((c, _, removed)) => {
                        spec::before_pass_collapse(
                            self,
                            (cost, p.0, q.0),
                            previous,
                            first_limit,
                            &c,
                        );
                        previous = Some(k);
                        self.pass_mark[p.index()] = pass;
                        self.pass_mark[q.index()] = pass;
                        lists.kept.push(c.keep);
                        self.merge(&c, removed);
                        if self.real_faces <= self.target {
                            break;
                        }
                    }
                    Err(r) => {
                        self.refused.count(r);
                        lists.refused.push(k);
                    }
                }
            }
            if self.collapses == made_before {
                if deferred && !unlimited {
                    unlimited = true;
                    self.refresh(&mut keys, &mut lists, pass);
                    continue;
                }
                // Every key was resolved (the limit stops a pass only after a collapse)
                // and refused (none waits: the pass had no limit), with nothing merged in
                // between: no edge passes every guard.
                break;
            }
            unlimited = false;
            if self.real_faces <= self.target {
                break;
            }
            self.refresh(&mut keys, &mut lists, pass);
        }
        report.end(self, observer);
        true
    }

    /// After pass `pass`: drops the keys with an endpoint it merged, parks the keys it
    /// refused, and merges into the sorted list the keys of the edges at the vertices
    /// it kept and the parked keys next to them (a collapse next to an edge is the only
    /// thing that changes its verdict). O(E) plus the sort of the new keys.
    fn refresh(&mut self, keys: &mut Vec<u128>, lists: &mut Lists, pass: u32) {
        let mark = &self.pass_mark;
        let stale = |k: u128| {
            let (_, p, q) = unpack(k);
            mark[p as usize] == pass || mark[q as usize] == pass
        };
        // The refused keys are in the list's order: one walk drops them.
        let mut r = 0;
        let refused = &lists.refused;
        keys.retain(|&k| {
            if r < refused.len() && refused[r] == k {
                r += 1;
                return false;
            }
            !stale(k)
        });
        lists.parked.extend_from_slice(&lists.refused);
        // One walk around each kept vertex: marks its neighbourhood and costs its edges.
        // In id order, which is mostly the memory order of their corners (the pass met
        // them in cost order, all over the mesh).
        lists.kept.sort_unstable();
        for &v in &lists.kept {
            self.near_mark[v.index()] = pass;
            for n in self.tri.link(v) {
                self.near_mark[n.index()] = pass;
            }
        }
        let fresh = &mut lists.fresh;
        fresh.clear();
        let (this, kept) = (&*self, &lists.kept);
        pool::extend_keys(kept.len(), fresh, |i, out| {
            let v = kept[i];
            for n in this.tri.link(v) {
                // An edge between two kept vertices is costed from its smaller end.
                if this.is_virtual(n) || (this.pass_mark[n.index()] == pass && n < v) {
                    continue;
                }
                if let Ok(c) = this.candidate(v, n) {
                    out.push(edge_key(v, n, c.cost));
                }
            }
        });
        let (mark, near) = (&self.pass_mark, &self.near_mark);
        let stale = |k: u128| {
            let (_, p, q) = unpack(k);
            mark[p as usize] == pass || mark[q as usize] == pass
        };
        lists.parked.retain(|&k| {
            if stale(k) {
                return false;
            }
            let (_, p, q) = unpack(k);
            if near[p as usize] == pass || near[q as usize] == pass {
                fresh.push(k);
                return false;
            }
            true
        });
        pool::sort(fresh);
        merge_sorted(keys, fresh);
    }
}

/// The pass schedule's working lists besides the sorted keys.
#[derive(Default)]
struct Lists {
    /// The vertices the current pass kept (merged others into).
    kept: Vec<VertexId>,
    /// The keys the current pass refused, in order.
    refused: Vec<u128>,
    /// Keys refused with no collapse next to them since.
    parked: Vec<u128>,
    /// New keys, before they are merged into the list.
    fresh: Vec<u128>,
}

/// Merges the sorted `b` into the sorted `a` in place, from the back. O(|a| + |b|).
fn merge_sorted(a: &mut Vec<u128>, b: &[u128]) {
    let (mut i, mut j) = (a.len(), b.len());
    a.resize(i + j, 0);
    let mut k = a.len();
    while j > 0 {
        k -= 1;
        if i > 0 && a[i - 1] > b[j - 1] {
            a[k] = a[i - 1];
            i -= 1;
        } else {
            a[k] = b[j - 1];
            j -= 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{merge_sorted, Lists};
    use crate::core::{ConedSurfaces, VertexId};
    use crate::decimate::queue::unpack;
    use crate::decimate::run::Decimator;
    use crate::decimate::{Options, Placement, Schedule};
    use crate::gen;

    /// After a pass without collapses, `refresh` takes the refused keys out of the list
    /// and parks them; after a pass that kept a vertex, it costs that vertex's edges
    /// again and returns the parked keys next to it, and only those.
    #[test]
    fn refresh_parks_refused_keys_until_a_collapse_next_to_them() {
        let mesh = gen::isosurface(&gen::IsoParams::new(
            gen::Implicit::Sphere { radius: 1.0 },
            gen::Tessellation::SixTetrahedra,
            5,
        ))
        .expect("a sphere");
        let opts = Options {
            target_faces: 0,
            max_error: None,
            placement: Placement::Optimal,
            schedule: Schedule::Passes,
            guard: true,
            lock_boundary: false,
            locked: Vec::new(),
        };
        let whole = ConedSurfaces::whole(mesh.vertex_count, &mesh.faces).expect("a surface");
        let positions = mesh.positions.as_deref().expect("positions");
        let mut d = Decimator::new(whole, positions, &opts);
        let all = d.all_keys();
        let n = all.len();
        assert!(n > 20);
        // Pass 1 refused three keys and made no collapse.
        let refused = vec![all[1], all[n / 2], all[n - 1]];
        let mut keys = all.clone();
        let mut lists = Lists {
            refused: refused.clone(),
            ..Lists::default()
        };
        d.refresh(&mut keys, &mut lists, 1);
        let rest: Vec<u128> = all
            .iter()
            .copied()
            .filter(|k| !refused.contains(k))
            .collect();
        assert_eq!(keys, rest);
        assert_eq!(lists.parked, refused);
        // Pass 2 kept a neighbour `v` of the first parked edge's endpoint `p` (its
        // position and quadric as they were): that key comes back, the others stay.
        let (_, p, q) = unpack(refused[0]);
        let v = d
            .tri
            .link(VertexId(p))
            .find(|&v| v.0 != q)
            .expect("a neighbour");
        d.pass_mark[v.index()] = 2;
        lists.kept = vec![v];
        lists.refused.clear();
        d.refresh(&mut keys, &mut lists, 2);
        let near = |x: u32| {
            let x = VertexId(x);
            x == v || d.tri.link(v).any(|w| w == x)
        };
        let (back, parked): (Vec<u128>, Vec<u128>) = refused.iter().partition(|&&k| {
            let (_, a, b) = unpack(k);
            near(a) || near(b)
        });
        assert!(back.contains(&refused[0]));
        assert_eq!(lists.parked, parked);
        let mut want: Vec<u128> = rest.iter().chain(&back).copied().collect();
        want.sort_unstable();
        assert_eq!(keys, want);
    }

    #[test]
    fn merging_keeps_every_key_in_order() {
        let cases: [(&[u128], &[u128]); 5] = [
            (&[], &[]),
            (&[1, 4, 9], &[]),
            (&[], &[2, 3]),
            (&[1, 4, 9], &[0, 4, 5, 10]),
            (&[5, 6], &[1, 2]),
        ];
        for (a, b) in cases {
            let mut merged = a.to_vec();
            merge_sorted(&mut merged, b);
            let mut want: Vec<u128> = a.iter().chain(b).copied().collect();
            want.sort_unstable();
            assert_eq!(merged, want, "{a:?} + {b:?}");
        }
    }
}
