//! The greedy initial pairings of the tri-quad paper (Sec. 3.1): SG (`quad::greedy`) and
//! PS (`quad::pulli_segal`), checked by code that does not share theirs.
//!
//! - **Pairing**: `Pairing::check` and, independently, from `pairs()` and the face
//!   vertices alone: each pair's two faces are live and share exactly two vertices (an
//!   edge: distinct faces of a closed triangulation never share three), every face
//!   occurs in at most one pair, and `mate` agrees with `pairs()`.
//! - **Maximality**: no edge of the petgraph dual graph (`common::dual_graph`) has both
//!   faces unpaired, unpaired meaning "in no pair of `pairs()`".
//! - **Size**: on small inputs, never more pairs than petgraph's `maximum_matching`, and
//!   at least half of it (a maximal matching has at least half the maximum size).
//! - **Determinism**: the same seed gives the same pairing; different seeds give
//!   different pairings on all but tiny inputs.
//! - **Quality** on every component of every real mesh: SG pairs 85–90% of the faces of
//!   each mesh of at least 10k faces (the paper: 87.45–87.86%), PS at least 99% (the
//!   paper: α ≤ 0.0021). By default the meshes the repository carries and their
//!   subdivisions to 10k faces or more; in the ignored `corpus` tests every closed corpus
//!   mesh. The measured distribution is printed (`--nocapture`) and, for the corpus,
//!   recorded in `spec/quad.md`.
//!
//! Inputs: random surfaces of genus 0..8 and 1..6 cross-caps, the meshes, and proptest
//! cases over random surfaces.

use crate::common;

use std::path::Path;

use contractible::gen::{random, subdivide, RandomParams, SurfaceKind};
use contractible::quad::{greedy, pulli_segal, Options, Pairing};
use contractible::{Surfaces, TriMesh, Triangulation};
use petgraph::algo::maximum_matching;
use petgraph::visit::EdgeRef;
use proptest::prelude::*;

type Algo = fn(&Triangulation, &Options) -> Pairing;
const ALGOS: [(&str, Algo); 2] = [
    ("SG", greedy::initial_pairing),
    ("PS", pulli_segal::initial_pairing),
];

/// Largest input on which petgraph's (cubic worst case) maximum matching is compared.
const PETGRAPH_CAP: usize = 2_500;

/// Checks `p` on `t` independently of the algorithms (see the module documentation);
/// returns the number of paired faces.
fn check_pairing(t: &Triangulation, p: &Pairing, label: &str) -> usize {
    assert_eq!(p.check(t), Ok(()), "{label}");
    let mut times = vec![0u32; t.face_capacity()];
    let mut paired = 0;
    for (f, g) in p.pairs() {
        assert!(t.is_face(f) && t.is_face(g), "{label}: pair ({f}, {g})");
        let a = t.face_vertices(f);
        let shared = t.face_vertices(g).iter().filter(|v| a.contains(v)).count();
        assert_eq!(
            shared, 2,
            "{label}: pair ({f}, {g}) shares {shared} vertices"
        );
        times[f.index()] += 1;
        times[g.index()] += 1;
        paired += 2;
    }
    for f in t.faces() {
        let k = times[f.index()];
        assert!(k <= 1, "{label}: {f} in {k} pairs");
        assert_eq!(p.mate(f).is_some(), k == 1, "{label}: mate({f}) vs pairs()");
    }
    assert_eq!(paired, 2 * p.len(), "{label}");
    // Maximality on the petgraph dual graph.
    let g = common::dual_graph(t);
    for e in g.edge_references() {
        let (fa, fb) = (g[e.source()], g[e.target()]);
        assert!(
            times[fa.index()] + times[fb.index()] > 0,
            "{label}: dual edge {fa}-{fb} has both faces unpaired"
        );
    }
    if t.face_count() <= PETGRAPH_CAP {
        let max = maximum_matching(&g).edges().count();
        assert!(p.len() <= max, "{label}: {} pairs > maximum {max}", p.len());
        assert!(
            2 * p.len() >= max,
            "{label}: {} pairs < maximum {max} / 2",
            p.len()
        );
    }
    paired
}

fn surfaces() -> Vec<SurfaceKind> {
    let mut v: Vec<SurfaceKind> = (0..=8).map(SurfaceKind::Orientable).collect();
    v.extend((1..=6).map(SurfaceKind::NonOrientable));
    v
}

fn random_surface(surface: SurfaceKind, min_faces: usize, seed: u64) -> Triangulation {
    random(&RandomParams {
        surface,
        min_faces,
        flip_percent: 30,
        seed,
    })
    .expect("a random surface within the limits")
}

/// Runs both algorithms on `t` for `seeds`: checks every output and determinism;
/// returns the paired faces per algorithm, summed over the seeds.
fn run_both(t: &Triangulation, seeds: std::ops::Range<u64>, label: &str) -> [usize; 2] {
    let mut total = [0; 2];
    for (i, (name, algo)) in ALGOS.iter().enumerate() {
        let mut distinct: Vec<Pairing> = Vec::new();
        for seed in seeds.clone() {
            let opts = Options { seed };
            let p = algo(t, &opts);
            let label = format!("{name} {label} seed {seed}");
            total[i] += check_pairing(t, &p, &label);
            assert_eq!(p, algo(t, &opts), "{label}: not deterministic");
            if !distinct.contains(&p) {
                distinct.push(p);
            }
        }
        if seeds.end - seeds.start >= 2 && t.face_count() >= 100 {
            assert!(
                distinct.len() >= 2,
                "{name} {label}: every seed gave the same pairing"
            );
        }
    }
    total
}

#[test]
fn random_surfaces_of_every_kind() {
    let mut rows = Vec::new();
    for (k, surface) in surfaces().into_iter().enumerate() {
        for min_faces in [60, 1_000, 20_000] {
            let t = random_surface(surface, min_faces, 500 + k as u64);
            let seeds = if min_faces > 5_000 { 0..2 } else { 0..4 };
            let runs = (seeds.end - seeds.start) as f64;
            let paired = run_both(&t, seeds, &format!("{surface:?} F={}", t.face_count()));
            let pct = paired.map(|p| 100.0 * p as f64 / (runs * t.face_count() as f64));
            if min_faces == 20_000 {
                // SG is insensitive to the input: the paper's band holds here too.
                assert!((85.0..=90.0).contains(&pct[0]), "SG {surface:?}: {pct:?}");
                // PS is not: these surfaces are far less regular than scanned meshes
                // (about 19% degree-3 vertices), and PS pairs 98.07–98.34% of them, below
                // the paper's 99% (see spec/quad.md). 97.5% is a regression guard.
                assert!(pct[1] >= 97.5, "PS {surface:?}: {pct:?}");
                rows.push((surface, t.face_count(), pct));
            }
        }
    }
    println!("random surfaces (≥ 20k faces), % paired, mean of seeds 0 and 1:");
    for (s, f, [sg, ps]) in &rows {
        println!("  {s:?}: F = {f}, SG {sg:.3}%, PS {ps:.4}%");
    }
}

/// Min, median, max of `v`.
fn spread(mut v: Vec<f64>) -> (f64, f64, f64) {
    v.sort_by(f64::total_cmp);
    (v[0], v[v.len() / 2], v[v.len() - 1])
}

/// What [`pairing_quality`] found over several meshes.
#[derive(Default)]
struct Quality {
    components: usize,
    /// SG and PS % paired of each mesh of at least 10k faces.
    large: Vec<[f64; 2]>,
    /// The meshes of at least 10k faces outside the paper's bands.
    exceptions: Vec<String>,
}

/// Both algorithms on every component of `mesh` ([`run_both`]), and the paper's bands on
/// the whole mesh if it has at least 10k faces.
fn pairing_quality(mesh: &TriMesh, name: &str, q: &mut Quality) {
    let surfaces = Surfaces::from_mesh(mesh).unwrap_or_else(|e| panic!("{name}: {e}"));
    let (mut faces, mut paired) = (0, [0usize; 2]);
    for (k, c) in surfaces.components.iter().enumerate() {
        // Two seeds on the small components, one on the large (determinism and
        // seed-dependence are covered on the random surfaces too).
        let seeds = if c.tri.face_count() > 20_000 {
            0..1
        } else {
            0..2
        };
        let p = run_both(&c.tri, seeds.clone(), &format!("{name}[{k}]"));
        let runs = (seeds.end - seeds.start) as usize;
        faces += c.tri.face_count();
        for i in 0..2 {
            paired[i] += p[i] / runs;
        }
        q.components += 1;
    }
    let pct = paired.map(|p| 100.0 * p as f64 / faces as f64);
    println!(
        "{name}, {faces}, {}, {:.3}, {:.4}",
        surfaces.components.len(),
        pct[0],
        pct[1]
    );
    if faces >= 10_000 {
        if !(85.0..=90.0).contains(&pct[0]) || pct[1] < 99.0 {
            q.exceptions.push(format!("{name} (F = {faces}): {pct:?}"));
        }
        q.large.push(pct);
    }
}

/// [`pairing_quality`] on every closed mesh of the manifest of `meshes`.
fn every_closed_mesh_of(meshes: &Path, q: &mut Quality) {
    println!("mesh, faces, components, SG % paired, PS % paired (seed 0)");
    for row in common::manifest_in(meshes)
        .iter()
        .filter(|r| r.set == "closed")
    {
        let path = meshes.join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        pairing_quality(&mesh, &row.name, q);
    }
}

/// Prints the spread over the meshes of at least 10k faces.
fn print_spread(q: &Quality) {
    let (sg, ps): (Vec<f64>, Vec<f64>) = q.large.iter().map(|p| (p[0], p[1])).unzip();
    println!(
        "{} meshes of ≥ 10k faces: SG min/median/max {:.3?}, PS {:.4?}",
        q.large.len(),
        spread(sg),
        spread(ps)
    );
}

/// The closed meshes the repository carries (all below 10k faces: the checks without
/// the bands), and each of those of at least 1,000 faces subdivided until it has 10k
/// faces or more (1-to-4 subdivision of a real mesh is as regular as a finer scan: the
/// bands must hold on it).
#[test]
fn every_repository_mesh_and_its_subdivisions() {
    let mut q = Quality::default();
    every_closed_mesh_of(&common::data_meshes(), &mut q);
    assert!(q.components >= 20, "{} components", q.components);
    assert!(q.large.is_empty(), "no repository mesh has 10k faces");
    let mut subdivided = 0;
    for row in common::data_manifest()
        .iter()
        .filter(|r| r.set == "closed" && r.f >= 1_000)
    {
        let mut mesh = contractible::io::read_tri_mesh(&common::data_meshes().join(&row.file))
            .unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let mut levels = 0;
        while mesh.faces.len() < 10_000 {
            mesh = subdivide(&mesh, 1).expect("a valid mesh within the limits");
            levels += 1;
        }
        pairing_quality(&mesh, &format!("{} subdivided {levels}", row.name), &mut q);
        subdivided += 1;
    }
    print_spread(&q);
    assert_eq!(subdivided, 7);
    assert_eq!(q.large.len(), subdivided, "meshes of at least 10k faces");
    assert!(
        q.exceptions.is_empty(),
        "outside the paper's bands: {:#?}",
        q.exceptions
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Both algorithms give a valid maximal pairing, deterministically, on any random
    /// surface and seed.
    #[test]
    fn maximal_and_deterministic_on_random_surfaces(
        kind in 0usize..15,
        min_faces in 4usize..1_500,
        gen_seed in any::<u64>(),
        seed in any::<u64>(),
    ) {
        let t = random_surface(surfaces()[kind], min_faces, gen_seed);
        for (name, algo) in ALGOS {
            let opts = Options { seed };
            let p = algo(&t, &opts);
            check_pairing(&t, &p, &format!("{name} kind {kind} F {}", t.face_count()));
            prop_assert_eq!(&p, &algo(&t, &opts));
        }
    }
}

mod corpus {
    use super::*;

    /// Every closed corpus mesh; the paper's bands on each of at least 10k faces.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_real_mesh() {
        let mut q = Quality::default();
        every_closed_mesh_of(&common::corpus_meshes(), &mut q);
        print_spread(&q);
        assert!(q.components >= 100, "{} components", q.components);
        assert!(q.large.len() >= 50, "{} large meshes", q.large.len());
        assert!(
            q.exceptions.is_empty(),
            "outside the paper's bands: {:#?}",
            q.exceptions
        );
    }
}
