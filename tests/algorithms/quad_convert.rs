//! `quad::convert` end to end, every algorithm (initial step + completion), on every
//! component of every closed mesh the repository carries, of the generated closed
//! surfaces of `closed_inputs`, in the ignored `corpus` tests of every closed corpus mesh,
//! and on random surfaces of genus 0..8 and cross-caps 1..6, checked by code that shares
//! nothing with the algorithms: the fuzz harness's `check_quadrangulation` (face lists,
//! pairs and quads only) and, on inputs up to 2,000 faces, petgraph's
//! `maximum_matching` of the dual graph (F/2 edges: a perfect matching exists, so
//! "perfect" is the right target).

use crate::{common, harness};
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::{convert, Algorithm, Options, Quadrangulation};
use contractible::{Surfaces, TriMesh, Triangulation};
use std::path::Path;

const ALGORITHMS: [Algorithm; 4] = [
    Algorithm::Lrs,
    Algorithm::PulliSegal,
    Algorithm::SimpleGreedy,
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
            })
            .expect("a random surface within the limits");
            for algo in ALGORITHMS {
                let q = convert(input.clone(), algo, &Options { seed })
                    .expect("a closed triangulation");
                check(&input, &q, &format!("{kind:?} seed {seed} {}", algo.name()));
            }
        }
    }
}

/// Every algorithm on every component of `mesh`; returns the number of components.
fn every_algorithm_on_every_component(mesh: &TriMesh, name: &str) -> usize {
    let surfaces = Surfaces::from_mesh(mesh).unwrap_or_else(|e| panic!("{name}: {e}"));
    for (i, c) in surfaces.components.iter().enumerate() {
        for algo in ALGORITHMS {
            let q =
                convert(c.tri.clone(), algo, &Options { seed: 1 }).expect("a closed triangulation");
            let label = format!("{name} #{i} {}", algo.name());
            check(&c.tri, &q, &label);
        }
    }
    surfaces.components.len()
}

/// Every mesh of `meshes/closed`; returns the number of components.
fn every_component_of_every_closed_mesh_of(meshes: &Path) -> usize {
    let dir = meshes.join("closed");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("entry").path())
        .collect();
    files.sort();
    let mut components = 0;
    for path in files {
        let mesh = contractible::io::read_tri_mesh(&path).expect("readable");
        components += every_algorithm_on_every_component(&mesh, &path.display().to_string());
    }
    components
}

/// Every closed mesh the repository carries (as many components as its manifest lists)
/// and every generated closed surface of `closed_inputs`.
#[test]
fn every_algorithm_on_every_component_of_the_repository_and_generated_meshes() {
    let listed: usize = common::data_manifest()
        .iter()
        .filter(|r| r.set == "closed")
        .map(|r| r.components)
        .sum();
    let components = every_component_of_every_closed_mesh_of(&common::data_meshes());
    assert_eq!(components, listed, "components of the repository's meshes");
    assert!(components >= 20, "{components} components");
    let mut generated = 0;
    for g in crate::closed_inputs::closed_surfaces() {
        generated += every_algorithm_on_every_component(&g.mesh, &g.name);
    }
    assert_eq!(generated, crate::closed_inputs::COMPONENTS);
}

#[test]
fn the_same_input_and_seed_give_the_same_quads() {
    let input = random(&RandomParams {
        surface: SurfaceKind::NonOrientable(3),
        min_faces: 4000,
        flip_percent: 25,
        seed: 9,
    })
    .expect("a random surface within the limits");
    for algo in ALGORITHMS {
        let a = convert(input.clone(), algo, &Options { seed: 4 }).expect("a closed triangulation");
        let b = convert(input.clone(), algo, &Options { seed: 4 }).expect("a closed triangulation");
        assert_eq!(a.pairing, b.pairing, "{}", algo.name());
        assert_eq!(a.tri, b.tri, "{}", algo.name());
        assert_eq!(a.stats.flips, b.stats.flips);
        assert_eq!(a.stats.augmenting_paths, b.stats.augmenting_paths);
    }
}

mod corpus {
    use super::*;

    /// Every component of every closed corpus mesh.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_algorithm_on_every_component_of_every_shared_mesh() {
        let components = every_component_of_every_closed_mesh_of(&common::corpus_meshes());
        assert!(components >= 100, "{components} components");
    }
}
