//! The simple greedy initial pairing SG (tri-quad paper, Sec. 3.1, first two
//! paragraphs; `matching-notes.md` §1.1): a maximal matching of the dual graph, built by
//! taking the edges one at a time in a seeded random order.
//!
//! # Guarantee
//! [`initial_pairing`] returns a pairing of edge-adjacent faces that is *maximal*: no
//! edge of the triangulation has both of its faces unpaired. It is usually not perfect:
//! the paper measures about 87% of the triangles paired (α ∈ [0.12, 0.13] unpaired, Table
//! 4.3); the unpaired ones are left to the completion by augmenting paths.
//!
//! # The paper's rule, and how it is implemented
//! Every edge is *free* or *locked*, all free at first. The edges are selected one at a
//! time; a free edge pairs its two triangles and locks their remaining edges, a locked edge
//! is discarded. Each edge is selected exactly once, so an edge is locked exactly when
//! one of its two triangles is already paired (the edge that paired a triangle is never
//! selected again). The implementation therefore keeps no separate lock bits: "free" is
//! tested as "both faces unpaired" on the [`Pairing`] itself. This is the same decision at
//! every step, so the output is the paper's.
//!
//! # Determinism (reproducible by ports)
//! The output is a function of the triangulation (its corner table, ids as they are) and
//! [`Options::seed`]:
//! 1. the edges are listed in [`Triangulation::edges`] order (live faces by increasing id,
//!    within a face its corners by slot, each edge reported from the smaller of its two
//!    opposite corners); an edge is its reported corner `c`, its faces are `c.face()` and
//!    `opposite(c).face()`;
//! 2. that list is shuffled by [`Rng::shuffle`] on `Rng::new(seed)` (Fisher–Yates from the
//!    last index down, `E − 1` draws of [`Rng::below`]; no other draw is made);
//! 3. the shuffled list is scanned from index 0 up, pairing every edge whose two faces are
//!    both unpaired.
//!
//! Only corners and face adjacency are used, never slot parity or face orientation, so
//! orientable and non-orientable surfaces are handled alike.
//!
//! # Complexity
//! Θ(E) = Θ(F) time (one shuffle, one scan); `E` corners of extra space plus the pairing.

use super::{Options, Pairing};
use crate::core::{Corner, Triangulation};
use crate::rng::Rng;

/// The SG pairing of `tri` for `options.seed`: a maximal matching of the dual graph (no
/// edge with both faces unpaired), deterministic for (`tri`, seed); see the module
/// documentation for the exact order. Θ(F).
pub fn initial_pairing(tri: &Triangulation, options: &Options) -> Pairing {
    let mut edges: Vec<Corner> = tri.edges().map(|(_, _, c)| c).collect();
    Rng::new(options.seed).shuffle(&mut edges);
    let mut pairing = Pairing::new(tri.face_capacity());
    for c in edges {
        let (f, g) = (c.face(), tri.opposite(c).face());
        // Free iff neither triangle is paired yet (see the module documentation).
        if !pairing.is_paired(f) && !pairing.is_paired(g) {
            pairing.pair(f, g);
        }
    }
    pairing
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::{octahedron, random, tetrahedron, RandomParams, SurfaceKind};

    fn from_mesh(m: &crate::mesh::TriMesh) -> Triangulation {
        Triangulation::from_faces(m.vertex_count, &m.faces).expect("closed surface")
    }

    #[test]
    fn every_maximal_matching_of_the_tetrahedron_is_perfect() {
        // The dual of the tetrahedron is K4: after any first pair, the other two faces
        // are adjacent, so SG must pair everything whatever the order.
        let t = from_mesh(&tetrahedron());
        for seed in 0..20 {
            let p = initial_pairing(&t, &Options { seed });
            assert_eq!(p.check(&t), Ok(()));
            assert!(p.is_perfect(&t), "seed {seed}");
        }
    }

    #[test]
    fn maximal_and_seeded() {
        let o = from_mesh(&octahedron());
        for seed in 0..10 {
            let p = initial_pairing(&o, &Options { seed });
            assert_eq!(p.check(&o), Ok(()));
            for (_, _, c) in o.edges() {
                assert!(
                    p.is_paired(c.face()) || p.is_paired(o.opposite(c).face()),
                    "seed {seed}: free edge left"
                );
            }
        }
        let t = random(&RandomParams {
            surface: SurfaceKind::NonOrientable(3),
            min_faces: 400,
            flip_percent: 30,
            seed: 5,
        })
        .expect("a random surface within the limits");
        let a = initial_pairing(&t, &Options { seed: 1 });
        assert_eq!(a, initial_pairing(&t, &Options { seed: 1 }));
        assert_ne!(a, initial_pairing(&t, &Options { seed: 2 }));
    }
}
