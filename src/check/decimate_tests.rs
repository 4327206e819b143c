//! The `decimate` checker on the library's decimations (every target, placement, lock
//! and schedule, with and without the maps) and on wrong ones: stopped early, gone past
//! the target, maps that lie, moved locked vertices, positions off the input's.

use super::simplify_tests::{geometric, surfaces};
use super::tests::kinds;
use super::*;
use crate::decimate::{Placement, Schedule, NO_VERTEX};
use crate::{decimate as run_decimate, gen, DecimateOptions, DecimateResult, MaxError};

/// The check of `r` with the run's `o`, the maps stated or not.
fn judge(mesh: &TriMesh, r: &DecimateResult, o: &DecimateOptions, maps: bool) -> Verdict {
    let c = if maps {
        DecimateCheck::of_result(o, r)
    } else {
        DecimateCheck::of_run(o)
    };
    decimate(mesh, &r.mesh, &c).expect("the task accepts the input")
}

fn runs(faces: usize) -> Vec<DecimateOptions> {
    let half = faces / 2;
    vec![
        DecimateOptions::keep(0.25),
        DecimateOptions {
            schedule: Schedule::Passes,
            ..DecimateOptions::faces(half)
        },
        DecimateOptions {
            placement: Placement::Endpoint,
            ..DecimateOptions::keep(0.3)
        },
        DecimateOptions {
            placement: Placement::Midpoint,
            allow_foldover: true,
            ..DecimateOptions::default()
        },
        DecimateOptions {
            allow_foldover: true,
            schedule: Schedule::Passes,
            ..DecimateOptions::default()
        },
        DecimateOptions {
            max_error: Some(MaxError::Relative(0.02)),
            ..DecimateOptions::default()
        },
        DecimateOptions {
            lock_boundary: true,
            allow_foldover: true,
            locked: vec![0, 2],
            ..DecimateOptions::keep(0.1)
        },
        DecimateOptions {
            locked: vec![1],
            ..DecimateOptions::default()
        },
    ]
}

#[test]
fn the_librarys_decimations_pass_with_and_without_their_maps() {
    let mut blocked_unguarded = 0;
    // The small surfaces and one marching-tetrahedra sphere: every run of each.
    for (name, mesh) in surfaces()
        .into_iter()
        .chain(geometric().into_iter().take(1))
    {
        for o in runs(mesh.faces.len()) {
            let r = run_decimate(&mesh, &o).expect("decimates");
            for maps in [true, false] {
                let v = judge(&mesh, &r, &o, maps);
                assert!(v.passed(), "{name} {o:?} maps {maps}: {:?}", v.failures);
            }
            if o.allow_foldover && o.max_error.is_none() && !r.mesh.faces.is_empty() {
                blocked_unguarded +=
                    usize::from(r.stats.stopped == crate::decimate::Stopped::Blocked);
            }
        }
    }
    // The stop rule was judged (not skipped) on runs the link condition blocked.
    assert!(blocked_unguarded >= 10, "{blocked_unguarded}");
}

#[test]
fn stopping_early_or_going_past_the_target_is_named() {
    let mesh = geometric().remove(0).1;
    let unguarded = DecimateCheck {
        allow_foldover: true,
        ..DecimateCheck::default()
    };
    // The input as its own answer: above any target with collapsible edges left.
    let v = decimate(
        &mesh,
        &mesh,
        &DecimateCheck {
            keep: Some(0.5),
            ..unguarded.clone()
        },
    )
    .expect("judged");
    assert_eq!(kinds(&v), vec![FailureKind::TargetMissed]);
    assert!(v.failures.iter().all(|f| f.edge.is_some()));
    // Guarded, the checker cannot tell a guard's refusal from a missed edge: it passes.
    let guarded = DecimateCheck {
        keep: Some(0.5),
        ..DecimateCheck::default()
    };
    assert!(decimate(&mesh, &mesh, &guarded).expect("judged").passed());
    // With a cap, neither.
    let capped = DecimateCheck {
        keep: Some(0.5),
        max_error: Some(MaxError::Absolute(0.0)),
        ..unguarded.clone()
    };
    assert!(decimate(&mesh, &mesh, &capped).expect("judged").passed());
    // Locked everywhere: nothing could collapse.
    let all: Vec<u32> = (0..mesh.vertex_count as u32).collect();
    let locked = DecimateCheck {
        keep: Some(0.5),
        locked: &all,
        ..unguarded.clone()
    };
    assert!(decimate(&mesh, &mesh, &locked).expect("judged").passed());
    // An unguarded run stopped early, its output on its own (compacted) vertex list and
    // judged without maps: with nothing locked, its collapsible edges are still named.
    let half = run_decimate(
        &mesh,
        &DecimateOptions {
            allow_foldover: true,
            ..DecimateOptions::keep(0.5)
        },
    )
    .expect("decimates");
    assert_ne!(half.mesh.vertex_count, mesh.vertex_count);
    let v = decimate(
        &mesh,
        &half.mesh,
        &DecimateCheck {
            keep: Some(0.25),
            ..unguarded.clone()
        },
    )
    .expect("judged");
    assert_eq!(kinds(&v), vec![FailureKind::TargetMissed], "{v:?}");
    // A quarter of the faces judged against a target of a half: gone past it.
    let r = run_decimate(&mesh, &DecimateOptions::keep(0.25)).expect("decimates");
    let v = decimate(
        &mesh,
        &r.mesh,
        &DecimateCheck {
            keep: Some(0.5),
            ..DecimateCheck::default()
        },
    )
    .expect("judged");
    assert_eq!(kinds(&v), vec![FailureKind::TargetMissed]);
    assert!(v.failures[0].message.contains("went past its target"));
    // One collapse below the target is allowed (a collapse removes two faces).
    let t = r.mesh.faces.len() + 1;
    let v = decimate(
        &mesh,
        &r.mesh,
        &DecimateCheck {
            faces: Some(t),
            ..DecimateCheck::default()
        },
    )
    .expect("judged");
    assert!(v.passed(), "{v:?}");
    let v = decimate(
        &mesh,
        &r.mesh,
        &DecimateCheck {
            faces: Some(t + 1),
            ..DecimateCheck::default()
        },
    )
    .expect("judged");
    assert!(!v.passed());
}

#[test]
fn maps_that_lie_are_named() {
    let (_, mesh) = surfaces().remove(1);
    let o = DecimateOptions::keep(0.3);
    let r = run_decimate(&mesh, &o).expect("decimates");
    let check = |vm: &[u32], cm: &[u32], fo: &[u32]| {
        let c = DecimateCheck {
            keep: Some(0.3),
            vertex_map: Some(vm),
            collapse_map: Some(cm),
            face_origin: Some(fo),
            ..DecimateCheck::default()
        };
        decimate(&mesh, &r.mesh, &c).expect("judged")
    };
    let (vm, cm, fo) = (&r.vertex_map, &r.collapse_map, &r.face_origin);
    assert!(check(vm, cm, fo).passed());
    let mut bad = vm.clone();
    bad.swap(0, 1);
    assert!(kinds(&check(&bad, cm, fo)).contains(&FailureKind::InconsistentMap));
    let mut bad = vm.clone();
    bad[1] = bad[0];
    assert!(check(&bad, cm, fo).failures[0]
        .message
        .contains("named twice"));
    assert!(check(&vm[1..], cm, fo).failures[0]
        .message
        .contains("entries"));
    let mut bad = cm.clone();
    // An input vertex sent to another output vertex: classes no longer joined, or a
    // map that disagrees with vertex_map.
    let i = vm[0] as usize;
    bad[i] = (bad[i] + 1) % r.mesh.vertex_count as u32;
    assert!(kinds(&check(vm, &bad, fo)).contains(&FailureKind::InconsistentMap));
    let mut bad = cm.clone();
    bad[i] = NO_VERTEX;
    assert!(kinds(&check(vm, &bad, fo)).contains(&FailureKind::InconsistentMap));
    let mut bad = fo.clone();
    bad.swap(0, 1);
    let v = check(vm, cm, &bad);
    assert!(
        v.failures[0].message.contains("renamed by collapse_map"),
        "{v:?}"
    );
    let mut bad = fo.clone();
    bad[0] = mesh.faces.len() as u32;
    assert!(check(vm, cm, &bad).failures[0].message.contains("beyond"));
    // A face given no origin: an input face that keeps three corners is unaccounted for.
    let mut short = r.mesh.clone();
    short.faces.pop();
    let c = DecimateCheck {
        keep: Some(0.3),
        vertex_map: Some(vm),
        collapse_map: Some(cm),
        face_origin: Some(&fo[..fo.len() - 1]),
        ..DecimateCheck::default()
    };
    let v = decimate(&mesh, &short, &c).expect("judged");
    assert!(
        v.failures
            .iter()
            .any(|f| f.message.contains("no output face descends")),
        "{v:?}"
    );
    // An output vertex whose input vertices are not joined by input edges.
    let mut apart = cm.clone();
    let far = (0..mesh.vertex_count)
        .find(|&j| {
            cm[j] != cm[i]
                && !mesh
                    .faces
                    .iter()
                    .any(|f| f.contains(&(j as u32)) && f.iter().any(|&x| cm[x as usize] == cm[i]))
        })
        .expect("a far vertex");
    apart[far] = cm[i];
    let v = check(vm, &apart, fo);
    assert!(
        v.failures.iter().any(|f| f.message.contains("not joined")),
        "{v:?}"
    );
}

#[test]
fn locks_and_endpoint_positions_are_checked() {
    let (_, mesh) = surfaces().remove(4); // a torus with three holes
    let locked = vec![3u32, 8];
    let o = DecimateOptions {
        placement: Placement::Endpoint,
        lock_boundary: true,
        locked: locked.clone(),
        ..DecimateOptions::keep(0.3)
    };
    let r = run_decimate(&mesh, &o).expect("decimates");
    assert!(judge(&mesh, &r, &o, true).passed());
    // A locked vertex moved.
    let o3 = r.collapse_map[3] as usize;
    let mut moved = r.clone();
    if let Some(p) = moved.mesh.positions.as_mut() {
        p[o3][0] += 0.5;
    }
    let v = judge(&mesh, &moved, &o, true);
    assert!(kinds(&v).contains(&FailureKind::MovedVertex), "{v:?}");
    // Named by the output vertex it survives as (not its input id, 3).
    assert_ne!(o3, 3);
    let named = v
        .failures
        .iter()
        .find(|f| f.kind == FailureKind::MovedVertex);
    assert_eq!(named.and_then(|f| f.vertex), Some(o3 as u32), "{v:?}");
    // ... and no longer an input position: the endpoint placement is broken too.
    assert!(kinds(&v).contains(&FailureKind::InvalidPosition), "{v:?}");
    // Without the maps the output's vertices are not the input's (a compacted list):
    // the lock cannot be told, the position can.
    let v = judge(&mesh, &moved, &o, false);
    assert_eq!(kinds(&v), vec![FailureKind::InvalidPosition]);
    // At another input vertex's position, not one merged into it.
    let mut elsewhere = r.clone();
    let o5 = r.mesh.faces[0][0] as usize;
    let foreign = (0..mesh.vertex_count)
        .find(|&j| r.collapse_map[j] != o5 as u32 && r.collapse_map[j] != NO_VERTEX)
        .expect("another vertex");
    if let (Some(p), Some(q)) = (elsewhere.mesh.positions.as_mut(), mesh.positions.as_ref()) {
        p[o5] = q[foreign];
    }
    let v = judge(
        &mesh,
        &elsewhere,
        &DecimateOptions {
            lock_boundary: false,
            locked: vec![],
            ..o.clone()
        },
        true,
    );
    assert!(kinds(&v).contains(&FailureKind::InvalidPosition), "{v:?}");
}

#[test]
fn inputs_decimate_refuses_are_errors() {
    let mesh = gen::icosahedron();
    let c = DecimateCheck::default();
    let mut no_positions = mesh.clone();
    no_positions.positions = None;
    assert!(matches!(
        decimate(&no_positions, &mesh, &c),
        Err(Error::MissingPositions { task: "decimate" })
    ));
    let keep = DecimateCheck {
        keep: Some(1.5),
        ..DecimateCheck::default()
    };
    assert!(matches!(
        decimate(&mesh, &mesh, &keep),
        Err(Error::BadOption { option: "keep", .. })
    ));
    let locked = [99u32];
    let far = DecimateCheck {
        locked: &locked,
        ..DecimateCheck::default()
    };
    assert!(matches!(
        decimate(&mesh, &mesh, &far),
        Err(Error::BadOption {
            option: "locked",
            ..
        })
    ));
}

#[test]
fn a_map_that_lies_stops_the_checks_that_would_read_it() {
    let (_, mesh) = surfaces().remove(1);
    let o = DecimateOptions {
        locked: vec![5],
        ..DecimateOptions::keep(0.3)
    };
    let r = run_decimate(&mesh, &o).expect("decimates");
    assert!(judge(&mesh, &r, &o, true).passed());
    // One entry too many: one reason, and nothing reads the map past the output.
    let mut long = r.vertex_map.clone();
    long.push(0);
    let mut c = DecimateCheck::of_result(&o, &r);
    c.vertex_map = Some(&long);
    let v = decimate(&mesh, &r.mesh, &c).expect("judged");
    assert_eq!(v.counts, vec![(FailureKind::InconsistentMap, 1)], "{v:?}");
    // The locked vertex's survivor swapped with another in vertex_map: the maps
    // disagree, and the map is not used to find the locked vertex (which did not move).
    let kept = r.collapse_map[5] as usize;
    let mut swapped = r.vertex_map.clone();
    let other = (kept + 1) % swapped.len();
    swapped.swap(kept, other);
    let mut c = DecimateCheck::of_result(&o, &r);
    c.vertex_map = Some(&swapped);
    let v = decimate(&mesh, &r.mesh, &c).expect("judged");
    assert_eq!(kinds(&v), vec![FailureKind::InconsistentMap], "{v:?}");
}

#[test]
fn surface_changes_name_the_orientability() {
    // A Klein bottle answered by the 7-vertex torus on seven of its vertices: the reason
    // says which is which.
    let klein = super::tests::random(gen::SurfaceKind::NonOrientable(2), 200, 4);
    let torus = TriMesh::combinatorial(klein.vertex_count, gen::torus7().faces);
    let v = super::reduce(&klein, &torus).expect("judged");
    let changed = v
        .failures
        .iter()
        .find(|f| f.kind == FailureKind::SurfaceChanged)
        .expect("the surface changed");
    assert!(
        changed.message.contains("χ 0 non-orientable")
            && changed.message.contains("χ 0 orientable"),
        "{}",
        changed.message
    );
}

#[test]
fn endpoint_positions_take_minus_zero_as_zero() {
    // The octahedron (coordinates 0 and ±1) decimated with endpoint placement; its
    // output written with -0.0 for every 0.0, and the input with them too: the same
    // positions either way.
    let mesh = gen::octahedron();
    let o = DecimateOptions {
        placement: Placement::Endpoint,
        allow_foldover: true,
        ..DecimateOptions::faces(4)
    };
    let r = run_decimate(&mesh, &o).expect("decimates");
    let flip = |m: &TriMesh| {
        let mut m = m.clone();
        for p in m.positions.as_mut().expect("positions") {
            for x in p.iter_mut() {
                if *x == 0.0 {
                    *x = -*x;
                }
            }
        }
        m
    };
    let c = DecimateCheck::of_result(&o, &r);
    assert!(decimate(&mesh, &r.mesh, &c).expect("judged").passed());
    let v = decimate(&mesh, &flip(&r.mesh), &c).expect("judged");
    assert!(v.passed(), "{v:?}");
    let v = decimate(&flip(&mesh), &r.mesh, &c).expect("judged");
    assert!(v.passed(), "{v:?}");
}
