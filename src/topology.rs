//! The topological type of a connected closed surface: one description (χ, orientability,
//! genus, name) shared by every report, so that they all name surfaces the same way.

use std::fmt;

use crate::core::Triangulation;
use crate::gen::SurfaceKind;

/// The topological type of a connected closed surface.
///
/// Guarantees that it describes a surface that exists: by the classification theorem a
/// connected closed surface is determined by its Euler characteristic χ and its
/// orientability, with χ = 2 − 2g (g ≥ 0 handles) if orientable and χ = 2 − h (h ≥ 1
/// cross-caps) if not. Every constructor enforces exactly these constraints.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct SurfaceType {
    euler_characteristic: i64,
    orientable: bool,
}

impl SurfaceType {
    /// The surface with Euler characteristic `euler_characteristic` and the given
    /// orientability, or `None` if there is none: χ > 2, odd χ for an orientable surface,
    /// or χ = 2 for a non-orientable one.
    pub fn new(euler_characteristic: i64, orientable: bool) -> Option<Self> {
        let valid = if orientable {
            euler_characteristic <= 2 && euler_characteristic % 2 == 0
        } else {
            euler_characteristic <= 1
        };
        valid.then_some(SurfaceType {
            euler_characteristic,
            orientable,
        })
    }

    /// The type of the surface `t` triangulates. O(V + F) (orientability is computed).
    pub fn of(t: &Triangulation) -> Self {
        // A Triangulation is a connected closed surface by construction, so its χ and
        // orientability always satisfy the constraints of `new`.
        SurfaceType {
            euler_characteristic: t.euler_characteristic(),
            orientable: t.is_orientable(),
        }
    }

    /// Euler characteristic χ = V − E + F.
    pub fn euler_characteristic(self) -> i64 {
        self.euler_characteristic
    }

    /// Whether the surface is orientable.
    pub fn is_orientable(self) -> bool {
        self.orientable
    }

    /// Euler genus 2 − χ: twice the genus if orientable, the number of cross-caps if not.
    pub fn euler_genus(self) -> i64 {
        2 - self.euler_characteristic
    }

    /// The genus in the classification: the number of handles g of an orientable
    /// surface, the number of cross-caps h of a non-orientable one.
    pub fn genus(self) -> i64 {
        if self.orientable {
            self.euler_genus() / 2
        } else {
            self.euler_genus()
        }
    }

    /// The number of handles g if the surface is orientable, `None` otherwise.
    pub fn orientable_genus(self) -> Option<i64> {
        self.orientable.then(|| self.euler_genus() / 2)
    }

    /// The number of cross-caps h if the surface is non-orientable, `None` otherwise.
    pub fn crosscaps(self) -> Option<i64> {
        (!self.orientable).then(|| self.euler_genus())
    }

    /// The generator's description of this surface (`None` only if the genus does not
    /// fit a `u32`).
    pub fn kind(self) -> Option<SurfaceKind> {
        let n = u32::try_from(self.genus()).ok()?;
        Some(if self.orientable {
            SurfaceKind::Orientable(n)
        } else {
            SurfaceKind::NonOrientable(n)
        })
    }

    /// A short English name: `sphere (genus 0)`, `torus (genus 1)`, `orientable genus g`,
    /// `non-orientable genus 1 (projective plane)`, `non-orientable genus 2 (Klein
    /// bottle)`, `non-orientable genus h`. The same text as [`fmt::Display`].
    pub fn name(self) -> String {
        self.to_string()
    }
}

impl fmt::Display for SurfaceType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // These strings are part of the command line's output; keep them stable.
        match (self.orientable, self.genus()) {
            (true, 0) => f.write_str("sphere (genus 0)"),
            (true, 1) => f.write_str("torus (genus 1)"),
            (true, g) => write!(f, "orientable genus {g}"),
            (false, 1) => f.write_str("non-orientable genus 1 (projective plane)"),
            (false, 2) => f.write_str("non-orientable genus 2 (Klein bottle)"),
            (false, h) => write!(f, "non-orientable genus {h}"),
        }
    }
}

impl From<SurfaceKind> for SurfaceType {
    /// The type a generator's [`SurfaceKind`] asks for. A `NonOrientable(0)` (which names
    /// no surface) maps to the projective plane, the smallest non-orientable surface, as
    /// the generator does.
    fn from(kind: SurfaceKind) -> Self {
        match kind {
            SurfaceKind::Orientable(g) => SurfaceType {
                euler_characteristic: 2 - 2 * i64::from(g),
                orientable: true,
            },
            SurfaceKind::NonOrientable(h) => SurfaceType {
                euler_characteristic: 2 - i64::from(h.max(1)),
                orientable: false,
            },
        }
    }
}

/// Serialised as the four fields the reports print, in this order:
/// `euler_characteristic`, `orientable`, `genus` (the orientable genus, `null` for a
/// non-orientable surface) and `euler_genus` (2 − χ). The name is left out: it follows
/// from these.
#[cfg(feature = "serde")]
impl serde::Serialize for SurfaceType {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let mut s = serializer.serialize_struct("SurfaceType", 4)?;
        s.serialize_field("euler_characteristic", &self.euler_characteristic)?;
        s.serialize_field("orientable", &self.orientable)?;
        s.serialize_field("genus", &self.orientable_genus())?;
        s.serialize_field("euler_genus", &self.euler_genus())?;
        s.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;

    fn of_mesh(m: &crate::TriMesh) -> SurfaceType {
        SurfaceType::of(&Triangulation::from_faces(m.vertex_count, &m.faces).expect("surface"))
    }

    #[test]
    fn standard_surfaces_are_classified() {
        let cases = [
            (gen::tetrahedron(), 2, true, 0, "sphere (genus 0)"),
            (gen::torus7(), 0, true, 1, "torus (genus 1)"),
            (
                gen::projective_plane6(),
                1,
                false,
                1,
                "non-orientable genus 1 (projective plane)",
            ),
            (
                gen::klein_bottle(),
                0,
                false,
                2,
                "non-orientable genus 2 (Klein bottle)",
            ),
        ];
        for (mesh, chi, orientable, genus, name) in cases {
            let s = of_mesh(&mesh);
            assert_eq!(s.euler_characteristic(), chi, "{name}");
            assert_eq!(s.is_orientable(), orientable, "{name}");
            assert_eq!(s.genus(), genus, "{name}");
            assert_eq!(s.euler_genus(), 2 - chi, "{name}");
            assert_eq!(s.name(), name);
            assert_eq!(Some(s), SurfaceType::new(chi, orientable));
        }
    }

    #[test]
    fn higher_genus_names_and_fields() {
        let s = SurfaceType::new(-4, true).expect("genus 3");
        assert_eq!(s.name(), "orientable genus 3");
        assert_eq!(
            (s.genus(), s.orientable_genus(), s.crosscaps()),
            (3, Some(3), None)
        );
        let n = SurfaceType::new(-1, false).expect("3 cross-caps");
        assert_eq!(n.name(), "non-orientable genus 3");
        assert_eq!(
            (n.genus(), n.orientable_genus(), n.crosscaps()),
            (3, None, Some(3))
        );
        assert_eq!(n.euler_genus(), 3);
    }

    #[test]
    fn impossible_surfaces_are_rejected() {
        assert_eq!(SurfaceType::new(3, true), None);
        assert_eq!(SurfaceType::new(1, true), None);
        assert_eq!(SurfaceType::new(2, false), None);
        assert_eq!(SurfaceType::new(4, false), None);
        assert!(SurfaceType::new(-7, false).is_some());
    }

    #[test]
    fn generator_kinds_round_trip() {
        for kind in [
            SurfaceKind::Orientable(0),
            SurfaceKind::Orientable(5),
            SurfaceKind::NonOrientable(1),
            SurfaceKind::NonOrientable(4),
        ] {
            let s = SurfaceType::from(kind);
            assert_eq!(s.euler_characteristic(), kind.euler_characteristic());
            assert_eq!(s.is_orientable(), kind.is_orientable());
            assert_eq!(s.kind(), Some(kind));
        }
    }

    #[test]
    fn random_surfaces_have_the_requested_type() {
        for kind in [SurfaceKind::Orientable(2), SurfaceKind::NonOrientable(3)] {
            let t = gen::random(&gen::RandomParams {
                surface: kind,
                min_faces: 200,
                flip_percent: 30,
                seed: 1,
            });
            assert_eq!(SurfaceType::of(&t), SurfaceType::from(kind));
        }
    }
}
