//! Deliberately broken and as-printed variants of RS are caught by the specification
//! checks (the evidence for spec/ERRATA.md and proof that the checks can fail).

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::rs::{reduce_variant, Variant};
use contractible::irreducible::Options;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `variant` on the random input for (`surface`, `seed`) and returns the panic
/// message of the specification check that fired, if any.
fn failure(variant: Variant, surface: SurfaceKind, seed: u64) -> Option<String> {
    let g = match surface {
        SurfaceKind::Orientable(g) | SurfaceKind::NonOrientable(g) => g as usize,
    };
    let t = random(&RandomParams {
        surface,
        min_faces: 200 + 100 * g,
        flip_percent: 40,
        seed,
    });
    let res = catch_unwind(AssertUnwindSafe(|| {
        reduce_variant(t, &Options::default(), variant)
    }));
    res.err().map(|e| {
        e.downcast_ref::<String>()
            .cloned()
            .unwrap_or_else(|| "non-string panic".into())
    })
}

fn assert_caught(variant: Variant, surface: SurfaceKind, seed: u64, statement: &str) {
    if !cfg!(any(debug_assertions, feature = "invariants")) {
        return; // the checks are compiled out
    }
    let msg =
        failure(variant, surface, seed).unwrap_or_else(|| panic!("{variant:?} was not caught"));
    assert!(
        msg.contains(statement),
        "expected a {statement} failure, got: {msg}"
    );
    // The correct algorithm passes the same input.
    assert_eq!(failure(Variant::default(), surface, seed), None);
}

/// Mutation: dropping the counter decrements of Alg. 4.3 l.5–23 leaves c(x) too high.
#[test]
fn skipping_the_degree3_decrement_is_caught_by_proposition_11() {
    let v = Variant {
        skip_degree3_decrement: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(0), 0, "Proposition 11");
}

/// Erratum E1: Alg. 4.3 l.13 as printed (`t(x) > o(y)`) misses the decrement when y
/// became a neighbour of u at the same time stamp at which [u, x] was tested.
#[test]
fn erratum_e1_strict_time_stamp_breaks_proposition_11() {
    let v = Variant {
        printed_strict_stamp: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(1), 2, "Proposition 11");
}

/// Erratum E3: Alg. 4.2 l.8–19 as printed does not reset c(v) of the initial neighbours,
/// so a counter left over from an earlier processed vertex violates Proposition 8(6).
#[test]
fn erratum_e3_missing_counter_reset_breaks_proposition_8_6() {
    let v = Variant {
        printed_no_counter_reset: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(1), 0, "Proposition 8(6)");
}
