//! `quad::frink`: Frink's reduction with the naive strategy (tri-quad paper, App. A),
//! checked by code that shares nothing with it: the fuzz harness's
//! `check_quadrangulation` (face lists, pairs and quads only) and petgraph's
//! `maximum_matching` of the dual graph (its size must be F/2, as the pairing's).
//! Under `invariants` (the README's test command) the specification checks F1/F2 run
//! on every step.
//!
//! Inputs: the standard small surfaces, random surfaces of every kind, the closed meshes
//! the repository carries and the generated closed surfaces of `closed_inputs` (by
//! default), and in the ignored `corpus` tests every closed mesh of the real-mesh corpus. The
//! naive strategy is O(F²), so meshes are covered up to [`MAX_FACES`] faces per
//! component (every face of every mesh with `FRINK_FULL=1`, see [`full`]). The link–cut
//! (`CoverTree`) and Diks–Stańczyk strategies run on every component, whatever its size.

use crate::{closed_inputs, common, harness};
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::frink::{self, BiedlBoseDemaineLubiw, CoverTree, DiksStanczyk, Naive};
use contractible::quad::{initial_stats, Algorithm, Pairing, Quadrangulation};
use contractible::{Surfaces, TriMesh, Triangulation};
use proptest::prelude::*;
use std::path::Path;

/// Largest component of a mesh run here (the naive strategy is quadratic), and the
/// largest checked against petgraph; `FRINK_FULL=1` lifts the first (see [`full`]).
const MAX_FACES: usize = 6_000;

/// Largest component of a corpus mesh the BBDL test runs (its 2-edge structure's
/// tree-edge deletions are not polylogarithmic; this keeps the test short);
/// `FRINK_FULL=1` lifts it.
const BBDL_MAX_FACES: usize = 15_000;

/// With `FRINK_FULL` set, the naive and BBDL tests run every component of every closed
/// mesh (up to 199,034 faces in the corpus) instead of stopping at [`MAX_FACES`] and
/// [`BBDL_MAX_FACES`]: the one-off run that shows each strategy on every corpus mesh
/// (`FRINK_FULL=1 cargo test --release --features invariants --test algorithms
/// quad_frink:: -- --include-ignored`; tens of minutes, the naive strategy being O(F²)).
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
    let (p, stats) = frink::perfect_matching_with(t, &mut naive).expect("a closed triangulation");
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
            frink::perfect_matching(t).as_ref() == Ok(&p),
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
            })
            .expect("a random surface within the limits");
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
    })
    .expect("a random surface within the limits");
    let t = contractible::irreducible::rs::reduce(t, &Default::default()).tri;
    assert!(t.face_capacity() > t.face_count());
    run(&t, "reduced", true);
}

/// Runs the naive strategy ([`run`]) on every component of `mesh` with at most `max`
/// faces; returns the components run, their faces, and the components skipped.
fn naive_on_components(mesh: &TriMesh, name: &str, max: usize) -> [usize; 3] {
    let s = Surfaces::from_mesh(mesh).unwrap_or_else(|e| panic!("{name}: {e}"));
    let (mut components, mut faces, mut skipped) = (0usize, 0usize, 0usize);
    for (k, comp) in s.components.iter().enumerate() {
        let t = &comp.tri;
        if t.face_count() > max {
            skipped += 1;
            continue;
        }
        run(t, &format!("{name}#{k}"), false);
        components += 1;
        faces += t.face_count();
    }
    [components, faces, skipped]
}

/// The naive strategy on every component of the closed meshes of the manifest of
/// `meshes` (at least `min_meshes`) with at most [`MAX_FACES`] faces (a mesh whose mean
/// component is larger is skipped whole, unread); returns the components run and
/// skipped.
fn naive_on_closed_meshes(meshes: &Path, min_meshes: usize) -> (usize, usize) {
    let rows: Vec<_> = common::manifest_in(meshes)
        .into_iter()
        .filter(|r| r.set == "closed")
        .collect();
    assert!(rows.len() >= min_meshes, "{} closed meshes", rows.len());
    let (mut components, mut faces, mut skipped) = (0usize, 0usize, 0usize);
    let clock = std::time::Instant::now();
    let max = cap(MAX_FACES);
    for row in &rows {
        if row.f > max.saturating_mul(row.components) {
            skipped += row.components;
            continue;
        }
        let path = meshes.join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let [c, f, k] = naive_on_components(&mesh, &row.name, max);
        assert_eq!(c + k, row.components, "{}", row.name);
        components += c;
        faces += f;
        skipped += k;
    }
    eprintln!(
        "frink: {components} components ({faces} faces) of {} closed meshes in {:.1} s, {skipped} larger skipped",
        rows.len(),
        clock.elapsed().as_secs_f64()
    );
    (components, skipped)
}

/// Every component of the closed meshes the repository carries with at most
/// [`MAX_FACES`] faces (the components run and skipped are those the face lists' own
/// components, found by union–find, say), and every component of the generated closed
/// surfaces of `closed_inputs` (all below the cap).
#[test]
fn repository_and_generated_closed_mesh_components() {
    let max = cap(MAX_FACES);
    let mut want = (0, 0);
    for row in common::data_manifest().iter().filter(|r| r.set == "closed") {
        let mesh = contractible::io::read_tri_mesh(&common::data_meshes().join(&row.file))
            .unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let sizes = closed_inputs::component_sizes(&mesh.faces);
        assert_eq!(sizes.len(), row.components, "{}", row.name);
        if row.f > max.saturating_mul(row.components) {
            want.1 += row.components;
        } else {
            want.0 += sizes.iter().filter(|&&f| f <= max).count();
            want.1 += sizes.iter().filter(|&&f| f > max).count();
        }
    }
    let got = naive_on_closed_meshes(&common::data_meshes(), 9);
    assert_eq!(got, want, "components covered, skipped");
    assert!(got.0 >= 15, "{got:?}");
    let mut generated = 0;
    for g in closed_inputs::closed_surfaces() {
        let [c, _, skipped] = naive_on_components(&g.mesh, &g.name, max);
        assert_eq!(skipped, 0, "{}", g.name);
        generated += c;
    }
    assert_eq!(generated, closed_inputs::COMPONENTS);
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
    let (p, stats) = frink::perfect_matching_with(t, &mut s).expect("a closed triangulation");
    check_sized(t, &p, label, algorithm);
    assert_eq!(stats.reductions, t.face_count() / 2 - 1, "{label}");
    if t.face_count() <= MAX_FACES {
        let (again, _) =
            frink::perfect_matching_with(t, &mut make()).expect("a closed triangulation");
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
    let (s, stats) = run_strategy(t, label, Algorithm::DiksStanczyk, DiksStanczyk::new);
    let c = s.counters();
    assert_eq!((stats.case_iv, c.restarts), (0, 0), "{label}: {c:?}");
    c
}

/// Runs the Biedl–Bose–Demaine–Lubiw strategy on `t` (checked by [`run_strategy`]);
/// its travelling forbidden edge must have kept every lift out of case (iv), and every
/// step was decided by the 2-edge structure.
fn run_bbdl(t: &Triangulation, label: &str) -> frink::BbdlCounters {
    let (s, stats) = run_strategy(
        t,
        label,
        Algorithm::BiedlBoseDemaineLubiw,
        BiedlBoseDemaineLubiw::new,
    );
    let c = s.counters();
    assert_eq!((stats.case_iv, c.restarts), (0, 0), "{label}: {c:?}");
    assert_eq!(c.took_h1 + c.took_h2, stats.reductions as u64, "{label}");
    c
}

/// Calls `f` on every component of every closed mesh of the manifest of `meshes` (label
/// `name#k`); returns the number of meshes, components and faces.
fn each_closed_component(meshes: &Path, mut f: impl FnMut(&Triangulation, &str)) -> [usize; 3] {
    let rows: Vec<_> = common::manifest_in(meshes)
        .into_iter()
        .filter(|r| r.set == "closed")
        .collect();
    let (mut components, mut faces) = (0usize, 0usize);
    for row in &rows {
        let path = meshes.join(&row.file);
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

/// Calls `f` on every component of the closed meshes the repository carries and of the
/// generated closed surfaces of `closed_inputs`; checks that every component was visited
/// (the manifest's count, and the generated ones') and returns the number of components
/// and faces.
fn each_repository_and_generated_component(mut f: impl FnMut(&Triangulation, &str)) -> [usize; 2] {
    let listed: usize = common::data_manifest()
        .iter()
        .filter(|r| r.set == "closed")
        .map(|r| r.components)
        .sum();
    let [meshes, mut components, mut faces] = each_closed_component(&common::data_meshes(), &mut f);
    assert_eq!(
        (meshes, components),
        (9, listed),
        "every repository component"
    );
    for g in closed_inputs::closed_surfaces() {
        for (k, t) in closed_inputs::components(&g.mesh, &g.name)
            .iter()
            .enumerate()
        {
            f(t, &format!("{}#{k}", g.name));
            components += 1;
            faces += t.face_count();
        }
    }
    assert_eq!(
        components,
        listed + closed_inputs::COMPONENTS,
        "every component"
    );
    [components, faces]
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
            })
            .expect("a random surface within the limits");
            f(&t, &format!("{kind:?} seed {seed}"));
        }
    }
}

/// Diks–Stańczyk on every component of the closed meshes the repository carries and of
/// the generated closed surfaces (no size limit), and on random surfaces of every kind
/// (orientable genus 0..8, non-orientable 1..6) at two sizes.
#[test]
fn diks_stanczyk_on_every_repository_and_generated_closed_mesh_and_random_surfaces() {
    let mut total = frink::DsCounters::default();
    let [components, faces] = each_repository_and_generated_component(|t, label| {
        total += run_ds(t, label);
    });
    eprintln!("ds: {components} components ({faces} faces), {total:?}");
    assert!(total.forced > 0 && total.free > 0, "{total:?}");
    each_random_surface(|t, label| {
        run_ds(t, label);
    });
}

/// Biedl–Bose–Demaine–Lubiw on every component of the closed meshes the repository
/// carries and of the generated closed surfaces (all below [`BBDL_MAX_FACES`] faces), and
/// on random surfaces of every kind at two sizes.
#[test]
fn bbdl_on_repository_and_generated_closed_meshes_and_random_surfaces() {
    let (mut runs, mut h2) = (0, 0);
    let [components, faces] = each_repository_and_generated_component(|t, label| {
        assert!(t.face_count() <= BBDL_MAX_FACES, "{label}");
        let c = run_bbdl(t, label);
        runs += 1;
        h2 += c.took_h2;
    });
    eprintln!("bbdl: {runs} of {components} components ({faces} faces); {h2} steps took H2");
    assert!(runs == components && h2 > 0, "{runs} runs, {h2} H2 steps");
    each_random_surface(|t, label| {
        run_bbdl(t, label);
    });
}

/// The link–cut strategy on every component of the closed meshes the repository carries
/// and of the generated closed surfaces, and on random surfaces of every kind.
#[test]
fn cover_tree_on_every_repository_and_generated_closed_mesh_and_random_surfaces() {
    let mut fallbacks = 0;
    let [components, faces] = each_repository_and_generated_component(|t, label| {
        fallbacks += run_cover(t, label).naive_steps;
    });
    eprintln!("frink-lct: {components} components ({faces} faces), {fallbacks} naive steps");
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
        }).expect("a random surface within the limits");
        run_ds(&t, &format!("{surface:?} F {} seed {seed}", t.face_count()));
    }
}

mod corpus {
    use super::*;

    /// Every component of the closed corpus meshes with at most [`MAX_FACES`] faces.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn shared_closed_mesh_components() {
        let got = naive_on_closed_meshes(&common::corpus_meshes(), 90);
        let want = if full() { (339 + 65, 0) } else { (339, 65) };
        assert_eq!(got, want, "components covered, skipped");
    }

    /// Calls `f` on every component of every closed corpus mesh (label `name#k`); returns
    /// the number of meshes, components and faces.
    fn each_shared_closed_component(f: impl FnMut(&Triangulation, &str)) -> [usize; 3] {
        each_closed_component(&common::corpus_meshes(), f)
    }

    /// Diks–Stańczyk on every component of every closed corpus mesh (no size limit: up to
    /// 199k faces), random surfaces of every kind (orientable genus 0..8, non-orientable
    /// 1..6) at two sizes.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
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

    /// Biedl–Bose–Demaine–Lubiw on every component of every closed corpus mesh up to
    /// [`BBDL_MAX_FACES`] faces (its 2-edge structure is not polylogarithmic: module
    /// `dyngraph::two_edge`) and random surfaces of every kind at two sizes.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
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

    /// The link–cut strategy on every component of every closed corpus mesh (no size limit:
    /// up to 199k faces), random surfaces of every kind and the standard ones.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
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
}
