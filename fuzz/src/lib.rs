//! The fuzz harness of `contractible`: input types and checks shared by the cargo-fuzz
//! targets in `fuzz_targets/` and by the main crate's `tests/core/fuzz_regressions.rs` (which
//! includes this file with `#[path]`), so a crash input replays through exactly the same
//! code in a plain `cargo test`.
//!
//! Depends only on `contractible` and `arbitrary`. Every check panics on failure.

use arbitrary::{Arbitrary, Unstructured};
use contractible::gen::{seed_surface, SurfaceKind};
use contractible::io::{read_tri_mesh_bytes, Format};
use contractible::irreducible::{reduce, Algorithm, Options, Reduction};
use contractible::rng::Rng;
use contractible::{ContractError, FaceId, History, Surfaces, Triangulation, VertexId};

/// At most this many operations of an input are applied (the rest are ignored).
pub const MAX_OPS: usize = 2000;
/// Steps of `journal_ops` taken from one input (each is followed by a from-scratch
/// validation, so fewer than [`MAX_OPS`]).
pub const JOURNAL_STEPS: usize = 300;
/// Full [`Triangulation::validate`] every this many applied operations (it is O(F)).
pub const VALIDATE_EVERY: usize = 128;

/// Which surface to start from; the numbers are reduced to `0..=6` (orientable genus)
/// and `1..=6` (cross-caps).
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Surface {
    /// Orientable genus `g % 7`.
    Orientable(u8),
    /// Non-orientable, Euler genus `1 + h % 6`.
    NonOrientable(u8),
}

impl Surface {
    /// The bounded surface kind.
    pub fn kind(self) -> SurfaceKind {
        match self {
            Surface::Orientable(g) => SurfaceKind::Orientable(u32::from(g % 7)),
            Surface::NonOrientable(h) => SurfaceKind::NonOrientable(1 + u32::from(h % 6)),
        }
    }
}

/// One local operation; indices are taken modulo the current sizes.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// Split `vertex` along its link vertices number `i` and `j` (positions in
    /// `link(vertex)`; `j` is moved off `i` so the two always differ).
    Split {
        /// Vertex id (mod vertex capacity).
        vertex: u16,
        /// First link position (mod degree).
        i: u8,
        /// Second link position (mod degree − 1, after `i`).
        j: u8,
    },
    /// Flip the edge opposite corner `slot` of `face`, if it is flippable.
    Flip {
        /// Face id (mod face capacity).
        face: u16,
        /// Corner slot (mod 3).
        slot: u8,
    },
    /// Rebuild with vertex ids, face order and corner slots permuted by the documented
    /// stream of `seed` (RS processes vertices in id order, and the star walks start at
    /// the first corner of each vertex, so this reaches other processing orders).
    Relabel {
        /// Seed of [`Rng`].
        seed: u64,
    },
}

/// The input of `surface_ops` and `rs_vertex_orders`.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct SurfaceInput {
    /// Starting surface ([`seed_surface`]).
    pub surface: Surface,
    /// Operations applied in order (at most [`MAX_OPS`]).
    pub ops: Vec<Op>,
    /// Seed for the algorithms' [`Options`] (used by the brute force).
    pub seed: u64,
}

/// The input of `contract_split`: a surface plus edge picks to contract.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct ContractInput {
    /// The surface to start from.
    pub base: SurfaceInput,
    /// `(vertex, k)`: contract `[vertex, link(vertex)[k]]` (ids mod capacity, `k` mod
    /// degree); `k = 255` instead tries a vertex that is *not* a neighbour.
    pub picks: Vec<(u16, u8)>,
}

/// One step of `journal_ops`: a contraction or flip of the edge opposite corner
/// `corner` (mod 3 × face capacity, moved to the next live corner), or an undo.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum JournalStep {
    /// `Journal::contract_at` (must succeed exactly when the naive link condition holds).
    Contract {
        /// Corner index.
        corner: u16,
    },
    /// `Journal::flip_at` (must succeed exactly when the edge is flippable).
    Flip {
        /// Corner index.
        corner: u16,
    },
    /// `Journal::undo` of the newest operation.
    Undo,
    /// A flip behind the journal's back: the next undo must be refused, without change;
    /// the flip is then undone exactly so the journal can go on.
    Sneak {
        /// Corner index.
        corner: u16,
    },
}

/// The input of `journal_ops`.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct JournalInput {
    /// The surface to start from.
    pub base: SurfaceInput,
    /// The steps (at most [`JOURNAL_STEPS`]).
    pub steps: Vec<JournalStep>,
}

/// Decodes fuzz bytes exactly as `libfuzzer_sys::fuzz_target!` does.
pub fn decode<'a, T: Arbitrary<'a>>(bytes: &'a [u8]) -> Option<T> {
    T::arbitrary_take_rest(Unstructured::new(bytes)).ok()
}

/// Applies one operation if it is valid; returns whether it changed anything.
pub fn apply_op(tri: &mut Triangulation, op: Op) -> bool {
    match op {
        Op::Split { vertex, i, j } => {
            let u = VertexId(u32::from(vertex) % tri.vertex_capacity() as u32);
            if !tri.is_vertex(u) {
                return false;
            }
            let link: Vec<VertexId> = tri.link(u).collect();
            let d = link.len();
            assert!(d >= 3, "vertex {u} of degree {d}");
            let i = usize::from(i) % d;
            let j = (i + 1 + usize::from(j) % (d - 1)) % d;
            let (v0, f0) = (tri.vertex_count(), tri.face_count());
            let v = tri
                .split_vertex(u, link[i], link[j])
                .expect("split along two distinct link vertices");
            assert_eq!(tri.vertex_count(), v0 + 1);
            assert_eq!(tri.face_count(), f0 + 2);
            assert!(tri.has_edge(u, v), "split: no edge [u, v]");
            assert_eq!(
                tri.edge_link(u, v).map(sorted2),
                Some(sorted2([link[i], link[j]]))
            );
            assert!(
                tri.link_condition_naive(u, v),
                "split edge not contractible"
            );
            true
        }
        Op::Relabel { seed } => {
            *tri = relabel(tri, seed);
            true
        }
        Op::Flip { face, slot } => {
            let f = FaceId(u32::from(face) % tri.face_capacity() as u32);
            if !tri.is_face(f) {
                return false;
            }
            let c = f.corner(u32::from(slot % 3));
            let [a, b] = tri.edge_endpoints(c);
            let flippable = tri.is_flippable(a, b);
            let before = tri.clone();
            match tri.flip(a, b) {
                Ok(()) => {
                    assert!(flippable, "flip succeeded on a non-flippable edge");
                    assert!(!tri.has_edge(a, b), "flipped edge still present");
                    true
                }
                Err(_) => {
                    assert!(!flippable, "flip refused a flippable edge");
                    assert_eq!(*tri, before, "refused flip changed the triangulation");
                    false
                }
            }
        }
    }
}

/// `tri` with vertex ids, face order and each face's slot rotation permuted by the
/// stream of `seed`; checked to be the same surface with the same degree multiset.
pub fn relabel(tri: &Triangulation, seed: u64) -> Triangulation {
    let n = tri.vertex_capacity();
    assert_eq!(n, tri.vertex_count(), "relabel needs dense vertex ids");
    let mut rng = Rng::new(seed);
    let mut perm: Vec<u32> = (0..n as u32).collect();
    rng.shuffle(&mut perm);
    let mut faces: Vec<[u32; 3]> = tri
        .face_list()
        .iter()
        .map(|f| {
            let g = f.map(|v| perm[v as usize]);
            let r = rng.index(3);
            [g[r], g[(r + 1) % 3], g[(r + 2) % 3]]
        })
        .collect();
    rng.shuffle(&mut faces);
    let out = Triangulation::from_faces(n, &faces).expect("a relabelled surface is a surface");
    assert_eq!(out.euler_characteristic(), tri.euler_characteristic());
    assert_eq!(out.is_orientable(), tri.is_orientable());
    for v in tri.vertices() {
        assert_eq!(out.degree(VertexId(perm[v.index()])), tri.degree(v));
    }
    out
}

fn sorted2(mut p: [VertexId; 2]) -> [VertexId; 2] {
    p.sort();
    p
}

/// The triangulation `input` describes: the seed surface with the ops applied, validated
/// (fully every [`VALIDATE_EVERY`] applied ops and at the end, χ after every op).
pub fn build_surface(input: &SurfaceInput) -> Triangulation {
    let mut tri = seed_surface(input.surface.kind()).expect("a seed surface within the limits");
    tri.validate().expect("seed surface valid");
    let chi = tri.euler_characteristic();
    let orientable = tri.is_orientable();
    let mut applied = 0usize;
    for &op in input.ops.iter().take(MAX_OPS) {
        if apply_op(&mut tri, op) {
            applied += 1;
            assert_eq!(tri.euler_characteristic(), chi, "χ changed by {op:?}");
            if applied % VALIDATE_EVERY == 0 {
                tri.validate()
                    .unwrap_or_else(|e| panic!("invalid after {applied} ops ({op:?}): {e}"));
            }
        }
    }
    tri.validate()
        .unwrap_or_else(|e| panic!("invalid after all {applied} ops: {e}"));
    assert_eq!(tri.is_orientable(), orientable, "orientability changed");
    tri
}

/// Options used by every harness run.
pub fn options(seed: u64) -> Options {
    Options {
        seed,
        count_retests: true,
    }
}

/// Checks one reduction of `input` against oracles that do not trust the algorithm:
/// valid, irreducible by the naive test on every edge, same χ and orientability (from
/// the face lists), Euler genus `h > 0` ⇒ `V ≤ 13h − 4`, `h = 0` ⇒ the tetrahedron,
/// `expand()` gives back the input exactly, counters consistent.
pub fn check_reduction(input: &Triangulation, r: &Reduction, label: &str) {
    let out = &r.tri;
    out.validate()
        .unwrap_or_else(|e| panic!("{label}: output invalid: {e}"));
    assert!(
        out.is_irreducible_naive(),
        "{label}: output not irreducible"
    );
    let (chi_in, or_in) = closed_surface_invariants(&input.face_list());
    let (chi_out, or_out) = closed_surface_invariants(&out.face_list());
    assert_eq!(chi_in, chi_out, "{label}: χ changed");
    assert_eq!(or_in, or_out, "{label}: orientability changed");
    let h = 2 - chi_in;
    if h > 0 {
        assert!(
            out.vertex_count() as i64 <= 13 * h - 4,
            "{label}: {} vertices > 13h - 4 = {}",
            out.vertex_count(),
            13 * h - 4
        );
    } else {
        assert_eq!(h, 0);
        assert!(
            out.vertex_count() == 4 && out.face_count() == 4,
            "{label}: genus 0 output is not the tetrahedron"
        );
    }
    let s = &r.stats;
    assert_eq!(
        s.contractions as usize,
        r.history.len(),
        "{label}: contractions"
    );
    assert_eq!(s.vertices_in, input.vertex_count(), "{label}: vertices_in");
    assert_eq!(s.edges_in, input.edge_count(), "{label}: edges_in");
    assert_eq!(s.vertices_out, out.vertex_count(), "{label}: vertices_out");
    assert_eq!(
        s.vertices_out + r.history.len(),
        input.vertex_count(),
        "{label}: one vertex per contraction"
    );
    assert_eq!(s.faces_out + 2 * r.history.len(), input.face_count());
    for rec in r.history.records() {
        assert!(
            !out.is_vertex(rec.v),
            "{label}: contracted {} still live",
            rec.v
        );
    }
    assert!(r.expand() == *input, "{label}: expand() != input");
}

/// `surface_ops`: RS, Schipper and brute force on clones of the built surface.
pub fn check_reductions(input: &SurfaceInput) {
    let tri = build_surface(input);
    let opts = options(input.seed);
    for alg in [Algorithm::Rs, Algorithm::Schipper, Algorithm::Brute] {
        let r = reduce(tri.clone(), alg, &opts);
        check_reduction(&tri, &r, alg.name());
        if alg == Algorithm::Rs {
            assert_eq!(r.stats.edges_tested_more_than_once, 0, "RS: ε > 0");
            assert!(
                r.stats.link_tests <= tri.edge_count() as u64,
                "RS: ℓ = {} > E = {}",
                r.stats.link_tests,
                tri.edge_count()
            );
        }
    }
}

/// Operations applied by [`check_vertex_orders`]: its surfaces stay small (at most a
/// few hundred faces), where one run is fast and many vertex orders fit in one input.
pub const SMALL_OPS: usize = 96;
/// Vertex orders tried per input by [`check_vertex_orders`].
pub const ORDERS: u64 = 8;

/// `rs_vertex_orders`: the surface of `input` with at most [`SMALL_OPS`] operations,
/// reduced by RS under [`ORDERS`] relabellings (other processing orders and star start
/// corners), each output checked by [`check_reduction`] plus ε = 0 and ℓ ≤ E. Erratum E4
/// (`spec/ERRATA.md`) only showed under a search over vertex orders of small surfaces:
/// this target keeps searching that space for the corrected algorithm.
pub fn check_vertex_orders(input: &SurfaceInput) {
    let small = SurfaceInput {
        surface: input.surface,
        ops: input.ops.iter().copied().take(SMALL_OPS).collect(),
        seed: input.seed,
    };
    // Splits and flips never remove vertices, so the ids stay dense for `relabel`.
    let base = build_surface(&small);
    for k in 0..ORDERS {
        let tri = relabel(&base, input.seed.wrapping_add(k));
        let r = reduce(tri.clone(), Algorithm::Rs, &options(input.seed));
        check_reduction(&tri, &r, "rs(vertex order)");
        assert_eq!(r.stats.edges_tested_more_than_once, 0, "RS: ε > 0");
        assert!(r.stats.link_tests <= tri.edge_count() as u64, "RS: ℓ > E");
    }
}

/// `contract_split`: contract the picked edges when the naive link condition holds
/// (`contract` must succeed exactly then, and leave the triangulation unchanged when it
/// refuses), then undo everything and compare with the pre-contraction triangulation.
pub fn check_contract_undo(input: &ContractInput) {
    let start = build_surface(&input.base);
    let mut tri = start.clone();
    let mut history = History::new();
    let chi = tri.euler_characteristic();
    let mut snapshots: Vec<Triangulation> = Vec::new();
    for &(vertex, k) in input.picks.iter().take(MAX_OPS) {
        let u = VertexId(u32::from(vertex) % tri.vertex_capacity() as u32);
        if !tri.is_vertex(u) {
            continue;
        }
        let link: Vec<VertexId> = tri.link(u).collect();
        if k == 255 {
            // A live vertex that is not a neighbour (if any): must be refused.
            let Some(w) = tri.vertices().find(|&w| w != u && !link.contains(&w)) else {
                continue;
            };
            let before = tri.clone();
            let res = tri.contract(u, w, &mut history);
            assert_eq!(res, Err(ContractError::NotAnEdge { u, v: w }));
            assert!(tri == before, "refused non-edge changed the triangulation");
            continue;
        }
        let v = link[usize::from(k) % link.len()];
        let naive = tri.link_condition_naive(u, v);
        let edge_link = tri.edge_link(u, v).expect("an edge");
        let before = tri.clone();
        let len_before = history.len();
        match tri.contract(u, v, &mut history) {
            Ok(rec) => {
                assert!(naive, "contract accepted [{u}, {v}] failing the naive test");
                assert_eq!((rec.u, rec.v), (u, v));
                assert_eq!(sorted2(rec.link), sorted2(edge_link));
                assert_eq!(rec.degree_v as usize, before.degree(v));
                assert_eq!(history.len(), len_before + 1);
                assert_eq!(history.renamed(&rec).len(), before.degree(v) - 2);
                assert!(!tri.is_vertex(v));
                assert_eq!(tri.vertex_count() + 1, before.vertex_count());
                assert_eq!(tri.euler_characteristic(), chi);
                if history.len() % 32 == 0 || tri.vertex_count() < 64 {
                    tri.validate()
                        .unwrap_or_else(|e| panic!("invalid after contracting [{u}, {v}]: {e}"));
                }
                if tri.vertex_count() < 64 {
                    snapshots.push(before);
                }
            }
            Err(e) => {
                assert!(
                    !naive,
                    "contract refused [{u}, {v}] passing the naive test: {e}"
                );
                assert_eq!(e, ContractError::NotContractible { u, v });
                assert!(
                    tri == before,
                    "refused contraction changed the triangulation"
                );
                assert_eq!(history.len(), len_before);
            }
        }
    }
    tri.validate().expect("valid after the contractions");
    // Undo one at a time; the last snapshots (small triangulations) are compared exactly.
    while let Some(rec) = history.undo(&mut tri) {
        assert!(tri.is_vertex(rec.v));
        if let Some(s) = snapshots.pop() {
            assert!(
                tri == s,
                "undo of [{}, {}] differs from before it",
                rec.u,
                rec.v
            );
        }
    }
    tri.validate().expect("valid after undo");
    assert!(
        tri == start,
        "undo of all contractions != the pre-contraction triangulation"
    );
}

/// A live corner near `index` (the first live one at or after it, cyclically).
fn live_corner_near(tri: &Triangulation, index: u16) -> contractible::Corner {
    let n = 3 * tri.face_capacity();
    let mut c = usize::from(index) % n;
    while !tri.is_face(contractible::Corner(c as u32).face()) {
        c = (c + 3) % n;
    }
    contractible::Corner(c as u32)
}

/// `journal_ops`: contractions, flips and undos in the fuzzer's interleaving through a
/// `Journal`, with an `EdgeNumbering` in lockstep. After every step the triangulation
/// validates from scratch and the numbering checks; a contraction or flip succeeds
/// exactly when the naive test says it may; a change behind the journal's back makes the
/// next undo refuse without changing anything; undoing everything restores the start
/// exactly (arrays and state stamp) and every edge number.
pub fn check_journal(input: &JournalInput) {
    use contractible::core::{Journal, Op as JOp};
    use contractible::EdgeNumbering;
    let start = build_surface(&input.base);
    let mut tri = start.clone();
    let mut journal = Journal::new();
    let mut numbers = EdgeNumbering::new(&tri);
    for &step in input.steps.iter().take(JOURNAL_STEPS) {
        match step {
            JournalStep::Contract { corner } => {
                let c = live_corner_near(&tri, corner);
                let [a, b] = tri.edge_endpoints(c);
                let naive = tri.link_condition_naive(a, b);
                let before = tri.clone();
                match journal.contract_at(&mut tri, c) {
                    Ok(rec) => {
                        assert!(naive, "contracted [{a}, {b}] failing the naive test");
                        assert_eq!((rec.u, rec.v), (a, b));
                        numbers.contracted(&rec);
                    }
                    Err(e) => {
                        assert!(!naive, "refused [{a}, {b}] passing the naive test: {e}");
                        assert!(tri == before, "a refused contraction changed the surface");
                    }
                }
            }
            JournalStep::Flip { corner } => {
                let c = live_corner_near(&tri, corner);
                let [a, b] = tri.edge_endpoints(c);
                let flippable = tri.is_flippable(a, b);
                match journal.flip_at(&mut tri, c) {
                    Ok(rec) => {
                        assert!(flippable, "flipped [{a}, {b}], not flippable");
                        numbers.flipped(&rec);
                    }
                    Err(_) => assert!(!flippable, "refused a flippable [{a}, {b}]"),
                }
            }
            JournalStep::Undo => match journal.undo(&mut tri).expect("journal undo") {
                Some(JOp::Contraction(rec)) => numbers.uncontracted(&rec),
                Some(JOp::Flip(rec)) => numbers.unflipped(&rec),
                None => assert!(tri == start),
            },
            JournalStep::Sneak { corner } => {
                let c = live_corner_near(&tri, corner);
                let Ok(rec) = tri.flip_at(c) else {
                    continue;
                };
                let snapshot = tri.clone();
                if !journal.is_empty() {
                    assert!(journal.undo(&mut tri).is_err(), "undo after a sneaked flip");
                    assert!(tri == snapshot, "a refused undo changed the surface");
                }
                tri.unflip(&rec).expect("unflip of the sneaked flip");
            }
        }
        tri.validate().unwrap_or_else(|e| panic!("invalid: {e}"));
        numbers
            .check(&tri)
            .unwrap_or_else(|e| panic!("edge numbering: {e}"));
    }
    while let Some(op) = journal.undo(&mut tri).expect("journal undo") {
        match op {
            JOp::Contraction(rec) => numbers.uncontracted(&rec),
            JOp::Flip(rec) => numbers.unflipped(&rec),
        }
    }
    assert!(
        tri == start,
        "undoing the journal did not restore the start"
    );
    assert_eq!(tri.state(), start.state(), "state stamp not restored");
    let fresh = EdgeNumbering::new(&start);
    for c in (0..3 * start.face_capacity() as u32).map(contractible::Corner) {
        assert_eq!(
            numbers.id(c),
            fresh.id(c),
            "edge number at {c} not restored"
        );
    }
}

/// `parse_*`: the reader must not panic; a parsed mesh goes to [`Surfaces::from_mesh`]
/// (must not panic), and every component it builds must validate and be consistent.
pub fn check_parse(bytes: &[u8], format: Option<Format>) {
    let Ok(mesh) = read_tri_mesh_bytes(bytes, format) else {
        return;
    };
    if let Some(p) = &mesh.positions {
        assert_eq!(p.len(), mesh.vertex_count, "positions vs vertex_count");
    }
    let Ok(surfaces) = Surfaces::from_mesh(&mesh) else {
        return;
    };
    let mut faces = 0;
    for c in &surfaces.components {
        c.tri
            .validate()
            .unwrap_or_else(|e| panic!("component invalid: {e}"));
        assert_eq!(c.face_origin.len(), c.tri.face_count());
        assert_eq!(c.vertex_origin.len(), c.tri.vertex_count());
        // Each local face is the mesh face it came from, renamed.
        for (f, &origin) in c.tri.face_list().iter().zip(&c.face_origin) {
            let mut a = f.map(|v| c.vertex_origin[v as usize]);
            let mut b = mesh.faces[origin as usize];
            a.sort_unstable();
            b.sort_unstable();
            assert_eq!(a, b, "component face does not match its origin");
        }
        faces += c.tri.face_count();
    }
    assert_eq!(faces, mesh.faces.len(), "faces lost between components");
}

/// χ and orientability by the face-list oracle; panics if the faces are not a closed surface.
fn closed_surface_invariants(faces: &[[u32; 3]]) -> (i64, bool) {
    contractible::spec::oracle::euler_and_orientability(faces).expect("a closed surface")
}

/// The quad algorithms run by [`check_quads`], in this order.
pub const QUAD_ALGORITHMS: [contractible::quad::Algorithm; 6] = [
    contractible::quad::Algorithm::Lrs,
    contractible::quad::Algorithm::PulliSegal,
    contractible::quad::Algorithm::SimpleGreedy,
    contractible::quad::Algorithm::Matching,
    contractible::quad::Algorithm::DiksStanczyk,
    contractible::quad::Algorithm::BiedlBoseDemaineLubiw,
];

/// `quad_ops`: the surface of `input` (as `surface_ops` builds it) converted by every
/// tri-quad algorithm with `Options { seed: input.seed }`, each result checked by
/// [`check_quadrangulation`]; LRS must leave exactly the face count of RS's irreducible
/// output unpaired before the completion (`irreducible::rs::reduce` on the same input).
pub fn check_quads(input: &SurfaceInput) {
    let tri = build_surface(input);
    let reduced = contractible::irreducible::rs::reduce(tri.clone(), &options(input.seed))
        .tri
        .face_count();
    for alg in QUAD_ALGORITHMS {
        check_quad_algorithm(&tri, alg, input.seed, reduced);
    }
}

/// One algorithm of [`check_quads`] on `tri` (also used by the exhaustive twins):
/// `reduced` is the face count of RS's irreducible output of `tri` (checked against
/// LRS's `initial_unpaired`).
pub fn check_quad_algorithm(
    tri: &Triangulation,
    alg: contractible::quad::Algorithm,
    seed: u64,
    reduced: usize,
) -> contractible::quad::Quadrangulation {
    use contractible::quad::{convert, Algorithm as QAlg, Options as QOptions};
    let label = format!("{}(seed {seed})", alg.name());
    let q = convert(tri.clone(), alg, &QOptions { seed }).expect("a closed triangulation");
    check_quadrangulation(tri, &q, &label);
    if alg == QAlg::Lrs {
        assert_eq!(
            q.stats.initial_unpaired, reduced,
            "{label}: LRS left {} unpaired, RS's irreducible output has {reduced} faces",
            q.stats.initial_unpaired
        );
    } else {
        assert_eq!(q.stats.flips, 0, "{label}: flips without LRS");
        assert!(q.tri == *tri, "{label}: K is not the input");
    }
    q
}

/// Checks a conversion of `input` by code that shares nothing with the algorithms (only
/// the face lists of the input and of `K`, the pairs and the quads are read):
///
/// - `K` validates, has the input's live vertex ids, vertex, edge and face counts, and
///   χ and orientability (by [`contractible::spec::oracle::euler_and_orientability`] on
///   the face lists); its edge set (vertex pairs) differs from the input's in at most
///   `stats.flips` edges, the same number removed as added;
/// - the pairing is perfect: every live face of `K` is in exactly one pair of `pairs()`,
///   `mate` agrees, the two faces of a pair share exactly two vertices (an edge: two
///   faces of a closed simplicial surface never share three); `F/2` pairs;
/// - counters: `faces = F`; every augmenting path adds one pair, so
///   `initial_unpaired = 2 · augmenting_paths`; the percentage agrees;
/// - `quad_faces` gives one quad per pair, in `pairs()` order, on the union of the pair's
///   vertices (4 distinct), with the shared edge as its diagonal `{q[1], q[3]}`; the
///   quads form a closed 2-manifold ([`check_closed_quad_surface`]) over exactly `K`'s
///   vertices, with the input's χ (V − E + F of the quad mesh) and orientability.
pub fn check_quadrangulation(
    input: &Triangulation,
    q: &contractible::quad::Quadrangulation,
    label: &str,
) {
    use std::collections::BTreeSet;
    let k = &q.tri;
    k.validate()
        .unwrap_or_else(|e| panic!("{label}: K invalid: {e}"));
    let in_vertices: Vec<VertexId> = input.vertices().collect();
    let k_vertices: Vec<VertexId> = k.vertices().collect();
    assert_eq!(in_vertices, k_vertices, "{label}: vertex set of K");
    assert_eq!(
        (k.vertex_count(), k.edge_count(), k.face_count()),
        (input.vertex_count(), input.edge_count(), input.face_count()),
        "{label}: counts of K"
    );
    let in_faces = input.face_list();
    let k_faces = k.face_list();
    let (chi, orientable) = closed_surface_invariants(&in_faces);
    assert_eq!(
        closed_surface_invariants(&k_faces),
        (chi, orientable),
        "{label}: χ / orientability of K"
    );
    let edges = |faces: &[[u32; 3]]| -> BTreeSet<(u32, u32)> {
        faces
            .iter()
            .flat_map(|&[a, b, c]| [(a, b), (b, c), (c, a)])
            .map(|(x, y)| (x.min(y), x.max(y)))
            .collect()
    };
    let (e_in, e_k) = (edges(&in_faces), edges(&k_faces));
    let removed = e_in.difference(&e_k).count();
    let added = e_k.difference(&e_in).count();
    assert_eq!(removed, added, "{label}: edges removed vs added");
    assert!(
        removed <= q.stats.flips,
        "{label}: K differs in {removed} edges, {} flips",
        q.stats.flips
    );

    // The pairing, from `pairs()` and the face vertices alone.
    let f_count = k.face_count();
    let mut seen = vec![0u8; k.face_capacity()];
    let pairs: Vec<(FaceId, FaceId)> = q.pairing.pairs().collect();
    for &(f, g) in &pairs {
        for h in [f, g] {
            assert!(
                h.index() < k.face_capacity() && k.is_face(h),
                "{label}: pair ({f}, {g}) holds a face that is not live"
            );
            seen[h.index()] += 1;
        }
        assert_eq!(q.pairing.mate(f), Some(g), "{label}: mate({f})");
        assert_eq!(q.pairing.mate(g), Some(f), "{label}: mate({g})");
        let (vf, vg) = (k.face_vertices(f), k.face_vertices(g));
        let shared = vf.iter().filter(|v| vg.contains(v)).count();
        assert_eq!(
            shared, 2,
            "{label}: pair ({f}, {g}) shares {shared} vertices"
        );
    }
    for f in k.faces() {
        assert_eq!(
            seen[f.index()],
            1,
            "{label}: face {f} in {} pairs",
            seen[f.index()]
        );
    }
    assert_eq!(2 * pairs.len(), f_count, "{label}: not perfect");

    let s = &q.stats;
    assert_eq!(s.faces, f_count, "{label}: stats.faces");
    assert_eq!(
        s.initial_unpaired,
        2 * s.augmenting_paths,
        "{label}: each augmenting path pairs two faces"
    );
    if f_count > 0 {
        let percent = 100.0 * (f_count - s.initial_unpaired) as f64 / f_count as f64;
        assert!(
            (percent - s.initial_paired_percent).abs() < 1e-9,
            "{label}: initial_paired_percent"
        );
    }

    // The quads: one per pair, on the pair's vertices, the shared edge as a diagonal.
    let quads = contractible::quad::quad_faces(k, &q.pairing)
        .unwrap_or_else(|| panic!("{label}: quad_faces refused a perfect pairing"));
    assert_eq!(quads.len(), pairs.len(), "{label}: one quad per pair");
    for (quad, &(f, g)) in quads.iter().zip(&pairs) {
        let (vf, vg) = (k.face_vertices(f), k.face_vertices(g));
        let mut union: Vec<u32> = vf.iter().chain(&vg).map(|v| v.0).collect();
        union.sort_unstable();
        union.dedup();
        let mut qs = quad.to_vec();
        qs.sort_unstable();
        assert_eq!(qs, union, "{label}: quad {quad:?} of ({f}, {g})");
        let mut diagonal = [quad[1], quad[3]];
        diagonal.sort_unstable();
        let mut common: Vec<u32> = vf.iter().filter(|v| vg.contains(v)).map(|v| v.0).collect();
        common.sort_unstable();
        assert_eq!(diagonal.to_vec(), common, "{label}: diagonal of {quad:?}");
    }
    let (quad_chi, quad_orientable) = check_closed_quad_surface(&quads, label);
    let quad_vertices: BTreeSet<u32> = quads.iter().flatten().copied().collect();
    let k_ids: BTreeSet<u32> = k_vertices.iter().map(|v| v.0).collect();
    assert_eq!(quad_vertices, k_ids, "{label}: vertices of the quads");
    assert_eq!(quad_chi, chi, "{label}: χ of the quad mesh");
    assert_eq!(
        quad_orientable, orientable,
        "{label}: orientability of the quads"
    );
    if is_consistently_oriented(&in_faces) {
        // Each directed quad edge once: a consistent orientation carried over.
        let mut directed = BTreeSet::new();
        for quad in &quads {
            for i in 0..4 {
                assert!(
                    directed.insert((quad[i], quad[(i + 1) % 4])),
                    "{label}: oriented input, quad edge {:?} used twice in one direction",
                    (quad[i], quad[(i + 1) % 4])
                );
            }
        }
    }
}

/// Whether every directed edge of `faces` occurs at most once (on a closed surface:
/// the faces are consistently oriented).
pub fn is_consistently_oriented(faces: &[[u32; 3]]) -> bool {
    let mut directed = std::collections::HashSet::new();
    faces.iter().all(|&[a, b, c]| {
        [(a, b), (b, c), (c, a)]
            .into_iter()
            .all(|e| directed.insert(e))
    })
}

/// Checks that `quads` (each with 4 distinct vertices) form a closed 2-manifold: every
/// undirected quad edge lies in exactly two quads, and the quads around each vertex form
/// a single cycle (the graph whose nodes are the quad edges at `v` and whose links join
/// the two edges at `v` of each quad at `v` is one cycle). Returns χ = V − E + F of the
/// quad mesh and its orientability (whether the quads can be oriented so that each edge
/// is traversed once in each direction: a breadth-first propagation of orientations).
/// Independent of the library: it reads only the vertex lists.
pub fn check_closed_quad_surface(quads: &[[u32; 4]], label: &str) -> (i64, bool) {
    use std::collections::{BTreeMap, BTreeSet};
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    // Undirected edge -> the quads holding it, each with the direction it is used in.
    let mut edge_quads: BTreeMap<(u32, u32), Vec<(usize, bool)>> = BTreeMap::new();
    for (i, q) in quads.iter().enumerate() {
        let mut s = *q;
        s.sort_unstable();
        assert!(
            s.windows(2).all(|w| w[0] != w[1]),
            "{label}: quad {q:?} repeats a vertex"
        );
        for j in 0..4 {
            let (a, b) = (q[j], q[(j + 1) % 4]);
            edge_quads.entry(key(a, b)).or_default().push((i, a < b));
        }
    }
    for (e, qs) in &edge_quads {
        assert_eq!(
            qs.len(),
            2,
            "{label}: quad edge {e:?} in {} quads",
            qs.len()
        );
    }
    // Vertex links: per vertex v, the quad edges [v, w] at v joined through each quad.
    let mut at: BTreeMap<u32, Vec<(u32, u32)>> = BTreeMap::new();
    for q in quads {
        for j in 0..4 {
            let v = q[j];
            at.entry(v)
                .or_default()
                .push((q[(j + 3) % 4], q[(j + 1) % 4]));
        }
    }
    for (v, wedges) in &at {
        let mut adj: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
        for &(a, b) in wedges {
            adj.entry(a).or_default().push(b);
            adj.entry(b).or_default().push(a);
        }
        for (w, n) in &adj {
            assert_eq!(
                n.len(),
                2,
                "{label}: edge [{v}, {w}] in {} quads at {v}",
                n.len()
            );
        }
        // Connected (every node of degree 2): the link is one cycle.
        let start = *adj.keys().next().expect("a vertex of a quad has edges");
        let mut reached = BTreeSet::from([start]);
        let mut stack = vec![start];
        while let Some(w) = stack.pop() {
            for &x in &adj[&w] {
                if reached.insert(x) {
                    stack.push(x);
                }
            }
        }
        assert_eq!(
            reached.len(),
            adj.len(),
            "{label}: the link of vertex {v} is not a single cycle"
        );
    }
    // Orientability: flip[i] says whether quad i is reversed; the two quads of an edge
    // must use it in opposite directions after the flips.
    let mut flip: Vec<Option<bool>> = vec![None; quads.len()];
    let mut neighbours: Vec<Vec<(usize, bool)>> = vec![Vec::new(); quads.len()];
    for qs in edge_quads.values() {
        let [(i, di), (j, dj)] = [qs[0], qs[1]];
        // Same direction: exactly one of the two must be flipped.
        let differ = di == dj;
        neighbours[i].push((j, differ));
        neighbours[j].push((i, differ));
    }
    let mut orientable = true;
    for s in 0..quads.len() {
        if flip[s].is_some() {
            continue;
        }
        flip[s] = Some(false);
        let mut stack = vec![s];
        while let Some(i) = stack.pop() {
            let fi = flip[i].unwrap_or(false);
            for &(j, differ) in &neighbours[i] {
                let want = fi ^ differ;
                match flip[j] {
                    None => {
                        flip[j] = Some(want);
                        stack.push(j);
                    }
                    Some(fj) if fj != want => orientable = false,
                    Some(_) => {}
                }
            }
        }
    }
    let v = at.len() as i64;
    let e = edge_quads.len() as i64;
    (v - e + quads.len() as i64, orientable)
}

// ---- Short-edge simplification (`simplify`): an independent topology checker and the
// `simplify` target's checks.

/// The topological type of one connected component of a surface with boundary, as
/// [`surface_topology`] computes it from a bare face list.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct ComponentType {
    /// V − E + F of the component.
    pub euler: i64,
    /// Whether its faces can be oriented consistently.
    pub orientable: bool,
    /// Number of boundary loops (cycles of edges in one face).
    pub boundary_loops: usize,
}

/// What [`surface_topology`] finds: the components' types (sorted, so two meshes of the
/// same surfaces compare equal whatever their order) and the global counts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Topology {
    /// One entry per connected component, sorted.
    pub components: Vec<ComponentType>,
    /// Vertices used by a face.
    pub vertices: usize,
    /// Distinct edges.
    pub edges: usize,
    /// Edges in exactly one face.
    pub boundary_edges: usize,
    /// Faces.
    pub faces: usize,
}

impl Topology {
    /// The total number of boundary loops.
    pub fn loops(&self) -> usize {
        self.components.iter().map(|c| c.boundary_loops).sum()
    }
}

fn uf_find(parent: &mut [u32], mut i: u32) -> u32 {
    while parent[i as usize] != i {
        let p = parent[parent[i as usize] as usize];
        parent[i as usize] = p;
        i = p;
    }
    i
}

fn uf_union(parent: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (uf_find(parent, a), uf_find(parent, b));
    if ra == rb {
        return false;
    }
    parent[ra as usize] = rb;
    true
}

/// Classifies `faces` as a disjoint union of compact 2-manifolds with boundary, sharing
/// no code with the library: no degenerate face, no duplicate face (as a vertex set),
/// every edge in one or two faces, the faces around every vertex one fan (its link a
/// single cycle, or a single path for a boundary vertex). Then per connected component
/// (faces joined through shared edges): χ = V − E + F, orientability (a flip bit per
/// face propagated through the interior edges: the two faces of an edge must traverse
/// it in opposite directions), and the boundary loops (cycles of the one-face edges).
/// `Err` names the first violation found. O(F log F).
pub fn surface_topology(faces: &[[u32; 3]]) -> Result<Topology, String> {
    let n = faces
        .iter()
        .flat_map(|f| f.iter())
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0);
    for (i, f) in faces.iter().enumerate() {
        if f[0] == f[1] || f[1] == f[2] || f[0] == f[2] {
            return Err(format!("face {i} {f:?} is degenerate"));
        }
    }
    let mut sorted: Vec<([u32; 3], usize)> = faces
        .iter()
        .enumerate()
        .map(|(i, f)| {
            let mut s = *f;
            s.sort_unstable();
            (s, i)
        })
        .collect();
    sorted.sort_unstable();
    if let Some(w) = sorted.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(format!(
            "faces {} and {} are the same triangle",
            w[0].1, w[1].1
        ));
    }
    drop(sorted);
    // Edges: (low, high, face, whether the face runs low → high).
    let mut edges: Vec<(u32, u32, u32, bool)> = Vec::with_capacity(3 * faces.len());
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            edges.push((a.min(b), a.max(b), i as u32, a < b));
        }
    }
    edges.sort_unstable();
    // Face adjacency across interior edges: (neighbour, must the flip bits differ).
    let mut adj: Vec<Vec<(u32, bool)>> = vec![Vec::new(); faces.len()];
    let mut boundary: Vec<(u32, u32)> = Vec::new();
    let mut edge_face: Vec<u32> = Vec::new();
    let mut i = 0;
    while i < edges.len() {
        let mut j = i;
        while j < edges.len() && edges[j].0 == edges[i].0 && edges[j].1 == edges[i].1 {
            j += 1;
        }
        let (a, b) = (edges[i].0, edges[i].1);
        match j - i {
            1 => boundary.push((a, b)),
            2 => {
                let (f, df) = (edges[i].2, edges[i].3);
                let (g, dg) = (edges[i + 1].2, edges[i + 1].3);
                // Same direction in both faces: exactly one of them must be flipped.
                adj[f as usize].push((g, df == dg));
                adj[g as usize].push((f, df == dg));
            }
            k => return Err(format!("edge [{a}, {b}] is in {k} faces")),
        }
        edge_face.push(edges[i].2);
        i = j;
    }
    drop(edges);
    // Vertex links: the edge opposite each vertex in each of its faces must form one
    // cycle or one path (edges in ≤ 2 faces already bound every link degree by 2).
    let mut start = vec![0usize; n + 1];
    for f in faces {
        for &v in f {
            start[v as usize + 1] += 1;
        }
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut link_edges = vec![(0u32, 0u32); 3 * faces.len()];
    for f in faces {
        for k in 0..3 {
            let v = f[k] as usize;
            link_edges[fill[v]] = (f[(k + 1) % 3], f[(k + 2) % 3]);
            fill[v] += 1;
        }
    }
    let mut used = 0usize;
    let mut ends: Vec<(u32, u32)> = Vec::new();
    for v in 0..n {
        let link = &link_edges[start[v]..start[v + 1]];
        if link.is_empty() {
            continue;
        }
        used += 1;
        ends.clear();
        for (e, &(a, b)) in link.iter().enumerate() {
            ends.push((a, e as u32));
            ends.push((b, e as u32));
        }
        ends.sort_unstable();
        let mut odd = Vec::new();
        let mut k = 0;
        while k < ends.len() {
            let mut m = k;
            while m < ends.len() && ends[m].0 == ends[k].0 {
                m += 1;
            }
            match m - k {
                1 => odd.push(ends[k].0),
                2 => {}
                d => {
                    return Err(format!(
                        "vertex {v}: link vertex {} has degree {d}",
                        ends[k].0
                    ))
                }
            }
            k = m;
        }
        if !odd.is_empty() && odd.len() != 2 {
            return Err(format!("vertex {v}: its link has {} path ends", odd.len()));
        }
        // Walk the link from a path end (or anywhere on a cycle); it must use every edge.
        let other_edge = |w: u32, e: u32| -> Option<u32> {
            let p = ends.partition_point(|&(x, _)| x < w);
            ends[p..]
                .iter()
                .take_while(|&&(x, _)| x == w)
                .map(|&(_, f)| f)
                .find(|&f| f != e)
        };
        let first = odd.first().copied().unwrap_or(link[0].0);
        let first_edge = ends[ends.partition_point(|&(x, _)| x < first)].1;
        let (mut w, mut e, mut walked) = (first, first_edge, 1usize);
        loop {
            let (a, b) = link[e as usize];
            w = if a == w { b } else { a };
            match other_edge(w, e) {
                Some(next) if w != first => {
                    e = next;
                    walked += 1;
                }
                _ => break,
            }
        }
        if walked != link.len() {
            return Err(format!(
                "vertex {v}: its faces form more than one fan ({walked} of {} faces reached)",
                link.len()
            ));
        }
    }
    // Components through interior edges, with orientation bits.
    let mut comp = vec![u32::MAX; faces.len()];
    let mut flip = vec![false; faces.len()];
    let mut orientable = Vec::new();
    let mut stack = Vec::new();
    for s in 0..faces.len() {
        if comp[s] != u32::MAX {
            continue;
        }
        let c = orientable.len() as u32;
        orientable.push(true);
        comp[s] = c;
        stack.push(s as u32);
        while let Some(f) = stack.pop() {
            for &(g, differ) in &adj[f as usize] {
                let want = flip[f as usize] ^ differ;
                if comp[g as usize] == u32::MAX {
                    comp[g as usize] = c;
                    flip[g as usize] = want;
                    stack.push(g);
                } else if flip[g as usize] != want {
                    orientable[c as usize] = false;
                }
            }
        }
    }
    let count = orientable.len();
    let mut euler = vec![0i64; count];
    let mut vcomp = vec![u32::MAX; n];
    for (f, vs) in faces.iter().enumerate() {
        euler[comp[f] as usize] += 1;
        for &v in vs {
            let slot = &mut vcomp[v as usize];
            if *slot == u32::MAX {
                *slot = comp[f];
                euler[comp[f] as usize] += 1;
            } else if *slot != comp[f] {
                // Impossible when every link is one fan; kept as a check of the checker.
                return Err(format!("vertex {v} is in two components"));
            }
        }
    }
    for &f in &edge_face {
        euler[comp[f as usize] as usize] -= 1;
    }
    // Boundary loops: every boundary vertex has exactly two boundary edges (its link is
    // a path), so the boundary edges form disjoint cycles; count them per component.
    let mut parent: Vec<u32> = (0..n as u32).collect();
    let mut on_boundary = vec![0u8; n];
    for &(a, b) in &boundary {
        uf_union(&mut parent, a, b);
        on_boundary[a as usize] += 1;
        on_boundary[b as usize] += 1;
    }
    let mut loops = vec![0usize; count];
    for v in 0..n as u32 {
        match on_boundary[v as usize] {
            0 => {}
            2 => {
                if uf_find(&mut parent, v) == v {
                    loops[vcomp[v as usize] as usize] += 1;
                }
            }
            k => return Err(format!("vertex {v} is on {k} boundary edges")),
        }
    }
    let mut components: Vec<ComponentType> = (0..count)
        .map(|c| ComponentType {
            euler: euler[c],
            orientable: orientable[c],
            boundary_loops: loops[c],
        })
        .collect();
    components.sort_unstable();
    Ok(Topology {
        components,
        vertices: used,
        edges: edge_face.len(),
        boundary_edges: boundary.len(),
        faces: faces.len(),
    })
}

/// The distinct edges of `faces` and the squared length of each.
fn edge_lengths2(faces: &[[u32; 3]], positions: &[[f64; 3]]) -> Vec<f64> {
    let mut edges: Vec<(u32, u32)> = faces
        .iter()
        .flat_map(|f| (0..3).map(move |k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3]))))
        .collect();
    edges.sort_unstable();
    edges.dedup();
    edges
        .iter()
        .map(|&(a, b)| {
            let (p, q) = (positions[a as usize], positions[b as usize]);
            let d = [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
            d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
        })
        .collect()
}

/// The number of distinct edges of `faces` strictly shorter than `eps`.
pub fn short_edge_count(faces: &[[u32; 3]], positions: &[[f64; 3]], eps: f64) -> usize {
    edge_lengths2(faces, positions)
        .into_iter()
        .filter(|&l2| l2 < eps * eps)
        .count()
}

/// Simplifies `mesh` with `opts` and checks the result by code independent of the
/// simplifier: [`surface_topology`] of the output equals that of the input (the sorted
/// per-component (χ, orientable, loops), hence also the component count); the positions
/// are finite, one per vertex, every vertex used; the statistics agree with the meshes
/// (vertex, face, component and loop counts; one vertex fewer per contraction and per
/// vertex removed inside a disc; two faces fewer per contraction and per removed
/// vertex, one less per boundary edge lost; the shortest output edge); every output edge
/// shorter than ε is counted once in `stats.remaining` (recounted here from the output),
/// none of them as `frozen`; the naive mode removes no disc and never skips for
/// `non_disc`; with the guard off nothing is skipped for fold-over. Panics with `label`.
pub fn check_simplify(
    mesh: &contractible::TriMesh,
    opts: &contractible::simplify::Options,
    label: &str,
) -> contractible::simplify::Simplified {
    let before = surface_topology(&mesh.faces).unwrap_or_else(|e| panic!("{label}: input: {e}"));
    check_simplify_with(mesh, &before, opts, label)
}

/// [`check_simplify`] with the input's topology already computed (`before` must be
/// [`surface_topology`] of `mesh.faces`; it depends only on the faces, so a perturbed
/// copy of a mesh shares it).
pub fn check_simplify_with(
    mesh: &contractible::TriMesh,
    before: &Topology,
    opts: &contractible::simplify::Options,
    label: &str,
) -> contractible::simplify::Simplified {
    use contractible::simplify::{simplify, Mode};
    assert_eq!(
        before.faces,
        mesh.faces.len(),
        "{label}: `before` is another mesh's"
    );
    let out = simplify(mesh, opts).unwrap_or_else(|e| panic!("{label}: simplify: {e}"));
    let s = &out.stats;
    let m = &out.mesh;
    let after = surface_topology(&m.faces)
        .unwrap_or_else(|e| panic!("{label}: the output is not a surface: {e}"));
    assert_eq!(
        after.components, before.components,
        "{label}: the surface changed (per component: χ, orientable, boundary loops)"
    );
    let positions = m
        .positions
        .as_deref()
        .unwrap_or_else(|| panic!("{label}: output without positions"));
    assert_eq!(
        positions.len(),
        m.vertex_count,
        "{label}: one position per vertex"
    );
    assert!(
        positions.iter().flatten().all(|x| x.is_finite()),
        "{label}: a non-finite output coordinate"
    );
    assert_eq!(
        after.vertices, m.vertex_count,
        "{label}: an unused output vertex"
    );
    // Statistics against the meshes.
    assert_eq!(s.faces_in, mesh.faces.len(), "{label}: faces_in");
    assert_eq!(s.vertices_in, before.vertices, "{label}: vertices_in");
    assert_eq!(s.faces_out, m.faces.len(), "{label}: faces_out");
    assert_eq!(s.vertices_out, m.vertex_count, "{label}: vertices_out");
    assert_eq!(s.components, before.components.len(), "{label}: components");
    assert_eq!(s.boundary_loops, before.loops(), "{label}: boundary_loops");
    assert_eq!(
        s.vertices_in - s.vertices_out,
        s.edges_contracted + s.vertices_removed_inside,
        "{label}: one vertex per contraction and per vertex removed inside a disc"
    );
    // An interior edge's contraction removes two faces, a boundary edge's one (and the
    // loop loses that edge); a disc of 2I + 1 faces becomes one face.
    let lost_boundary = before.boundary_edges - after.boundary_edges;
    assert_eq!(
        s.faces_in - s.faces_out,
        2 * s.edges_contracted - lost_boundary + 2 * s.vertices_removed_inside,
        "{label}: faces removed"
    );
    assert!(
        s.vertices_removed_inside >= s.discs_removed,
        "{label}: a removed disc has an interior vertex"
    );
    if !m.faces.is_empty() {
        assert!(s.passes >= 1, "{label}: no pass");
    }
    let lengths = edge_lengths2(&m.faces, positions);
    let shortest = lengths.iter().copied().fold(f64::INFINITY, f64::min);
    match s.shortest_remaining_edge {
        None => assert!(lengths.is_empty(), "{label}: shortest edge missing"),
        Some(l) => assert!(
            (l - shortest.sqrt()).abs() <= 1e-12 * l.max(1e-300),
            "{label}: shortest_remaining_edge {l} but the output's is {}",
            shortest.sqrt()
        ),
    }
    // Every short edge accounted for, recounted from the output.
    let short = lengths
        .iter()
        .filter(|&&l2| l2 < opts.eps * opts.eps)
        .count();
    assert_eq!(
        short, s.short_edges_remaining,
        "{label}: the output has {short} edges shorter than ε, stats say {}",
        s.short_edges_remaining
    );
    assert_eq!(s.remaining.total(), short, "{label}: remaining by reason");
    assert_eq!(
        s.remaining.frozen, 0,
        "{label}: a short edge left as frozen"
    );
    if opts.mode == Mode::Naive {
        assert_eq!(s.discs_removed, 0, "{label}: naive removed a disc");
        assert_eq!(
            s.vertices_removed_inside, 0,
            "{label}: naive removed vertices"
        );
        assert_eq!(
            s.skipped.non_disc + s.remaining.non_disc,
            0,
            "{label}: naive non_disc"
        );
    }
    if !opts.guard {
        assert_eq!(
            s.skipped.foldover + s.remaining.foldover,
            0,
            "{label}: guard off"
        );
    }
    out
}

/// [`check_simplify_with`] in both modes with the other options of `opts`; also checks that
/// the nested mode contracts at least as many edges as the naive one (it runs the naive
/// passes to their fixed point first). Returns (naive, nested).
pub fn check_simplify_modes(
    mesh: &contractible::TriMesh,
    before: &Topology,
    opts: &contractible::simplify::Options,
    label: &str,
) -> (
    contractible::simplify::Simplified,
    contractible::simplify::Simplified,
) {
    use contractible::simplify::{Mode, Options as SOptions};
    let naive = check_simplify_with(
        mesh,
        before,
        &SOptions {
            mode: Mode::Naive,
            ..*opts
        },
        &format!("{label} naive"),
    );
    let nested = check_simplify_with(
        mesh,
        before,
        &SOptions {
            mode: Mode::Nested,
            ..*opts
        },
        &format!("{label} nested"),
    );
    assert!(
        nested.stats.edges_contracted >= naive.stats.edges_contracted,
        "{label}: nested contracted {} edges, naive {}",
        nested.stats.edges_contracted,
        naive.stats.edges_contracted
    );
    (naive, nested)
}

/// At most this many operations of a [`SimplifyInput`]'s surface are applied (the
/// simplifier runs twice per input and the checker is O(F log F): keep inputs small).
pub const SIMPLIFY_OPS: usize = 400;
/// At most this many faces are removed to make boundary.
pub const SIMPLIFY_HOLES: usize = 8;

/// The input of `simplify`: a random closed surface (as `surface_ops` grows it, at most
/// [`SIMPLIFY_OPS`] operations), random positions, faces removed to open it, a random ε
/// and random options.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct SimplifyInput {
    /// The surface (its `seed` is unused).
    pub base: SurfaceInput,
    /// Seed of the positions ([`Rng`]).
    pub positions: u64,
    /// Rounds of neighbour averaging applied to the random positions (`% 4`): 0 leaves
    /// them scattered in the unit cube, more rounds make a crumpled surface with many
    /// short edges.
    pub smoothing: u8,
    /// ε as a fraction of the bounding-box diagonal: `(eps / 65535)² · 0.6`.
    pub eps: u16,
    /// Faces to remove (ids mod F, in order); a face sharing a vertex with one already
    /// removed is kept, so the result stays a surface with boundary.
    pub holes: Vec<u16>,
    /// Options of [`contractible::simplify::Options`]: `side % 3` (count, path,
    /// Euclidean), the quadric position, the guard.
    pub side: u8,
    /// Quadric positions instead of midpoints.
    pub quadric: bool,
    /// The geometry guard.
    pub guard: bool,
}

/// The mesh and ε a [`SimplifyInput`] describes.
pub fn simplify_mesh(input: &SimplifyInput) -> (contractible::TriMesh, f64) {
    let base = SurfaceInput {
        ops: input.base.ops.iter().take(SIMPLIFY_OPS).copied().collect(),
        ..input.base.clone()
    };
    let tri = build_surface(&base);
    let n = tri.vertex_capacity();
    let mut rng = Rng::new(input.positions);
    let unit = |rng: &mut Rng| (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    let mut pos: Vec<[f64; 3]> = (0..n)
        .map(|_| [unit(&mut rng), unit(&mut rng), unit(&mut rng)])
        .collect();
    smooth_positions(&tri, &mut pos, usize::from(input.smoothing % 4));
    let mut faces = tri.face_list();
    let mut holed = vec![false; n];
    for &h in input.holes.iter().take(SIMPLIFY_HOLES) {
        if faces.len() <= 1 {
            break;
        }
        let i = usize::from(h) % faces.len();
        if faces[i].iter().any(|&v| holed[v as usize]) {
            continue;
        }
        for &v in &faces[i] {
            holed[v as usize] = true;
        }
        faces.swap_remove(i);
    }
    let diag = contractible::simplify::bbox_diagonal(pos.iter().copied());
    let r = f64::from(input.eps) / 65535.0;
    let eps = (r * r * 0.6 * diag).max(1e-9);
    (contractible::TriMesh::with_positions(pos, faces), eps)
}

/// `simplify`: the mesh of `input` simplified in both modes with its options, each run
/// checked by [`check_simplify`] (independent topology and accounting), nested ≥ naive
/// contractions.
pub fn check_simplify_input(input: &SimplifyInput) {
    use contractible::simplify::{Options as SOptions, Position, Side};
    let (mesh, eps) = simplify_mesh(input);
    let opts = SOptions {
        side: [Side::Count, Side::Path, Side::Euclidean][usize::from(input.side % 3)],
        position: if input.quadric {
            Position::Quadric
        } else {
            Position::Midpoint
        },
        guard: input.guard,
        ..SOptions::new(eps)
    };
    let before = surface_topology(&mesh.faces).expect("a random surface with holes");
    check_simplify_modes(&mesh, &before, &opts, "simplify input");
}

/// `rounds` rounds of Laplacian smoothing of `pos` (indexed by vertex id) over `tri`:
/// each vertex moves halfway to the mean of its neighbours (a full step would collapse
/// K7 to a point). Shared by the fuzz target and the property tests.
pub fn smooth_positions(tri: &Triangulation, pos: &mut [[f64; 3]], rounds: usize) {
    for _ in 0..rounds {
        let old = pos.to_vec();
        for v in tri.vertices() {
            let mut sum = [0.0; 3];
            let mut k = 0.0;
            for w in tri.link(v) {
                for (s, x) in sum.iter_mut().zip(old[w.index()]) {
                    *s += x;
                }
                k += 1.0;
            }
            let o = old[v.index()];
            pos[v.index()] = [0, 1, 2].map(|i| 0.5 * o[i] + 0.5 * sum[i] / k);
        }
    }
}
