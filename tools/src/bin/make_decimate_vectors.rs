//! Regenerates the decimation conformance vectors `spec/vectors/decimate.jsonl`
//! (format: `spec/vectors/README.md`, section "Decimation vectors").
//!
//! `cargo run --release -p contractible-tools --bin make_decimate_vectors [OUT_DIR]`
//! (default `spec/vectors` of this checkout). Builds the small input meshes below (every
//! input coordinate a dyadic rational with few bits), runs `contractible::decimate` on
//! each with the eleven runs of `runs` below (every placement, both schedules, the guard on
//! and off, face and fraction targets, error caps, locks, no target), and writes each output with its maps
//! and statistics. `tests/algorithms/decimate_vectors.rs` checks that the library still
//! reproduces them exactly and that every stored output passes the independent checks
//! of `tests/algorithms/decimate.rs`.

use std::fmt::Write as _;
use std::path::PathBuf;

use contractible::decimate::{Placement, Refusals, Schedule, Stats, NO_VERTEX};
use contractible::gen::{self, isosurface, Implicit, IsoParams, Tessellation};
use contractible::rng::Rng;
use contractible::{DecimateOptions, MaxError, TriMesh};
use serde_json::{json, Value};

/// One input: name, source description, mesh.
struct Input {
    name: &'static str,
    source: &'static str,
    mesh: TriMesh,
}

/// `mesh` with every coordinate moved by a multiple of 1/8 in {−1/8, 0, 1/8}, from the
/// seeded stream (so that costs are not all tied).
fn jitter(mut mesh: TriMesh, seed: u64) -> TriMesh {
    let mut rng = Rng::new(seed);
    if let Some(p) = mesh.positions.as_mut() {
        for x in p.iter_mut().flatten() {
            *x += (rng.below(3) as f64 - 1.0) / 8.0;
        }
    }
    mesh
}

/// A `u × v` grid of quads split along alternating diagonals, on a square tube (`tube`:
/// both directions periodic, a torus) or a band (`v` a segment), with the `u` seam
/// reflecting `v` when `twisted` (a Klein bottle, a Möbius band). `u` and `v` multiples
/// of 4: every coordinate is a multiple of 1/8.
fn grid(u: u32, v: u32, tube: bool, twisted: bool) -> TriMesh {
    let rows = if tube { v } else { v + 1 };
    let square = |k: u32, side: u32| -> (f64, f64) {
        let (s, o) = (k / side % 4, f64::from(k % side) * 2.0 / f64::from(side));
        match s {
            0 => (-1.0 + o, -1.0),
            1 => (1.0, -1.0 + o),
            2 => (1.0 - o, 1.0),
            _ => (-1.0, 1.0 - o),
        }
    };
    let id = |i: u32, j: u32| -> u32 {
        let (i, j) = if i == u {
            (0, if twisted { (v - j) % rows } else { j })
        } else {
            (i, j)
        };
        i * rows + j % rows
    };
    let mut positions = Vec::new();
    for i in 0..u {
        let (sx, sy) = square(i, u / 4);
        for j in 0..rows {
            let (radial, z) = if tube {
                let (cx, cz) = square(j, v / 4);
                (cx / 2.0, cz / 2.0)
            } else {
                (0.0, f64::from(j) / f64::from(v) - 0.5)
            };
            positions.push([(2.0 + radial) * sx, (2.0 + radial) * sy, z]);
        }
    }
    let mut faces = Vec::new();
    for i in 0..u {
        for j in 0..v {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            if (i + j) % 2 == 0 {
                faces.push([a, b, c]);
                faces.push([a, c, d]);
            } else {
                faces.push([a, b, d]);
                faces.push([b, c, d]);
            }
        }
    }
    TriMesh::with_positions(positions, faces)
}

/// An `n × n` square disc over `[-1, 1]²`, flat (`tent` 0) or with a tent of height
/// `tent` in `z`.
fn disc(n: u32, tent: f64) -> TriMesh {
    let step = 2.0 / f64::from(n);
    let mut positions = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (-1.0 + f64::from(i) * step, -1.0 + f64::from(j) * step);
            positions.push([x, y, tent * (1.0 - x.abs().max(y.abs()))]);
        }
    }
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut faces = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            faces.push([a, b, c]);
            faces.push([a, c, d]);
        }
    }
    TriMesh::with_positions(positions, faces)
}

/// Two meshes side by side, `b` moved by `shift`.
fn union(a: &TriMesh, b: &TriMesh, shift: [f64; 3]) -> TriMesh {
    let mut positions = a.positions.clone().expect("positions");
    let base = positions.len() as u32;
    positions.extend(
        b.positions
            .as_deref()
            .expect("positions")
            .iter()
            .map(|p| [0, 1, 2].map(|k| p[k] + shift[k])),
    );
    let mut faces = a.faces.clone();
    faces.extend(b.faces.iter().map(|f| f.map(|v| v + base)));
    TriMesh::with_positions(positions, faces)
}

/// Dyadic pseudo-random positions (multiples of 1/4 in `[0, 4)³`) for a combinatorial
/// mesh.
fn positioned(mesh: &TriMesh, seed: u64) -> TriMesh {
    let mut rng = Rng::new(seed);
    let positions = (0..mesh.vertex_count)
        .map(|_| [0; 3].map(|_: i32| rng.below(16) as f64 / 4.0))
        .collect();
    TriMesh::with_positions(positions, mesh.faces.clone())
}

fn inputs() -> Vec<Input> {
    let octahedron = {
        let mut m = gen::octahedron();
        for x in m
            .positions
            .as_mut()
            .expect("positions")
            .iter_mut()
            .flatten()
        {
            *x *= 2.0;
        }
        m
    };
    let rp2 = {
        let p = gen::projective_plane6();
        let positions = vec![
            [2.0, 0.0, 0.0],
            [0.0, 2.0, 0.0],
            [0.0, 0.0, 2.0],
            [-2.0, 0.0, 1.0],
            [1.0, -2.0, 0.0],
            [0.0, 1.0, -2.0],
        ];
        gen::subdivide(&TriMesh::with_positions(positions, p.faces), 1).expect("subdivide")
    };
    let iso_sphere = isosurface(&IsoParams {
        implicit: Implicit::Sphere { radius: 1.0 },
        tessellation: Tessellation::SixTetrahedra,
        cells: [4; 3],
        min: [-1.5; 3],
        max: [2.5; 3],
        level: 1.25,
    })
    .expect("isosurface");
    vec![
        Input {
            name: "decimate_tetrahedron",
            source: "gen::tetrahedron (irreducible: nothing may collapse)",
            mesh: gen::tetrahedron(),
        },
        Input {
            name: "decimate_octahedron_subdivided",
            source: "gen::octahedron scaled by 2, gen::subdivide 1 level, jitter seed 1",
            mesh: jitter(gen::subdivide(&octahedron, 1).expect("subdivide"), 1),
        },
        Input {
            name: "decimate_isosurface_sphere",
            source: "iso_sphere_block_six of iso-exact.jsonl (every coordinate exact)",
            mesh: iso_sphere,
        },
        Input {
            name: "decimate_torus_grid",
            source: "8 × 4 torus grid, jitter seed 2",
            mesh: jitter(grid(8, 4, true, false), 2),
        },
        Input {
            name: "decimate_klein_bottle_grid",
            source: "8 × 4 Klein bottle grid (seam reflected), jitter seed 3",
            mesh: jitter(grid(8, 4, true, true), 3),
        },
        Input {
            name: "decimate_projective_plane_subdivided",
            source: "gen::projective_plane6 with 6 dyadic positions, gen::subdivide 1 level",
            mesh: rp2,
        },
        Input {
            name: "decimate_torus7_positioned",
            source: "gen::torus7's faces at seeded dyadic positions (seed 4): irreducible",
            mesh: positioned(&gen::torus7(), 4),
        },
        Input {
            name: "decimate_flat_disc",
            source: "a flat 4 × 4 square disc over [-1, 1]²",
            mesh: disc(4, 0.0),
        },
        Input {
            name: "decimate_mobius_band_grid",
            source: "8 × 2 Möbius band grid (seam reflected), jitter seed 5",
            mesh: jitter(grid(8, 2, false, true), 5),
        },
        Input {
            name: "decimate_disc_and_sphere",
            source: "a 4 × 4 tent disc (height 1/2), then gen::octahedron subdivided once, moved by (2.5, 0, 0), jitter seed 6",
            mesh: jitter(
                union(
                    &disc(4, 0.5),
                    &gen::subdivide(&gen::octahedron(), 1).expect("subdivide"),
                    [2.5, 0.0, 0.0],
                ),
                6,
            ),
        },
    ]
}

/// The options of every run, in order (the README's table).
fn runs(faces: usize, vertices: usize) -> Vec<DecimateOptions> {
    let base = DecimateOptions::default;
    vec![
        DecimateOptions {
            keep: Some(0.5),
            ..base()
        },
        DecimateOptions {
            faces: Some(faces / 4),
            placement: Placement::Midpoint,
            ..base()
        },
        DecimateOptions {
            faces: Some(faces / 4),
            placement: Placement::Endpoint,
            allow_foldover: true,
            ..base()
        },
        DecimateOptions {
            allow_foldover: true,
            ..base()
        },
        DecimateOptions {
            placement: Placement::Midpoint,
            max_error: Some(MaxError::Relative(0.0625)),
            ..base()
        },
        DecimateOptions {
            placement: Placement::Endpoint,
            keep: Some(0.25),
            max_error: Some(MaxError::Absolute(0.25)),
            lock_boundary: true,
            ..base()
        },
        DecimateOptions {
            faces: Some(faces / 3),
            locked: (0..vertices as u32).step_by(5).collect(),
            ..base()
        },
        DecimateOptions {
            placement: Placement::Midpoint,
            ..base()
        },
        DecimateOptions {
            faces: Some(faces / 4),
            schedule: Schedule::Passes,
            ..base()
        },
        DecimateOptions {
            schedule: Schedule::Passes,
            ..base()
        },
        DecimateOptions {
            placement: Placement::Endpoint,
            schedule: Schedule::Passes,
            max_error: Some(MaxError::Relative(0.0625)),
            lock_boundary: true,
            locked: (0..vertices as u32).step_by(7).collect(),
            ..base()
        },
    ]
}

fn options_json(o: &DecimateOptions) -> Value {
    json!({
        "faces": o.faces,
        "keep": o.keep,
        "max_error": match o.max_error {
            None => Value::Null,
            Some(MaxError::Absolute(e)) => json!({"absolute": e}),
            Some(MaxError::Relative(r)) => json!({"relative": r}),
        },
        "placement": o.placement.name(),
        "schedule": o.schedule.name(),
        "allow_foldover": o.allow_foldover,
        "lock_boundary": o.lock_boundary,
        "locked": o.locked,
    })
}

fn refusals_json(r: &Refusals) -> Value {
    json!({
        "lock": r.lock,
        "boundary": r.boundary,
        "error": r.error,
        "link_condition": r.link_condition,
        "foldover": r.foldover,
    })
}

fn stats_json(s: &Stats) -> Value {
    json!({
        "faces_in": s.faces_in,
        "faces_out": s.faces_out,
        "vertices_in": s.vertices_in,
        "vertices_out": s.vertices_out,
        "components": s.components,
        "boundary_loops": s.boundary_loops,
        "target_faces": s.target_faces,
        "max_error_cap": s.max_error_cap,
        "stopped": s.stopped.name(),
        "collapses": s.collapses,
        "passes": s.passes,
        "max_error": s.max_error,
        "remaining": refusals_json(&s.remaining),
        "component_list": s.component_list.iter().map(|c| json!({
            "faces_in": c.faces_in,
            "faces_out": c.faces_out,
            "vertices_in": c.vertices_in,
            "vertices_out": c.vertices_out,
            "boundary_loops": c.boundary_loops,
            "remaining": refusals_json(&c.remaining),
        })).collect::<Vec<_>>(),
    })
}

fn run_json(input: &Input, o: &DecimateOptions) -> Value {
    let r =
        contractible::decimate(&input.mesh, o).unwrap_or_else(|e| panic!("{}: {e}", input.name));
    assert!(r.verified, "{}", input.name);
    json!({
        "options": options_json(o),
        "output_positions": r.mesh.positions.as_deref().expect("positions"),
        "output_faces": r.mesh.faces,
        "vertex_map": r.vertex_map,
        "collapse_map": r.collapse_map.iter().map(|&c| (c != NO_VERTEX).then_some(c)).collect::<Vec<_>>(),
        "face_origin": r.face_origin,
        "stopped": r.stats.stopped.name(),
        "faces_out": r.mesh.faces.len(),
        "stats": stats_json(&r.stats),
    })
}

fn components_json(mesh: &TriMesh) -> Value {
    let c = contractible_tools::component_topology(mesh).expect("a surface");
    json!(c
        .iter()
        .map(|&(e, o, l)| json!({"euler_characteristic": e, "orientable": o, "boundary_loops": l}))
        .collect::<Vec<_>>())
}

fn vector(input: &Input) -> Value {
    let positions = input.mesh.positions.as_deref().expect("positions");
    assert!(
        positions
            .iter()
            .flatten()
            .all(|&x| (x * 1024.0).fract() == 0.0 && x.abs() < 16.0),
        "{}: dyadic input coordinates",
        input.name
    );
    let runs: Vec<Value> = runs(input.mesh.faces.len(), input.mesh.vertex_count)
        .iter()
        .map(|o| run_json(input, o))
        .collect();
    json!({
        "name": input.name,
        "group": "decimate",
        "source": {"mesh": input.source},
        "vertex_count": input.mesh.vertex_count,
        "positions": positions,
        "faces": input.mesh.faces,
        "components": components_json(&input.mesh),
        "runs": runs,
    })
}

fn main() {
    let root = contractible_tools::repo_root();
    let out_dir = std::env::args()
        .nth(1)
        .map_or_else(|| root.join("spec/vectors"), PathBuf::from);
    std::fs::create_dir_all(&out_dir).expect("create output directory");
    let mut text = String::new();
    let all = inputs();
    for input in &all {
        writeln!(
            text,
            "{}",
            serde_json::to_string(&vector(input)).expect("json")
        )
        .expect("write");
    }
    let path = out_dir.join("decimate.jsonl");
    std::fs::write(&path, &text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    println!(
        "{}: {} vectors, {} bytes",
        path.display(),
        all.len(),
        text.len()
    );
}
