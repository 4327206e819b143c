//! The one documented random source of the crate, so that other languages can reproduce
//! every seeded output bit for bit.
//!
//! - Stream: ChaCha with 8 rounds as implemented by `rand_chacha::ChaCha8Rng`, keyed by
//!   32 bytes: the seed as a little-endian `u64` in bytes 0..8, zeros elsewhere; stream
//!   id 0; `next_u64` joins two consecutive 32-bit output words, low word first.
//! - [`Rng::below`]`(n)`: draw `x = next_u64()` until `x < n * floor(2^64 / n)`, return
//!   `x % n` (plain rejection sampling, unbiased).
//! - [`Rng::chance`]`(num, den)`: `below(den) < num`.
//! - [`Rng::shuffle`]: Fisher–Yates from the last index down: for `i` in `(1..len).rev()`,
//!   swap `i` with `below(i + 1)`.

use rand_chacha::ChaCha8Rng;
use rand_core::{RngCore, SeedableRng};

/// A seeded deterministic random source (see the module documentation for the exact
/// algorithm).
#[derive(Clone, Debug)]
pub struct Rng(ChaCha8Rng);

impl Rng {
    /// The stream for `seed`.
    pub fn new(seed: u64) -> Self {
        let mut key = [0u8; 32];
        key[..8].copy_from_slice(&seed.to_le_bytes());
        Rng(ChaCha8Rng::from_seed(key))
    }

    /// The next 64 raw bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// A uniform integer in `0..n`. `n` must be positive.
    pub fn below(&mut self, n: u64) -> u64 {
        assert!(n > 0, "Rng::below(0)");
        let limit = n * (u64::MAX / n);
        loop {
            let x = self.next_u64();
            if x < limit {
                return x % n;
            }
        }
    }

    /// `below(n)` as a `usize`.
    pub fn index(&mut self, n: usize) -> usize {
        self.below(n as u64) as usize
    }

    /// True with probability `num / den`.
    pub fn chance(&mut self, num: u64, den: u64) -> bool {
        self.below(den) < num
    }

    /// Shuffles `items` in place (Fisher–Yates, documented order).
    pub fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.index(i + 1);
            items.swap(i, j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn deterministic_and_in_range() {
        let mut a = Rng::new(7);
        let mut b = Rng::new(7);
        for n in 1..200u64 {
            let x = a.below(n);
            assert_eq!(x, b.below(n));
            assert!(x < n);
        }
        assert_ne!(Rng::new(1).next_u64(), Rng::new(2).next_u64());
    }

    /// Pins the stream so an accidental change of algorithm or seeding fails loudly;
    /// ports compare against these numbers.
    #[test]
    fn pinned_stream() {
        let mut r = Rng::new(0);
        let first: Vec<u64> = (0..3).map(|_| r.next_u64()).collect();
        assert_eq!(
            first,
            [
                15438444565445410878,
                11647726043916688255,
                4287315583106450476
            ]
        );
        let mut r = Rng::new(42);
        let picks: Vec<u64> = (0..8).map(|_| r.below(10)).collect();
        assert_eq!(picks, [9, 9, 2, 2, 2, 5, 3, 3]);
    }
}
