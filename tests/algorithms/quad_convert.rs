//! `quad::convert` end to end, every algorithm (initial step + completion), on every
//! component of every shared closed mesh and on random surfaces of genus 0..8 and
//! cross-caps 1..6, checked by code that shares nothing with the algorithms:
//!
//! - `K` rebuilt from its face list by `Triangulation::from_faces` (full validation) has
//!   the input's vertex set and counts, and the input's χ and orientability by the
//!   face-list oracle `spec::oracle::euler_and_orientability`;
//! - `K` differs from the input by at most `2 · flips` edges (as vertex pairs), and not
//!   at all for the algorithms that do not flip;
//! - the pairs cover every face of `K` exactly once and each shares exactly two vertices
//!   in `K`'s face lists;
//! - the quads (`quad_faces`) have four distinct vertices and every quad edge lies in
//!   exactly two quads;
//! - on inputs up to 2,000 faces, petgraph's `maximum_matching` of the dual graph has
//!   F/2 edges (a perfect matching exists, so "perfect" is the right target).

use std::collections::{HashMap, HashSet};

use crate::common;
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::{convert, quad_faces, Algorithm, Options, Quadrangulation};
use contractible::spec::oracle::euler_and_orientability;
use contractible::{Surfaces, Triangulation};

const ALGORITHMS: [Algorithm; 4] = [
    Algorithm::Lrs,
    Algorithm::Ps,
    Algorithm::Sg,
    Algorithm::Matching,
];

fn edge_set(faces: &[[u32; 3]]) -> HashSet<(u32, u32)> {
    faces
        .iter()
        .flat_map(|f| (0..3).map(move |k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3]))))
        .collect()
}

fn check(input: &Triangulation, q: &Quadrangulation, label: &str) {
    let in_faces = input.face_list();
    let k_faces = q.tri.face_list();
    let rebuilt = Triangulation::from_faces(q.tri.vertex_capacity(), &k_faces);
    // Removed vertex ids make `from_faces` report unused vertices; compare the sets.
    if input.vertex_count() == input.vertex_capacity() {
        let r = rebuilt.unwrap_or_else(|e| panic!("{label}: K is not a surface: {e}"));
        assert_eq!(r.face_count(), input.face_count(), "{label}");
    }
    assert!(q.tri.vertices().eq(input.vertices()), "{label}: vertex set");
    assert_eq!(k_faces.len(), in_faces.len(), "{label}: face count");
    assert_eq!(
        euler_and_orientability(&k_faces),
        euler_and_orientability(&in_faces),
        "{label}: χ and orientability"
    );
    let (ei, ek) = (edge_set(&in_faces), edge_set(&k_faces));
    let changed = ei.difference(&ek).count();
    assert_eq!(changed, ek.difference(&ei).count());
    if q.algorithm == Algorithm::Lrs {
        assert!(changed <= q.stats.flips, "{label}: {changed} edges changed");
    } else {
        assert_eq!((changed, q.stats.flips), (0, 0), "{label}: only LRS flips");
    }

    // Pairs, from K's face lists by id.
    let by_id: HashMap<u32, [u32; 3]> = q
        .tri
        .faces()
        .map(|f| (f.0, q.tri.face_vertices(f).map(|v| v.0)))
        .collect();
    let mut seen = HashSet::new();
    let mut pairs = 0;
    for (f, g) in q.pairing.pairs() {
        let (a, b) = (by_id[&f.0], by_id[&g.0]);
        assert_eq!(a.iter().filter(|v| b.contains(v)).count(), 2, "{label}");
        assert!(
            seen.insert(f.0) && seen.insert(g.0),
            "{label}: a face twice"
        );
        pairs += 1;
    }
    assert_eq!(2 * pairs, k_faces.len(), "{label}: not perfect");
    assert_eq!(
        q.stats.initial_unpaired,
        k_faces.len() - 2 * (pairs - q.stats.augmenting_paths),
        "{label}: each augmenting path adds one pair"
    );

    let quads = quad_faces(&q.tri, &q.pairing).expect("perfect");
    let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
    for quad in &quads {
        let mut s = *quad;
        s.sort_unstable();
        assert!(s.windows(2).all(|w| w[0] != w[1]), "{label}: {quad:?}");
        for i in 0..4 {
            let (a, b) = (quad[i], quad[(i + 1) % 4]);
            *uses.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    assert!(uses.values().all(|&n| n == 2), "{label}: quad edges");
    let v = quads.iter().flatten().collect::<HashSet<_>>().len() as i64;
    assert_eq!(
        v - uses.len() as i64 + quads.len() as i64,
        input.euler_characteristic(),
        "{label}: χ of the quad mesh"
    );

    if k_faces.len() <= 2000 {
        let g = common::dual_graph(&q.tri);
        let m = petgraph::algo::maximum_matching(&g);
        assert_eq!(2 * m.edges().count(), k_faces.len(), "{label}: petgraph");
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
