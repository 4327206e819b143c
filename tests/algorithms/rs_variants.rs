//! Deliberately broken and as-printed variants of RS are caught by the specification
//! checks (the evidence for spec/ERRATA.md and proof that the checks can fail).
//!
//! A test that expects a check to fire exists only where the checks are compiled in
//! (`debug_assertions` or the `invariants` feature). Where a variant's error also shows in
//! its output, a twin test for builds without the checks asserts the wrong output.

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::rs::{reduce_variant, Variant};
use contractible::irreducible::Options;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// The random input the variants run on, for (`surface`, `seed`).
fn input(surface: SurfaceKind, seed: u64) -> contractible::Triangulation {
    let g = match surface {
        SurfaceKind::Orientable(g) | SurfaceKind::NonOrientable(g) => g as usize,
    };
    random(&RandomParams {
        surface,
        min_faces: 200 + 100 * g,
        flip_percent: 40,
        seed,
    })
    .expect("a random surface within the limits")
}

/// Runs `variant` on the random input for (`surface`, `seed`) and returns the panic
/// message of the specification check that fired, if any.
#[cfg(any(debug_assertions, feature = "invariants"))]
fn failure(variant: Variant, surface: SurfaceKind, seed: u64) -> Option<String> {
    let t = input(surface, seed);
    let res = catch_unwind(AssertUnwindSafe(|| {
        reduce_variant(t, &Options::default(), variant)
    }));
    res.err().map(|e| {
        e.downcast_ref::<String>()
            .cloned()
            .unwrap_or_else(|| "non-string panic".into())
    })
}

/// Asserts that `variant` fails the check naming `statement` on the random input for
/// (`surface`, `seed`), and that the correct algorithm passes the same input.
#[cfg(any(debug_assertions, feature = "invariants"))]
fn assert_caught(variant: Variant, surface: SurfaceKind, seed: u64, statement: &str) {
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
#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn skipping_the_degree3_decrement_is_caught_by_proposition_11() {
    let v = Variant {
        skip_degree3_decrement: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(0), 0, "Proposition 11");
}

/// Erratum E1: Alg. 4.3 l.13 as printed (`t(x) > o(y)`; l.19 keeps its printed `>=`)
/// misses the decrement when y became a neighbour of u at the same time stamp at which
/// [u, x] was tested.
#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn erratum_e1_strict_time_stamp_breaks_proposition_11() {
    let v = Variant {
        printed_strict_stamp: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::NonOrientable(1), 13, "Proposition 11");
}

/// Erratum E3: Alg. 4.2 l.8–19 as printed does not reset c(v) of the initial neighbours,
/// so a counter left over from an earlier processed vertex violates Proposition 8(6).
#[cfg(any(debug_assertions, feature = "invariants"))]
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
#[cfg(any(debug_assertions, feature = "invariants"))]
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
#[cfg(any(debug_assertions, feature = "invariants"))]
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
#[cfg(any(debug_assertions, feature = "invariants"))]
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
#[cfg(any(debug_assertions, feature = "invariants"))]
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
#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn not_moving_an_incremented_edge_is_caught_by_proposition_10() {
    let v = Variant {
        no_move_on_increment: true,
        ..Variant::default()
    };
    assert_caught(v, SurfaceKind::Orientable(0), 2, "Proposition 10");
}

#[cfg(not(any(debug_assertions, feature = "invariants")))]
/// Without the checks, the mutations whose effect reaches the output are caught by the
/// naive link test: on these inputs the mutated algorithm returns a triangulation with a
/// contractible edge, where the correct one returns an irreducible one. (The other
/// mutations leave these outputs right, or stop with an out-of-bounds panic, and are
/// caught by the checks only.)
#[test]
fn mutations_that_reach_the_output_leave_it_reducible() {
    for (variant, surface, seed) in [
        (
            Variant {
                count_link_vertices: true,
                ..Variant::default()
            },
            SurfaceKind::Orientable(1),
            0,
        ),
        (
            Variant {
                skip_degree3_decrement: true,
                ..Variant::default()
            },
            SurfaceKind::Orientable(0),
            2,
        ),
    ] {
        let t = input(surface, seed);
        let (ours, _) = reduce_variant(t.clone(), &Options::default(), Variant::default());
        assert!(ours.tri.is_irreducible_naive());
        let (theirs, _) = reduce_variant(t.clone(), &Options::default(), variant);
        theirs.tri.validate().expect("still a triangulation");
        assert_eq!(theirs.tri.euler_characteristic(), t.euler_characteristic());
        assert!(
            !theirs.tri.is_irreducible_naive(),
            "{variant:?}: the output should keep a contractible edge"
        );
    }
}

/// Erratum E4 witness: a 16-vertex Klein bottle (found by a search over random small
/// surfaces and vertex orders, then shrunk by contractions that keep the failure). With
/// the printed `until lue = ∅` exit of Alg. 4.2 l.34, the processing of a vertex stops
/// while an edge at it is still contractible.
const E4_KLEIN_BOTTLE: [[u32; 3]; 32] = [
    [1, 5, 12],
    [0, 4, 8],
    [1, 12, 4],
    [4, 11, 15],
    [13, 4, 3],
    [6, 11, 1],
    [4, 12, 10],
    [12, 6, 10],
    [15, 11, 14],
    [10, 4, 0],
    [9, 13, 8],
    [9, 8, 4],
    [12, 11, 6],
    [11, 3, 8],
    [11, 4, 2],
    [1, 4, 2],
    [15, 14, 7],
    [11, 10, 5],
    [10, 1, 5],
    [14, 11, 7],
    [3, 11, 7],
    [11, 0, 10],
    [8, 0, 1],
    [8, 13, 3],
    [11, 2, 0],
    [15, 3, 4],
    [3, 15, 7],
    [9, 4, 13],
    [12, 5, 11],
    [11, 1, 8],
    [10, 6, 1],
    [2, 1, 0],
];

/// Erratum E4 witness with a wrong *output*: a 25-vertex surface of genus 4 (found and
/// shrunk the same way, with the checks compiled out, looking for a reducible result).
/// With the printed exit, a vertex is left loose and no later vertex re-tests the edge,
/// so the returned triangulation still has a contractible edge.
const E4_GENUS_4: [[u32; 3]; 62] = [
    [21, 2, 7],
    [21, 7, 16],
    [2, 16, 18],
    [2, 18, 7],
    [16, 7, 8],
    [16, 8, 18],
    [18, 8, 21],
    [13, 11, 19],
    [8, 15, 2],
    [8, 2, 21],
    [19, 11, 16],
    [16, 4, 5],
    [5, 4, 15],
    [4, 2, 15],
    [5, 3, 17],
    [17, 15, 0],
    [17, 3, 1],
    [0, 15, 3],
    [3, 15, 12],
    [3, 12, 1],
    [12, 22, 17],
    [16, 9, 22],
    [16, 17, 9],
    [22, 19, 17],
    [22, 9, 19],
    [17, 19, 6],
    [9, 12, 19],
    [19, 16, 6],
    [1, 5, 15],
    [16, 2, 10],
    [10, 5, 1],
    [14, 13, 18],
    [24, 20, 18],
    [16, 22, 6],
    [18, 19, 15],
    [19, 12, 15],
    [13, 14, 21],
    [23, 18, 21],
    [16, 11, 21],
    [11, 13, 21],
    [10, 1, 4],
    [7, 15, 8],
    [22, 12, 6],
    [15, 7, 18],
    [16, 10, 4],
    [0, 5, 2],
    [24, 19, 20],
    [19, 18, 20],
    [18, 13, 24],
    [1, 2, 4],
    [5, 10, 2],
    [0, 3, 5],
    [12, 17, 2],
    [21, 14, 23],
    [14, 18, 23],
    [17, 6, 9],
    [6, 12, 9],
    [1, 12, 2],
    [5, 17, 16],
    [15, 17, 1],
    [19, 24, 13],
    [2, 17, 0],
];

/// The printed loop exit of Alg. 4.2 l.34 (erratum E4).
fn printed_loop_exit() -> Variant {
    Variant {
        printed_loop_exit: true,
        ..Variant::default()
    }
}

/// Runs `printed` on `faces`: returns the message of the check that fired (when the checks
/// are compiled in), or whether the output is irreducible (naive link test). Checks first
/// that the correct algorithm gives an irreducible triangulation of the same surface.
fn run_printed(printed: Variant, faces: &[[u32; 3]], n: usize) -> Result<bool, String> {
    use contractible::Triangulation;
    let t = Triangulation::from_faces(n, faces).expect("a closed surface");
    // Ours gives an irreducible triangulation of the same surface.
    let (ours, _) = reduce_variant(t.clone(), &Options::default(), Variant::default());
    assert!(ours.tri.is_irreducible_naive());
    assert_eq!(ours.tri.euler_characteristic(), t.euler_characteristic());
    match catch_unwind(AssertUnwindSafe(|| {
        reduce_variant(t, &Options::default(), printed)
    })) {
        Ok((r, _)) => Ok(r.tri.is_irreducible_naive()),
        Err(e) => Err(e
            .downcast_ref::<String>()
            .cloned()
            .unwrap_or_else(|| "non-string panic".into())),
    }
}

/// Erratum E4: on the Klein bottle witness the printed exit leaves vertex 3 loose, and
/// Definition 4 catches it when the processing of vertex 3 ends.
#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn erratum_e4_printed_loop_exit_leaves_a_vertex_loose() {
    let msg = run_printed(printed_loop_exit(), &E4_KLEIN_BOTTLE, 16)
        .expect_err("the printed loop exit is caught");
    assert!(
        msg.contains("Definition 4") && msg.contains("u = 3,"),
        "{msg}"
    );
}

/// Erratum E4 on the Klein bottle witness without the checks: later vertices happen to
/// remove the loose edge, so the output is right (the genus-4 witness below is the one
/// whose output is wrong).
#[cfg(not(any(debug_assertions, feature = "invariants")))]
#[test]
fn erratum_e4_printed_loop_exit_on_the_klein_bottle_still_ends_irreducible() {
    assert_eq!(
        run_printed(printed_loop_exit(), &E4_KLEIN_BOTTLE, 16),
        Ok(true)
    );
}

/// Erratum E4 on the genus-4 witness: Definition 4 catches the loose vertex.
#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn erratum_e4_printed_loop_exit_on_the_genus_4_witness_is_caught_by_definition_4() {
    let msg = run_printed(printed_loop_exit(), &E4_GENUS_4, 25)
        .expect_err("the printed loop exit is caught");
    assert!(msg.contains("Definition 4"), "{msg}");
}

/// Erratum E4 on the genus-4 witness without the checks: the returned triangulation
/// still has a contractible edge (naive link test).
#[cfg(not(any(debug_assertions, feature = "invariants")))]
#[test]
fn erratum_e4_printed_loop_exit_returns_a_reducible_triangulation() {
    assert_eq!(
        run_printed(printed_loop_exit(), &E4_GENUS_4, 25),
        Ok(false),
        "the printed exit's output must be reducible"
    );
}

/// Erratum E1 witness with a wrong *output*: a 16-vertex surface of Euler genus 4 (found
/// by `tools/src/bin/errata_search.rs` (`e1`, checks compiled out),
/// and shrunk). The printed strict stamp of Alg. 4.3 l.13 leaves a counter one too
/// high, the edge never reaches the front of `lte`, and the output keeps it contractible.
const E1_EULER_GENUS_4: [[u32; 3]; 36] = [
    [0, 2, 14],
    [10, 14, 0],
    [8, 11, 9],
    [8, 1, 11],
    [12, 1, 15],
    [6, 12, 11],
    [15, 11, 1],
    [6, 15, 11],
    [4, 10, 11],
    [13, 9, 11],
    [14, 9, 2],
    [9, 13, 2],
    [13, 5, 10],
    [15, 8, 6],
    [1, 6, 12],
    [13, 3, 2],
    [3, 0, 2],
    [4, 12, 8],
    [4, 9, 10],
    [9, 1, 10],
    [14, 3, 10],
    [3, 13, 10],
    [0, 4, 1],
    [10, 0, 1],
    [5, 13, 11],
    [7, 10, 11],
    [4, 11, 12],
    [1, 6, 9],
    [6, 8, 9],
    [9, 4, 0],
    [7, 11, 5],
    [10, 7, 5],
    [9, 0, 3],
    [9, 14, 3],
    [8, 4, 1],
    [12, 15, 8],
];

/// The printed strict stamp of Alg. 4.3 l.13 (erratum E1).
fn printed_strict_stamp() -> Variant {
    Variant {
        printed_strict_stamp: true,
        ..Variant::default()
    }
}

/// Erratum E1 on its witness: Proposition 11 catches the counter left one too high.
#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn erratum_e1_printed_stamp_on_the_witness_is_caught_by_proposition_11() {
    let msg = run_printed(printed_strict_stamp(), &E1_EULER_GENUS_4, 16)
        .expect_err("the printed stamp is caught");
    assert!(msg.contains("Proposition 11"), "{msg}");
}

/// Erratum E1 on its witness without the checks: the output keeps a contractible edge.
#[cfg(not(any(debug_assertions, feature = "invariants")))]
#[test]
fn erratum_e1_printed_stamp_returns_a_reducible_triangulation() {
    assert_eq!(
        run_printed(printed_strict_stamp(), &E1_EULER_GENUS_4, 16),
        Ok(false),
        "the printed stamp's output must be reducible"
    );
}
