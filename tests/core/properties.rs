//! Property tests: proptest for structured generated surfaces (shrinking over surface
//! kind, size, seed and operation list), quickcheck for small algebraic laws.
//!
//! Surfaces: random triangulations (`gen::random`) of orientable genus 0..8 and
//! non-orientable Euler genus 1..6, modified by a random list of operations (splits,
//! flips, contractions) so the properties see states the generator alone never makes.
//! Case counts are kept moderate (32 per proptest property) so the file stays well under
//! a minute in debug builds.

use crate::common;

use std::collections::BTreeSet;

use contractible::core::Corner;
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::irreducible::{reduce, Algorithm, Options};
use contractible::rng::Rng;
use contractible::spec::oracle::contractible_by_theorem_3;
use contractible::{FaceId, History, LinkTester, Triangulation, VertexId};
use proptest::prelude::*;
use quickcheck::{quickcheck, TestResult};

// ---- Generated inputs.

fn surface_kind() -> impl Strategy<Value = SurfaceKind> {
    prop_oneof![
        (0u32..=8).prop_map(SurfaceKind::Orientable),
        (1u32..=6).prop_map(SurfaceKind::NonOrientable),
    ]
}

/// One local operation, its targets given as raw numbers reduced modulo the current
/// sizes when applied (so every generated list is applicable and shrinks well).
#[derive(Clone, Debug)]
enum Op {
    Split {
        vertex: u32,
        i: u8,
        j: u8,
    },
    Flip {
        face: u32,
        slot: u8,
    },
    Contract {
        face: u32,
        slot: u8,
        keep_first: bool,
    },
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        (any::<u32>(), any::<u8>(), any::<u8>()).prop_map(|(vertex, i, j)| Op::Split {
            vertex,
            i,
            j
        }),
        (any::<u32>(), 0u8..3).prop_map(|(face, slot)| Op::Flip { face, slot }),
        (any::<u32>(), 0u8..3, any::<bool>()).prop_map(|(face, slot, keep_first)| {
            Op::Contract {
                face,
                slot,
                keep_first,
            }
        }),
    ]
}

#[derive(Clone, Debug)]
struct Input {
    surface: SurfaceKind,
    min_faces: usize,
    seed: u64,
    ops: Vec<Op>,
}

fn input(max_faces: usize) -> impl Strategy<Value = Input> {
    (
        surface_kind(),
        0..max_faces,
        any::<u64>(),
        proptest::collection::vec(op(), 0..40),
    )
        .prop_map(|(surface, min_faces, seed, ops)| Input {
            surface,
            min_faces,
            seed,
            ops,
        })
}

/// The live face containing raw index `face` (the next live one, cyclically).
fn live_face(t: &Triangulation, face: u32) -> FaceId {
    let n = t.face_capacity() as u32;
    (0..n)
        .map(|k| FaceId((face % n + k) % n))
        .find(|&f| t.is_face(f))
        .expect("a live face")
}

fn live_vertex(t: &Triangulation, vertex: u32) -> VertexId {
    let n = t.vertex_capacity() as u32;
    (0..n)
        .map(|k| VertexId((vertex % n + k) % n))
        .find(|&v| t.is_vertex(v))
        .expect("a live vertex")
}

/// Applies one op if it is applicable; returns whether it changed the triangulation.
fn apply(t: &mut Triangulation, op: &Op, h: &mut History) -> bool {
    match *op {
        Op::Split { vertex, i, j } => {
            let u = live_vertex(t, vertex);
            let link: Vec<VertexId> = t.link(u).collect();
            let d = link.len();
            let i = i as usize % d;
            let j = (i + 1 + j as usize % (d - 1)) % d;
            t.split_vertex(u, link[i], link[j]).expect("valid split");
            true
        }
        Op::Flip { face, slot } => {
            let [a, b] = t.edge_endpoints(live_face(t, face).corner(slot as u32));
            t.is_flippable(a, b) && t.flip(a, b).is_ok()
        }
        Op::Contract {
            face,
            slot,
            keep_first,
        } => {
            let [a, b] = t.edge_endpoints(live_face(t, face).corner(slot as u32));
            let (u, v) = if keep_first { (a, b) } else { (b, a) };
            t.contract(u, v, h).is_ok()
        }
    }
}

fn build(inp: &Input) -> Triangulation {
    let mut t = random(&RandomParams {
        surface: inp.surface,
        min_faces: inp.min_faces,
        flip_percent: 20,
        seed: inp.seed,
    })
    .expect("a random surface within the limits");
    let mut h = History::new();
    for op in &inp.ops {
        apply(&mut t, op, &mut h);
    }
    t
}

fn face_set(t: &Triangulation) -> BTreeSet<[u32; 3]> {
    t.face_list()
        .into_iter()
        .map(|mut f| {
            f.sort_unstable();
            f
        })
        .collect()
}

fn config(cases: u32) -> ProptestConfig {
    ProptestConfig::with_cases(cases)
}

proptest! {
    #![proptest_config(config(32))]

    /// Naive link condition == marked `LinkTester` == `is_contractible` == Theorem 3
    /// oracle on every edge, after a random op sequence; every op keeps the triangulation
    /// valid and the surface the same.
    #[test]
    fn link_tests_agree_after_random_ops(inp in input(400)) {
        let base = random(&RandomParams {
            surface: inp.surface,
            min_faces: inp.min_faces,
            flip_percent: 20,
            seed: inp.seed,
        }).expect("a random surface within the limits");
        let mut t = base.clone();
        let mut h = History::new();
        for op in &inp.ops {
            apply(&mut t, op, &mut h);
            t.validate().map_err(|e| TestCaseError::fail(format!("{op:?}: {e}")))?;
            prop_assert_eq!(t.euler_characteristic(), base.euler_characteristic());
            prop_assert_eq!(t.is_orientable(), base.is_orientable());
        }
        let mut tester = LinkTester::new(t.vertex_capacity());
        for u in t.vertices() {
            tester.mark(&t, u);
            for w in t.link(u) {
                let naive = t.link_condition_naive(u, w);
                prop_assert_eq!(naive, tester.test_marked(&t, u, w), "marked {}-{}", u, w);
                prop_assert_eq!(naive, t.is_contractible(u, w), "is_contractible {}-{}", u, w);
                prop_assert_eq!(naive, contractible_by_theorem_3(&t, u, w), "Theorem 3 {}-{}", u, w);
            }
        }
    }

    /// Contract/undo is the identity (exact `==`), one contraction at a time and for a
    /// whole random contraction sequence undone at once.
    #[test]
    fn contract_undo_round_trips(inp in input(400), picks in proptest::collection::vec((any::<u32>(), 0u8..3, any::<bool>()), 1..30)) {
        let t = build(&inp);
        let mut work = t.clone();
        let mut h = History::new();
        let mut done = 0;
        for &(face, slot, keep_first) in &picks {
            let before = work.clone();
            let len = h.len();
            if apply(&mut work, &Op::Contract { face, slot, keep_first }, &mut h) {
                done += 1;
                work.validate().map_err(|e| TestCaseError::fail(e.to_string()))?;
                let mut single = work.clone();
                let mut hs = h.clone();
                hs.undo(&mut single).expect("record");
                prop_assert!(single == before, "single undo");
                prop_assert_eq!(h.len(), len + 1);
            } else {
                prop_assert!(work == before, "a refused contraction changed the triangulation");
            }
        }
        prop_assert_eq!(h.len(), done);
        h.undo_all(&mut work);
        prop_assert!(work == t, "undo_all after {} contractions", done);
    }

    /// Flipping `[u, v]` then the new edge `[w, z]` gives back the same face set.
    #[test]
    fn flip_flip_round_trips(inp in input(400), face in any::<u32>(), slot in 0u8..3) {
        let mut t = build(&inp);
        let before = face_set(&t);
        let [u, v] = t.edge_endpoints(live_face(&t, face).corner(slot as u32));
        let Some([w, z]) = t.edge_link(u, v) else {
            return Err(TestCaseError::fail("edge_endpoints gave a non-edge"));
        };
        if !t.is_flippable(u, v) {
            prop_assert!(t.has_edge(w, z));
            prop_assert!(t.flip(u, v).is_err());
            prop_assert_eq!(face_set(&t), before);
            return Ok(());
        }
        t.flip(u, v).map_err(|e| TestCaseError::fail(e.to_string()))?;
        t.validate().map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(!t.has_edge(u, v) && t.has_edge(w, z));
        t.flip(w, z).map_err(|e| TestCaseError::fail(e.to_string()))?;
        t.validate().map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(face_set(&t), before);
    }

    /// Splitting `u` into `u` and a new `w`, then contracting `[u, w]` keeping `u`, gives
    /// back the same face set; keeping `w` gives it with `u` renamed `w`.
    #[test]
    fn split_then_contract_round_trips(inp in input(400), vertex in any::<u32>(), i in any::<u8>(), j in any::<u8>()) {
        let t = build(&inp);
        let before = face_set(&t);
        let u = live_vertex(&t, vertex);
        let link: Vec<VertexId> = t.link(u).collect();
        let d = link.len();
        let i = i as usize % d;
        let j = (i + 1 + j as usize % (d - 1)) % d;
        let mut s = t.clone();
        let w = s.split_vertex(u, link[i], link[j]).map_err(|e| TestCaseError::fail(e.to_string()))?;
        s.validate().map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(!t.is_vertex(w) && s.is_vertex(w));
        prop_assert_eq!(s.edge_link(u, w).map(|l| l.into_iter().collect::<BTreeSet<_>>()),
            Some([link[i], link[j]].into_iter().collect()));

        let mut keep_u = s.clone();
        keep_u.contract(u, w, &mut History::new()).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert_eq!(face_set(&keep_u), before.clone());

        let mut keep_w = s.clone();
        keep_w.contract(w, u, &mut History::new()).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let renamed: BTreeSet<[u32; 3]> = before
            .iter()
            .map(|f| {
                let mut g = f.map(|z| if z == u.0 { w.0 } else { z });
                g.sort_unstable();
                g
            })
            .collect();
        prop_assert_eq!(face_set(&keep_w), renamed);
    }
}

proptest! {
    #![proptest_config(config(24))]

    /// RS, Schipper and brute force each give a verified irreducible triangulation of the
    /// same surface (`common::check`: naive irreducibility, validity, χ, orientability,
    /// Joret–Wood 13h − 4, T4 for spheres, `expand() == input`, counters).
    #[test]
    fn every_algorithm_output_is_verified(inp in input(600), seed in any::<u64>()) {
        let t = build(&inp);
        for alg in common::ALL {
            let r = reduce(t.clone(), alg, &common::options(seed));
            common::check(&t, &r, alg, &format!("{inp:?}"));
        }
    }

    /// Same input and seed give the same output, history and statistics (seconds aside).
    #[test]
    fn algorithms_are_deterministic(inp in input(600), seed in any::<u64>()) {
        let t = build(&inp);
        prop_assert!(build(&inp) == t, "the generator is deterministic");
        for alg in common::ALL {
            let opts = Options { seed, count_retests: true, keep_history: true };
            let a = reduce(t.clone(), alg, &opts);
            let b = reduce(t.clone(), alg, &opts);
            prop_assert!(a.tri == b.tri, "{:?}: output", alg);
            prop_assert!(a.history == b.history, "{:?}: history", alg);
            let (mut sa, mut sb) = (a.stats.clone(), b.stats.clone());
            sa.seconds = 0.0;
            sb.seconds = 0.0;
            prop_assert_eq!(sa, sb, "{:?}: stats", alg);
        }
    }
}

// ---- quickcheck: small algebraic laws.

fn qc_below_in_range(seed: u64, n: u64) -> TestResult {
    if n == 0 {
        return TestResult::discard();
    }
    let mut r = Rng::new(seed);
    TestResult::from_bool((0..16).all(|_| r.below(n) < n))
}

fn qc_shuffle_is_permutation(seed: u64, items: Vec<u16>) -> bool {
    let mut shuffled = items.clone();
    Rng::new(seed).shuffle(&mut shuffled);
    let mut a = items;
    a.sort_unstable();
    shuffled.sort_unstable();
    a == shuffled
}

fn qc_shuffle_is_deterministic(seed: u64, items: Vec<u16>) -> bool {
    let (mut a, mut b) = (items.clone(), items);
    Rng::new(seed).shuffle(&mut a);
    Rng::new(seed).shuffle(&mut b);
    a == b
}

fn qc_corner_cycles(c: u32) -> bool {
    let c = Corner(c % (u32::MAX - 3));
    c.next().next().next() == c
        && c.prev().prev().prev() == c
        && c.next().prev() == c
        && c.next().face() == c.face()
        && c.prev().face() == c.face()
        && c.face().corner(c.slot()) == c
}

/// A small random surface picked by `k` (kind and seed), flip an edge and back.
fn qc_flip_flip_face_set(k: u8, seed: u64, edge: usize) -> bool {
    let surface = if k % 2 == 0 {
        SurfaceKind::Orientable(u32::from(k / 2 % 4))
    } else {
        SurfaceKind::NonOrientable(1 + u32::from(k / 2 % 3))
    };
    let mut t = random(&RandomParams {
        surface,
        min_faces: 60,
        flip_percent: 20,
        seed,
    })
    .expect("a random surface within the limits");
    let before = face_set(&t);
    let (u, v, _) = t.edges().nth(edge % t.edge_count()).expect("edge");
    let [w, z] = t.edge_link(u, v).expect("edge");
    if !t.is_flippable(u, v) {
        return t.flip(u, v).is_err() && face_set(&t) == before;
    }
    t.flip(u, v).is_ok()
        && t.validate().is_ok()
        && t.flip(w, z).is_ok()
        && t.validate().is_ok()
        && face_set(&t) == before
}

fn qc_random_is_deterministic(k: u8, seed: u64) -> bool {
    let p = RandomParams {
        surface: SurfaceKind::Orientable(u32::from(k % 4)),
        min_faces: 80,
        flip_percent: 30,
        seed,
    };
    random(&p).expect("a random surface within the limits")
        == random(&p).expect("a random surface within the limits")
}

#[test]
fn quickcheck_rng_laws() {
    quickcheck(qc_below_in_range as fn(u64, u64) -> TestResult);
    quickcheck(qc_shuffle_is_permutation as fn(u64, Vec<u16>) -> bool);
    quickcheck(qc_shuffle_is_deterministic as fn(u64, Vec<u16>) -> bool);
}

#[test]
fn quickcheck_corner_laws() {
    quickcheck(qc_corner_cycles as fn(u32) -> bool);
}

#[test]
fn quickcheck_flip_flip_and_determinism() {
    quickcheck::QuickCheck::new()
        .tests(40)
        .quickcheck(qc_flip_flip_face_set as fn(u8, u64, usize) -> bool);
    quickcheck::QuickCheck::new()
        .tests(20)
        .quickcheck(qc_random_is_deterministic as fn(u8, u64) -> bool);
}

#[test]
fn brute_force_seed_changes_are_allowed_but_outputs_stay_valid() {
    // Not a law: documents that different seeds may give different (valid) brute-force
    // outputs, while RS and Schipper ignore the seed.
    let t = random(&RandomParams {
        surface: SurfaceKind::Orientable(2),
        min_faces: 300,
        flip_percent: 20,
        seed: 3,
    })
    .expect("a random surface within the limits");
    for alg in [Algorithm::Rs, Algorithm::Schipper] {
        let a = reduce(t.clone(), alg, &common::options(1));
        let b = reduce(t.clone(), alg, &common::options(2));
        assert!(
            a.tri == b.tri && a.history == b.history,
            "{alg:?} depends on the seed"
        );
    }
    for seed in 0..4 {
        let r = reduce(t.clone(), Algorithm::Brute, &common::options(seed));
        common::check(&t, &r, Algorithm::Brute, "brute");
    }
}
