//! petgraph as the independent reference for the core's combinatorics.
//!
//! - **Critical cycles**: the vertex–edge graph of the triangulation is built as a
//!   `petgraph::graph::UnGraph`; every 3-cycle is enumerated from petgraph adjacency
//!   (`neighbors`, `find_edge`), the ones bounding a face (face set from `face_list`) are
//!   discarded, and the rest are counted per edge. The counts must equal
//!   `spec::oracle::critical_cycles_through` on every edge, and Theorem 3 must hold
//!   against the link tests: the naive link condition, `is_contractible` and the marked
//!   `LinkTester` all say "contractible" iff the count is 0 and the surface is not T4.
//!   Inputs: the 57 small surfaces, the published tori and projective planes, random
//!   surfaces of genus 0..8 and non-orientable genus 1..6 (100 and 2000 faces), and real
//!   meshes (every edge): every closed mesh the repository carries, and in the ignored
//!   `corpus` tests the corpus meshes socket, casting, double_torus, helmet, fertility.
//!   After random contraction sequences: **every step** on the small inputs (the 57
//!   surfaces, the published lists, the 100-face random surfaces); **sampled** on the
//!   large ones (every 100th contraction and the final state for the 2000-face random
//!   surfaces; every 500th and the final state on the real meshes).
//! - **Perfect matchings of the dual graph** (`common::dual_graph`,
//!   `petgraph::algo::maximum_matching`): perfect (F/2 edges, checked to be a matching
//!   of dual edges) on every component of the closed real meshes (the repository's, and
//!   in the ignored `corpus` tests the corpus's) with at most `MATCHING_FACE_CAP` faces (the
//!   others are skipped because Gabow's algorithm is cubic in the worst case; set
//!   `CONTRACTIBLE_ORACLE_ALL_MESHES=1`, best with `--release`, to include every mesh),
//!   on the generated closed surfaces of `closed_inputs` (bricks, subdivisions, an
//!   isosurface, several components) and on random surfaces of every kind (Petersen's
//!   theorem: a bridgeless cubic graph has a perfect matching).

use crate::{closed_inputs, common};

use std::collections::{HashMap, HashSet};
use std::path::Path;

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::rng::Rng;
use contractible::spec::oracle::critical_cycles_through;
use contractible::{History, LinkTester, Surfaces, Triangulation, VertexId};
use petgraph::algo::maximum_matching;
use petgraph::graph::{NodeIndex, UnGraph};
use petgraph::visit::EdgeRef;

/// Critical 3-cycles per edge `(a, b)` (`a < b`), from petgraph alone.
fn critical_counts_petgraph(t: &Triangulation) -> HashMap<(u32, u32), usize> {
    let mut g: UnGraph<u32, ()> = UnGraph::new_undirected();
    let mut node: HashMap<u32, NodeIndex> = HashMap::new();
    for v in t.vertices() {
        node.insert(v.0, g.add_node(v.0));
    }
    for (a, b, _) in t.edges() {
        g.add_edge(node[&a.0], node[&b.0], ());
    }
    let faces: HashSet<[u32; 3]> = t
        .face_list()
        .into_iter()
        .map(|mut f| {
            f.sort_unstable();
            f
        })
        .collect();
    let mut counts = HashMap::new();
    for a in g.node_indices() {
        let wa = g[a];
        for b in g.neighbors(a) {
            let wb = g[b];
            if wb <= wa {
                continue;
            }
            for c in g.neighbors(b) {
                let wc = g[c];
                if wc <= wb || g.find_edge(a, c).is_none() {
                    continue;
                }
                // a < b < c is a 3-cycle of the graph.
                if faces.contains(&[wa, wb, wc]) {
                    continue;
                }
                for e in [(wa, wb), (wb, wc), (wa, wc)] {
                    *counts.entry(e).or_insert(0) += 1;
                }
            }
        }
    }
    counts
}

/// Compares petgraph's critical-cycle counts with the oracle and the link tests on
/// every edge. Returns (edges, contractible edges).
fn compare_all(t: &Triangulation, label: &str) -> (usize, usize) {
    let counts = critical_counts_petgraph(t);
    let t4 = t.vertex_count() == 4 && t.face_count() == 4;
    let mut tester = LinkTester::new(t.vertex_capacity());
    let (mut edges, mut contractible) = (0, 0);
    for u in t.vertices() {
        tester.mark(t, u);
        for w in t.link(u) {
            if w < u {
                continue;
            }
            let cc = counts.get(&(u.0, w.0)).copied().unwrap_or(0);
            assert_eq!(
                critical_cycles_through(t, u, w),
                Some(cc),
                "{label}: critical cycles through {u}-{w}"
            );
            let want = cc == 0 && !t4;
            assert_eq!(t.link_condition_naive(u, w), want, "{label}: naive {u}-{w}");
            assert_eq!(
                t.is_contractible(u, w),
                want,
                "{label}: is_contractible {u}-{w}"
            );
            assert_eq!(tester.test_marked(t, u, w), want, "{label}: marked {u}-{w}");
            edges += 1;
            contractible += want as usize;
        }
    }
    assert_eq!(edges, t.edge_count(), "{label}");
    // Every counted cycle is through an edge of t.
    assert!(counts
        .keys()
        .all(|&(a, b)| t.has_edge(VertexId(a), VertexId(b))));
    (edges, contractible)
}

/// A random contractible edge (by rejection over random corners), if any is found in a
/// bounded number of tries; falls back to a scan.
fn random_contractible(t: &Triangulation, rng: &mut Rng) -> Option<(VertexId, VertexId)> {
    for _ in 0..64 {
        let f = contractible::FaceId(rng.index(t.face_capacity()) as u32);
        if !t.is_face(f) {
            continue;
        }
        let [a, b] = t.edge_endpoints(f.corner(rng.index(3) as u32));
        let (a, b) = if rng.chance(1, 2) { (a, b) } else { (b, a) };
        if t.is_contractible(a, b) {
            return Some((a, b));
        }
    }
    t.edges()
        .map(|(a, b, _)| (a, b))
        .find(|&(a, b)| t.is_contractible(a, b))
}

/// Contracts random contractible edges until irreducible, comparing every `every`-th
/// state (and the last). Returns the number of comparisons.
fn contraction_sequence(t: &Triangulation, seed: u64, every: usize, label: &str) -> usize {
    let mut k = t.clone();
    let mut rng = Rng::new(seed);
    let mut h = History::new();
    let mut compared = 0;
    let mut steps = 0;
    while let Some((u, v)) = random_contractible(&k, &mut rng) {
        k.contract(u, v, &mut h).expect("contractible");
        steps += 1;
        if steps % every == 0 {
            compare_all(&k, &format!("{label} after {steps} contractions"));
            compared += 1;
        }
    }
    assert!(
        k.is_irreducible_naive(),
        "{label}: no contractible edge left"
    );
    compare_all(&k, &format!("{label} irreducible"));
    h.undo_all(&mut k);
    assert!(k == *t, "{label}: undo_all");
    compared + 1
}

fn surface_kinds() -> Vec<SurfaceKind> {
    let mut v: Vec<SurfaceKind> = (0..=8).map(SurfaceKind::Orientable).collect();
    v.extend((1..=6).map(SurfaceKind::NonOrientable));
    v
}

fn small_lists() -> Vec<(String, Triangulation)> {
    common::small_published_surfaces()
}

#[test]
fn critical_cycles_agree_on_small_and_published_surfaces() {
    let mut edges = 0;
    let mut comparisons = 0;
    for (i, (name, t)) in small_lists().iter().enumerate() {
        edges += compare_all(t, name).0;
        for run in 0..3 {
            comparisons += contraction_sequence(t, (3 * i + run) as u64, 1, name);
        }
    }
    println!("small + published: {edges} edges, {comparisons} states compared");
    assert!(edges >= 1500 && comparisons >= 450);
}

#[test]
fn critical_cycles_agree_on_random_surfaces() {
    let mut edges = 0;
    let mut comparisons = 0;
    for (k, surface) in surface_kinds().into_iter().enumerate() {
        for (min_faces, every) in [(100, 1), (2000, 100)] {
            let t = random(&RandomParams {
                surface,
                min_faces,
                flip_percent: 30,
                seed: 1000 + k as u64,
            })
            .expect("a random surface within the limits");
            let label = format!("{surface:?} {min_faces}");
            let (e, c) = compare_all(&t, &label);
            assert!(
                c > 0,
                "{label}: a fresh random surface has contractible edges"
            );
            edges += e;
            comparisons += contraction_sequence(&t, k as u64, every, &label);
        }
    }
    println!("random: {edges} edges, {comparisons} states compared");
    assert!(edges >= 15 * 3150 && comparisons >= 15 * 20);
}

/// The components of the closed mesh `meshes/closed/NAME.off.gz`.
fn closed_mesh(meshes: &Path, name: &str) -> Vec<Triangulation> {
    let path = meshes.join(format!("closed/{name}.off.gz"));
    let mesh = contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
    Surfaces::from_mesh(&mesh)
        .unwrap_or_else(|e| panic!("{name}: {e}"))
        .components
        .into_iter()
        .map(|c| c.tri)
        .collect()
}

/// Every edge of the closed meshes `names` of `meshes`, before and along a random
/// contraction sequence (every 500th state); at least `min_edges` edges in all.
fn critical_cycles_on_real_meshes(meshes: &Path, names: &[&str], min_edges: usize) {
    let mut edges = 0;
    for name in names {
        for (k, t) in closed_mesh(meshes, name).iter().enumerate() {
            let label = format!("{name}[{k}]");
            edges += compare_all(t, &label).0;
            contraction_sequence(t, k as u64, 500, &label);
        }
    }
    println!("real meshes: {edges} edges");
    assert!(edges >= min_edges, "{edges} edges");
}

/// Every closed mesh the repository carries (genus 0 to 24, up to 10 components, one
/// not consistently oriented), every edge: as many as the manifest's E column says.
#[test]
fn critical_cycles_agree_on_the_repository_meshes() {
    let rows: Vec<_> = common::data_manifest()
        .into_iter()
        .filter(|r| r.set == "closed")
        .collect();
    assert_eq!(rows.len(), 9);
    let names: Vec<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    let edges: usize = rows.iter().map(|r| r.e).sum();
    critical_cycles_on_real_meshes(&common::data_meshes(), &names, edges);
}

// ---- Perfect matchings of the dual graph.

const MATCHING_FACE_CAP: usize = 8_000;

/// Asserts that petgraph finds a perfect matching of `t`'s dual graph, and that it is a
/// matching of dual edges covering every face once.
fn assert_perfect_dual_matching(t: &Triangulation, label: &str) {
    let g = common::dual_graph(t);
    assert_eq!(g.node_count(), t.face_count(), "{label}");
    assert_eq!(g.edge_count(), t.edge_count(), "{label}");
    for n in g.node_indices() {
        assert_eq!(g.edges(n).count(), 3, "{label}: dual graph is cubic");
    }
    // petgraph's Gabow implementation recurses along augmenting paths: on the larger
    // meshes that overflows the default test-thread stack in debug builds, so it runs
    // on a thread with a large stack.
    let m = std::thread::scope(|s| {
        std::thread::Builder::new()
            .stack_size(1 << 30)
            .spawn_scoped(s, || {
                let m = maximum_matching(&g);
                m.edges().collect::<Vec<_>>()
            })
            .expect("spawn")
            .join()
            .expect("matching thread")
    });
    assert_eq!(
        2 * m.len(),
        t.face_count(),
        "{label}: matching of size {}",
        m.len()
    );
    let mut covered = vec![false; g.node_count()];
    for &(a, b) in &m {
        assert!(
            g.find_edge(a, b).is_some(),
            "{label}: matched pair is not a dual edge"
        );
        for n in [a, b] {
            assert!(!covered[n.index()], "{label}: face matched twice");
            covered[n.index()] = true;
        }
    }
    assert!(covered.iter().all(|&c| c), "{label}");
    // Matched faces share an edge of t.
    for e in g.edge_references() {
        let (fa, fb) = (g[e.source()], g[e.target()]);
        let va = t.face_vertices(fa);
        let shared = t
            .face_vertices(fb)
            .iter()
            .filter(|v| va.contains(v))
            .count();
        assert_eq!(shared, 2, "{label}: dual edge joins faces sharing an edge");
    }
}

/// Every closed mesh of the manifest of `meshes` up to [`MATCHING_FACE_CAP`] faces (or
/// all with `CONTRACTIBLE_ORACLE_ALL_MESHES`); returns the components checked and the
/// components of the meshes above the cap, which were skipped.
fn perfect_matchings_on_closed_meshes(meshes: &Path) -> (usize, usize) {
    let all = std::env::var_os("CONTRACTIBLE_ORACLE_ALL_MESHES").is_some();
    let manifest = common::manifest_in(meshes);
    let mut components = 0;
    let mut skipped = Vec::new();
    let mut skipped_components = 0;
    for row in manifest.iter().filter(|r| r.set == "closed") {
        if !all && row.f > MATCHING_FACE_CAP {
            skipped.push(row.name.clone());
            skipped_components += row.components;
            continue;
        }
        let path = meshes.join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let surfaces = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        for (k, c) in surfaces.components.iter().enumerate() {
            assert_perfect_dual_matching(&c.tri, &format!("{}[{k}]", row.name));
            components += 1;
        }
    }
    println!(
        "perfect dual matchings: {components} components; skipped (> {MATCHING_FACE_CAP} faces): {}",
        skipped.len()
    );
    (components, skipped_components)
}

/// Every closed mesh the repository carries up to [`MATCHING_FACE_CAP`] faces: every
/// component of theirs (the manifest's count), the others' counted as skipped.
#[test]
fn dual_graphs_of_the_repository_meshes_have_perfect_matchings() {
    let rows: Vec<_> = common::data_manifest()
        .into_iter()
        .filter(|r| r.set == "closed")
        .collect();
    assert_eq!(rows.len(), 9);
    let (components, skipped) = perfect_matchings_on_closed_meshes(&common::data_meshes());
    assert_eq!(
        components + skipped,
        rows.iter().map(|r| r.components).sum::<usize>()
    );
    assert!(components >= 9, "{components}");
}

/// Every component of the generated closed surfaces of `closed_inputs` (bricks,
/// subdivisions, an isosurface, random surfaces with and without orientation, a mesh of
/// four components).
#[test]
fn dual_graphs_of_generated_closed_surfaces_have_perfect_matchings() {
    let mut components = 0;
    for g in closed_inputs::closed_surfaces() {
        for (k, t) in closed_inputs::components(&g.mesh, &g.name)
            .iter()
            .enumerate()
        {
            assert_perfect_dual_matching(t, &format!("{}[{k}]", g.name));
            components += 1;
        }
    }
    assert_eq!(components, closed_inputs::COMPONENTS);
}

#[test]
fn dual_graphs_of_random_surfaces_have_perfect_matchings() {
    let mut cases = 0;
    for (k, surface) in surface_kinds().into_iter().enumerate() {
        for min_faces in [100, 2000] {
            let t = random(&RandomParams {
                surface,
                min_faces,
                flip_percent: 30,
                seed: 77 + k as u64,
            })
            .expect("a random surface within the limits");
            assert_perfect_dual_matching(&t, &format!("{surface:?} {min_faces}"));
            cases += 1;
        }
    }
    assert_eq!(cases, 30);
}

/// The face-list oracle `spec::oracle::euler_and_orientability` (used by the vector and
/// fuzz checks) agrees with the surface codes of the published lists and with the core's
/// corner-table χ and orientability, and rejects face lists that are not closed.
#[test]
fn face_list_oracle_agrees_with_list_names_and_the_core() {
    use contractible::spec::oracle::euler_and_orientability;
    let mut checked = 0;
    for (name, t) in small_lists() {
        let (chi, orientable) = euler_and_orientability(&t.face_list()).expect(&name);
        let expected = match &name[..2] {
            "S0" => (2, true),
            "S1" | "to" => (0, true),
            "N1" | "pr" => (1, false),
            "N2" => (0, false),
            other => panic!("{name}: unknown surface code {other}"),
        };
        assert_eq!((chi, orientable), expected, "{name}");
        assert_eq!(
            (t.euler_characteristic(), t.is_orientable()),
            expected,
            "{name}"
        );
        checked += 1;
    }
    for (k, surface) in surface_kinds().into_iter().enumerate() {
        let t = random(&RandomParams {
            surface,
            min_faces: 500,
            flip_percent: 30,
            seed: 77 + k as u64,
        })
        .expect("a random surface within the limits");
        let got = euler_and_orientability(&t.face_list()).expect("closed");
        assert_eq!(
            got,
            (surface.euler_characteristic(), surface.is_orientable())
        );
        assert_eq!(got, (t.euler_characteristic(), t.is_orientable()));
        checked += 1;
    }
    assert_eq!(checked, 57 + 21 + 2 + 15);
    // Open or non-manifold face lists are not surfaces.
    assert_eq!(euler_and_orientability(&[[0, 1, 2]]), None);
    assert_eq!(
        euler_and_orientability(&[[0, 1, 2], [0, 1, 3], [0, 1, 4], [2, 3, 4]]),
        None
    );
}

mod corpus {
    use super::*;

    /// The corpus meshes double_torus, helmet, socket, fertility and casting, every edge.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn critical_cycles_agree_on_real_meshes() {
        critical_cycles_on_real_meshes(
            &common::corpus_meshes(),
            &["double_torus", "helmet", "socket", "fertility", "casting"],
            2544 + 15336 + 13500 + 1500 + 102,
        );
    }

    /// Every closed corpus mesh up to [`MATCHING_FACE_CAP`] faces.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn dual_graphs_of_closed_meshes_have_perfect_matchings() {
        let (components, _) = perfect_matchings_on_closed_meshes(&common::corpus_meshes());
        assert!(components >= 40, "{components}");
    }
}
