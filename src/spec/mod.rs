//! The executable specification: the RS paper's lemmas and propositions as runtime
//! checks, called by the algorithms at the points the statements name.
//!
//! Compiled in under `debug_assertions` or the cargo feature `invariants`; otherwise
//! every hook is an empty inline function and costs nothing. A failing check panics with
//! the statement's name, the vertices involved and the time stamp `ts`.
//!
//! Cost policy: checks are local to the operation (the processed vertex and its
//! neighbourhood). Where a check would be quadratic in a degree, it runs in full when the
//! degree is at most [`FULL_CHECK_DEGREE`] and on a bounded prefix otherwise; the
//! full-graph oracles (petgraph critical cycles, naive irreducibility) run in the tests.

/// Degree (or list length) up to which a local check runs in full.
pub const FULL_CHECK_DEGREE: usize = 64;

/// Whether the checks are compiled in.
pub const ENABLED: bool = cfg!(any(debug_assertions, feature = "invariants"));

pub mod oracle;
