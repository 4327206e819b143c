//! Surfaces with boundary (`Surfaces::from_mesh_with_boundary`): every result is checked
//! by code written here from the face lists alone (edge counts, boundary loop walks,
//! fans around vertices, χ, orientability by propagation, contraction by relabelling),
//! never by the library's own traversals.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use contractible::gen::{self, RandomParams, SurfaceKind};
use contractible::{BuildError, ConedComponent, FaceId, Surfaces, TriMesh, VertexId};

use crate::common;

// ---------------------------------------------------------------------------------
// Independent oracle on face lists.

type Edge = (u32, u32);

fn key(a: u32, b: u32) -> Edge {
    (a.min(b), a.max(b))
}

/// Faces per undirected edge.
fn edge_faces(faces: &[[u32; 3]]) -> BTreeMap<Edge, Vec<usize>> {
    let mut m: BTreeMap<Edge, Vec<usize>> = BTreeMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            m.entry(key(f[k], f[(k + 1) % 3])).or_default().push(i);
        }
    }
    m
}

/// Boundary loops (edges in exactly one face) walked through the boundary-edge graph,
/// each written from its smallest vertex towards the smaller neighbour; sorted. Panics
/// if a vertex is on other than two boundary edges.
fn walk_loops(faces: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut adj: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (&(a, b), fs) in &edge_faces(faces) {
        if fs.len() == 1 {
            adj.entry(a).or_default().push(b);
            adj.entry(b).or_default().push(a);
        }
    }
    let mut seen = BTreeSet::new();
    let mut loops = Vec::new();
    for (&start, ns) in &adj {
        assert_eq!(ns.len(), 2, "vertex {start} on {} boundary edges", ns.len());
        if seen.contains(&start) {
            continue;
        }
        let mut cycle = vec![start];
        seen.insert(start);
        let mut prev = start;
        let mut cur = ns[0].min(ns[1]);
        while cur != start {
            cycle.push(cur);
            seen.insert(cur);
            let n = &adj[&cur];
            let next = if n[0] == prev { n[1] } else { n[0] };
            prev = cur;
            cur = next;
        }
        loops.push(cycle);
    }
    loops.sort();
    loops
}

/// V − E + F over the vertices the faces use.
fn chi(faces: &[[u32; 3]]) -> i64 {
    let vs: BTreeSet<u32> = faces.iter().flatten().copied().collect();
    vs.len() as i64 - edge_faces(faces).len() as i64 + faces.len() as i64
}

/// Orientability by propagating face orientations over interior edges: a face is
/// flipped or not so that every interior edge is traversed in opposite directions.
fn orientable(faces: &[[u32; 3]]) -> bool {
    let ef = edge_faces(faces);
    let dir = |f: &[u32; 3], a: u32, b: u32| (0..3).any(|k| f[k] == a && f[(k + 1) % 3] == b);
    let mut flip: Vec<Option<bool>> = vec![None; faces.len()];
    for s in 0..faces.len() {
        if flip[s].is_some() {
            continue;
        }
        flip[s] = Some(false);
        let mut stack = vec![s];
        while let Some(f) = stack.pop() {
            let ff = flip[f].unwrap();
            for k in 0..3 {
                let (a, b) = (faces[f][k], faces[f][(k + 1) % 3]);
                for &g in &ef[&key(a, b)] {
                    if g == f {
                        continue;
                    }
                    // Same direction in both faces: g must be flipped relative to f.
                    let want = ff ^ dir(&faces[g], a, b);
                    match flip[g] {
                        None => {
                            flip[g] = Some(want);
                            stack.push(g);
                        }
                        Some(x) if x != want => return false,
                        _ => {}
                    }
                }
            }
        }
    }
    true
}

/// Whether the faces form a compact surface, possibly with boundary: no repeated vertex
/// in a face, no two faces on one vertex set, every edge in one or two faces, and the
/// faces around each vertex connected through the edges at that vertex (one fan).
fn is_surface_with_boundary(faces: &[[u32; 3]]) -> bool {
    if faces
        .iter()
        .any(|f| f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
    {
        return false;
    }
    let sets: BTreeSet<[u32; 3]> = faces
        .iter()
        .map(|f| {
            let mut s = *f;
            s.sort_unstable();
            s
        })
        .collect();
    if sets.len() != faces.len() {
        return false;
    }
    if edge_faces(faces).values().any(|fs| fs.len() > 2) {
        return false;
    }
    let mut around: HashMap<u32, Vec<usize>> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for &v in f {
            around.entry(v).or_default().push(i);
        }
    }
    around.iter().all(|(&v, fs)| fan_count(faces, v, fs) == 1)
}

/// Number of groups of `fs` (faces at `v`) connected by sharing an edge at `v`.
fn fan_count(faces: &[[u32; 3]], v: u32, fs: &[usize]) -> usize {
    let others = |f: usize| -> Vec<u32> { faces[f].iter().copied().filter(|&x| x != v).collect() };
    let mut group: Vec<usize> = (0..fs.len()).collect();
    fn find(g: &mut [usize], i: usize) -> usize {
        let mut i = i;
        while g[i] != i {
            g[i] = g[g[i]];
            i = g[i];
        }
        i
    }
    for i in 0..fs.len() {
        for j in i + 1..fs.len() {
            if others(fs[i]).iter().any(|x| others(fs[j]).contains(x)) {
                let (a, b) = (find(&mut group, i), find(&mut group, j));
                group[a] = b;
            }
        }
    }
    (0..fs.len()).filter(|&i| find(&mut group, i) == i).count()
}

/// Connected components of a face list (faces sharing an edge), each as face indices
/// in increasing order, ordered by their first face.
fn components(faces: &[[u32; 3]]) -> Vec<Vec<usize>> {
    let ef = edge_faces(faces);
    let mut label = vec![usize::MAX; faces.len()];
    let mut out = Vec::new();
    for s in 0..faces.len() {
        if label[s] != usize::MAX {
            continue;
        }
        let k = out.len();
        label[s] = k;
        let mut stack = vec![s];
        let mut comp = vec![];
        while let Some(f) = stack.pop() {
            comp.push(f);
            for e in 0..3 {
                for &g in &ef[&key(faces[f][e], faces[f][(e + 1) % 3])] {
                    if label[g] == usize::MAX {
                        label[g] = k;
                        stack.push(g);
                    }
                }
            }
        }
        comp.sort_unstable();
        out.push(comp);
    }
    out
}

/// The library's loops of `c`, over mesh vertex ids, canonical and sorted.
fn library_loops(c: &ConedComponent) -> Vec<Vec<u32>> {
    let mut loops: Vec<Vec<u32>> = c
        .boundary_loops()
        .into_iter()
        .map(|l| {
            let mesh: Vec<u32> = l
                .iter()
                .map(|&v| c.vertex_origin_of(v).expect("real loop vertex"))
                .collect();
            canonical(mesh)
        })
        .collect();
    loops.sort();
    loops
}

fn canonical(mut cycle: Vec<u32>) -> Vec<u32> {
    let k = (0..cycle.len()).min_by_key(|&i| cycle[i]).unwrap();
    cycle.rotate_left(k);
    if cycle.len() > 2 && cycle[cycle.len() - 1] < cycle[1] {
        cycle[1..].reverse();
    }
    cycle
}

/// Checks every component of `mesh` against the oracle; returns (components, loops).
fn check_mesh(mesh: &TriMesh, label: &str) -> (usize, usize) {
    let s = Surfaces::from_mesh_with_boundary(mesh).unwrap_or_else(|e| panic!("{label}: {e}"));
    let comps = components(&mesh.faces);
    assert_eq!(s.components.len(), comps.len(), "{label}: components");
    let used: BTreeSet<u32> = mesh.faces.iter().flatten().copied().collect();
    let dropped: Vec<u32> = (0..mesh.vertex_count as u32)
        .filter(|v| !used.contains(v))
        .collect();
    assert_eq!(s.dropped_vertices, dropped, "{label}: dropped vertices");
    let mut recovered: Vec<Option<[u32; 3]>> = vec![None; mesh.faces.len()];
    let mut loops = 0;
    for (c, faces_idx) in s.components.iter().zip(&comps) {
        // The same faces as the oracle's component, in input order.
        assert_eq!(
            c.face_origin
                .iter()
                .map(|&f| f as usize)
                .collect::<Vec<_>>(),
            *faces_idx,
            "{label}: component faces"
        );
        let faces: Vec<[u32; 3]> = faces_idx.iter().map(|&f| mesh.faces[f]).collect();
        // Round trip: the open faces over mesh ids are the input's, in the input's order.
        let open = c.open_faces_in_mesh();
        assert_eq!(open, faces, "{label}: open faces round trip");
        for (&f, g) in c.face_origin.iter().zip(&open) {
            recovered[f as usize] = Some(*g);
        }
        // The coned triangulation is a valid closed surface with χ = χ(open) + loops.
        c.tri()
            .validate()
            .unwrap_or_else(|e| panic!("{label}: {e}"));
        let expected_loops = walk_loops(&faces);
        assert_eq!(library_loops(c), expected_loops, "{label}: loops");
        // As written, each loop starts at its smallest local id and goes towards the
        // smaller of that vertex's neighbours.
        for l in c.boundary_loops() {
            let ids: Vec<u32> = l.iter().map(|v| v.0).collect();
            assert_eq!(ids, canonical(ids.clone()), "{label}: loop as written");
        }
        // A real face names its mesh face (the same vertices); a cone face, on a virtual
        // vertex, names none.
        for f in c.tri().faces() {
            let vs = c.tri().face_vertices(f);
            match c.face_origin_of(f) {
                Some(m) => {
                    let mut got: Vec<u32> = vs
                        .iter()
                        .map(|&v| c.vertex_origin_of(v).expect("a real face's vertex"))
                        .collect();
                    let mut want = mesh.faces[m as usize].to_vec();
                    got.sort_unstable();
                    want.sort_unstable();
                    assert_eq!(got, want, "{label}: face {} origin", f.0);
                }
                None => assert!(
                    vs.iter().any(|&v| c.is_virtual(v)),
                    "{label}: face {} has no origin",
                    f.0
                ),
            }
        }
        // A boundary vertex lies on its loop's virtual vertex; others on none.
        for v in c.tri().vertices() {
            match c.loop_of(v) {
                Some(w) => assert!(
                    c.is_virtual(w) && c.tri().link(w).any(|x| x == v),
                    "{label}: loop of {}",
                    v.0
                ),
                None => assert!(
                    c.is_virtual(v) || c.tri().link(v).all(|x| !c.is_virtual(x)),
                    "{label}: {} is on a loop",
                    v.0
                ),
            }
        }
        // Ids past the triangulation's are neither virtual, on a loop, nor faces of the mesh.
        let past = VertexId(c.tri().vertex_capacity() as u32 + 1);
        assert!(!c.is_virtual(past) && c.loop_of(past).is_none(), "{label}");
        let past_face = FaceId(c.tri().face_capacity() as u32);
        assert_eq!(c.face_origin_of(past_face), None, "{label}");
        let b = expected_loops.len();
        loops += b;
        let lengths: Vec<usize> = c.boundary_loops().iter().map(Vec::len).collect();
        assert_eq!(c.loop_lengths(), lengths, "{label}: loop lengths");
        assert_eq!(c.virtual_vertices().count(), b);
        for w in c.virtual_vertices() {
            assert!(c.is_virtual(w) && c.vertex_origin_of(w).is_none());
            assert!(w.index() >= c.real_vertex_count());
        }
        let x = chi(&faces);
        assert_eq!(
            c.tri().euler_characteristic(),
            x + b as i64,
            "{label}: coned χ"
        );
        let o = orientable(&faces);
        assert_eq!(c.tri().is_orientable(), o, "{label}: orientability");
        let st = c.surface_type();
        assert_eq!(
            (
                st.euler_characteristic(),
                st.is_orientable(),
                st.boundary_loops()
            ),
            (x, o, b),
            "{label}: surface type"
        );
        // Genus from χ = 2 − 2g − b (orientable) or 2 − h − b (not).
        let eg = 2 - x - b as i64;
        assert_eq!(st.euler_genus(), eg, "{label}");
        if o {
            assert_eq!(eg % 2, 0, "{label}: orientable with odd Euler genus");
            assert_eq!(st.orientable_genus(), Some(eg / 2), "{label}");
        } else {
            assert_eq!(st.crosscaps(), Some(eg), "{label}");
            assert!(eg >= 1);
        }
        let (v, e, f) = c.open_counts();
        let vs: BTreeSet<u32> = faces.iter().flatten().copied().collect();
        assert_eq!(
            (v, e, f),
            (vs.len(), edge_faces(&faces).len(), faces.len()),
            "{label}: open counts"
        );
    }
    assert!(recovered.iter().all(Option::is_some), "{label}: faces lost");
    (s.components.len(), loops)
}

// ---------------------------------------------------------------------------------
// Inputs.

/// `mesh` without the faces around each vertex of `centres` (open discs removed).
fn without_stars(mesh: &TriMesh, centres: &[u32]) -> TriMesh {
    TriMesh::combinatorial(
        mesh.vertex_count,
        mesh.faces
            .iter()
            .filter(|f| !f.iter().any(|v| centres.contains(v)))
            .copied()
            .collect(),
    )
}

fn random_closed(kind: SurfaceKind, faces: usize, seed: u64) -> TriMesh {
    let t = gen::random(&RandomParams {
        surface: kind,
        min_faces: faces,
        flip_percent: 30,
        seed,
    })
    .expect("a random surface within the limits");
    TriMesh::combinatorial(t.vertex_capacity(), t.face_list())
}

/// A small deterministic generator (SplitMix64), independent of the library's RNG.
struct Mix(u64);
impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

fn kinds() -> Vec<SurfaceKind> {
    vec![
        SurfaceKind::Orientable(0),
        SurfaceKind::Orientable(1),
        SurfaceKind::Orientable(2),
        SurfaceKind::NonOrientable(1),
        SurfaceKind::NonOrientable(2),
        SurfaceKind::NonOrientable(3),
    ]
}

// ---------------------------------------------------------------------------------
// Tests.

#[test]
fn named_small_surfaces_with_boundary() {
    // Möbius band: the projective plane minus a vertex star.
    let m = without_stars(&gen::projective_plane6(), &[0]);
    check_mesh(&m, "möbius");
    let s = Surfaces::from_mesh_with_boundary(&m).unwrap();
    let st = s.components[0].surface_type();
    assert_eq!(
        st.name(),
        "Möbius band (non-orientable genus 1, 1 boundary loop)"
    );
    assert_eq!((st.euler_characteristic(), st.is_orientable()), (0, false));
    assert_eq!(s.dropped_vertices, vec![0]);

    // Annulus: the icosahedron minus the stars of two antipodal vertices.
    let ico = gen::icosahedron();
    let star = |v: u32| -> BTreeSet<u32> {
        ico.faces
            .iter()
            .filter(|f| f.contains(&v))
            .flatten()
            .copied()
            .collect()
    };
    // The antipode of 0: its closed star is disjoint from 0's.
    let far = (1..12u32)
        .find(|&u| star(u).is_disjoint(&star(0)))
        .expect("antipode");
    let a = without_stars(&ico, &[0, far]);
    let (_, loops) = check_mesh(&a, "annulus");
    assert_eq!(loops, 2);
    let s = Surfaces::from_mesh_with_boundary(&a).unwrap();
    assert_eq!(
        s.components[0].surface_type().name(),
        "annulus (genus 0, 2 boundary loops)"
    );
    assert_eq!(s.components[0].loop_lengths(), vec![5, 5]);

    // A disc whose loop has length 3 and whose coned surface is the tetrahedron.
    let t = TriMesh::combinatorial(3, vec![[0, 1, 2]]);
    check_mesh(&t, "triangle");
    let s = Surfaces::from_mesh_with_boundary(&t).unwrap();
    assert!(s.components[0].tri().is_tetrahedron());
    assert_eq!(
        s.components[0].surface_type().name(),
        "disc (genus 0, 1 boundary loop)"
    );
    // A disc of 3 faces (tetrahedron minus a face): loop of length 3 whose triangle is
    // not a face.
    let d = TriMesh::combinatorial(4, gen::tetrahedron().faces[1..].to_vec());
    check_mesh(&d, "tetrahedron minus a face");

    // A torus with one hole, a Klein bottle with two.
    let t = without_stars(&gen::torus7(), &[0]);
    assert_eq!(check_mesh(&t, "punctured torus").1, 1);
    let k = without_stars(&gen::klein_bottle(), &[0]);
    assert_eq!(check_mesh(&k, "punctured klein bottle").1, 1);

    // Several components, closed and open, with vertices shared by none: a tetrahedron,
    // then the Möbius band shifted past it, then the annulus shifted past both.
    let shift = |fs: &[[u32; 3]], by: u32| -> Vec<[u32; 3]> {
        fs.iter().map(|f| f.map(|v| v + by)).collect()
    };
    let mut faces = gen::tetrahedron().faces;
    faces.extend(shift(
        &without_stars(&gen::projective_plane6(), &[0]).faces,
        4,
    ));
    faces.extend(shift(&a.faces, 10));
    let mixed = TriMesh::combinatorial(22, faces);
    assert_eq!(check_mesh(&mixed, "mixed"), (3, 3));
    let s = Surfaces::from_mesh_with_boundary(&mixed).unwrap();
    assert!(s.components[0].is_closed() && !s.is_closed());
    assert_eq!(s.dropped_vertices, vec![4, 10, 10 + far]);
}

#[test]
fn closed_meshes_build_as_before() {
    for (name, m) in [
        ("tetrahedron", gen::tetrahedron()),
        ("klein", gen::klein_bottle()),
        ("g2", random_closed(SurfaceKind::Orientable(2), 300, 3)),
    ] {
        let closed = Surfaces::from_mesh(&m).unwrap();
        let coned = Surfaces::from_mesh_with_boundary(&m).unwrap();
        assert!(coned.is_closed(), "{name}");
        assert_eq!(coned.loop_count(), 0);
        assert_eq!(closed.components.len(), coned.components.len());
        for (a, b) in closed.components.iter().zip(&coned.components) {
            assert_eq!(a.tri.face_list(), b.tri().face_list(), "{name}");
            assert_eq!(a.vertex_origin, b.vertex_origin, "{name}");
            assert_eq!(a.face_origin, b.face_origin, "{name}");
            assert_eq!(b.surface_type(), contractible::SurfaceType::of(&a.tri));
        }
        check_mesh(&m, name);
    }
}

#[test]
fn random_open_surfaces_match_the_oracle() {
    let mut rng = Mix(42);
    let mut accepted = 0;
    let mut rejected = 0;
    for (i, kind) in kinds().into_iter().enumerate() {
        for seed in 0..6u64 {
            let closed = random_closed(kind, 160 + 40 * i, seed);
            let n = closed.vertex_count;
            // Remove a few vertex stars and a few single faces.
            let centres: Vec<u32> = (0..1 + rng.below(3)).map(|_| rng.below(n) as u32).collect();
            let mut m = without_stars(&closed, &centres);
            for _ in 0..rng.below(4) {
                if m.faces.len() > 1 {
                    let k = rng.below(m.faces.len());
                    m.faces.remove(k);
                }
            }
            let label = format!("{kind:?} seed {seed} centres {centres:?}");
            let r = Surfaces::from_mesh_with_boundary(&m);
            if is_surface_with_boundary(&m.faces) {
                let (_, loops) = check_mesh(&m, &label);
                assert!(loops >= 1, "{label}");
                accepted += 1;
            } else {
                match r {
                    Err(BuildError::PinchedBoundaryVertex { vertex, .. })
                    | Err(BuildError::VertexLinkNotCycle { vertex, .. }) => {
                        // The located vertex really has several fans.
                        let fs: Vec<usize> = (0..m.faces.len())
                            .filter(|&f| m.faces[f].contains(&vertex))
                            .collect();
                        assert!(fan_count(&m.faces, vertex, &fs) > 1, "{label}");
                        if let Err(BuildError::VertexLinkNotCycle { faces, .. }) = r {
                            assert_eq!(faces, fs.len(), "{label}: the mesh's faces at the vertex");
                        }
                    }
                    other => panic!("{label}: expected a pinch, got {other:?}"),
                }
                rejected += 1;
            }
        }
    }
    assert!(accepted >= 20, "only {accepted} valid open surfaces");
    eprintln!("open surfaces: {accepted} accepted, {rejected} pinched");
}

#[test]
fn pinched_and_non_manifold_meshes_are_located_errors() {
    // Two triangles sharing vertex 0 only.
    let bowtie = TriMesh::combinatorial(5, vec![[0, 1, 2], [0, 3, 4]]);
    assert_eq!(
        Surfaces::from_mesh_with_boundary(&bowtie).unwrap_err(),
        BuildError::PinchedBoundaryVertex {
            vertex: 0,
            boundary_edges: 4
        }
    );
    // A closed octahedron and a triangle hanging from its vertex 0: vertex 0 has one
    // cycle of faces and one path.
    let mut faces = gen::octahedron().faces;
    faces.push([0, 6, 7]);
    let e = Surfaces::from_mesh_with_boundary(&TriMesh::combinatorial(8, faces)).unwrap_err();
    assert!(
        matches!(
            e,
            BuildError::VertexLinkNotCycle {
                vertex: 0,
                cycles: 2,
                faces: 5
            }
        ),
        "{e:?}"
    );
    // Three faces on one edge; a duplicated face; a face with a repeated vertex.
    let fin = TriMesh::combinatorial(5, vec![[0, 1, 2], [0, 1, 3], [0, 1, 4]]);
    assert!(matches!(
        Surfaces::from_mesh_with_boundary(&fin),
        Err(BuildError::NonManifoldEdge {
            a: 0,
            b: 1,
            faces: 3,
            ..
        })
    ));
    let dup = TriMesh::combinatorial(4, vec![[0, 1, 2], [2, 1, 0], [0, 1, 3]]);
    assert!(matches!(
        Surfaces::from_mesh_with_boundary(&dup),
        Err(BuildError::DuplicateFace {
            face: 1,
            first: 0,
            ..
        })
    ));
    let deg = TriMesh::combinatorial(3, vec![[0, 1, 1]]);
    assert!(matches!(
        Surfaces::from_mesh_with_boundary(&deg),
        Err(BuildError::DegenerateFace { face: 0, .. })
    ));
}

/// `count` vertices of `mesh` pairwise at least 4 edges apart (greedily, in id order), so
/// that removing their stars opens `count` holes with disjoint boundary loops.
fn far_apart_vertices(mesh: &TriMesh, count: usize) -> Vec<u32> {
    let mut adj: Vec<BTreeSet<u32>> = vec![BTreeSet::new(); mesh.vertex_count];
    for f in &mesh.faces {
        for k in 0..3 {
            adj[f[k] as usize].insert(f[(k + 1) % 3]);
            adj[f[(k + 1) % 3] as usize].insert(f[k]);
        }
    }
    let mut blocked = vec![false; mesh.vertex_count];
    let mut out = Vec::new();
    for v in 0..mesh.vertex_count as u32 {
        if out.len() == count {
            break;
        }
        if blocked[v as usize] || adj[v as usize].is_empty() {
            continue;
        }
        out.push(v);
        // Block everything within distance 3.
        let mut frontier = vec![v];
        blocked[v as usize] = true;
        for _ in 0..3 {
            let mut next = Vec::new();
            for &x in &frontier {
                for &y in &adj[x as usize] {
                    if !blocked[y as usize] {
                        blocked[y as usize] = true;
                        next.push(y);
                    }
                }
            }
            frontier = next;
        }
    }
    assert_eq!(out.len(), count, "{count} far-apart vertices");
    out
}

/// Real meshes opened by removing the stars of far-apart vertices report one loop per
/// hole, checked against the independent loop walk (`check_mesh`).
#[test]
fn opened_real_meshes_report_their_loops() {
    let dir = common::data_meshes().join("closed");
    for (name, holes) in [("bunny_npm", 1), ("bunny_npm", 5), ("high_genus_3", 3)] {
        let m = contractible::io::read_tri_mesh(&dir.join(format!("{name}.off.gz"))).unwrap();
        let open = without_stars(&m, &far_apart_vertices(&m, holes));
        assert_eq!(check_mesh(&open, name), (1, holes), "{name}");
    }
}

/// The repository's non-manifold real meshes are errors with or without boundary, and
/// the same located error.
#[test]
fn non_manifold_real_meshes_stay_errors() {
    non_manifold_meshes_stay_errors(
        &common::data_meshes().join("invalid"),
        &["joined_tetrahedra", "shared_edge_stl"],
    );
}

fn non_manifold_meshes_stay_errors(dir: &std::path::Path, names: &[&str]) {
    for name in names {
        let m = contractible::io::read_tri_mesh(&dir.join(format!("{name}.off.gz"))).unwrap();
        let closed = Surfaces::from_mesh(&m).unwrap_err();
        let open = Surfaces::from_mesh_with_boundary(&m).unwrap_err();
        assert_eq!(open, closed, "{name}: same located error");
        assert!(
            matches!(
                open,
                BuildError::DuplicateFace { .. }
                    | BuildError::NonManifoldEdge { .. }
                    | BuildError::MultipleEdges { .. }
            ),
            "{name}: {open:?}"
        );
    }
}

/// The open and non-manifold meshes of the real-mesh corpus.
mod corpus {
    use super::*;

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn shared_open_meshes_report_their_loops() {
        let dir = common::corpus_meshes().join("invalid");
        for (name, loops) in [("open_camelhead", 1), ("open_bunny_stanford", 5)] {
            let m = contractible::io::read_tri_mesh(&dir.join(format!("{name}.off.gz"))).unwrap();
            assert_eq!(check_mesh(&m, name), (1, loops), "{name}");
        }
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn shared_non_manifold_meshes_stay_errors() {
        non_manifold_meshes_stay_errors(
            &common::corpus_meshes().join("invalid"),
            &[
                "nonmanifold_dino",
                "joined_tetrahedra",
                "shared_edge_stl",
                "dupfaces_crank",
                "happy_vrip_res4",
            ],
        );
    }
}

/// The oracle's verdict on contracting `[u, v]` (mesh ids) in a connected surface with
/// boundary: the image of the simplicial map `v ↦ u` is still a pure 2-complex (every
/// vertex and edge of the image lies in a face of the image, so no vertex and no edge
/// is left dangling) and a connected surface with boundary of the same χ,
/// orientability and number of loops.
fn contraction_keeps_topology(faces: &[[u32; 3]], u: u32, v: u32) -> bool {
    let map = |x: u32| if x == v { u } else { x };
    let after: Vec<[u32; 3]> = faces
        .iter()
        .filter(|f| !(f.contains(&u) && f.contains(&v)))
        .map(|f| f.map(map))
        .collect();
    if after.is_empty() || !is_surface_with_boundary(&after) || components(&after).len() != 1 {
        return false;
    }
    let image_vertices: BTreeSet<u32> = faces.iter().flatten().map(|&x| map(x)).collect();
    let after_vertices: BTreeSet<u32> = after.iter().flatten().copied().collect();
    let after_edges = edge_faces(&after);
    let edges_kept = edge_faces(faces)
        .keys()
        .filter(|&&(a, b)| map(a) != map(b))
        .all(|&(a, b)| after_edges.contains_key(&key(map(a), map(b))));
    if image_vertices != after_vertices || !edges_kept {
        return false;
    }
    let loops = |fs: &[[u32; 3]]| walk_loops(fs).len();
    chi(&after) == chi(faces)
        && orientable(&after) == orientable(faces)
        && loops(&after) == loops(faces)
}

#[test]
fn boundary_link_condition_matches_the_oracle() {
    let mut rng = Mix(7);
    let mut checked = 0;
    let mut cone_alone_wrong = 0;
    for kind in kinds() {
        for seed in 0..4u64 {
            let closed = random_closed(kind, 60, seed);
            let n = closed.vertex_count;
            let centres: Vec<u32> = (0..2).map(|_| rng.below(n) as u32).collect();
            let m = without_stars(&closed, &centres);
            if !is_surface_with_boundary(&m.faces) {
                continue;
            }
            let s = Surfaces::from_mesh_with_boundary(&m).unwrap();
            for c in &s.components {
                let faces: Vec<[u32; 3]> =
                    c.face_origin.iter().map(|&f| m.faces[f as usize]).collect();
                let loops = walk_loops(&faces);
                for (a, b) in edge_faces(&faces).keys().copied() {
                    let local = |x: u32| {
                        VertexId(c.vertex_origin.iter().position(|&o| o == x).unwrap() as u32)
                    };
                    let (la, lb) = (local(a), local(b));
                    let expected = contraction_keeps_topology(&faces, a, b);
                    assert_eq!(
                        c.is_contractible(la, lb),
                        expected,
                        "{kind:?} seed {seed}: edge [{a}, {b}]"
                    );
                    if c.tri().is_contractible(la, lb) != expected {
                        // Only an edge joining two different loops can fool the cone.
                        let on = |x: u32| loops.iter().position(|l| l.contains(&x));
                        let (pa, pb) = (on(a), on(b));
                        assert!(
                            pa.is_some() && pb.is_some() && pa != pb,
                            "{kind:?} seed {seed}: cone wrong on [{a}, {b}]"
                        );
                        cone_alone_wrong += 1;
                    }
                    checked += 1;
                }
                for w in c.virtual_vertices() {
                    for x in c.tri().link(w) {
                        assert!(
                            !c.is_contractible(w, x),
                            "virtual edges are never contractible"
                        );
                    }
                }
            }
        }
    }
    assert!(checked > 500, "only {checked} edges checked");
    // The per-loop cone alone accepts edges joining two loops; the extra check matters.
    eprintln!("{checked} edges, {cone_alone_wrong} where the per-loop cone alone is wrong");
    assert!(cone_alone_wrong > 0, "no edge joined two boundary loops");
}
