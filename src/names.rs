//! The one list of names of every choice (algorithms, modes, heuristics): each choice's
//! enum writes its name with `Display` and reads it with `FromStr`, and the command line,
//! the Python package and JSON all use those names.

/// A name that is none of the choices; its message lists them all.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown {what} {given:?}: expected one of {}", .expected.join(", "))]
pub struct UnknownName {
    /// What was being named ("reduction algorithm", "simplification mode"...).
    pub what: &'static str,
    /// The name given.
    pub given: String,
    /// Every accepted name, in documentation order.
    pub expected: Vec<&'static str>,
}

/// The choice among `all` whose `name` is `s` (exactly: names are lowercase ASCII), or
/// the error listing every name.
pub(crate) fn parse<T: Copy>(
    s: &str,
    what: &'static str,
    all: &[T],
    name: impl Fn(T) -> &'static str,
) -> Result<T, UnknownName> {
    all.iter()
        .copied()
        .find(|&a| name(a) == s)
        .ok_or_else(|| UnknownName {
            what,
            given: s.to_string(),
            expected: all.iter().map(|&a| name(a)).collect(),
        })
}

/// `Display` and `FromStr` of a choice enum through its `name` method and `ALL` list.
macro_rules! named_choice {
    ($ty:ty, $what:literal) => {
        impl std::fmt::Display for $ty {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(self.name())
            }
        }

        impl std::str::FromStr for $ty {
            type Err = $crate::names::UnknownName;

            /// One of the names of `name()`; the error lists them all.
            fn from_str(s: &str) -> Result<Self, Self::Err> {
                $crate::names::parse(s, $what, &<$ty>::ALL, <$ty>::name)
            }
        }

        /// Serialised as its name.
        #[cfg(feature = "serde")]
        impl serde::Serialize for $ty {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                s.serialize_str(self.name())
            }
        }
    };
}
pub(crate) use named_choice;

#[cfg(test)]
mod tests {
    use crate::{irreducible, quad, simplify};

    /// Every name reads back as its choice, and a wrong name lists them all.
    #[test]
    fn every_name_round_trips_and_a_wrong_one_lists_them() {
        for a in irreducible::Algorithm::ALL {
            assert_eq!(a.to_string().parse::<irreducible::Algorithm>(), Ok(a));
        }
        for a in quad::Algorithm::ALL {
            assert_eq!(a.to_string().parse::<quad::Algorithm>(), Ok(a));
        }
        for m in simplify::Mode::ALL {
            assert_eq!(m.to_string().parse::<simplify::Mode>(), Ok(m));
        }
        for s in simplify::Side::ALL {
            assert_eq!(s.to_string().parse::<simplify::Side>(), Ok(s));
        }
        for p in simplify::Position::ALL {
            assert_eq!(p.to_string().parse::<simplify::Position>(), Ok(p));
        }
        let e = "RS".parse::<irreducible::Algorithm>().unwrap_err();
        assert_eq!(
            e.to_string(),
            "unknown reduction algorithm \"RS\": expected one of rs, schipper, brute"
        );
        let e = "dsn".parse::<quad::Algorithm>().unwrap_err();
        assert_eq!(e.expected.len(), 8);
    }

    /// The names are the documented ones, and every choice has its own non-empty summary
    /// (the command line's help would otherwise list blank or repeated lines).
    #[test]
    fn names_are_the_documented_ones_and_summaries_are_distinct() {
        fn distinct(what: &str, mut lines: Vec<&'static str>) {
            assert!(
                lines.iter().all(|l| !l.trim().is_empty()),
                "{what}: {lines:?}"
            );
            let n = lines.len();
            lines.sort_unstable();
            lines.dedup();
            assert_eq!(lines.len(), n, "{what}: repeated line");
        }
        let names: Vec<_> = irreducible::Algorithm::ALL.map(|a| a.name()).into();
        assert_eq!(names, ["rs", "schipper", "brute"]);
        let names: Vec<_> = quad::Algorithm::ALL.map(|a| a.name()).into();
        assert_eq!(
            names,
            [
                "lrs",
                "ps",
                "sg",
                "matching",
                "ds",
                "bbdl",
                "frink-lct",
                "ds-naive"
            ]
        );
        let names: Vec<_> = simplify::Mode::ALL.map(|a| a.name()).into();
        assert_eq!(names, ["nested", "naive"]);
        let names: Vec<_> = simplify::Side::ALL.map(|a| a.name()).into();
        assert_eq!(names, ["count", "path", "euclidean"]);
        let names: Vec<_> = simplify::Position::ALL.map(|a| a.name()).into();
        assert_eq!(names, ["midpoint", "quadric"]);
        distinct(
            "irreducible",
            irreducible::Algorithm::ALL.map(|a| a.summary()).into(),
        );
        distinct("quad", quad::Algorithm::ALL.map(|a| a.summary()).into());
        distinct("mode", simplify::Mode::ALL.map(|a| a.summary()).into());
        distinct("side", simplify::Side::ALL.map(|a| a.summary()).into());
        distinct(
            "position",
            simplify::Position::ALL.map(|a| a.summary()).into(),
        );
    }
}
