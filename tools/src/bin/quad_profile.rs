//! Timing and output fingerprints of the tri-quad conversion, one input at a time: for
//! each algorithm, the initial step and the completion are timed separately (wall clock
//! and CPU time of the thread, which means more on a shared machine), and a 64-bit FNV-1a
//! fingerprint of the initial pairing and of the output (`K`'s face lists and the pairs)
//! is printed, so that an optimisation can be shown not to change any output (the
//! fingerprints are pinned by `tests/algorithms/quad_qbench.rs`).
//!
//! Run: `cargo run --release -p contractible-tools --bin quad_profile -- B0 C0 mesh:botijo rand:o3:2000`
//! (inputs: a paper family member `B0`…`C7`; `mesh:NAME` for the biggest component of
//! `../shared/meshes/closed/NAME.off.gz`; `rand:oG:F` / `rand:nH:F` for a random
//! orientable genus-G / non-orientable genus-H surface with at least F faces, seed 1).
//! Optional `--algo lrs|ps|sg|matching` (repeatable) restricts the algorithms;
//! `--seed N` sets the seed of SG and PS (default 1, as the benches; the CLI's default
//! is 0).

use contractible_tools::cpu;
use std::time::Instant;

use contractible::gen::{paper_family, random, RandomParams, SurfaceKind};
use contractible::quad::augment;
use contractible::quad::{Algorithm, Options, Pairing};
use contractible::{Surfaces, Triangulation};

fn main() {
    let mut names = Vec::new();
    let mut algos = Vec::new();
    let mut options = Options { seed: 1 };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--seed" {
            let v = args.next().expect("--seed needs a value");
            options.seed = v.parse().expect("--seed takes an integer");
        } else if a == "--algo" {
            let v = args.next().expect("--algo needs a value");
            algos.push(match v.as_str() {
                "lrs" => Algorithm::Lrs,
                "ps" => Algorithm::PulliSegal,
                "sg" => Algorithm::SimpleGreedy,
                "matching" => Algorithm::Matching,
                _ => panic!("unknown algorithm {v}"),
            });
        } else {
            names.push(a);
        }
    }
    if algos.is_empty() {
        algos = vec![
            Algorithm::Lrs,
            Algorithm::PulliSegal,
            Algorithm::SimpleGreedy,
            Algorithm::Matching,
        ];
    }
    for name in &names {
        let t = build(name);
        println!("{name}: {} faces", t.face_count());
        for &alg in &algos {
            let input = t.clone();
            let (w0, c0) = (Instant::now(), cpu());
            let (k, mut p) = initial_step(input, alg, &options);
            let (wa, ca) = (w0.elapsed().as_secs_f64(), cpu() - c0);
            let fp_initial = fingerprint_pairing(&p);
            let unpaired = k.face_count() - 2 * p.len();
            let (w1, c1) = (Instant::now(), cpu());
            let work = augment::complete(&k, &mut p).expect("a closed triangulation");
            let (wd, cd) = (w1.elapsed().as_secs_f64(), cpu() - c1);
            assert!(p.is_perfect(&k), "perfect");
            println!(
                "  {:8} initial {wa:7.3} s (cpu {ca:6.2}) unpaired {unpaired:7} | completion {wd:7.3} s (cpu {cd:6.2}) paths {} phases {} visits {} | fp initial {fp_initial:016x} output {:016x}",
                alg.name(),
                work.augmenting_paths,
                work.phases,
                work.edge_visits,
                fingerprint_output(&k, &p)
            );
        }
    }
}

fn initial_step(t: Triangulation, alg: Algorithm, options: &Options) -> (Triangulation, Pairing) {
    let i = contractible::quad::initial_pairing(t, alg, options).expect("a closed triangulation");
    (i.tri, i.pairing)
}

fn build(name: &str) -> Triangulation {
    if let Some(spec) = name.strip_prefix("rand:") {
        let (kind, faces) = spec.split_once(':').expect("rand:KIND:FACES");
        let g: u32 = kind[1..].parse().expect("genus");
        let surface = if kind.starts_with('o') {
            SurfaceKind::Orientable(g)
        } else {
            SurfaceKind::NonOrientable(g)
        };
        return random(&RandomParams {
            surface,
            min_faces: faces.parse().expect("faces"),
            flip_percent: 30,
            seed: 1,
        })
        .expect("a random surface within the limits");
    }
    let mesh = if let Some(file) = name.strip_prefix("mesh:") {
        let path =
            contractible_tools::repo_root().join(format!("../shared/meshes/closed/{file}.off.gz"));
        contractible::io::read_tri_mesh(path.as_ref()).expect("mesh reads")
    } else {
        let mut c = name.chars();
        let group = c.next().expect("group letter");
        paper_family(group, c.as_str().parse().expect("member index"))
            .expect("valid brick parameters")
    };
    let s = Surfaces::from_mesh(&mesh).expect("closed surface");
    s.components
        .into_iter()
        .max_by_key(|c| c.tri.face_count())
        .expect("a component")
        .tri
}

/// FNV-1a, 64 bits, over little-endian `u32` words.
struct Fnv(u64);

impl Fnv {
    fn new() -> Self {
        Fnv(0xcbf2_9ce4_8422_2325)
    }
    fn word(&mut self, w: u32) {
        for b in w.to_le_bytes() {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// The pairs in increasing smaller id.
fn fingerprint_pairing(p: &Pairing) -> u64 {
    let mut h = Fnv::new();
    for (f, g) in p.pairs() {
        h.word(f.0);
        h.word(g.0);
    }
    h.0
}

/// `K`'s face lists (live faces in increasing id, id and slot order) and the pairs.
fn fingerprint_output(k: &Triangulation, p: &Pairing) -> u64 {
    let mut h = Fnv::new();
    for f in k.faces() {
        h.word(f.0);
        for v in k.face_vertices(f) {
            h.word(v.0);
        }
    }
    h.word(fingerprint_pairing(p) as u32);
    h.word((fingerprint_pairing(p) >> 32) as u32);
    h.0
}
