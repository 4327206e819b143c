//! The surface builder against a naive reference that shares nothing with it: edges
//! counted in a `BTreeMap`, fans found by a union-find over each vertex's faces,
//! components by a breadth-first search over shared edges. On random surfaces and on
//! corruptions of them (faces removed, repeated, made degenerate or out of range,
//! vertices identified, surfaces glued at a vertex, high-degree pinches), the builder
//! must report exactly the reference's error — kind, location and counts, in the
//! documented precedence — and on success give a corner table the reference confirms.

use contractible::gen::random::{random, RandomParams, SurfaceKind};
use contractible::rng::Rng;
use contractible::{BuildError, Corner, FaceId, Surfaces, Triangulation, VertexId};
use std::collections::{BTreeMap, BTreeSet, VecDeque};

/// What the reference accepts: the used vertices and the number of components.
struct Accepted {
    used: Vec<bool>,
    components: usize,
}

fn find(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// The documented validation of a face list as a possibly disconnected closed surface,
/// written the slow and obvious way.
fn reference(vertex_count: usize, faces: &[[u32; 3]]) -> Result<Accepted, BuildError> {
    if faces.is_empty() {
        return Err(BuildError::Empty);
    }
    // 1. The first face with an index out of range or a repeated vertex.
    for (i, f) in faces.iter().enumerate() {
        if let Some(&vertex) = f.iter().find(|&&v| v as usize >= vertex_count) {
            return Err(BuildError::VertexOutOfRange {
                face: i,
                vertex,
                vertex_count,
            });
        }
        if f[0] == f[1] || f[1] == f[2] || f[0] == f[2] {
            return Err(BuildError::DegenerateFace {
                face: i,
                vertices: *f,
            });
        }
    }
    // Every pair of endpoints with its faces, in increasing endpoint order.
    let mut edges: BTreeMap<(u32, u32), Vec<usize>> = BTreeMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[(k + 1) % 3], f[(k + 2) % 3]);
            edges.entry((a.min(b), a.max(b))).or_default().push(i);
        }
    }
    let third = |f: usize, a: u32, b: u32| {
        faces[f]
            .into_iter()
            .find(|&z| z != a && z != b)
            .expect("a face on an edge has a third vertex")
    };
    // 2. The first edge (in endpoint order) with two faces sharing their third vertex.
    for (&(a, b), on) in &edges {
        for p in 0..on.len() {
            for q in p + 1..on.len() {
                if third(on[p], a, b) == third(on[q], a, b) {
                    return Err(BuildError::DuplicateFace {
                        face: on[q],
                        first: on[p],
                        vertices: faces[on[q]],
                    });
                }
            }
        }
    }
    // 3. The first edge in three or more faces; 4. the first in one face.
    for (&(a, b), on) in &edges {
        let n = on.len();
        if n >= 3 {
            let face = on[0];
            return Err(if n % 2 == 1 {
                BuildError::NonManifoldEdge {
                    a,
                    b,
                    faces: n,
                    face,
                }
            } else {
                BuildError::MultipleEdges {
                    a,
                    b,
                    edges: n / 2,
                    faces: n,
                    face,
                }
            });
        }
    }
    if let Some((&(a, b), on)) = edges.iter().find(|(_, on)| on.len() == 1) {
        return Err(BuildError::BoundaryEdge { a, b, face: on[0] });
    }
    // 5. The first vertex whose faces do not form one fan, or fewer than three.
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); vertex_count];
    for (i, f) in faces.iter().enumerate() {
        for &v in f {
            at[v as usize].push(i);
        }
    }
    for (v, around) in at.iter().enumerate() {
        if around.is_empty() {
            continue;
        }
        let v = v as u32;
        let mut parent: Vec<usize> = (0..around.len()).collect();
        for p in 0..around.len() {
            for q in p + 1..around.len() {
                let shared = faces[around[p]]
                    .iter()
                    .filter(|&&z| z != v && faces[around[q]].contains(&z))
                    .count();
                if shared > 0 {
                    let (x, y) = (find(&mut parent, p), find(&mut parent, q));
                    parent[x] = y;
                }
            }
        }
        let cycles = (0..around.len())
            .filter(|&p| find(&mut parent, p) == p)
            .count();
        if cycles != 1 {
            return Err(BuildError::VertexLinkNotCycle {
                vertex: v,
                cycles,
                faces: around.len(),
            });
        }
        if around.len() < 3 {
            return Err(BuildError::VertexDegreeTooLow {
                vertex: v,
                degree: around.len(),
            });
        }
    }
    // Components: faces joined across their edges.
    let mut label = vec![usize::MAX; faces.len()];
    let mut components = 0;
    for start in 0..faces.len() {
        if label[start] != usize::MAX {
            continue;
        }
        let mut queue = VecDeque::from([start]);
        label[start] = components;
        while let Some(f) = queue.pop_front() {
            for k in 0..3 {
                let (a, b) = (faces[f][(k + 1) % 3], faces[f][(k + 2) % 3]);
                for &g in &edges[&(a.min(b), a.max(b))] {
                    if label[g] == usize::MAX {
                        label[g] = components;
                        queue.push_back(g);
                    }
                }
            }
        }
        components += 1;
    }
    Ok(Accepted {
        used: at.iter().map(|a| !a.is_empty()).collect(),
        components,
    })
}

/// The strict builder's verdict from the reference's.
fn reference_strict(vertex_count: usize, faces: &[[u32; 3]]) -> Result<(), BuildError> {
    let ok = reference(vertex_count, faces)?;
    if let Some(v) = ok.used.iter().position(|&u| !u) {
        return Err(BuildError::UnusedVertex { vertex: v as u32 });
    }
    if ok.components != 1 {
        return Err(BuildError::Disconnected {
            components: ok.components,
        });
    }
    Ok(())
}

/// The corner table `t` is the surface of `faces`, as the reference sees it: the same
/// faces at the same ids, each corner glued to the other face of its opposite edge,
/// per-vertex degrees, and the smallest corner at each vertex as its corner.
fn assert_table(t: &Triangulation, faces: &[[u32; 3]], origin: &[u32], vertex_origin: &[u32]) {
    assert_eq!(t.face_count(), origin.len());
    let mut degree: BTreeMap<u32, usize> = BTreeMap::new();
    let mut first: BTreeMap<u32, u32> = BTreeMap::new();
    for (local, &f) in origin.iter().enumerate() {
        let fv = t.face_vertices(FaceId(local as u32));
        let mesh = fv.map(|v| vertex_origin[v.0 as usize]);
        assert_eq!(mesh, faces[f as usize], "face {f}");
        for k in 0..3 {
            let c = Corner(3 * local as u32 + k as u32);
            *degree.entry(fv[k].0).or_default() += 1;
            first.entry(fv[k].0).or_insert(c.0);
            let o = t.opposite(c);
            assert_ne!(o.0 / 3, c.0 / 3, "corner {c:?} glued into its own face");
            let mine: BTreeSet<u32> = [fv[(k + 1) % 3].0, fv[(k + 2) % 3].0].into();
            let g = t.face_vertices(FaceId(o.0 / 3));
            let s = (o.0 % 3) as usize;
            let theirs: BTreeSet<u32> = [g[(s + 1) % 3].0, g[(s + 2) % 3].0].into();
            assert_eq!(mine, theirs, "corner {c:?} glued across another edge");
            assert_eq!(t.opposite(o), c, "opposite is not an involution at {c:?}");
        }
    }
    for (&v, &d) in &degree {
        assert_eq!(t.degree(VertexId(v)), d, "degree of {v}");
        assert_eq!(t.corner_of(VertexId(v)).0, first[&v], "corner of {v}");
    }
    t.validate().expect("a built triangulation validates");
}

/// Checks both builders on one face list against the reference.
fn check(vertex_count: usize, faces: &[[u32; 3]]) -> bool {
    let want = reference(vertex_count, faces);
    let got = Surfaces::from_faces(vertex_count, faces);
    match (&want, &got) {
        (Ok(ok), Ok(s)) => {
            assert_eq!(s.components.len(), ok.components, "{faces:?}");
            let dropped: Vec<u32> = (0..vertex_count as u32)
                .filter(|&v| !ok.used[v as usize])
                .collect();
            assert_eq!(s.dropped_vertices, dropped);
            let mut seen_faces: Vec<u32> = Vec::new();
            for c in &s.components {
                assert_table(&c.tri, faces, &c.face_origin, &c.vertex_origin);
                seen_faces.extend(&c.face_origin);
            }
            // Components come in the order of their smallest face and cover every face.
            let smallest: Vec<u32> = s.components.iter().map(|c| c.face_origin[0]).collect();
            assert!(smallest.windows(2).all(|w| w[0] < w[1]));
            seen_faces.sort_unstable();
            assert_eq!(seen_faces, (0..faces.len() as u32).collect::<Vec<_>>());
        }
        (Err(e), Err(f)) => assert_eq!(e, f, "{faces:?}"),
        _ => panic!(
            "reference {:?}, builder {:?} on {faces:?}",
            want.as_ref().map(|a| a.components),
            got.as_ref().map(|s| s.components.len())
        ),
    }
    let strict = Triangulation::from_faces(vertex_count, faces);
    match (reference_strict(vertex_count, faces), strict) {
        (Ok(()), Ok(t)) => {
            let ids: Vec<u32> = (0..vertex_count as u32).collect();
            let all: Vec<u32> = (0..faces.len() as u32).collect();
            assert_table(&t, faces, &all, &ids);
        }
        (Err(e), Err(f)) => assert_eq!(e, f, "{faces:?}"),
        (w, g) => panic!("reference {w:?}, strict builder {:?}", g.map(|_| ())),
    }
    want.is_ok()
}

/// A random closed surface's faces, its vertices relabelled at random.
fn surface(rng: &mut Rng, min_faces: usize) -> (usize, Vec<[u32; 3]>) {
    let kinds = [
        SurfaceKind::Orientable(0),
        SurfaceKind::Orientable(1),
        SurfaceKind::Orientable(2),
        SurfaceKind::NonOrientable(1),
        SurfaceKind::NonOrientable(3),
    ];
    let t = random(&RandomParams {
        surface: kinds[rng.index(kinds.len())],
        min_faces,
        flip_percent: 30,
        seed: rng.next_u64(),
    })
    .expect("small surface");
    let n = t.vertex_count();
    let mut perm: Vec<u32> = (0..n as u32).collect();
    rng.shuffle(&mut perm);
    let mut faces: Vec<[u32; 3]> = t
        .face_list()
        .into_iter()
        .map(|f| f.map(|v| perm[v as usize]))
        .collect();
    rng.shuffle(&mut faces);
    (n, faces)
}

/// One random corruption of a face list (or none).
fn corrupt(rng: &mut Rng, n: &mut usize, faces: &mut Vec<[u32; 3]>) {
    let f = rng.index(faces.len());
    match rng.below(9) {
        0 => {}
        1 => {
            faces.remove(f);
        }
        2 => {
            let mut g = faces[f];
            g.swap(0, 1);
            faces.insert(rng.index(faces.len() + 1), g);
        }
        3 => faces[f][rng.index(3)] = faces[f][(rng.index(2) + 1) % 3],
        4 => faces[f][rng.index(3)] = *n as u32 + rng.below(3) as u32,
        5 => {
            // Identify two vertices (pinches, non-manifold or multiple edges, ...).
            let (a, b) = (rng.below(*n as u64) as u32, rng.below(*n as u64) as u32);
            for g in faces.iter_mut() {
                for v in g.iter_mut() {
                    if *v == b {
                        *v = a;
                    }
                }
            }
        }
        6 => {
            // A second surface glued at one vertex: a pinch with two fans.
            let size = 4 + rng.index(20);
            let (m, other) = surface(rng, size);
            let shared = rng.below(*n as u64) as u32;
            let at = rng.below(m as u64) as u32;
            let base = *n as u32;
            faces.extend(other.into_iter().map(|g| {
                g.map(|v| match v {
                    v if v == at => shared,
                    v if v < at => base + v,
                    v => base + v - 1,
                })
            }));
            *n += m - 1;
        }
        7 => {
            // A disjoint second surface, and maybe a vertex no face uses.
            let size = 4 + rng.index(20);
            let (m, other) = surface(rng, size);
            let base = *n as u32;
            faces.extend(other.into_iter().map(|g| g.map(|v| base + v)));
            *n += m + rng.index(2);
        }
        _ => {
            let (a, b) = (rng.index(faces.len()), rng.index(faces.len()));
            faces.swap(a, b);
        }
    }
}

#[test]
fn the_builder_reports_what_the_reference_finds() {
    let mut rng = Rng::new(0xb01d);
    let mut accepted = 0;
    let mut rejected = 0;
    for round in 0..600 {
        let size = 4 + rng.index(60);
        let (mut n, mut faces) = surface(&mut rng, size);
        for _ in 0..round % 3 {
            corrupt(&mut rng, &mut n, &mut faces);
        }
        if faces.is_empty() {
            continue;
        }
        if check(n, &faces) {
            accepted += 1;
        } else {
            rejected += 1;
        }
    }
    assert!(
        accepted > 150 && rejected > 150,
        "weak test: {accepted} accepted, {rejected} rejected"
    );
}

/// A double cone over an `n`-gon: apexes `n` and `n + 1`, each of degree `n`.
fn bipyramid(n: u32) -> Vec<[u32; 3]> {
    (0..n)
        .flat_map(|i| [[i, (i + 1) % n, n], [(i + 1) % n, i, n + 1]])
        .collect()
}

#[test]
fn high_degree_vertices_and_pinches_of_every_size() {
    // Degrees on both sides of the builder's small-link limit, alone and pinched
    // together at an apex (two fans of `n` and `m` faces).
    for n in [3u32, 4, 15, 16, 17, 31, 32, 33, 40, 100] {
        let faces = bipyramid(n);
        assert!(check(n as usize + 2, &faces), "bipyramid {n}");
        for m in [3u32, 16, 17, 40] {
            let mut pinched = faces.clone();
            let base = n + 2;
            pinched.extend(bipyramid(m).into_iter().map(|f| {
                f.map(|v| match v {
                    v if v == m => n, // glued to the first apex
                    v if v < m => base + v,
                    _ => base + m,
                })
            }));
            assert!(!check((base + m + 1) as usize, &pinched), "pinch {n}/{m}");
            assert_eq!(
                Surfaces::from_faces((base + m + 1) as usize, &pinched).unwrap_err(),
                BuildError::VertexLinkNotCycle {
                    vertex: n,
                    cycles: 2,
                    faces: (n + m) as usize,
                }
            );
        }
    }
}

#[test]
fn an_edge_in_any_number_of_faces_is_classified_by_its_parity() {
    // A book of `k` triangles on the spine [0, 1]: the spine is in `k` faces (every
    // other edge in one), so the error is the spine's, non-manifold for odd `k` and
    // `k / 2` edges with the same endpoints for even `k`.
    for k in 3u32..=9 {
        let faces: Vec<[u32; 3]> = (0..k).map(|i| [0, 1, 2 + i]).collect();
        assert!(!check(k as usize + 2, &faces), "book of {k}");
        let want = if k % 2 == 1 {
            BuildError::NonManifoldEdge {
                a: 0,
                b: 1,
                faces: k as usize,
                face: 0,
            }
        } else {
            BuildError::MultipleEdges {
                a: 0,
                b: 1,
                edges: k as usize / 2,
                faces: k as usize,
                face: 0,
            }
        };
        assert_eq!(
            Triangulation::from_faces(k as usize + 2, &faces).unwrap_err(),
            want
        );
    }
}

/// Bipyramids over `sizes[i]`-gons, disjoint but for one shared vertex (0), an apex of
/// each: a vertex with one fan of `sizes[i]` faces per bipyramid, in this order.
fn bouquet(sizes: &[u32]) -> (usize, Vec<[u32; 3]>) {
    let mut faces = Vec::new();
    let mut next = 1u32;
    for &n in sizes {
        let base = next;
        faces.extend(bipyramid(n).into_iter().map(|f| {
            f.map(|v| match v {
                v if v == n => 0,
                v if v < n => base + v,
                _ => base + n,
            })
        }));
        next = base + n + 1;
    }
    (next as usize, faces)
}

#[test]
fn a_vertex_with_several_fans_reports_them_all() {
    // Fan sizes whose running sums and products cross the total (6 · 7 = 6 + 7 + 29):
    // counting must not stop before the last fan, on both sides of the small-link limit.
    for sizes in [
        &[3u32, 3, 3][..],
        &[6, 7, 29],
        &[3, 4, 5, 6],
        &[20, 3, 3],
        &[40, 3, 3, 3],
    ] {
        let (n, faces) = bouquet(sizes);
        assert!(!check(n, &faces), "{sizes:?}");
        assert_eq!(
            Surfaces::from_faces(n, &faces).unwrap_err(),
            BuildError::VertexLinkNotCycle {
                vertex: 0,
                cycles: sizes.len(),
                faces: sizes.iter().sum::<u32>() as usize,
            },
            "{sizes:?}"
        );
    }
}
