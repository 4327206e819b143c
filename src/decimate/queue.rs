//! The decimator's priority queue: a 4-ary min-heap of packed 128-bit keys.
//!
//! **Guarantee.** [`Queue::pop`] returns the smallest key held (keys are compared as
//! integers); every operation is O(log₄ n) comparisons.
//!
//! **Why not `std::collections::BinaryHeap`.** The decimator pops about nine entries per
//! collapse (most of them stale: the edges of a merged vertex are queued again with
//! their new costs and the old entries are dropped when they come out), from a heap of
//! a few hundred thousand entries that does not fit in the cache, so the pops' cache
//! misses dominated the whole run (48 % of the time on an 86k-face mesh with `std`'s
//! binary heap of 24-byte entries). Here an entry is one `u128` (the cost's bits, then
//! the endpoints), the four children of a node share one cache line, and a pop walks
//! half as many levels.

/// The key of an edge `[p, q]` (`p < q`) of cost `cost ≥ 0`: ordered by cost, then
/// `p`, then `q`. (A non-negative `f64`'s bits order as the number does.)
#[inline]
pub(super) fn key(cost: f64, p: u32, q: u32) -> u128 {
    debug_assert!(cost >= 0.0 && cost.is_sign_positive());
    (u128::from(cost.to_bits()) << 64) | (u128::from(p) << 32) | u128::from(q)
}

/// The cost, `p` and `q` of a key.
#[inline]
pub(super) fn unpack(key: u128) -> (f64, u32, u32) {
    (
        f64::from_bits((key >> 64) as u64),
        (key >> 32) as u32,
        key as u32,
    )
}

/// Four keys, one cache line.
#[derive(Clone, Copy, Debug)]
#[repr(align(64))]
struct Line([u128; 4]);

/// A line of empty slots: every slot past the last node holds `u128::MAX`, so that a
/// pop compares four children without counting them (no key is `u128::MAX`: its
/// endpoints would be `u32::MAX`, which is no vertex).
const EMPTY: Line = Line([u128::MAX; 4]);

/// A min-heap of keys with four children per node (node `i`'s are `4i + 1 ..= 4i + 4`).
///
/// Node `i` is stored in slot `i + 3` of a list of 64-byte lines, so that the four
/// children of node `i` (slots `4i + 4 ..= 4i + 7`) fill line `i + 1`: a level of a pop
/// reads one line, not two.
#[derive(Clone, Debug, Default)]
pub(super) struct Queue {
    lines: Vec<Line>,
    len: usize,
}

/// The slot offset of node 0.
const OFFSET: usize = 3;

impl Queue {
    #[inline]
    fn get(&self, i: usize) -> u128 {
        let s = i + OFFSET;
        self.lines[s >> 2].0[s & 3]
    }

    #[inline]
    fn set(&mut self, i: usize, key: u128) {
        let s = i + OFFSET;
        self.lines[s >> 2].0[s & 3] = key;
    }

    /// A heap of `keys`, built bottom up in O(n). `count` is the number of keys: room
    /// for them and an eighth more is allocated at once (the keys are never held twice,
    /// and the decimator's heap grows by 3–6 % over a run on the corpus: a growth by
    /// doubling would hold three times the list at its peak).
    pub(super) fn from_keys(count: usize, keys: impl IntoIterator<Item = u128>) -> Self {
        let mut q = Queue {
            lines: Vec::with_capacity((count + count / 8 + OFFSET).div_ceil(4)),
            len: 0,
        };
        for k in keys {
            let s = q.len + OFFSET;
            if (s >> 2) >= q.lines.len() {
                q.lines.push(EMPTY);
            }
            q.lines[s >> 2].0[s & 3] = k;
            q.len += 1;
        }
        let n = q.len;
        if n > 1 {
            for i in (0..=(n - 2) / 4).rev() {
                let key = q.get(i);
                q.sift_down(i, key);
            }
        }
        q
    }

    /// A heap of `keys`.
    #[cfg(test)]
    fn from_vec(keys: Vec<u128>) -> Self {
        Self::from_keys(keys.len(), keys)
    }

    #[cfg(test)]
    fn len(&self) -> usize {
        self.len
    }

    pub(super) fn push(&mut self, key: u128) {
        let mut i = self.len;
        self.len += 1;
        if ((i + OFFSET) >> 2) >= self.lines.len() {
            self.lines.push(EMPTY);
        }
        while i > 0 {
            let parent = (i - 1) / 4;
            let up = self.get(parent);
            if up <= key {
                break;
            }
            self.set(i, up);
            i = parent;
        }
        self.set(i, key);
    }

    /// The smallest key, removed.
    pub(super) fn pop(&mut self) -> Option<u128> {
        if self.len == 0 {
            return None;
        }
        self.len -= 1;
        let last = self.get(self.len);
        self.set(self.len, u128::MAX);
        if self.len == 0 {
            return Some(last);
        }
        let top = self.get(0);
        self.sift_down(0, last);
        Some(top)
    }

    /// Places `key` at node `i` or below it, moving smaller children up.
    fn sift_down(&mut self, mut i: usize, key: u128) {
        // The children of node `i` fill line `i + 1` (empty slots hold `u128::MAX`, which
        // never moves up: no key is larger).
        while let Some(&Line([a, b, c, d])) = self.lines.get(i + 1) {
            // The first smallest of the four, as a scan would pick it.
            let (j1, m1) = if b < a { (1, b) } else { (0, a) };
            let (j2, m2) = if d < c { (3, d) } else { (2, c) };
            let (j, smallest) = if m2 < m1 { (j2, m2) } else { (j1, m1) };
            if smallest >= key {
                break;
            }
            self.set(i, smallest);
            i = 4 * i + 1 + j;
        }
        self.set(i, key);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Keys come out in increasing order whatever the order in: the cost first, then
    /// the endpoints; built at once or pushed one by one, with pops in between.
    #[test]
    fn pops_in_key_order() {
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let keys: Vec<u128> = (0..2000)
            .map(|_| {
                let r = next();
                key(
                    (r % 50) as f64 * 0.25,
                    (r >> 20) as u32 % 7,
                    (r >> 40) as u32 % 5,
                )
            })
            .collect();
        let mut sorted = keys.clone();
        sorted.sort_unstable();
        let mut q = Queue::from_vec(keys.clone());
        assert_eq!(q.len(), 2000);
        let out: Vec<u128> = std::iter::from_fn(|| q.pop()).collect();
        assert_eq!(out, sorted);
        let mut q = Queue::default();
        let mut out = Vec::new();
        for (i, &k) in keys.iter().enumerate() {
            q.push(k);
            if i % 3 == 2 {
                out.push(q.pop().expect("not empty"));
            }
        }
        out.extend(std::iter::from_fn(|| q.pop()));
        assert_eq!(out.len(), 2000);
        // Each pop was the smallest of what was in at the time: the pops after the
        // last push are increasing, and the whole is a permutation of the keys.
        let mut all = out.clone();
        all.sort_unstable();
        assert_eq!(all, sorted);
    }

    /// Every node's key is at most its children's: the heap order on which the
    /// O(log₄ n) bound of the operations rests.
    fn assert_heap_order(q: &Queue) {
        for i in 1..q.len() {
            let (k, parent) = (q.get(i), (i - 1) / 4);
            assert!(
                q.get(parent) <= k,
                "node {i} is below a larger key at {parent}"
            );
        }
    }

    /// The heap order holds after the build, after every push and after every pop, for
    /// heaps of every size up to a few levels (keys drawn with repeats, so that equal
    /// children occur).
    #[test]
    fn the_heap_order_holds_after_every_operation() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for n in (0..=90).chain([341, 1000]) {
            let keys: Vec<u128> = (0..n)
                .map(|_| {
                    let r = next();
                    key((r % 40) as f64, (r >> 20) as u32 % 3, (r >> 40) as u32 % 3)
                })
                .collect();
            let mut q = Queue::from_vec(keys.clone());
            assert_heap_order(&q);
            let mut popped = Vec::new();
            while let Some(k) = q.pop() {
                assert_heap_order(&q);
                popped.push(k);
            }
            let mut sorted = keys.clone();
            sorted.sort_unstable();
            assert_eq!(popped, sorted);
            for (i, &k) in keys.iter().enumerate() {
                q.push(k);
                assert_heap_order(&q);
                if i % 4 == 3 {
                    q.pop();
                    assert_heap_order(&q);
                }
            }
        }
    }

    /// A heap of `n ≥ 1` keys holds them in `⌈(n + 3) / 4⌉` lines (node 0 at slot 3; no
    /// line for no key), built at once or pushed one by one: the memory bound of the
    /// decimator counts on it (the build allocates an eighth more room, which pushes
    /// fill before the list grows).
    #[test]
    fn a_heap_of_n_keys_takes_n_plus_three_slots() {
        for n in [0usize, 1, 2, 5, 13, 14, 100, 1000] {
            let keys: Vec<u128> = (0..n as u128).rev().collect();
            let lines = if n == 0 { 0 } else { (n + OFFSET).div_ceil(4) };
            let built = Queue::from_vec(keys.clone());
            assert_eq!(built.lines.len(), lines, "built, n = {n}");
            assert!(built.lines.capacity() >= (n + n / 8 + OFFSET).div_ceil(4));
            let mut pushed = Queue::default();
            for &k in &keys {
                pushed.push(k);
            }
            assert_eq!(pushed.lines.len(), lines, "pushed, n = {n}");
        }
    }

    /// Heaps built from no key, one key and two keys give them back in order (the
    /// bottom-up build has no parent to sift below two keys).
    #[test]
    fn the_smallest_heaps_build_and_pop() {
        let (a, b) = (key(1.0, 2, 3), key(0.5, 7, 8));
        assert_eq!(Queue::from_vec(Vec::new()).pop(), None);
        let mut q = Queue::from_vec(vec![a]);
        assert_eq!((q.pop(), q.pop()), (Some(a), None));
        let mut q = Queue::from_vec(vec![a, b]);
        assert_eq!((q.pop(), q.pop(), q.pop()), (Some(b), Some(a), None));
    }

    #[test]
    fn keys_order_by_cost_then_endpoints_and_unpack() {
        assert!(key(0.5, 9, 9) < key(1.0, 0, 0));
        assert!(key(1.0, 1, 9) < key(1.0, 2, 0));
        assert!(key(1.0, 2, 3) < key(1.0, 2, 4));
        assert!(key(0.0, 0, 1) < key(f64::MIN_POSITIVE, 0, 0));
        assert!(key(1e300, 0, 0) < key(f64::INFINITY, 0, 0));
        assert_eq!(
            unpack(key(2.75, 17, 4_000_000_000)),
            (2.75, 17, 4_000_000_000)
        );
    }
}
