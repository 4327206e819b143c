//! Fuzz inputs replayed as plain tests, through the very harness the fuzz targets use
//! (`fuzz/src/lib.rs`, included below), so they run in every `cargo test` (debug build:
//! the executable specification is on).
//!
//! - every file of the seed corpora `fuzz/corpus/<target>/` and of
//!   `fuzz/regressions/<target>/` (minimized crash inputs, see `fuzz/README.md`) is fed
//!   to its target's check;
//! - fixed, decoded inputs (op lists drawn from the documented RNG) cover every surface
//!   the fuzzers start from with a few hundred operations;
//! - a crash found by a campaign gets its own test here, with the input inline.

#[allow(dead_code)]
#[path = "../../fuzz/src/lib.rs"]
pub(crate) mod harness;

use std::path::PathBuf;

use contractible::io::Format;
use contractible::rng::Rng;
use harness::{
    CheckInput, ContractInput, DecimateInput, Edit, ErrorCap, Geometry, JournalInput, JournalStep,
    Op, Part, Positions, SimplifyInput, Surface, SurfaceInput, TaskInput, VertexCount,
};

/// The files of `fuzz/<dir>/<target>/`, sorted. The seed corpora (`corpus`) are part of
/// the repository, so a missing one fails; `regressions/<target>` exists only once a
/// campaign has found a crash for that target.
fn files(dir: &str, target: &str) -> Vec<(PathBuf, Vec<u8>)> {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz")
        .join(dir)
        .join(target);
    let rd = match std::fs::read_dir(&d) {
        Ok(rd) => rd,
        Err(_) if dir == "regressions" => return Vec::new(),
        Err(e) => panic!("{}: {e}", d.display()),
    };
    let mut out: Vec<_> = rd
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.is_file())
        .map(|p| {
            let bytes = std::fs::read(&p).expect("read");
            (p, bytes)
        })
        .collect();
    out.sort();
    out
}

fn replay(target: &str, run: impl Fn(&[u8])) -> usize {
    let mut n = 0;
    for dir in ["corpus", "regressions"] {
        for (path, bytes) in files(dir, target) {
            eprintln!("{target}: {}", path.display());
            run(&bytes);
            n += 1;
        }
    }
    n
}

/// Replays `target`'s files through `check` after decoding them as `T`; returns how
/// many decoded (each one checked).
fn replay_decoded<T: for<'a> arbitrary::Arbitrary<'a>>(target: &str, check: impl Fn(&T)) -> usize {
    let decoded = std::cell::Cell::new(0);
    replay(target, |b| {
        if let Some(i) = harness::decode::<T>(b) {
            check(&i);
            decoded.set(decoded.get() + 1);
        }
    });
    decoded.get()
}

#[test]
fn seed_corpora_and_regressions_of_the_structured_targets() {
    let n = replay_decoded("surface_ops", harness::check_reductions);
    assert!(n >= 5, "surface_ops: {n} inputs decoded");
    let n = replay_decoded("rs_vertex_orders", harness::check_vertex_orders);
    assert!(n >= 5, "rs_vertex_orders: {n} inputs decoded");
    let n = replay_decoded("contract_split", harness::check_contract_undo);
    assert!(n >= 5, "contract_split: {n} inputs decoded");
    let n = replay_decoded("journal_ops", harness::check_journal);
    assert!(n >= 5, "journal_ops: {n} inputs decoded");
    let n = replay_decoded("quad_ops", harness::check_quads);
    assert!(n >= 5, "quad_ops: {n} inputs decoded");
    let n = replay_decoded("simplify", harness::check_simplify_input);
    assert!(n >= 4, "simplify: {n} inputs decoded");
    let n = replay_decoded("tasks", harness::check_tasks);
    assert!(n >= 8, "tasks: {n} inputs decoded");
    let n = replay_decoded("decimate", harness::check_decimate_input);
    assert!(n >= 8, "decimate: {n} inputs decoded");
    let n = replay_decoded("check", harness::check_check);
    assert!(n >= 8, "check: {n} inputs decoded");
    let n = replay_decoded("check_simplify", harness::check_simplify_check);
    assert!(n >= 8, "check_simplify: {n} inputs decoded");
    let n = replay_decoded("check_quad", harness::check_quad_check);
    assert!(n >= 8, "check_quad: {n} inputs decoded");
    let n = replay_decoded("check_decimate", harness::check_decimate_check);
    assert!(n >= 8, "check_decimate: {n} inputs decoded");
}

#[test]
fn seed_corpora_and_regressions_of_the_parsers() {
    for (target, format) in [
        ("parse_off", Some(Format::Off)),
        ("parse_obj", Some(Format::Obj)),
        ("parse_ply", Some(Format::Ply)),
        ("parse_stl", Some(Format::Stl)),
        ("parse_any", None),
    ] {
        let n = replay(target, |b| harness::check_parse(b, format));
        assert!(n >= 4, "{target} corpus missing");
    }
    let n = replay("poly_weld", harness::check_poly_bytes);
    assert!(n >= 20, "poly_weld corpus missing");
}

/// The seed meshes must actually parse into closed surfaces (otherwise the parser
/// corpora would only exercise error paths).
#[test]
fn parser_seed_meshes_are_closed_surfaces() {
    let seeds = files("corpus", "parse_any");
    assert!(seeds.len() >= 18, "{} parse_any seeds", seeds.len());
    for (path, bytes) in seeds {
        let mesh = contractible::io::read_tri_mesh_bytes(&bytes, None)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let s = contractible::Surfaces::from_mesh(&mesh)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let expect = if path.to_string_lossy().contains("two_tetrahedra") {
            2
        } else {
            1
        };
        assert_eq!(s.components.len(), expect, "{}", path.display());
    }
}

/// `len` random ops from the documented stream (splits about twice as likely as flips,
/// a relabelling about once in 256).
fn ops(seed: u64, len: usize) -> Vec<Op> {
    let mut rng = Rng::new(seed);
    (0..len)
        .map(|_| {
            let w = rng.next_u64();
            let [a, b, c, d, e, ..] = w.to_le_bytes();
            if e == 0 {
                Op::Relabel { seed: w }
            } else if e % 3 == 0 {
                Op::Flip {
                    face: u16::from_le_bytes([a, b]),
                    slot: c,
                }
            } else {
                Op::Split {
                    vertex: u16::from_le_bytes([a, b]),
                    i: c,
                    j: d,
                }
            }
        })
        .collect()
}

fn surfaces() -> Vec<Surface> {
    (0..7u8)
        .map(Surface::Orientable)
        .chain((0..6u8).map(Surface::NonOrientable))
        .collect()
}

#[test]
fn every_start_surface_with_random_ops_reduces_correctly() {
    for (k, surface) in surfaces().into_iter().enumerate() {
        // Splits and flips, a relabelling (other RS processing order), more ops.
        let mut o = ops(k as u64, 300);
        o.insert(150, Op::Relabel { seed: k as u64 });
        let input = SurfaceInput {
            surface,
            ops: o,
            seed: k as u64,
        };
        harness::check_reductions(&input);
        harness::check_vertex_orders(&input);
    }
}

/// `quad_ops` on every start surface: splits and flips, a relabelling, more ops, then every
/// tri-quad algorithm (two seeds) checked by the harness.
#[test]
fn every_start_surface_with_random_ops_converts_to_quads_correctly() {
    for (k, surface) in surfaces().into_iter().enumerate() {
        let mut o = ops(300 + k as u64, 240);
        o.insert(120, Op::Relabel { seed: k as u64 });
        // The directed-edge check of the quads runs on every orientable input: splits,
        // flips and relabellings (slot rotations) keep the seed surfaces oriented.
        let built = harness::build_surface(&SurfaceInput {
            surface,
            ops: o.clone(),
            seed: 0,
        });
        assert_eq!(
            harness::is_consistently_oriented(&built.face_list()),
            built.is_orientable(),
            "{surface:?}: orientable inputs are consistently oriented"
        );
        for seed in [k as u64, 1000 + k as u64] {
            harness::check_quads(&SurfaceInput {
                surface,
                ops: o.clone(),
                seed,
            });
        }
    }
}

#[test]
fn every_start_surface_contract_and_undo() {
    for (k, surface) in surfaces().into_iter().enumerate() {
        let mut rng = Rng::new(100 + k as u64);
        let picks = (0..400)
            .map(|_| (rng.below(1 << 16) as u16, rng.below(256) as u8))
            .collect();
        let input = ContractInput {
            base: SurfaceInput {
                surface,
                ops: ops(50 + k as u64, 200),
                seed: 0,
            },
            picks,
        };
        harness::check_contract_undo(&input);
    }
}

#[test]
fn every_start_surface_journal_of_contractions_flips_and_undos() {
    for (k, surface) in surfaces().into_iter().enumerate() {
        let mut rng = Rng::new(200 + k as u64);
        let steps = (0..300)
            .map(|_| {
                let corner = rng.below(1 << 16) as u16;
                match rng.below(20) {
                    0..=7 => JournalStep::Contract { corner },
                    8..=13 => JournalStep::Flip { corner },
                    14..=18 => JournalStep::Undo,
                    _ => JournalStep::Sneak { corner },
                }
            })
            .collect();
        let input = JournalInput {
            base: SurfaceInput {
                surface,
                ops: ops(70 + k as u64, 150),
                seed: 0,
            },
            steps,
        };
        harness::check_journal(&input);
    }
}

/// The decoder is the one libFuzzer uses: a fixed byte string decodes to a fixed input,
/// pinned here (if `arbitrary` changed its format, saved crash files would replay as other
/// inputs, and this test says so).
#[test]
fn crash_files_decode_stably() {
    let bytes: Vec<u8> = (0u8..64).collect();
    let a = harness::decode::<SurfaceInput>(&bytes).expect("decodes");
    assert_eq!(
        a,
        SurfaceInput {
            surface: Surface::Orientable(4),
            ops: vec![Op::Split {
                vertex: 2826,
                i: 12,
                j: 13
            }],
            seed: 1_591_200_115_485_380_623,
        }
    );
}

/// `simplify` on every layout of the positions ([`Geometry`]: coincident, collinear,
/// coplanar, integer-grid, perturbed by 1e-12, wildly scaled, shifted far from the
/// origin) at unit and extreme scales, both modes, with an absolute and a relative ε
/// through the task call and the lower-level call (the `simplify` target's checks).
#[test]
fn simplify_on_degenerate_and_extreme_layouts() {
    let layouts = [
        Geometry::Random { smoothing: 2 },
        Geometry::Grid { range: 3 },
        Geometry::Grid { range: 0 },
        Geometry::Clusters { points: 0 },
        Geometry::Clusters { points: 2 },
        Geometry::Flat { plane: false },
        Geometry::Flat { plane: true },
        Geometry::Perturbed {
            range: 1,
            digits: 0,
        },
        Geometry::Scales { spread: 40 },
        Geometry::Shifted { digits: 16 },
    ];
    for (k, geometry) in layouts.into_iter().enumerate() {
        for (j, scale) in [0i8, 127, -127, 90].into_iter().enumerate() {
            let t = k + j;
            harness::check_simplify_input(&SimplifyInput {
                base: SurfaceInput {
                    surface: Surface::Orientable((t % 3) as u8),
                    ops: ops(500 + t as u64, 60),
                    seed: 0,
                },
                positions: t as u64,
                geometry,
                scale,
                eps: 20_000 + 7_000 * (t % 4) as u16,
                relative: t % 2 == 0,
                holes: if t % 3 == 0 { vec![] } else { vec![3, 17, 40] },
                side: t as u8,
                quadric: k % 2 == 1,
                guard: t % 3 != 1,
                nested: j % 2 == 0,
            });
        }
    }
}

/// `decimate` on every layout of the positions at unit and extreme scales, closed and
/// opened, one and two components, with every placement, the guard on and off, face,
/// fraction and error targets (valid and refused values), boundary and vertex locks (the
/// `decimate` target's checks: refusals of the documented kind, outputs checked from
/// their face lists and maps, a second run identical).
#[test]
fn decimate_on_degenerate_layouts_and_every_option() {
    let layouts = [
        Geometry::Random { smoothing: 1 },
        Geometry::Grid { range: 2 },
        Geometry::Grid { range: 0 },
        Geometry::Clusters { points: 1 },
        Geometry::Flat { plane: false },
        Geometry::Flat { plane: true },
        Geometry::Perturbed {
            range: 0,
            digits: 3,
        },
        Geometry::Scales { spread: 63 },
        Geometry::Shifted { digits: 17 },
    ];
    let caps = [
        None,
        Some(ErrorCap::Relative(3_000)),
        Some(ErrorCap::Absolute(20_000)),
        Some(ErrorCap::Relative(65_530)),
        Some(ErrorCap::Relative(65_534)),
        Some(ErrorCap::Absolute(65_532)),
    ];
    for (k, geometry) in layouts.into_iter().enumerate() {
        for (j, scale) in [0i8, 127, -127].into_iter().enumerate() {
            let t = 3 * k + j;
            harness::check_decimate_input(&DecimateInput {
                base: SurfaceInput {
                    surface: if t % 4 == 3 {
                        Surface::NonOrientable(t as u8)
                    } else {
                        Surface::Orientable((t % 3) as u8)
                    },
                    ops: ops(700 + t as u64, 80),
                    seed: 0,
                },
                extra: (t % 3 == 1).then(|| (Surface::NonOrientable(0), ops(900 + t as u64, 20))),
                positions: t as u64,
                geometry,
                scale,
                holes: if t % 2 == 0 { vec![] } else { vec![5, 11, 29] },
                spare: t as u8,
                faces: (t % 4 != 0).then_some(7 * t as u16),
                keep: (t % 5 == 1).then_some([6_000, 60_000, 65_533, 65_535][t % 4]),
                max_error: caps[t % caps.len()],
                placement: t as u8,
                guard: t % 3 != 2,
                lock_boundary: t % 4 == 1,
                locked: if t % 3 == 0 {
                    vec![]
                } else {
                    vec![t as u16, 3, 40]
                },
                skip_verify: t % 2 == 1,
                passes: t % 3 == 1,
            });
        }
    }
}

/// `tasks` on fixed inputs: every part kind, every edit, every declared vertex count and
/// kind of positions, each through every reduction and tri-quad algorithm (the `tasks`
/// target's checks: refusals typed and in agreement with `describe` and the surface
/// oracle, outputs checked from their face lists).
#[test]
fn task_calls_on_assembled_and_edited_face_lists() {
    let surface = |s: Surface, seed: u64| Part::Surface {
        surface: s,
        ops: ops(seed, 30),
    };
    let laid = |geometry, seed| Positions::Laid {
        geometry,
        scale: 0,
        seed,
    };
    let cases: Vec<(Vec<Part>, Vec<Edit>, VertexCount, Positions)> = vec![
        // Closed surfaces side by side, unused vertices, positions.
        (
            vec![
                surface(Surface::Orientable(1), 1),
                Part::Standard { which: 5 },
                Part::Standard { which: 0 },
            ],
            vec![],
            VertexCount::Extra { unused: 3 },
            laid(Geometry::Random { smoothing: 1 }, 1),
        ),
        // Without positions; faces swapped and reversed (still closed surfaces).
        (
            vec![
                surface(Surface::NonOrientable(2), 2),
                Part::Standard { which: 4 },
            ],
            vec![Edit::Swap { a: 0, b: 9 }, Edit::Reverse { face: 4 }],
            VertexCount::Parts,
            Positions::None,
        ),
        // Boundary: faces removed.
        (
            vec![
                surface(Surface::Orientable(0), 3),
                Part::Standard { which: 3 },
            ],
            vec![Edit::Remove { face: 2 }, Edit::Remove { face: 30 }],
            VertexCount::Parts,
            laid(Geometry::Grid { range: 5 }, 3),
        ),
        // A duplicate face, a rotated and reversed copy.
        (
            vec![Part::Standard { which: 1 }],
            vec![Edit::Duplicate { face: 3, turn: 130 }],
            VertexCount::Parts,
            laid(Geometry::Flat { plane: true }, 4),
        ),
        // Two spheres pinched at a vertex; a corner out of range.
        (
            vec![Part::Standard { which: 0 }, Part::Standard { which: 1 }],
            vec![Edit::Merge { keep: 0, gone: 5 }],
            VertexCount::Parts,
            laid(Geometry::Clusters { points: 1 }, 5),
        ),
        (
            vec![Part::Standard { which: 2 }],
            vec![Edit::Corner {
                face: 7,
                slot: 1,
                vertex: u32::MAX,
            }],
            VertexCount::Parts,
            Positions::None,
        ),
        // Arbitrary triples and an added face (non-manifold, degenerate).
        (
            vec![Part::Raw {
                vertices: 6,
                faces: vec![
                    [0, 1, 2],
                    [0, 2, 3],
                    [0, 3, 1],
                    [1, 2, 3],
                    [1, 2, 4],
                    [5, 5, 1],
                ],
            }],
            vec![Edit::Add { corners: [1, 2, 8] }],
            VertexCount::Extra { unused: 1 },
            laid(Geometry::Random { smoothing: 0 }, 6),
        ),
        // No faces at all.
        (
            vec![],
            vec![],
            VertexCount::Extra { unused: 4 },
            Positions::None,
        ),
        // A vertex count beyond the core's ids.
        (
            vec![Part::Standard { which: 0 }],
            vec![],
            VertexCount::Huge,
            laid(Geometry::Random { smoothing: 0 }, 7),
        ),
        // Positions: a non-finite coordinate, one too many.
        (
            vec![Part::Standard { which: 1 }],
            vec![],
            VertexCount::Parts,
            Positions::NonFinite {
                geometry: Geometry::Random { smoothing: 0 },
                seed: 8,
                vertex: 2,
                axis: 1,
                value: 0,
            },
        ),
        (
            vec![Part::Standard { which: 3 }],
            vec![],
            VertexCount::Parts,
            Positions::Miscounted { seed: 9, delta: 1 },
        ),
    ];
    for (k, (parts, edits, vertices, positions)) in cases.into_iter().enumerate() {
        for reduce in 0..3u8 {
            for quad in 0..8u8 {
                harness::check_tasks(&TaskInput {
                    parts: parts.clone(),
                    edits: edits.clone(),
                    vertices,
                    positions,
                    reduce,
                    quad,
                    seed: k as u64,
                    eps: 30_000,
                    relative: quad % 2 == 0,
                    nested: reduce != 1,
                    side: quad,
                    quadric: reduce == 2,
                    foldover: quad % 3 == 0,
                });
            }
        }
    }
}

/// `tasks` found: `reduce` of a mesh whose positions are not one per vertex failed with
/// an internal error (`Unverified`: "the output does not map onto the input's
/// vertices") instead of refusing the input, and `quadrangulate` returned a quad mesh
/// with that wrong number of positions. Both now refuse with `PositionCount` first
/// (the file `fuzz/regressions/tasks/positions-not-one-per-vertex` is the input found).
#[test]
fn reduce_and_quadrangulate_refuse_positions_that_are_not_one_per_vertex() {
    use contractible::{Error, QuadOptions, ReduceOptions, SimplifyOptions};
    let octahedron = contractible::gen::octahedron();
    for n in [0, 5, 7] {
        let mut m = octahedron.clone();
        m.positions.as_mut().expect("positions").resize(n, [1.0; 3]);
        for e in [
            contractible::reduce(&m, &ReduceOptions::default()).err(),
            contractible::quadrangulate(&m, &QuadOptions::default()).err(),
        ] {
            assert!(
                matches!(e, Some(Error::PositionCount { vertices: 6, positions }) if positions == n),
                "{n} positions: {e:?}"
            );
        }
        harness::check_task_calls(
            &m,
            &ReduceOptions::default(),
            &QuadOptions::default(),
            &SimplifyOptions::default(),
        );
    }
}

/// `tasks` found: with coordinates near 1e240 (a wide spread of per-vertex scales) every
/// squared edge length overflowed, so `simplify` reported `shortest_remaining_edge:
/// None` for an output with edges (and no edge could count as shorter than ε). The
/// simplifier now works on positions scaled by a power of two (exact), which keeps
/// every squared length finite (`fuzz/regressions/tasks/huge-coordinates-shortest-edge`).
#[test]
fn huge_coordinates_are_simplified_with_their_shortest_edge() {
    harness::check_tasks(&TaskInput {
        parts: vec![
            Part::Surface {
                surface: Surface::Orientable(32),
                ops: vec![
                    Op::Relabel {
                        seed: 9_022_979_780_515_220_293,
                    },
                    Op::Relabel {
                        seed: 14_305_965_111_539_402_376,
                    },
                    Op::Relabel {
                        seed: 5_180_219_219_341_647_679,
                    },
                    Op::Relabel {
                        seed: 16_651_039_371_925_406_194,
                    },
                ],
            },
            Part::Standard { which: 49 },
            Part::Raw {
                vertices: 140,
                faces: vec![],
            },
        ],
        edits: vec![],
        vertices: VertexCount::Parts,
        positions: Positions::Laid {
            geometry: Geometry::Scales { spread: 207 },
            scale: 120,
            seed: 1_314_713_215_837_044_058,
        },
        reduce: 202,
        quad: 133,
        seed: 16_022_286_312_828_509_232,
        eps: 6922,
        relative: false,
        nested: true,
        side: 165,
        quadric: false,
        foldover: false,
    });
}

/// `poly_weld` on inline inputs: a quad strip whose shorter diagonals would repeat an
/// edge (another fan start is taken), polygons of 5 and 6 corners, a triangle soup in
/// OFF whose corners weld at several tolerances, a binary STL of a soup with `-0.0`
/// and a repeated corner, and the same as ASCII.
#[test]
fn polygon_reading_triangulation_and_welding_inline() {
    let strip = "OFF\n6 2 0\n0 0 0\n1 0 0\n2 0 0\n2 1 0\n1 1 0\n0 1 0\n4 0 1 4 5\n4 1 2 3 4\n";
    let polygons = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5\nf 1 5 6\nf 2 1 6 5 4 3\n";
    let soup = "OFF\n9 3 0\n0 0 0\n1 0 0\n0 1 0\n1e-13 0 0\n0 1 0\n1 1 0\n1 0 0\n1.0000001 1 0\n2 0 0\n3 0 1 2\n3 3 5 4\n3 6 7 8\n";
    for text in [strip, polygons, soup] {
        harness::check_poly_bytes(text.as_bytes());
    }
    let tris: [[[f32; 3]; 3]; 3] = [
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        [[-0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
        [[0.5, 0.5, 0.0], [0.5, 0.5, 0.0], [1.0, 1.0, 1.0]],
    ];
    let mut binary = b"solid but binary".to_vec();
    binary.resize(80, 0);
    binary.extend_from_slice(&3u32.to_le_bytes());
    let mut ascii = String::from("solid s\n");
    for t in tris {
        binary.extend_from_slice(&[0; 12]);
        ascii.push_str("facet normal 0 0 1\nouter loop\n");
        for c in t {
            for x in c {
                binary.extend_from_slice(&x.to_le_bytes());
            }
            ascii.push_str(&format!("vertex {} {} {}\n", c[0], c[1], c[2]));
        }
        binary.extend_from_slice(&[0, 0]);
        ascii.push_str("endloop\nendfacet\n");
    }
    ascii.push_str("endsolid s\n");
    harness::check_poly_bytes(&binary);
    harness::check_poly_bytes(ascii.as_bytes());
    let m = contractible::io::read_tri_mesh_bytes(&binary, Some(Format::Stl)).expect("STL");
    // -0.0 and 0.0 stay apart; the repeated corner is kept (for validation to refuse).
    assert_eq!(m.vertex_count, 6);
    assert_eq!(m.faces[2][0], m.faces[2][1]);
}

/// `poly_weld` found: welding with tolerance 1 left apart two vertices whose squared
/// distance rounds to exactly 1 (y = -3.06e-32 and y = 1: cells -1 and 1 of a grid of
/// side 1, never compared), while the same pair shifted above 0 merged. The grid's cells
/// now have twice the tolerance as side
/// (`fuzz/regressions/poly_weld/pair-at-exactly-the-tolerance.stl`).
#[test]
fn welding_merges_a_pair_at_exactly_the_tolerance() {
    let off = "OFF\n3 1 0\n1 -3.062228611575705e-32 1\n1 1 1\n5 5 5\n3 0 1 2\n";
    harness::check_poly_bytes(off.as_bytes());
    let m = contractible::io::read_tri_mesh_bytes(off.as_bytes(), Some(Format::Off)).expect("OFF");
    let (w, merged) = m.welded_within(1.0).expect("a tolerance");
    assert_eq!((merged, w.faces[0]), (1, [0, 0, 1]));
}

/// Found by the `decimate` target's seed corpus (the minimized input is
/// `fuzz/regressions/decimate/m1-guard-on-positions-spanning-many-decades`): the
/// 7-vertex torus after one split (8 vertices, 16 faces), each vertex scaled by its own
/// power of ten (exponents up to ±63) and everything by 10^252, decimated to 1/6 of its
/// faces with the optimal placement and the fold-over guard on. The first collapse,
/// `[1, 7]` at cost 0, fails the specification check M1 (`src/decimate/spec.rs`): the
/// check's own decision of the guards (the naive link condition, the fold-over test on
/// every moved face, then the decimator's alternatives) did not allow that edge at all,
/// while the decimator collapsed it: the check used the test's reference formula, which
/// rounds differently from the guard's at such scales. M1 now decides the guard with the
/// guard's own test on the faces it enumerates itself, and both agree.
#[test]
fn decimate_collapses_only_what_its_specification_allows_on_extreme_scales() {
    harness::check_decimate_input(&DecimateInput {
        base: SurfaceInput {
            surface: Surface::Orientable(1),
            ops: vec![Op::Split {
                vertex: 33899,
                i: 1,
                j: 0,
            }],
            seed: 120_199_328_135_659_671,
        },
        extra: None,
        positions: 1_008_806_316_547_768_359,
        geometry: Geometry::Scales { spread: 63 },
        scale: 127,
        holes: vec![],
        spare: 0,
        faces: None,
        keep: Some(10_000),
        max_error: None,
        placement: 0,
        guard: true,
        lock_boundary: false,
        locked: vec![],
        skip_verify: false,
        passes: false,
    });
}

/// The `check` target's checks on fixed answers: every surface kind grown by 60 random
/// splits, contracted by 0, 40 or all possible picks (then irreducible), written in the
/// input's ids or compacted, unedited and with each kind of edit.
#[test]
fn check_judges_contracted_and_corrupted_answers_as_the_core_does() {
    let mut rng = Rng::new(0xc4ec);
    let edits = [
        vec![],
        vec![Edit::Remove { face: 3 }],
        vec![Edit::Duplicate { face: 1, turn: 129 }],
        vec![Edit::Reverse { face: 2 }],
        vec![Edit::Merge { keep: 1, gone: 5 }],
        vec![Edit::Swap { a: 0, b: 4 }],
        vec![Edit::Add {
            corners: [0, 1, 900],
        }],
    ];
    for (s, surface) in [
        Surface::Orientable(0),
        Surface::Orientable(1),
        Surface::Orientable(3),
        Surface::NonOrientable(0),
        Surface::NonOrientable(3),
    ]
    .into_iter()
    .enumerate()
    {
        let ops: Vec<Op> = (0..60)
            .map(|_| Op::Split {
                vertex: rng.below(1 << 16) as u16,
                i: rng.below(256) as u8,
                j: rng.below(256) as u8,
            })
            .collect();
        for (p, picks) in [0usize, 40].into_iter().enumerate() {
            for finish in [false, true] {
                for (e, edit) in edits.iter().enumerate() {
                    harness::check_check(&CheckInput {
                        base: SurfaceInput {
                            surface,
                            ops: ops.clone(),
                            seed: 0,
                        },
                        picks: (0..picks)
                            .map(|_| (rng.below(1 << 16) as u16, rng.below(256) as u8))
                            .collect(),
                        finish,
                        edits: edit.clone(),
                        compact: (s + p + e) % 2 == 0,
                        // Each kind of history edit, and none.
                        history_edits: match (s + e) % 5 {
                            0 => vec![],
                            k => vec![(k as u8 - 1, rng.below(64) as u16, rng.below(64) as u16)],
                        },
                    });
                }
            }
        }
    }
}
