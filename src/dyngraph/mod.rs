//! Dynamic graph structures on `u32` ids in flat arrays, independent of surfaces: they
//! know nothing of triangulations or of the tri-quad conversion, which uses them
//! (`quad::frink`'s strategies).
//!
//! | structure | guarantee | cost (amortised) | memory |
//! |---|---|---|---|
//! | [`Hdt`] (module `hdt`): Holm–de Lichtenberg–Thorup fully dynamic connectivity, JACM 48(4) 2001, Sec. 2 | after every update a spanning forest of the current multigraph (each change reported as a [`ForestChange`]); exact [`Hdt::connected`]; the same changes for the same updates (no randomness, independent of queries) | O(log² n) per update, O(log n) per query | O(m + n log n) nodes of 24 bytes; 137 bytes per vertex measured on a Frink-like workload of cubic graphs |
//! | Euler-tour trees (module `ett`, crate-internal): Henzinger–King, as HDT use them | each tree's Euler tour kept exactly under link and cut, with subtree vertex counts and two searchable flags | O(log n) per operation | 24 bytes per node |
//! | [`Lct`] (module `lct`): Sleator–Tarjan link–cut trees, splay-based | the represented forest and its `i32` node values exactly as a naive forest would keep them, under link, cut, re-rooting, path add and path minimum | O(log n) per operation | 28 bytes per node |
//! | [`PlainLct`] (module `lct`) | [`Lct`] without values: link, cut, re-rooting and the LCAs of a walk | O(log n) per operation | 16 bytes per node |
//! | [`TwoEdge`] (module `two_edge`): fully dynamic 2-edge-connectivity, HDT Sec. 3's cover idea with exact cover counts and without its levels | exact [`TwoEdge::connected`] and [`TwoEdge::two_edge_connected`] after every update | O(log n) per query, insertion and non-tree deletion; O(s + k log n) per tree-edge deletion (`s` the degree sum of the smaller side of the cut, `k` the edges covering it): **not** polylogarithmic | 21 bytes per edge id, 28 per vertex and per tree edge, plus the incidence lists |
//!
//! The Euler-tour and link–cut trees share one splay-tree core (module `splay`): the
//! bottom-up rotation and splay and the sequence operations (join, split at a root,
//! extreme node, balanced build), generic over the node type, which brings its own
//! aggregate and lazy tags; two constants of the node type compile path-parents and
//! lazy tags in only where they are used. Each module's documentation gives the algorithm, the sources,
//! the departures from them and the measurements; each is tested against a naive
//! reference (adjacency lists and breadth-first search) after every operation of random
//! sequences.
//!
//! Preconditions (an edge id not live before its insertion, ends in different trees for
//! a link, ...) are stated on each method. [`Hdt`] ignores a call that breaks them in a
//! release build and [`TwoEdge`] panics; the link–cut trees check theirs with
//! `debug_assert!` only (they are the inner loop of their callers), so in a release build
//! a broken precondition leaves the forest unspecified.

pub(crate) mod ett;
pub(crate) mod hdt;
pub(crate) mod lct;
mod splay;
pub(crate) mod two_edge;

pub use hdt::{ForestChange, Hdt, HdtStats};
pub use lct::{Lct, PlainLct};
pub use two_edge::{TwoEdge, TwoEdgeCounters};
