//! The decimator's data-parallel steps: costing every edge at the start, costing the
//! kept vertices' edges between passes, and sorting keys. On rayon's current thread
//! pool where the crate's `parallel` feature is on, the pool has two threads or more
//! and the step has at least [`MIN_ITEMS`] items; in the calling thread otherwise.
//!
//! **Guarantee.** The result is the same on any pool: costs are pure functions of the
//! state read (nothing is written while they are computed), each output slot is
//! written by one task, and key lists are sorted before use — keys are whole values
//! (cost bits, then endpoint ids), so a sorted list does not depend on the order in
//! which its keys were produced.
//!
//! **Memory.** Keys are produced in blocks of [`BLOCK`] items, so the per-task lists
//! add at most one block's keys beyond the list being filled.

/// Steps with fewer items run in the calling thread (a task costs microseconds to start).
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
pub(super) const MIN_ITEMS: usize = 1 << 11;

/// Items per block when keys are produced on the pool.
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
const BLOCK: usize = 1 << 16;

/// The number of threads a step of `items` items runs on (1: the calling thread).
pub(super) fn threads(items: usize) -> usize {
    #[cfg(feature = "parallel")]
    {
        let t = rayon::current_num_threads();
        if t >= 2 && items >= MIN_ITEMS {
            return t;
        }
    }
    let _ = items;
    1
}

/// Sets `out[i] = f(i)` for every slot.
// Without the feature, the early return is the whole body.
#[cfg_attr(not(feature = "parallel"), allow(clippy::needless_return))]
pub(super) fn fill<T, F>(out: &mut [T], f: F)
where
    T: Send,
    F: Fn(usize) -> T + Sync,
{
    let t = threads(out.len());
    if t < 2 {
        for (i, o) in out.iter_mut().enumerate() {
            *o = f(i);
        }
        return;
    }
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        let chunk = out.len().div_ceil(4 * t);
        out.par_chunks_mut(chunk).enumerate().for_each(|(k, part)| {
            for (j, o) in part.iter_mut().enumerate() {
                *o = f(k * chunk + j);
            }
        });
    }
}

/// Appends to `out` the keys `f` pushes for each of `0..n`, in an order that depends
/// on the pool: sort `out` before reading it.
// Without the feature, the early return is the whole body.
#[cfg_attr(not(feature = "parallel"), allow(clippy::needless_return))]
pub(super) fn extend_keys<F>(n: usize, out: &mut Vec<u128>, f: F)
where
    F: Fn(usize, &mut Vec<u128>) + Sync,
{
    let t = threads(n);
    if t < 2 {
        for i in 0..n {
            f(i, out);
        }
        return;
    }
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        for start in (0..n).step_by(BLOCK) {
            let end = (start + BLOCK).min(n);
            let part = (end - start).div_ceil(t);
            let lists: Vec<Vec<u128>> = (0..t)
                .into_par_iter()
                .map(|k| {
                    let mut keys = Vec::new();
                    for i in (start + k * part)..(start + (k + 1) * part).min(end) {
                        f(i, &mut keys);
                    }
                    keys
                })
                .collect();
            for keys in lists {
                out.extend_from_slice(&keys);
            }
        }
    }
}

/// Sorts keys in increasing order.
// Without the feature, the early return is the whole body.
#[cfg_attr(not(feature = "parallel"), allow(clippy::needless_return))]
pub(super) fn sort(keys: &mut [u128]) {
    if threads(keys.len()) < 2 {
        keys.sort_unstable();
        return;
    }
    #[cfg(feature = "parallel")]
    {
        use rayon::prelude::*;
        keys.par_sort_unstable();
    }
}

#[cfg(test)]
mod tests {
    use super::{extend_keys, fill, sort, threads, MIN_ITEMS};
    use std::collections::BTreeSet;
    use std::sync::Mutex;
    use std::time::{Duration, Instant};

    fn pool(threads: usize) -> rayon::ThreadPool {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool")
    }

    /// A step of [`MIN_ITEMS`] items on a pool of two or three threads runs on two of
    /// them at least: each item records its thread and waits (until a deadline five
    /// seconds away) for a second one, which can only come if the step handed work to
    /// another thread. Smaller steps, and any step on one thread, stay in the calling
    /// thread.
    #[test]
    fn large_steps_use_two_threads_of_a_pool() {
        for n in [2, 3] {
            large_steps_use_two_threads_of(n);
        }
        pool(1).install(|| assert_eq!(threads(usize::MAX), 1));
    }

    fn large_steps_use_two_threads_of(n: usize) {
        pool(n).install(|| {
            assert_eq!(threads(MIN_ITEMS), n);
            assert_eq!(threads(MIN_ITEMS - 1), 1);
            let seen = Mutex::new(BTreeSet::new());
            // Records the calling thread, then waits (until `deadline`) for a second one.
            let meet = |deadline: Instant| {
                let me = rayon::current_thread_index();
                seen.lock().expect("no poisoned lock").insert(me);
                while seen.lock().expect("no poisoned lock").len() < 2 && Instant::now() < deadline
                {
                    std::thread::yield_now();
                }
            };
            let deadline = Instant::now() + Duration::from_secs(5);
            let mut out = vec![0u8; MIN_ITEMS];
            fill(&mut out, |_| {
                meet(deadline);
                1
            });
            assert!(seen.lock().expect("no poisoned lock").len() >= 2, "fill");
            seen.lock().expect("no poisoned lock").clear();
            let deadline = Instant::now() + Duration::from_secs(5);
            let mut keys = Vec::new();
            extend_keys(MIN_ITEMS, &mut keys, |i, out| {
                meet(deadline);
                out.push(i as u128);
            });
            assert!(
                seen.lock().expect("no poisoned lock").len() >= 2,
                "extend_keys"
            );
        });
    }

    /// `fill`, `extend_keys` and `sort` give what their sequential definitions give,
    /// below and above the size at which they use the pool, on pools of 1, 2 and 3
    /// threads.
    #[test]
    fn every_pool_gives_the_sequential_result() {
        let key = |i: usize| ((i as u128 * 0x9E37_79B9_7F4A_7C15) % 1_000_003) << 64 | i as u128;
        for n in [
            0,
            5,
            MIN_ITEMS - 1,
            MIN_ITEMS,
            3 * MIN_ITEMS + 7,
            (1 << 16) + 3,
        ] {
            let mut want_fill: Vec<u128> = (0..n).map(key).collect();
            let mut want_keys: Vec<u128> = (0..n).filter(|i| i % 3 != 1).map(key).collect();
            want_keys.sort_unstable();
            want_fill.reverse();
            for threads in [1, 2, 3] {
                pool(threads).install(|| {
                    let mut filled = vec![0u128; n];
                    fill(&mut filled, |i| key(n - 1 - i));
                    assert_eq!(filled, want_fill, "fill, n = {n}, {threads} threads");
                    let mut keys = vec![u128::MAX];
                    extend_keys(n, &mut keys, |i, out| {
                        if i % 3 != 1 {
                            out.push(key(i));
                        }
                    });
                    assert_eq!(keys.remove(0), u128::MAX, "kept what was there");
                    sort(&mut keys);
                    assert_eq!(keys, want_keys, "keys, n = {n}, {threads} threads");
                });
            }
        }
    }
}
