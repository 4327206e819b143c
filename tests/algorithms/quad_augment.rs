//! `quad::augment::complete` and `quad::matching`: every completion is checked by code
//! independent of the completion (pairs share an edge by their vertex sets, every live face
//! is in exactly one pair), and on small inputs its size is compared with petgraph's
//! maximum matching of the dual graph.
//!
//! Inputs: random surfaces of every kind, the repository's closed meshes, the generated
//! closed surfaces of `closed_inputs`, the published small surfaces, the paper's C0, and
//! in the ignored `corpus` tests every closed mesh of the real-mesh corpus (the biggest are
//! slow in debug builds; the README's test command is a release build).

use std::collections::BTreeSet;
use std::path::Path;

use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::augment::{complete, Completion};
use contractible::quad::{matching, Pairing};
use contractible::rng::Rng;
use contractible::{FaceId, Surfaces, TriMesh, Triangulation};

use crate::common;

/// Independent check that `p` is a perfect pairing of `t`: every live face has exactly one
/// mate among the pairs listed by `pairs()`, mates are live, distinct and share exactly
/// two vertices (an edge: two faces of a closed surface that share two vertices share
/// the edge between them, as no two edges have the same endpoints), and there are F/2
/// pairs.
fn assert_perfect(t: &Triangulation, p: &Pairing, label: &str) {
    let mut seen = vec![0u8; t.face_capacity()];
    let mut pairs = 0usize;
    for (f, g) in p.pairs() {
        assert!(
            t.is_face(f) && t.is_face(g) && f != g,
            "{label}: bad pair ({f}, {g})"
        );
        let a: BTreeSet<u32> = t.face_vertices(f).iter().map(|v| v.0).collect();
        let b: BTreeSet<u32> = t.face_vertices(g).iter().map(|v| v.0).collect();
        assert_eq!(
            a.intersection(&b).count(),
            2,
            "{label}: ({f}, {g}) share no edge"
        );
        seen[f.index()] += 1;
        seen[g.index()] += 1;
        pairs += 1;
    }
    for f in t.faces() {
        assert_eq!(
            seen[f.index()],
            1,
            "{label}: face {f} in {} pairs",
            seen[f.index()]
        );
    }
    assert_eq!(2 * pairs, t.face_count(), "{label}: pair count");
    assert!(p.is_perfect(t), "{label}: is_perfect");
}

/// A random greedy maximal pairing, the simple greedy SG of the paper (§3.1) in dual
/// terms: the edges in a seeded shuffled order, each joining two unpaired faces pairs
/// them. A stand-in for `quad::greedy`, leaving about 12–13% unpaired on mesh duals.
fn greedy(t: &Triangulation, seed: u64) -> Pairing {
    let mut edges: Vec<(FaceId, FaceId)> = t
        .edges()
        .map(|(_, _, c)| (c.face(), t.opposite(c).face()))
        .collect();
    Rng::new(seed).shuffle(&mut edges);
    let mut p = Pairing::new(t.face_capacity());
    for (f, g) in edges {
        if !p.is_paired(f) && !p.is_paired(g) {
            p.pair(f, g);
        }
    }
    p
}

/// A random sparse, generally non-maximal pairing: each pair of a greedy pairing is kept
/// with probability 1/4.
fn sparse(t: &Triangulation, seed: u64) -> Pairing {
    let g = greedy(t, seed);
    let mut rng = Rng::new(seed ^ 0x5eed);
    let mut p = Pairing::new(t.face_capacity());
    for (a, b) in g.pairs() {
        if rng.chance(1, 4) {
            p.pair(a, b);
        }
    }
    p
}

/// Completes `start` and checks the result independently; returns the counters and the
/// completed pairing.
fn complete_checked(t: &Triangulation, start: &Pairing, label: &str) -> (Completion, Pairing) {
    let mut p = start.clone();
    let c = complete(t, &mut p).expect("a closed triangulation");
    assert_perfect(t, &p, label);
    assert_eq!(
        c.augmenting_paths,
        t.face_count() / 2 - start.len(),
        "{label}: one pair per augmenting path"
    );
    // Deterministic: the same input gives the same output.
    let mut again = start.clone();
    assert_eq!(
        complete(t, &mut again).expect("a closed triangulation"),
        c,
        "{label}: counters differ"
    );
    assert!(again == p, "{label}: output differs between runs");
    (c, p)
}

/// The starts used on every input: empty, two random greedy maximal, two random sparse.
fn starts(t: &Triangulation, seed: u64) -> Vec<(String, Pairing)> {
    vec![
        ("empty".into(), matching::initial_pairing(t)),
        ("greedy".into(), greedy(t, seed)),
        ("greedy'".into(), greedy(t, seed + 1000)),
        ("sparse".into(), sparse(t, seed)),
        ("sparse'".into(), sparse(t, seed + 1000)),
    ]
}

fn petgraph_matching_size(t: &Triangulation) -> usize {
    petgraph::algo::maximum_matching(&common::dual_graph(t)).len()
}

fn kinds() -> Vec<SurfaceKind> {
    (0..=8)
        .map(SurfaceKind::Orientable)
        .chain((1..=6).map(SurfaceKind::NonOrientable))
        .collect()
}

#[test]
fn small_random_surfaces_are_completed_to_maximum_matchings() {
    for kind in kinds() {
        for seed in 0..3u64 {
            for min_faces in [60, 400, 1_500] {
                let t = random(&RandomParams {
                    surface: kind,
                    min_faces,
                    flip_percent: 40,
                    seed,
                })
                .expect("a random surface within the limits");
                if t.face_count() > 2_000 {
                    continue;
                }
                assert_eq!(petgraph_matching_size(&t), t.face_count() / 2);
                for (name, start) in starts(&t, seed) {
                    let label = format!("{kind:?} seed {seed} F {} {name}", t.face_count());
                    complete_checked(&t, &start, &label);
                }
            }
        }
    }
}

#[test]
fn medium_random_surfaces_are_completed_in_near_linear_work() {
    for kind in kinds() {
        for seed in 0..2u64 {
            let t = random(&RandomParams {
                surface: kind,
                min_faces: 30_000,
                flip_percent: 30,
                seed: 100 + seed,
            })
            .expect("a random surface within the limits");
            for (name, start) in starts(&t, seed) {
                let label = format!("{kind:?} seed {seed} F {} {name}", t.face_count());
                let (c, _) = complete_checked(&t, &start, &label);
                // A few BFS sweeps (3 visits per face each) at most: the design's point.
                let per_face = c.edge_visits as f64 / t.face_count() as f64;
                assert!(
                    per_face < 15.0,
                    "{label}: {per_face:.2} edge visits per face"
                );
            }
        }
    }
}

/// Faces removed by contractions leave holes in the face ids; the completion must work
/// on the live faces only.
#[test]
fn triangulations_with_removed_faces_are_completed() {
    for kind in [
        SurfaceKind::Orientable(2),
        SurfaceKind::NonOrientable(3),
        SurfaceKind::Orientable(5),
    ] {
        let t = random(&RandomParams {
            surface: kind,
            min_faces: 800,
            flip_percent: 30,
            seed: 9,
        })
        .expect("a random surface within the limits");
        let r = contractible::irreducible::rs::reduce(t, &Default::default());
        let t = r.tri;
        assert!(
            t.face_capacity() > t.face_count(),
            "{kind:?}: no holes made"
        );
        assert_eq!(petgraph_matching_size(&t), t.face_count() / 2);
        for (name, start) in starts(&t, 4) {
            complete_checked(&t, &start, &format!("{kind:?} reduced {name}"));
        }
    }
}

/// Completes every component of `name`'s mesh from the first four [`starts`] (checked
/// by [`complete_checked`]; petgraph's matching size up to 2,000 faces); adds the faces
/// and edge visits of the greedy starts to `totals`.
fn complete_every_component(mesh: &TriMesh, name: &str, totals: &mut (usize, u64)) {
    let s = Surfaces::from_mesh(mesh).unwrap_or_else(|e| panic!("{name}: {e}"));
    for (k, comp) in s.components.iter().enumerate() {
        let t = &comp.tri;
        if t.face_count() <= 2_000 {
            assert_eq!(petgraph_matching_size(t), t.face_count() / 2, "{name}#{k}");
        }
        for (start_name, start) in starts(t, k as u64).into_iter().take(4) {
            let (c, _) = complete_checked(t, &start, &format!("{name}#{k} {start_name}"));
            if start_name == "greedy" {
                totals.0 += t.face_count();
                totals.1 += c.edge_visits;
            }
        }
    }
}

/// Every mesh of `meshes/closed` (at least `min_files`) by [`complete_every_component`];
/// returns the greedy starts' faces and edge visits.
fn complete_every_closed_mesh_of(meshes: &Path, min_files: usize) -> (usize, u64) {
    let dir = meshes.join("closed");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.to_string_lossy().ends_with(".off.gz"))
        .collect();
    files.sort();
    assert!(files.len() >= min_files, "{} closed meshes", files.len());
    let mut totals = (0usize, 0u64);
    for path in files {
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
        let name = name.unwrap_or_default();
        let mesh = contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{name}: {e}"));
        complete_every_component(&mesh, &name, &mut totals);
    }
    totals
}

/// Fewer than 10 edge visits per face of the greedy starts, over everything completed.
fn assert_near_linear((faces, visits): (usize, u64), what: &str) {
    let per_face = visits as f64 / faces as f64;
    eprintln!("{what}, greedy starts: {per_face:.2} edge visits per face");
    assert!(per_face < 10.0, "{per_face:.2} edge visits per face");
}

/// Every component of every closed mesh the repository carries and of every generated
/// closed surface of `closed_inputs` (genera 0 to 24, cross-caps 1 to 5, meshes of up to
/// 10 components).
#[test]
fn every_repository_and_generated_closed_mesh_component_is_completed() {
    let mut totals = complete_every_closed_mesh_of(&common::data_meshes(), 9);
    for g in crate::closed_inputs::closed_surfaces() {
        complete_every_component(&g.mesh, &g.name, &mut totals);
    }
    assert_near_linear(totals, "repository and generated closed meshes");
}

/// Every small published surface, from empty and from every single-pair start (every
/// edge of the triangulation as the one initial pair).
#[test]
fn every_small_published_surface_from_every_single_pair_start() {
    let mut count = 0;
    for (name, t) in common::small_published_surfaces() {
        assert_eq!(petgraph_matching_size(&t), t.face_count() / 2, "{name}");
        complete_checked(&t, &matching::initial_pairing(&t), &name);
        for (_, _, c) in t.edges() {
            let (f, g) = (c.face(), t.opposite(c).face());
            let mut start = Pairing::new(t.face_capacity());
            start.pair(f, g);
            complete_checked(&t, &start, &format!("{name} from ({f}, {g})"));
            count += 1;
        }
    }
    assert!(count > 1_000, "{count} single-pair starts");
}

/// The matching route computes the whole pairing from empty.
#[test]
fn the_matching_route_is_the_completion_from_empty() {
    let t = random(&RandomParams {
        surface: SurfaceKind::Orientable(4),
        min_faces: 5_000,
        flip_percent: 30,
        seed: 1,
    })
    .expect("a random surface within the limits");
    let start = matching::initial_pairing(&t);
    assert!(start.is_empty() && start.face_capacity() == t.face_capacity());
    let (c, _) = complete_checked(&t, &start, "matching");
    assert_eq!(c.augmenting_paths, t.face_count() / 2);
}

/// The performance case: SG-like leftovers (~13% unpaired) on the paper's C0
/// (4.2M triangles, genus 3,500). Asserts perfection and the near-linear work (edge
/// visits per face, a deterministic count); prints the time for reference (the timing
/// itself is `benches/quad.rs`). Runs in release builds (the README's test command,
/// about 5 s); skipped in debug builds, where building C0 alone takes minutes.
#[test]
#[cfg_attr(debug_assertions, ignore = "4.2M triangles: runs in release builds")]
fn c0_greedy_leftovers_are_completed_in_near_linear_work() {
    let mesh = contractible::gen::paper_family('C', 0).expect("valid brick parameters");
    let t = Triangulation::from_faces(mesh.vertex_count, &mesh.faces).expect("C0");
    let start = greedy(&t, 1);
    let unpaired = t.face_count() - 2 * start.len();
    let mut p = start.clone();
    let (clock, cpu) = (std::time::Instant::now(), crate::cpu::cpu());
    let c = complete(&t, &mut p).expect("a closed triangulation");
    let seconds = clock.elapsed().as_secs_f64();
    let cpu = crate::cpu::cpu() - cpu;
    let per_face = c.edge_visits as f64 / t.face_count() as f64;
    eprintln!(
        "C0: F {} unpaired {} ({:.2}%), {:?}, {per_face:.2} edge visits per face, {seconds:.3} s wall, {cpu:.2} s CPU",
        t.face_count(),
        unpaired,
        100.0 * unpaired as f64 / t.face_count() as f64,
        c
    );
    assert_perfect(&t, &p, "C0");
    assert!(per_face < 8.0, "{per_face:.2} edge visits per face");
    // Calibration: one plain BFS sweep of the dual (3 visits per face) on this machine.
    let (clock, cpu) = (std::time::Instant::now(), crate::cpu::cpu());
    let mut seen = vec![false; t.face_capacity()];
    let mut queue: Vec<FaceId> = t.faces().take(1).collect();
    seen[queue[0].index()] = true;
    let mut head = 0;
    while head < queue.len() {
        let f = queue[head];
        head += 1;
        for g in t.face_neighbours(f) {
            if !seen[g.index()] {
                seen[g.index()] = true;
                queue.push(g);
            }
        }
    }
    assert_eq!(queue.len(), t.face_count());
    eprintln!(
        "C0 plain BFS sweep: {:.3} s wall, {:.2} s CPU",
        clock.elapsed().as_secs_f64(),
        crate::cpu::cpu() - cpu
    );
    let mut q = matching::initial_pairing(&t);
    let (clock, cpu) = (std::time::Instant::now(), crate::cpu::cpu());
    let c = complete(&t, &mut q).expect("a closed triangulation");
    eprintln!(
        "C0 from empty: {:?}, {:.2} edge visits per face, {:.3} s wall, {:.2} s CPU",
        c,
        c.edge_visits as f64 / t.face_count() as f64,
        clock.elapsed().as_secs_f64(),
        crate::cpu::cpu() - cpu
    );
    assert_perfect(&t, &q, "C0 from empty");
}

/// Two unpaired faces far apart: a perfect pairing in which one pair is freed and the
/// freedom of one end is then pushed along a long random alternating walk (re-pairing
/// as it goes), so the only way back is a long augmenting path through whatever blossoms
/// lie between. The completion must find it (one path).
#[test]
fn long_augmenting_paths_are_found() {
    for (k, kind) in [SurfaceKind::Orientable(0), SurfaceKind::NonOrientable(5)]
        .into_iter()
        .enumerate()
    {
        let t = random(&RandomParams {
            surface: kind,
            min_faces: 20_000,
            flip_percent: 30,
            seed: 40 + k as u64,
        })
        .expect("a random surface within the limits");
        let mut p = matching::initial_pairing(&t);
        complete(&t, &mut p).expect("a closed triangulation");
        assert_perfect(&t, &p, "base");
        let mut rng = Rng::new(k as u64);
        let a = t.faces().nth(rng.index(t.face_count())).expect("a face");
        let mut e = p.unpair(a).expect("perfect");
        let mut steps = 0;
        for _ in 0..5_000 {
            // e is free: pair it with a random neighbour y (not a), freeing y's mate.
            let y = t.face_neighbours(e)[rng.index(3)];
            if y == a {
                continue;
            }
            let Some(z) = p.unpair(y) else { continue };
            p.pair(e, y);
            e = z;
            steps += 1;
        }
        assert!(steps > 1_000 && !p.is_paired(a) && !p.is_paired(e));
        let (c, _) = complete_checked(&t, &p, &format!("{kind:?} walk"));
        assert_eq!(c.augmenting_paths, 1);
    }
}

/// PS's leftovers on the paper's bricks are sparse (at least 32, at most one per 1,000
/// faces), so the completion runs its sparse pass of single-root searches (visible in
/// the counters: one search per augmentation rather than a few phases); its output is
/// checked independently like every other completion.
#[test]
#[cfg_attr(
    debug_assertions,
    ignore = "bricks of up to 1M faces: runs in release builds"
)]
fn sparse_ps_leftovers_are_completed_by_single_root_searches() {
    use contractible::gen::paper_family;
    use contractible::quad::{pulli_segal, Options};
    for (group, member, seed) in [('C', 4, 1), ('C', 2, 0), ('B', 2, 1)] {
        let label = format!("{group}{member} PS seed {seed}");
        let s = Surfaces::from_mesh(&paper_family(group, member).expect("valid brick parameters"))
            .expect("closed surface");
        let t = &s.components[0].tri;
        let start = pulli_segal::initial_pairing(t, &Options { seed });
        let unpaired = t.face_count() - 2 * start.len();
        assert!(
            unpaired >= 32 && unpaired * 1000 <= t.face_count(),
            "{label}: {unpaired} leftovers are not sparse"
        );
        let (c, _) = complete_checked(t, &start, &label);
        assert!(
            c.phases > 4,
            "{label}: {} searches, the sparse pass did not run",
            c.phases
        );
    }
}

/// A sphere shaped as a tube of rings of 3 or 4 vertices: segment `k` has
/// `segments[k]` bands, its rings have 3 vertices for even `k` and 4 for odd `k`, and
/// both ends are capped by a fan. Faces are listed cap, bands, cap, each band in its
/// cyclic strip order (consecutive faces of a band share an edge). Returns the faces and
/// the pairing of consecutive faces within each cap and band: a band between rings of 3
/// and 4 vertices has 7 faces and a cap on a ring of 3 has 3, so each of those leaves its
/// last face unpaired: the two caps and one face per change of ring size, far apart when
/// the segments are long.
fn tube(segments: &[usize]) -> (Triangulation, Pairing) {
    let size = |k: usize| 3 + (k % 2) as u32;
    let mut rings: Vec<(u32, u32)> = Vec::new(); // (first vertex, vertex count)
    let mut next = 1u32; // vertex 0 is the top apex
    let mut add_ring = |n: u32, rings: &mut Vec<(u32, u32)>| {
        rings.push((next, n));
        next += n;
    };
    add_ring(size(0), &mut rings);
    for (k, &bands) in segments.iter().enumerate() {
        for _ in 0..bands {
            add_ring(size(k), &mut rings);
        }
        if k + 1 < segments.len() {
            add_ring(size(k + 1), &mut rings);
        }
    }
    let bottom = next;
    let mut groups: Vec<Vec<[u32; 3]>> = Vec::new();
    let (s0, n0) = rings[0];
    groups.push((0..n0).map(|i| [0, s0 + (i + 1) % n0, s0 + i]).collect());
    for w in rings.windows(2) {
        let ((a0, na), (b0, nb)) = (w[0], w[1]);
        // Walk both rings once: each face advances one of them, the smaller ratio first,
        // so that consecutive faces share the edge between the two current vertices.
        let (mut i, mut j) = (0u32, 0u32);
        let mut band = Vec::new();
        while i < na || j < nb {
            let (a, b) = (a0 + i % na, b0 + j % nb);
            if j * na < i * nb || i == na {
                band.push([a, b0 + (j + 1) % nb, b]);
                j += 1;
            } else {
                band.push([a, a0 + (i + 1) % na, b]);
                i += 1;
            }
        }
        groups.push(band);
    }
    let (sl, nl) = *rings.last().expect("a ring");
    groups.push(
        (0..nl)
            .map(|i| [bottom, sl + i, sl + (i + 1) % nl])
            .collect(),
    );
    let faces: Vec<[u32; 3]> = groups.iter().flatten().copied().collect();
    let t = Triangulation::from_faces(bottom as usize + 1, &faces).expect("a tube is a sphere");
    let mut p = Pairing::new(t.face_capacity());
    let mut first = 0u32;
    for g in &groups {
        for k in (0..g.len() as u32 / 2).map(|k| first + 2 * k) {
            p.pair(FaceId(k), FaceId(k + 1));
        }
        first += g.len() as u32;
    }
    (t, p)
}

/// The sparse pass (module documentation, step 2) on 32 far-apart leftovers of a
/// 32,000-face tube: one single-root search per pair of leftovers when each finds its
/// partner within `F / 4` edge visits; when the first must cross a quarter of the
/// surface it is aborted, and the phases take every leftover.
#[test]
fn a_single_root_search_past_its_budget_hands_the_leftovers_to_the_phases() {
    for (long, searches) in [(1, 16..=16), (0, 2..=4)] {
        let mut segments = vec![40; 31];
        segments[long] = 4_000;
        let (t, start) = tube(&segments);
        let unpaired = t.face_count() - 2 * start.len();
        assert!(
            unpaired == 32 && t.face_count() >= 32 * 1000,
            "{unpaired} leftovers on {} faces",
            t.face_count()
        );
        let (c, _) = complete_checked(&t, &start, &format!("tube, segment {long} long"));
        assert_eq!(c.augmenting_paths, 16);
        assert!(
            searches.contains(&c.phases),
            "long segment {long}: {} searches, expected {searches:?}",
            c.phases
        );
    }
}

/// The linear pass as the module documentation states it (step 1), written from that
/// text: for each unpaired face `f` in increasing id, its first unpaired neighbour in
/// slot order, else the first unpaired `x ≠ f` among the neighbours of `mate(v)` for the
/// neighbours `v` of `f`, every slot looked at counted as one edge visit. Returns the
/// pairing after the pass, the visits and the number of paths of length 3.
fn linear_pass_by_the_rule(t: &Triangulation, start: &Pairing) -> (Pairing, u64, usize) {
    let mut p = start.clone();
    let (mut visits, mut threes) = (0u64, 0);
    let unpaired: Vec<FaceId> = start.unpaired(t).collect();
    for f in unpaired {
        if p.is_paired(f) {
            continue;
        }
        let nb = t.face_neighbours(f);
        if let Some(&g) = nb.iter().find(|&&g| {
            visits += 1;
            !p.is_paired(g)
        }) {
            p.pair(f, g);
            continue;
        }
        'three: for v in nb {
            let w = p.mate(v).expect("every neighbour is paired");
            for x in t.face_neighbours(w) {
                visits += 1;
                if x != f && !p.is_paired(x) {
                    p.unpair(v);
                    p.pair(f, v);
                    p.pair(w, x);
                    threes += 1;
                    break 'three;
                }
            }
        }
    }
    (p, visits, threes)
}

/// When the linear pass alone completes a pairing, the output is the one its rule gives
/// and the edge visits are exactly the slots it looked at. Starts: perfect pairings with
/// a few pairs removed, and with a few pairs (f, v), (w, x) replaced by (v, w), which
/// leaves `f` and `x` unpaired at distance 3 when they share no edge.
#[test]
fn the_linear_pass_pairs_and_counts_as_documented() {
    let (mut complete_starts, mut paths_of_3) = (0, 0);
    for seed in 0..12u64 {
        let t = random(&RandomParams {
            surface: kinds()[seed as usize % kinds().len()],
            min_faces: 300,
            flip_percent: 30,
            seed: 900 + seed,
        })
        .expect("a random surface within the limits");
        let mut perfect = matching::initial_pairing(&t);
        complete(&t, &mut perfect).expect("a closed triangulation");
        let mut rng = Rng::new(seed);
        for removed in 1..=4 {
            let mut start = perfect.clone();
            for _ in 0..removed {
                let f = t.faces().nth(rng.index(t.face_count())).expect("a face");
                let Some(v) = start.mate(f) else { continue };
                if seed % 2 == 0 {
                    start.unpair(f);
                    continue;
                }
                // Replace (f, v), (w, x) by (v, w) for a neighbour w of v other than f.
                let w = t.face_neighbours(v)[rng.index(3)];
                if w == f || !start.is_paired(w) {
                    continue;
                }
                start.unpair(f);
                start.unpair(w);
                start.pair(v, w);
            }
            let (expected, visits, threes) = linear_pass_by_the_rule(&t, &start);
            if !expected.is_perfect(&t) {
                continue;
            }
            let label = format!("seed {seed}, {removed} changes");
            let (c, out) = complete_checked(&t, &start, &label);
            assert!(out == expected, "{label}: not the rule's pairing");
            assert_eq!(c.phases, 0, "{label}: a search ran");
            assert_eq!(c.edge_visits, visits, "{label}: edge visits");
            complete_starts += 1;
            paths_of_3 += threes;
        }
    }
    assert!(
        complete_starts >= 20 && paths_of_3 >= 10,
        "{complete_starts} starts completed by the linear pass, {paths_of_3} paths of length 3"
    );
}

mod corpus {
    use super::*;

    /// Every component of every closed corpus mesh.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_shared_closed_mesh_component_is_completed() {
        let totals = complete_every_closed_mesh_of(&common::corpus_meshes(), 90);
        assert_near_linear(totals, "closed meshes");
    }
}
