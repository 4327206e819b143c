//! One call per task on a mesh: [`describe`], [`reduce`], [`quadrangulate`],
//! [`simplify`] (re-exported at the crate root).
//!
//! Each call takes a plain [`TriMesh`](crate::TriMesh) (as read by [`crate::io`] or made
//! by [`crate::gen`]) and an options struct with a [`Default`], and does the whole job the
//! command line does:
//!
//! 1. validates the faces (a located, typed [`Error`] if they are not what the task
//!    accepts: closed surfaces for `reduce` and `quadrangulate`, surfaces possibly with
//!    boundary for `simplify` and `describe`);
//! 2. splits them into connected components and runs the chosen algorithm on each, in
//!    the order of their smallest face index;
//! 3. verifies every output independently of the algorithm (unless the options turn the
//!    check off) and refuses to return an output that fails ([`Error::Unverified`]);
//! 4. reassembles one result mesh over the input's vertices, with the input's positions,
//!    ready for [`crate::io::write_mesh`].
//!
//! Progress and cancellation go through the options' [`Monitor`]. Results are
//! deterministic for a given input and options (timings aside), and identical to the
//! command line's and the Python package's, which are thin layers over these calls.

mod decimate;
mod describe;
mod error;
mod monitor;
mod quadrangulate;
mod reduce;
mod simplify;

pub use decimate::{decimate, verify_decimation, DecimateOptions, DecimateResult, MaxError};
pub use describe::{describe, ComponentDescription, Description};
pub use error::Error;
pub use monitor::{Event, Monitor, Step};
pub use quadrangulate::{
    quadrangulate, verify_quadrangulation, QuadComponent, QuadOptions, QuadResult, QuadStats,
};
pub use reduce::{
    check_irreducible, reduce, IrreducibleCheck, ReduceOptions, ReduceResult, ReduceStats,
    ReducedComponent, NAIVE_MAX_EDGES,
};
pub use simplify::{
    component_types, simplify, verify_simplification, Eps, SimplifyOptions, SimplifyResult, TypeKey,
};
