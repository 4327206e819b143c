//! Output pins of the tri-quad conversion, so that an optimisation cannot change its
//! results: every algorithm's initial pairing and final output (`K`'s face lists and the
//! pairs) on a few inputs, as 64-bit FNV-1a fingerprints recorded from the implementation
//! *before* any optimisation (commit b70e3ef, by `tools/src/bin/quad_profile.rs`). A speed-up that changes
//! a single pair, flip or face slot changes a fingerprint and fails here. The
//! fingerprints are computed by this file's own code from the public results only.
//! One deliberate change since: LRS's `K` on the non-orientable input (`rand:n5`), whose
//! flips now start from each edge's canonical corner (`quad/lrs/mod.rs`, "Flips trust
//! Prop. 3.3"), re-pinned with the reason beside the values.
//!
//! Inputs: random surfaces, the paper's bricks B6 and C5 and four meshes the repository
//! carries (`data:NAME`, the largest component of `tests/data/meshes/closed/NAME.off.gz`)
//! by default; the corpus mesh botijo in the ignored `corpus` tests. The repository's meshes
//! were pinned later, by this file's fingerprint code linked against the library of
//! commit b70e3ef (which reproduces this file's pins of `rand:o3` and botijo exactly).

use contractible::gen::{paper_family, random, RandomParams, SurfaceKind};
use contractible::quad::{self, greedy, lrs, matching, pulli_segal};
use contractible::quad::{Algorithm, Options, Pairing};
use contractible::{Surfaces, Triangulation};

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

/// The pairs, each once, in increasing smaller face id (read from the mates directly).
fn fingerprint_pairing(t: &Triangulation, p: &Pairing) -> u64 {
    let mut h = Fnv::new();
    for f in 0..p.face_capacity() as u32 {
        let f = contractible::FaceId(f);
        if let Some(g) = p.mate(f) {
            if f.0 < g.0 {
                assert!(t.is_face(f) && t.is_face(g), "pair of removed faces");
                h.word(f.0);
                h.word(g.0);
            }
        }
    }
    h.0
}

/// `K`'s live faces in increasing id (id, then the vertices in slot order), then the
/// pairing's fingerprint.
fn fingerprint_output(k: &Triangulation, p: &Pairing) -> u64 {
    let mut h = Fnv::new();
    for f in k.faces() {
        h.word(f.0);
        for v in k.face_vertices(f) {
            h.word(v.0);
        }
    }
    let fp = fingerprint_pairing(k, p);
    h.word(fp as u32);
    h.word((fp >> 32) as u32);
    h.0
}

/// The largest component of `mesh`.
fn largest_component(mesh: &contractible::TriMesh) -> Triangulation {
    Surfaces::from_mesh(mesh)
        .expect("closed surface")
        .components
        .into_iter()
        .max_by_key(|c| c.tri.face_count())
        .expect("a component")
        .tri
}

fn build(name: &str) -> Triangulation {
    let random_surface = |surface| {
        random(&RandomParams {
            surface,
            min_faces: 3000,
            flip_percent: 30,
            seed: 1,
        })
        .expect("a random surface within the limits")
    };
    let mesh = match name {
        "rand:o3" => return random_surface(SurfaceKind::Orientable(3)),
        "rand:n5" => return random_surface(SurfaceKind::NonOrientable(5)),
        "B6" => paper_family('B', 6).expect("valid brick parameters"),
        "C5" => paper_family('C', 5).expect("valid brick parameters"),
        _ => {
            let file = name
                .strip_prefix("data:")
                .unwrap_or_else(|| panic!("no input {name}"));
            let path = crate::common::data_meshes().join(format!("closed/{file}.off.gz"));
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
        }
    };
    largest_component(&mesh)
}

/// An input, an algorithm, and what it gives with seed 1 (see [`PINS`]).
type Pin = (&'static str, Algorithm, usize, usize, usize, u64, u64);

/// (input, algorithm, unpaired after the initial step, augmenting paths, phases,
/// fingerprint of the initial pairing, fingerprint of the output), seed 1.
const PINS: &[Pin] = &[
    (
        "rand:o3",
        Algorithm::Lrs,
        38,
        19,
        1,
        0xa3d8a66b7f732e15,
        0x793a0dc37a439a07,
    ),
    (
        "rand:o3",
        Algorithm::PulliSegal,
        48,
        24,
        2,
        0x394a772604a0ff7e,
        0x99b1a1f1a607d50d,
    ),
    (
        "rand:o3",
        Algorithm::SimpleGreedy,
        396,
        198,
        2,
        0xf265c1ef4e84e4bf,
        0xd59c73eece3d0a76,
    ),
    (
        "rand:o3",
        Algorithm::Matching,
        3000,
        1500,
        2,
        0xcbf29ce484222325,
        0x6a4906c153eb8144,
    ),
    (
        "rand:n5",
        Algorithm::Lrs,
        34,
        17,
        1,
        // Re-pinned once: K's flips are made from each edge's canonical
        // corner, which changes face slots on surfaces whose faces are not consistently
        // oriented; the counters and the orientable pins are unchanged.
        0x3401144586e2cb86,
        0xc244bf3c9ce10790,
    ),
    (
        "rand:n5",
        Algorithm::PulliSegal,
        48,
        24,
        2,
        0xdf77a5dcfbf59459,
        0xa48726bed976626a,
    ),
    (
        "rand:n5",
        Algorithm::SimpleGreedy,
        404,
        202,
        3,
        0x5d66124accb6f7d0,
        0xec24f774a3298a6f,
    ),
    (
        "rand:n5",
        Algorithm::Matching,
        3000,
        1500,
        3,
        0xcbf29ce484222325,
        0x044e443ef766566e,
    ),
    (
        "B6",
        Algorithm::Lrs,
        4,
        2,
        1,
        0x264e19cac0527cbf,
        0xc60aaa97c5fcaebb,
    ),
    (
        "B6",
        Algorithm::PulliSegal,
        6,
        3,
        2,
        0xe6ba545746a805cb,
        0x993c4e6df4d993fc,
    ),
    (
        "B6",
        Algorithm::SimpleGreedy,
        8128,
        4064,
        3,
        0xeaf670bfc64d8c46,
        0xaf5b671b2ed55c42,
    ),
    (
        "B6",
        Algorithm::Matching,
        69552,
        34776,
        1,
        0xcbf29ce484222325,
        0x39288f3e875294a8,
    ),
    (
        "C5",
        Algorithm::Lrs,
        33428,
        16714,
        2,
        0xe81fb35411101b39,
        0xa7f279aa85336733,
    ),
    (
        "C5",
        Algorithm::PulliSegal,
        206,
        103,
        1,
        0x56c573ccceeb9435,
        0x995350a8ab527b4b,
    ),
    (
        "C5",
        Algorithm::SimpleGreedy,
        23892,
        11946,
        2,
        0xa208040bcb82337a,
        0xa805ffb98a95f596,
    ),
    (
        "C5",
        Algorithm::Matching,
        197056,
        98528,
        1,
        0xcbf29ce484222325,
        0x42fd99bd4a746e1c,
    ),
    (
        "data:bunny_npm",
        Algorithm::Lrs,
        4,
        2,
        1,
        0x5c635f5b501e5347,
        0x75e1122d5528e2b0,
    ),
    (
        "data:bunny_npm",
        Algorithm::PulliSegal,
        4,
        2,
        1,
        0x4124e001ebddf141,
        0x6b9e97bd38975a8e,
    ),
    (
        "data:bunny_npm",
        Algorithm::SimpleGreedy,
        436,
        218,
        2,
        0x9169c9bf5ce03d64,
        0xa7b848c7a4da4453,
    ),
    (
        "data:bunny_npm",
        Algorithm::Matching,
        3674,
        1837,
        2,
        0xcbf29ce484222325,
        0x9811c51f7e328366,
    ),
    (
        "data:letter",
        Algorithm::Lrs,
        16,
        8,
        1,
        0xc27429e5ddbe4c06,
        0x4331c83bc25026c1,
    ),
    (
        "data:letter",
        Algorithm::PulliSegal,
        6,
        3,
        1,
        0x361055d3048eaf1a,
        0xdeaeda6e6a1ff73a,
    ),
    (
        "data:letter",
        Algorithm::SimpleGreedy,
        1072,
        536,
        2,
        0x6d8aea3844e2a6e3,
        0xb8db957d87d6e611,
    ),
    (
        "data:letter",
        Algorithm::Matching,
        8832,
        4416,
        2,
        0xcbf29ce484222325,
        0x7746d15b0836c6b5,
    ),
    (
        "data:adis16480_stl",
        Algorithm::Lrs,
        244,
        122,
        2,
        0xb76256f1450ef8e8,
        0xc728c6add787571d,
    ),
    (
        "data:adis16480_stl",
        Algorithm::PulliSegal,
        12,
        6,
        1,
        0xf1dfe7b88eca2885,
        0x4d3980b5760699f5,
    ),
    (
        "data:adis16480_stl",
        Algorithm::SimpleGreedy,
        922,
        461,
        2,
        0x462fa04205d93e64,
        0x360eebb85ac2d20a,
    ),
    (
        "data:adis16480_stl",
        Algorithm::Matching,
        7436,
        3718,
        2,
        0xcbf29ce484222325,
        0x04f7ec9174e36cac,
    ),
    (
        "data:box_stl",
        Algorithm::Lrs,
        82,
        41,
        1,
        0xc22e3bfc80578d5e,
        0x89481e7db98cab04,
    ),
    (
        "data:box_stl",
        Algorithm::PulliSegal,
        22,
        11,
        1,
        0xf87534cab203a965,
        0x89d7bd8676484db3,
    ),
    (
        "data:box_stl",
        Algorithm::SimpleGreedy,
        188,
        94,
        3,
        0xacbdf45b117d1ad5,
        0xc8fef0ec1dfb2051,
    ),
    (
        "data:box_stl",
        Algorithm::Matching,
        1594,
        797,
        2,
        0xcbf29ce484222325,
        0xe972fa22b49b2c73,
    ),
];

/// Checks every pin of `pins`, building each input once with `build`.
fn check_pins(pins: &[Pin], build: impl Fn(&str) -> Triangulation) {
    const OPTIONS: Options = Options { seed: 1 };
    let mut current: Option<(&str, Triangulation)> = None;
    for &(name, alg, unpaired, paths, phases, fp_initial, fp_output) in pins {
        if current.as_ref().map(|c| c.0) != Some(name) {
            current = Some((name, build(name)));
        }
        let t = &current.as_ref().expect("input").1;
        let label = format!("{name} {}", alg.name());
        // The initial step through the module's own entry point.
        let (k0, p0) = match alg {
            Algorithm::Lrs => {
                let e = lrs::initial_pairing(t.clone());
                (e.tri, e.pairing)
            }
            Algorithm::PulliSegal => (t.clone(), pulli_segal::initial_pairing(t, &OPTIONS)),
            Algorithm::SimpleGreedy => (t.clone(), greedy::initial_pairing(t, &OPTIONS)),
            Algorithm::Matching => (t.clone(), matching::initial_pairing(t)),
            Algorithm::DsNaive
            | Algorithm::FrinkLct
            | Algorithm::DiksStanczyk
            | Algorithm::BiedlBoseDemaineLubiw => {
                unreachable!("not in PINS")
            }
        };
        assert_eq!(
            k0.face_count() - 2 * p0.len(),
            unpaired,
            "{label}: unpaired"
        );
        assert_eq!(
            fingerprint_pairing(&k0, &p0),
            fp_initial,
            "{label}: initial pairing changed"
        );
        // The whole pipeline, as the CLI runs it.
        let q = quad::convert(t.clone(), alg, &OPTIONS).expect("a closed triangulation");
        assert_eq!(q.pairing.check(&q.tri), Ok(()), "{label}");
        assert!(q.pairing.is_perfect(&q.tri), "{label}: perfect");
        assert_eq!(
            (
                q.stats.initial_unpaired,
                q.stats.augmenting_paths,
                q.stats.phases
            ),
            (unpaired, paths, phases),
            "{label}: counters"
        );
        assert_eq!(
            fingerprint_output(&q.tri, &q.pairing),
            fp_output,
            "{label}: output changed"
        );
    }
}

#[test]
fn outputs_are_those_of_the_unoptimised_implementation() {
    assert_eq!(PINS.len(), 4 * 8, "four algorithms on eight inputs");
    check_pins(PINS, build);
}

mod corpus {
    use super::*;

    /// The pins of the corpus mesh botijo (82,332 faces, genus 5).
    const PINS: &[Pin] = &[
        (
            "botijo",
            Algorithm::Lrs,
            66,
            33,
            1,
            0x53d666a94cd189fb,
            0x62e69497006bb02e,
        ),
        (
            "botijo",
            Algorithm::PulliSegal,
            6,
            3,
            1,
            0x8055c0e5834fdaa4,
            0x1636280d87895f22,
        ),
        (
            "botijo",
            Algorithm::SimpleGreedy,
            10314,
            5157,
            2,
            0x71373e06a08c01dd,
            0xffbdebdae82bfcd0,
        ),
        (
            "botijo",
            Algorithm::Matching,
            82332,
            41166,
            2,
            0xcbf29ce484222325,
            0xfc15a074ff232468,
        ),
    ];

    fn build(name: &str) -> Triangulation {
        assert_eq!(name, "botijo", "no corpus input {name}");
        let path = crate::common::corpus_meshes().join("closed/botijo.off.gz");
        largest_component(&contractible::io::read_tri_mesh(&path).expect("botijo reads"))
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn outputs_are_those_of_the_unoptimised_implementation() {
        check_pins(PINS, build);
    }
}
