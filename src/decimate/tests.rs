//! Unit tests of the decimator on small generated surfaces. In test builds the
//! specification checks (module `spec`: priority, quadric sums, stop rule) run on every
//! collapse of these runs, so each run here is also a check of M1–M3.

use super::{Placement, Schedule, Stopped};
use crate::gen::{self, Implicit, IsoParams, Tessellation};
use crate::{decimate, DecimateOptions, MaxError, TriMesh};

fn iso(shape: Implicit, n: u32) -> TriMesh {
    gen::isosurface(&IsoParams::new(shape, Tessellation::SixTetrahedra, n)).expect("a surface")
}

fn shapes() -> Vec<(&'static str, TriMesh)> {
    vec![
        ("sphere", iso(Implicit::Sphere { radius: 1.0 }, 7)),
        (
            "torus",
            iso(
                Implicit::Torus {
                    major: 1.0,
                    minor: 0.45,
                },
                9,
            ),
        ),
        ("genus 2", iso(Implicit::GenusG { g: 2 }, 9)),
        (
            "two discs",
            iso(
                Implicit::TwoSheetHyperboloid {
                    c: 0.3,
                    half_width: 1.0,
                    half_height: 1.2,
                },
                8,
            ),
        ),
    ]
}

/// A fraction kept, a face count, an error cap, no target (for `f` input faces).
fn targets(f: usize) -> [DecimateOptions; 4] {
    [
        DecimateOptions::keep(0.3),
        DecimateOptions::faces(f / 10),
        DecimateOptions {
            max_error: Some(MaxError::Relative(0.01)),
            ..Default::default()
        },
        DecimateOptions::default(),
    ]
}

#[test]
fn every_option_keeps_the_checks_and_the_output_check() {
    for (name, mesh) in shapes() {
        let f = mesh.faces.len();
        let targets = targets(f);
        let guards = [(true, false), (false, false), (true, true)];
        // Every placement with every guard setting, the targets taken in turn (the
        // checks examine every edge at every collapse: all 36 combinations per shape
        // would take minutes in debug builds).
        for (i, placement) in Placement::ALL.into_iter().enumerate() {
            for (j, &(guard, lock_boundary)) in guards.iter().enumerate() {
                let o = DecimateOptions {
                    placement,
                    allow_foldover: !guard,
                    lock_boundary,
                    locked: vec![0, 5],
                    ..targets[(i + j) % targets.len()].clone()
                };
                let d = decimate(&mesh, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
                assert!(d.verified);
                assert!(d.mesh.faces.len() <= f, "{name}");
                if d.stats.stopped == Stopped::Target {
                    let t = d.stats.target_faces.expect("a face target");
                    assert!(d.mesh.faces.len() <= t && d.mesh.faces.len() + 2 > t);
                }
                if let Some(cap) = d.stats.max_error_cap {
                    assert!(d.stats.max_error <= cap * (1.0 + 1e-12), "{name}");
                }
            }
        }
    }
}

#[test]
fn the_same_input_gives_the_same_output() {
    let mesh = iso(Implicit::GenusG { g: 2 }, 10);
    let o = DecimateOptions::keep(0.2);
    let a = decimate(&mesh, &o).expect("valid");
    let b = decimate(&mesh, &o).expect("valid");
    assert_eq!(a.mesh, b.mesh);
    assert_eq!(a.vertex_map, b.vertex_map);
    assert_eq!(a.collapse_map, b.collapse_map);
    assert_eq!(a.face_origin, b.face_origin);
}

#[test]
fn the_tetrahedron_is_irreducible_and_stays() {
    let mut t = gen::tetrahedron();
    t.positions = Some(vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ]);
    let d = decimate(
        &t,
        &DecimateOptions {
            allow_foldover: true,
            ..DecimateOptions::faces(0)
        },
    )
    .expect("valid");
    assert_eq!(d.mesh.faces.len(), 4);
    assert_eq!(d.stats.stopped, Stopped::Blocked);
    assert_eq!(d.stats.remaining.link_condition, 6);
}

/// The pass schedule under every option (the specification's P1, M2 and M3 run on every
/// collapse here), and where it must agree with the exact schedule: the stop rule, so
/// with no target both end blocked with every edge left refused.
#[test]
fn the_pass_schedule_keeps_the_checks_and_stops_where_nothing_passes() {
    for (name, mesh) in shapes() {
        let f = mesh.faces.len();
        let targets = targets(f);
        for (i, placement) in Placement::ALL.into_iter().enumerate() {
            for (j, target) in targets.iter().enumerate() {
                let o = DecimateOptions {
                    placement,
                    schedule: Schedule::Passes,
                    allow_foldover: (i + j) % 2 == 1,
                    lock_boundary: (i + j) % 3 == 2,
                    locked: vec![0, 5],
                    ..target.clone()
                };
                let d = decimate(&mesh, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
                assert!(d.verified && d.stats.passes > 0, "{name}");
                match d.stats.stopped {
                    Stopped::Target => {
                        let t = d.stats.target_faces.expect("a face target");
                        assert!(d.mesh.faces.len() <= t && d.mesh.faces.len() + 2 > t);
                    }
                    _ => assert!(d.stats.remaining.total() > 0, "{name}"),
                }
                if let Some(cap) = d.stats.max_error_cap {
                    assert!(d.stats.max_error <= cap * (1.0 + 1e-12), "{name}");
                }
            }
        }
    }
}

/// A target the input already meets makes no collapse, under both schedules (the run
/// stops at the first face count at or below the target, which is the input's).
#[test]
fn a_target_already_met_collapses_nothing() {
    for (name, mesh) in shapes() {
        let f = mesh.faces.len();
        for schedule in Schedule::ALL {
            for o in [DecimateOptions::faces(f), DecimateOptions::keep(1.0)] {
                let o = DecimateOptions { schedule, ..o };
                let d = decimate(&mesh, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
                assert_eq!(d.stats.stopped, Stopped::Target, "{name} {o:?}");
                assert_eq!((d.stats.collapses, d.stats.passes), (0, 0), "{name} {o:?}");
                assert_eq!(d.mesh.faces, mesh.faces, "{name} {o:?}");
            }
        }
    }
}

/// The names are the documented ones and read back as their choices; every choice has
/// its own non-empty summary (the command line's help lists them).
#[test]
fn choices_have_their_documented_names_and_distinct_summaries() {
    let names: Vec<_> = Placement::ALL.map(|p| p.name()).into();
    assert_eq!(names, ["optimal", "midpoint", "endpoint"]);
    let names: Vec<_> = Schedule::ALL.map(|s| s.name()).into();
    assert_eq!(names, ["exact", "passes"]);
    for p in Placement::ALL {
        assert_eq!(p.to_string().parse::<Placement>(), Ok(p));
    }
    for s in Schedule::ALL {
        assert_eq!(s.to_string().parse::<Schedule>(), Ok(s));
    }
    let summaries: [Vec<&str>; 2] = [
        Placement::ALL.map(|p| p.summary()).into(),
        Schedule::ALL.map(|s| s.summary()).into(),
    ];
    for mut lines in summaries {
        assert!(lines.iter().all(|l| !l.trim().is_empty()), "{lines:?}");
        let n = lines.len();
        lines.sort_unstable();
        lines.dedup();
        assert_eq!(lines.len(), n, "a repeated summary");
    }
}

/// A stop prints as its name, the one JSON and Python use.
#[test]
fn stops_print_as_their_names() {
    let stops = [Stopped::Target, Stopped::Error, Stopped::Blocked];
    assert_eq!(stops.map(|s| s.name()), ["target", "error", "blocked"]);
    for s in stops {
        assert_eq!(s.to_string(), s.name());
    }
}

/// A flat `k × k` grid of unit squares in the plane z = 0, each split along the same
/// diagonal, every face counter-clockwise seen from +z; the interior vertices take the
/// smallest ids (row by row), the border the rest.
fn flat_grid(k: u32) -> TriMesh {
    let border = |i: u32, j: u32| i == 0 || j == 0 || i == k - 1 || j == k - 1;
    let cells = || (0..k).flat_map(move |j| (0..k).map(move |i| (i, j)));
    let order = cells()
        .filter(|&(i, j)| !border(i, j))
        .chain(cells().filter(|&(i, j)| border(i, j)));
    let mut id = vec![0u32; (k * k) as usize];
    let mut positions = Vec::new();
    for (n, (i, j)) in order.enumerate() {
        id[(i + k * j) as usize] = n as u32;
        positions.push([f64::from(i), f64::from(j), 0.0]);
    }
    let mut faces = Vec::new();
    for j in 0..k - 1 {
        for i in 0..k - 1 {
            let v = |di: u32, dj: u32| id[(i + di + k * (j + dj)) as usize];
            faces.push([v(0, 0), v(1, 0), v(1, 1)]);
            faces.push([v(0, 0), v(1, 1), v(0, 1)]);
        }
    }
    TriMesh {
        vertex_count: positions.len(),
        positions: Some(positions),
        faces,
    }
}

/// Endpoint placement keeps the endpoint of smaller error, ties going to the smaller id.
/// On a flat grid every interior vertex's quadric is the plane's alone, so an edge
/// between interior vertices costs exactly 0 at either end: a tie. With the interior
/// first in id order, the first collapse is such an edge at vertex 0 (every cost is 0,
/// and keys order ties by ids), and the vertex it removes is the larger endpoint.
#[test]
fn endpoint_ties_keep_the_smaller_id() {
    let mesh = flat_grid(8);
    let faces = mesh.faces.len();
    for schedule in Schedule::ALL {
        let d = decimate(
            &mesh,
            &DecimateOptions {
                placement: Placement::Endpoint,
                schedule,
                ..DecimateOptions::faces(faces - 2)
            },
        )
        .expect("valid");
        assert_eq!(d.stats.collapses, 1, "{schedule:?}");
        let gone: Vec<usize> = (0..mesh.vertex_count)
            .filter(|&v| d.vertex_map[d.collapse_map[v] as usize] as usize != v)
            .collect();
        let [g] = gone[..] else {
            panic!("{schedule:?}: {gone:?} merged");
        };
        let kept = d.vertex_map[d.collapse_map[g] as usize];
        assert_eq!(kept, 0, "{schedule:?}: vertex {g} went into {kept}");
        assert!(
            g > 0 && g < 36,
            "{schedule:?}: {g} is not an interior vertex"
        );
    }
}

/// The exact schedule queues only edges both endpoints allow (locks, the error cap), so
/// its refusals while running are the link condition's and the fold-over guard's alone;
/// the edges the endpoints refuse show up only among those left at the end.
#[test]
fn the_exact_schedule_never_queues_an_edge_its_endpoints_refuse() {
    for (name, mesh) in shapes() {
        let o = DecimateOptions {
            lock_boundary: true,
            locked: (0..mesh.vertex_count as u32).step_by(7).collect(),
            max_error: Some(MaxError::Relative(0.02)),
            ..DecimateOptions::faces(0)
        };
        let d = decimate(&mesh, &o).unwrap_or_else(|e| panic!("{name}: {e}"));
        let r = d.stats.refused;
        assert_eq!((r.lock, r.boundary, r.error), (0, 0, 0), "{name}: {r:?}");
        let left = d.stats.remaining;
        assert!(left.lock > 0, "{name}: {left:?}");
        assert!(left.error > 0, "{name}: {left:?}");
    }
}
