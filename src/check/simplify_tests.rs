//! The `simplify` checker: its link test with boundary against the core's coned
//! predicates, the library's own outputs, outputs that stop early, and every failure
//! kind on a corrupted output.

use super::*;
use crate::gen::{self, Implicit, IsoParams, RandomParams, SurfaceKind, Tessellation};
use crate::simplify::{Mode, Position};
use crate::{simplify as run_simplify, ConedSurfaces, Eps, SimplifyOptions, Triangulation};

fn kinds(v: &Verdict) -> Vec<FailureKind> {
    let mut k: Vec<FailureKind> = v.counts.iter().map(|&(k, _)| k).collect();
    k.sort_unstable();
    k
}

fn count(v: &Verdict, kind: FailureKind) -> usize {
    v.counts
        .iter()
        .find(|(k, _)| *k == kind)
        .map_or(0, |&(_, n)| n)
}

/// A uniform number in [0, 1) from `rng` (its top 53 bits).
fn uniform(rng: &mut crate::rng::Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

/// Seeded positions in the unit cube.
fn random_positions(n: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = crate::rng::Rng::new(seed);
    let mut unit = || uniform(&mut rng);
    (0..n).map(|_| [unit(), unit(), unit()]).collect()
}

fn random(kind: SurfaceKind, faces: usize, seed: u64) -> TriMesh {
    let t = gen::random(&RandomParams {
        surface: kind,
        min_faces: faces,
        flip_percent: 30,
        seed,
    })
    .expect("a random surface");
    TriMesh::with_positions(random_positions(t.vertex_capacity(), seed), t.face_list())
}

fn iso(implicit: Implicit, resolution: u32) -> TriMesh {
    gen::isosurface(&IsoParams::new(
        implicit,
        Tessellation::SixTetrahedra,
        resolution,
    ))
    .expect("a valid isosurface")
}

/// `mesh` without the open stars of `k` vertices whose closed stars are disjoint (the
/// first found in id order, every `step`-th): `k` holes, the vertex list kept.
fn with_holes(mesh: &TriMesh, k: usize, step: usize) -> TriMesh {
    let mut taken = vec![false; mesh.vertex_count];
    let mut centres = Vec::new();
    for v in (0..mesh.vertex_count as u32).step_by(step.max(1)) {
        if centres.len() == k {
            break;
        }
        let star: Vec<u32> = mesh
            .faces
            .iter()
            .filter(|f| f.contains(&v))
            .flatten()
            .copied()
            .collect();
        if star.is_empty() || star.iter().any(|&x| taken[x as usize]) {
            continue;
        }
        for &x in &star {
            taken[x as usize] = true;
        }
        centres.push(v);
    }
    assert_eq!(centres.len(), k, "{k} holes");
    TriMesh {
        faces: mesh
            .faces
            .iter()
            .filter(|f| !f.iter().any(|v| centres.contains(v)))
            .copied()
            .collect(),
        ..mesh.clone()
    }
}

/// Surfaces with and without boundary, with positions.
pub(super) fn surfaces() -> Vec<(&'static str, TriMesh)> {
    let torus = random(SurfaceKind::Orientable(1), 200, 1);
    let klein = random(SurfaceKind::NonOrientable(2), 200, 4);
    let hyperboloid = iso(
        Implicit::TwoSheetHyperboloid {
            c: 0.25,
            half_width: 1.0,
            half_height: 1.0,
        },
        14,
    );
    vec![
        ("icosahedron", gen::icosahedron()),
        ("torus", torus.clone()),
        ("genus 3", random(SurfaceKind::Orientable(3), 300, 2)),
        ("klein bottle", klein.clone()),
        ("torus with 3 holes", with_holes(&torus, 3, 7)),
        ("klein bottle with 2 holes", with_holes(&klein, 2, 5)),
        ("sphere with 2 holes", with_holes(&gen::icosahedron(), 2, 1)),
        ("hyperboloid", hyperboloid),
        (
            "genus 2 with 2 holes",
            with_holes(&iso(Implicit::GenusG { g: 2 }, 16), 2, 11),
        ),
        (
            "one triangle",
            TriMesh::with_positions(random_positions(3, 9), vec![[0, 1, 2]]),
        ),
        (
            "two-triangle disc",
            TriMesh::with_positions(random_positions(4, 9), vec![[0, 1, 2], [0, 2, 3]]),
        ),
        (
            "tetrahedron",
            TriMesh::with_positions(random_positions(4, 3), gen::tetrahedron().faces),
        ),
    ]
}

/// Every edge of `mesh` that passes the core's link condition of the surface with
/// boundary (`ConedComponent::is_contractible`), by mesh ids; on closed components also
/// asserted equal to the naive predicate.
fn core_contractible(mesh: &TriMesh) -> Vec<[u32; 2]> {
    let s = ConedSurfaces::from_mesh(mesh).expect("a surface");
    let mut out = Vec::new();
    for c in &s.components {
        let t = c.tri();
        for (a, b, _) in t.edges() {
            if c.is_virtual(a) || c.is_virtual(b) {
                continue;
            }
            let yes = c.is_contractible(a, b);
            if c.is_closed() {
                assert_eq!(yes, t.link_condition_naive(a, b));
            }
            if yes {
                let (x, y) = (c.vertex_origin[a.index()], c.vertex_origin[b.index()]);
                out.push([x.min(y), x.max(y)]);
            }
        }
    }
    out.sort_unstable();
    out
}

/// Every edge is shorter than this; with the guard off, the flagged edges are exactly
/// those passing the link condition.
fn every_edge() -> SimplifyCheck {
    SimplifyCheck {
        allow_foldover: true,
        ..SimplifyCheck::absolute(1e300)
    }
}

fn flagged(v: &Verdict) -> Vec<[u32; 2]> {
    let mut e: Vec<[u32; 2]> = v
        .failures
        .iter()
        .filter(|f| f.kind == FailureKind::ShortContractibleEdge)
        .filter_map(|f| f.edge)
        .collect();
    e.sort_unstable();
    e
}

#[test]
fn the_link_test_with_boundary_is_the_cores() {
    let mut with_boundary = 0;
    for (name, mesh) in surfaces() {
        let a = analyse(mesh.vertex_count, &mesh.faces, "x").unwrap_or_else(|_| panic!("{name}"));
        let mut ours: Vec<[u32; 2]> = a
            .edges
            .iter()
            .filter(|&&(e, o, f)| simplify_check::passes_link_condition(&a, e, o, f))
            .map(|&((x, y), _, _)| [x, y])
            .collect();
        ours.sort_unstable();
        let core = core_contractible(&mesh);
        assert_eq!(ours, core, "{name}");
        // Through the public call: all edges short, the guard off.
        let v = simplify(&mesh, &mesh, &every_edge()).expect("a valid input");
        assert_eq!(
            count(&v, FailureKind::ShortContractibleEdge),
            core.len(),
            "{name}"
        );
        if core.len() <= surface::LISTED {
            assert_eq!(flagged(&v), core, "{name}");
        }
        if a.parts.iter().any(|p| p.boundary_loops > 0) {
            with_boundary += 1;
        }
    }
    assert!(with_boundary >= 6);
}

#[test]
fn the_link_test_agrees_on_partly_contracted_surfaces_with_boundary() {
    // Contract random edges passing the core's coned test (never a virtual vertex):
    // surfaces with boundary where many edges fail the link condition.
    for seed in 0..8u64 {
        let kind = [SurfaceKind::Orientable(0), SurfaceKind::Orientable(2)][seed as usize % 2];
        let mesh = with_holes(&random(kind, 150, 40 + seed), 1 + seed as usize % 3, 3);
        let s = ConedSurfaces::from_mesh(&mesh).expect("a surface");
        let c = &s.components[0];
        let mut t: Triangulation = c.tri().clone();
        let mut rng = crate::rng::Rng::new(seed);
        let mut scratch = Vec::new();
        for _ in 0..(t.face_count() / 3) {
            let edges: Vec<_> = t
                .edges()
                .filter(|&(a, b, _)| coned_contractible(c, &t, a, b))
                .collect();
            if edges.is_empty() {
                break;
            }
            let (a, b, _) = edges[rng.below(edges.len() as u64) as usize];
            t.collapse(a, b, &mut scratch);
        }
        // The real faces, in local ids; the loops' apexes are the ids from
        // `real_vertex_count` on.
        let real = c.real_vertex_count() as u32;
        let faces: Vec<[u32; 3]> = t
            .face_list()
            .into_iter()
            .filter(|f| f.iter().all(|&v| v < real))
            .collect();
        let n = real as usize;
        let a = analyse(n, &faces, "x").unwrap_or_else(|_| panic!("seed {seed}"));
        let mut ours: Vec<[u32; 2]> = a
            .edges
            .iter()
            .filter(|&&(e, o, f)| simplify_check::passes_link_condition(&a, e, o, f))
            .map(|&((x, y), _, _)| [x, y])
            .collect();
        ours.sort_unstable();
        let mut theirs: Vec<[u32; 2]> = t
            .edges()
            .filter(|&(a, b, _)| coned_contractible(c, &t, a, b))
            .map(|(a, b, _)| [a.0.min(b.0), a.0.max(b.0)])
            .collect();
        theirs.sort_unstable();
        assert_eq!(ours, theirs, "seed {seed}");
        let failing = a.edges.len() - ours.len();
        assert!(failing > 0 && !ours.is_empty(), "seed {seed}: both kinds");
    }
}

/// The link condition of the surface with boundary on `t`, a contracted copy of `c`'s
/// coned surface, by the core's predicates (the fast and the naive test must agree): no
/// virtual end, the closed test, and not two different loops (read in `t`: a vertex's
/// loop is its virtual neighbour).
fn coned_contractible(
    c: &crate::core::ConedComponent,
    t: &Triangulation,
    a: crate::core::VertexId,
    b: crate::core::VertexId,
) -> bool {
    if c.is_virtual(a) || c.is_virtual(b) {
        return false;
    }
    let closed = t.is_contractible(a, b);
    assert_eq!(closed, t.link_condition_naive(a, b));
    let apex = |v| t.link(v).find(|&w| c.is_virtual(w));
    closed
        && match (apex(a), apex(b)) {
            (Some(x), Some(y)) => x == y,
            _ => true,
        }
}

fn options(mode: Mode, position: Position, allow_foldover: bool, eps: Eps) -> SimplifyOptions {
    SimplifyOptions {
        eps,
        mode,
        position,
        allow_foldover,
        ..SimplifyOptions::default()
    }
}

/// `mesh` with every position moved by up to `amount` of the bounding box (seeded), so
/// that the guard has triangles to refuse.
fn perturbed(mesh: &TriMesh, amount: f64, seed: u64) -> TriMesh {
    let mut rng = crate::rng::Rng::new(seed);
    let mut unit = || uniform(&mut rng) - 0.5;
    let mut m = mesh.clone();
    for p in m.positions.as_mut().expect("positions") {
        for x in p.iter_mut() {
            *x += amount * unit();
        }
    }
    m
}

pub(super) fn geometric() -> Vec<(&'static str, TriMesh)> {
    let hyperboloid = iso(
        Implicit::TwoSheetHyperboloid {
            c: 0.25,
            half_width: 1.0,
            half_height: 1.0,
        },
        16,
    );
    let genus2 = iso(Implicit::GenusG { g: 2 }, 20);
    vec![
        ("sphere", iso(Implicit::Sphere { radius: 1.0 }, 12)),
        ("genus 2", genus2.clone()),
        ("genus 2, perturbed", perturbed(&genus2, 0.15, 5)),
        ("hyperboloid", hyperboloid.clone()),
        ("hyperboloid, perturbed", perturbed(&hyperboloid, 0.1, 6)),
        ("genus 2 with 3 holes", with_holes(&genus2, 3, 13)),
    ]
}

#[test]
fn the_librarys_outputs_pass_and_the_guard_is_recomputed() {
    let mut foldovers = 0;
    for (name, mesh) in geometric() {
        for mode in [Mode::Naive, Mode::Nested] {
            for position in [Position::Midpoint, Position::Quadric] {
                for allow_foldover in [false, true] {
                    for rel in [0.03, 0.1] {
                        let eps = Eps::Relative(rel);
                        let label = format!("{name} {mode:?} {position:?} {allow_foldover} {rel}");
                        let r = run_simplify(&mesh, &options(mode, position, allow_foldover, eps))
                            .unwrap_or_else(|e| panic!("{label}: {e}"));
                        let check = SimplifyCheck {
                            eps,
                            position,
                            allow_foldover,
                        };
                        let v = simplify(&mesh, &r.mesh, &check).expect("a valid input");
                        assert!(v.passed(), "{label}: {:?}", v.failures);
                        if mode == Mode::Naive && position == Position::Midpoint && !allow_foldover
                        {
                            // The short edges the guard alone kept: flagged exactly when
                            // the check is told the guard was off.
                            let off = SimplifyCheck {
                                allow_foldover: true,
                                ..check
                            };
                            let v = simplify(&mesh, &r.mesh, &off).expect("valid");
                            assert_eq!(
                                count(&v, FailureKind::ShortContractibleEdge),
                                r.stats.remaining.foldover,
                                "{label}"
                            );
                            foldovers += r.stats.remaining.foldover;
                        }
                    }
                }
            }
        }
    }
    assert!(foldovers > 0, "some short edge kept by the guard");
}

#[test]
fn an_output_that_stops_early_fails_exactly_when_the_library_would_go_on() {
    let mut stopped = 0;
    for (name, mesh) in geometric() {
        for allow_foldover in [false, true] {
            for (smaller, larger) in [(0.01, 0.05), (0.03, 0.06), (0.05, 0.05)] {
                let o = |rel| options(Mode::Naive, Position::Midpoint, allow_foldover, rel);
                let r = run_simplify(&mesh, &o(Eps::Relative(smaller))).expect("simplifies");
                // Judged against the larger ε (absolute: the output's own diagonal is
                // smaller than the input's).
                let eps = larger * r.bbox_diagonal;
                let check = SimplifyCheck {
                    allow_foldover,
                    ..SimplifyCheck::absolute(eps)
                };
                let v = simplify(&mesh, &r.mesh, &check).expect("valid");
                let again = run_simplify(&r.mesh, &o(Eps::Absolute(eps))).expect("simplifies");
                let label = format!("{name} {allow_foldover} {smaller} {larger}");
                assert_eq!(
                    v.passed(),
                    again.stats.edges_contracted == 0,
                    "{label}: {:?}",
                    v.failures
                );
                assert!(
                    kinds(&v)
                        .iter()
                        .all(|&k| k == FailureKind::ShortContractibleEdge),
                    "{label}"
                );
                if !v.passed() {
                    stopped += 1;
                    assert!(v
                        .failures
                        .iter()
                        .all(|f| f.edge.is_some() && f.face.is_some()));
                }
            }
        }
    }
    assert!(stopped >= 10, "{stopped}");
}

#[test]
fn the_input_as_its_own_output_keeps_its_surfaces_but_stops_early() {
    for (name, mesh) in geometric() {
        let v = simplify(&mesh, &mesh, &SimplifyCheck::relative(0.05)).expect("valid");
        assert_eq!(kinds(&v), [FailureKind::ShortContractibleEdge], "{name}");
        // With an ε below every edge: nothing to contract.
        let v = simplify(&mesh, &mesh, &SimplifyCheck::absolute(1e-12)).expect("valid");
        assert!(v.passed(), "{name}: {:?}", v.failures);
    }
}

#[test]
fn eps_is_strict_and_relative_to_the_inputs_used_vertices() {
    // A unit square as two triangles: sides 1, diagonal √2; an unused far vertex.
    let positions = vec![
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
        [100.0, 100.0, 100.0],
    ];
    let disc = TriMesh::with_positions(positions, vec![[0, 1, 2], [0, 2, 3]]);
    // Every side passes the link condition (a disc of two triangles).
    let at = |e: f64| simplify(&disc, &disc, &SimplifyCheck::absolute(e)).expect("valid");
    assert!(at(1.0).passed(), "length 1 is not shorter than ε = 1");
    assert_eq!(
        count(&at(1.0 + 1e-15), FailureKind::ShortContractibleEdge),
        4
    );
    // The diagonal (√2, of the square's bounding box: the unused vertex is not counted)
    // times 1/√2 is 1 up to rounding; the library's ε is the same number.
    let rel = std::f64::consts::FRAC_1_SQRT_2;
    let r = run_simplify(&disc, &SimplifyOptions::relative(rel)).expect("simplifies");
    let v = simplify(&disc, &disc, &SimplifyCheck::relative(rel)).expect("valid");
    let short = r.eps > 1.0;
    assert_eq!(v.passed(), !short, "ε = {}", r.eps);
    assert!(simplify(&disc, &r.mesh, &SimplifyCheck::relative(rel))
        .expect("valid")
        .passed());
}

#[test]
fn invalid_positions_are_located() {
    let sphere = iso(Implicit::Sphere { radius: 1.0 }, 10);
    let r = run_simplify(&sphere, &SimplifyOptions::relative(0.05)).expect("simplifies");
    let check = SimplifyCheck::relative(0.05);
    let bare = TriMesh::combinatorial(r.mesh.vertex_count, r.mesh.faces.clone());
    let v = simplify(&sphere, &bare, &check).expect("valid");
    assert_eq!(kinds(&v), [FailureKind::InvalidPosition]);
    assert_eq!(v.failures[0].vertex, None);
    let mut nan = r.mesh.clone();
    let used = nan.faces[3][1];
    nan.positions.as_mut().expect("positions")[used as usize][1] = f64::NAN;
    let v = simplify(&sphere, &nan, &check).expect("valid");
    assert_eq!(kinds(&v), [FailureKind::InvalidPosition]);
    assert_eq!(v.failures[0].vertex, Some(used));
    let mut short = r.mesh.clone();
    short.positions.as_mut().expect("positions").pop();
    let v = simplify(&sphere, &short, &check).expect("valid");
    assert_eq!(kinds(&v), [FailureKind::InvalidPosition]);
    assert_eq!(v.failures[0].vertex, Some(short.vertex_count as u32 - 1));
}

/// Two meshes side by side, the second moved by `shift`.
fn union(a: &TriMesh, b: &TriMesh, shift: f64) -> TriMesh {
    let n = a.vertex_count as u32;
    let mut faces = a.faces.clone();
    faces.extend(b.faces.iter().map(|f| f.map(|v| v + n)));
    let mut positions = a.positions.clone().expect("positions");
    positions.extend(
        b.positions
            .as_deref()
            .expect("positions")
            .iter()
            .map(|p| p.map(|x| x + shift)),
    );
    TriMesh::with_positions(positions, faces)
}

#[test]
fn changed_surfaces_are_named_by_type_or_by_id() {
    let sphere = iso(Implicit::Sphere { radius: 1.0 }, 10);
    let torus = iso(
        Implicit::Torus {
            major: 1.0,
            minor: 0.4,
        },
        16,
    );
    let check = SimplifyCheck::relative(0.05);
    let s = run_simplify(&sphere, &SimplifyOptions::relative(0.05)).expect("simplifies");
    // A sphere for a torus (compacted: matched as types).
    let v = simplify(&torus, &s.mesh, &check).expect("valid");
    assert!(kinds(&v).contains(&FailureKind::SurfaceChanged), "{v:?}");
    assert_eq!(v.failures[0].component, Some(0));
    // A face taken out: one more boundary loop, χ one less.
    let mut holed = s.mesh.clone();
    holed.faces.remove(5);
    let v = simplify(&sphere, &holed, &check).expect("valid");
    let changed: Vec<&Failure> = v
        .failures
        .iter()
        .filter(|f| f.kind == FailureKind::SurfaceChanged)
        .collect();
    assert_eq!(changed.len(), 1, "{v:?}");
    assert!(
        changed[0].message.contains("1 boundary loop"),
        "{}",
        changed[0].message
    );
    // The same by id: the input's vertex list kept, one face out.
    let mut same_list = sphere.clone();
    same_list.faces.remove(0);
    let v = simplify(&sphere, &same_list, &check).expect("valid");
    assert!(kinds(&v).contains(&FailureKind::SurfaceChanged), "{v:?}");
    // Only the loops differ: a disc with one hole is an annulus (χ 0), a torus has χ 0
    // too but no loop.
    let annulus = with_holes(&sphere, 2, 17);
    let t = run_simplify(&torus, &SimplifyOptions::relative(0.05)).expect("simplifies");
    let v = simplify(&annulus, &t.mesh, &check).expect("valid");
    assert!(kinds(&v).contains(&FailureKind::SurfaceChanged), "{v:?}");
    // Two components in, one out; one in, two out.
    let two = union(&sphere, &torus, 5.0);
    let v = simplify(&two, &s.mesh, &SimplifyCheck::absolute(s.eps)).expect("valid");
    assert_eq!(kinds(&v), [FailureKind::ComponentLost], "{v:?}");
    assert_eq!(v.failures[0].component, Some(1));
    let both = union(&s.mesh, &t.mesh, 5.0);
    let v = simplify(&sphere, &both, &check).expect("valid");
    assert!(kinds(&v).contains(&FailureKind::ComponentSplit), "{v:?}");
    // Both, in either order: passes as a multiset.
    let r2 = run_simplify(&two, &SimplifyOptions::relative(0.05)).expect("simplifies");
    assert!(simplify(&two, &r2.mesh, &check).expect("valid").passed());
    let swapped = union(&t.mesh, &s.mesh, 5.0);
    let v = simplify(&two, &swapped, &SimplifyCheck::absolute(r2.eps)).expect("valid");
    assert!(
        !kinds(&v).iter().any(|&k| matches!(
            k,
            FailureKind::SurfaceChanged | FailureKind::ComponentLost | FailureKind::ComponentSplit
        )),
        "{v:?}"
    );
    // By id, two input components joined by one output component (a tetrahedron on
    // two vertices of each).
    let n = sphere.vertex_count as u32;
    let (p, q) = (sphere.faces[0], torus.faces[0]);
    let tet = vec![
        [p[0], p[1], n + q[0]],
        [p[0], n + q[1], p[1]],
        [p[1], n + q[1], n + q[0]],
        [n + q[0], n + q[1], p[0]],
    ];
    let joined = TriMesh {
        faces: tet,
        ..two.clone()
    };
    let v = simplify(&two, &joined, &check).expect("valid");
    assert!(kinds(&v).contains(&FailureKind::ComponentsMerged), "{v:?}");
    assert_eq!(count(&v, FailureKind::ComponentLost), 2, "{v:?}");
}

#[test]
fn a_face_list_that_is_no_surface_fails_as_for_reduce() {
    let sphere = iso(Implicit::Sphere { radius: 1.0 }, 10);
    let mut rep = sphere.clone();
    rep.faces.push(rep.faces[0]);
    let v = simplify(&sphere, &rep, &SimplifyCheck::relative(0.05)).expect("valid");
    assert_eq!(v.failures[0].kind, FailureKind::RepeatedFace, "{v:?}");
    assert_eq!(v.failures[0].face, Some(sphere.faces.len()));
    // Surface defects stop the later stages: no short edge is judged.
    assert!(!kinds(&v).contains(&FailureKind::ShortContractibleEdge));
}

#[test]
fn inputs_simplify_refuses_are_errors() {
    let sphere = iso(Implicit::Sphere { radius: 1.0 }, 8);
    let check = SimplifyCheck::relative(0.05);
    let bare = TriMesh::combinatorial(sphere.vertex_count, sphere.faces.clone());
    assert!(matches!(
        simplify(&bare, &sphere, &check),
        Err(Error::MissingPositions { task: "simplify" })
    ));
    let mut nan = sphere.clone();
    nan.positions.as_mut().expect("positions")[2][0] = f64::INFINITY;
    assert!(matches!(
        simplify(&nan, &sphere, &check),
        Err(Error::NonFiniteCoordinate { vertex: 2, .. })
    ));
    let mut few = sphere.clone();
    few.positions.as_mut().expect("positions").pop();
    assert!(matches!(
        simplify(&few, &sphere, &check),
        Err(Error::PositionCount { .. })
    ));
    let point = TriMesh::with_positions(vec![[1.0; 3]; 4], gen::tetrahedron().faces);
    assert!(matches!(
        simplify(&point, &point, &check),
        Err(Error::NoCoordinates { .. })
    ));
    for bad in [
        SimplifyCheck::absolute(0.0),
        SimplifyCheck::absolute(f64::NAN),
        SimplifyCheck::relative(-1.0),
        SimplifyCheck::relative(f64::INFINITY),
        SimplifyCheck::relative(f64::MAX),
    ] {
        let e = simplify(&sphere, &sphere, &bad).expect_err("refused");
        assert_eq!(e.kind(), "bad_option", "{bad:?}");
        let lib = run_simplify(
            &sphere,
            &SimplifyOptions {
                eps: bad.eps,
                ..SimplifyOptions::default()
            },
        )
        .expect_err("refused");
        assert_eq!(lib.kind(), "bad_option", "{bad:?}");
        // Refused for the option itself, before the input is read, as the library does.
        assert_eq!(e.to_string(), lib.to_string(), "{bad:?}");
        // (A finite fraction whose ε overflows is known bad only with the diagonal.)
        if !matches!(bad.eps, Eps::Relative(r) if r == f64::MAX) {
            let e = simplify(&bare, &sphere, &bad).expect_err("refused");
            assert_eq!(
                e.kind(),
                "bad_option",
                "{bad:?} on an input without positions"
            );
        }
    }
    let mut pinched = sphere.clone();
    pinched.faces.push(pinched.faces[0]);
    let e = simplify(&pinched, &sphere, &check).expect_err("refused");
    let lib = run_simplify(&pinched, &SimplifyOptions::relative(0.05)).expect_err("refused");
    assert_eq!(e.to_string(), lib.to_string());
}

/// A flat disc (boundary loop L B R T, interior I and J) whose one short edge `[B, I]`
/// joins the boundary vertex B to the interior vertex I; moving I to B keeps every
/// triangle, moving B to I (or to the midpoint) turns the triangle B R J over. `b_first`:
/// B has the smaller id of the two.
fn disc_with_a_short_edge_to_the_boundary(b_first: bool) -> (TriMesh, [u32; 2]) {
    let (l, r, t, j) = (0u32, 2, 3, 5);
    let (b, i) = if b_first { (1u32, 4u32) } else { (4, 1) };
    let mut positions = vec![[0.0; 3]; 6];
    positions[l as usize] = [-1.0, 0.0, 0.0];
    positions[b as usize] = [0.0, 0.0, 0.0];
    positions[r as usize] = [1.0, 0.0, 0.0];
    positions[t as usize] = [0.0, 1.0, 0.0];
    positions[i as usize] = [-0.05, 0.05, 0.0];
    positions[j as usize] = [0.3, 0.01, 0.0];
    let faces = vec![
        [l, b, i],
        [b, j, i],
        [b, r, j],
        [r, t, j],
        [j, t, i],
        [i, t, l],
    ];
    (
        TriMesh::with_positions(positions, faces),
        [b.min(i), b.max(i)],
    )
}

/// `mesh` turned by `angle` about the axis (1, 2, 3): no coordinate of a normal or an
/// edge vector stays zero, so every component of the guard's cross products counts.
fn turned(mesh: &TriMesh, angle: f64) -> TriMesh {
    let n = 14f64.sqrt();
    let (x, y, z) = (1.0 / n, 2.0 / n, 3.0 / n);
    let (c, s) = (angle.cos(), angle.sin());
    let t = 1.0 - c;
    let r = [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ];
    let mut m = mesh.clone();
    for p in m.positions.as_mut().expect("positions") {
        *p = r.map(|row| row[0] * p[0] + row[1] * p[1] + row[2] * p[2]);
    }
    m
}

#[test]
fn an_edge_with_one_end_on_the_boundary_is_guarded_at_that_end() {
    for (b_first, angle) in [(true, 0.0), (false, 0.0), (true, 1.0), (false, 2.5)] {
        let (disc, edge) = disc_with_a_short_edge_to_the_boundary(b_first);
        let disc = turned(&disc, angle);
        let v = simplify(&disc, &disc, &SimplifyCheck::absolute(0.1)).expect("valid");
        assert_eq!(kinds(&v), [FailureKind::ShortContractibleEdge], "{b_first}");
        assert_eq!(flagged(&v), [edge]);
        // The library contracts it, and only it.
        let o = options(Mode::Naive, Position::Midpoint, false, Eps::Absolute(0.1));
        let r = run_simplify(&disc, &o).expect("simplifies");
        assert_eq!(r.stats.edges_contracted, 1);
        assert!(simplify(&disc, &r.mesh, &SimplifyCheck::absolute(0.1))
            .expect("valid")
            .passed());
    }
}

/// The checker's guard (its own arithmetic) decides every moved triangle as the
/// library's guard does (`simplify::geometry::fan_move_ok`), on random triangles in every
/// orientation and on the margins: `to` near the line of the opposite edge at a
/// thousandth, half, twice and a thousand times the zero-area bound (the distance from
/// the line over the edge's length is the ratio of the area to the bound here), on either
/// side, so across the line too (a fold by a hair).
#[test]
fn the_guard_decides_each_moved_triangle_as_the_librarys() {
    use super::simplify_check::{faces_at, guard_allows};
    use crate::simplify::geometry::{cross, dot, fan_move_ok, sub};
    let mut rng = crate::rng::Rng::new(20261207);
    let mut unit = || uniform(&mut rng) - 0.5;
    // One face [0, 1, 2]; the edge [0, 3] moves vertex 0 (vertex 3 has no face).
    let faces = [[0u32, 1, 2]];
    let at = faces_at(4, &faces);
    let (mut allowed, mut refused) = (0, 0);
    for _ in 0..4000 {
        let x = [unit(), unit(), unit()];
        let p1 = [unit(), unit(), unit()];
        let p2 = [unit(), unit(), unit()];
        let e = sub(p2, p1);
        let n = cross(sub(p1, x), e);
        let along = 0.5 + unit();
        // The unit vector in the face's plane, across the edge [p1, p2] towards x.
        let towards = cross(e, n);
        let len = dot(towards, towards).sqrt();
        if len == 0.0 {
            continue;
        }
        let scale = dot(e, e).sqrt();
        let side = if dot(towards, sub(x, p1)) > 0.0 {
            1.0
        } else {
            -1.0
        };
        for offset in [
            0.0, 1e-13, 5e-11, 2e-10, 1e-7, -1e-13, -5e-11, -2e-10, -1e-7, 0.3, -0.3,
        ] {
            let h = side * offset * scale / len;
            let to: [f64; 3] = std::array::from_fn(|k| {
                p1[k] + along * e[k] + h * towards[k] + 0.01 * offset.signum() * n[k]
            });
            let pos = |v: u32| [x, p1, p2, [9.0; 3]][v as usize];
            let ours = guard_allows(&faces, &at, &pos, (0, 3), to);
            let library = fan_move_ok(x, to, p1, p2);
            assert_eq!(ours, library, "x {x:?} p1 {p1:?} p2 {p2:?} to {to:?}");
            if ours {
                allowed += 1;
            } else {
                refused += 1;
            }
        }
    }
    assert!(
        allowed > 10000 && refused > 10000,
        "{allowed} allowed, {refused} refused"
    );
}

/// `mesh` with every position multiplied by `s`.
fn scaled(mesh: &TriMesh, s: f64) -> TriMesh {
    let mut m = mesh.clone();
    for p in m.positions.as_mut().expect("positions") {
        *p = p.map(|x| x * s);
    }
    m
}

/// A verdict without its sentences (which print lengths): what, where, how many.
type Located = (
    Vec<(FailureKind, Option<usize>, Option<[u32; 2]>, Option<u32>)>,
    Vec<(FailureKind, usize)>,
);

fn located(v: &Verdict) -> Located {
    let failures = v
        .failures
        .iter()
        .map(|f| (f.kind, f.face, f.edge, f.vertex))
        .collect();
    (failures, v.counts.clone())
}

/// Scaling the input and the output by a power of two changes no verdict, even where the
/// squared lengths and the areas of the scaled meshes leave the `f64` range (2^±560: the
/// checker works on coordinates brought near 1 by a power of two, exactly).
#[test]
fn verdicts_are_the_same_at_every_power_of_two_scale() {
    let mut failing = 0;
    for (name, mesh) in geometric() {
        for allow_foldover in [false, true] {
            let run = |rel| {
                run_simplify(
                    &mesh,
                    &options(
                        Mode::Naive,
                        Position::Midpoint,
                        allow_foldover,
                        Eps::Relative(rel),
                    ),
                )
                .expect("simplifies")
            };
            // The library's output, one that stops early, and the input itself.
            let outputs = [run(0.05).mesh, run(0.02).mesh, mesh.clone()];
            let check = SimplifyCheck {
                allow_foldover,
                ..SimplifyCheck::relative(0.05)
            };
            for (k, out) in outputs.iter().enumerate() {
                let label = format!("{name} {allow_foldover} output {k}");
                let at_one = simplify(&mesh, out, &check).expect("valid");
                failing += usize::from(!at_one.passed());
                for e in [560, -560, 3] {
                    let s = 2f64.powi(e);
                    let v = simplify(&scaled(&mesh, s), &scaled(out, s), &check)
                        .unwrap_or_else(|err| panic!("{label} at 2^{e}: {err}"));
                    assert_eq!(located(&v), located(&at_one), "{label} at 2^{e}");
                }
            }
        }
    }
    assert!(failing >= 12, "{failing} failing verdicts compared");
}

/// A face list on one used vertex (a degenerate face) is refused as the library refuses
/// it, not as "every vertex at one point" (which needs two vertices to say anything).
#[test]
fn a_single_used_vertex_is_refused_as_the_library_refuses_it() {
    let one = TriMesh::with_positions(vec![[1.0, 2.0, 3.0]; 2], vec![[0, 0, 0]]);
    let e = simplify(&one, &one, &SimplifyCheck::relative(0.05)).expect_err("refused");
    let lib = run_simplify(&one, &SimplifyOptions::relative(0.05)).expect_err("refused");
    assert_eq!((e.kind(), e.to_string()), (lib.kind(), lib.to_string()));
    assert_ne!(e.kind(), "no_coordinates");
}

/// A grid in a coordinate plane far from the origin (every coordinate near 10), one
/// interior vertex moved towards a neighbour so that their edge is the only one shorter
/// than ε: the guard allows it at its true midpoint, so an output that kept it stopped
/// early. A guard tried at another point (a coordinate of the midpoint computed wrongly
/// lands about 10 away, outside the edge's fan in the planes that contain that axis)
/// would refuse it and pass the output. The coordinates are multiples of 1/8, so the
/// verdict is also the same, exactly, on the grid scaled into the subnormal range.
#[test]
fn a_short_edge_the_guard_allows_at_its_midpoint_is_flagged() {
    let n = 5u32;
    let id = |i: u32, j: u32| i * n + j;
    let mut faces = Vec::new();
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    let (a, b) = (id(2, 2), id(3, 2));
    // The grid's two directions along axes `u` and `w`, the third coordinate 10.
    for (u, w) in [(0, 1), (1, 2), (2, 0)] {
        let mut positions: Vec<[f64; 3]> = (0..n * n)
            .map(|v| {
                let mut p = [10.0; 3];
                p[u] += f64::from(v / n);
                p[w] += f64::from(v % n);
                p
            })
            .collect();
        // b moves to a quarter of the way from a: |ab| = 0.25, every other edge at
        // least 0.75.
        let (pa, pb) = (positions[a as usize], positions[b as usize]);
        positions[b as usize] = [0, 1, 2].map(|k| pa[k] + 0.25 * (pb[k] - pa[k]));
        let grid = TriMesh::with_positions(positions, faces.clone());
        let check = |s: f64| SimplifyCheck {
            eps: Eps::Absolute(0.5 * s),
            position: Position::Midpoint,
            allow_foldover: false,
        };
        let label = format!("plane of axes {u} and {w}");
        let v = simplify(&grid, &grid, &check(1.0)).expect("valid");
        let edges: Vec<_> = v.failures.iter().map(|f| (f.kind, f.edge)).collect();
        assert_eq!(
            edges,
            [(FailureKind::ShortContractibleEdge, Some([a, b]))],
            "{label}: {:?}",
            v.failures
        );
        for e in [-1068, 600] {
            // 2^e from its bits (`powi` would go through 2^1068, which overflows).
            let s = if e < -1022 {
                f64::from_bits(1 << (e + 1074))
            } else {
                f64::from_bits(((e + 1023) as u64) << 52)
            };
            let tiny = scaled(&grid, s);
            let at_scale = simplify(&tiny, &tiny, &check(s)).expect("valid");
            assert_eq!(located(&at_scale), located(&v), "{label} at 2^{e}");
        }
        // The library contracts exactly that edge, and its output passes.
        let midpoints = options(Mode::Naive, Position::Midpoint, false, Eps::Absolute(0.5));
        let r = run_simplify(&grid, &midpoints).expect("runs");
        assert_eq!(r.stats.edges_contracted, 1, "{label}");
        assert!(simplify(&grid, &r.mesh, &check(1.0))
            .expect("valid")
            .passed());
    }
}
