//! Newtype indices into the flat arrays of [`crate::Triangulation`].
//!
//! All three are `u32` wrappers: the core stores 3 corners per face, so a
//! triangulation has at most [`MAX_FACES`] faces and [`MAX_VERTICES`] vertices.

use std::fmt;

/// Sentinel stored in the flat arrays for "no element" (a removed vertex or face).
pub(crate) const NONE: u32 = u32::MAX;

/// The largest vertex count the core can index (`u32::MAX` is reserved as a sentinel).
pub const MAX_VERTICES: usize = (u32::MAX - 1) as usize;
/// The largest face count the core can index (3 corners per face must fit in a `u32`).
pub const MAX_FACES: usize = ((u32::MAX - 1) / 3) as usize;

/// A vertex of a [`crate::Triangulation`]. Ids are stable under every operation:
/// contraction removes one, a split adds or restores one, nothing renumbers.
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct VertexId(pub u32);

/// A triangle of a [`crate::Triangulation`]. Ids are stable like [`VertexId`]s.
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct FaceId(pub u32);

/// A corner: one vertex slot of one face, `3 * face + i` for `i` in `0..3`.
///
/// A corner also names the edge *opposite* it (the face's other two vertices), which is
/// how edges are handled in the core: an edge has exactly two opposite corners, one in
/// each of its faces, and [`crate::Triangulation::opposite`] maps one to the other.
#[derive(Copy, Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Corner(pub u32);

impl VertexId {
    /// The id as an array index.
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl FaceId {
    /// The id as an array index.
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
    /// The `i`-th corner of this face (`i` in `0..3`).
    #[inline]
    pub fn corner(self, i: u32) -> Corner {
        debug_assert!(i < 3);
        Corner(3 * self.0 + i)
    }
    /// The three corners of this face in slot order.
    #[inline]
    pub fn corners(self) -> [Corner; 3] {
        [self.corner(0), self.corner(1), self.corner(2)]
    }
}

impl Corner {
    /// The corner as an array index.
    #[inline]
    pub fn index(self) -> usize {
        self.0 as usize
    }
    /// The face this corner belongs to.
    #[inline]
    pub fn face(self) -> FaceId {
        FaceId(self.0 / 3)
    }
    /// The slot of this corner within its face (`0..3`).
    #[inline]
    pub fn slot(self) -> u32 {
        self.0 % 3
    }
    /// The next corner of the same face, cyclically (slot order, not geometric orientation).
    #[inline]
    pub fn next(self) -> Corner {
        // `(c + 1) % 3 == 0` rather than `c % 3 == 2`: the same test, which compiles to a
        // multiply and a compare (divisibility by 3) instead of a full remainder.
        if (self.0 + 1) % 3 == 0 {
            Corner(self.0 - 2)
        } else {
            Corner(self.0 + 1)
        }
    }
    /// The previous corner of the same face, cyclically.
    #[inline]
    pub fn prev(self) -> Corner {
        if self.0 % 3 == 0 {
            Corner(self.0 + 2)
        } else {
            Corner(self.0 - 1)
        }
    }
}

macro_rules! show {
    ($t:ty, $p:literal) => {
        impl fmt::Debug for $t {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!($p, "{}"), self.0)
            }
        }
        impl fmt::Display for $t {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, "{}", self.0)
            }
        }
    };
}
show!(VertexId, "v");
show!(FaceId, "f");
show!(Corner, "c");

#[cfg(test)]
mod tests {
    use super::{MAX_FACES, MAX_VERTICES, NONE};

    /// The bounds are the largest counts whose ids, and the counts themselves, stay
    /// below the sentinel: one more vertex or face would reach it.
    #[test]
    fn the_largest_counts_leave_the_sentinel_free() {
        assert!(MAX_VERTICES < NONE as usize);
        assert!(MAX_VERTICES + 1 >= NONE as usize);
        assert!(3 * MAX_FACES < NONE as usize);
        assert!(3 * (MAX_FACES + 1) >= NONE as usize);
    }
}
