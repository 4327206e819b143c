//! Regenerates the marching-tetrahedra conformance vectors `spec/vectors/iso-*.jsonl`
//! (format: `spec/vectors/README.md`, section "Marching-tetrahedra vectors").
//!
//! `cargo run --release -p contractible-tools --bin make_iso_vectors [OUT_DIR]` (default
//! `spec/vectors` of this checkout). Runs `gen::isosurface` on the fixed parameter sets
//! below, both tessellations, and writes the output meshes with, per output vertex, the
//! grid edge it lies on (found here by matching every crossing edge's interpolated
//! position; each vertex must match exactly one). Checks each output's components
//! against the topology stated for its parameters. `tests/algorithms/iso_vectors.rs`
//! checks that the library still reproduces them and, independently, that they are
//! what the parameters say.
//!
//! Two groups: `iso-exact` (sphere and two-sheeted hyperboloid on small dyadic grids
//! whose every interpolation parameter is a dyadic rational, found by a search over the
//! level and the box offset: every stored coordinate is the exact real value of the
//! interpolation) and `iso-rounded` (a larger sphere, the torus and the one-sheeted
//! hyperboloid: the stored coordinates are the binary64 results of the documented
//! operation order; the torus needs a square root, so no grid makes it exact).

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::PathBuf;

use contractible::gen::{isosurface, Implicit, IsoParams, Tessellation, CLAMP};
use serde_json::{json, Value};

/// A topological type (χ, orientable, boundary loops) of one component.
type Component = (i64, bool, usize);

/// One parameter set: name, implicit, tessellation, cells, box, level, whether every
/// interpolation is exact, and the components the output must have (sorted).
struct Case {
    name: &'static str,
    implicit: Implicit,
    tessellation: Tessellation,
    cells: [u32; 3],
    min: [f64; 3],
    max: [f64; 3],
    level: f64,
    exact: bool,
    components: Vec<Component>,
}

const SIX: Tessellation = Tessellation::SixTetrahedra;
const BCC: Tessellation = Tessellation::BodyCentred;
const UNIT_SPHERE: Implicit = Implicit::Sphere { radius: 1.0 };
/// `x² + y² − z² + 1/4`; `half_width` and `half_height` only set the default box, which
/// the vectors do not use.
const HYPERBOLOID: Implicit = Implicit::TwoSheetHyperboloid {
    c: 0.25,
    half_width: 1.0,
    half_height: 1.0,
};

fn sphere() -> Component {
    (2, true, 0)
}

fn disc() -> Component {
    (1, true, 1)
}

fn cases() -> Vec<Case> {
    let cube = |lo: f64, hi: f64| ([lo; 3], [hi; 3]);
    let case = |name,
                implicit,
                tessellation,
                n: u32,
                (min, max): ([f64; 3], [f64; 3]),
                level,
                exact,
                components| Case {
        name,
        implicit,
        tessellation,
        cells: [n; 3],
        min,
        max,
        level,
        exact,
        components,
    };
    vec![
        // One sample inside (the origin): the smallest closed output.
        case(
            "iso_sphere_one_sample_six",
            UNIT_SPHERE,
            SIX,
            2,
            cube(-1.0, 1.0),
            -0.90625,
            true,
            vec![sphere()],
        ),
        case(
            "iso_sphere_one_sample_bcc",
            UNIT_SPHERE,
            BCC,
            2,
            cube(-1.0, 1.0),
            -0.953125,
            true,
            vec![sphere()],
        ),
        // A 2 × 2 × 2 block of samples inside.
        case(
            "iso_sphere_block_six",
            UNIT_SPHERE,
            SIX,
            4,
            cube(-1.5, 2.5),
            1.25,
            true,
            vec![sphere()],
        ),
        Case {
            name: "iso_sphere_closed_bcc",
            implicit: UNIT_SPHERE,
            tessellation: BCC,
            cells: [4; 3],
            min: [-2.0, -1.75, -1.5],
            max: [2.0, 2.25, 2.5],
            level: 0.203125,
            exact: true,
            components: vec![sphere()],
        },
        // The sphere pokes out of the box through its six faces: a sphere with six holes.
        case(
            "iso_sphere_six_holes_six",
            UNIT_SPHERE,
            SIX,
            2,
            cube(-1.0, 1.0),
            0.078125,
            true,
            vec![(-4, true, 6)],
        ),
        case(
            "iso_sphere_six_holes_bcc",
            UNIT_SPHERE,
            BCC,
            2,
            cube(-1.0, 1.0),
            0.453125,
            true,
            vec![(-4, true, 6)],
        ),
        // The box's eight corners stick out of the ball: eight discs.
        case(
            "iso_sphere_eight_discs_six",
            UNIT_SPHERE,
            SIX,
            4,
            cube(-2.0, 2.0),
            7.34375,
            true,
            vec![disc(); 8],
        ),
        case(
            "iso_sphere_eight_discs_bcc",
            UNIT_SPHERE,
            BCC,
            2,
            cube(-1.0, 1.0),
            1.4375,
            true,
            vec![disc(); 8],
        ),
        // x² + y² − z² = level − 1/4 < 0: two sheets; the box keeps one or both.
        case(
            "iso_hyperboloid_one_sheet_in_box_six",
            HYPERBOLOID,
            SIX,
            4,
            cube(-1.5, 2.5),
            -4.75,
            true,
            vec![disc()],
        ),
        case(
            "iso_hyperboloid_two_sheets_six",
            HYPERBOLOID,
            SIX,
            4,
            cube(-2.0, 2.0),
            -3.28125,
            true,
            vec![disc(); 2],
        ),
        case(
            "iso_hyperboloid_two_sheets_bcc",
            HYPERBOLOID,
            BCC,
            4,
            cube(-2.0, 2.0),
            -3.46875,
            true,
            vec![disc(); 2],
        ),
        // The rounded group: grids of step 1/2 (exact sample positions, and an exact
        // product of the interpolation parameter with an edge's extent), level 0 or a
        // dyadic one.
        case(
            "iso_sphere_six",
            UNIT_SPHERE,
            SIX,
            6,
            cube(-1.5, 1.5),
            0.0,
            false,
            vec![sphere()],
        ),
        case(
            "iso_sphere_bcc",
            UNIT_SPHERE,
            BCC,
            6,
            cube(-1.5, 1.5),
            0.0,
            false,
            vec![sphere()],
        ),
        Case {
            name: "iso_torus_six",
            implicit: Implicit::Torus {
                major: 1.0,
                minor: 0.5,
            },
            tessellation: SIX,
            cells: [8, 8, 4],
            min: [-2.0, -2.0, -1.0],
            max: [2.0, 2.0, 1.0],
            level: 0.0,
            exact: false,
            components: vec![(0, true, 0)],
        },
        Case {
            name: "iso_torus_bcc",
            implicit: Implicit::Torus {
                major: 1.0,
                minor: 0.5,
            },
            tessellation: BCC,
            cells: [8, 8, 4],
            min: [-2.0, -2.0, -1.0],
            max: [2.0, 2.0, 1.0],
            level: 0.0,
            exact: false,
            components: vec![(0, true, 0)],
        },
        // x² + y² − z² = 1/2: one sheet, cut by the box's top and bottom: an annulus.
        Case {
            name: "iso_hyperboloid_annulus_six",
            implicit: HYPERBOLOID,
            tessellation: SIX,
            cells: [8, 8, 4],
            min: [-2.0, -2.0, -1.0],
            max: [2.0, 2.0, 1.0],
            level: 0.75,
            exact: false,
            components: vec![(0, true, 2)],
        },
    ]
}

/// A sample point in doubled lattice coordinates (corners even, cube centres odd).
type Lattice = [u32; 3];

/// Whether `p` is a sample of `tess` on the doubled grid of extents `ext`.
fn is_sample(tess: Tessellation, ext: [u32; 3], p: Lattice) -> bool {
    let odd = p.iter().filter(|&&c| c % 2 == 1).count();
    match (tess, odd) {
        (_, 0) => true,
        (Tessellation::BodyCentred, 3) => true,
        (Tessellation::BodyCentred, 2) => {
            (0..3).any(|a| p[a] % 2 == 0 && (p[a] == 0 || p[a] == ext[a]))
        }
        _ => false,
    }
}

/// Every edge of the tessellation, each once, as a pair of samples.
fn tessellation_edges(tess: Tessellation, ext: [u32; 3]) -> Vec<(Lattice, Lattice)> {
    let mut out = Vec::new();
    let add = |a: Lattice, d: [i64; 3], out: &mut Vec<(Lattice, Lattice)>| {
        let b = [0, 1, 2].map(|k| i64::from(a[k]) + d[k]);
        if (0..3).all(|k| b[k] >= 0 && b[k] <= i64::from(ext[k])) {
            let b = b.map(|x| x as u32);
            if is_sample(tess, ext, b) {
                out.push((a, b));
            }
        }
    };
    for z in 0..=ext[2] {
        for y in 0..=ext[1] {
            for x in 0..=ext[0] {
                let a = [x, y, z];
                if !is_sample(tess, ext, a) {
                    continue;
                }
                let odd = a.iter().filter(|&&c| c % 2 == 1).count();
                match (tess, odd) {
                    (Tessellation::SixTetrahedra, _) => {
                        for m in 1..8u32 {
                            let d = [0, 1, 2].map(|k| 2 * i64::from((m >> k) & 1));
                            add(a, d, &mut out);
                        }
                    }
                    (Tessellation::BodyCentred, 0 | 3) => {
                        // Along the axes to the same kind (cube edges, centre to centre).
                        for k in 0..3 {
                            let mut d = [0; 3];
                            d[k] = 2;
                            add(a, d, &mut out);
                        }
                        // A corner to the centres of its cubes.
                        if odd == 0 {
                            for m in 0..8u32 {
                                let d = [0, 1, 2].map(|k| if (m >> k) & 1 == 1 { 1 } else { -1 });
                                add(a, d, &mut out);
                            }
                        }
                    }
                    (Tessellation::BodyCentred, _) => {
                        // A box-face centre to its four corners and its cube's centre.
                        let k = (0..3).find(|&k| a[k] % 2 == 0).unwrap_or(0);
                        for m in 0..4u32 {
                            let mut d = [0; 3];
                            d[(k + 1) % 3] = if m & 1 == 1 { 1 } else { -1 };
                            d[(k + 2) % 3] = if m & 2 == 2 { 1 } else { -1 };
                            add(a, d, &mut out);
                        }
                        let mut d = [0; 3];
                        d[k] = if a[k] == 0 { 1 } else { -1 };
                        add(a, d, &mut out);
                    }
                }
            }
        }
    }
    out
}

fn params(c: &Case) -> IsoParams {
    IsoParams {
        implicit: c.implicit,
        tessellation: c.tessellation,
        cells: c.cells,
        min: c.min,
        max: c.max,
        level: c.level,
    }
}

/// The grid edge (inside sample, outside sample) of every output vertex: the crossing
/// edges' interpolated positions (as `gen::isosurface` documents them) matched with the
/// output positions, bit for bit; every vertex must match exactly one edge, every
/// crossing edge one vertex.
fn vertex_edges(c: &Case, positions: &[[f64; 3]]) -> Vec<(Lattice, Lattice)> {
    let ext = c.cells.map(|n| 2 * n);
    let half: [f64; 3] = [0, 1, 2].map(|a| (c.max[a] - c.min[a]) / f64::from(ext[a]));
    let pos = |p: Lattice| [0, 1, 2].map(|a| c.min[a] + f64::from(p[a]) * half[a]);
    let mut at: HashMap<[u64; 3], (Lattice, Lattice)> = HashMap::new();
    for (a, b) in tessellation_edges(c.tessellation, ext) {
        let (fa, fb) = (c.implicit.eval(pos(a)), c.implicit.eval(pos(b)));
        let (i, o, fi, fo) = match (fa <= c.level, fb <= c.level) {
            (true, false) => (a, b, fa, fb),
            (false, true) => (b, a, fb, fa),
            _ => continue,
        };
        let t = ((c.level - fi) / (fo - fi)).clamp(CLAMP, 1.0 - CLAMP);
        let (pi, po) = (pos(i), pos(o));
        let p = [0, 1, 2].map(|k| pi[k] + t * (po[k] - pi[k]));
        let old = at.insert(p.map(f64::to_bits), (i, o));
        assert!(old.is_none(), "{}: two crossing edges at {p:?}", c.name);
    }
    assert_eq!(
        at.len(),
        positions.len(),
        "{}: crossing edges and vertices",
        c.name
    );
    positions
        .iter()
        .map(|p| {
            *at.get(&p.map(f64::to_bits))
                .unwrap_or_else(|| panic!("{}: vertex {p:?} on no crossing edge", c.name))
        })
        .collect()
}

/// Whether every coordinate is a dyadic rational with at most 30 bits after the point
/// and below 2^20 in magnitude (a cheap filter; the test checks exactness rationally).
fn looks_exact(positions: &[[f64; 3]]) -> bool {
    positions.iter().flatten().all(|&x| {
        let y = x * f64::from(1u32 << 30);
        y == y.trunc() && x.abs() < f64::from(1u32 << 20)
    })
}

fn implicit_json(i: &Implicit) -> Value {
    match *i {
        Implicit::Sphere { radius } => json!({ "kind": "sphere", "radius": radius }),
        Implicit::Torus { major, minor } => {
            json!({ "kind": "torus", "major": major, "minor": minor })
        }
        Implicit::GenusG { g } => json!({ "kind": "genus", "g": g }),
        Implicit::TwoSheetHyperboloid {
            c,
            half_width,
            half_height,
        } => json!({
            "kind": "two_sheet_hyperboloid",
            "c": c,
            "half_width": half_width,
            "half_height": half_height,
        }),
    }
}

fn vector(c: &Case, group: &str) -> Value {
    let mesh = isosurface(&params(c)).unwrap_or_else(|e| panic!("{}: {e}", c.name));
    let positions = mesh.positions.clone().expect("isosurface positions");
    let components = contractible_tools::component_topology(&mesh)
        .unwrap_or_else(|| panic!("{}: not a union of surfaces", c.name));
    let mut expected = c.components.clone();
    expected.sort_unstable();
    assert_eq!(components, expected, "{}: topology", c.name);
    assert_eq!(
        looks_exact(&positions),
        c.exact,
        "{}: exactness of the coordinates",
        c.name
    );
    let edges = vertex_edges(c, &positions);
    json!({
        "name": c.name,
        "group": group,
        "params": {
            "implicit": implicit_json(&c.implicit),
            "tessellation": match c.tessellation {
                Tessellation::SixTetrahedra => "six",
                Tessellation::BodyCentred => "bcc",
            },
            "cells": c.cells,
            "min": c.min,
            "max": c.max,
            "level": c.level,
        },
        "exact": c.exact,
        "expected_components": expected
            .iter()
            .map(|&(euler, orientable, loops)| json!({
                "euler_characteristic": euler,
                "orientable": orientable,
                "boundary_loops": loops,
            }))
            .collect::<Vec<_>>(),
        "vertex_count": mesh.vertex_count,
        "positions": positions,
        "faces": mesh.faces,
        "vertex_edges": edges.iter().map(|&(i, o)| [i, o]).collect::<Vec<_>>(),
    })
}

fn main() {
    let root = contractible_tools::repo_root();
    let out_dir = std::env::args()
        .nth(1)
        .map_or_else(|| root.join("spec/vectors"), PathBuf::from);
    std::fs::create_dir_all(&out_dir).expect("create output directory");
    let all = cases();
    for (group, exact) in [("iso-exact", true), ("iso-rounded", false)] {
        let mut text = String::new();
        let mut n = 0;
        for c in all.iter().filter(|c| c.exact == exact) {
            let v = vector(c, group);
            writeln!(text, "{}", serde_json::to_string(&v).expect("json")).expect("write");
            n += 1;
        }
        let path = out_dir.join(format!("{group}.jsonl"));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        println!("{}: {n} vectors", path.display());
    }
}
