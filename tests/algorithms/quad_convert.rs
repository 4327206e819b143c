//! `quad::convert` end to end, every algorithm (initial step + completion), on every
//! component of every shared closed mesh and on random surfaces of genus 0..8 and
//! cross-caps 1..6, checked by code that shares nothing with the algorithms: the fuzz
//! harness's `check_quadrangulation` (face lists, pairs and quads only) and, on inputs up
//! to 2,000 faces, petgraph's `maximum_matching` of the dual graph (F/2 edges: a perfect
//! matching exists, so "perfect" is the right target).

use crate::{common, harness};
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::{convert, Algorithm, Options, Quadrangulation};
use contractible::{Surfaces, Triangulation};

const ALGORITHMS: [Algorithm; 4] = [
    Algorithm::Lrs,
    Algorithm::Ps,
    Algorithm::Sg,
    Algorithm::Matching,
];

/// The fuzz harness's independent check (K rebuilt and compared by face lists, the
/// pairing, the quads as a closed 2-manifold with the input's χ and orientability, the
/// counters), plus petgraph's maximum matching size on small inputs.
fn check(input: &Triangulation, q: &Quadrangulation, label: &str) {
    harness::check_quadrangulation(input, q, label);
    if q.tri.face_count() <= 2000 {
        let g = common::dual_graph(&q.tri);
        let m = petgraph::algo::maximum_matching(&g);
        assert_eq!(
            2 * m.edges().count(),
            q.tri.face_count(),
            "{label}: petgraph"
        );
    }
}

#[test]
fn every_algorithm_on_random_surfaces_of_every_kind() {
    let kinds = (0..=8)
        .map(SurfaceKind::Orientable)
        .chain((1..=6).map(SurfaceKind::NonOrientable));
    for kind in kinds {
        for (seed, faces) in [(1u64, 300usize), (2, 1500), (3, 6000)] {
            let input = random(&RandomParams {
                surface: kind,
                min_faces: faces,
                flip_percent: 25,
                seed,
            });
            for algo in ALGORITHMS {
                let q = convert(input.clone(), algo, &Options { seed });
                check(&input, &q, &format!("{kind:?} seed {seed} {}", algo.name()));
            }
        }
    }
}

#[test]
fn every_algorithm_on_every_component_of_every_shared_mesh() {
    let dir = common::shared_dir().join("meshes/closed");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("meshes/closed")
        .map(|e| e.expect("entry").path())
        .collect();
    files.sort();
    let mut components = 0;
    for path in files {
        let mesh = contractible::io::read_tri_mesh(&path).expect("readable");
        let surfaces = Surfaces::from_mesh(&mesh).expect("closed");
        for (i, c) in surfaces.components.iter().enumerate() {
            for algo in ALGORITHMS {
                let q = convert(c.tri.clone(), algo, &Options { seed: 1 });
                let label = format!("{} #{i} {}", path.display(), algo.name());
                check(&c.tri, &q, &label);
            }
            components += 1;
        }
    }
    assert!(components >= 100, "{components} components");
}

#[test]
fn the_same_input_and_seed_give_the_same_quads() {
    let input = random(&RandomParams {
        surface: SurfaceKind::NonOrientable(3),
        min_faces: 4000,
        flip_percent: 25,
        seed: 9,
    });
    for algo in ALGORITHMS {
        let a = convert(input.clone(), algo, &Options { seed: 4 });
        let b = convert(input.clone(), algo, &Options { seed: 4 });
        assert_eq!(a.pairing, b.pairing, "{}", algo.name());
        assert_eq!(a.tri, b.tri, "{}", algo.name());
        assert_eq!(a.stats.flips, b.stats.flips);
        assert_eq!(a.stats.augmenting_paths, b.stats.augmenting_paths);
    }
}
