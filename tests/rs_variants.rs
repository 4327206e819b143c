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

/// Mutation: Alg. 4.4 counting the link vertices `x, y` of `[u, v]` as critical is
/// caught at the link test by the oracle count (Theorem 3).
#[test]
fn counting_link_vertices_is_caught_by_theorem_3() {
    let v = Variant {
        count_link_vertices: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(1), 0, "Alg. 4.4 / Theorem 3");
}

/// Mutation: the degree-3 shortcut (Alg. 4.3) taken for a degree-4 endpoint is caught by
/// Proposition 6.
#[test]
fn degree3_path_for_degree_4_is_caught_by_proposition_6() {
    let v = Variant {
        degree3_path_up_to_4: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::NonOrientable(1), 0, "Proposition 6");
}

/// Mutation: marking a link vertex processed in Alg. 4.5 makes a loose vertex look
/// trapped; Lemma 5 (processed vertices stay trapped) catches it.
#[test]
fn marking_a_link_vertex_processed_is_caught_by_lemma_5() {
    let v = Variant {
        mark_link_vertex_processed: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(2), 0, "Lemma 5");
}

/// Mutation: ending the processing of `u` after one pass over `lue` leaves edges whose
/// counters dropped to 0 uncontracted; Definition 4 (u trapped) catches it.
#[test]
fn a_single_pass_is_caught_by_definition_4() {
    let v = Variant {
        single_pass: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(0), 0, "Definition 4");
}

/// Mutation: an edge whose counter leaves 0 staying in place breaks the order of `lte`;
/// Proposition 10 catches it.
#[test]
fn not_moving_an_incremented_edge_is_caught_by_proposition_10() {
    let v = Variant {
        no_move_on_increment: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(0), 2, "Proposition 10");
}
