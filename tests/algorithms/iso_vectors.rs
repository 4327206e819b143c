//! The marching-tetrahedra conformance vectors `spec/vectors/iso-*.jsonl` (format:
//! `spec/vectors/README.md`, section "Marching-tetrahedra vectors"):
//!
//! 1. **Exactly**: `gen::isosurface` on the stored parameters gives the stored positions
//!    (bit for bit) and faces. Regenerate with
//!    `cargo run --release -p contractible-tools --bin make_iso_vectors` only for an
//!    intended change.
//! 2. **Independently** of the generator, from the stored data and the documented
//!    functions alone: the faces form 2-manifolds whose components (χ, orientability,
//!    boundary loops, by the fuzz harness's face-list classifier) are those stated for
//!    the parameters; every vertex lies on the stored grid edge, an edge of the
//!    tessellation (decided here from the sample lattice) whose ends are on opposite
//!    sides of the level, at the interpolated position recomputed here; the stored edges
//!    are exactly the crossing edges of the grid, each once; every face's normal points
//!    from the inside end to the outside end of each of its vertices' edges. For the
//!    `iso-exact` group the interpolation is verified in integer arithmetic: each stored
//!    coordinate is the exact rational value, no rounding anywhere.

use std::collections::BTreeSet;

use contractible::gen::{isosurface, Implicit, IsoParams, Tessellation};
use serde_json::Value;

use crate::common;
use crate::harness::{surface_topology, ComponentType};

const GROUPS: [(&str, usize); 2] = [("iso-exact", 11), ("iso-rounded", 5)];

/// The interpolation clamp the generator documents (`[CLAMP, 1 − CLAMP]`), written here
/// rather than read from the library.
const CLAMP: f64 = 1e-3;

/// A sample point in doubled lattice coordinates.
type Lattice = [u32; 3];

/// The implicit function as the vector states it.
#[derive(Clone, Copy, Debug)]
enum Field {
    Sphere { radius: f64 },
    Torus { major: f64, minor: f64 },
    Hyperboloid { c: f64 },
}

impl Field {
    /// `f(p)` in the operation order `spec/vectors/README.md` documents.
    fn eval(self, [x, y, z]: [f64; 3]) -> f64 {
        match self {
            Field::Sphere { radius } => x * x + y * y + z * z - radius * radius,
            Field::Torus { major, minor } => {
                let q = (x * x + y * y).sqrt() - major;
                q * q + z * z - minor * minor
            }
            Field::Hyperboloid { c } => x * x + y * y - z * z + c,
        }
    }
}

/// The stored parameters.
struct Grid {
    field: Field,
    bcc: bool,
    ext: [u32; 3],
    min: [f64; 3],
    max: [f64; 3],
    level: f64,
}

impl Grid {
    fn half(&self, a: usize) -> f64 {
        (self.max[a] - self.min[a]) / f64::from(self.ext[a])
    }

    fn position(&self, p: Lattice) -> [f64; 3] {
        [0, 1, 2].map(|a| self.min[a] + f64::from(p[a]) * self.half(a))
    }

    fn inside(&self, p: Lattice) -> bool {
        self.field.eval(self.position(p)) <= self.level
    }

    fn in_range(&self, p: [i64; 3]) -> bool {
        (0..3).all(|a| p[a] >= 0 && p[a] <= i64::from(self.ext[a]))
    }

    /// Corners (all even), cube centres (all odd, body-centred only), centres of cube
    /// faces on the box surface (two odd, the even one 0 or the extent; body-centred).
    fn is_sample(&self, p: Lattice) -> bool {
        let odd: Vec<usize> = (0..3).filter(|&a| p[a] % 2 == 1).collect();
        match odd.len() {
            0 => true,
            3 => self.bcc,
            2 => {
                let even = 3 - odd[0] - odd[1];
                self.bcc && (p[even] == 0 || p[even] == self.ext[even])
            }
            _ => false,
        }
    }

    /// Whether `a`–`b` is an edge of a tetrahedron of the tessellation. Six tetrahedra:
    /// two corners whose difference is a nonzero 0/1 vector up to sign (the edges of
    /// the Kuhn paths). Body-centred: a cube edge, two adjacent cube centres, a corner and
    /// the centre of a cube at it, a box-face centre and a corner of its face, a box-face
    /// centre and the centre of its cube.
    fn is_edge(&self, a: Lattice, b: Lattice) -> bool {
        if a == b || !self.is_sample(a) || !self.is_sample(b) {
            return false;
        }
        let d: [i64; 3] = [0, 1, 2].map(|k| i64::from(b[k]) - i64::from(a[k]));
        let kind = |p: Lattice| p.iter().filter(|&&c| c % 2 == 1).count();
        let (ka, kb) = (kind(a), kind(b));
        if !self.bcc {
            let pos = d.iter().all(|&x| x == 0 || x == 2);
            let neg = d.iter().all(|&x| x == 0 || x == -2);
            return pos || neg;
        }
        let nonzero = d.iter().filter(|&&x| x != 0).count();
        let all_abs = |v: i64| d.iter().all(|&x| x.abs() == v || x == 0);
        match (ka.min(kb), ka.max(kb)) {
            // Corner–corner and centre–centre: one axis step.
            (0, 0) | (3, 3) => nonzero == 1 && all_abs(2),
            // Corner–centre: a half diagonal.
            (0, 3) => nonzero == 3 && all_abs(1),
            // Face centre–corner: within the face plane, a half diagonal of the face.
            (0, 2) => nonzero == 2 && all_abs(1),
            // Face centre–centre: half a step along the face's normal.
            (2, 3) => nonzero == 1 && all_abs(1),
            _ => false,
        }
    }

    /// Every edge of the tessellation joining an inside and an outside sample, as
    /// (inside, outside), found by testing every pair of samples at most one cell apart.
    fn crossing_edges(&self) -> BTreeSet<(Lattice, Lattice)> {
        let mut out = BTreeSet::new();
        for z in 0..=self.ext[2] {
            for y in 0..=self.ext[1] {
                for x in 0..=self.ext[0] {
                    let a = [x, y, z];
                    if !self.is_sample(a) || !self.inside(a) {
                        continue;
                    }
                    for dz in -2i64..=2 {
                        for dy in -2i64..=2 {
                            for dx in -2i64..=2 {
                                let b = [i64::from(x) + dx, i64::from(y) + dy, i64::from(z) + dz];
                                if !self.in_range(b) {
                                    continue;
                                }
                                let b = b.map(|c| c as u32);
                                if self.is_edge(a, b) && self.is_sample(b) && !self.inside(b) {
                                    out.insert((a, b));
                                }
                            }
                        }
                    }
                }
            }
        }
        out
    }

    /// The interpolated point on the edge from inside `i` to outside `o`, in the
    /// documented operation order.
    fn interpolate(&self, i: Lattice, o: Lattice) -> [f64; 3] {
        let (pi, po) = (self.position(i), self.position(o));
        let (fi, fo) = (self.field.eval(pi), self.field.eval(po));
        let t = ((self.level - fi) / (fo - fi)).clamp(CLAMP, 1.0 - CLAMP);
        [0, 1, 2].map(|k| pi[k] + t * (po[k] - pi[k]))
    }
}

fn f64s<const N: usize>(v: &Value) -> [f64; N] {
    let a = v.as_array().expect("array");
    assert_eq!(a.len(), N);
    std::array::from_fn(|k| a[k].as_f64().expect("number"))
}

fn u32s<const N: usize>(v: &Value) -> [u32; N] {
    let a = v.as_array().expect("array");
    assert_eq!(a.len(), N);
    std::array::from_fn(|k| a[k].as_u64().expect("integer") as u32)
}

fn grid(v: &Value) -> Grid {
    let p = &v["params"];
    let imp = &p["implicit"];
    let num = |k: &str| imp[k].as_f64().unwrap_or_else(|| panic!("implicit {k}"));
    let field = match imp["kind"].as_str().expect("kind") {
        "sphere" => Field::Sphere {
            radius: num("radius"),
        },
        "torus" => Field::Torus {
            major: num("major"),
            minor: num("minor"),
        },
        "two_sheet_hyperboloid" => Field::Hyperboloid { c: num("c") },
        other => panic!("unknown implicit {other}"),
    };
    let bcc = match p["tessellation"].as_str().expect("tessellation") {
        "six" => false,
        "bcc" => true,
        other => panic!("unknown tessellation {other}"),
    };
    Grid {
        field,
        bcc,
        ext: u32s::<3>(&p["cells"]).map(|n| 2 * n),
        min: f64s(&p["min"]),
        max: f64s(&p["max"]),
        level: p["level"].as_f64().expect("level"),
    }
}

/// The library's parameters for the stored ones.
fn library_params(v: &Value) -> IsoParams {
    let p = &v["params"];
    let imp = &p["implicit"];
    let num = |k: &str| imp[k].as_f64().unwrap_or_else(|| panic!("implicit {k}"));
    let implicit = match imp["kind"].as_str().expect("kind") {
        "sphere" => Implicit::Sphere {
            radius: num("radius"),
        },
        "torus" => Implicit::Torus {
            major: num("major"),
            minor: num("minor"),
        },
        "two_sheet_hyperboloid" => Implicit::TwoSheetHyperboloid {
            c: num("c"),
            half_width: num("half_width"),
            half_height: num("half_height"),
        },
        other => panic!("unknown implicit {other}"),
    };
    IsoParams {
        implicit,
        tessellation: match p["tessellation"].as_str().expect("tessellation") {
            "six" => Tessellation::SixTetrahedra,
            _ => Tessellation::BodyCentred,
        },
        cells: u32s(&p["cells"]),
        min: f64s(&p["min"]),
        max: f64s(&p["max"]),
        level: p["level"].as_f64().expect("level"),
    }
}

fn positions(v: &Value) -> Vec<[f64; 3]> {
    v["positions"]
        .as_array()
        .expect("positions")
        .iter()
        .map(f64s::<3>)
        .collect()
}

fn faces(v: &Value) -> Vec<[u32; 3]> {
    v["faces"]
        .as_array()
        .expect("faces")
        .iter()
        .map(u32s::<3>)
        .collect()
}

fn vertex_edges(v: &Value) -> Vec<(Lattice, Lattice)> {
    v["vertex_edges"]
        .as_array()
        .expect("vertex_edges")
        .iter()
        .map(|e| {
            let e = e.as_array().expect("pair");
            assert_eq!(e.len(), 2);
            (u32s::<3>(&e[0]), u32s::<3>(&e[1]))
        })
        .collect()
}

fn all() -> Vec<Value> {
    common::read_vector_groups(&GROUPS)
}

#[test]
fn library_reproduces_every_iso_vector_exactly() {
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let mesh = isosurface(&library_params(&v)).unwrap_or_else(|e| panic!("{name}: {e}"));
        let got: Vec<[u64; 3]> = mesh
            .positions
            .as_deref()
            .expect("positions")
            .iter()
            .map(|p| p.map(f64::to_bits))
            .collect();
        let want: Vec<[u64; 3]> = positions(&v).iter().map(|p| p.map(f64::to_bits)).collect();
        assert_eq!(mesh.vertex_count, want.len(), "{name}: vertex count");
        if let Some(k) = (0..want.len()).find(|&k| got[k] != want[k]) {
            panic!(
                "{name}: position {k} differs: {:?}, stored {:?}",
                got[k].map(f64::from_bits),
                want[k].map(f64::from_bits)
            );
        }
        assert_eq!(mesh.faces, faces(&v), "{name}: faces");
    }
}

/// `x` as an integer multiple of `2^-bits`, if it is one (and fits easily in an i128).
fn scaled(x: f64, bits: i32) -> Option<i128> {
    let y = x * 2f64.powi(bits);
    (y == y.trunc() && y.abs() < 2f64.powi(100)).then_some(y as i128)
}

/// Checks in integer arithmetic that `p` is exactly the interpolation of the edge from
/// inside `i` to outside `o` for a polynomial field (sphere or hyperboloid) on a dyadic
/// grid: with `S` the scale making the grid integral, `f` scaled by `2^(2S)` is an
/// integer, and `(p − p_i) · (f_o − f_i) = (level − f_i) · (p_o − p_i)` holds exactly on
/// every axis (so `t` was not rounded, not clamped, and neither was the point).
fn check_exact(g: &Grid, i: Lattice, o: Lattice, p: [f64; 3], label: &str) {
    let constant = match g.field {
        Field::Sphere { radius } => radius * radius,
        Field::Hyperboloid { c } => c,
        Field::Torus { .. } => panic!("{label}: the torus cannot be exact"),
    };
    // The smallest scale making the grid integral and the level and constant integral
    // at the squared scale.
    let s = (0..=16)
        .find(|&s| {
            (0..3).all(|a| scaled(g.min[a], s).is_some() && scaled(g.half(a), s).is_some())
                && scaled(g.level, 2 * s).is_some()
                && scaled(constant, 2 * s).is_some()
        })
        .unwrap_or_else(|| panic!("{label}: grid, level or constant not dyadic"));
    // Integer coordinates scaled by 2^s.
    let lat = |q: Lattice| -> [i128; 3] {
        [0, 1, 2].map(|a| {
            scaled(g.min[a], s).expect("dyadic")
                + i128::from(q[a]) * scaled(g.half(a), s).expect("dyadic")
        })
    };
    let k = scaled(constant, 2 * s).expect("dyadic");
    let f = |q: [i128; 3]| -> i128 {
        let [x, y, z] = q;
        match g.field {
            Field::Sphere { .. } => x * x + y * y + z * z - k,
            _ => x * x + y * y - z * z + k,
        }
    };
    let level = scaled(g.level, 2 * s).expect("dyadic");
    let (qi, qo) = (lat(i), lat(o));
    let (fi, fo) = (f(qi), f(qo));
    assert!(fi <= level && level < fo, "{label}: edge does not cross");
    let (num, den) = (level - fi, fo - fi);
    assert!(
        num > 0,
        "{label}: a sample at the level (t would be clamped)"
    );
    // The stored point scaled by 2^(s + extra).
    let extra = 40;
    for a in 0..3 {
        let pa = scaled(p[a], s + extra)
            .unwrap_or_else(|| panic!("{label}: coordinate {} is no short dyadic", p[a]));
        let lhs = (pa - (qi[a] << extra)) * den;
        let rhs = num * ((qo[a] - qi[a]) << extra);
        assert_eq!(lhs, rhs, "{label}: axis {a} is not the exact interpolation");
    }
}

#[test]
fn stored_iso_vectors_are_valid_independently() {
    let mut exact_vertices = 0;
    for v in all() {
        let name = v["name"].as_str().expect("name");
        let g = grid(&v);
        let pos = positions(&v);
        let fs = faces(&v);
        let edges = vertex_edges(&v);
        let n = v["vertex_count"].as_u64().expect("vertex_count") as usize;
        assert_eq!(
            (pos.len(), edges.len()),
            (n, n),
            "{name}: one entry per vertex"
        );
        // The README's premise: a grid step of a power of two on every axis, so sample
        // positions and the product of `t` with an edge's extent are exact.
        for a in 0..3 {
            let step = 2.0 * g.half(a);
            let m = step.log2().round();
            assert!(2f64.powf(m) == step, "{name}: step {step} on axis {a}");
        }
        // Topology, from the face list.
        let topo = surface_topology(&fs).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(topo.vertices, n, "{name}: an unused vertex");
        assert!(
            fs.iter().flatten().all(|&x| (x as usize) < n),
            "{name}: vertex out of range"
        );
        let mut expected: Vec<ComponentType> = v["expected_components"]
            .as_array()
            .expect("expected_components")
            .iter()
            .map(|c| ComponentType {
                euler: c["euler_characteristic"].as_i64().expect("χ"),
                orientable: c["orientable"].as_bool().expect("orientable"),
                boundary_loops: c["boundary_loops"].as_u64().expect("loops") as usize,
            })
            .collect();
        expected.sort_unstable();
        assert_eq!(topo.components, expected, "{name}: components");
        // Every vertex on its crossing edge, at the interpolated point.
        let exact = v["exact"].as_bool().expect("exact");
        for (k, (&(i, o), &p)) in edges.iter().zip(&pos).enumerate() {
            let label = format!("{name} vertex {k}");
            assert!(
                g.is_edge(i, o),
                "{label}: {i:?}–{o:?} is no tessellation edge"
            );
            assert!(
                g.inside(i) && !g.inside(o),
                "{label}: the edge does not cross the level"
            );
            let q = g.interpolate(i, o);
            assert!(
                q.map(f64::to_bits) == p.map(f64::to_bits),
                "{label}: stored {p:?}, interpolated {q:?}"
            );
            if exact {
                check_exact(&g, i, o, p, &label);
                exact_vertices += 1;
            }
        }
        // Exactly the crossing edges, each once.
        let stored: BTreeSet<(Lattice, Lattice)> = edges.iter().copied().collect();
        assert_eq!(stored.len(), n, "{name}: two vertices on one edge");
        assert!(
            stored == g.crossing_edges(),
            "{name}: not the crossing edges"
        );
        // Normals point from inside to outside.
        for (fi, f) in fs.iter().enumerate() {
            let [a, b, c] = f.map(|x| pos[x as usize]);
            let u = [0, 1, 2].map(|k| b[k] - a[k]);
            let w = [0, 1, 2].map(|k| c[k] - a[k]);
            let nrm = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            for &x in f {
                let (i, o) = edges[x as usize];
                let (pi, po) = (g.position(i), g.position(o));
                let d: f64 = (0..3).map(|k| nrm[k] * (po[k] - pi[k])).sum();
                assert!(d > 0.0, "{name} face {fi}: normal points inwards at {x}");
            }
        }
    }
    assert!(
        exact_vertices > 500,
        "{exact_vertices} vertices verified exact"
    );
}

/// The independent checks can fail: a moved vertex, a reversed face and an edge that is
/// not of the tessellation are each caught.
#[test]
fn the_iso_checks_reject_broken_vectors() {
    let v = common::read_vectors("iso-exact")
        .into_iter()
        .find(|v| v["name"] == "iso_sphere_block_six")
        .expect("vector");
    let g = grid(&v);
    let pos = positions(&v);
    let edges = vertex_edges(&v);
    let (i, o) = edges[0];
    // A point moved by one unit in the last place is not the interpolation.
    let mut p = pos[0];
    p[0] = f64::from_bits(p[0].to_bits() + 1);
    let moved = std::panic::catch_unwind(|| check_exact(&g, i, o, p, "moved"));
    assert!(moved.is_err(), "a moved vertex passed the exact check");
    assert!(g.interpolate(i, o).map(f64::to_bits) != p.map(f64::to_bits));
    // A face diagonal in the wrong direction, a diagonal of two cells: no edges.
    assert!(!g.is_edge([0, 2, 0], [2, 0, 0]));
    assert!(!g.is_edge([0, 0, 0], [4, 0, 0]));
    assert!(g.is_edge([0, 0, 0], [2, 2, 0]) && g.is_edge([2, 2, 2], [0, 0, 0]));
    // A reversed face fails the normal test somewhere.
    let fs = faces(&v);
    let [a, b, c] = fs[0].map(|x| pos[x as usize]);
    let u = [0, 1, 2].map(|k| c[k] - a[k]);
    let w = [0, 1, 2].map(|k| b[k] - a[k]);
    let nrm = [
        u[1] * w[2] - u[2] * w[1],
        u[2] * w[0] - u[0] * w[2],
        u[0] * w[1] - u[1] * w[0],
    ];
    let (i, o) = edges[fs[0][0] as usize];
    let (pi, po) = (g.position(i), g.position(o));
    let d: f64 = (0..3).map(|k| nrm[k] * (po[k] - pi[k])).sum();
    assert!(d < 0.0, "a reversed face passed the normal test");
}
