//! A journal of typed operations (contractions and flips) that undoes any interleaving of
//! them exactly, newest first.
//!
//! # Why two undo logs
//! [`History`] is the contraction stack `S` of the RS paper: compact, and what the
//! irreducible algorithms return. Its undo is slot-exact, so it is only sound on the very
//! state its newest record left; a flip in between would make it write stale slots. The
//! [state stamp](crate::Triangulation::state) makes that a refused undo
//! ([`crate::core::UndoError`]) instead of a silent corruption.
//!
//! A [`Journal`] records contractions *and* flips in one order and undoes them in reverse,
//! each exactly, so callers that mix the two (tests, local search, interactive tools) can
//! always get back to the input.
//!
//! # How the tri-quad expansion interleaves splits and flips (decision)
//! The expansion of the tri-quad paper (Alg. 3.1–3.4) splits vertices in the reverse
//! order of the RS contractions and flips edges in between. We follow the paper's own
//! data design rather than re-deriving splits from a flipped star: the working
//! triangulation `T` only ever changes by exact undo of the RS [`History`] (each guarded),
//! and the flips are *flags* on dense edge numbers ([`crate::core::EdgeNumbering`],
//! which revives numbers on undo), exactly as the paper keeps a `flipped` flag in each
//! DCEL edge record ("K is never built; it is recovered from T plus the flags"). The
//! flipped triangulation `K` is materialised once at the end by [`Triangulation::flip_at`]
//! on the flagged edges. This keeps every split slot-exact and checkable (the guard never
//! fires in a correct expansion), and the matching `M` is a flag array on the same
//! numbers. The alternative, re-deriving each split from the current (flipped) star, needs
//! a side rule that survives flips of `[u, z]` edges and loses exact replay; we did not
//! take it.

use super::contract::{ContractError, ContractionRecord, History, UndoError};
use super::flip::{FlipError, FlipRecord};
use super::ids::{Corner, VertexId};
use super::tri::Triangulation;

/// One journal entry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// A contraction (its record lives in the journal's [`History`]).
    Contraction(ContractionRecord),
    /// A flip.
    Flip(FlipRecord),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Contraction,
    Flip,
}

/// Contractions and flips in the order they were applied, undone exactly in reverse.
///
/// Guarantee: if every change of the triangulation since the journal was created went
/// through the journal, [`Self::undo_all`] restores it exactly (ids, corner slots,
/// opposite table, degrees, state stamp). A change made behind the journal's back makes
/// [`Self::undo`] refuse ([`UndoError::Modified`]) instead of corrupting the surface.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Journal {
    contractions: History,
    flips: Vec<FlipRecord>,
    order: Vec<Kind>,
}

impl Journal {
    /// An empty journal.
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of recorded operations.
    pub fn len(&self) -> usize {
        self.order.len()
    }

    /// Whether nothing is recorded.
    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// Contracts `[u, v]` keeping `u` if it passes the link condition
    /// ([`Triangulation::contract`]), and records it.
    pub fn contract(
        &mut self,
        tri: &mut Triangulation,
        u: VertexId,
        v: VertexId,
    ) -> Result<ContractionRecord, ContractError> {
        let rec = tri.contract(u, v, &mut self.contractions)?;
        self.order.push(Kind::Contraction);
        Ok(rec)
    }

    /// Contracts the edge opposite `c` ([`Triangulation::contract_at`]) and records it.
    pub fn contract_at(
        &mut self,
        tri: &mut Triangulation,
        c: Corner,
    ) -> Result<ContractionRecord, ContractError> {
        let rec = tri.contract_at(c, &mut self.contractions)?;
        self.order.push(Kind::Contraction);
        Ok(rec)
    }

    /// Flips the edge opposite `c` ([`Triangulation::flip_at`]) and records it.
    pub fn flip_at(&mut self, tri: &mut Triangulation, c: Corner) -> Result<FlipRecord, FlipError> {
        let rec = tri.flip_at(c)?;
        self.flips.push(rec);
        self.order.push(Kind::Flip);
        Ok(rec)
    }

    /// Flips `[u, v]` ([`Triangulation::flip`]) and records it.
    pub fn flip(
        &mut self,
        tri: &mut Triangulation,
        u: VertexId,
        v: VertexId,
    ) -> Result<FlipRecord, FlipError> {
        let Some([c, _]) = tri.edge_corners(u, v) else {
            return Err(FlipError::NotAnEdge { u, v });
        };
        self.flip_at(tri, c)
    }

    /// Undoes the newest operation exactly. `Ok(None)` when the journal is empty; an
    /// error, with nothing changed, when `tri` is not in the state that operation left.
    /// O(1) for a flip, O(d_v) for a contraction.
    pub fn undo(&mut self, tri: &mut Triangulation) -> Result<Option<Op>, UndoError> {
        match self.order.last() {
            None => Ok(None),
            Some(Kind::Contraction) => {
                let rec = self.contractions.try_undo(tri)?;
                self.order.pop();
                Ok(rec.map(Op::Contraction))
            }
            Some(Kind::Flip) => {
                let rec = *self.flips.last().expect("order and flips agree");
                tri.unflip(&rec).map_err(|_| UndoError::Modified {
                    u: rec.old_edge[0],
                    v: rec.old_edge[1],
                    expected: rec.state_after(),
                    found: tri.state(),
                })?;
                self.flips.pop();
                self.order.pop();
                Ok(Some(Op::Flip(rec)))
            }
        }
    }

    /// Undoes every operation, newest first; stops at the first refusal.
    pub fn undo_all(&mut self, tri: &mut Triangulation) -> Result<(), UndoError> {
        while self.undo(tri)?.is_some() {}
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::icosahedron;

    /// `len` and `is_empty` count the operations recorded and not yet undone, and
    /// `undo_all` restores the surface and empties the journal.
    #[test]
    fn length_emptiness_and_undo_all() {
        let m = icosahedron();
        let t0 = Triangulation::from_faces(m.vertex_count, &m.faces).expect("icosahedron");
        let mut t = t0.clone();
        let mut j = Journal::new();
        assert!(j.is_empty());
        assert_eq!(j.len(), 0);
        j.flip_at(&mut t, Corner(0))
            .expect("an icosahedron edge flips");
        assert!(!j.is_empty());
        assert_eq!(j.len(), 1);
        let (u, v) = (VertexId(3), t.link(VertexId(3)).next().expect("neighbour"));
        j.contract(&mut t, u, v).expect("contractible");
        j.flip_at(&mut t, Corner(6)).expect("flips");
        assert_eq!(j.len(), 3);
        assert_ne!(t, t0);
        j.undo(&mut t).expect("the state the flip left");
        assert_eq!(j.len(), 2);
        j.undo_all(&mut t).expect("every state as left");
        assert!(j.is_empty());
        assert_eq!(t, t0);
    }
}
