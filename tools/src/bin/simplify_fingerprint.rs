//! Output fingerprints of `simplify`, for checking that a change to the simplifier's
//! speed leaves its outputs unchanged: `cargo run --release -p contractible-tools --bin
//! simplify_fingerprint > new.txt` prints one line per run, and `... -- --check FILE`
//! compares with a saved file (exit 1 and the differing lines if any differ). The saved reference is `benches/simplify_fingerprints.txt` (regenerate it
//! only for a deliberate change of the output, and say so in the commit).
//!
//! Runs: the three ≥ 1M-triangle marching-tetrahedra surfaces of `benches/simplify.rs`
//! (nested and naive at ε = 1 %, nested at 3 %), then every `*.off.gz` of
//! `../shared/meshes/closed/` (or `$CONTRACTIBLE_SHARED/meshes/closed/`) in both modes at
//! ε = 1 % and 3 % of the bounding-box diagonal, and a deterministically jittered copy
//! of each (every vertex moved by up to 0.3 of the mean edge length, from a fixed
//! splitmix64 stream) in the nested mode, where disc removal happens; and a few meshes
//! with the other options (quadric positions, path and Euclidean sides, no guard).
//! `--quick` skips the shared meshes above 50,000 faces.
//!
//! Each line: the run's label, output vertices and faces, edges contracted, discs and
//! vertices removed inside them, passes, the remaining short edges by reason, the
//! shortest remaining edge's bits, and a 64-bit FNV-1a hash of the output faces and the
//! bits of the output positions. `Stats::skipped` (per-visit skip events) is not part of
//! the line: it counts visits, which a faster pass may make fewer of without changing
//! any decision.

use std::path::{Path, PathBuf};

use contractible::gen::{isosurface, large_hyperboloid, large_torus, Tessellation};
use contractible::simplify::{bbox_diagonal, simplify, Mode, Options, Position, Side};
use contractible::TriMesh;

/// FNV-1a over 64-bit words (each word's eight bytes, little-endian).
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
    fn word(&mut self, w: u64) {
        for b in w.to_le_bytes() {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

fn diagonal(mesh: &TriMesh) -> f64 {
    bbox_diagonal(mesh.positions.as_deref().unwrap_or(&[]).iter().copied())
}

/// One line describing the output of `simplify(mesh, opts)`.
fn mode_name(m: Mode) -> &'static str {
    if m == Mode::Nested {
        "nested"
    } else {
        "naive"
    }
}

/// [`line()`] for `mode` at `rel` times the diagonal `diag`, labelled `NAME MODE REL`.
fn mode_line(name: &str, mesh: &TriMesh, mode: Mode, rel: f64, diag: f64) -> String {
    let opts = Options {
        mode,
        ..Options::new(rel * diag)
    };
    line(&format!("{name} {} {rel}", mode_name(mode)), mesh, &opts)
}

fn line(label: &str, mesh: &TriMesh, opts: &Options) -> String {
    let out = match simplify(mesh, opts) {
        Ok(out) => out,
        Err(e) => return format!("{label} error {e}"),
    };
    let mut h = Fnv::new();
    h.word(out.mesh.vertex_count as u64);
    h.word(out.mesh.faces.len() as u64);
    for f in &out.mesh.faces {
        for &v in f {
            h.word(u64::from(v));
        }
    }
    for p in out.mesh.positions.as_deref().unwrap_or(&[]) {
        for x in p {
            h.word(x.to_bits());
        }
    }
    let s = &out.stats;
    let r = &s.remaining;
    format!(
        "{label} V={} F={} contracted={} discs={} inside={} passes={} remaining={}/{}/{}/{} shortest={:016x} hash={:016x}",
        s.vertices_out,
        s.faces_out,
        s.edges_contracted,
        s.discs_removed,
        s.vertices_removed_inside,
        s.passes,
        r.link_condition,
        r.non_disc,
        r.foldover,
        r.frozen,
        s.shortest_remaining_edge.map_or(0, f64::to_bits),
        h.0
    )
}

fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// `mesh` with every vertex moved by a vector of coordinates uniform in ±0.3 / √3 of
/// the mean edge length (so at most 0.3 of it), from a splitmix64 stream seeded by
/// `seed`.
fn jittered(mesh: &TriMesh, seed: u64) -> TriMesh {
    let pos = mesh.positions.as_deref().unwrap_or(&[]);
    let (mut sum, mut n) = (0.0, 0usize);
    for f in &mesh.faces {
        for k in 0..3 {
            let (a, b) = (pos[f[k] as usize], pos[f[(k + 1) % 3] as usize]);
            sum += ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
            n += 1;
        }
    }
    let r = 0.3 * sum / n.max(1) as f64 / 3f64.sqrt();
    let mut state = seed;
    let moved = pos
        .iter()
        .map(|p| {
            p.map(|x| {
                let u = (splitmix(&mut state) >> 11) as f64 / (1u64 << 53) as f64;
                x + r * (2.0 * u - 1.0)
            })
        })
        .collect();
    TriMesh::with_positions(moved, mesh.faces.clone())
}

fn shared_dir() -> PathBuf {
    std::env::var_os("CONTRACTIBLE_SHARED").map_or_else(
        || contractible_tools::repo_root().join("../shared"),
        PathBuf::from,
    )
}

fn closed_meshes() -> Vec<PathBuf> {
    let dir = shared_dir().join("meshes").join("closed");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(".off.gz"))
        .collect();
    files.sort();
    files
}

fn name_of(p: &Path) -> String {
    p.file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let quick = args.iter().any(|a| a == "--quick");
    let check = args
        .iter()
        .position(|a| a == "--check")
        .and_then(|i| args.get(i + 1))
        .cloned();
    let mut lines = Vec::new();
    let mut emit = |l: String| {
        if check.is_none() {
            println!("{l}");
        }
        lines.push(l);
    };

    let large = [
        ("large_torus_bcc", large_torus(Tessellation::BodyCentred)),
        ("large_torus_six", large_torus(Tessellation::SixTetrahedra)),
        (
            "large_hyperboloid_bcc",
            large_hyperboloid(Tessellation::BodyCentred),
        ),
    ];
    for (name, params) in large {
        let mesh = isosurface(&params).expect("a valid preset");
        let diag = diagonal(&mesh);
        for (mode, rel) in [
            (Mode::Nested, 0.01),
            (Mode::Naive, 0.01),
            (Mode::Nested, 0.03),
        ] {
            emit(mode_line(name, &mesh, mode, rel, diag));
        }
    }

    for (i, path) in closed_meshes().iter().enumerate() {
        let name = name_of(path);
        let mesh = match contractible::io::read_tri_mesh(path) {
            Ok(m) => m,
            Err(e) => {
                emit(format!("{name} unreadable {e}"));
                continue;
            }
        };
        if quick && mesh.faces.len() > 50_000 {
            continue;
        }
        let diag = diagonal(&mesh);
        for rel in [0.01, 0.03] {
            for mode in [Mode::Naive, Mode::Nested] {
                emit(mode_line(&name, &mesh, mode, rel, diag));
            }
            let moved = jittered(&mesh, i as u64 + 1);
            let opts = Options::new(rel * diagonal(&moved));
            emit(line(
                &format!("{name} jittered nested {rel}"),
                &moved,
                &opts,
            ));
        }
        // The other options, on every seventh mesh.
        if i % 7 == 0 {
            let base = Options::new(0.03 * diag);
            let variants = [
                (
                    "quadric",
                    Options {
                        position: Position::Quadric,
                        ..base
                    },
                ),
                (
                    "path",
                    Options {
                        side: Side::Path,
                        ..base
                    },
                ),
                (
                    "euclidean",
                    Options {
                        side: Side::Euclidean,
                        ..base
                    },
                ),
                (
                    "noguard",
                    Options {
                        guard: false,
                        ..base
                    },
                ),
            ];
            for (v, opts) in variants {
                emit(line(&format!("{name} {v} 0.03"), &mesh, &opts));
            }
        }
    }

    if let Some(file) = check {
        let saved = std::fs::read_to_string(&file).unwrap_or_else(|e| panic!("{file}: {e}"));
        let saved: Vec<&str> = saved.lines().collect();
        let mut differ = 0;
        for l in &lines {
            let label_end = l
                .find(" V=")
                .or_else(|| l.find(" error"))
                .unwrap_or(l.len());
            let label = &l[..label_end];
            match saved
                .iter()
                .find(|s| s.starts_with(label) && s[label.len()..].starts_with(' '))
            {
                Some(s) if *s == l => {}
                Some(s) => {
                    differ += 1;
                    println!("differs:\n  saved {s}\n  now   {l}");
                }
                None => {
                    differ += 1;
                    println!("not in {file}: {l}");
                }
            }
        }
        println!("{} runs compared with {file}, {differ} differ", lines.len());
        if differ > 0 {
            std::process::exit(1);
        }
    }
}
