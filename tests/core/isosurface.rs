//! Marching tetrahedra (`gen::isosurface`) against an independent manifold checker: edge
//! incidences, vertex links (path or cycle), components, boundary loops, Euler
//! characteristic, orientation of every shared edge, signed volume, the implicit
//! functions re-implemented here, and the paper's Table 1 sizes.

use std::collections::{HashMap, HashSet};

use contractible::gen::{
    isosurface, large_torus, paper_hyperboloid, paper_torus, Implicit, IsoError, IsoParams,
    Tessellation,
};
use contractible::{Surfaces, TriMesh, Triangulation};

use crate::common::{find, union};

const BOTH: [Tessellation; 2] = [Tessellation::SixTetrahedra, Tessellation::BodyCentred];

/// One connected component as seen by the checker.
#[derive(Debug)]
struct Part {
    v: usize,
    e: usize,
    f: usize,
    boundary_edges: usize,
    boundary_loops: usize,
}

impl Part {
    fn chi(&self) -> i64 {
        self.v as i64 - self.e as i64 + self.f as i64
    }
}

/// Checks that `m` is a 2-manifold, possibly with boundary, whose faces are oriented
/// consistently (every interior edge traversed once in each direction), with every
/// vertex used and distinct positions; returns its components in order of first face.
fn check_manifold(m: &TriMesh) -> Result<Vec<Part>, String> {
    let n = m.vertex_count;
    let pos = m.positions.as_ref().ok_or("no positions")?;
    if pos.len() != n {
        return Err("positions length".into());
    }
    let mut seen_pos = HashSet::new();
    for p in pos {
        if p.iter().any(|c| !c.is_finite()) {
            return Err(format!("non-finite position {p:?}"));
        }
        if !seen_pos.insert(p.map(f64::to_bits)) {
            return Err(format!("two vertices at {p:?}"));
        }
    }
    let mut tri_set = HashSet::new();
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    let mut undirected: HashMap<(u32, u32), usize> = HashMap::new();
    let mut used = vec![false; n];
    for (fi, f) in m.faces.iter().enumerate() {
        if f.iter().any(|&x| x as usize >= n) {
            return Err(format!("face {fi} out of range"));
        }
        if f[0] == f[1] || f[1] == f[2] || f[0] == f[2] {
            return Err(format!("degenerate face {fi}"));
        }
        let mut s = *f;
        s.sort_unstable();
        if !tri_set.insert(s) {
            return Err(format!("duplicate face {fi}"));
        }
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            used[a as usize] = true;
            if directed.insert((a, b), fi).is_some() {
                return Err(format!(
                    "directed edge {a}->{b} twice: orientation inconsistent"
                ));
            }
            *undirected.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    if let Some(v) = used.iter().position(|&u| !u) {
        return Err(format!("vertex {v} unused"));
    }
    if let Some((e, c)) = undirected.iter().find(|(_, &c)| c > 2) {
        return Err(format!("edge {e:?} in {c} faces"));
    }
    // Vertex links: the edges opposite each vertex form one path or one cycle.
    let mut link: Vec<Vec<(u32, u32)>> = vec![Vec::new(); n];
    for f in &m.faces {
        for k in 0..3 {
            link[f[k] as usize].push((f[(k + 1) % 3], f[(k + 2) % 3]));
        }
    }
    for (v, edges) in link.iter().enumerate() {
        let mut deg: HashMap<u32, usize> = HashMap::new();
        let mut ids: HashMap<u32, usize> = HashMap::new();
        for &(a, b) in edges {
            *deg.entry(a).or_default() += 1;
            *deg.entry(b).or_default() += 1;
            let next = ids.len();
            ids.entry(a).or_insert(next);
            let next = ids.len();
            ids.entry(b).or_insert(next);
        }
        if deg.values().any(|&d| d > 2) {
            return Err(format!("vertex {v}: link vertex of degree > 2"));
        }
        let mut parent: Vec<usize> = (0..ids.len()).collect();
        for &(a, b) in edges {
            union(&mut parent, ids[&a], ids[&b]);
        }
        let roots: HashSet<usize> = (0..ids.len()).map(|i| find(&mut parent, i)).collect();
        if roots.len() != 1 {
            return Err(format!("vertex {v}: link has {} pieces", roots.len()));
        }
        let nodes = ids.len();
        if edges.len() != nodes && edges.len() + 1 != nodes {
            return Err(format!("vertex {v}: link is neither a path nor a cycle"));
        }
    }
    // Components over shared edges, and boundary loops per component.
    let nf = m.faces.len();
    let mut parent: Vec<usize> = (0..nf).collect();
    let mut first_face: HashMap<(u32, u32), usize> = HashMap::new();
    for (fi, f) in m.faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            if let Some(&g) = first_face.get(&(a.min(b), a.max(b))) {
                union(&mut parent, fi, g);
            } else {
                first_face.insert((a.min(b), a.max(b)), fi);
            }
        }
    }
    let mut order: Vec<usize> = Vec::new();
    let mut part_of: HashMap<usize, usize> = HashMap::new();
    for fi in 0..nf {
        let r = find(&mut parent, fi);
        if let std::collections::hash_map::Entry::Vacant(e) = part_of.entry(r) {
            e.insert(order.len());
            order.push(r);
        }
    }
    let mut parts: Vec<Part> = order
        .iter()
        .map(|_| Part {
            v: 0,
            e: 0,
            f: 0,
            boundary_edges: 0,
            boundary_loops: 0,
        })
        .collect();
    let mut vertex_part = vec![usize::MAX; n];
    for (fi, f) in m.faces.iter().enumerate() {
        let p = part_of[&find(&mut parent, fi)];
        parts[p].f += 1;
        for &v in f {
            vertex_part[v as usize] = p;
        }
    }
    for &p in &vertex_part {
        parts[p].v += 1;
    }
    let mut bparent: Vec<usize> = (0..n).collect();
    let mut boundary_vertices = HashSet::new();
    for (&(a, b), &c) in &undirected {
        let p = vertex_part[a as usize];
        parts[p].e += 1;
        if c == 1 {
            parts[p].boundary_edges += 1;
            union(&mut bparent, a as usize, b as usize);
            boundary_vertices.insert(a as usize);
            boundary_vertices.insert(b as usize);
        }
    }
    let loops: HashSet<usize> = boundary_vertices
        .iter()
        .map(|&v| find(&mut bparent, v))
        .collect();
    for r in loops {
        parts[vertex_part[r]].boundary_loops += 1;
    }
    Ok(parts)
}

/// The signed volume enclosed by a closed oriented mesh (positive when outward).
fn signed_volume(m: &TriMesh) -> f64 {
    let p = m.positions.as_ref().expect("positions");
    m.faces
        .iter()
        .map(|f| {
            let [a, b, c] = f.map(|v| p[v as usize]);
            (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]))
                / 6.0
        })
        .sum()
}

fn min_area(m: &TriMesh) -> f64 {
    let p = m.positions.as_ref().expect("positions");
    m.faces
        .iter()
        .map(|f| {
            let [a, b, c] = f.map(|v| p[v as usize]);
            let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
            let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
            let x = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            0.5 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

/// The implicit functions, written again from their documentation.
fn f_indep(s: &Implicit, p: [f64; 3]) -> f64 {
    let [x, y, z] = p;
    match *s {
        Implicit::Sphere { radius } => x * x + y * y + z * z - radius * radius,
        Implicit::Torus { major, minor } => {
            let q = (x * x + y * y).sqrt() - major;
            q * q + z * z - minor * minor
        }
        Implicit::TwoSheetHyperboloid { c, .. } => x * x + y * y - z * z + c,
        Implicit::GenusG { g } => {
            let last = 2.0 * (g.max(1) - 1) as f64;
            let d = if x < 0.0 {
                -x
            } else if x > last {
                x - last
            } else {
                0.0
            };
            let mut f = (d * d + y * y + 4.0 * z * z).sqrt() - 1.0;
            for i in 0..g {
                let hx = x - 2.0 * i as f64;
                f = f.max(0.45 - (hx * hx + y * y).sqrt());
            }
            f
        }
    }
}

fn gradient_norm(s: &Implicit, p: [f64; 3]) -> f64 {
    let h = 1e-6;
    let g: Vec<f64> = (0..3)
        .map(|a| {
            let (mut lo, mut hi) = (p, p);
            lo[a] -= h;
            hi[a] += h;
            (f_indep(s, hi) - f_indep(s, lo)) / (2.0 * h)
        })
        .collect();
    (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt()
}

/// Every vertex is within about a cell of the surface: `|f(p)| <= |∇f(p)|·diag`.
fn assert_on_surface(params: &IsoParams, m: &TriMesh, what: &str) {
    let diag = (0..3)
        .map(|a| ((params.max[a] - params.min[a]) / params.cells[a] as f64).powi(2))
        .sum::<f64>()
        .sqrt();
    for (v, &p) in m.positions.as_ref().expect("positions").iter().enumerate() {
        let f = f_indep(&params.implicit, p) - params.level;
        let g = gradient_norm(&params.implicit, p);
        assert!(
            f.abs() <= g * diag,
            "{what}: vertex {v} at {p:?}: |f| = {} > |∇f|·diag = {}",
            f.abs(),
            g * diag
        );
    }
}

/// A closed orientable surface with Euler characteristic `chi`, outward, consistent.
fn assert_closed(params: &IsoParams, chi: i64, what: &str) -> TriMesh {
    let m = isosurface(params).unwrap_or_else(|e| panic!("{what}: {e}"));
    let parts = check_manifold(&m).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(parts.len(), 1, "{what}: components {parts:?}");
    assert_eq!(parts[0].boundary_edges, 0, "{what}: open");
    assert_eq!(parts[0].chi(), chi, "{what}: χ");
    assert!(signed_volume(&m) > 0.0, "{what}: not outward");
    assert!(min_area(&m) > 0.0, "{what}: zero-area triangle");
    // The library's own builder agrees: closed, connected, already consistently oriented.
    let t = Triangulation::from_faces(m.vertex_count, &m.faces)
        .unwrap_or_else(|e| panic!("{what}: from_faces: {e}"));
    assert_eq!(t.euler_characteristic(), chi, "{what}");
    let flips = t
        .orientation()
        .unwrap_or_else(|| panic!("{what}: non-orientable"));
    assert!(
        flips.iter().all(|&f| !f),
        "{what}: faces not consistently oriented"
    );
    let s = Surfaces::from_mesh(&m).unwrap_or_else(|e| panic!("{what}: {e}"));
    assert_eq!(s.components.len(), 1, "{what}");
    assert_on_surface(params, &m, what);
    m
}

#[test]
fn spheres_and_tori_are_closed_outward_and_on_the_surface() {
    for tess in BOTH {
        for res in [6, 11, 24] {
            let p = IsoParams::new(Implicit::Sphere { radius: 1.3 }, tess, res);
            assert_closed(&p, 2, &format!("sphere {tess:?} {res}"));
        }
        for res in [20, 33, 48] {
            let torus = Implicit::Torus {
                major: 1.0,
                minor: 0.4,
            };
            assert_closed(
                &IsoParams::new(torus, tess, res),
                0,
                &format!("torus {tess:?} {res}"),
            );
        }
    }
}

#[test]
fn genus_g_surfaces_have_genus_g() {
    for tess in BOTH {
        for g in 0..=5u32 {
            // About 12 cells per unit: holes of radius 0.45 and a slab 1 thick resolve.
            for per_unit in [12, 17] {
                let res = per_unit * (2 * g.max(1) + 1);
                let p = IsoParams::new(Implicit::GenusG { g }, tess, res);
                assert_closed(&p, 2 - 2 * g as i64, &format!("genus {g} {tess:?} {res}"));
            }
        }
    }
}

#[test]
fn samples_exactly_at_the_level_give_manifolds_without_zero_area() {
    // Box ±1.25 and 10 cells: half-steps of 0.125, so the six points (±1, 0, 0), ...
    // and many more lattice points lie exactly on the unit sphere (f = 0 exactly).
    for tess in BOTH {
        for res in [10, 20] {
            let p = IsoParams::new(Implicit::Sphere { radius: 1.0 }, tess, res);
            let half = (p.max[0] - p.min[0]) / (2 * p.cells[0]) as f64;
            let on = (0..=2 * p.cells[0])
                .filter(|&i| {
                    let x = p.min[0] + i as f64 * half;
                    x * x == 1.0
                })
                .count();
            assert_eq!(on, 2, "the lattice hits x = ±1 exactly");
            assert_closed(&p, 2, &format!("unit sphere on the lattice {tess:?} {res}"));
        }
        // Torus (1, 0.5) on the box ±2 × ±2 × ±1 with 16 × 16 × 8 cells: half-steps of
        // 0.125, so the samples (±1.5, 0, 0), (±0.5, 0, 0), (0, ±1.5, 0), ... have f = 0.
        let torus = Implicit::Torus {
            major: 1.0,
            minor: 0.5,
        };
        let p = IsoParams {
            implicit: torus,
            tessellation: tess,
            cells: [16, 16, 8],
            min: [-2.0, -2.0, -1.0],
            max: [2.0, 2.0, 1.0],
            level: 0.0,
        };
        let zeros = (0..=32)
            .flat_map(|i| {
                (0..=32).map(move |j| [-2.0 + i as f64 * 0.125, -2.0 + j as f64 * 0.125, 0.0])
            })
            .filter(|&q| f_indep(&torus, q) == 0.0)
            .count();
        assert!(zeros >= 8, "{zeros} lattice samples exactly on the torus");
        assert_closed(&p, 0, &format!("torus on the lattice {tess:?}"));
    }
}

#[test]
fn hyperboloid_is_two_discs() {
    for tess in BOTH {
        for res in [12, 25, 40] {
            let implicit = Implicit::TwoSheetHyperboloid {
                c: 0.3,
                half_width: 1.2,
                half_height: 1.5,
            };
            let p = IsoParams::new(implicit, tess, res);
            let what = format!("hyperboloid {tess:?} {res}");
            let m = isosurface(&p).unwrap_or_else(|e| panic!("{what}: {e}"));
            let parts = check_manifold(&m).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_eq!(parts.len(), 2, "{what}: {parts:?}");
            for part in &parts {
                assert_eq!(part.chi(), 1, "{what}: {part:?}");
                assert_eq!(part.boundary_loops, 1, "{what}: {part:?}");
                assert!(part.boundary_edges >= 3, "{what}: {part:?}");
            }
            assert!(min_area(&m) > 0.0, "{what}");
            assert_on_surface(&p, &m, &what);
            // The boundary lies on the box: every boundary vertex is on a box face.
            let pos = m.positions.as_ref().expect("positions");
            let mut count: HashMap<(u32, u32), usize> = HashMap::new();
            for f in &m.faces {
                for k in 0..3 {
                    let (a, b) = (f[k], f[(k + 1) % 3]);
                    *count.entry((a.min(b), a.max(b))).or_default() += 1;
                }
            }
            for (&(a, _), _) in count.iter().filter(|(_, &c)| c == 1) {
                let q = pos[a as usize];
                let on_box = (0..3)
                    .any(|k| (q[k] - p.min[k]).abs() < 1e-9 || (q[k] - p.max[k]).abs() < 1e-9);
                assert!(
                    on_box,
                    "{what}: boundary vertex {a} at {q:?} inside the box"
                );
            }
        }
    }
}

#[test]
fn output_is_deterministic() {
    for tess in BOTH {
        let p = IsoParams::new(Implicit::GenusG { g: 2 }, tess, 40);
        let a = isosurface(&p).expect("genus 2");
        let b = isosurface(&{ p }).expect("genus 2");
        assert_eq!(a, b);
    }
}

#[test]
fn paper_table_1_sizes() {
    for tess in BOTH {
        let p = paper_torus(tess);
        let m = assert_closed(&p, 0, &format!("paper torus {tess:?}"));
        assert_eq!(
            (m.vertex_count, m.faces.len()),
            (16_772, 33_544),
            "{tess:?}"
        );

        let p = paper_hyperboloid(tess);
        let m = isosurface(&p).expect("paper hyperboloid");
        let parts = check_manifold(&m).unwrap_or_else(|e| panic!("{tess:?}: {e}"));
        assert_eq!(parts.len(), 2);
        assert!(parts.iter().all(|q| q.chi() == 1 && q.boundary_loops == 1));
        assert_eq!(m.vertex_count, 56_288, "{tess:?}");
        let want_faces = match tess {
            Tessellation::BodyCentred => 111_140,
            // Both counts cannot match with this tessellation (see the preset's doc).
            Tessellation::SixTetrahedra => 111_332,
        };
        assert_eq!(m.faces.len(), want_faces, "{tess:?}");
    }
}

#[test]
fn large_torus_has_a_million_triangles() {
    for tess in BOTH {
        let p = large_torus(tess);
        let m = isosurface(&p).expect("large torus");
        assert!(m.faces.len() >= 1_000_000, "{tess:?}: {}", m.faces.len());
        let t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("closed surface");
        assert_eq!(t.euler_characteristic(), 0);
    }
}

#[test]
fn bad_parameters_are_typed_errors() {
    let sphere = IsoParams::new(
        Implicit::Sphere { radius: 1.0 },
        Tessellation::SixTetrahedra,
        8,
    );
    let mut p = sphere;
    p.cells[1] = 0;
    assert_eq!(isosurface(&p), Err(IsoError::NoCells { axis: 1 }));
    let mut p = sphere;
    p.max[2] = p.min[2];
    assert!(matches!(
        isosurface(&p),
        Err(IsoError::BadBox { axis: 2, .. })
    ));
    let mut p = sphere;
    p.level = f64::NAN;
    assert!(matches!(isosurface(&p), Err(IsoError::BadLevel(_))));
    let mut p = sphere;
    p.implicit = Implicit::Torus {
        major: 0.5,
        minor: 0.5,
    };
    assert!(matches!(isosurface(&p), Err(IsoError::BadSurface { .. })));
    let mut p = sphere;
    p.cells = [1 << 12, 1 << 11, 1];
    assert!(matches!(isosurface(&p), Err(IsoError::GridTooLarge { .. })));
    let mut p = sphere;
    p.level = 100.0; // every sample inside
    assert_eq!(isosurface(&p), Err(IsoError::Empty));
}

/// Pepko–Borisenko Theorem 3: marching-tetrahedra output has no edge failing the link
/// condition (such edges only appear after contractions). Checked with the naive link
/// test, which shares nothing with the fast one, on the Table 1 workloads and genus
/// 0..5 with both tessellations; an edge of the open hyperboloid is judged on the surface
/// closed by a cone over each boundary loop, and the test checks that it looked at
/// every edge of the mesh.
#[test]
fn marching_tetrahedra_output_satisfies_theorem_3() {
    for tess in BOTH {
        let mut inputs = vec![paper_torus(tess), paper_hyperboloid(tess)];
        inputs.extend((0..=5).map(|g| IsoParams::new(Implicit::GenusG { g }, tess, 24)));
        for params in inputs {
            let mesh = isosurface(&params).expect("valid parameters");
            let surfaces = Surfaces::from_mesh_with_boundary(&mesh).expect("a surface");
            let mut real_edges = 0;
            for c in &surfaces.components {
                for (u, v, _) in c.tri().edges() {
                    if c.is_virtual(u) || c.is_virtual(v) {
                        continue;
                    }
                    real_edges += 1;
                    assert!(
                        c.tri().link_condition_naive(u, v),
                        "{params:?}: [{u}, {v}] fails the link condition"
                    );
                }
            }
            let distinct: HashSet<(u32, u32)> = mesh
                .faces
                .iter()
                .flat_map(|f| {
                    (0..3).map(move |k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3])))
                })
                .collect();
            assert_eq!(real_edges, distinct.len(), "{params:?}: every edge seen");
        }
    }
}
