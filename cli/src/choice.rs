//! The library's choice enums (algorithms, simplification modes, sides, positions) as
//! clap arguments: the accepted values are the library's names (`ALL`, `name`), each with
//! its one-line summary as help, and a value is parsed by the library's `FromStr`. The
//! library does not depend on clap, so the command line adapts its enums here instead of
//! deriving `ValueEnum` on copies of them: one list of names for both.

use std::marker::PhantomData;

use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};

/// A library enum with a fixed list of named choices.
pub trait Choice: Copy + Send + Sync + std::str::FromStr<Err: std::fmt::Display> + 'static {
    /// Every choice, in the library's order.
    fn all() -> &'static [Self];
    /// The name the command line accepts.
    fn name(self) -> &'static str;
    /// The one-line help of the choice.
    fn summary(self) -> &'static str;
}

macro_rules! choice {
    ($ty:ty) => {
        impl Choice for $ty {
            fn all() -> &'static [Self] {
                &<$ty>::ALL
            }
            fn name(self) -> &'static str {
                <$ty>::name(self)
            }
            fn summary(self) -> &'static str {
                <$ty>::summary(self)
            }
        }
    };
}

choice!(contractible::irreducible::Algorithm);
choice!(contractible::quad::Algorithm);
choice!(contractible::simplify::Mode);
choice!(contractible::simplify::Side);
choice!(contractible::simplify::Position);
choice!(contractible::decimate::Placement);
choice!(contractible::decimate::Schedule);

/// The clap value parser of a [`Choice`] (`#[arg(value_parser = parser::<T>())]`).
#[derive(Clone)]
pub struct ChoiceParser<T>(PhantomData<T>);

/// The parser of `T`'s choices.
pub fn parser<T: Choice>() -> ChoiceParser<T> {
    ChoiceParser(PhantomData)
}

impl<T: Choice> ChoiceParser<T> {
    fn values() -> impl Iterator<Item = PossibleValue> {
        T::all()
            .iter()
            .map(|c| PossibleValue::new(c.name()).help(c.summary()))
    }
}

impl<T: Choice> TypedValueParser for ChoiceParser<T> {
    type Value = T;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<T, clap::Error> {
        // The possible-values parser gives clap's own error for a value outside the
        // list (the same message, with the list, as for the derived enums).
        let name = PossibleValuesParser::new(Self::values()).parse_ref(cmd, arg, value)?;
        name.parse::<T>().map_err(|e| {
            clap::Error::raw(clap::error::ErrorKind::InvalidValue, format!("{e}\n")).with_cmd(cmd)
        })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(Self::values()))
    }
}
