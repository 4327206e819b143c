//! Regenerates the simplification conformance vectors `spec/vectors/simplify-*.jsonl`
//! (format: `spec/vectors/README.md`, section "Simplification vectors").
//!
//! `cargo run --release -p contractible-tools --bin make_simplify_vectors [OUT_DIR]`
//! (default `spec/vectors` of this checkout). Builds the input meshes below (every
//! coordinate a dyadic rational with few bits), runs `simplify::simplify_with` on each
//! with both modes at three ε, and at the middle ε also without the guard and with the
//! two other side heuristics, always with the midpoint placement, and writes the outputs
//! with the per-pass reports and the statistics. Every run is checked to satisfy the
//! exactness bound of the README (so that every length comparison, midpoint and guard
//! decision is exact in binary64). `tests/algorithms/simplify_vectors.rs` checks that the
//! library still reproduces them and, independently, what every output must satisfy.

use std::fmt::Write as _;
use std::path::PathBuf;

use contractible::gen::{self, isosurface, Implicit, IsoParams, Tessellation};
use contractible::rng::Rng;
use contractible::simplify::{self, Mode, Options, PassReport, Position, Side};
use contractible::{ConedSurfaces, TriMesh};
use serde_json::{json, Value};

/// One input: name, source description, mesh, and its three ε (increasing).
struct Input {
    name: &'static str,
    source: Value,
    mesh: TriMesh,
    eps: [f64; 3],
}

/// `positions` moved by a multiple of 1/8 in {−1/8, 0, 1/8} per coordinate, from the
/// seeded stream (so that edge lengths are not all tied).
fn jitter(mut mesh: TriMesh, seed: u64) -> TriMesh {
    let mut rng = Rng::new(seed);
    if let Some(p) = mesh.positions.as_mut() {
        for x in p.iter_mut().flatten() {
            *x += (rng.below(3) as f64 - 1.0) / 8.0;
        }
    }
    mesh
}

fn scaled(mut mesh: TriMesh, factor: f64) -> TriMesh {
    if let Some(p) = mesh.positions.as_mut() {
        for x in p.iter_mut().flatten() {
            *x *= factor;
        }
    }
    mesh
}

/// The point `k` of `4·side` points around the square `[-1, 1]²` (counter-clockwise from
/// `(-1, -1)`, `side` points per side): dyadic when `side` is a power of two.
fn square(k: u32, side: u32) -> (f64, f64) {
    let (s, o) = (k / side % 4, f64::from(k % side) * 2.0 / f64::from(side));
    match s {
        0 => (-1.0 + o, -1.0),
        1 => (1.0, -1.0 + o),
        2 => (1.0 - o, 1.0),
        _ => (-1.0, 1.0 - o),
    }
}

/// How the grid's rows and columns are glued.
#[derive(Clone, Copy, PartialEq)]
enum Glue {
    /// Both directions periodic: a torus.
    Torus,
    /// Both periodic, the `u` seam reflecting `v`: a Klein bottle.
    Klein,
    /// `u` periodic, `v` a segment: an annulus.
    Annulus,
    /// `u` periodic reflecting `v`, `v` a segment: a Möbius band.
    Mobius,
}

/// A `u × v` grid of quads, each split along a diagonal that alternates with the parity
/// of the cell, glued as `glue` says. Positions: `u` goes around the square of
/// half-width 2 (`u/4` points per side), `v` around a square cross-section of
/// half-width 1/2 (`v/4` points per side) for the closed glues, or along a vertical
/// segment `z ∈ [−1/2, 1/2]` for the bands.
fn grid(u: u32, v: u32, glue: Glue) -> TriMesh {
    let closed_v = matches!(glue, Glue::Torus | Glue::Klein);
    let twisted = matches!(glue, Glue::Klein | Glue::Mobius);
    let rows = if closed_v { v } else { v + 1 };
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
            let (radial, z) = if closed_v {
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

/// `mesh` without the faces at the given vertices, unused vertices dropped.
fn without_stars(mesh: &TriMesh, centres: &[u32]) -> TriMesh {
    let faces: Vec<[u32; 3]> = mesh
        .faces
        .iter()
        .filter(|f| !f.iter().any(|v| centres.contains(v)))
        .copied()
        .collect();
    let holed = TriMesh::with_positions(mesh.positions.clone().expect("positions"), faces);
    holed.compacted().map_or(holed, |(m, _)| m)
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

/// A square disc: an `n × n` grid over `[-1, 1]²` with a tent of height 1/2 in `z`.
fn disc(n: u32) -> TriMesh {
    let step = 2.0 / f64::from(n);
    let mut positions = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (-1.0 + f64::from(i) * step, -1.0 + f64::from(j) * step);
            positions.push([x, y, 0.5 * (1.0 - x.abs().max(y.abs()))]);
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

fn iso(
    implicit: Implicit,
    tessellation: Tessellation,
    n: u32,
    lo: f64,
    hi: f64,
    level: f64,
) -> TriMesh {
    isosurface(&IsoParams {
        implicit,
        tessellation,
        cells: [n; 3],
        min: [lo; 3],
        max: [hi; 3],
        level,
    })
    .expect("isosurface")
}

/// The octahedron (±x = 0, 1; ±y = 2, 3; ±z = 4, 5) with vertex 2 moved to 1/16 from
/// vertex 0 and face [0, 2, 4] replaced by a disc of five faces around vertices 6 and 7
/// inside the 3-cycle 0 2 4: the short edge [0, 2] fails the link condition (common
/// neighbours 4, 5, 6, 7), and only the nested mode, by removing the disc, contracts it.
fn octahedron_with_a_disc() -> TriMesh {
    let positions = vec![
        [1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0],
        [1.0, 0.0625, 0.0],
        [0.0, -1.0, 0.0],
        [0.0, 0.0, 1.0],
        [0.0, 0.0, -1.0],
        [1.25, 0.5, 0.75],
        [1.625, 0.25, 0.25],
    ];
    let faces = vec![
        [2, 4, 6],
        [4, 0, 6],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
        [0, 2, 7],
        [2, 6, 7],
        [6, 0, 7],
    ];
    TriMesh::with_positions(positions, faces)
}

/// A torus of 8 rings of 3 vertices around the square of half-width 1, each ring a
/// triangle around the tube (a 3-cycle that does not separate); ring 3 has radius 1/64,
/// the others 1/4. Its three short edges fail the link condition, and the nested mode
/// refuses them as non-discs.
fn thin_handle_torus() -> TriMesh {
    let rings = 8;
    let id = |i: u32, j: u32| 3 * (i % rings) + j % 3;
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for i in 0..rings {
        let (cx, cy) = square(i, 2);
        let r = if i == 3 { 1.0 / 64.0 } else { 0.25 };
        for (j, (radial, z)) in [(1.0, 0.0), (-0.5, 1.0), (-0.5, -1.0)]
            .into_iter()
            .enumerate()
        {
            let k = 1.0 + r * radial;
            positions.push([k * cx, k * cy, r * z]);
            let j = j as u32;
            faces.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            faces.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    TriMesh::with_positions(positions, faces)
}

/// Two 7-vertex tori glued along a triangle (`gen::seed_surface`, genus 2), vertices at
/// seeded positions on the grid of step 1/4 in `[0, 4)³`, one edge of the glued 3-cycle
/// made 1/32 long: that 3-cycle separates two punctured tori, so the nested mode
/// refuses the edge as a non-disc on both sides.
fn genus_on_both_sides() -> TriMesh {
    let tri = gen::seed_surface(gen::SurfaceKind::Orientable(2)).expect("seed surface");
    let faces = tri.face_list();
    let mut rng = Rng::new(8);
    let mut positions: Vec<[f64; 3]> = (0..tri.vertex_capacity())
        .map(|_| [0; 3].map(|_: i32| rng.below(16) as f64 / 4.0))
        .collect();
    let glued = *gen::torus7().faces.last().expect("a face");
    let (p, q) = (glued[0] as usize, glued[1] as usize);
    positions[q] = [
        positions[p][0] + 1.0 / 32.0,
        positions[p][1],
        positions[p][2],
    ];
    TriMesh::with_positions(positions, faces)
}

/// The suspension of a path with its lower faces subdivided: `p` = 0 at `(0, 0, −1/8)`
/// and `q` = 1 at `(0, 0, 1/8)` (the edge `[p, q]`, 1/4 long), both joined to every
/// vertex of the path `w_0 … w_14` (vertices 2 … 16) at the points 1 … 15 of [`square`]
/// with four per side (1/2 apart), except, with `far`, `w_0`, moved from `(−1/2, −1)`
/// to `(−1/2, −4)`; faces `[p, q, w_0]`, `[p, w_14, q]`, `[q, w_t+1, w_t]`, and
/// `[p, w_t, w_t+1]` split at a vertex `c_t` (vertex 17 + t, at half the midpoint of
/// `w_t w_t+1`, `z = −1/16`) into `[p, w_t, c_t]`, `[p, c_t, w_t+1]`,
/// `[c_t, w_t, w_t+1]` (with `far`, `c_0` at `(−1/4, −2, −1/16)`). `w_0` and `w_14` are
/// the opposite vertices of `[p, q]`, and each of `w_1 … w_13` closes a separating
/// 3-cycle with it: 13 nested cycles, each slab between two of them a disc of four
/// faces around its `c_t`. Only `[p, q]` is shorter than 1/2, so the nested mode
/// contracts it after removing the discs the side heuristic assigns; the slab where the
/// two sides meet stays, and its `c_t` tells where that was. `count` grows the sides in
/// lockstep, and they reach the middle cycle `w_7` with regions of the same size (the
/// tie rule decides); `path` splits by hops (the middle), `euclidean` by distance (with
/// `far`, every cycle to `w_14`'s side; without, the path is symmetric about the line
/// through `w_7` = (1, 1), so `w_1 … w_6` go to `w_0`'s side, `w_8 … w_13` to `w_14`'s
/// and `w_7`, as near one end as the other, to `w_0`'s by the tie rule). With `hole`,
/// the face `[q, w_10, w_9]` is removed: a boundary loop in the slab between the cycles
/// through `w_9` and `w_10`, which neither side may remove.
fn suspension(far: bool, hole: bool) -> TriMesh {
    let m = 14u32;
    let w = |t: u32| 2 + t;
    let c = |t: u32| 2 + m + 1 + t;
    let mut positions = vec![[0.0, 0.0, -0.125], [0.0, 0.0, 0.125]];
    for t in 0..=m {
        let (x, y) = square(t + 1, 4);
        positions.push(if far && t == 0 {
            [x, -4.0, 0.0]
        } else {
            [x, y, 0.0]
        });
    }
    for t in 0..m {
        let (a, b) = (positions[w(t) as usize], positions[w(t + 1) as usize]);
        positions.push(if far && t == 0 {
            [-0.25, -2.0, -0.0625]
        } else {
            [(a[0] + b[0]) / 4.0, (a[1] + b[1]) / 4.0, -0.0625]
        });
    }
    let mut faces = vec![[0, 1, w(0)], [0, w(m), 1]];
    for t in 0..m {
        faces.extend([[0, w(t), c(t)], [0, c(t), w(t + 1)], [c(t), w(t), w(t + 1)]]);
        if !(hole && t == 9) {
            faces.push([1, w(t + 1), w(t)]);
        }
    }
    TriMesh::with_positions(positions, faces)
}

fn inputs() -> Vec<Input> {
    let octahedron = scaled(gen::octahedron(), 2.0);
    let octa2 = gen::subdivide(&octahedron, 2).expect("subdivide");
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
        let m = TriMesh::with_positions(positions, p.faces);
        gen::subdivide(&m, 2).expect("subdivide")
    };
    let torus = grid(16, 8, Glue::Torus);
    let sphere = Implicit::Sphere { radius: 1.0 };
    vec![
        Input {
            name: "simplify_octahedron_subdivided",
            source: json!({"mesh": "gen::octahedron scaled by 2, gen::subdivide 2 levels, jitter seed 1"}),
            mesh: jitter(octa2.clone(), 1),
            eps: [0.5, 0.75, 1.0],
        },
        Input {
            name: "simplify_torus_grid",
            source: json!({"mesh": "16 × 8 torus grid, jitter seed 2"}),
            mesh: jitter(torus.clone(), 2),
            eps: [0.5, 0.875, 1.125],
        },
        Input {
            name: "simplify_klein_bottle_grid",
            source: json!({"mesh": "16 × 8 Klein bottle grid (seam reflected), jitter seed 3"}),
            mesh: jitter(grid(16, 8, Glue::Klein), 3),
            eps: [0.5, 0.875, 1.125],
        },
        Input {
            name: "simplify_projective_plane_subdivided",
            source: json!({"mesh": "gen::projective_plane6 with 6 dyadic positions, gen::subdivide 2 levels, jitter seed 4"}),
            mesh: jitter(rp2, 4),
            eps: [0.5, 0.75, 1.0],
        },
        Input {
            name: "simplify_isosurface_sphere",
            source: json!({"mesh": "iso_sphere_block_six of iso-exact.jsonl"}),
            mesh: iso(sphere, Tessellation::SixTetrahedra, 4, -1.5, 2.5, 1.25),
            eps: [0.375, 0.5, 0.75],
        },
        Input {
            name: "simplify_isosurface_sphere_six_holes",
            source: json!({"mesh": "iso_sphere_six_holes_bcc of iso-exact.jsonl"}),
            mesh: iso(sphere, Tessellation::BodyCentred, 2, -1.0, 1.0, 0.453125),
            eps: [0.25, 0.5, 0.75],
        },
        Input {
            name: "simplify_isosurface_eight_discs",
            source: json!({"mesh": "iso_sphere_eight_discs_bcc of iso-exact.jsonl"}),
            mesh: iso(sphere, Tessellation::BodyCentred, 2, -1.0, 1.0, 1.4375),
            eps: [0.25, 0.375, 0.5],
        },
        Input {
            name: "simplify_annulus_grid",
            source: json!({"mesh": "16 × 4 annulus grid (a vertical band), jitter seed 5"}),
            mesh: jitter(grid(16, 4, Glue::Annulus), 5),
            eps: [0.5, 0.75, 1.0],
        },
        Input {
            name: "simplify_mobius_band_grid",
            source: json!({"mesh": "16 × 4 Möbius band grid (seam reflected), jitter seed 6"}),
            mesh: jitter(grid(16, 4, Glue::Mobius), 6),
            eps: [0.5, 0.75, 1.0],
        },
        Input {
            name: "simplify_torus_with_two_holes",
            source: json!({"mesh": "simplify_torus_grid without the faces at vertices 0 and 68, unused vertices dropped"}),
            mesh: jitter(without_stars(&torus, &[0, 68]), 2),
            eps: [0.5, 0.875, 1.125],
        },
        Input {
            name: "simplify_disc_and_sphere",
            source: json!({"mesh": "an 8 × 8 tent disc, then gen::octahedron subdivided once, moved by (2.5, 0, 0), jitter seed 7"}),
            mesh: jitter(
                union(
                    &disc(8),
                    &gen::subdivide(&gen::octahedron(), 1).expect("subdivide"),
                    [2.5, 0.0, 0.0],
                ),
                7,
            ),
            eps: [0.25, 0.5, 0.75],
        },
        Input {
            name: "simplify_octahedron_with_a_disc",
            source: json!({"mesh": "the octahedron with a short edge on a 3-cycle around a disc of five faces"}),
            mesh: octahedron_with_a_disc(),
            eps: [0.125, 0.5, 0.75],
        },
        Input {
            name: "simplify_thin_handle_torus",
            source: json!({"mesh": "a torus of 8 triangular rings, ring 3 thin"}),
            mesh: thin_handle_torus(),
            eps: [0.0625, 0.125, 0.25],
        },
        Input {
            name: "simplify_genus_on_both_sides",
            source: json!({"mesh": "gen::seed_surface(Orientable(2)), seeded positions (seed 8), one edge of the glued 3-cycle 1/32 long"}),
            mesh: genus_on_both_sides(),
            eps: [0.0625, 0.125, 0.1875],
        },
        Input {
            name: "simplify_nested_cycles",
            source: json!({"mesh": "the suspension of a 14-edge path, one end far: a short edge on 13 nested separating 3-cycles"}),
            mesh: suspension(true, false),
            eps: [0.3125, 0.375, 0.5],
        },
        Input {
            name: "simplify_nested_cycles_with_a_hole",
            source: json!({"mesh": "the suspension of a 14-edge path, one end far, with a hole between the 9th and 10th of its 13 nested 3-cycles"}),
            mesh: suspension(true, true),
            eps: [0.3125, 0.375, 0.5],
        },
        Input {
            name: "simplify_nested_cycles_symmetric",
            source: json!({"mesh": "the suspension of a 14-edge path symmetric about its middle vertex: a short edge on 13 nested separating 3-cycles, split by distance at the middle"}),
            mesh: suspension(false, false),
            eps: [0.3125, 0.375, 0.5],
        },
    ]
}

/// The fewest bits after the binary point and the fewest bits before it that every
/// coordinate needs: every coordinate is a multiple of `2^-fraction` and below
/// `2^magnitude` in absolute value.
fn coordinate_bits(positions: &[[f64; 3]]) -> (u32, u32) {
    let fraction = (0..=30u32)
        .find(|&k| {
            positions.iter().flatten().all(|&x| {
                let y = x * f64::from(1u32 << k);
                y == y.trunc()
            })
        })
        .expect("dyadic coordinates");
    let magnitude = (0..=30u32)
        .find(|&m| {
            positions
                .iter()
                .flatten()
                .all(|&x| x.abs() < f64::from(1u32 << m))
        })
        .expect("bounded coordinates");
    (fraction, magnitude)
}

/// The exactness bound of the README. A pass never reuses a position created in it (the
/// merged vertex is frozen), so after `depth` passes that contract something in a
/// component its coordinates are multiples of `2^-(fraction + depth)`, and within the
/// input's bounding box. With `B = magnitude + fraction + depth + 1` bits per coordinate
/// difference, squared lengths are exact when `2B + 2 <= 53`; the guard also reads the
/// next midpoint (one bit more) in cross and dot products of four factors, exact when
/// `4(B + 1) + 4 <= 53`.
fn exact_bound_holds(fraction: u32, magnitude: u32, depth: usize, guard: bool) -> bool {
    let b = magnitude as usize + fraction as usize + depth + 1;
    if guard {
        4 * (b + 1) + 4 <= 53
    } else {
        2 * b + 2 <= 53
    }
}

/// The most passes that contracted something in one component.
fn depth(reports: &[[usize; 4]]) -> usize {
    let components = reports.iter().map(|r| r[0] + 1).max().unwrap_or(0);
    (0..components)
        .map(|c| reports.iter().filter(|r| r[0] == c && r[2] > 0).count())
        .max()
        .unwrap_or(0)
}

fn components_json(mesh: &TriMesh) -> Value {
    let c = contractible_tools::component_topology(mesh).expect("a surface");
    json!(c
        .iter()
        .map(|&(e, o, l)| json!({"euler_characteristic": e, "orientable": o, "boundary_loops": l}))
        .collect::<Vec<_>>())
}

fn skip_json(s: &simplify::SkipCounts) -> Value {
    json!({
        "link_condition": s.link_condition,
        "non_disc": s.non_disc,
        "foldover": s.foldover,
        "frozen": s.frozen,
    })
}

fn run_json(input: &Input, opts: &Options, bits: (u32, u32)) -> Value {
    let mut reports: Vec<[usize; 4]> = Vec::new();
    let out = simplify::simplify_with(&input.mesh, opts, &mut |r: &PassReport| {
        reports.push([r.component, r.pass, r.contracted, r.faces]);
    })
    .unwrap_or_else(|e| panic!("{}: {e}", input.name));
    let s = &out.stats;
    let d = depth(&reports);
    assert!(
        exact_bound_holds(bits.0, bits.1, d, opts.guard),
        "{} eps {} {} guard {}: {d} contracting passes break the exactness bound",
        input.name,
        opts.eps,
        opts.mode.name(),
        opts.guard,
    );
    json!({
        "mode": opts.mode.name(),
        "side": opts.side.name(),
        "position": opts.position.name(),
        "guard": opts.guard,
        "eps": opts.eps,
        "output_positions": out.mesh.positions.as_deref().expect("positions"),
        "output_faces": out.mesh.faces,
        "pass_reports": reports,
        "stats": {
            "vertices_in": s.vertices_in,
            "faces_in": s.faces_in,
            "vertices_out": s.vertices_out,
            "faces_out": s.faces_out,
            "components": s.components,
            "boundary_loops": s.boundary_loops,
            "edges_contracted": s.edges_contracted,
            "discs_removed": s.discs_removed,
            "vertices_removed_inside": s.vertices_removed_inside,
            "skipped": skip_json(&s.skipped),
            "remaining": skip_json(&s.remaining),
            "short_edges_remaining": s.short_edges_remaining,
            "shortest_remaining_edge": s.shortest_remaining_edge,
            "passes": s.passes,
        },
    })
}

/// The runs of one input: both modes (count heuristic) with the guard at the smallest ε,
/// both modes without the guard at each ε, and at the largest ε the nested mode without
/// the guard with the path and Euclidean heuristics. Always the midpoint placement. (The
/// guard's products need more exact bits than the lengths, so it runs where the passes
/// are few: see `exact_bound_holds`.)
fn options(eps: [f64; 3]) -> Vec<Options> {
    let run = |eps, mode, side, guard| Options {
        eps,
        mode,
        side,
        position: Position::Midpoint,
        guard,
    };
    let mut out = vec![
        run(eps[0], Mode::Naive, Side::Count, true),
        run(eps[0], Mode::Nested, Side::Count, true),
    ];
    for e in eps {
        out.push(run(e, Mode::Naive, Side::Count, false));
        out.push(run(e, Mode::Nested, Side::Count, false));
    }
    out.push(run(eps[2], Mode::Nested, Side::Path, false));
    out.push(run(eps[2], Mode::Nested, Side::Euclidean, false));
    out
}

fn vector(input: &Input, group: &str) -> Value {
    let positions = input.mesh.positions.as_deref().expect("positions");
    let bits = coordinate_bits(positions);
    let runs: Vec<Value> = options(input.eps)
        .iter()
        .map(|o| run_json(input, o, bits))
        .collect();
    json!({
        "name": input.name,
        "group": group,
        "source": input.source,
        "vertex_count": input.mesh.vertex_count,
        "positions": positions,
        "faces": input.mesh.faces,
        "components": components_json(&input.mesh),
        "coordinate_bits": {"fraction": bits.0, "magnitude": bits.1},
        "runs": runs,
    })
}

fn main() {
    let root = contractible_tools::repo_root();
    let out_dir = std::env::args()
        .nth(1)
        .map_or_else(|| root.join("spec/vectors"), PathBuf::from);
    std::fs::create_dir_all(&out_dir).expect("create output directory");
    let all = inputs();
    for (group, closed) in [("simplify-closed", true), ("simplify-bounded", false)] {
        let mut text = String::new();
        let mut n = 0;
        for input in &all {
            let surfaces = ConedSurfaces::from_mesh(&input.mesh)
                .unwrap_or_else(|e| panic!("{}: {e}", input.name));
            if surfaces.is_closed() != closed {
                continue;
            }
            let v = vector(input, group);
            writeln!(text, "{}", serde_json::to_string(&v).expect("json")).expect("write");
            n += 1;
        }
        let path = out_dir.join(format!("{group}.jsonl"));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        println!("{}: {n} vectors", path.display());
    }
}
