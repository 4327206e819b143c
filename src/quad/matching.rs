//! The graph route ("graph-matching approach" of Lemos–Ramaswami–Siqueira, §3.2): the
//! whole perfect matching of the dual graph is computed by a general matching algorithm,
//! with no greedy start.
//!
//! # Guarantee
//! [`initial_pairing`] returns the *empty* pairing of a triangulation; completing it with
//! [`super::augment::complete`] (Edmonds with blossoms, multi-source phases) gives a
//! perfect pairing of every closed triangulation (Petersen). So the `matching` algorithm
//! is exactly `augment::complete` from empty: its initial step pairs nothing (statistics
//! (b) = 0 %, (c) = F) and all the work is reported as completion.
//!
//! # Where the paper is silent / differs
//! The paper's graph route is Diks–Stańczyk (a Frink-reduction algorithm built on dynamic
//! connectivity), which always returns a perfect matching. This module replaces it by the
//! project's Edmonds completion run from empty, whose first step (the linear pass of
//! [`super::augment`]) is a greedy maximal matching in face-id order followed by local
//! length-3 repairs, and whose phases then complete it. Deterministic: the output depends
//! on the triangulation's face ids and slot order only. Complexity: O(F) here; the
//! completion's complexity is documented in [`super::augment`] (worst case O(F²·α(F)),
//! near-linear in practice).

use super::Pairing;
use crate::core::Triangulation;

/// The empty pairing of `tri` (capacity `tri.face_capacity()`): the start of the graph
/// route, whose whole perfect matching is then computed by
/// [`super::augment::complete`]. O(F).
pub fn initial_pairing(tri: &Triangulation) -> Pairing {
    Pairing::new(tri.face_capacity())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::{random, RandomParams, SurfaceKind};
    use crate::quad::augment::complete;

    #[test]
    fn the_graph_route_starts_empty_and_ends_perfect() {
        let t = random(&RandomParams {
            surface: SurfaceKind::NonOrientable(3),
            min_faces: 600,
            flip_percent: 40,
            seed: 3,
        })
        .expect("a random surface within the limits");
        let mut p = initial_pairing(&t);
        assert!(p.is_empty());
        assert_eq!(p.face_capacity(), t.face_capacity());
        assert_eq!(p.unpaired(&t).count(), t.face_count());
        let c = complete(&t, &mut p).expect("a pairing of the triangulation");
        assert!(p.is_perfect(&t));
        assert_eq!(p.check(&t), Ok(()));
        assert_eq!(c.augmenting_paths, t.face_count() / 2);
    }
}
