//! Irreducible triangulations: contract edges under the link condition until none is
//! contractible (RS paper). Three algorithms sharing one result type:
//!
//! - [`rs`]: Ramaswami–Siqueira (Alg. 4.1–4.7), every edge tested at most once per
//!   processed vertex, O(g² + g·n);
//! - [`schipper`]: Schipper's algorithm (Sec. 3), lowest-degree loose vertex first,
//!   neighbour dictionaries, O(n log n + g log n + g⁴);
//! - [`brute`]: the randomized brute force of Sec. 5 (shuffle, pass, retry failures).
//!
//! All three return a [`Reduction`]: the irreducible triangulation with the input's
//! vertex ids, the contraction [`History`] (the stack S) that [`Reduction::expand`]
//! replays, and [`Stats`] with the paper's counters ℓ and ε.

use std::time::Instant;

use crate::core::{ContractionRecord, Corner, EdgeIds, History, Triangulation};

pub mod brute;
pub mod rs;
pub mod schipper;

/// Which algorithm to run.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash, Default)]
pub enum Algorithm {
    /// Ramaswami–Siqueira (the default).
    #[default]
    Rs,
    /// Schipper.
    Schipper,
    /// Randomized brute force.
    Brute,
}

impl Algorithm {
    /// Every algorithm, in the order the documentation lists them.
    pub const ALL: [Algorithm; 3] = [Algorithm::Rs, Algorithm::Schipper, Algorithm::Brute];

    /// The short name used on the command line, in Python and in JSON (`rs`, `schipper`,
    /// `brute`; `Display` writes it, `FromStr` reads it).
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Rs => "rs",
            Algorithm::Schipper => "schipper",
            Algorithm::Brute => "brute",
        }
    }

    /// One line on what the algorithm is (the command line's help).
    pub fn summary(self) -> &'static str {
        match self {
            Algorithm::Rs => "Ramaswami–Siqueira",
            Algorithm::Schipper => "Schipper",
            Algorithm::Brute => "Randomized brute force",
        }
    }
}

crate::names::named_choice!(Algorithm, "reduction algorithm");

/// Counters and timings of one reduction (the quantities of the RS paper's Tables 6–11).
#[derive(Clone, Debug, Default, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Stats {
    /// Vertices of the input.
    pub vertices_in: usize,
    /// Edges of the input.
    pub edges_in: usize,
    /// Faces of the input.
    pub faces_in: usize,
    /// Vertices of the output.
    pub vertices_out: usize,
    /// Faces of the output.
    pub faces_out: usize,
    /// ℓ: link condition tests carried out (the degree-3 shortcut of Prop. 6 counts as a
    /// test for S and BF, which test every edge they examine, and not for RS, which
    /// decides it without testing, as the paper counts).
    pub link_tests: u64,
    /// ε: edges tested more than once. Edge identity follows the DCEL of the paper: an
    /// edge `[v, z]` renamed `[u, z]` by a contraction is the same edge, and the merged
    /// `[u, x]` keeps the identity of the old `[u, x]`.
    pub edges_tested_more_than_once: u64,
    /// Contractions carried out.
    pub contractions: u64,
    /// Seconds spent in the algorithm proper (no I/O, no construction).
    pub seconds: f64,
}

/// The result of a reduction.
#[derive(Clone, Debug)]
pub struct Reduction {
    /// Which algorithm produced it.
    pub algorithm: Algorithm,
    /// The irreducible triangulation. Vertex and face ids are the input's (removed ones
    /// are simply absent); see [`Triangulation::vertices`].
    pub tri: Triangulation,
    /// Every contraction, oldest first.
    pub history: History,
    /// Counters.
    pub stats: Stats,
}

impl Reduction {
    /// Replays the history backwards by vertex splits: gives back the input exactly
    /// (same ids, same corner slots). O(n).
    pub fn expand(&self) -> Triangulation {
        let mut t = self.tri.clone();
        let mut h = self.history.clone();
        h.undo_all(&mut t);
        t
    }
}

/// Options shared by the three algorithms.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Seed of the documented stream ([`crate::rng`]); used by the brute force's shuffle
    /// (RS and Schipper are deterministic without it).
    pub seed: u64,
    /// Track edge identities to count ε ([`Stats::edges_tested_more_than_once`], which
    /// stays 0 without it). Instrumentation: costs 8 bytes per face and a little time, so
    /// it is off by default; the command line and the paper's tables turn it on.
    pub count_retests: bool,
    /// Keep the contraction records ([`Reduction::history`]), which undo the reduction
    /// and replay it as vertex splits. Without them the history comes back empty and
    /// the reduction needs 88 bytes less per contraction (about 44 bytes per input
    /// triangle); the output and every counter are the same.
    pub keep_history: bool,
}

impl Default for Options {
    /// Seed 0, no instrumentation (`count_retests: false`), history kept.
    fn default() -> Self {
        Options {
            seed: 0,
            count_retests: false,
            keep_history: true,
        }
    }
}

/// Runs `algorithm` on `tri` (consumed: the reduction happens in place).
pub fn reduce(tri: Triangulation, algorithm: Algorithm, options: &Options) -> Reduction {
    reduce_observed(tri, algorithm, options, &mut crate::progress::ignore)
}

/// [`reduce`], reporting progress inside the reduction to `observer` (see
/// [`crate::progress`]; RS and Schipper count settled vertices, the brute force the
/// edges visited in its current pass). The result is the same as [`reduce`]'s; the
/// reports cost one comparison per step.
pub fn reduce_observed(
    tri: Triangulation,
    algorithm: Algorithm,
    options: &Options,
    observer: &mut dyn FnMut(crate::progress::Progress),
) -> Reduction {
    match algorithm {
        Algorithm::Rs => rs::reduce_observed(tri, options, observer),
        Algorithm::Schipper => schipper::reduce_observed(tri, options, observer),
        Algorithm::Brute => brute::reduce_observed(tri, options, observer),
    }
}

/// Counts ε (edges tested more than once) over contractions, with the edge identity of
/// [`crate::core::EdgeNumbering`] (the DCEL of the paper: the merged `[u, x]` keeps its
/// identity), kept by its per-corner half [`EdgeIds`].
#[derive(Clone, Debug, Default)]
pub struct RetestCounter {
    numbers: Option<EdgeIds>,
    tests: Vec<u8>,
    more_than_once: u64,
}

impl RetestCounter {
    /// A counter for `tri`; a disabled one does nothing and allocates nothing.
    pub fn new(tri: &Triangulation, enabled: bool) -> Self {
        if !enabled {
            return RetestCounter::default();
        }
        let numbers = EdgeIds::new(tri);
        RetestCounter {
            tests: vec![0; numbers.capacity()],
            numbers: Some(numbers),
            more_than_once: 0,
        }
    }

    /// Records one link test of the edge opposite corner `c`.
    #[inline]
    pub fn tested(&mut self, c: Corner) {
        let Some(numbers) = &self.numbers else {
            return;
        };
        let t = &mut self.tests[numbers.id(c).index()];
        if *t == 1 {
            self.more_than_once += 1;
        }
        *t = t.saturating_add(1);
    }

    /// Updates identities after a contraction.
    #[inline]
    pub fn contracted(&mut self, rec: &ContractionRecord) {
        if let Some(numbers) = &mut self.numbers {
            numbers.contracted(rec);
        }
    }

    /// Whether identities are tracked.
    pub fn is_enabled(&self) -> bool {
        self.numbers.is_some()
    }

    /// ε so far.
    pub fn more_than_once(&self) -> u64 {
        self.more_than_once
    }
}

/// Fills the size fields of [`Stats`] and the timing.
pub(crate) fn finish(
    algorithm: Algorithm,
    tri: Triangulation,
    history: History,
    contractions: u64,
    mut stats: Stats,
    started: Instant,
) -> Reduction {
    stats.seconds = started.elapsed().as_secs_f64();
    stats.vertices_out = tri.vertex_count();
    stats.faces_out = tri.face_count();
    stats.contractions = contractions;
    Reduction {
        algorithm,
        tri,
        history,
        stats,
    }
}

/// [`Stats`] with the input sizes filled in.
pub(crate) fn start_stats(tri: &Triangulation) -> Stats {
    Stats {
        vertices_in: tri.vertex_count(),
        edges_in: tri.edge_count(),
        faces_in: tri.face_count(),
        ..Stats::default()
    }
}

#[cfg(test)]
mod tests {
    use super::RetestCounter;
    use crate::core::{Triangulation, VertexId};

    /// The counter counts only when enabled, and counts an edge once however often it is
    /// retested (ε is a number of edges, not of tests).
    #[test]
    fn the_retest_counter_counts_retested_edges_only_when_enabled() {
        let faces = [[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]];
        let tri = Triangulation::from_faces(4, &faces).expect("the tetrahedron");
        let c = tri.corner_of(VertexId(0));
        let d = c.next();

        let mut off = RetestCounter::new(&tri, false);
        assert!(!off.is_enabled());
        for _ in 0..3 {
            off.tested(c);
        }
        assert_eq!(off.more_than_once(), 0);

        let mut on = RetestCounter::new(&tri, true);
        assert!(on.is_enabled());
        on.tested(c);
        on.tested(d);
        assert_eq!(on.more_than_once(), 0, "two different edges, once each");
        on.tested(c);
        assert_eq!(on.more_than_once(), 1);
        on.tested(c);
        on.tested(c);
        assert_eq!(on.more_than_once(), 1, "the same edge counts once");
        on.tested(d);
        assert_eq!(on.more_than_once(), 2);
    }
}
