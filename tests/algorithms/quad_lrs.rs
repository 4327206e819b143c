//! The LRS initial pairing (`quad::lrs`, tri-quad paper Sec. 3.3) checked by independent
//! code: `K` validates and has the input's vertex set and counts, differs from the input
//! by exactly `flips` edges (edge sets compared as vertex pairs), the pairing pairs
//! faces that share two vertices in `K`'s face lists, and exactly `n'_f` faces stay
//! unpaired, within the paper's bound (4 for genus 0, `56g − 12` for orientable genus
//! `g > 0`, `28h − 12` for Euler genus `h` non-orientable, from Joret–Wood's
//! `n'_v ≤ 13h − 4`).

use std::collections::HashSet;
use std::path::Path;

use crate::common;
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::lrs::{initial_pairing, Expansion};
#[cfg(any(debug_assertions, feature = "invariants"))]
use contractible::quad::lrs::{initial_pairing_variant, Variant};
use contractible::rng::Rng;
use contractible::{Surfaces, TriMesh, Triangulation, VertexId};

/// The edge set of a face list, as sorted vertex pairs.
fn edge_set(faces: &[[u32; 3]]) -> HashSet<(u32, u32)> {
    let mut s = HashSet::new();
    for f in faces {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            s.insert((a.min(b), a.max(b)));
        }
    }
    s
}

/// The faces of `t` by id (`None` for dead ids), from its face list.
fn faces_by_id(t: &Triangulation) -> Vec<Option<[u32; 3]>> {
    let mut out = vec![None; t.face_capacity()];
    for f in t.faces() {
        let [a, b, c] = t.face_vertices(f);
        out[f.index()] = Some([a.0, b.0, c.0]);
    }
    out
}

/// The paper's bound on the unpaired count, from the surface alone.
fn bound(input: &Triangulation) -> usize {
    let h = input.euler_genus();
    if h == 0 {
        4
    } else if input.is_orientable() {
        (56 * (h / 2) - 12) as usize
    } else {
        (28 * h - 12) as usize
    }
}

/// Every independent check of one run; returns the unpaired count.
fn check(input: &Triangulation, ex: &Expansion, label: &str) -> usize {
    let k = &ex.tri;
    k.validate()
        .unwrap_or_else(|e| panic!("{label}: K invalid: {e}"));
    assert_eq!(
        (k.vertex_count(), k.edge_count(), k.face_count()),
        (input.vertex_count(), input.edge_count(), input.face_count()),
        "{label}: counts"
    );
    let vin: Vec<_> = input.vertices().collect();
    let vk: Vec<_> = k.vertices().collect();
    assert_eq!(vin, vk, "{label}: vertex set");
    assert_eq!(
        k.euler_characteristic(),
        input.euler_characteristic(),
        "{label}"
    );
    assert_eq!(k.is_orientable(), input.is_orientable(), "{label}");
    // K differs from the input by exactly `flips` edges.
    let ein = edge_set(&input.face_list());
    let ek = edge_set(&k.face_list());
    assert_eq!(
        ein.difference(&ek).count(),
        ex.flips,
        "{label}: edges removed"
    );
    assert_eq!(
        ek.difference(&ein).count(),
        ex.flips,
        "{label}: edges added"
    );
    // The pairing: symmetric, live, mates share exactly two vertices in K's face lists.
    let faces = faces_by_id(k);
    let mut paired = 0;
    for f in k.faces() {
        let Some(g) = ex.pairing.mate(f) else {
            continue;
        };
        assert_eq!(ex.pairing.mate(g), Some(f), "{label}: asymmetric pair");
        assert_ne!(f, g, "{label}");
        let (Some(a), Some(b)) = (faces[f.index()], faces[g.index()]) else {
            panic!("{label}: pair ({f}, {g}) holds a dead face");
        };
        let shared = a.iter().filter(|x| b.contains(x)).count();
        assert_eq!(shared, 2, "{label}: {f} {a:?} and {g} {b:?} paired");
        paired += 1;
    }
    assert_eq!(paired, 2 * ex.pairing.len(), "{label}");
    let unpaired = k.face_count() - paired;
    assert_eq!(unpaired, ex.reduced_faces, "{label}: unpaired = n'_f");
    assert!(
        unpaired <= bound(input),
        "{label}: {unpaired} > bound {}",
        bound(input)
    );
    if input.euler_genus() == 0 {
        assert_eq!(unpaired, 4, "{label}: genus 0 leaves the tetrahedron's 4");
    }
    // One split per contraction: 2 faces and 3 edges each (Lemma 3.4 counts n_e − n'_e).
    assert_eq!(
        2 * ex.cases.splits,
        k.face_count() - ex.reduced_faces,
        "{label}"
    );
    assert_eq!(
        3 * ex.cases.splits,
        k.edge_count() - 3 * ex.reduced_faces / 2,
        "{label}"
    );
    unpaired
}

/// On small inputs, petgraph's dual graph and maximum matching as a second reference:
/// every pair is an edge of the dual of `K` (adjacency computed by petgraph's graph,
/// not by our face lists), and the dual of `K` has a perfect matching (Petersen), so the
/// completion has something to reach; ours is no larger.
fn check_with_petgraph(ex: &Expansion, label: &str) {
    let g = common::dual_graph(&ex.tri);
    let node_of: std::collections::HashMap<_, _> = g.node_indices().map(|n| (g[n], n)).collect();
    for (f, h) in ex.pairing.pairs() {
        assert!(
            g.find_edge(node_of[&f], node_of[&h]).is_some(),
            "{label}: pair ({f}, {h}) is not a dual edge"
        );
    }
    let max = petgraph::algo::maximum_matching(&g);
    assert_eq!(
        2 * max.len(),
        ex.tri.face_count(),
        "{label}: K's dual has a perfect matching"
    );
    assert!(ex.pairing.len() <= max.len(), "{label}");
}

fn surfaces() -> Vec<SurfaceKind> {
    let mut v: Vec<_> = (0..=8).map(SurfaceKind::Orientable).collect();
    v.extend((1..=6).map(SurfaceKind::NonOrientable));
    v
}

#[test]
fn random_surfaces() {
    let mut total = contractible::quad::lrs::Cases::default();
    for surface in surfaces() {
        for seed in 0..6u64 {
            for &(min_faces, flip_percent) in &[(200usize, 0u32), (600, 30), (2000, 60)] {
                let t = random(&RandomParams {
                    surface,
                    min_faces,
                    flip_percent,
                    seed,
                })
                .expect("a random surface within the limits");
                let label = format!("{surface:?} seed {seed} faces {min_faces}");
                let ex = initial_pairing(t.clone());
                check(&t, &ex, &label);
                if seed == 0 {
                    // Deterministic: a second run gives the same K and the same pairs.
                    let again = initial_pairing(t.clone());
                    assert_eq!(again.tri.face_list(), ex.tri.face_list(), "{label}");
                    assert!(again.pairing.pairs().eq(ex.pairing.pairs()), "{label}");
                }
                let c = ex.cases;
                // Every split takes exactly one branch of Alg. 3.1.
                assert_eq!(
                    c.splits,
                    c.line7 + c.degree3 + c.degree4 + c.degree4_flagged + c.degree_greater_than4,
                    "{label}: branches"
                );
                // Flags are set only on the two edges a split creates, so no edge is
                // flagged twice; each unflip clears one, and every flag left is flipped
                // (the flips counted against the edge sets by `check`).
                assert_eq!(ex.flips + c.unflips, c.flags_set, "{label}: flags");
                total.splits += c.splits;
                total.line7 += c.line7;
                total.degree3 += c.degree3;
                total.unflips += c.unflips;
                total.degree4 += c.degree4;
                total.degree4_flagged += c.degree4_flagged;
                total.degree_greater_than4 += c.degree_greater_than4;
                total.flags_set += c.flags_set;
            }
        }
    }
    eprintln!("{total:?}");
    // Every branch, and unflips, occur on these inputs (so the identities above are
    // tested on each).
    let t = total;
    for (n, what) in [
        (t.line7, "line 7"),
        (t.degree3, "degree 3"),
        (t.unflips, "unflips"),
        (t.degree4, "degree 4"),
        (t.degree4_flagged, "degree 4 flagged"),
        (t.degree_greater_than4, "degree > 4"),
    ] {
        assert!(n > 0, "{what} never ran: {total:?}");
    }
}

/// Runs `variant` on the input it is pinned to (the first input of
/// [`random_surfaces`]' order that trips it) and asserts the statement its panic names.
/// Exists only where the checks are compiled in, as do the tests that call it.
#[cfg(any(debug_assertions, feature = "invariants"))]
fn assert_variant_caught(
    variant: Variant,
    surface: SurfaceKind,
    min_faces: usize,
    statement: &str,
) {
    let t = random(&RandomParams {
        surface,
        min_faces,
        flip_percent: if min_faces == 200 { 0 } else { 30 },
        seed: 0,
    })
    .expect("a random surface within the limits");
    let err = std::panic::catch_unwind(|| initial_pairing_variant(t, variant))
        .expect_err("the mutation must be caught");
    let msg = err
        .downcast_ref::<String>()
        .cloned()
        .unwrap_or_else(|| "non-string panic".into());
    assert!(
        msg.starts_with("specification violated: ") && msg.contains(statement),
        "expected {statement}, got {msg}"
    );
}

#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn mutation_skipping_the_unflip_of_alg_3_2_is_caught() {
    assert_variant_caught(
        Variant {
            skip_unflip: true,
            ..Variant::default()
        },
        SurfaceKind::Orientable(0),
        200,
        "L3 (Prop. 3.3 (ii)): the inserted edge is not flipped",
    );
}

#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn mutation_ignoring_the_flags_at_degree_4_is_caught() {
    assert_variant_caught(
        Variant {
            degree4_ignores_flags: true,
            ..Variant::default()
        },
        SurfaceKind::Orientable(0),
        600,
        "L1 (Alg. 3.1): one new edge in M per split",
    );
}

#[cfg(any(debug_assertions, feature = "invariants"))]
#[test]
fn mutation_materialising_k_in_reverse_flag_order_is_caught() {
    // The flags do not commute (spec/ERRATA.md T6): K is the flips in the order made.
    assert_variant_caught(
        Variant {
            materialise_reversed: true,
            ..Variant::default()
        },
        SurfaceKind::Orientable(0),
        200,
        "L7 (Claim 3.1 (ii)): M* is a matching of K_i",
    );
}

/// Grows `t` by `splits` random vertex splits (a random vertex, two distinct random
/// neighbours), seeded.
fn random_splits(mut t: Triangulation, splits: usize, seed: u64) -> Triangulation {
    let mut rng = Rng::new(seed);
    for _ in 0..splits {
        let vs: Vec<VertexId> = t.vertices().collect();
        let u = vs[rng.index(vs.len())];
        let link: Vec<VertexId> = t.link(u).collect();
        let i = rng.index(link.len());
        let j = (i + 1 + rng.index(link.len() - 1)) % link.len();
        t.split_vertex(u, link[i], link[j])
            .expect("distinct neighbours");
    }
    t
}

/// LRS on every small published surface and on random vertex splits of it (1, 5 and 40
/// splits, 8 seeds). Also the exhaustive twins of the `quad_ops` fuzz target: on the same
/// surfaces (the published ones and their 1-, 5- and 40-split ones of split seeds 0..3),
/// every algorithm with seeds 0..4 through the fuzz harness's checks
/// (`quad_qfuzz::check_every_algorithm`).
#[test]
fn every_small_surface_and_random_splits_of_it() {
    let mut irreducible = 0;
    let mut twins = 0;
    for file in [
        "surfaces-upto-8-vertices.txt",
        "torus.txt",
        "projective-plane.txt",
    ] {
        for s in common::read_surface_list(file) {
            let t = Triangulation::from_faces(s.vertex_count, &s.faces)
                .unwrap_or_else(|e| panic!("{}: {e}", s.name));
            let label = format!("{file}: {}", s.name);
            let ex = initial_pairing(t.clone());
            check(&t, &ex, &label);
            check_with_petgraph(&ex, &label);
            twins += crate::quad_qfuzz::check_every_algorithm(&t, &label);
            // Published irreducible surfaces: nothing to expand, nothing paired.
            let is_irreducible = !s.name.contains("_red_");
            if is_irreducible {
                irreducible += 1;
                assert_eq!(ex.cases.splits, 0, "{label}");
                assert_eq!((ex.flips, ex.pairing.len()), (0, 0), "{label}");
                assert_eq!(ex.reduced_faces, t.face_count(), "{label}");
                assert_eq!(ex.tri.face_list(), t.face_list(), "{label}: K = T");
            } else {
                assert!(ex.cases.splits > 0, "{label}: a reducible surface expands");
            }
            for seed in 0..8u64 {
                for splits in [1usize, 5, 40] {
                    let grown = random_splits(t.clone(), splits, seed);
                    let label = format!("{label} + {splits} splits (seed {seed})");
                    let ex = initial_pairing(grown.clone());
                    check(&grown, &ex, &label);
                    if splits <= 5 {
                        check_with_petgraph(&ex, &label);
                    }
                    if seed < 4 {
                        twins += crate::quad_qfuzz::check_every_algorithm(&grown, &label);
                    }
                }
            }
        }
    }
    assert_eq!(irreducible, 14 + 21 + 2, "irreducible surfaces seen");
    // 80 surfaces, each published and with 12 grown versions, every algorithm x 5 seeds.
    assert_eq!(
        twins,
        80 * 13 * 5 * crate::harness::QUAD_ALGORITHMS.len(),
        "conversions checked by the twins"
    );
}

/// LRS on every component of `mesh` ([`check`]); returns the components and flips.
fn lrs_on_every_component(mesh: &TriMesh, name: &str) -> (usize, usize) {
    let surfaces = Surfaces::from_mesh(mesh).unwrap_or_else(|e| panic!("{name}: {e}"));
    let mut flips = 0;
    for (k, comp) in surfaces.components.iter().enumerate() {
        let label = format!("{name} component {k}");
        let ex = initial_pairing(comp.tri.clone());
        check(&comp.tri, &ex, &label);
        flips += ex.flips;
    }
    (surfaces.components.len(), flips)
}

/// LRS on every component of every mesh of `meshes/closed` (at least `min_files`).
fn every_closed_mesh_component_of(meshes: &Path, min_files: usize) {
    let dir = meshes.join("closed");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .collect();
    files.sort();
    assert!(
        files.len() >= min_files,
        "{} meshes in {}",
        files.len(),
        dir.display()
    );
    let mut components = 0;
    let mut flips = 0;
    for path in &files {
        let name = path
            .file_name()
            .expect("file")
            .to_string_lossy()
            .to_string();
        let mesh = contractible::io::read_tri_mesh(path).unwrap_or_else(|e| panic!("{name}: {e}"));
        let (c, f) = lrs_on_every_component(&mesh, &name);
        components += c;
        flips += f;
    }
    assert!(components >= files.len());
    eprintln!("{components} components, {flips} flips");
}

/// Every component of every closed mesh the repository carries.
#[test]
fn every_repository_closed_mesh_component() {
    every_closed_mesh_component_of(&common::data_meshes(), 9);
}

/// Every component of the generated closed surfaces of `closed_inputs` (orientable and
/// not: the bound differs).
#[test]
fn every_generated_closed_surface_component() {
    let mut components = 0;
    for g in crate::closed_inputs::closed_surfaces() {
        components += lrs_on_every_component(&g.mesh, &g.name).0;
    }
    assert_eq!(components, crate::closed_inputs::COMPONENTS);
}

/// Erratum T7 (`spec/ERRATA.md`): Lemma 3.4's proof says the unmatched faces of `K` are
/// "the faces in T', which are also in K". As triangles (vertex triples) most are not:
/// splits hand `T'`'s faces to split-off vertices and flips change them (Alg. 3.2 l.8,
/// the proof's own Case 2.1: "[x, y, z] stays unmatched"). What holds exactly is the
/// face-record reading: the unmatched faces are the face ids of `T'`.
#[test]
fn erratum_unmatched_faces_of_k_are_not_the_faces_of_t_prime() {
    let (mut unmatched, mut not_in_t_prime, mut ids_not_in_t_prime) = (0usize, 0usize, 0usize);
    for surface in surfaces() {
        for seed in 0..3u64 {
            let t = random(&RandomParams {
                surface,
                min_faces: 600,
                flip_percent: 30,
                seed,
            })
            .expect("a random surface within the limits");
            let reduced = contractible::irreducible::rs::reduce(
                t.clone(),
                &contractible::irreducible::Options::default(),
            );
            let tp: HashSet<[u32; 3]> = reduced
                .tri
                .face_list()
                .into_iter()
                .map(|mut f| {
                    f.sort_unstable();
                    f
                })
                .collect();
            let ex = initial_pairing(t);
            for f in ex.pairing.unpaired(&ex.tri) {
                ids_not_in_t_prime += usize::from(!reduced.tri.is_face(f));
                let mut vs = ex.tri.face_vertices(f).map(|v| v.0);
                vs.sort_unstable();
                unmatched += 1;
                not_in_t_prime += usize::from(!tp.contains(&vs));
            }
        }
    }
    eprintln!("{not_in_t_prime} of {unmatched} unmatched faces are not faces of T' ({ids_not_in_t_prime} by id)");
    assert!(not_in_t_prime > 0);
    assert_eq!(ids_not_in_t_prime, 0);
}

mod corpus {
    use super::*;

    /// Every component of every closed corpus mesh.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_closed_mesh_component() {
        every_closed_mesh_component_of(&common::corpus_meshes(), 90);
    }
}
