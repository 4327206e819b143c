//! The executable specification: the shared oracles, the switch and the cost bound of the
//! runtime checks, and the catalogue of which statement of the RS paper is checked where.
//!
//! The checks themselves live beside the algorithm they check (for RS:
//! `irreducible::rs::spec`, a child module that reads the algorithm's private state).
//! Every hook begins with `if !ENABLED { return }`, so the checks are type-checked in
//! every build and cost nothing when `ENABLED` is false. A failing check panics with
//! the statement's name, the vertices involved and the time stamp `ts`.
//!
//! Cost policy: checks are local to the operation (the processed vertex and its
//! neighbourhood). Where a check would be quadratic in a degree, it runs in full when the
//! degree is at most `FULL_CHECK_DEGREE` and on a bounded prefix otherwise; the
//! full-graph oracles (petgraph critical cycles, naive irreducibility) run in the tests.
//!
//! # Catalogue
//!
//! The statements, their sources and extents, and the tests that show each check can
//! fail are tabulated in `spec/README.md`; the runtime checks are these functions of
//! `irreducible::rs::spec`:
//!
//! | statement | RS paper | check | called at |
//! |---|---|---|---|
//! | S1, S2 | Eq. 1, Theorem 3 | `after_test` | Alg. 4.4, every link test |
//! | S2′ | Theorem 3 | `before_contraction` | Alg. 4.5, every contraction |
//! | S3 | Lemma 5 | `after_contraction` | Alg. 4.5, after the collapse |
//! | S4 | Proposition 6 | `degree3` | Alg. 4.3 |
//! | S5 | Proposition 7 | `prop7_before`, `prop7` | Alg. 4.5 |
//! | S6, S8, S9 | Propositions 8(1)–(6), 9(2), 10 | `at_line_22` | Alg. 4.2 l.22 |
//! | S8, S9, S10 | Propositions 9(2), 10, 11 | `at_line_32` | Alg. 4.2 l.32 |
//! | S10′ | Proposition 11 | `at_alg46_line_12`, `decrement` | Alg. 4.6 l.12, Alg. 4.3 |
//! | S11 | Definition 4 | `vertex_trapped` | end of the processing of `u` |
//! | S13 | Sec. 4.3 | `new_neighbour`, `leaving_lue` | Alg. 4.5 l.8, Alg. 4.2 l.24 |
//! | S14 | Sec. 4.3 | `degree3_untested` | Alg. 4.3, after the contraction |
//! | S15 | Alg. 4.2, Lemma 5 | `at_end` | end of the run |
//!
//! The simplifier's checks D1–D3 live in `simplify::spec` (catalogue: `spec/simplify.md`).
//!
//! S7 (ε = 0) and S12 (genus 0: one processed vertex does every contraction) are test
//! assertions over whole runs (`tests/algorithms/rs_algorithm.rs`); [`oracle`] holds the
//! independent definitions the checks and the tests compare against.

/// Degree (or list length) up to which a local check runs in full.
pub(crate) const FULL_CHECK_DEGREE: usize = 64;

/// Whether a check quadratic in `degree` runs in full: `degree ≤ FULL_CHECK_DEGREE`.
/// Every check asks here, so the bound is one comparison tested at its edge.
#[inline]
pub(crate) fn fully_checked(degree: usize) -> bool {
    degree <= FULL_CHECK_DEGREE
}

/// Whether the checks run: under `debug_assertions` or the cargo feature `invariants`.
/// A `const`, so a hook's `if !ENABLED { return }` is resolved at compile time. (Defined by
/// the core, whose own self-checks it switches too: the oracles here read triangulations,
/// so the core sits below this module.)
pub(crate) const ENABLED: bool = crate::core::CHECKS;

pub mod oracle;

/// Defines `Variant`, an algorithm's deliberate deviations (printed pseudo-code, errata,
/// mutations) for the tests that show its checks or the printed errata can fail, from one
/// list of `bool` switches.
///
/// With the cargo feature `mutation-tests` (which the project's own tests and the errata
/// search turn on, never a program) it is a public struct of those fields with a `const`
/// method of each name returning it. Without it, it is a private zero-sized type whose
/// methods return `false`: the algorithm reads every switch through the methods, so each
/// branch on one is compiled out and the library's users build the algorithm as
/// specified, with nothing of the variants in its API.
macro_rules! mutation_switches {
    (
        $(#[$attr:meta])*
        pub struct Variant {
            $( $(#[$field_attr:meta])* pub $field:ident: bool, )*
        }
    ) => {
        $(#[$attr])*
        #[cfg(feature = "mutation-tests")]
        #[doc(hidden)]
        #[derive(Copy, Clone, Debug, Default, PartialEq, Eq)]
        pub struct Variant {
            $( $(#[$field_attr])* pub $field: bool, )*
        }

        #[cfg(feature = "mutation-tests")]
        impl Variant {
            /// The algorithm as specified: every switch off.
            pub(crate) const SPECIFIED: Self = Self { $( $field: false, )* };

            $(
                $(#[$field_attr])*
                #[inline]
                pub const fn $field(self) -> bool {
                    self.$field
                }
            )*
        }

        /// The algorithm as specified: built without the cargo feature `mutation-tests`,
        /// no switch can be on.
        #[cfg(not(feature = "mutation-tests"))]
        #[derive(Copy, Clone, Debug)]
        struct Variant;

        #[cfg(not(feature = "mutation-tests"))]
        impl Variant {
            /// The algorithm as specified.
            const SPECIFIED: Self = Self;

            $(
                #[inline(always)]
                const fn $field(self) -> bool {
                    false
                }
            )*
        }
    };
}
pub(crate) use mutation_switches;

/// Shared code of the corrupted-state tests that show each check able to fail.
///
/// Tests that show a gated check (one that starts with `if !ENABLED { return }`) firing are
/// compiled only where the checks are (`#[cfg(any(debug_assertions, feature =
/// "invariants"))]` on the test or its module), so that no such test exists, and passes
/// without checking anything, in a build without them; `spec/README.md` lists them.
#[cfg(test)]
pub(crate) mod testing {
    use std::panic::{catch_unwind, AssertUnwindSafe};

    /// Runs `check` and returns its panic message; panics if it passed.
    fn failure(check: impl FnOnce()) -> String {
        let err = catch_unwind(AssertUnwindSafe(check)).expect_err("the check must fail");
        err.downcast_ref::<String>()
            .cloned()
            .unwrap_or_else(|| "non-string panic".into())
    }

    /// Asserts that `check`, which runs a gated specification check, fails with a
    /// violation naming `statement`. It exists only where the checks are compiled in, so
    /// a test calling it that is not gated the same way does not compile without them.
    #[cfg(any(debug_assertions, feature = "invariants"))]
    pub(crate) fn assert_fails(statement: &str, check: impl FnOnce()) {
        assert_fails_ungated(statement, check);
    }

    /// Asserts that `check` fails with a violation naming `statement`, for checks that
    /// run in every build (they are called from gated hooks only, but are not gated
    /// themselves, e.g. `quad::lrs::spec`'s L7 materialisation).
    pub(crate) fn assert_fails_ungated(statement: &str, check: impl FnOnce()) {
        let msg = failure(check);
        assert!(
            msg.starts_with("specification violated: ") && msg.contains(statement),
            "expected {statement}, got {msg}"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::{fully_checked, FULL_CHECK_DEGREE};

    #[test]
    fn the_full_check_bound_includes_its_degree() {
        for d in [0, 3, FULL_CHECK_DEGREE] {
            assert!(fully_checked(d), "degree {d}");
        }
        for d in [FULL_CHECK_DEGREE + 1, usize::MAX] {
            assert!(!fully_checked(d), "degree {d}");
        }
    }
}
