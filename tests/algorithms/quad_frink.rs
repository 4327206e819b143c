//! `quad::frink`: Frink's reduction with the naive strategy (tri-quad paper, App. A),
//! checked by code that shares nothing with it: the fuzz harness's
//! `check_quadrangulation` (face lists, pairs and quads only) and petgraph's
//! `maximum_matching` of the dual graph (its size must be F/2, as the pairing's). The
//! naive strategy is O(F²), so the shared meshes are covered up to [`MAX_FACES`] faces
//! (every face of every mesh with `FRINK_FULL=1`, see [`full`]).
//! Under `invariants` (the README's test command) the specification checks F1/F2 run
//! on every step. The link–cut (`CoverTree`) and Diks–Stańczyk strategies run on every
//! shared closed mesh, whatever its size.

use crate::{common, harness};
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::frink::{self, BiedlBoseDemaineLubiw, CoverTree, DiksStanczyk, Naive};
use contractible::quad::{initial_stats, Algorithm, Pairing, Quadrangulation};
use contractible::{Surfaces, Triangulation};
use proptest::prelude::*;

/// Largest component of a shared mesh run here (the naive strategy is quadratic), and
/// the largest checked against petgraph; `FRINK_FULL=1` lifts the first (see [`full`]).
const MAX_FACES: usize = 6_000;

/// Largest component of a shared mesh the BBDL test runs (its 2-edge structure's
/// tree-edge deletions are not polylogarithmic; this keeps the test short);
/// `FRINK_FULL=1` lifts it.
const BBDL_MAX_FACES: usize = 15_000;

/// With `FRINK_FULL` set, the naive and BBDL tests run every component of every shared
/// closed mesh (up to 199,034 faces) instead of stopping at [`MAX_FACES`] and
/// [`BBDL_MAX_FACES`]: the one-off run that shows each strategy on every mesh
/// (`FRINK_FULL=1 cargo test --release --features invariants --test algorithms
/// quad_frink::`; tens of minutes, the naive strategy being O(F²)).
fn full() -> bool {
    std::env::var_os("FRINK_FULL").is_some()
}

/// The size cap `cap`, or none under [`full`].
fn cap(cap: usize) -> usize {
    if full() {
        usize::MAX
    } else {
        cap
    }
}

/// Checks `p` independently: the harness's check of a conversion whose pairing is `p`
/// (the `algorithm` field is not read by it; the statistics are those of a perfect
/// initial pairing with no completion), and petgraph's maximum matching size.
fn check(t: &Triangulation, p: &Pairing, label: &str) {
    let q = Quadrangulation {
        algorithm: Algorithm::Matching,
        tri: t.clone(),
        pairing: p.clone(),
        stats: initial_stats(t, p, 0.0),
    };
    harness::check_quadrangulation(t, &q, label);
    let dual = common::dual_graph(t);
    let m = petgraph::algo::maximum_matching(&dual);
    assert_eq!(2 * m.len(), t.face_count(), "{label}: petgraph");
    assert_eq!(m.len(), p.len(), "{label}: size against petgraph");
}

/// [`check`] up to [`MAX_FACES`] faces; above, the harness's check alone (petgraph's
/// recursive matching takes seconds there and a deep stack).
fn check_sized(t: &Triangulation, p: &Pairing, label: &str, algorithm: Algorithm) {
    if t.face_count() <= MAX_FACES {
        check(t, p, label);
    } else {
        let q = Quadrangulation {
            algorithm,
            tri: t.clone(),
            pairing: p.clone(),
            stats: initial_stats(t, p, 0.0),
        };
        harness::check_quadrangulation(t, &q, label);
    }
}

/// Runs the naive strategy on `t`, checks the result, returns the counters; with
/// `twice`, runs it again and requires the same pairing.
fn run(t: &Triangulation, label: &str, twice: bool) -> frink::Stats {
    let mut naive = Naive::new();
    let (p, stats) = frink::perfect_matching_with(t, &mut naive);
    check_sized(t, &p, label, Algorithm::DsNaive);
    assert_eq!(
        stats.reductions,
        t.face_count() / 2 - 1,
        "{label}: reductions"
    );
    assert_eq!(
        stats.cases.iter().sum::<usize>(),
        stats.reductions,
        "{label}: one case per lift"
    );
    // One DFS per decision, a second only when H1 fails.
    let dfs = naive.dfs_runs() as usize;
    assert_eq!(
        dfs,
        2 * stats.reductions - stats.took_h1,
        "{label}: DFS runs"
    );
    if twice {
        assert!(
            frink::perfect_matching(t) == p,
            "{label}: differs between runs"
        );
    }
    stats
}

#[test]
fn the_standard_small_surfaces() {
    use contractible::gen::{
        icosahedron, klein_bottle, octahedron, projective_plane6, tetrahedron, torus7,
    };
    for (name, m) in [
        ("tetrahedron", tetrahedron()),
        ("octahedron", octahedron()),
        ("icosahedron", icosahedron()),
        ("torus7", torus7()),
        ("projective plane", projective_plane6()),
        ("Klein bottle", klein_bottle()),
    ] {
        let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect(name);
        run(&t, name, true);
    }
}

/// Random surfaces of genus 0..8 and Euler genus 1..6 (non-orientable), a few thousand
/// faces, and smaller ones; case (iv) must occur on some.
#[test]
fn random_surfaces_of_every_kind() {
    let kinds = (0..=8)
        .map(SurfaceKind::Orientable)
        .chain((1..=6).map(SurfaceKind::NonOrientable));
    let (mut inputs, mut case_iv, mut blossoms) = (0, 0, 0);
    for kind in kinds {
        for (seed, min_faces) in [(1u64, 200usize), (2, 3_000)] {
            let t = random(&RandomParams {
                surface: kind,
                min_faces,
                flip_percent: 30,
                seed,
            });
            let s = run(
                &t,
                &format!("{kind:?} seed {seed} F {}", t.face_count()),
                true,
            );
            inputs += 1;
            case_iv += s.case_iv;
            blossoms += s.blossoms;
        }
    }
    eprintln!(
        "frink random surfaces: {inputs} inputs, {case_iv} case (iv) lifts, {blossoms} blossoms"
    );
    assert_eq!(inputs, 30);
    assert!(case_iv > 0, "case (iv) never occurred");
}

/// Faces removed by contractions leave holes in the face ids.
#[test]
fn triangulations_with_removed_faces() {
    let t = random(&RandomParams {
        surface: SurfaceKind::NonOrientable(3),
        min_faces: 1_000,
        flip_percent: 30,
        seed: 5,
    });
    let t = contractible::irreducible::rs::reduce(t, &Default::default()).tri;
    assert!(t.face_capacity() > t.face_count());
    run(&t, "reduced", true);
}

/// Every component of the shared closed meshes with at most [`MAX_FACES`] faces.
#[test]
fn shared_closed_mesh_components() {
    let rows: Vec<_> = common::manifest()
        .into_iter()
        .filter(|r| r.set == "closed")
        .collect();
    assert!(rows.len() >= 90, "{} closed meshes", rows.len());
    let (mut components, mut faces, mut skipped) = (0usize, 0usize, 0usize);
    let clock = std::time::Instant::now();
    let max = cap(MAX_FACES);
    for row in &rows {
        if row.f > max.saturating_mul(row.components) {
            skipped += row.components;
            continue;
        }
        let path = common::shared_dir().join("meshes").join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let s = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        assert_eq!(s.components.len(), row.components, "{}", row.name);
        for (k, comp) in s.components.iter().enumerate() {
            let t = &comp.tri;
            if t.face_count() > max {
                skipped += 1;
                continue;
            }
            run(t, &format!("{}#{k}", row.name), false);
            components += 1;
            faces += t.face_count();
        }
    }
    eprintln!(
        "frink: {components} components ({faces} faces) of {} closed meshes in {:.1} s, {skipped} larger skipped",
        rows.len(),
        clock.elapsed().as_secs_f64()
    );
    let want = if full() { (339 + 65, 0) } else { (339, 65) };
    assert_eq!((components, skipped), want, "components covered, skipped");
}

/// Runs `make()`'s strategy on `t` and checks the result independently (the harness
/// check always, petgraph's matching size up to [`MAX_FACES`] faces, the same pairing
/// from a second run); returns the strategy and the counters.
fn run_strategy<S: frink::Strategy>(
    t: &Triangulation,
    label: &str,
    algorithm: Algorithm,
    make: impl Fn() -> S,
) -> (S, frink::Stats) {
    let mut s = make();
    let (p, stats) = frink::perfect_matching_with(t, &mut s);
    check_sized(t, &p, label, algorithm);
    assert_eq!(stats.reductions, t.face_count() / 2 - 1, "{label}");
    if t.face_count() <= MAX_FACES {
        let (again, _) = frink::perfect_matching_with(t, &mut make());
        assert!(again == p, "{label}: differs between runs");
    }
    (s, stats)
}

/// Runs the link–cut cover-count strategy on `t` (checked by [`run_strategy`]).
fn run_cover(t: &Triangulation, label: &str) -> frink::CoverCounters {
    run_strategy(t, label, Algorithm::FrinkLct, CoverTree::new)
        .0
        .counters()
}

/// Runs the Diks–Stańczyk strategy on `t` (checked by [`run_strategy`]); its travelling
/// forbidden edge must have kept every lift out of case (iv).
fn run_ds(t: &Triangulation, label: &str) -> frink::DsCounters {
    let (s, stats) = run_strategy(t, label, Algorithm::Ds, DiksStanczyk::new);
    let c = s.counters();
    assert_eq!((stats.case_iv, c.restarts), (0, 0), "{label}: {c:?}");
    c
}

/// Runs the Biedl–Bose–Demaine–Lubiw strategy on `t` (checked by [`run_strategy`]);
/// its travelling forbidden edge must have kept every lift out of case (iv), and every
/// step was decided by the 2-edge structure.
fn run_bbdl(t: &Triangulation, label: &str) -> frink::BbdlCounters {
    let (s, stats) = run_strategy(t, label, Algorithm::Bbdl, BiedlBoseDemaineLubiw::new);
    let c = s.counters();
    assert_eq!((stats.case_iv, c.restarts), (0, 0), "{label}: {c:?}");
    assert_eq!(c.took_h1 + c.took_h2, stats.reductions as u64, "{label}");
    c
}

/// Calls `f` on every component of every shared closed mesh (label `name#k`); returns
/// the number of meshes, components and faces.
fn each_shared_closed_component(mut f: impl FnMut(&Triangulation, &str)) -> [usize; 3] {
    let rows: Vec<_> = common::manifest()
        .into_iter()
        .filter(|r| r.set == "closed")
        .collect();
    let (mut components, mut faces) = (0usize, 0usize);
    for row in &rows {
        let path = common::shared_dir().join("meshes").join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let s = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        for (k, comp) in s.components.iter().enumerate() {
            f(&comp.tri, &format!("{}#{k}", row.name));
            components += 1;
            faces += comp.tri.face_count();
        }
    }
    [rows.len(), components, faces]
}

/// Calls `f` on random surfaces of every kind (orientable genus 0..8, non-orientable
/// 1..6) at two sizes (at least 200 and 3,000 faces).
fn each_random_surface(mut f: impl FnMut(&Triangulation, &str)) {
    let kinds = (0..=8)
        .map(SurfaceKind::Orientable)
        .chain((1..=6).map(SurfaceKind::NonOrientable));
    for kind in kinds {
        for (seed, min_faces) in [(1u64, 200usize), (2, 3_000)] {
            let t = random(&RandomParams {
                surface: kind,
                min_faces,
                flip_percent: 30,
                seed,
            });
            f(&t, &format!("{kind:?} seed {seed}"));
        }
    }
}

/// Diks–Stańczyk on every component of every shared closed mesh (no size limit: up to
/// 199k faces), random surfaces of every kind (orientable genus 0..8, non-orientable
/// 1..6) at two sizes.
#[test]
fn diks_stanczyk_on_every_shared_closed_mesh_and_random_surfaces() {
    let mut total = frink::DsCounters::default();
    let clock = std::time::Instant::now();
    let [meshes, components, faces] = each_shared_closed_component(|t, label| {
        total += run_ds(t, label);
    });
    eprintln!(
        "ds: {components} components ({faces} faces) of {meshes} closed meshes in {:.1} s, {total:?}",
        clock.elapsed().as_secs_f64()
    );
    assert_eq!(components, 339 + 65, "every component");
    assert!(total.forced > 0 && total.free > 0, "{total:?}");
    each_random_surface(|t, label| {
        run_ds(t, label);
    });
}

/// Biedl–Bose–Demaine–Lubiw on every component of every shared closed mesh up to
/// [`BBDL_MAX_FACES`] faces (its 2-edge structure is not polylogarithmic: module
/// `frink::two_edge`) and random surfaces of every kind at two sizes.
#[test]
fn bbdl_on_shared_closed_meshes_and_random_surfaces() {
    let (mut runs, mut skipped, mut h2, mut digons, mut swaps) = (0, 0, 0, 0, 0);
    let clock = std::time::Instant::now();
    let max = cap(BBDL_MAX_FACES);
    let [meshes, components, faces] = each_shared_closed_component(|t, label| {
        if t.face_count() > max {
            skipped += 1;
            return;
        }
        let c = run_bbdl(t, label);
        runs += 1;
        h2 += c.took_h2;
        digons += c.digon_steps;
        swaps += c.structure.swaps;
    });
    eprintln!(
        "bbdl: {runs} of {components} components ({faces} faces) of {meshes} closed meshes in {:.1} s ({skipped} above {BBDL_MAX_FACES} faces); {h2} steps took H2, {digons} digon steps, {swaps} swaps",
        clock.elapsed().as_secs_f64()
    );
    assert_eq!(components, 339 + 65, "every component");
    assert!(runs > 300 && h2 > 0, "{runs} runs, {h2} H2 steps");
    each_random_surface(|t, label| {
        run_bbdl(t, label);
    });
}

/// The link–cut strategy on every component of every shared closed mesh (no size limit:
/// up to 199k faces), random surfaces of every kind and the standard ones.
#[test]
fn cover_tree_on_every_shared_closed_mesh_and_random_surfaces() {
    let mut fallbacks = 0;
    let clock = std::time::Instant::now();
    let [meshes, components, faces] = each_shared_closed_component(|t, label| {
        fallbacks += run_cover(t, label).naive_steps;
    });
    eprintln!(
        "frink-lct: {components} components ({faces} faces) of {meshes} closed meshes in {:.1} s, {fallbacks} naive steps",
        clock.elapsed().as_secs_f64()
    );
    assert_eq!(components, 339 + 65, "every component");
    each_random_surface(|t, label| {
        run_cover(t, label);
    });
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    /// Diks–Stańczyk on any random closed surface (orientable genus 0..8 or
    /// non-orientable genus 1..6, any size up to 3,000 faces, any generator seed): a
    /// perfect pairing by the harness and petgraph, the same on a second run, and never
    /// a case (iv) lift.
    #[test]
    fn diks_stanczyk_on_any_random_surface(
        kind in 0usize..15,
        min_faces in 4usize..3_000,
        seed in any::<u64>(),
    ) {
        let surface = if kind <= 8 {
            SurfaceKind::Orientable(kind as u32)
        } else {
            SurfaceKind::NonOrientable(kind as u32 - 8)
        };
        let t = random(&RandomParams {
            surface,
            min_faces,
            flip_percent: 30,
            seed,
        });
        run_ds(&t, &format!("{surface:?} F {} seed {seed}", t.face_count()));
    }
}
