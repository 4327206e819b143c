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
mod harness;

use std::path::PathBuf;

use contractible::io::Format;
use contractible::rng::Rng;
use harness::{ContractInput, JournalInput, JournalStep, Op, Surface, SurfaceInput};

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
