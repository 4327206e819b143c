//! Work in progress.

use super::{Options, Reduction};
use crate::core::Triangulation;

/// Not yet written.
pub fn reduce(_tri: Triangulation, _options: &Options) -> Reduction {
    todo!("brute")
}
