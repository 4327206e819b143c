//! Contractions, flips and undos in random interleavings on random surfaces of every
//! kind: the journal restores the input exactly, the contraction history either restores
//! exactly or is refused by its state guard (never corrupts), and dense edge numbers stay
//! exact through all of it. Checked by `validate()` (from scratch), array equality and
//! `EdgeNumbering::check`, plus an independent per-vertex-pair identity model.

use std::collections::HashMap;

use contractible::core::{Journal, Op, UndoError};
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::rng::Rng;
use contractible::{Corner, EdgeNumbering, History, Triangulation, VertexId};

fn surfaces() -> Vec<(SurfaceKind, u64)> {
    let mut out = Vec::new();
    for g in 0..=5 {
        out.push((SurfaceKind::Orientable(g), 10 + g as u64));
    }
    for h in 1..=5 {
        out.push((SurfaceKind::NonOrientable(h), 20 + h as u64));
    }
    out
}

fn surface(kind: SurfaceKind, seed: u64, min_faces: usize) -> Triangulation {
    random(&RandomParams {
        surface: kind,
        min_faces,
        flip_percent: 30,
        seed,
    })
    .expect("a random surface within the limits")
}

fn random_live_corner(t: &Triangulation, rng: &mut Rng) -> Corner {
    loop {
        let c = Corner(rng.index(3 * t.face_capacity()) as u32);
        if t.is_face(c.face()) {
            return c;
        }
    }
}

/// The numbering as a map from endpoint pairs to numbers (an independent view of it).
fn numbers_by_pair(t: &Triangulation, n: &EdgeNumbering) -> HashMap<(VertexId, VertexId), u32> {
    t.edges().map(|(a, b, c)| ((a, b), n.id(c).0)).collect()
}

#[test]
fn journal_undoes_random_interleavings_exactly_and_numbers_follow() {
    let (mut contractions, mut flips, mut undos) = (0, 0, 0);
    for (kind, seed) in surfaces() {
        for round in 0..6u64 {
            let input = surface(kind, seed * 100 + round, 60 + 20 * round as usize);
            let mut t = input.clone();
            let mut j = Journal::new();
            let mut numbers = EdgeNumbering::new(&t);
            let mut rng = Rng::new(seed ^ (round << 8));
            for step in 0..200 {
                let before = numbers_by_pair(&t, &numbers);
                let op = rng.below(10);
                match op {
                    0..=3 => {
                        let c = random_live_corner(&t, &mut rng);
                        let [a, b] = t.edge_endpoints(c);
                        let uv = numbers.id(c).0;
                        let passes = t.link_condition_naive(a, b);
                        match j.contract_at(&mut t, c) {
                            Ok(rec) => {
                                assert!(passes, "{kind:?}: contracted a failing edge");
                                let dead = numbers.contracted(&rec);
                                assert_eq!(dead[0].0, uv);
                                contractions += 1;
                                // Identity model: [b, z] became [a, z] with the same
                                // number, except [b, x], [b, y] which died in favour of
                                // [a, x], [a, y]; [a, b] died.
                                let after = numbers_by_pair(&t, &numbers);
                                let key = |p: VertexId, q: VertexId| (p.min(q), p.max(q));
                                for (&(p, q), &e) in &before {
                                    let (p2, q2) =
                                        (if p == b { a } else { p }, if q == b { a } else { q });
                                    if p2 == q2 {
                                        continue; // [a, b] itself
                                    }
                                    let merged_away = (p == b || q == b)
                                        && rec.link.contains(if p == b { &q } else { &p });
                                    if !merged_away {
                                        assert_eq!(after.get(&key(p2, q2)), Some(&e));
                                    }
                                }
                            }
                            Err(_) => assert!(!passes, "{kind:?}: refused a passing edge"),
                        }
                    }
                    4..=6 => {
                        let c = random_live_corner(&t, &mut rng);
                        let old = numbers.id(c).0;
                        if let Ok(rec) = j.flip_at(&mut t, c) {
                            numbers.flipped(&rec);
                            flips += 1;
                            let [w, z] = rec.new_edge;
                            let after = numbers_by_pair(&t, &numbers);
                            assert_eq!(after[&(w.min(z), w.max(z))], old);
                        }
                    }
                    _ => match j.undo(&mut t).expect("journal undo") {
                        Some(Op::Contraction(rec)) => {
                            numbers.uncontracted(&rec);
                            undos += 1;
                        }
                        Some(Op::Flip(rec)) => {
                            numbers.unflipped(&rec);
                            undos += 1;
                        }
                        None => {}
                    },
                }
                t.validate().unwrap_or_else(|e| panic!("{kind:?}: {e}"));
                numbers
                    .check(&t)
                    .unwrap_or_else(|e| panic!("{kind:?} step {step} op {op}: numbering: {e}"));
                assert_eq!(t.euler_characteristic(), input.euler_characteristic());
                assert_eq!(t.is_orientable(), input.is_orientable());
            }
            while let Some(op) = j.undo(&mut t).expect("journal undo") {
                match op {
                    Op::Contraction(rec) => numbers.uncontracted(&rec),
                    Op::Flip(rec) => numbers.unflipped(&rec),
                }
            }
            assert_eq!(t, input, "{kind:?} round {round}: not restored exactly");
            assert_eq!(t.state(), input.state(), "the state stamp is restored too");
            let fresh = EdgeNumbering::new(&input);
            for c in (0..3 * input.face_capacity() as u32).map(Corner) {
                assert_eq!(
                    numbers.id(c),
                    fresh.id(c),
                    "{kind:?}: number at {c} restored"
                );
            }
            assert_eq!(numbers.live_count(), fresh.live_count());
        }
    }
    assert!(
        contractions > 500 && flips > 500 && undos > 500,
        "mix: {contractions} contractions, {flips} flips, {undos} undos"
    );
}

#[test]
fn history_restores_exactly_or_is_refused_never_corrupts() {
    let (mut refused, mut accepted) = (0, 0);
    for (kind, seed) in surfaces() {
        for round in 0..4u64 {
            let input = surface(kind, seed * 1000 + round, 80);
            let mut t = input.clone();
            let mut h = History::new();
            // Model: the flips made after each recorded contraction (level 0: before any).
            let mut levels: Vec<Vec<contractible::FlipRecord>> = vec![Vec::new()];
            let mut rng = Rng::new(seed + 7 * round);
            for _ in 0..150 {
                match rng.below(6) {
                    0..=2 => {
                        let c = random_live_corner(&t, &mut rng);
                        if t.contract_at(c, &mut h).is_ok() {
                            levels.push(Vec::new());
                        }
                    }
                    3 => {
                        let c = random_live_corner(&t, &mut rng);
                        if let Ok(rec) = t.flip_at(c) {
                            levels.last_mut().expect("level 0").push(rec);
                        }
                    }
                    _ => {
                        let snapshot = t.clone();
                        let flipped_since = !levels.last().expect("level").is_empty();
                        match h.try_undo(&mut t) {
                            Ok(None) => assert_eq!(levels.len(), 1, "empty history"),
                            Ok(Some(_)) => {
                                assert!(!flipped_since, "undo after a flip accepted");
                                levels.pop();
                                accepted += 1;
                            }
                            Err(UndoError::Modified { .. }) => {
                                assert!(flipped_since, "refused without a flip");
                                assert_eq!(t, snapshot, "a refused undo changed the surface");
                                refused += 1;
                                // Unflipping (exactly, newest first) re-enables the undo.
                                while let Some(rec) = levels.last_mut().and_then(|l| l.pop()) {
                                    t.unflip(&rec).expect("unflip");
                                }
                                if levels.len() > 1 {
                                    h.try_undo(&mut t).expect("accepted after the unflips");
                                    levels.pop();
                                }
                            }
                            Err(e) => panic!("unexpected {e}"),
                        }
                    }
                }
                t.validate().unwrap_or_else(|e| panic!("{kind:?}: {e}"));
            }
            while let Some(mut level) = levels.pop() {
                while let Some(rec) = level.pop() {
                    t.unflip(&rec).expect("unflip");
                }
                if !levels.is_empty() {
                    h.undo(&mut t);
                }
            }
            assert!(h.is_empty());
            assert_eq!(t, input, "{kind:?}: not restored");
        }
    }
    assert!(
        refused > 10 && accepted > 10,
        "refused {refused}, accepted {accepted}"
    );
}

#[test]
fn the_guard_fires_on_a_flip_between_contraction_and_undo() {
    let input = surface(SurfaceKind::NonOrientable(2), 5, 40);
    let mut t = input.clone();
    let mut h = History::new();
    let (a, b, _) = t
        .edges()
        .find(|&(a, b, _)| t.link_condition_naive(a, b))
        .expect("a contractible edge");
    t.contract(a, b, &mut h).expect("contractible");
    let contracted = t.clone();
    let (p, q, c) = t
        .edges()
        .find(|&(p, q, _)| t.is_flippable(p, q))
        .expect("a flippable edge");
    let rec = t.flip_at(c).expect("flippable");
    let mut old = rec.old_edge;
    old.sort();
    assert_eq!(old, [p.min(q), p.max(q)]);
    let snapshot = t.clone();
    let err = h.try_undo(&mut t).expect_err("the guard must refuse");
    assert!(matches!(err, UndoError::Modified { u, v, .. } if u == a && v == b));
    assert_eq!(t, snapshot, "a refused undo changes nothing");
    assert_eq!(h.len(), 1, "the record stays for a later, valid undo");

    // Flipping the new edge back gives the contracted face set again, but not its slots
    // and not its state: still refused.
    let [w, z] = rec.new_edge;
    t.flip(w, z).expect("the new edge flips back");
    assert!(h.try_undo(&mut t).is_err());

    // `undo` panics where `try_undo` refuses.
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let mut t2 = snapshot.clone();
        let mut h2 = h.clone();
        h2.undo(&mut t2);
    }));
    assert!(r.is_err(), "undo must panic on a modified triangulation");

    // The exact unflip restores the recorded state, and the undo goes through.
    let mut t3 = snapshot;
    t3.unflip(&rec).expect("unflip of the newest flip");
    assert_eq!(t3, contracted);
    h.undo(&mut t3);
    assert_eq!(t3, input);
}

#[test]
fn a_history_is_refused_by_a_diverged_clone_with_the_same_arrays() {
    let input = surface(SurfaceKind::Orientable(1), 3, 50);
    let (a, b, _) = input
        .edges()
        .find(|&(a, b, _)| input.link_condition_naive(a, b))
        .unwrap();
    let mut t = input.clone();
    let mut h = History::new();
    t.contract(a, b, &mut h).unwrap();
    // The same contraction on another clone: equal arrays, but another state.
    let mut other = input.clone();
    other.contract(a, b, &mut History::new()).unwrap();
    assert_eq!(other, t);
    assert!(h.try_undo(&mut other).is_err());
    // A clone of `t` is the same state and accepts it.
    let mut clone = t.clone();
    assert!(h.clone().try_undo(&mut clone).is_ok());
    assert_eq!(clone, input);
}

#[test]
fn corner_helpers_agree_with_the_face_vertices() {
    for (kind, seed) in surfaces() {
        let t = surface(kind, seed, 120);
        for f in t.faces() {
            let vs = t.face_vertices(f);
            for c in f.corners() {
                let w = t.vertex(c);
                for &z in vs.iter().filter(|&&z| z != w) {
                    let k = t.corner_facing(c, z);
                    assert_eq!(k.face(), f);
                    assert!(t.vertex(k) != w && t.vertex(k) != z);
                    assert_eq!(t.vertex(t.corner_at(c, z)), z);
                }
            }
        }
        for (a, b, c) in t.edges() {
            let [c1, c2] = t.edge_corners(a, b).expect("an edge");
            assert_eq!(t.opposite(c1), c2);
            assert!(c == c1 || c == c2);
            let mut ends = t.edge_endpoints(c);
            ends.sort();
            assert_eq!(ends, [a, b]);
            // One canonical handle per edge, whichever opposite corner names it.
            assert_eq!(t.edge_at(c1), t.edge_at(c2));
            assert_eq!(t.edge_at(c).corner(), c1.min(c2));
            for k in [c1, c2] {
                let f = t.face_vertices(k.face());
                assert!(f.contains(&a) && f.contains(&b));
            }
            let mut link = t.edge_link(a, b).expect("an edge");
            link.sort();
            let mut want = [t.vertex(c1), t.vertex(c2)];
            want.sort();
            assert_eq!(link, want);
            assert_eq!(
                t.edge_link(b, a).map(|mut l| {
                    l.sort();
                    l
                }),
                Some(want)
            );
        }
    }
}

#[test]
fn every_link_test_agrees_with_the_definition() {
    let mut tester = contractible::LinkTester::new(0);
    for (kind, seed) in surfaces() {
        let t = surface(kind, seed + 50, 150);
        let vs: Vec<VertexId> = t.vertices().collect();
        for &u in &vs {
            for &v in &vs {
                let naive = t.link_condition_naive(u, v);
                assert_eq!(t.is_contractible(u, v), naive, "{kind:?} [{u}, {v}]");
                assert_eq!(t.is_contractible_with(u, v, &mut tester), naive);
            }
        }
    }
}
