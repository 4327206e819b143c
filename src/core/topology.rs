//! The topological type of a connected compact surface, closed or with boundary: one
//! description (χ, orientability, genus, boundary loops, name) shared by every report,
//! so that they all name surfaces the same way; and [`SurfaceKind`], the closed surfaces
//! as the generators are asked for them. Part of the core (it reads a [`Triangulation`]);
//! re-exported as `contractible::topology` and `contractible::SurfaceType`.

use std::fmt;

use super::Triangulation;

/// The topological type of a connected compact surface, closed or with boundary.
///
/// Guarantees that it describes a surface that exists: by the classification theorem a
/// connected compact surface is determined by its Euler characteristic χ, its
/// orientability and its number b of boundary loops, with χ = 2 − 2g − b (g ≥ 0
/// handles) if orientable and χ = 2 − h − b (h ≥ 1 cross-caps) if not. Every
/// constructor enforces exactly these constraints. A closed surface has b = 0 and is
/// described, printed and serialised exactly as before boundaries were supported.
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct SurfaceType {
    euler_characteristic: i64,
    orientable: bool,
    boundary_loops: u32,
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
            boundary_loops: 0,
        })
    }

    /// The surface with Euler characteristic `euler_characteristic`, the given
    /// orientability and `boundary_loops` boundary loops, or `None` if there is none
    /// (when the closed surface obtained by gluing a disc into every loop, of
    /// characteristic χ + b, does not exist; see [`Self::new`]).
    pub fn with_boundary(
        euler_characteristic: i64,
        orientable: bool,
        boundary_loops: usize,
    ) -> Option<Self> {
        let b = u32::try_from(boundary_loops).ok()?;
        let capped = Self::new(euler_characteristic.checked_add(i64::from(b))?, orientable)?;
        Some(capped.with_discs_removed(b as usize))
    }

    /// This surface with `loops` more open discs removed (each one lowers χ by 1 and adds
    /// a boundary loop; orientability and genus are kept). Saturates at `u32::MAX` loops.
    pub fn with_discs_removed(self, loops: usize) -> Self {
        let loops = u32::try_from(loops).unwrap_or(u32::MAX);
        let added = loops.min(u32::MAX - self.boundary_loops);
        SurfaceType {
            euler_characteristic: self.euler_characteristic - i64::from(added),
            orientable: self.orientable,
            boundary_loops: self.boundary_loops + added,
        }
    }

    /// The closed surface obtained by gluing a disc into every boundary loop (the
    /// surface itself if it is closed).
    pub fn capped(self) -> Self {
        SurfaceType {
            euler_characteristic: self.euler_characteristic + i64::from(self.boundary_loops),
            orientable: self.orientable,
            boundary_loops: 0,
        }
    }

    /// Number of boundary loops b (0 for a closed surface).
    pub fn boundary_loops(self) -> usize {
        self.boundary_loops as usize
    }

    /// Whether the surface has no boundary.
    pub fn is_closed(self) -> bool {
        self.boundary_loops == 0
    }

    /// The type of the surface `t` triangulates. O(V + F) (orientability is computed).
    pub fn of(t: &Triangulation) -> Self {
        // A Triangulation is a connected closed surface by construction, so its χ and
        // orientability always satisfy the constraints of `new`.
        SurfaceType {
            euler_characteristic: t.euler_characteristic(),
            orientable: t.is_orientable(),
            boundary_loops: 0,
        }
    }

    /// Euler characteristic χ = V − E + F (of the surface itself, with its boundary).
    pub fn euler_characteristic(self) -> i64 {
        self.euler_characteristic
    }

    /// Whether the surface is orientable.
    pub fn is_orientable(self) -> bool {
        self.orientable
    }

    /// Euler genus 2 − χ − b: twice the genus if orientable, the number of cross-caps if
    /// not (2 − χ for a closed surface).
    pub fn euler_genus(self) -> i64 {
        2 - self.euler_characteristic - i64::from(self.boundary_loops)
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

    /// The generator's description of this surface, or of its [`Self::capped`] surface if
    /// it has boundary (`None` only if the genus does not fit a `u32`).
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
    /// bottle)`, `non-orientable genus h`; with boundary: `disc (genus 0, 1 boundary
    /// loop)`, `annulus (genus 0, 2 boundary loops)`, `Möbius band (non-orientable genus
    /// 1, 1 boundary loop)`, otherwise `orientable genus g, b boundary loops` or
    /// `non-orientable genus h, b boundary loops`. The same text as [`fmt::Display`].
    pub fn name(self) -> String {
        self.to_string()
    }
}

impl fmt::Display for SurfaceType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // These strings are part of the command line's output; keep them stable.
        let b = self.boundary_loops;
        if b > 0 {
            let loops = if b == 1 {
                "1 boundary loop".to_string()
            } else {
                format!("{b} boundary loops")
            };
            return match (self.orientable, self.genus(), b) {
                (true, 0, 1) => write!(f, "disc (genus 0, {loops})"),
                (true, 0, 2) => write!(f, "annulus (genus 0, {loops})"),
                (false, 1, 1) => write!(f, "Möbius band (non-orientable genus 1, {loops})"),
                (true, g, _) => write!(f, "orientable genus {g}, {loops}"),
                (false, h, _) => write!(f, "non-orientable genus {h}, {loops}"),
            };
        }
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

/// A closed surface named by its orientability and genus: what the generators are asked
/// for ([`crate::gen::random()`], [`crate::gen::seed_surface`]); [`SurfaceType::kind`] and
/// `From` convert between it and [`SurfaceType`].
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum SurfaceKind {
    /// The orientable surface of genus `g` (sphere for 0, torus for 1, ...).
    Orientable(u32),
    /// The non-orientable surface of Euler genus `h >= 1` (connected sum of `h`
    /// projective planes: 1 = projective plane, 2 = Klein bottle).
    NonOrientable(u32),
}

impl SurfaceKind {
    /// Euler characteristic of the surface.
    pub fn euler_characteristic(self) -> i64 {
        match self {
            SurfaceKind::Orientable(g) => 2 - 2 * g as i64,
            SurfaceKind::NonOrientable(h) => 2 - h as i64,
        }
    }

    /// Whether the surface is orientable.
    pub fn is_orientable(self) -> bool {
        matches!(self, SurfaceKind::Orientable(_))
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
                boundary_loops: 0,
            },
            SurfaceKind::NonOrientable(h) => SurfaceType {
                euler_characteristic: 2 - i64::from(h.max(1)),
                orientable: false,
                boundary_loops: 0,
            },
        }
    }
}

/// Serialised as the four fields the reports print, in this order:
/// `euler_characteristic`, `orientable`, `genus` (the orientable genus, `null` for a
/// non-orientable surface) and `euler_genus` (2 − χ − b), followed, only for a surface
/// with boundary, by `boundary_loops` (b), so that a closed surface serialises exactly
/// as before boundaries were supported. The name is left out: it follows from these.
#[cfg(feature = "serde")]
impl serde::Serialize for SurfaceType {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeStruct;
        let with_boundary = self.boundary_loops > 0;
        let mut s = serializer.serialize_struct("SurfaceType", 4 + usize::from(with_boundary))?;
        s.serialize_field("euler_characteristic", &self.euler_characteristic)?;
        s.serialize_field("orientable", &self.orientable)?;
        s.serialize_field("genus", &self.orientable_genus())?;
        s.serialize_field("euler_genus", &self.euler_genus())?;
        if with_boundary {
            s.serialize_field("boundary_loops", &self.boundary_loops)?;
        }
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
    fn surfaces_with_boundary() {
        let cases = [
            (1, true, 1, 0, "disc (genus 0, 1 boundary loop)"),
            (0, true, 2, 0, "annulus (genus 0, 2 boundary loops)"),
            (
                0,
                false,
                1,
                1,
                "Möbius band (non-orientable genus 1, 1 boundary loop)",
            ),
            (-1, true, 1, 1, "orientable genus 1, 1 boundary loop"),
            (-3, true, 5, 0, "orientable genus 0, 5 boundary loops"),
            (-2, false, 2, 2, "non-orientable genus 2, 2 boundary loops"),
        ];
        for (chi, orientable, b, genus, name) in cases {
            let s = SurfaceType::with_boundary(chi, orientable, b).expect(name);
            assert_eq!(s.name(), name);
            assert_eq!(s.genus(), genus, "{name}");
            assert_eq!(s.euler_genus(), 2 - chi - b as i64, "{name}");
            assert_eq!(s.boundary_loops(), b);
            assert!(!s.is_closed());
            let capped = s.capped();
            assert!(capped.is_closed());
            assert_eq!(capped.euler_characteristic(), chi + b as i64);
            assert_eq!(capped.genus(), genus, "{name}");
            assert_eq!(capped.with_discs_removed(b), s);
        }
        // A disc with a handle's χ but an odd Euler genus; a non-orientable sphere.
        assert_eq!(SurfaceType::with_boundary(0, true, 1), None);
        assert_eq!(SurfaceType::with_boundary(1, false, 1), None);
        assert_eq!(SurfaceType::with_boundary(2, true, 1), None);
        // No boundary: exactly `new`.
        assert_eq!(
            SurfaceType::with_boundary(-2, true, 0),
            SurfaceType::new(-2, true)
        );
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
            })
            .expect("a random surface within the limits");
            assert_eq!(SurfaceType::of(&t), SurfaceType::from(kind));
        }
    }

    /// Removing discs from a surface that already has boundary adds to its loops and
    /// lowers χ by as many, up to `u32::MAX` loops.
    #[test]
    fn removing_discs_from_a_surface_with_boundary() {
        let annulus = SurfaceType::with_boundary(0, true, 2).expect("an annulus");
        let more = annulus.with_discs_removed(3);
        assert_eq!(
            (more.euler_characteristic(), more.boundary_loops()),
            (-3, 5)
        );
        assert_eq!(more.capped(), annulus.capped());
        let most = annulus.with_discs_removed(usize::MAX);
        assert_eq!(most.boundary_loops(), u32::MAX as usize);
        assert_eq!(most.euler_characteristic(), -(i64::from(u32::MAX) - 2));
    }

    /// The serialised fields, in order, with the struct's length: `boundary_loops` only
    /// for a surface with boundary.
    #[cfg(feature = "serde")]
    #[test]
    fn serialises_the_reported_fields() {
        use serde_test::{assert_ser_tokens, Token};
        let fields = |chi: i64, genus: Option<i64>, euler_genus: i64| {
            let mut t = vec![
                Token::Str("euler_characteristic"),
                Token::I64(chi),
                Token::Str("orientable"),
                Token::Bool(genus.is_some()),
                Token::Str("genus"),
            ];
            t.extend(match genus {
                Some(g) => vec![Token::Some, Token::I64(g)],
                None => vec![Token::None],
            });
            t.extend([Token::Str("euler_genus"), Token::I64(euler_genus)]);
            t
        };
        let torus = SurfaceType::new(0, true).expect("a torus");
        let mut want = vec![Token::Struct {
            name: "SurfaceType",
            len: 4,
        }];
        want.extend(fields(0, Some(1), 2));
        want.push(Token::StructEnd);
        assert_ser_tokens(&torus, &want);

        let mobius = SurfaceType::with_boundary(0, false, 1).expect("a Möbius band");
        let mut want = vec![Token::Struct {
            name: "SurfaceType",
            len: 5,
        }];
        want.extend(fields(0, None, 1));
        want.extend([Token::Str("boundary_loops"), Token::U32(1)]);
        want.push(Token::StructEnd);
        assert_ser_tokens(&mobius, &want);
    }
}
