//! The progress observers of the long algorithms (`reduce_observed`, `convert_observed`,
//! `simplify_surfaces_observed`): they report inside a component (not only when it is
//! done), within each stage `done` never decreases and never exceeds `total`, a finished
//! stage ends at `done == total`, reports are throttled, and the result is exactly the
//! unobserved one.

use contractible::gen::{self, Implicit, IsoParams, RandomParams, SurfaceKind, Tessellation};
use contractible::irreducible::{self, Algorithm, Options};
use contractible::progress::{Progress, REPORT_EVERY};
use contractible::quad;
use contractible::simplify;
use contractible::{ConedSurfaces, Triangulation};

/// Checks the invariants of a sequence of reports; returns how many there were.
fn check_reports(reports: &[Progress], label: &str) -> usize {
    assert!(!reports.is_empty(), "{label}: no report");
    let mut prev: Option<Progress> = None;
    for &p in reports {
        assert!(p.done <= p.total, "{label}: {p:?}");
        if let Some(q) = prev {
            // A stage restarts (a new pass, the next step) only from a finished one.
            if q.stage == p.stage && p.done < q.done {
                assert_eq!(
                    q.done, q.total,
                    "{label}: {q:?} -> {p:?} went back mid-stage"
                );
            }
        }
        prev = Some(p);
    }
    let last = reports[reports.len() - 1];
    assert_eq!(last.done, last.total, "{label}: ends at {last:?}");
    reports.len()
}

fn random_surface(kind: SurfaceKind, faces: usize) -> Triangulation {
    gen::random(&RandomParams {
        surface: kind,
        min_faces: faces,
        flip_percent: 30,
        seed: 11,
    })
    .expect("a random surface within the limits")
}

#[test]
fn reductions_report_inside_the_component_and_match_the_unobserved_result() {
    // The sphere: RS contracts everything while processing its first vertex; genus 3:
    // the work is spread over many processed vertices.
    for surface in [
        random_surface(SurfaceKind::Orientable(0), 200_000),
        random_surface(SurfaceKind::Orientable(3), 60_000),
    ] {
        reductions_report_inside(&surface);
    }
}

fn reductions_report_inside(sphere: &Triangulation) {
    let n = sphere.vertex_count() as u64;
    let options = Options {
        seed: 5,
        count_retests: true,
        keep_history: true,
    };
    for algo in [Algorithm::Rs, Algorithm::Schipper, Algorithm::Brute] {
        let label = &format!("{} on {n} vertices", algo.name());
        let mut reports = Vec::new();
        let observed =
            irreducible::reduce_observed(sphere.clone(), algo, &options, &mut |p| reports.push(p));
        let plain = irreducible::reduce(sphere.clone(), algo, &options);
        assert_eq!(
            observed.tri.vertex_count(),
            plain.tri.vertex_count(),
            "{label}"
        );
        assert_eq!(observed.stats.link_tests, plain.stats.link_tests, "{label}");
        assert_eq!(
            observed.stats.contractions, plain.stats.contractions,
            "{label}"
        );
        assert_eq!(
            observed.stats.edges_tested_more_than_once, plain.stats.edges_tested_more_than_once,
            "{label}"
        );
        let count = check_reports(&reports, label);
        // Inside the only component: many reports strictly between 0 and the end (genus
        // 0: RS makes every contraction while processing its first vertex, and still
        // reports), but not one per step.
        let mut middle: Vec<u64> = reports
            .iter()
            .filter(|p| p.done > 0 && p.done < p.total)
            .map(|p| p.done)
            .collect();
        // One report per `REPORT_EVERY` units of work at most: on the smaller surface,
        // fewer than 10.
        let want = (n / REPORT_EVERY).saturating_sub(1).min(10) as usize;
        assert!(
            middle.len() >= want,
            "{label}: {middle:?} reports inside the work"
        );
        // ... and they count the work done: many different values.
        middle.dedup();
        assert!(
            middle.len() >= want,
            "{label}: reports inside at {middle:?}"
        );
        assert!(
            (count as u64) < 4 * n / REPORT_EVERY + 64,
            "{label}: {count} reports for {n} vertices"
        );
        if algo != Algorithm::Brute {
            assert!(reports.iter().all(|p| p.total == n), "{label}");
        }
    }
}

#[test]
fn tri_quad_reports_the_initial_step_and_the_completion() {
    let t = random_surface(SurfaceKind::NonOrientable(3), 20_000);
    let faces = t.face_count() as u64;
    for algo in [
        quad::Algorithm::Lrs,
        quad::Algorithm::PulliSegal,
        quad::Algorithm::SimpleGreedy,
        quad::Algorithm::Matching,
    ] {
        let label = algo.name();
        let options = quad::Options { seed: 2 };
        let mut reports = Vec::new();
        let q = quad::convert_observed(t.clone(), algo, &options, &mut |p| reports.push(p))
            .expect("a closed triangulation");
        let plain = quad::convert(t.clone(), algo, &options).expect("a closed triangulation");
        assert_eq!(q.pairing, plain.pairing, "{label}");
        check_reports(&reports, label);
        assert_eq!(
            reports[0],
            Progress::new(quad::INITIAL, 0, faces),
            "{label}"
        );
        assert!(
            reports
                .iter()
                .any(|p| p.stage == quad::INITIAL && p.done > 0)
                || algo == quad::Algorithm::Matching,
            "{label}: the initial step paired nothing"
        );
        let last = reports[reports.len() - 1];
        assert_eq!((last.done, last.total), (faces, faces), "{label}");
    }
}

#[test]
fn simplification_reports_every_pass_and_matches_the_unobserved_result() {
    let params = IsoParams::new(Implicit::GenusG { g: 2 }, Tessellation::BodyCentred, 48);
    let mesh = gen::isosurface(&params).expect("isosurface");
    let surfaces = ConedSurfaces::from_mesh(&mesh).expect("surface");
    let positions = mesh.positions.clone().expect("positions");
    let options = simplify::Options::new(0.01 * simplify::bbox_diagonal(positions.iter().copied()));
    let mut reports = Vec::new();
    let mut passes = 0;
    let observed = simplify::simplify_surfaces_observed(
        surfaces.clone(),
        &positions,
        &options,
        &mut |_| passes += 1,
        &mut |p| reports.push(p),
    )
    .expect("simplify");
    let plain =
        simplify::simplify_surfaces(surfaces, &positions, &options, &mut |_| {}).expect("simplify");
    assert_eq!(observed.mesh.faces, plain.mesh.faces);
    check_reports(&reports, "simplify");
    // Every pass starts at 0 and ends at its total, with reports in between on a mesh
    // this size.
    let starts = reports.iter().filter(|p| p.done == 0).count();
    assert_eq!(starts, passes);
    assert!(reports.iter().any(|p| p.done > 0 && p.done < p.total));
}

/// Simplification compacts its face slots once a third of them are dead: each pass
/// scans (reports as its total) the slots left by the pass before, which are that
/// pass's live faces if more than a third of its slots were dead, and the same slots
/// otherwise. On a closed surface (no cone faces) of one component, over every pass.
#[test]
fn simplification_compacts_once_a_third_of_the_slots_are_dead() {
    let params = IsoParams::new(Implicit::GenusG { g: 2 }, Tessellation::BodyCentred, 48);
    let mesh = gen::isosurface(&params).expect("isosurface");
    let surfaces = ConedSurfaces::from_mesh(&mesh).expect("surface");
    assert!(surfaces.is_closed() && surfaces.components.len() == 1);
    let positions = mesh.positions.clone().expect("positions");
    let diagonal = simplify::bbox_diagonal(positions.iter().copied());
    let (mut compacted, mut kept) = (0, 0);
    for fraction in [0.01, 0.03, 0.1] {
        let options = simplify::Options::new(fraction * diagonal);
        let mut slots = Vec::new();
        let mut faces = Vec::new();
        simplify::simplify_surfaces_observed(
            surfaces.clone(),
            &positions,
            &options,
            &mut |r| faces.push(r.faces),
            &mut |p| {
                if p.stage == simplify::SCANNED && p.done == 0 {
                    slots.push(p.total as usize);
                }
            },
        )
        .expect("simplify");
        assert_eq!(slots.len(), faces.len(), "one start per pass");
        assert_eq!(slots[0], mesh.faces.len());
        for k in 1..slots.len() {
            let (before, live) = (slots[k - 1], faces[k - 1]);
            if 3 * (before - live) > before {
                assert_eq!(slots[k], live, "{fraction}: pass {k}");
                compacted += 1;
            } else {
                assert_eq!(slots[k], before, "{fraction}: pass {k}");
                kept += 1;
            }
        }
    }
    assert!(
        compacted > 0 && kept > 0,
        "{compacted} compactions, {kept} kept"
    );
}
