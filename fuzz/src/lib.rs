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
        keep_history: true,
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
    check_streamed(bytes, format);
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

/// A reader handing out 1 to 7 bytes per call, so that every line and record of a
/// stream crosses buffer refills.
pub struct Trickle<'a> {
    bytes: &'a [u8],
    calls: usize,
}

impl<'a> Trickle<'a> {
    /// Streams `bytes`.
    pub fn new(bytes: &'a [u8]) -> Self {
        Trickle { bytes, calls: 0 }
    }
}

impl std::io::Read for Trickle<'_> {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        self.calls += 1;
        let n = (self.calls % 7 + 1).min(out.len()).min(self.bytes.len());
        out[..n].copy_from_slice(&self.bytes[..n]);
        self.bytes = &self.bytes[n..];
        Ok(n)
    }
}

/// Reading `bytes` streamed from a reader gives what reading them from memory gives: the
/// same mesh, or an error of the same kind at the same location. Skipped where the STL
/// rule needs the length that only memory knows beforehand (documented at
/// `contractible::io::decode_reader`): gzip STL, and undeclared content whose length is
/// that of a binary STL.
pub fn check_streamed(bytes: &[u8], format: Option<Format>) {
    let gzip = bytes.starts_with(&[0x1f, 0x8b]);
    let outcome = |r: Result<contractible::TriMesh, contractible::io::ReadError>| match r {
        Ok(m) => Ok(m),
        Err(e) => Err((format!("{:?}", e.kind), e.location)),
    };
    let (memory, streamed) = match format {
        Some(f) => {
            if gzip && f == Format::Stl {
                return;
            }
            (
                outcome(read_tri_mesh_bytes(bytes, Some(f))),
                outcome(contractible::io::read_tri_mesh_from(Trickle::new(bytes), f)),
            )
        }
        None => {
            let binary_stl_size = bytes.get(80..84).is_some_and(|c| {
                let n = u64::from(u32::from_le_bytes([c[0], c[1], c[2], c[3]]));
                (bytes.len() - 84) as u64 == 50 * n
            });
            if gzip || binary_stl_size {
                return;
            }
            let tri = |r: Result<contractible::io::Decoded, contractible::io::ReadError>| {
                r.and_then(|d| d.mesh.into_tri_mesh())
            };
            (
                outcome(tri(contractible::io::decode(bytes, None))),
                outcome(tri(contractible::io::decode_reader(
                    Trickle::new(bytes),
                    None,
                ))),
            )
        }
    };
    assert_eq!(
        memory, streamed,
        "streamed reading differs from reading from memory"
    );
}

/// χ and orientability by the face-list oracle; panics if the faces are not a closed surface.
fn closed_surface_invariants(faces: &[[u32; 3]]) -> (i64, bool) {
    contractible::spec::oracle::euler_and_orientability(faces).expect("a closed surface")
}

/// The quad algorithms run by [`check_quads`]: every one, in the order of
/// [`contractible::quad::Algorithm::ALL`] (so an algorithm added to the library is fuzzed
/// without a change here).
pub const QUAD_ALGORITHMS: [contractible::quad::Algorithm; 8] = contractible::quad::Algorithm::ALL;

/// The most faces `alg`'s structures hold: the node limit of its Frink strategy
/// ([`contractible::quad::frink::Strategy::max_nodes`]; the dual graph has one node per
/// face), `None` for the algorithms without one (LRS, PS, SG, matching).
pub fn frink_limit(alg: contractible::quad::Algorithm) -> Option<usize> {
    use contractible::quad::frink::{self, Strategy as _};
    use contractible::quad::Algorithm as QAlg;
    match alg {
        QAlg::DsNaive => Some(frink::Naive::new().max_nodes()),
        QAlg::FrinkLct => Some(frink::CoverTree::new().max_nodes()),
        QAlg::DiksStanczyk => Some(frink::DiksStanczyk::new().max_nodes()),
        QAlg::BiedlBoseDemaineLubiw => Some(frink::BiedlBoseDemaineLubiw::new().max_nodes()),
        _ => None,
    }
}

/// `quad_ops`: the surface of `input` (as `surface_ops` builds it) converted by every
/// tri-quad algorithm with `Options { seed: input.seed }`, each result checked by
/// [`convert_checked`]; LRS must leave exactly the face count of RS's irreducible
/// output unpaired before the completion (`irreducible::rs::reduce` on the same input).
pub fn check_quads(input: &SurfaceInput) {
    let tri = build_surface(input);
    let reduced = contractible::irreducible::rs::reduce(tri.clone(), &options(input.seed))
        .tri
        .face_count();
    for alg in QUAD_ALGORITHMS {
        convert_checked(&tri, alg, input.seed, reduced);
    }
}

/// One algorithm of [`check_quads`] on `tri` (also used by the exhaustive twins):
/// [`convert_checked`], which must convert (`tri` is within every strategy's limit).
pub fn check_quad_algorithm(
    tri: &Triangulation,
    alg: contractible::quad::Algorithm,
    seed: u64,
    reduced: usize,
) -> contractible::quad::Quadrangulation {
    convert_checked(tri, alg, seed, reduced).unwrap_or_else(|| {
        panic!(
            "{}: {} faces refused as too large",
            alg.name(),
            tri.face_count()
        )
    })
}

/// Converts `tri` by `alg` and checks the outcome: [`ConvertError::TooLarge`] exactly
/// when the face count exceeds [`frink_limit`] (with the algorithm, the face count and
/// that limit in the error; then `None`), no other error; a conversion is checked by
/// [`check_quadrangulation`]; `reduced` is the face count of RS's irreducible output of
/// `tri`, which LRS must leave unpaired before its completion; every other algorithm
/// pairs the input itself (`K == tri`, no flips); the Frink algorithms are perfect
/// without a completion (nothing left unpaired, no augmenting path, no search).
///
/// [`ConvertError::TooLarge`]: contractible::quad::ConvertError::TooLarge
pub fn convert_checked(
    tri: &Triangulation,
    alg: contractible::quad::Algorithm,
    seed: u64,
    reduced: usize,
) -> Option<contractible::quad::Quadrangulation> {
    use contractible::quad::{convert, Algorithm as QAlg, ConvertError, Options as QOptions};
    let label = format!("{}(seed {seed})", alg.name());
    let faces = tri.face_count();
    let limit = frink_limit(alg);
    let q = match convert(tri.clone(), alg, &QOptions { seed }) {
        Ok(q) => q,
        Err(ConvertError::TooLarge {
            algorithm,
            faces: f,
            limit: l,
        }) => {
            assert_eq!(algorithm, alg, "{label}: TooLarge names another algorithm");
            assert_eq!(f, faces, "{label}: TooLarge face count");
            assert_eq!(Some(l), limit, "{label}: TooLarge limit");
            assert!(f > l, "{label}: {f} faces refused, the limit is {l}");
            return None;
        }
        Err(e) => panic!("{label}: a closed triangulation refused: {e}"),
    };
    if let Some(l) = limit {
        assert!(
            faces <= l,
            "{label}: {faces} faces converted, the limit is {l}"
        );
    }
    check_quadrangulation(tri, &q, &label);
    assert_eq!(q.algorithm, alg, "{label}: algorithm of the result");
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
    if alg.is_perfect_directly() {
        assert_eq!(
            (
                q.stats.initial_unpaired,
                q.stats.augmenting_paths,
                q.stats.phases
            ),
            (0, 0, 0),
            "{label}: Frink's reduction left work for a completion"
        );
    }
    Some(q)
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

/// A power of two that brings `largest` (a magnitude) to `[1, 2)`, from its exponent
/// bits, the exponent clamped to ±1000 so that the scale is a normal number (so a
/// subnormal value gets `2^1000`); 1 for 0 and for a non-finite value.
pub fn unit_scale(largest: f64) -> f64 {
    let biased = ((largest.to_bits() >> 52) & 0x7ff) as i32;
    if largest == 0.0 || biased == 0x7ff {
        return 1.0;
    }
    let exponent = if biased == 0 { -1000 } else { biased - 1023 };
    f64::from_bits(((1023 - exponent.clamp(-1000, 1000)) as u64) << 52)
}

/// Squared edge lengths of `faces`, robust to the ends of the `f64` range: the positions
/// multiplied by [`unit_scale`] of their largest coordinate (exact: a power of two), so
/// that nothing overflows. Their lengths are `sqrt(l2) / scale`.
pub struct EdgeLengths {
    /// The scale.
    pub scale: f64,
    /// The squared length of every distinct edge, scaled.
    pub l2: Vec<f64>,
}

impl EdgeLengths {
    /// The edges of `faces` over `positions`.
    pub fn of(faces: &[[u32; 3]], positions: &[[f64; 3]]) -> Self {
        let mut edges: Vec<(u32, u32)> = faces
            .iter()
            .flat_map(|f| (0..3).map(move |k| (f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3]))))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        let largest = edges
            .iter()
            .flat_map(|&(a, b)| {
                positions[a as usize]
                    .into_iter()
                    .chain(positions[b as usize])
            })
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let scale = unit_scale(largest);
        let l2 = edges
            .iter()
            .map(|&(a, b)| {
                let (p, q) = (positions[a as usize], positions[b as usize]);
                let d = [0, 1, 2].map(|i| p[i] * scale - q[i] * scale);
                d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
            })
            .collect();
        EdgeLengths { scale, l2 }
    }

    /// The shortest length (`None` without edges).
    pub fn shortest(&self) -> Option<f64> {
        let m = self.l2.iter().copied().fold(f64::INFINITY, f64::min);
        (!self.l2.is_empty()).then(|| m.sqrt() / self.scale)
    }

    /// How many are strictly shorter than `eps` (compared squared in the scaled
    /// coordinates; ε² at least the smallest positive number, so that an edge of length
    /// 0 is shorter than every ε > 0).
    pub fn shorter_than(&self, eps: f64) -> usize {
        let e = eps * self.scale;
        let e2 = (e * e).max(f64::from_bits(1));
        self.l2.iter().filter(|&&l2| l2 < e2).count()
    }
}

/// The number of distinct edges of `faces` strictly shorter than `eps`
/// ([`EdgeLengths::shorter_than`]).
pub fn short_edge_count(faces: &[[u32; 3]], positions: &[[f64; 3]], eps: f64) -> usize {
    EdgeLengths::of(faces, positions).shorter_than(eps)
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
    let out = contractible::simplify::simplify(mesh, opts)
        .unwrap_or_else(|e| panic!("{label}: simplify: {e}"));
    check_simplified(mesh, before, opts, &out.mesh, &out.stats, label);
    out
}

/// The checks of [`check_simplify_with`] on an output `m` with statistics `s` that a
/// run with `opts` made from `mesh` (by the lower-level call or by the task call
/// [`contractible::simplify()`](fn@contractible::simplify)).
pub fn check_simplified(
    mesh: &contractible::TriMesh,
    before: &Topology,
    opts: &contractible::simplify::Options,
    m: &contractible::TriMesh,
    s: &contractible::simplify::Stats,
    label: &str,
) {
    use contractible::simplify::Mode;
    assert_eq!(
        before.faces,
        mesh.faces.len(),
        "{label}: `before` is another mesh's"
    );
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
    let lengths = EdgeLengths::of(&m.faces, positions);
    match (s.shortest_remaining_edge, lengths.shortest()) {
        (None, None) => {}
        (Some(l), Some(shortest)) => assert!(
            l == shortest || (l - shortest).abs() <= 1e-12 * l,
            "{label}: shortest_remaining_edge {l} but the output's is {shortest}"
        ),
        (l, shortest) => {
            panic!("{label}: shortest_remaining_edge {l:?} but the output's is {shortest:?}")
        }
    }
    // Every short edge accounted for, recounted from the output.
    let short = lengths.shorter_than(opts.eps);
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

// ---- Positions for the simplifier and the task calls: degenerate and near-degenerate
// layouts, integer grids, wildly different scales.

/// How [`layout`] places the vertices (then scaled by `10^`[`scale_exponent`]).
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Geometry {
    /// Uniform in the unit cube, then `smoothing % 4` rounds halfway to the neighbours'
    /// mean (a crumpled surface with many short edges).
    Random {
        /// Rounds of smoothing (`% 4`).
        smoothing: u8,
    },
    /// Integer coordinates in `0..=range % 16`: coincident vertices, collinear and
    /// coplanar triples, zero-area faces (range 0 puts every vertex at the origin).
    Grid {
        /// The largest coordinate (`% 16`).
        range: u8,
    },
    /// Every vertex on one of `1 + points % 4` random points: coincident vertices
    /// everywhere (one point: no coordinates at all).
    Clusters {
        /// The number of points (`1 + points % 4`).
        points: u8,
    },
    /// On one random line (every face has zero area) or on one random plane.
    Flat {
        /// A plane instead of a line.
        plane: bool,
    },
    /// Integer coordinates in `0..=1 + range % 4`, every other vertex moved by a relative
    /// `10^-(12 + digits % 4)` on each axis: near-coincident vertices, near-collinear
    /// slivers beside exact ones.
    Perturbed {
        /// The largest coordinate (`1 + range % 4`).
        range: u8,
        /// The perturbation's exponent (`12 + digits % 4`).
        digits: u8,
    },
    /// Unit-cube positions, each vertex scaled by `10^k` for its own `k`, uniform in
    /// `-(spread % 64)..=spread % 64`: edge lengths of wildly different scales.
    Scales {
        /// The largest exponent (`% 64`).
        spread: u8,
    },
    /// Unit-cube positions shifted by `10^(digits % 18)` on every axis: the shape keeps
    /// only the last few digits of each coordinate (quantised, with coincident vertices
    /// and degenerate faces for large shifts).
    Shifted {
        /// The shift's exponent (`% 18`).
        digits: u8,
    },
}

/// A uniform sample of `[0, 1)`.
fn unit(rng: &mut Rng) -> f64 {
    (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

/// The sorted, distinct in-range neighbours of every vertex `0..n` in `faces` (indices
/// `>= n` are skipped).
pub fn neighbours(n: usize, faces: &[[u32; 3]]) -> Vec<Vec<u32>> {
    let mut adj = vec![Vec::new(); n];
    for f in faces {
        for k in 0..3 {
            let (a, b) = (f[k] as usize, f[(k + 1) % 3] as usize);
            if a < n && b < n && a != b {
                adj[a].push(b as u32);
                adj[b].push(a as u32);
            }
        }
    }
    for a in &mut adj {
        a.sort_unstable();
        a.dedup();
    }
    adj
}

/// The exponent of a fuzzed scale: `scale · |scale| / 64` (0 for `|scale| < 8`, ±252 at
/// the ends: unit scale and extreme ones both common).
pub fn scale_exponent(scale: i8) -> i32 {
    let s = i32::from(scale);
    s * s.abs() / 64
}

/// Positions for the `neighbours.len()` vertices: `geometry` drawn from the stream of
/// `seed`, then every coordinate times `10^`[`scale_exponent`]`(scale)`; each vertex's total exponent is
/// clamped so that every coordinate stays below `1e300` in magnitude (finite, as the
/// simplifier requires; squared lengths and areas may still overflow, which the checks
/// must survive). Every coordinate is finite.
pub fn layout(geometry: Geometry, scale: i8, seed: u64, neighbours: &[Vec<u32>]) -> Vec<[f64; 3]> {
    let n = neighbours.len();
    let mut rng = Rng::new(seed);
    let point = |rng: &mut Rng| [unit(rng), unit(rng), unit(rng)];
    let mut exponent = vec![0i32; n];
    let mut pos: Vec<[f64; 3]> = match geometry {
        Geometry::Random { smoothing } => {
            let mut pos: Vec<[f64; 3]> = (0..n).map(|_| point(&mut rng)).collect();
            for _ in 0..smoothing % 4 {
                let old = pos.clone();
                for (v, near) in neighbours.iter().enumerate() {
                    if near.is_empty() {
                        continue;
                    }
                    let k = near.len() as f64;
                    let mean = [0, 1, 2]
                        .map(|i| near.iter().map(|&w| old[w as usize][i]).sum::<f64>() / k);
                    pos[v] = [0, 1, 2].map(|i| 0.5 * old[v][i] + 0.5 * mean[i]);
                }
            }
            pos
        }
        Geometry::Grid { range } => {
            let k = u64::from(range % 16) + 1;
            (0..n)
                .map(|_| [0; 3].map(|_: i32| rng.below(k) as f64))
                .collect()
        }
        Geometry::Clusters { points } => {
            let centres: Vec<[f64; 3]> = (0..1 + points % 4).map(|_| point(&mut rng)).collect();
            (0..n).map(|_| centres[rng.index(centres.len())]).collect()
        }
        Geometry::Flat { plane } => {
            let (origin, u, w) = (point(&mut rng), point(&mut rng), point(&mut rng));
            (0..n)
                .map(|_| {
                    let (s, t) = (unit(&mut rng), if plane { unit(&mut rng) } else { 0.0 });
                    [0, 1, 2].map(|i| origin[i] + s * u[i] + t * w[i])
                })
                .collect()
        }
        Geometry::Perturbed { range, digits } => {
            let k = u64::from(range % 4) + 2;
            let delta = 10f64.powi(-(12 + i32::from(digits % 4)));
            (0..n)
                .map(|v| {
                    let p = [0; 3].map(|_: i32| rng.below(k) as f64);
                    if v % 2 == 0 {
                        return p;
                    }
                    p.map(|x| x + x.abs().max(1.0) * delta * (2.0 * unit(&mut rng) - 1.0))
                })
                .collect()
        }
        Geometry::Scales { spread } => {
            let s = u64::from(spread % 64);
            (0..n)
                .map(|v| {
                    exponent[v] = rng.below(2 * s + 1) as i32 - s as i32;
                    point(&mut rng)
                })
                .collect()
        }
        Geometry::Shifted { digits } => {
            let shift = 10f64.powi(i32::from(digits % 18));
            (0..n).map(|_| point(&mut rng).map(|x| x + shift)).collect()
        }
    };
    for (p, e) in pos.iter_mut().zip(&exponent) {
        let largest = p.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        // `largest · 10^top < 1e300`: `largest` is below 10^18.
        let top = 299 - largest.log10().ceil() as i32;
        let e = (e + scale_exponent(scale)).clamp(-300, top);
        let f = 10f64.powi(e);
        *p = p.map(|x| x * f);
    }
    assert!(
        pos.iter().flatten().all(|x| x.is_finite()),
        "layout made a non-finite coordinate"
    );
    pos
}

/// The diagonal of the axis-aligned bounding box of `points`, computed here (not by the
/// library's `bbox_diagonal`): 0 without points, infinite only when the diagonal itself
/// exceeds the `f64` range (the sides are scaled by [`unit_scale`] before squaring, so
/// that the squares neither overflow nor underflow).
pub fn diagonal<'a>(points: impl IntoIterator<Item = &'a [f64; 3]>) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut any = false;
    for p in points {
        any = true;
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if !any {
        return 0.0;
    }
    let d = [hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]];
    let s = unit_scale(d[0].max(d[1]).max(d[2]));
    let d = d.map(|x| x * s);
    (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt() / s
}

/// ε as a fraction of the bounding-box diagonal, from a fuzz byte pair: `(eps / 65535)² ·
/// 0.6` (0 for `eps = 0`, which a relative ε must refuse).
pub fn eps_fraction(eps: u16) -> f64 {
    let r = f64::from(eps) / 65535.0;
    r * r * 0.6
}

/// An absolute ε for the lower-level simplifier: `fraction · diagonal` when that is a
/// finite number > 0; otherwise `10⁻⁹ · diagonal`, `f64::MAX` for an infinite diagonal,
/// `1e-150` for a zero one (still > 0 when squared, so zero-length edges count as short).
pub fn absolute_eps(fraction: f64, diagonal: f64) -> f64 {
    let usable = |e: f64| e.is_finite() && e > 0.0;
    if usable(fraction * diagonal) {
        fraction * diagonal
    } else if usable(1e-9 * diagonal) {
        1e-9 * diagonal
    } else if diagonal.is_infinite() {
        f64::MAX
    } else {
        1e-150
    }
}

/// At most this many operations of a [`SimplifyInput`]'s surface are applied (the
/// simplifier runs three times per input and the checker is O(F log F): keep inputs
/// small).
pub const SIMPLIFY_OPS: usize = 400;
/// At most this many faces are removed to make boundary.
pub const SIMPLIFY_HOLES: usize = 8;

/// The input of `simplify`: a random closed surface (as `surface_ops` grows it, at most
/// [`SIMPLIFY_OPS`] operations), positions laid out by [`layout`] (degenerate ones
/// included), faces removed to open it, a random ε and random options.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct SimplifyInput {
    /// The surface (its `seed` is unused).
    pub base: SurfaceInput,
    /// Seed of the positions ([`Rng`]).
    pub positions: u64,
    /// The layout of the positions.
    pub geometry: Geometry,
    /// Every coordinate times `10^`[`scale_exponent`]`(scale)` ([`layout`]).
    pub scale: i8,
    /// ε as a fraction of the bounding-box diagonal ([`eps_fraction`]).
    pub eps: u16,
    /// The task call's ε: [`contractible::Eps::Relative`] with the fraction, or
    /// [`contractible::Eps::Absolute`] with the lower-level runs' ε.
    pub relative: bool,
    /// Faces to remove (ids mod F, in order); a face sharing a vertex with one already
    /// removed is kept, so the result stays a surface with boundary.
    pub holes: Vec<u16>,
    /// `side % 3`: count, path, Euclidean.
    pub side: u8,
    /// Quadric positions instead of midpoints.
    pub quadric: bool,
    /// The geometry guard (the task call's `allow_foldover` is its negation).
    pub guard: bool,
    /// The task call's mode: nested, or naive.
    pub nested: bool,
}

/// The mesh a [`SimplifyInput`] describes, with its ε.
#[derive(Clone, Debug)]
pub struct SimplifyCase {
    /// The surface with its holes and positions.
    pub mesh: contractible::TriMesh,
    /// ε as a fraction of the bounding-box diagonal ([`eps_fraction`]).
    pub fraction: f64,
    /// The absolute ε of the lower-level runs ([`absolute_eps`]).
    pub eps: f64,
}

/// The mesh and ε a [`SimplifyInput`] describes.
pub fn simplify_mesh(input: &SimplifyInput) -> SimplifyCase {
    let base = SurfaceInput {
        ops: input.base.ops.iter().take(SIMPLIFY_OPS).copied().collect(),
        ..input.base.clone()
    };
    let tri = build_surface(&base);
    let n = tri.vertex_capacity();
    let mut faces = tri.face_list();
    let pos = layout(
        input.geometry,
        input.scale,
        input.positions,
        &neighbours(n, &faces),
    );
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
    let fraction = eps_fraction(input.eps);
    let eps = absolute_eps(fraction, diagonal(&pos));
    SimplifyCase {
        mesh: contractible::TriMesh::with_positions(pos, faces),
        fraction,
        eps,
    }
}

/// The options of the `simplify` target's runs (lower level, ε given).
fn simplify_options(input: &SimplifyInput, eps: f64) -> contractible::simplify::Options {
    use contractible::simplify::{Options as SOptions, Position, Side};
    SOptions {
        side: Side::ALL[usize::from(input.side % 3)],
        position: if input.quadric {
            Position::Quadric
        } else {
            Position::Midpoint
        },
        guard: input.guard,
        ..SOptions::new(eps)
    }
}

/// `simplify`: the mesh of `input` through the task call
/// [`contractible::simplify()`](fn@contractible::simplify) with its options (ε relative or
/// absolute, checked by [`check_simplify_task`]), then through the lower-level
/// [`contractible::simplify::simplify`] in both modes with the task's ε (each run
/// checked by [`check_simplify_with`]: independent topology and accounting, finite
/// positions; nested ≥ naive contractions); the task's result must be the lower-level
/// result of its mode (the task call is a layer over it).
pub fn check_simplify_input(input: &SimplifyInput) {
    use contractible::simplify::Mode;
    let case = simplify_mesh(input);
    let before = surface_topology(&case.mesh.faces).expect("a random surface with holes");
    let mode = if input.nested {
        Mode::Nested
    } else {
        Mode::Naive
    };
    let lower = simplify_options(input, case.eps);
    let task_opts = contractible::SimplifyOptions {
        eps: if input.relative {
            contractible::Eps::Relative(case.fraction)
        } else {
            contractible::Eps::Absolute(case.eps)
        },
        mode,
        side: lower.side,
        position: lower.position,
        allow_foldover: !input.guard,
        ..contractible::SimplifyOptions::default()
    };
    let task = check_simplify_task(&case.mesh, &task_opts, "simplify task").ok();
    let eps = task.as_ref().map_or(case.eps, |t| t.eps);
    let (naive, nested) = check_simplify_modes(
        &case.mesh,
        &before,
        &simplify_options(input, eps),
        "simplify input",
    );
    if let Some(t) = task {
        let low = if mode == Mode::Naive { naive } else { nested };
        assert_same_simplification(&t, &low, "simplify task");
    }
}

/// The task call's result is the lower-level one: the same mesh (positions compared bit
/// for bit) and the same statistics but the timing.
pub fn assert_same_simplification(
    task: &contractible::SimplifyResult,
    lower: &contractible::simplify::Simplified,
    label: &str,
) {
    assert_eq!(
        task.mesh.faces, lower.mesh.faces,
        "{label}: faces differ from the lower-level call"
    );
    assert_eq!(
        task.mesh.vertex_count, lower.mesh.vertex_count,
        "{label}: vertex count"
    );
    let bits = |m: &contractible::TriMesh| {
        m.positions
            .as_ref()
            .map(|p| p.iter().map(|q| q.map(f64::to_bits)).collect::<Vec<_>>())
    };
    assert_eq!(
        bits(&task.mesh),
        bits(&lower.mesh),
        "{label}: positions differ from the lower-level call"
    );
    let mut a = task.stats.clone();
    let mut b = lower.stats.clone();
    a.seconds = 0.0;
    b.seconds = 0.0;
    assert_eq!(a, b, "{label}: statistics differ from the lower-level call");
}

/// Why the task call [`contractible::simplify()`](fn@contractible::simplify) may refuse
/// `mesh` with `eps`, decided here from the documented rules without the library: the
/// kinds ([`contractible::Error::kind`], `"mesh"` for any [`contractible::Error::Mesh`])
/// of every refusal that applies. Empty exactly when the call must succeed.
///
/// - `bad_option`: ε not a finite number > 0; for a relative ε, also the fraction times
///   the diagonal of the used vertices' bounding box not a finite number > 0 (only once
///   positions and faces are accepted: it is computed from them);
/// - `missing_positions`, `position_count`, `non_finite_coordinate`;
/// - `no_coordinates`: every used vertex (two at least) at one point (`==`);
/// - `mesh`: the faces are not a union of surfaces ([`oracle_surface`]).
pub fn simplify_refusals(
    mesh: &contractible::TriMesh,
    eps: &contractible::Eps,
) -> Vec<&'static str> {
    use contractible::Eps;
    let usable = |e: f64| e.is_finite() && e > 0.0;
    let mut out = Vec::new();
    let (Eps::Absolute(e) | Eps::Relative(e)) = *eps;
    if !usable(e) {
        out.push("bad_option");
    }
    let positions = match &mesh.positions {
        None => {
            out.push("missing_positions");
            None
        }
        Some(p) if p.len() != mesh.vertex_count => {
            out.push("position_count");
            None
        }
        Some(p) if p.iter().flatten().any(|x| !x.is_finite()) => {
            out.push("non_finite_coordinate");
            None
        }
        Some(p) => Some(p),
    };
    let surface = oracle_surface(mesh).is_ok();
    if !surface {
        out.push("mesh");
    }
    if let Some(p) = positions {
        let used = used_vertices(mesh);
        let mut at = used.iter().map(|&v| p[v as usize]);
        if let Some(first) = at.next() {
            if used.len() > 1 && at.all(|q| q == first) {
                out.push("no_coordinates");
            }
        }
        if let (Eps::Relative(r), true, true) = (*eps, surface, out.is_empty()) {
            if !usable(r * diagonal(used.iter().map(|&v| &p[v as usize]))) {
                out.push("bad_option");
            }
        }
    }
    out
}

/// The in-range vertices the faces of `mesh` use, increasing.
pub fn used_vertices(mesh: &contractible::TriMesh) -> Vec<u32> {
    let mut used: Vec<u32> = mesh
        .faces
        .iter()
        .flatten()
        .copied()
        .filter(|&v| (v as usize) < mesh.vertex_count)
        .collect();
    used.sort_unstable();
    used.dedup();
    used
}

/// The task call [`contractible::simplify()`](fn@contractible::simplify) on `mesh` with
/// `opts`, checked: it refuses exactly when [`simplify_refusals`] lists a reason, with
/// one of those (an input error, the first non-finite coordinate located exactly);
/// otherwise its result passes [`check_simplified`] against the input's topology
/// ([`surface_topology`]), was verified, has the ε asked for (absolute; or the fraction
/// times its diagonal, which matches the one computed here), drops exactly the unused
/// vertices. Returns the result (for the caller to compare with the lower-level call,
/// [`assert_same_simplification`]), or the refusal.
pub fn check_simplify_task(
    mesh: &contractible::TriMesh,
    opts: &contractible::SimplifyOptions,
    label: &str,
) -> Result<contractible::SimplifyResult, contractible::Error> {
    use contractible::{Eps, Error};
    let refusals = simplify_refusals(mesh, &opts.eps);
    let r = match contractible::simplify(mesh, opts) {
        Err(e) => {
            let kind = if matches!(e, Error::Mesh(_)) {
                "mesh"
            } else {
                e.kind()
            };
            assert!(
                refusals.contains(&kind),
                "{label}: refused ({e}), expected one of {refusals:?}"
            );
            assert!(e.is_input(), "{label}: {e} is not the input's fault");
            if let Error::NonFiniteCoordinate {
                vertex,
                axis,
                value,
            } = e
            {
                let p = mesh.positions.as_deref().expect("positions");
                let v = p
                    .iter()
                    .position(|q| q.iter().any(|x| !x.is_finite()))
                    .expect("a non-finite coordinate");
                let k = p[v].iter().position(|x| !x.is_finite()).expect("an axis");
                assert_eq!((vertex, axis), (v, ['x', 'y', 'z'][k]), "{label}: located");
                assert_eq!(value.to_bits(), p[v][k].to_bits(), "{label}: value");
            }
            return Err(e);
        }
        Ok(r) => r,
    };
    assert!(
        refusals.is_empty(),
        "{label}: accepted, expected a refusal: {refusals:?}"
    );
    let before = oracle_surface(mesh).expect("accepted only for surfaces");
    assert!(r.verified, "{label}: not verified");
    let used = used_vertices(mesh);
    assert_eq!(
        r.dropped_vertices,
        mesh.vertex_count - used.len(),
        "{label}: dropped vertices"
    );
    let p = mesh.positions.as_deref().expect("positions");
    let diag = diagonal(used.iter().map(|&v| &p[v as usize]));
    assert!(
        r.bbox_diagonal == diag || (r.bbox_diagonal - diag).abs() <= 1e-12 * diag,
        "{label}: bbox_diagonal {} but the used vertices' is {diag}",
        r.bbox_diagonal
    );
    match opts.eps {
        Eps::Absolute(e) => assert_eq!((r.eps, r.eps_rel), (e, None), "{label}: ε"),
        Eps::Relative(f) => assert_eq!(
            (r.eps, r.eps_rel),
            (f * r.bbox_diagonal, Some(f)),
            "{label}: relative ε"
        ),
    }
    let lower_opts = contractible::simplify::Options {
        eps: r.eps,
        mode: opts.mode,
        side: opts.side,
        position: opts.position,
        guard: !opts.allow_foldover,
    };
    check_simplified(mesh, &before, &lower_opts, &r.mesh, &r.stats, label);
    Ok(r)
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

// ---- The per-task library calls on arbitrary face lists (`tasks`).

/// At most this many parts make a [`TaskInput`]'s mesh.
pub const TASK_PARTS: usize = 4;
/// At most this many operations grow a [`Part::Surface`].
pub const TASK_OPS: usize = 48;
/// At most this many triples of a [`Part::Raw`] are used.
pub const TASK_RAW_FACES: usize = 64;
/// At most this many edits of a [`TaskInput`] are applied.
pub const TASK_EDITS: usize = 24;

/// One part of a [`TaskInput`]'s mesh, on vertices of its own (parts are disjoint until
/// edits join them).
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub enum Part {
    /// A closed surface: the start surface with at most [`TASK_OPS`] operations (as
    /// `surface_ops` builds it).
    Surface {
        /// The start surface.
        surface: Surface,
        /// Splits, flips and relabellings.
        ops: Vec<Op>,
    },
    /// A standard mesh (`which % 6`): tetrahedron, octahedron, icosahedron, 7-vertex
    /// torus, 6-vertex projective plane, Klein bottle.
    Standard {
        /// Which one.
        which: u8,
    },
    /// Arbitrary triples on `1 + vertices % 32` vertices (at most [`TASK_RAW_FACES`]):
    /// degenerate, repeated, non-manifold, open.
    Raw {
        /// The part's vertex count (`1 + vertices % 32`).
        vertices: u8,
        /// The triples (each index modulo the vertex count).
        faces: Vec<[u8; 3]>,
    },
}

/// An edit of the assembled face list (faces modulo the face count, vertices modulo the
/// parts' vertex count unless said otherwise).
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    /// Remove a face (boundary, or an isolated edge's loss).
    Remove {
        /// The face.
        face: u16,
    },
    /// Add a face on arbitrary vertices (modulo the vertex count plus 2: sometimes out of
    /// range, sometimes degenerate).
    Add {
        /// Its corners.
        corners: [u16; 3],
    },
    /// Add a copy of a face, rotated by `turn % 3` and reversed when `turn >= 128`.
    Duplicate {
        /// The face copied.
        face: u16,
        /// Rotation and reversal.
        turn: u8,
    },
    /// Reverse a face's orientation.
    Reverse {
        /// The face.
        face: u16,
    },
    /// Identify two vertices (every corner at `gone` moved to `keep`): pinched vertices,
    /// degenerate faces, non-manifold edges, joined components.
    Merge {
        /// The vertex kept.
        keep: u16,
        /// The vertex replaced.
        gone: u16,
    },
    /// Set one corner to an arbitrary index (out of range when large).
    Corner {
        /// The face.
        face: u16,
        /// The corner (`% 3`).
        slot: u8,
        /// The index.
        vertex: u32,
    },
    /// Exchange two faces (which problem is met first depends on the order).
    Swap {
        /// One face.
        a: u16,
        /// The other.
        b: u16,
    },
}

/// The vertex count declared by a [`TaskInput`]'s mesh.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum VertexCount {
    /// The parts' vertices.
    Parts,
    /// The parts' vertices and `unused` more that no face uses.
    Extra {
        /// How many more.
        unused: u8,
    },
    /// One more than the core can index ([`contractible::core::MAX_VERTICES`]` + 1`):
    /// refused by every call before anything is allocated for it.
    Huge,
}

/// The positions of a [`TaskInput`]'s mesh.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Positions {
    /// None (what `simplify` refuses).
    None,
    /// Laid out by [`layout`], one per declared vertex (one per part vertex for
    /// [`VertexCount::Huge`], which then has the wrong count).
    Laid {
        /// The layout.
        geometry: Geometry,
        /// Its scale ([`layout`]).
        scale: i8,
        /// Its random stream.
        seed: u64,
    },
    /// As `Laid` (unit scale), with one coordinate replaced by NaN, +∞ or −∞
    /// (`value % 3`).
    NonFinite {
        /// The layout.
        geometry: Geometry,
        /// Its random stream.
        seed: u64,
        /// The vertex (modulo the count).
        vertex: u16,
        /// The axis (`% 3`).
        axis: u8,
        /// NaN, +∞ or −∞ (`% 3`).
        value: u8,
    },
    /// Random positions, `delta` more or fewer than the declared vertices (at least one
    /// off).
    Miscounted {
        /// Their random stream.
        seed: u64,
        /// How many more (or fewer).
        delta: i8,
    },
}

/// The input of `tasks`: a face list assembled from parts and edited, a declared vertex
/// count, positions, and the options of the four task calls.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct TaskInput {
    /// The parts, on disjoint vertices (at most [`TASK_PARTS`]).
    pub parts: Vec<Part>,
    /// Edits of the assembled faces (at most [`TASK_EDITS`]).
    pub edits: Vec<Edit>,
    /// The declared vertex count.
    pub vertices: VertexCount,
    /// The positions.
    pub positions: Positions,
    /// The reduction algorithm (`% 3` of [`contractible::irreducible::Algorithm::ALL`]);
    /// its high bit runs the components in parallel.
    pub reduce: u8,
    /// The tri-quad algorithm (`% 8` of [`contractible::quad::Algorithm::ALL`]); its high
    /// bit runs the components in parallel.
    pub quad: u8,
    /// The seed of both.
    pub seed: u64,
    /// `simplify`'s ε ([`eps_fraction`]; relative, or absolute times the harness's
    /// diagonal of the positions).
    pub eps: u16,
    /// A relative ε.
    pub relative: bool,
    /// `simplify`'s mode: nested, or naive.
    pub nested: bool,
    /// `simplify`'s side heuristic (`% 3`).
    pub side: u8,
    /// Quadric positions.
    pub quadric: bool,
    /// `allow_foldover`.
    pub foldover: bool,
}

/// Applies `edits` to `faces` over `nv` vertices, in order (see [`Edit`]).
pub fn apply_edits<'a>(
    faces: &mut Vec<[u32; 3]>,
    nv: u32,
    edits: impl IntoIterator<Item = &'a Edit>,
) {
    for &edit in edits {
        let nf = faces.len();
        let face = |i: u16| usize::from(i) % nf.max(1);
        match edit {
            _ if nf == 0 && !matches!(edit, Edit::Add { .. }) => {}
            Edit::Remove { face: i } => {
                faces.remove(face(i));
            }
            Edit::Add { corners } => faces.push(corners.map(|c| u32::from(c) % (nv + 2))),
            Edit::Duplicate { face: i, turn } => {
                let f = faces[face(i)];
                let r = usize::from(turn % 3);
                let mut g = [f[r], f[(r + 1) % 3], f[(r + 2) % 3]];
                if turn >= 128 {
                    g.swap(1, 2);
                }
                faces.push(g);
            }
            Edit::Reverse { face: i } => faces[face(i)].swap(1, 2),
            Edit::Merge { keep, gone } => {
                let (k, g) = (u32::from(keep) % nv, u32::from(gone) % nv);
                for v in faces.iter_mut().flatten() {
                    if *v == g {
                        *v = k;
                    }
                }
            }
            Edit::Corner {
                face: i,
                slot,
                vertex,
            } => faces[face(i)][usize::from(slot % 3)] = vertex,
            Edit::Swap { a, b } => faces.swap(face(a), face(b)),
        }
    }
}

/// The mesh a [`TaskInput`] describes: the parts side by side (vertex ids offset), the
/// edits applied in order, the declared vertex count and the positions.
pub fn task_mesh(input: &TaskInput) -> contractible::TriMesh {
    use contractible::gen;
    let standard: [fn() -> contractible::TriMesh; 6] = [
        gen::tetrahedron,
        gen::octahedron,
        gen::icosahedron,
        gen::torus7,
        gen::projective_plane6,
        gen::klein_bottle,
    ];
    let mut faces: Vec<[u32; 3]> = Vec::new();
    let mut total = 0usize;
    for part in input.parts.iter().take(TASK_PARTS) {
        let (n, part_faces) = match part {
            Part::Surface { surface, ops } => {
                let t = build_surface(&SurfaceInput {
                    surface: *surface,
                    ops: ops.iter().take(TASK_OPS).copied().collect(),
                    seed: 0,
                });
                (t.vertex_capacity(), t.face_list())
            }
            Part::Standard { which } => {
                let m = standard[usize::from(which % 6)]();
                (m.vertex_count, m.faces)
            }
            Part::Raw { vertices, faces } => {
                let n = 1 + u32::from(vertices % 32);
                let fs = faces
                    .iter()
                    .take(TASK_RAW_FACES)
                    .map(|f| f.map(|v| u32::from(v) % n))
                    .collect();
                (n as usize, fs)
            }
        };
        let offset = total as u32;
        faces.extend(part_faces.iter().map(|f| f.map(|v| v + offset)));
        total += n;
    }
    let nv = total.max(1) as u32;
    apply_edits(&mut faces, nv, input.edits.iter().take(TASK_EDITS));
    let vertex_count = match input.vertices {
        VertexCount::Parts => total,
        VertexCount::Extra { unused } => total + usize::from(unused),
        VertexCount::Huge => contractible::core::MAX_VERTICES + 1,
    };
    // Positions for the declared vertices (the parts' only when that count is huge).
    let n = if vertex_count > contractible::core::MAX_VERTICES {
        total
    } else {
        vertex_count
    };
    let positions = match input.positions {
        Positions::None => None,
        Positions::Laid {
            geometry,
            scale,
            seed,
        } => Some(layout(geometry, scale, seed, &neighbours(n, &faces))),
        Positions::NonFinite {
            geometry,
            seed,
            vertex,
            axis,
            value,
        } => {
            let mut p = layout(geometry, 0, seed, &neighbours(n, &faces));
            if n > 0 {
                p[usize::from(vertex) % n][usize::from(axis % 3)] =
                    [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][usize::from(value % 3)];
            }
            Some(p)
        }
        Positions::Miscounted { seed, delta } => {
            let delta = if delta == 0 { 1 } else { i64::from(delta) };
            let m = (n as i64 + delta).max(0) as usize;
            let geometry = Geometry::Random { smoothing: 0 };
            Some(layout(geometry, 0, seed, &vec![Vec::new(); m]))
        }
    };
    contractible::TriMesh {
        vertex_count,
        positions,
        faces,
    }
}

/// Whether `faces` over `0..vertex_count` form a union of surfaces (closed or with
/// boundary), decided without the library: faces present, counts within the core's
/// limits, every index in range, then [`surface_topology`]. `Err` says why not.
pub fn oracle_surface(mesh: &contractible::TriMesh) -> Result<Topology, String> {
    use contractible::core::{MAX_FACES, MAX_VERTICES};
    if mesh.faces.is_empty() {
        return Err("no faces".into());
    }
    if mesh.vertex_count > MAX_VERTICES || mesh.faces.len() > MAX_FACES {
        return Err("more vertices or faces than 32-bit ids hold".into());
    }
    if let Some((i, f)) = mesh
        .faces
        .iter()
        .enumerate()
        .find(|(_, f)| f.iter().any(|&v| v as usize >= mesh.vertex_count))
    {
        return Err(format!("face {i} {f:?}: an index out of range"));
    }
    surface_topology(&mesh.faces)
}

/// The connected components of the surface `faces` (faces sharing a vertex: on a
/// surface, where every vertex has one fan, the same as sharing an edge), each as its
/// face indices, in the order of their smallest face.
pub fn component_faces(faces: &[[u32; 3]]) -> Vec<Vec<usize>> {
    let n = faces
        .iter()
        .flatten()
        .map(|&v| v as usize + 1)
        .max()
        .unwrap_or(0);
    let mut parent: Vec<u32> = (0..n as u32).collect();
    for f in faces {
        uf_union(&mut parent, f[0], f[1]);
        uf_union(&mut parent, f[0], f[2]);
    }
    let mut slot = vec![usize::MAX; n];
    let mut out: Vec<Vec<usize>> = Vec::new();
    for (i, f) in faces.iter().enumerate() {
        let r = uf_find(&mut parent, f[0]) as usize;
        if slot[r] == usize::MAX {
            slot[r] = out.len();
            out.push(Vec::new());
        }
        out[slot[r]].push(i);
    }
    out
}

/// The topology of one component (the faces `which` of `faces`), by [`surface_topology`].
fn component_topology(faces: &[[u32; 3]], which: &[usize]) -> Topology {
    let sub: Vec<[u32; 3]> = which.iter().map(|&i| faces[i]).collect();
    let t = surface_topology(&sub).unwrap_or_else(|e| panic!("a component is not a surface: {e}"));
    assert_eq!(t.components.len(), 1, "a component splits");
    t
}

/// The first edge of the closed surface `faces` that passes the link condition, by its
/// definition on the face lists alone: `[a, b]` with opposite vertices `c`, `d` is
/// contractible iff the common neighbours of `a` and `b` are exactly `c` and `d` and the
/// faces `acd` and `bcd` are not both present (the links of `a` and `b` then share no
/// edge). `None`: the surface is irreducible.
pub fn contractible_edge(faces: &[[u32; 3]]) -> Option<(u32, u32)> {
    use std::collections::{BTreeMap, BTreeSet};
    let mut near: BTreeMap<u32, BTreeSet<u32>> = BTreeMap::new();
    let mut opposite: BTreeMap<(u32, u32), Vec<u32>> = BTreeMap::new();
    let key = |f: [u32; 3]| {
        let mut s = f;
        s.sort_unstable();
        s
    };
    let present: BTreeSet<[u32; 3]> = faces.iter().map(|&f| key(f)).collect();
    for f in faces {
        for k in 0..3 {
            let (a, b, c) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
            near.entry(a).or_default().insert(b);
            near.entry(b).or_default().insert(a);
            opposite.entry((a.min(b), a.max(b))).or_default().push(c);
        }
    }
    for (&(a, b), opp) in &opposite {
        let mut opp = opp.clone();
        opp.sort_unstable();
        let common: Vec<u32> = near[&a].intersection(&near[&b]).copied().collect();
        if common == opp
            && opp.len() == 2
            && !(present.contains(&key([a, opp[0], opp[1]]))
                && present.contains(&key([b, opp[0], opp[1]])))
        {
            return Some((a, b));
        }
    }
    None
}

/// Checks that `[a, b]` (`a < b`) is an edge of face `face` of `mesh` and of no other
/// face: a boundary edge, as a refusal for not being closed names it.
fn assert_boundary_edge(mesh: &contractible::TriMesh, a: u32, b: u32, face: usize, label: &str) {
    assert!(a < b, "{label}: boundary edge [{a}, {b}] not ordered");
    let holds = |f: &[u32; 3]| f.contains(&a) && f.contains(&b);
    assert!(
        mesh.faces.get(face).is_some_and(holds),
        "{label}: face {face} does not hold [{a}, {b}]"
    );
    let n = mesh.faces.iter().filter(|f| holds(f)).count();
    assert_eq!(
        n, 1,
        "{label}: [{a}, {b}] is in {n} faces, not a boundary edge"
    );
}

/// `describe` against the oracle: problems exactly when [`oracle_surface`] refuses (and
/// then the diagnosis lists a problem that is not the boundary); for a union of surfaces,
/// each component (in the order of its smallest face) has the oracle's vertex, edge and
/// face counts, χ, orientability and boundary loops, loop lengths that add up to its
/// boundary edges, a degree histogram over its vertices with `Σ d · n_d = 2E`; the
/// dropped vertices are the unused ones; and `diagnose` finds nothing but the boundary,
/// with the same totals.
pub fn check_description(
    mesh: &contractible::TriMesh,
    d: &contractible::Description,
    oracle: &Result<Topology, String>,
    label: &str,
) {
    use contractible::Description;
    match d {
        Description::Problems { diagnosis, first } => {
            if let Ok(t) = oracle {
                panic!("{label}: describe finds problems ({first}) in a union of surfaces: {t:?}");
            }
            assert!(
                !diagnosis.is_surface(),
                "{label}: problems ({first}) but the diagnosis lists none: {diagnosis:?}"
            );
            assert_eq!(
                diagnosis.faces,
                mesh.faces.len(),
                "{label}: diagnosis faces"
            );
        }
        Description::Surfaces {
            components,
            dropped_vertices,
        } => {
            let topo = oracle
                .as_ref()
                .unwrap_or_else(|e| panic!("{label}: describe accepts what is not a surface: {e}"));
            let parts = component_faces(&mesh.faces);
            assert_eq!(components.len(), parts.len(), "{label}: component count");
            for (i, (c, which)) in components.iter().zip(&parts).enumerate() {
                let t = component_topology(&mesh.faces, which);
                let ct = t.components[0];
                assert_eq!(
                    (c.vertices, c.edges, c.faces),
                    (t.vertices, t.edges, t.faces),
                    "{label}: counts of component {i}"
                );
                assert_eq!(
                    (
                        c.surface.euler_characteristic(),
                        c.surface.is_orientable(),
                        c.surface.boundary_loops()
                    ),
                    (ct.euler, ct.orientable, ct.boundary_loops),
                    "{label}: type of component {i}"
                );
                assert_eq!(c.boundary_loop_lengths.len(), ct.boundary_loops);
                assert!(c.boundary_loop_lengths.iter().all(|&l| l >= 3));
                assert_eq!(
                    c.boundary_loop_lengths.iter().sum::<usize>(),
                    t.boundary_edges,
                    "{label}: loop lengths of component {i}"
                );
                let h = &c.degree_histogram;
                assert_eq!(h.iter().sum::<usize>(), c.vertices, "{label}: histogram");
                let degrees: usize = h.iter().enumerate().map(|(d, n)| d * n).sum();
                assert_eq!(degrees, 2 * c.edges, "{label}: Σ d · n_d");
                assert_eq!(
                    h.last().map(|&n| n > 0),
                    Some(true),
                    "{label}: histogram end"
                );
                assert_eq!(c.degree_max, h.len() - 1, "{label}: degree_max");
                assert_eq!(
                    Some(c.degree_min),
                    h.iter().position(|&n| n > 0),
                    "{label}: degree_min"
                );
            }
            assert_eq!(
                *dropped_vertices,
                mesh.vertex_count - topo.vertices,
                "{label}: dropped vertices"
            );
            let g = contractible::diagnose::diagnose(mesh, 1);
            assert!(
                g.is_surface(),
                "{label}: a surface diagnosed with problems: {g:?}"
            );
            let euler: i64 = topo.components.iter().map(|c| c.euler).sum();
            let orientable = topo.components.iter().all(|c| c.orientable);
            assert_eq!(
                (
                    g.vertices,
                    g.edges,
                    g.faces,
                    g.components,
                    g.euler_characteristic
                ),
                (
                    topo.vertices,
                    topo.edges,
                    topo.faces,
                    topo.components.len(),
                    euler
                ),
                "{label}: diagnosis counts"
            );
            assert_eq!(
                g.orientable,
                Some(orientable),
                "{label}: diagnosis orientability"
            );
            assert_eq!(
                (g.boundary_edges, g.boundary_loops, g.unused_vertices),
                (topo.boundary_edges, topo.loops(), *dropped_vertices),
                "{label}: diagnosis boundary"
            );
        }
    }
}

/// A refusal (or not) of `reduce` or `quadrangulate` (`task`: the name their
/// [`contractible::Error::NotClosed`] carries), against `describe`'s verdict `d`:
///
/// - problems: refused for the input, with `describe`'s first problem
///   ([`contractible::Description::Problems::first`]); except that the closed-surface
///   validation meets a boundary edge before the checks that come after the edge
///   classification (pinched boundary vertex, vertex links and degrees, the coned
///   counts), so for those it may report a boundary edge instead (as `NotClosed` without
///   loops, the mesh not being a surface);
/// - surfaces, one with boundary: `NotClosed` naming a boundary edge and the mesh's
///   boundary loops;
/// - closed surfaces: accepted (`too_large` aside, checked by the caller).
fn check_closed_refusal(
    task: &str,
    mesh: &contractible::TriMesh,
    d: &contractible::Description,
    e: Option<&contractible::Error>,
    label: &str,
) {
    use contractible::{BuildError, Description, Error};
    match d {
        Description::Problems { first, .. } => {
            let e = e.unwrap_or_else(|| panic!("{label}: accepted, describe: {first}"));
            assert!(e.is_input(), "{label}: {e} is not the input's fault");
            match e {
                Error::Mesh(b) => assert_eq!(b, first, "{label}: not describe's first problem"),
                Error::NotClosed {
                    task: t,
                    a,
                    b,
                    face,
                    boundary_loops,
                } => {
                    assert_eq!(*t, task, "{label}: task name");
                    assert_eq!(*boundary_loops, None, "{label}: loops of a non-surface");
                    assert!(
                        matches!(
                            first,
                            BuildError::PinchedBoundaryVertex { .. }
                                | BuildError::VertexLinkNotCycle { .. }
                                | BuildError::VertexDegreeTooLow { .. }
                                | BuildError::TooLarge { .. }
                        ),
                        "{label}: a boundary edge reported before {first}"
                    );
                    assert_boundary_edge(mesh, *a, *b, *face, label);
                }
                e => panic!("{label}: refused with {e}, describe: {first}"),
            }
        }
        Description::Surfaces { components, .. } => {
            let loops: usize = components.iter().map(|c| c.surface.boundary_loops()).sum();
            if loops == 0 {
                if let Some(e) = e {
                    assert!(
                        matches!(e, Error::TooLarge { .. }),
                        "{label}: closed surfaces refused: {e}"
                    );
                }
                return;
            }
            match e {
                Some(Error::NotClosed {
                    task: t,
                    a,
                    b,
                    face,
                    boundary_loops,
                }) => {
                    assert_eq!(*t, task, "{label}: task name");
                    assert_eq!(*boundary_loops, Some(loops), "{label}: loops");
                    assert_boundary_edge(mesh, *a, *b, *face, label);
                }
                other => panic!("{label}: a surface with boundary gave {other:?}"),
            }
        }
    }
}

/// Checks a `reduce` result on `mesh` (closed surfaces of topology `topo`) from the face
/// lists alone: the output vertices are input vertices (`vertex_map` increasing), with
/// the input's positions bit for bit; the output is a union of closed surfaces using
/// every vertex, one per input component (its vertices all in that component) with the
/// same χ and orientability; each is irreducible ([`contractible_edge`]) within the
/// bounds (Euler genus `h > 0`: `V ≤ 13h − 4`; `h = 0`: the tetrahedron); every
/// component's history expands back to its input faces; counts, the dropped vertices and
/// the verdict agree.
pub fn check_reduce_result(
    mesh: &contractible::TriMesh,
    topo: &Topology,
    r: &contractible::ReduceResult,
    label: &str,
) {
    let out = &r.mesh;
    assert_eq!(
        r.vertex_map.len(),
        out.vertex_count,
        "{label}: vertex_map length"
    );
    assert!(
        r.vertex_map.windows(2).all(|w| w[0] < w[1])
            && r.vertex_map
                .last()
                .is_none_or(|&v| (v as usize) < mesh.vertex_count),
        "{label}: vertex_map not increasing input vertices"
    );
    let bits = |p: &[f64; 3]| p.map(f64::to_bits);
    match (&mesh.positions, &out.positions) {
        (None, None) => {}
        (Some(p), Some(q)) => {
            assert_eq!(q.len(), out.vertex_count, "{label}: positions");
            for (i, &v) in r.vertex_map.iter().enumerate() {
                assert_eq!(
                    bits(&q[i]),
                    bits(&p[v as usize]),
                    "{label}: position of {v}"
                );
            }
        }
        _ => panic!("{label}: positions appeared or vanished"),
    }
    assert!(
        out.faces
            .iter()
            .flatten()
            .all(|&v| (v as usize) < out.vertex_count),
        "{label}: an output index out of range"
    );
    let after = surface_topology(&out.faces)
        .unwrap_or_else(|e| panic!("{label}: the output is not a surface: {e}"));
    assert_eq!(
        after.vertices, out.vertex_count,
        "{label}: an unused output vertex"
    );
    assert_eq!(
        after.components, topo.components,
        "{label}: the surfaces changed"
    );
    // Pair every output component with the input component holding its vertices.
    let inputs = component_faces(&mesh.faces);
    let mut home = vec![usize::MAX; mesh.vertex_count];
    for (k, which) in inputs.iter().enumerate() {
        for &i in which {
            for &v in &mesh.faces[i] {
                home[v as usize] = k;
            }
        }
    }
    let mut seen = vec![false; inputs.len()];
    for which in component_faces(&out.faces) {
        let sub: Vec<[u32; 3]> = which.iter().map(|&i| out.faces[i]).collect();
        let k = home[r.vertex_map[sub[0][0] as usize] as usize];
        assert!(
            sub.iter()
                .flatten()
                .all(|&v| home[r.vertex_map[v as usize] as usize] == k),
            "{label}: an output component spans input components"
        );
        assert!(
            !std::mem::replace(&mut seen[k], true),
            "{label}: two outputs of one component"
        );
        let t_out = component_topology(&out.faces, &which);
        let t_in = component_topology(&mesh.faces, &inputs[k]);
        let (a, b) = (t_out.components[0], t_in.components[0]);
        assert_eq!(
            (a.euler, a.orientable),
            (b.euler, b.orientable),
            "{label}: component {k}"
        );
        if let Some((x, y)) = contractible_edge(&sub) {
            panic!("{label}: output edge [{x}, {y}] of component {k} is contractible");
        }
        let h = 2 - a.euler;
        if h > 0 {
            assert!(
                t_out.vertices as i64 <= 13 * h - 4,
                "{label}: {} vertices > 13h − 4 = {}",
                t_out.vertices,
                13 * h - 4
            );
        } else {
            assert_eq!(
                (t_out.vertices, t_out.faces),
                (4, 4),
                "{label}: not the tetrahedron"
            );
        }
    }
    assert!(
        seen.iter().all(|&s| s),
        "{label}: an input component has no output"
    );
    let rot = |f: [u32; 3]| {
        let k = (0..3).min_by_key(|&k| f[k]).unwrap_or(0);
        [f[k], f[(k + 1) % 3], f[(k + 2) % 3]]
    };
    for (k, c) in r.components.iter().enumerate() {
        let back = c.reduction.expand().face_list();
        assert_eq!(
            back.len(),
            c.face_origin.len(),
            "{label}: expanded faces of {k}"
        );
        for (f, &o) in back.iter().zip(&c.face_origin) {
            let got = f.map(|v| c.vertex_origin[v as usize]);
            assert_eq!(
                rot(got),
                rot(mesh.faces[o as usize]),
                "{label}: component {k} expands to another face {o}"
            );
        }
    }
    let t = &r.totals;
    assert_eq!(r.components.len(), inputs.len(), "{label}: components");
    assert_eq!(t.irreducible, Some(true), "{label}: verdict");
    assert_eq!(
        (t.vertices_out, t.faces_out, t.faces_in),
        (out.vertex_count, out.faces.len(), mesh.faces.len()),
        "{label}: totals"
    );
    assert_eq!(
        r.dropped_vertices,
        mesh.vertex_count - topo.vertices,
        "{label}: dropped vertices"
    );
}

/// Checks a `quadrangulate` result on `mesh` (closed surfaces of topology `topo`) by
/// `algorithm` from the face lists alone: the quad mesh keeps the vertex count and the
/// positions; `triangles` (the paired `K`) is the input for every algorithm but LRS, and
/// for LRS a surface of the same topology on the same vertices; `pairs` is a perfect
/// pairing of its rows, each pair sharing exactly two vertices; quad `i` is pair `i`'s
/// union with the shared edge as its diagonal; the quads of each component form a closed
/// 2-manifold ([`check_closed_quad_surface`]) with the input's χ and orientability
/// (multisets compared), each directed quad edge used once when `K` is consistently
/// oriented; the totals agree.
pub fn check_quad_result(
    mesh: &contractible::TriMesh,
    topo: &Topology,
    q: &contractible::QuadResult,
    algorithm: contractible::quad::Algorithm,
    label: &str,
) {
    use contractible::quad::Algorithm as QAlg;
    let k = &q.triangles;
    assert_eq!(
        q.mesh.vertex_count, mesh.vertex_count,
        "{label}: vertex count"
    );
    let bits = |m: &Option<Vec<[f64; 3]>>| {
        m.as_ref()
            .map(|p| p.iter().map(|x| x.map(f64::to_bits)).collect::<Vec<_>>())
    };
    assert_eq!(
        bits(&q.mesh.positions),
        bits(&mesh.positions),
        "{label}: positions"
    );
    assert_eq!(k.len(), mesh.faces.len(), "{label}: rows of K");
    if algorithm == QAlg::Lrs {
        let t = surface_topology(k).unwrap_or_else(|e| panic!("{label}: K not a surface: {e}"));
        assert_eq!(t.components, topo.components, "{label}: K's surfaces");
        assert_eq!(t.vertices, topo.vertices, "{label}: K's vertices");
        assert_eq!(used_vertices(mesh), {
            let m = contractible::TriMesh::combinatorial(mesh.vertex_count, k.clone());
            used_vertices(&m)
        });
    } else {
        assert_eq!(*k, mesh.faces, "{label}: K is not the input");
        assert_eq!(q.totals.flips, 0, "{label}: flips");
    }
    let mut seen = vec![0u8; k.len()];
    for &[f, g] in &q.pairs {
        for h in [f, g] {
            let slot = seen
                .get_mut(h as usize)
                .unwrap_or_else(|| panic!("{label}: pair row {h} out of range"));
            *slot += 1;
        }
    }
    assert!(
        seen.iter().all(|&n| n == 1),
        "{label}: not a perfect pairing"
    );
    assert_eq!(
        q.mesh.faces.len(),
        q.pairs.len(),
        "{label}: one quad per pair"
    );
    for (quad, &[f, g]) in q.mesh.faces.iter().zip(&q.pairs) {
        let (a, b) = (k[f as usize], k[g as usize]);
        let mut shared: Vec<u32> = a.iter().filter(|v| b.contains(v)).copied().collect();
        shared.sort_unstable();
        assert_eq!(shared.len(), 2, "{label}: rows {f}, {g} share {shared:?}");
        let mut union: Vec<u32> = a.iter().chain(&b).copied().collect();
        union.sort_unstable();
        union.dedup();
        let mut qs = quad.to_vec();
        qs.sort_unstable();
        assert_eq!(qs, union, "{label}: quad {quad:?} of rows {f}, {g}");
        let mut diagonal = [quad[1], quad[3]];
        diagonal.sort_unstable();
        assert_eq!(diagonal.to_vec(), shared, "{label}: diagonal of {quad:?}");
    }
    // The quads per component (quads sharing a vertex).
    let n = mesh.vertex_count;
    let mut parent: Vec<u32> = (0..n as u32).collect();
    for quad in &q.mesh.faces {
        for j in 1..4 {
            uf_union(&mut parent, quad[0], quad[j]);
        }
    }
    let mut groups: std::collections::BTreeMap<u32, Vec<[u32; 4]>> = Default::default();
    for quad in &q.mesh.faces {
        groups
            .entry(uf_find(&mut parent, quad[0]))
            .or_default()
            .push(*quad);
    }
    let mut types: Vec<(i64, bool)> = groups
        .values()
        .map(|quads| check_closed_quad_surface(quads, label))
        .collect();
    types.sort_unstable();
    let mut want: Vec<(i64, bool)> = topo
        .components
        .iter()
        .map(|c| (c.euler, c.orientable))
        .collect();
    want.sort_unstable();
    assert_eq!(types, want, "{label}: the quads' surfaces");
    if is_consistently_oriented(k) {
        let mut directed = std::collections::BTreeSet::new();
        for quad in &q.mesh.faces {
            for i in 0..4 {
                assert!(
                    directed.insert((quad[i], quad[(i + 1) % 4])),
                    "{label}: consistently oriented K, quad edge used twice in one direction"
                );
            }
        }
    }
    let t = &q.totals;
    assert_eq!(
        (t.faces, t.quads, t.algorithm),
        (k.len(), q.pairs.len(), algorithm),
        "{label}: totals"
    );
    assert!(t.verified, "{label}: not verified");
    assert_eq!(
        q.components.len(),
        topo.components.len(),
        "{label}: components"
    );
    assert_eq!(
        q.dropped_vertices,
        mesh.vertex_count - topo.vertices,
        "{label}: dropped vertices"
    );
}

/// `tasks`: the four task calls on the mesh of `input`, none of which may panic; each
/// refusal is a typed input error, and the calls agree with each other and with the
/// oracles:
///
/// - above the core's size limits every call refuses by the count (`describe`, `reduce`
///   and `quadrangulate` with `too_large`, or `empty` for no faces; `simplify` for its
///   positions);
/// - `describe` ([`check_description`]): problems exactly when [`oracle_surface`]
///   refuses;
/// - `reduce` and `quadrangulate`: positions present but not one per vertex refused
///   first (`position_count`); otherwise ([`check_closed_refusal`]) refused exactly when
///   `describe` finds problems or boundary, with `describe`'s first problem or a
///   boundary edge; `quadrangulate` by `ds-naive` also exactly when a component has more
///   than [`contractible::quad::DS_NAIVE_MAX_FACES`] faces; outputs by
///   [`check_reduce_result`] and [`check_quad_result`];
/// - `simplify` ([`check_simplify_task`]): refused exactly for the documented reasons
///   (with `describe`'s first problem when only the faces are at fault); an output is
///   the lower-level call's with the same options.
pub fn check_tasks(input: &TaskInput) {
    use contractible::quad::Algorithm as QAlg;
    let mesh = task_mesh(input);
    let reduce_opts = contractible::ReduceOptions {
        algorithm: contractible::irreducible::Algorithm::ALL[usize::from(input.reduce % 3)],
        seed: input.seed,
        count_retests: true,
        parallel: input.reduce >= 128,
        ..contractible::ReduceOptions::default()
    };
    let qalg = QAlg::ALL[usize::from(input.quad % 8)];
    let quad_opts = contractible::QuadOptions {
        algorithm: qalg,
        seed: input.seed,
        parallel: input.quad >= 128,
        ..contractible::QuadOptions::default()
    };
    let fraction = eps_fraction(input.eps);
    let simplify_opts = contractible::SimplifyOptions {
        eps: if input.relative {
            contractible::Eps::Relative(fraction)
        } else {
            let used = used_vertices(&mesh);
            let d = match &mesh.positions {
                Some(p) if p.len() == mesh.vertex_count => {
                    diagonal(used.iter().map(|&v| &p[v as usize]))
                }
                _ => 1.0,
            };
            contractible::Eps::Absolute(if d.is_finite() {
                absolute_eps(fraction, d)
            } else {
                // Non-finite coordinates: any ε, the call refuses the positions.
                fraction
            })
        },
        mode: if input.nested {
            contractible::simplify::Mode::Nested
        } else {
            contractible::simplify::Mode::Naive
        },
        side: contractible::simplify::Side::ALL[usize::from(input.side % 3)],
        position: if input.quadric {
            contractible::simplify::Position::Quadric
        } else {
            contractible::simplify::Position::Midpoint
        },
        allow_foldover: input.foldover,
        ..contractible::SimplifyOptions::default()
    };
    check_task_calls(&mesh, &reduce_opts, &quad_opts, &simplify_opts);
}

/// [`check_tasks`] on a given mesh with given options.
pub fn check_task_calls(
    mesh: &contractible::TriMesh,
    reduce_opts: &contractible::ReduceOptions,
    quad_opts: &contractible::QuadOptions,
    simplify_opts: &contractible::SimplifyOptions,
) {
    use contractible::{BuildError, Error};
    let qalg = quad_opts.algorithm;
    // Positions that are not one per vertex: `reduce` and `quadrangulate` (which carry
    // them over) refuse them before anything else.
    let miscounted = mesh
        .positions
        .as_ref()
        .map(|p| p.len())
        .filter(|&n| n != mesh.vertex_count);
    let position_count = |task: &str, e: Option<&Error>| match e {
        Some(&Error::PositionCount {
            vertices,
            positions,
        }) => assert_eq!(
            (vertices, Some(positions)),
            (mesh.vertex_count, miscounted),
            "tasks: {task}: position count"
        ),
        e => panic!(
            "tasks: {task} with {miscounted:?} positions for {} vertices: {e:?}",
            mesh.vertex_count
        ),
    };
    let described = contractible::describe(mesh);
    if mesh.vertex_count > contractible::core::MAX_VERTICES {
        assert!(
            matches!(described, Err(Error::Mesh(BuildError::TooLarge { .. }))),
            "tasks: describe of a huge vertex count: {described:?}"
        );
        for (task, e) in [
            ("reduce", contractible::reduce(mesh, reduce_opts).err()),
            ("quad", contractible::quadrangulate(mesh, quad_opts).err()),
        ] {
            if miscounted.is_some() {
                position_count(task, e.as_ref());
            } else {
                assert!(
                    matches!(
                        e,
                        Some(Error::Mesh(BuildError::TooLarge { .. } | BuildError::Empty))
                    ),
                    "tasks: {task} of a huge vertex count: {e:?}"
                );
            }
        }
        assert!(
            check_simplify_task(mesh, simplify_opts, "tasks: simplify").is_err(),
            "tasks: simplify of a huge vertex count"
        );
        return;
    }
    let d = described.unwrap_or_else(|e| panic!("tasks: describe refused: {e}"));
    let oracle = oracle_surface(mesh);
    check_description(mesh, &d, &oracle, "tasks: describe");

    let reduced = contractible::reduce(mesh, reduce_opts);
    if miscounted.is_some() {
        position_count("reduce", reduced.as_ref().err());
    } else {
        check_closed_refusal("reduce", mesh, &d, reduced.as_ref().err(), "tasks: reduce");
    }
    if let Ok(r) = &reduced {
        let topo = oracle.as_ref().expect("accepted only for surfaces");
        check_reduce_result(mesh, topo, r, "tasks: reduce");
    }

    let quads = contractible::quadrangulate(mesh, quad_opts);
    if miscounted.is_some() {
        position_count("quad", quads.as_ref().err());
    } else {
        check_quad_outcome(mesh, &d, &oracle, &quads, qalg);
    }
    check_tasks_simplify(mesh, &d, simplify_opts);
}

/// The `quadrangulate` part of [`check_tasks`] (positions one per vertex, or none):
/// [`check_closed_refusal`]; `ds-naive` refuses exactly the meshes with a component above
/// [`contractible::quad::DS_NAIVE_MAX_FACES`], naming the first; outputs by
/// [`check_quad_result`].
fn check_quad_outcome(
    mesh: &contractible::TriMesh,
    d: &contractible::Description,
    oracle: &Result<Topology, String>,
    quads: &Result<contractible::QuadResult, contractible::Error>,
    qalg: contractible::quad::Algorithm,
) {
    use contractible::quad::{Algorithm as QAlg, DS_NAIVE_MAX_FACES};
    use contractible::Error;
    check_closed_refusal("quad", mesh, d, quads.as_ref().err(), "tasks: quad");
    let big = d
        .components()
        .iter()
        .position(|c| qalg == QAlg::DsNaive && c.faces > DS_NAIVE_MAX_FACES);
    match quads {
        Err(Error::TooLarge {
            algorithm,
            component,
            faces,
            limit,
        }) => {
            assert!(d.is_closed(), "tasks: too large before closed");
            assert_eq!(*algorithm, qalg, "tasks: too large, algorithm");
            assert_eq!(Some(*component), big, "tasks: too large, component");
            assert_eq!(
                (*faces, *limit),
                (d.components()[*component].faces, DS_NAIVE_MAX_FACES),
                "tasks: too large, counts"
            );
        }
        Err(_) => assert!(!d.is_closed(), "tasks: closed surfaces refused"),
        Ok(q) => {
            assert_eq!(
                big, None,
                "tasks: ds-naive ran on a component above its limit"
            );
            let topo = oracle.as_ref().expect("accepted only for surfaces");
            check_quad_result(mesh, topo, q, qalg, "tasks: quad");
        }
    }
}

/// The `simplify` part of [`check_tasks`]: [`check_simplify_task`]; an output is the
/// lower-level call's with the same options; a refusal for the faces alone is
/// `describe`'s first problem.
fn check_tasks_simplify(
    mesh: &contractible::TriMesh,
    d: &contractible::Description,
    simplify_opts: &contractible::SimplifyOptions,
) {
    use contractible::{Description, Error};
    let simplified = check_simplify_task(mesh, simplify_opts, "tasks: simplify");
    match (&simplified, d) {
        (Ok(s), _) => {
            let lower = contractible::simplify::simplify(
                mesh,
                &contractible::simplify::Options {
                    eps: s.eps,
                    mode: simplify_opts.mode,
                    side: simplify_opts.side,
                    position: simplify_opts.position,
                    guard: !simplify_opts.allow_foldover,
                },
            )
            .unwrap_or_else(|e| panic!("tasks: the lower-level call refused: {e}"));
            assert_same_simplification(s, &lower, "tasks: simplify");
        }
        (Err(e), Description::Problems { first, .. }) => {
            if simplify_refusals(mesh, &simplify_opts.eps) == ["mesh"] {
                assert!(
                    matches!(e, Error::Mesh(b) if b == first),
                    "tasks: simplify refused with {e}, describe's first problem is {first}"
                );
            }
        }
        (Err(_), Description::Surfaces { .. }) => {}
    }
}

// ---- Decimation (`decimate`): quadric edge collapse to a budget, checked from the face
// lists and the maps alone.

/// At most this many operations grow a [`DecimateInput`]'s main surface.
pub const DECIMATE_OPS: usize = 300;
/// At most this many operations grow its second component.
pub const DECIMATE_EXTRA_OPS: usize = 60;
/// At most this many faces are removed to make boundary.
pub const DECIMATE_HOLES: usize = 6;
/// At most this many vertices are locked.
pub const DECIMATE_LOCKED: usize = 4;

/// The error cap of a [`DecimateInput`]: a fraction of the bounding-box diagonal from
/// [`cap_value`], given as an absolute distance (the fraction times the diagonal, when
/// that is finite) or as [`contractible::MaxError::Relative`].
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorCap {
    /// [`contractible::MaxError::Absolute`].
    Absolute(u16),
    /// [`contractible::MaxError::Relative`].
    Relative(u16),
}

/// The input of `decimate`: a random closed surface (as `surface_ops` grows it, at most
/// [`DECIMATE_OPS`] operations), optionally a second one on vertices of its own, faces
/// removed to open them, unused vertices appended, positions laid out by [`layout`]
/// (degenerate ones included), and random options: face target, fraction kept, error
/// cap (each also with values the call must refuse), placement, guard, locks.
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct DecimateInput {
    /// The main surface (its `seed` is unused).
    pub base: SurfaceInput,
    /// A second component: start surface and operations (at most
    /// [`DECIMATE_EXTRA_OPS`]).
    pub extra: Option<(Surface, Vec<Op>)>,
    /// Seed of the positions ([`Rng`]).
    pub positions: u64,
    /// The layout of the positions.
    pub geometry: Geometry,
    /// Every coordinate times `10^`[`scale_exponent`]`(scale)` ([`layout`]).
    pub scale: i8,
    /// Faces to remove (ids mod F, in order); a face sharing a vertex with one already
    /// removed is kept.
    pub holes: Vec<u16>,
    /// `spare % 3` vertices no face uses, appended (at `±1e300`: they must not count in
    /// the diagonal).
    pub spare: u8,
    /// The face target ([`decimate_faces`]).
    pub faces: Option<u16>,
    /// The fraction kept ([`keep_value`]).
    pub keep: Option<u16>,
    /// The error cap.
    pub max_error: Option<ErrorCap>,
    /// `placement % 3` of [`contractible::decimate::Placement::ALL`].
    pub placement: u8,
    /// The fold-over guard (the call's `allow_foldover` is its negation).
    pub guard: bool,
    /// [`contractible::DecimateOptions::lock_boundary`].
    pub lock_boundary: bool,
    /// Locked vertices (mod the vertex count; `u16::MAX`: the vertex count itself, out
    /// of range); at most [`DECIMATE_LOCKED`].
    pub locked: Vec<u16>,
    /// [`contractible::DecimateOptions::skip_verify`] (the harness checks either way).
    pub skip_verify: bool,
    /// The pass schedule ([`contractible::decimate::Schedule::Passes`]) instead of the
    /// exact one.
    pub passes: bool,
}

/// The face target of a fuzzed `faces` against the input's face count: `n mod (F + 1)`
/// (every target from 0 to the input itself), `usize::MAX` for `u16::MAX`.
pub fn decimate_faces(n: u16, faces_in: usize) -> usize {
    if n == u16::MAX {
        usize::MAX
    } else {
        usize::from(n) % (faces_in + 1)
    }
}

/// The fraction kept of a fuzzed `keep`: `k / 60000` up to 60000 (in `[0, 1]`), above
/// it up to 1.09 (refused), and three special values: `-0.0` (accepted), `-1e-300` and
/// NaN (refused).
pub fn keep_value(k: u16) -> f64 {
    match k {
        65533 => -0.0,
        65534 => -1e-300,
        65535 => f64::NAN,
        _ => f64::from(k) / 60000.0,
    }
}

/// The fraction of the diagonal of a fuzzed error cap: `(x / 65529)² · 0.2` below
/// 65530, then 0, −1, NaN, ∞, `f64::MAX` and `1e-300`.
pub fn cap_value(x: u16) -> f64 {
    match x {
        65530 => 0.0,
        65531 => -1.0,
        65532 => f64::NAN,
        65533 => f64::INFINITY,
        65534 => f64::MAX,
        65535 => 1e-300,
        _ => {
            let r = f64::from(x) / 65529.0;
            r * r * 0.2
        }
    }
}

/// The mesh and options a [`DecimateInput`] describes.
pub fn decimate_case(
    input: &DecimateInput,
) -> (contractible::TriMesh, contractible::DecimateOptions) {
    use contractible::decimate::{Placement, Schedule};
    use contractible::{DecimateOptions, MaxError};
    let base = SurfaceInput {
        ops: input.base.ops.iter().take(DECIMATE_OPS).copied().collect(),
        ..input.base.clone()
    };
    let tri = build_surface(&base);
    let mut n = tri.vertex_capacity();
    let mut faces = tri.face_list();
    if let Some((surface, ops)) = &input.extra {
        let extra = build_surface(&SurfaceInput {
            surface: *surface,
            ops: ops.iter().take(DECIMATE_EXTRA_OPS).copied().collect(),
            seed: 0,
        });
        let shift = n as u32;
        faces.extend(extra.face_list().iter().map(|f| f.map(|v| v + shift)));
        n += extra.vertex_capacity();
    }
    let mut pos = layout(
        input.geometry,
        input.scale,
        input.positions,
        &neighbours(n, &faces),
    );
    let mut holed = vec![false; n];
    for &h in input.holes.iter().take(DECIMATE_HOLES) {
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
    for k in 0..input.spare % 3 {
        let far = if k == 0 { 1e300 } else { -1e300 };
        pos.push([far, 0.0, -far]);
    }
    let vertex_count = pos.len();
    let faces_in = faces.len();
    let mesh = contractible::TriMesh::with_positions(pos, faces);
    let diag = diagonal(
        used_vertices(&mesh)
            .iter()
            .map(|&v| &mesh.positions.as_deref().expect("positions")[v as usize]),
    );
    let max_error = input.max_error.map(|cap| match cap {
        ErrorCap::Absolute(x) => {
            let f = cap_value(x);
            let e = f * diag;
            // A usable fraction of a usable diagonal; the refused values as they are.
            MaxError::Absolute(if e.is_finite() && f.is_finite() && f >= 0.0 {
                e
            } else {
                f
            })
        }
        ErrorCap::Relative(x) => MaxError::Relative(cap_value(x)),
    });
    let options = DecimateOptions {
        faces: input.faces.map(|f| decimate_faces(f, faces_in)),
        keep: input.keep.map(keep_value),
        max_error,
        placement: Placement::ALL[usize::from(input.placement % 3)],
        schedule: if input.passes {
            Schedule::Passes
        } else {
            Schedule::Exact
        },
        allow_foldover: !input.guard,
        lock_boundary: input.lock_boundary,
        locked: input
            .locked
            .iter()
            .take(DECIMATE_LOCKED)
            .map(|&v| {
                if v == u16::MAX {
                    vertex_count as u32
                } else {
                    u32::from(v) % vertex_count as u32
                }
            })
            .collect(),
        skip_verify: input.skip_verify,
        ..DecimateOptions::default()
    };
    (mesh, options)
}

/// Why [`contractible::decimate()`](fn@contractible::decimate) must refuse `mesh` (a
/// union of surfaces with finite positions, one per vertex) with `options`, decided here
/// from the documented rules: `no_coordinates` when every used vertex (two at least) is
/// at one point (checked first); `bad_option` for a fraction kept outside `[0, 1]`, an
/// error cap that is not a finite number ≥ 0, a relative cap whose product with the used
/// vertices' diagonal is not finite, a locked vertex out of range. `None`: it must
/// succeed. The second value says that the decision is too close to call (the product
/// of a relative cap and the diagonal at the edge of the `f64` range, where the
/// library's diagonal may differ from this one in the last bit): then either outcome
/// is accepted.
pub fn decimate_refusal(
    mesh: &contractible::TriMesh,
    options: &contractible::DecimateOptions,
) -> (Option<&'static str>, bool) {
    use contractible::MaxError;
    let p = mesh.positions.as_deref().expect("positions");
    let used = used_vertices(mesh);
    if let Some(&first) = used.first() {
        if used.len() > 1 && used.iter().all(|&v| p[v as usize] == p[first as usize]) {
            return (Some("no_coordinates"), false);
        }
    }
    let usable = |e: f64| e.is_finite() && e >= 0.0;
    if let Some(k) = options.keep {
        if !(k.is_finite() && (0.0..=1.0).contains(&k)) {
            return (Some("bad_option"), false);
        }
    }
    match options.max_error {
        None => {}
        Some(MaxError::Absolute(e)) if !usable(e) => return (Some("bad_option"), false),
        Some(MaxError::Absolute(_)) => {}
        Some(MaxError::Relative(r)) if !usable(r) => return (Some("bad_option"), false),
        Some(MaxError::Relative(r)) => {
            let d = diagonal(used.iter().map(|&v| &p[v as usize]));
            let (lo, hi) = (r * d * (1.0 - 1e-12), r * d * (1.0 + 1e-12));
            if lo.is_finite() != hi.is_finite() {
                return (None, true);
            }
            if !(r * d).is_finite() {
                return (Some("bad_option"), false);
            }
        }
    }
    if options
        .locked
        .iter()
        .any(|&v| v as usize >= mesh.vertex_count)
    {
        return (Some("bad_option"), false);
    }
    (None, false)
}

/// `decimate`: the mesh and options of `input` through
/// [`contractible::decimate()`](fn@contractible::decimate): a refusal exactly when
/// [`decimate_refusal`] says so, of that kind; otherwise the result passes
/// [`check_decimated`], the library's own [`contractible::verify_decimation`] accepts
/// it, and a second run with `skip_verify` flipped gives the same output (the call is
/// deterministic, and the check changes nothing).
pub fn check_decimate_input(input: &DecimateInput) {
    let (mesh, options) = decimate_case(input);
    let r = check_decimate_call(&mesh, &options, "decimate");
    if let Ok(r) = r {
        let again = contractible::DecimateOptions {
            skip_verify: !options.skip_verify,
            ..options.clone()
        };
        let s = contractible::decimate(&mesh, &again)
            .unwrap_or_else(|e| panic!("decimate: the second run refused: {e}"));
        assert_same_decimation(&r, &s, "decimate: the second run");
    }
}

/// The call on `mesh` with `options`, checked: refused exactly for the reason
/// [`decimate_refusal`] finds (a typed input error), otherwise checked by
/// [`check_decimated`].
pub fn check_decimate_call(
    mesh: &contractible::TriMesh,
    options: &contractible::DecimateOptions,
    label: &str,
) -> Result<contractible::DecimateResult, contractible::Error> {
    let (refusal, ambiguous) = decimate_refusal(mesh, options);
    match contractible::decimate(mesh, options) {
        Err(e) => {
            assert!(e.is_input(), "{label}: {e} is not the input's fault");
            if !ambiguous {
                assert_eq!(
                    Some(e.kind()),
                    refusal,
                    "{label}: refused ({e}), expected {refusal:?}"
                );
            } else {
                assert_eq!(e.kind(), "bad_option", "{label}: refused ({e})");
            }
            Err(e)
        }
        Ok(r) => {
            assert!(
                refusal.is_none() || ambiguous,
                "{label}: accepted, expected a refusal: {refusal:?}"
            );
            check_decimated(mesh, options, &r, label);
            Ok(r)
        }
    }
}

/// Two results of one call are the same: mesh (positions bit for bit), maps and
/// statistics but the timings.
pub fn assert_same_decimation(
    a: &contractible::DecimateResult,
    b: &contractible::DecimateResult,
    label: &str,
) {
    assert_eq!(a.mesh.faces, b.mesh.faces, "{label}: faces");
    assert_eq!(
        a.mesh.vertex_count, b.mesh.vertex_count,
        "{label}: vertices"
    );
    let bits = |m: &contractible::TriMesh| {
        m.positions
            .as_ref()
            .map(|p| p.iter().map(|q| q.map(f64::to_bits)).collect::<Vec<_>>())
    };
    assert_eq!(bits(&a.mesh), bits(&b.mesh), "{label}: positions");
    assert_eq!(a.vertex_map, b.vertex_map, "{label}: vertex_map");
    assert_eq!(a.collapse_map, b.collapse_map, "{label}: collapse_map");
    assert_eq!(a.face_origin, b.face_origin, "{label}: face_origin");
    assert_eq!(
        a.bbox_diagonal.to_bits(),
        b.bbox_diagonal.to_bits(),
        "{label}: bbox_diagonal"
    );
    let mut sa = a.stats.clone();
    let mut sb = b.stats.clone();
    sa.seconds = 0.0;
    sb.seconds = 0.0;
    assert_eq!(sa, sb, "{label}: statistics");
}

/// The sorted vertex pair of an edge.
fn edge_key(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The link condition of a surface with boundary decided from a face list alone (each
/// boundary loop coned to an apex of its own): `[u, v]` passes iff the common
/// neighbours of its endpoints in the coned surface are exactly the third vertices of
/// its two coned faces, the endpoints are not on two different loops, and they are not
/// both of degree 3 in the coned surface (an edge of a tetrahedron).
pub struct LinkOracle {
    neighbours: std::collections::BTreeMap<u64, std::collections::BTreeSet<u64>>,
    opposite: std::collections::BTreeMap<(u32, u32), std::collections::BTreeSet<u64>>,
    loop_of: std::collections::BTreeMap<u32, u64>,
}

impl LinkOracle {
    /// The oracle of the surface `faces`.
    pub fn new(faces: &[[u32; 3]]) -> Self {
        use std::collections::{BTreeMap, BTreeSet};
        let mut neighbours: BTreeMap<u64, BTreeSet<u64>> = BTreeMap::new();
        let mut opposite: BTreeMap<(u32, u32), BTreeSet<u64>> = BTreeMap::new();
        for f in faces {
            for k in 0..3 {
                let (a, b, c) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
                opposite
                    .entry(edge_key(a, b))
                    .or_default()
                    .insert(u64::from(c));
                neighbours.entry(a.into()).or_default().insert(b.into());
                neighbours.entry(b.into()).or_default().insert(a.into());
            }
        }
        let boundary: Vec<(u32, u32)> = opposite
            .iter()
            .filter(|(_, o)| o.len() == 1)
            .map(|(&e, _)| e)
            .collect();
        let n = faces
            .iter()
            .flatten()
            .map(|&v| v as usize + 1)
            .max()
            .unwrap_or(0);
        let mut parent: Vec<u32> = (0..n as u32).collect();
        for &(a, b) in &boundary {
            uf_union(&mut parent, a, b);
        }
        let mut loop_of = BTreeMap::new();
        for &(a, b) in &boundary {
            let apex = (1u64 << 32) + u64::from(uf_find(&mut parent, a));
            for v in [a, b] {
                loop_of.insert(v, apex);
                neighbours.entry(v.into()).or_default().insert(apex);
                neighbours.entry(apex).or_default().insert(v.into());
            }
            opposite.get_mut(&(a, b)).expect("an edge").insert(apex);
        }
        LinkOracle {
            neighbours,
            opposite,
            loop_of,
        }
    }

    /// Every edge, as a sorted pair.
    pub fn edges(&self) -> impl Iterator<Item = (u32, u32)> + '_ {
        self.opposite.keys().copied()
    }

    /// Whether collapsing `[u, v]` keeps the surface.
    pub fn passes(&self, u: u32, v: u32) -> bool {
        let (nu, nv) = (
            &self.neighbours[&u64::from(u)],
            &self.neighbours[&u64::from(v)],
        );
        let common: std::collections::BTreeSet<u64> = nu.intersection(nv).copied().collect();
        let two_loops = matches!(
            (self.loop_of.get(&u), self.loop_of.get(&v)),
            (Some(a), Some(b)) if a != b
        );
        common == self.opposite[&edge_key(u, v)] && !two_loops && !(nu.len() == 3 && nv.len() == 3)
    }
}

/// The edges of `faces` in exactly one face, as sorted pairs, increasing.
fn boundary_edges(faces: &[[u32; 3]]) -> Vec<(u32, u32)> {
    let mut edges: Vec<(u32, u32)> = faces
        .iter()
        .flat_map(|f| (0..3).map(move |k| edge_key(f[k], f[(k + 1) % 3])))
        .collect();
    edges.sort_unstable();
    let mut out = Vec::new();
    let mut i = 0;
    while i < edges.len() {
        let j = edges[i..].iter().take_while(|&&e| e == edges[i]).count();
        if j == 1 {
            out.push(edges[i]);
        }
        i += j;
    }
    out
}

/// Twice the squared area of the triangle `f` against its longest edge, `|n|² / L⁴`, on
/// positions multiplied by `scale` (a power of two); 0 for a degenerate one.
fn relative_area2(p: &[[f64; 3]], f: &[u32; 3], scale: f64) -> f64 {
    let [a, b, c] = f.map(|v| p[v as usize].map(|x| x * scale));
    let d = |x: [f64; 3], y: [f64; 3]| [y[0] - x[0], y[1] - x[1], y[2] - x[2]];
    let (u, w) = (d(a, b), d(a, c));
    let n = [
        u[1] * w[2] - u[2] * w[1],
        u[2] * w[0] - u[0] * w[2],
        u[0] * w[1] - u[1] * w[0],
    ];
    let n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    let l2 = |x: [f64; 3]| x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
    let l = l2(u).max(l2(w)).max(l2(d(b, c)));
    if l == 0.0 {
        0.0
    } else {
        n2 / (l * l)
    }
}

/// Checks a decimation `r` of `mesh` made with `options`, by code that shares nothing
/// with the decimator:
///
/// - the output is a union of surfaces ([`surface_topology`]) using every output vertex,
///   with finite positions, one per vertex; each of its components descends (through
///   `face_origin`) from exactly one input component, one to one, with the same (χ,
///   orientable, boundary loops); the library's rebuild of the output
///   (`Surfaces::from_mesh_with_boundary`) gives each component that type too;
/// - the maps: `vertex_map` increasing over input vertices, `collapse_map` its inverse
///   there, defined exactly on the used input vertices; `face_origin` increasing, and
///   every output face is `collapse_map ∘ input.faces[face_origin]`;
/// - locked vertices (and, with `lock_boundary`, the boundary vertices, whose boundary
///   edges stay) survive at their input positions; endpoint placement moves nothing;
///   with the guard on, an input whose faces all have area keeps area in every face;
/// - the statistics agree with the meshes (counts, one vertex per collapse, faces lost,
///   the target and the cap, the diagonal, the dropped vertices);
/// - the stop rule: at the target, at most the target's faces (and at most one below
///   it); otherwise above it, every edge left classified, the error cap reached only with
///   a cap, and without a cap the link-condition refusals are exactly the edges that fail
///   the face-list [`LinkOracle`] among those not locked at both ends (with the guard
///   off too, no edge left passes it).
pub fn check_decimated(
    mesh: &contractible::TriMesh,
    options: &contractible::DecimateOptions,
    r: &contractible::DecimateResult,
    label: &str,
) {
    use contractible::decimate::{Placement, Stopped, NO_VERTEX};
    use contractible::MaxError;
    let out = &r.mesh;
    let before = surface_topology(&mesh.faces).unwrap_or_else(|e| panic!("{label}: input: {e}"));
    let after = surface_topology(&out.faces)
        .unwrap_or_else(|e| panic!("{label}: the output is not a surface: {e}"));
    let (nv_in, nv_out) = (mesh.vertex_count, out.vertex_count);
    assert_eq!(after.vertices, nv_out, "{label}: an unused output vertex");
    let pin = mesh.positions.as_deref().expect("input positions");
    let pout = out
        .positions
        .as_deref()
        .unwrap_or_else(|| panic!("{label}: output without positions"));
    assert_eq!(pout.len(), nv_out, "{label}: one position per vertex");
    assert!(
        pout.iter().flatten().all(|x| x.is_finite()),
        "{label}: a non-finite output coordinate"
    );
    // The maps.
    assert_eq!(r.vertex_map.len(), nv_out, "{label}: vertex_map length");
    assert_eq!(r.collapse_map.len(), nv_in, "{label}: collapse_map length");
    assert_eq!(
        r.face_origin.len(),
        out.faces.len(),
        "{label}: face_origin length"
    );
    for (o, &i) in r.vertex_map.iter().enumerate() {
        assert!((i as usize) < nv_in, "{label}: vertex_map[{o}] = {i}");
        assert!(
            o == 0 || r.vertex_map[o - 1] < i,
            "{label}: vertex_map not increasing at {o}"
        );
        assert_eq!(
            r.collapse_map[i as usize], o as u32,
            "{label}: output vertex {o} survives as {i}, not in collapse_map"
        );
    }
    let used = used_vertices(mesh);
    let mut is_used = vec![false; nv_in];
    for &v in &used {
        is_used[v as usize] = true;
    }
    for (i, &o) in r.collapse_map.iter().enumerate() {
        if is_used[i] {
            assert!(
                (o as usize) < nv_out,
                "{label}: collapse_map[{i}] = {o} is no output vertex"
            );
        } else {
            assert_eq!(o, NO_VERTEX, "{label}: collapse_map of unused vertex {i}");
        }
    }
    for (k, (&f, face)) in r.face_origin.iter().zip(&out.faces).enumerate() {
        assert!(
            (f as usize) < mesh.faces.len(),
            "{label}: face_origin[{k}] = {f}"
        );
        assert!(
            k == 0 || r.face_origin[k - 1] < f,
            "{label}: face_origin not increasing at {k}"
        );
        let renamed = mesh.faces[f as usize].map(|v| r.collapse_map[v as usize]);
        assert_eq!(
            renamed, *face,
            "{label}: output face {k} is not input face {f} renamed"
        );
    }
    // Components, one to one, each of its input component's type.
    let comps_in = component_faces(&mesh.faces);
    let comps_out = component_faces(&out.faces);
    assert_eq!(
        comps_out.len(),
        comps_in.len(),
        "{label}: {} components in, {} out",
        comps_in.len(),
        comps_out.len()
    );
    let mut comp_of_face = vec![usize::MAX; mesh.faces.len()];
    for (c, fs) in comps_in.iter().enumerate() {
        for &f in fs {
            comp_of_face[f] = c;
        }
    }
    let types_in: Vec<ComponentType> = comps_in
        .iter()
        .map(|fs| component_topology(&mesh.faces, fs).components[0])
        .collect();
    let mut seen = vec![false; comps_in.len()];
    for fs in &comps_out {
        let from = comp_of_face[r.face_origin[fs[0]] as usize];
        assert!(
            fs.iter()
                .all(|&f| comp_of_face[r.face_origin[f] as usize] == from),
            "{label}: an output component descends from two input components"
        );
        assert!(
            !std::mem::replace(&mut seen[from], true),
            "{label}: input component {from} split"
        );
        let t = component_topology(&out.faces, fs).components[0];
        assert_eq!(
            t, types_in[from],
            "{label}: input component {from} changed its type"
        );
    }
    let rebuilt = Surfaces::from_mesh_with_boundary(out)
        .unwrap_or_else(|e| panic!("{label}: the library does not rebuild the output: {e}"));
    assert!(
        rebuilt.dropped_vertices.is_empty(),
        "{label}: the rebuild drops vertices"
    );
    assert_eq!(
        rebuilt.components.len(),
        comps_in.len(),
        "{label}: rebuilt components"
    );
    for c in &rebuilt.components {
        let t = c.surface_type();
        let from = comp_of_face[r.face_origin[c.face_origin[0] as usize] as usize];
        let want = types_in[from];
        assert_eq!(
            (
                t.euler_characteristic(),
                t.is_orientable(),
                t.boundary_loops()
            ),
            (want.euler, want.orientable, want.boundary_loops),
            "{label}: a rebuilt component differs from its input component"
        );
    }
    // Locks and placements.
    let boundary_in = boundary_edges(&mesh.faces);
    let survives = |i: u32, why: &str| {
        let o = r.collapse_map[i as usize];
        if o == NO_VERTEX {
            return;
        }
        assert_eq!(
            r.vertex_map[o as usize], i,
            "{label}: {why} vertex {i} did not survive"
        );
        assert_eq!(
            pout[o as usize].map(f64::to_bits),
            pin[i as usize].map(f64::to_bits),
            "{label}: {why} vertex {i} moved"
        );
    };
    for &i in &options.locked {
        survives(i, "locked");
    }
    let mut locked_set: std::collections::BTreeSet<u32> = options.locked.iter().copied().collect();
    if options.lock_boundary {
        for &(a, b) in &boundary_in {
            survives(a, "boundary");
            survives(b, "boundary");
            locked_set.insert(a);
            locked_set.insert(b);
        }
        let mut boundary_out: Vec<(u32, u32)> = boundary_edges(&out.faces)
            .into_iter()
            .map(|(a, b)| edge_key(r.vertex_map[a as usize], r.vertex_map[b as usize]))
            .collect();
        boundary_out.sort_unstable();
        assert_eq!(
            boundary_out, boundary_in,
            "{label}: the boundary edges changed"
        );
    }
    if options.placement == Placement::Endpoint {
        for (o, &i) in r.vertex_map.iter().enumerate() {
            assert_eq!(
                pout[o].map(f64::to_bits),
                pin[i as usize].map(f64::to_bits),
                "{label}: endpoint placement moved vertex {i}"
            );
        }
    }
    if !options.allow_foldover {
        let largest = pin
            .iter()
            .chain(pout)
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        let scale = unit_scale(largest);
        if mesh
            .faces
            .iter()
            .all(|f| relative_area2(pin, f, scale) > 1e-16)
        {
            for (k, f) in out.faces.iter().enumerate() {
                assert!(
                    relative_area2(pout, f, scale) > 0.0,
                    "{label}: the guard left output face {k} {f:?} without area"
                );
            }
        }
    }
    // The statistics against the meshes.
    let s = &r.stats;
    assert_eq!(s.faces_in, mesh.faces.len(), "{label}: faces_in");
    assert_eq!(s.faces_out, out.faces.len(), "{label}: faces_out");
    assert_eq!(s.vertices_in, used.len(), "{label}: vertices_in");
    assert_eq!(s.vertices_out, nv_out, "{label}: vertices_out");
    assert_eq!(s.components, comps_in.len(), "{label}: components");
    assert_eq!(s.boundary_loops, before.loops(), "{label}: boundary_loops");
    assert_eq!(s.collapses, used.len() - nv_out, "{label}: collapses");
    let lost_boundary = before.boundary_edges - after.boundary_edges;
    assert_eq!(
        s.faces_in - s.faces_out,
        2 * s.collapses - lost_boundary,
        "{label}: two faces per collapse, one per boundary edge lost"
    );
    assert_eq!(
        r.dropped_vertices,
        nv_in - used.len(),
        "{label}: dropped vertices"
    );
    assert_eq!(r.verified, !options.skip_verify, "{label}: verified");
    let diag = diagonal(used.iter().map(|&v| &pin[v as usize]));
    assert!(
        r.bbox_diagonal == diag || (r.bbox_diagonal - diag).abs() <= 1e-12 * diag,
        "{label}: bbox_diagonal {} but the used vertices' is {diag}",
        r.bbox_diagonal
    );
    let by_keep = options
        .keep
        .map(|k| (k * mesh.faces.len() as f64).ceil() as usize);
    let target = match (options.faces, by_keep) {
        (None, None) => None,
        (a, b) => Some(a.unwrap_or(0).max(b.unwrap_or(0))),
    };
    assert_eq!(s.target_faces, target, "{label}: target_faces");
    let cap = options.max_error.map(|m| match m {
        MaxError::Absolute(e) => e,
        MaxError::Relative(f) => f * r.bbox_diagonal,
    });
    assert_eq!(s.max_error_cap, cap, "{label}: the cap");
    assert!(
        s.max_error.is_finite() && s.max_error >= 0.0,
        "{label}: max_error {}",
        s.max_error
    );
    if let Some(cap) = cap {
        assert!(
            s.max_error <= cap,
            "{label}: max_error {} > cap {cap}",
            s.max_error
        );
    }
    if s.collapses == 0 {
        assert_eq!(s.max_error, 0.0, "{label}: an error without a collapse");
    }
    // The stop rule.
    let oracle = LinkOracle::new(&out.faces);
    let both_locked = |a: u32, b: u32| {
        locked_set.contains(&r.vertex_map[a as usize])
            && locked_set.contains(&r.vertex_map[b as usize])
    };
    match s.stopped {
        Stopped::Target => {
            let t = target.unwrap_or_else(|| panic!("{label}: stopped at a target without one"));
            assert!(out.faces.len() <= t, "{label}: above the target {t}");
            if mesh.faces.len() > t {
                assert!(
                    out.faces.len() + 1 >= t,
                    "{label}: {} faces, more than one below the target {t}",
                    out.faces.len()
                );
            } else {
                assert_eq!(s.collapses, 0, "{label}: collapses below the target");
            }
            assert_eq!(s.remaining.total(), 0, "{label}: remaining at the target");
        }
        Stopped::Error | Stopped::Blocked => {
            if let Some(t) = target {
                assert!(
                    out.faces.len() > t,
                    "{label}: stopped {} at the target {t}",
                    s.stopped
                );
            }
            assert_eq!(
                s.remaining.total(),
                after.edges,
                "{label}: every edge left classified"
            );
            let locked_edges = oracle.edges().filter(|&(a, b)| both_locked(a, b)).count();
            assert_eq!(
                s.remaining.lock + s.remaining.boundary,
                locked_edges,
                "{label}: edges locked at both ends"
            );
            if !options.lock_boundary {
                assert_eq!(s.remaining.boundary, 0, "{label}: boundary refusals");
            }
            if s.stopped == Stopped::Error {
                assert!(cap.is_some(), "{label}: stopped by the error without a cap");
                assert!(
                    s.remaining.error > 0,
                    "{label}: Error with no edge over the cap"
                );
            } else {
                assert_eq!(
                    s.remaining.error, 0,
                    "{label}: Blocked with edges over the cap"
                );
            }
            if options.allow_foldover {
                assert_eq!(
                    s.remaining.foldover, 0,
                    "{label}: fold-over with the guard off"
                );
            }
            if cap.is_none() {
                let failing = oracle
                    .edges()
                    .filter(|&(a, b)| !both_locked(a, b) && !oracle.passes(a, b))
                    .count();
                assert_eq!(
                    s.remaining.link_condition, failing,
                    "{label}: link-condition refusals against the face-list oracle"
                );
                if options.allow_foldover {
                    if let Some((a, b)) = oracle
                        .edges()
                        .find(|&(a, b)| !both_locked(a, b) && oracle.passes(a, b))
                    {
                        panic!("{label}: stopped {} with [{a}, {b}] collapsible", s.stopped);
                    }
                }
            }
        }
    }
    // The library's own check agrees.
    if let Err(e) = contractible::verify_decimation(mesh, options, r) {
        panic!("{label}: verify_decimation refuses a result the harness accepts: {e}");
    }
}

// ---- The polygon reader, polygon triangulation and welding (`poly_weld`).

/// What `poly_weld` declares to the readers: nothing (the content decides), then each
/// format.
pub const DECLARED: [Option<Format>; 5] = [
    None,
    Some(Format::Off),
    Some(Format::Obj),
    Some(Format::Ply),
    Some(Format::Stl),
];

/// Meshes with at most this many vertices get their welds compared with the quadratic
/// oracle (all pairs).
pub const WELD_NAIVE_MAX: usize = 300;

/// The gzip magic: such input is decompressed by the reader, so the checks that need the
/// parsed bytes themselves (line numbers, the STL payload) skip it.
const GZIP: [u8; 2] = [0x1f, 0x8b];

/// `poly_weld`: raw bytes through the polygon reader and everything built on it, each
/// call declaring no format and then each format ([`DECLARED`]). Nothing may panic;
/// every refusal is a typed [`contractible::io::ReadError`] located within the input
/// ([`check_read_error`]). The entry points agree: [`read_tri_mesh_bytes`] is
/// [`contractible::io::read_poly_mesh_bytes`] then `into_tri_mesh`, and
/// [`contractible::io::decode`] parses as the sniffed format, else the declared one.
/// Each parsed mesh passes [`check_poly_mesh`] (the reader's guarantees),
/// [`check_triangulated`] (the documented cut of every polygon) and [`check_welds`]
/// (welding against a quadratic oracle); a triangle mesh is written in every format and
/// read back ([`check_round_trip`]); STL gets [`check_stl`] (binary payloads decoded
/// independently, welding by bitwise-equal position).
pub fn check_poly_bytes(bytes: &[u8]) {
    use contractible::io::{decode, read_poly_mesh_bytes};
    let plain = (!bytes.starts_with(&GZIP)).then_some(bytes);
    let hash = bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
    });
    for declared in DECLARED {
        let poly = read_poly_mesh_bytes(bytes, declared);
        let tri = read_tri_mesh_bytes(bytes, declared);
        match (&poly, &tri) {
            (Ok(p), Ok(t)) => assert_eq!(
                p.clone().into_tri_mesh().ok().as_ref(),
                Some(t),
                "{declared:?}: the triangle reader differs"
            ),
            (Ok(p), Err(e)) => {
                assert!(
                    !p.is_triangle_mesh(),
                    "{declared:?}: triangles refused: {e}"
                );
                check_read_error(e, plain);
            }
            (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{declared:?}"),
            (Err(e), Ok(_)) => panic!("{declared:?}: polygons refused, triangles read: {e}"),
        }
        // The format parsed: declared, else sniffed (known here for plain bytes only).
        let sniffed = plain.and_then(Format::sniff);
        let format = declared.or(sniffed);
        match decode(bytes, declared) {
            Ok(d) => {
                assert_eq!(d.declared, declared, "decode: declared");
                if let Some(data) = plain {
                    assert_eq!(
                        Some(d.format),
                        Format::sniff(data).or(declared),
                        "decode: the sniffed format, else the declared one"
                    );
                }
                assert_eq!(d.disagreement(), declared.filter(|&f| f != d.format));
                let again = read_poly_mesh_bytes(bytes, Some(d.format));
                assert_eq!(
                    again.as_ref().ok(),
                    Some(&d.mesh),
                    "decode differs from the reader"
                );
            }
            Err(e) => {
                check_read_error(&e, plain);
                if plain.is_some() {
                    match sniffed.or(declared) {
                        None => assert!(
                            matches!(e.kind, contractible::io::ReadErrorKind::UnknownFormat),
                            "decode: {e}"
                        ),
                        Some(f) => {
                            let again = read_poly_mesh_bytes(bytes, Some(f));
                            assert_eq!(
                                again.as_ref().err().map(|a| a.to_string()),
                                Some(e.to_string()),
                                "decode refused, the reader as {f}"
                            );
                        }
                    }
                }
            }
        }
        match &poly {
            Err(e) => check_read_error(e, plain),
            Ok(p) => {
                check_poly_mesh(p, format, plain);
                check_triangulated(p);
                check_welds(p, hash);
                if let Ok(t) = &tri {
                    check_round_trip(t);
                }
            }
        }
        if declared == Some(Format::Stl) {
            check_stl(bytes, plain, poly.as_ref().ok());
        }
    }
}

/// A refusal of the readers on in-memory bytes: a typed kind (never an I/O error: there
/// is no I/O), no path, and, for bytes read as they are (`plain`), a location within
/// them (a byte offset at most their length, a line at most their line count).
pub fn check_read_error(e: &contractible::io::ReadError, plain: Option<&[u8]>) {
    use contractible::io::{Location, ReadErrorKind};
    assert!(
        !matches!(e.kind, ReadErrorKind::Io(_)),
        "an I/O error without I/O: {e}"
    );
    assert!(e.path.is_none(), "a path without a file: {e}");
    let Some(data) = plain else {
        return;
    };
    match e.location {
        Location::ByteOffset(o) => {
            assert!(o <= data.len() as u64, "{e}: beyond {} bytes", data.len())
        }
        Location::Line(n) => {
            let lines = data.iter().filter(|&&b| b == b'\n').count() + 1;
            assert!((1..=lines).contains(&n), "{e}: not one of {lines} lines");
        }
        Location::Face(_) | Location::Unknown => {}
    }
}

/// The guarantees of a mesh from the readers (`format`: the one parsed, when known;
/// `plain`: the bytes, when not compressed): positions one per vertex and finite; every
/// corner in range, at least 3 per face; `face` past the end is empty; the file lines of
/// the faces (text formats; none for STL) at least 1, non-decreasing, within the input;
/// OBJ numbers from 1, the others from 0, and only OBJ skips statements; the corner range
/// and `is_triangle_mesh` agree with the faces; `into_tri_mesh` gives the triangles, or
/// refuses naming the first polygon; the diagnosis counts every face, and is the same
/// for the triangle mesh.
pub fn check_poly_mesh(
    p: &contractible::io::PolyMesh,
    format: Option<Format>,
    plain: Option<&[u8]>,
) {
    use contractible::io::{ReadErrorKind, SkippedStatements};
    if let Some(pos) = &p.positions {
        assert_eq!(pos.len(), p.vertex_count, "positions vs vertex_count");
        assert!(
            pos.iter().flatten().all(|x| x.is_finite()),
            "a non-finite coordinate read"
        );
    }
    let n = p.face_count();
    let mut range: Option<(usize, usize)> = None;
    let mut first_polygon = None;
    for (i, f) in p.faces().enumerate() {
        assert!(f.len() >= 3, "face {i} has {} corners", f.len());
        assert!(
            f.iter().all(|&v| (v as usize) < p.vertex_count),
            "face {i} {f:?}: index out of range ({} vertices)",
            p.vertex_count
        );
        let k = f.len();
        range = Some(range.map_or((k, k), |(a, b)| (a.min(k), b.max(k))));
        if k > 3 && first_polygon.is_none() {
            first_polygon = Some((i, k));
        }
    }
    assert!(p.face(n).is_empty(), "a face past the end");
    assert_eq!(p.corner_range(), range.unwrap_or((0, 0)), "corner range");
    assert_eq!(
        p.is_triangle_mesh(),
        first_polygon.is_none(),
        "is_triangle_mesh"
    );
    if let Some(lines) = p.lines() {
        assert_eq!(lines.len(), n, "one line per face");
        assert!(lines.iter().all(|&l| l >= 1), "line 0");
        assert!(
            lines.windows(2).all(|w| w[0] <= w[1]),
            "face lines decrease"
        );
        for (i, &l) in lines.iter().enumerate() {
            assert_eq!(p.face_line(i), Some(l as usize));
        }
        if let (Some(data), Some(&last)) = (plain, lines.last()) {
            let count = data.iter().filter(|&&b| b == b'\n').count() + 1;
            assert!(last as usize <= count, "face line {last} of {count} lines");
        }
    }
    let one_based = format == Some(Format::Obj);
    if format.is_some() {
        assert_eq!(p.one_based(), one_based, "{format:?}: numbering");
    }
    assert_eq!(p.number(0), usize::from(p.one_based()), "number");
    match format {
        Some(Format::Stl) => assert!(p.lines().is_none(), "STL face lines"),
        Some(Format::Off | Format::Obj) => {
            assert!(p.lines().is_some(), "{format:?}: no face lines")
        }
        _ => {}
    }
    let skipped = p.skipped_statements();
    assert!(
        skipped.kinds.len() <= SkippedStatements::MAX_KINDS,
        "skipped kinds kept"
    );
    assert_eq!(
        skipped.total(),
        skipped.kinds.iter().map(|k| k.1).sum::<usize>() + skipped.others
    );
    if format.is_some() && !one_based {
        assert_eq!(skipped.total(), 0, "{format:?}: skipped statements");
    }
    match (p.clone().into_tri_mesh(), first_polygon) {
        (Ok(t), None) => {
            assert_eq!(t.vertex_count, p.vertex_count);
            assert_eq!(t.positions, p.positions);
            assert!(
                t.faces.iter().map(|f| &f[..]).eq(p.faces()),
                "into_tri_mesh faces"
            );
            let (a, b) = (
                contractible::diagnose::diagnose(&t, 2),
                contractible::diagnose::diagnose(p, 2),
            );
            assert_eq!(a, b, "diagnosis of the triangles and of the polygons");
        }
        (Err(e), Some((i, k))) => {
            assert!(
                matches!(
                    e.kind,
                    ReadErrorKind::NonTriangleFace { face, corners }
                        if face == p.number(i) && corners == k as u64
                ),
                "into_tri_mesh: {e}, the first polygon is face {i} of {k} corners"
            );
        }
        (r, first) => panic!("into_tri_mesh {r:?} with first polygon {first:?}"),
    }
    let g = contractible::diagnose::diagnose(p, 2);
    assert_eq!(g.faces, n, "diagnosis faces");
    assert_eq!(
        g.vertices + g.unused_vertices,
        p.vertex_count,
        "diagnosis vertices"
    );
}

/// [`contractible::io::PolyMesh::triangulated`] against its documented rule, re-derived
/// here with an ordered set of the vertex pairs that are edges (every polygon side, and
/// the diagonals cut so far): each polygon of `k` corners becomes `k − 2` triangles in
/// fan order from one start corner, in polygon order, with its origin; the start is the
/// preferred one (a quad's shorter diagonal, corners 1–3 only when strictly shorter than
/// 0–2 and positions exist; corner 0 otherwise) when its diagonals are all new, else the
/// first other start among the first 8 (the reader's `MAX_FAN_STARTS`) whose diagonals
/// are all new, else the preferred one; positions and vertex count kept; the
/// number of polygons (more than 3 corners) counted.
pub fn check_triangulated(p: &contractible::io::PolyMesh) {
    use std::collections::BTreeSet;
    const MAX_FAN_STARTS: usize = 8;
    let t = p.triangulated();
    assert_eq!(
        t.mesh.vertex_count, p.vertex_count,
        "triangulated vertex count"
    );
    assert_eq!(t.mesh.positions, p.positions, "triangulated positions");
    let pair = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut edges: BTreeSet<(u32, u32)> = p
        .faces()
        .flat_map(|f| (0..f.len()).map(move |j| pair(f[j], f[(j + 1) % f.len()])))
        .collect();
    let shorter_13 = |f: &[u32]| {
        let Some(pos) = &p.positions else {
            return false;
        };
        let d2 = |x: u32, y: u32| {
            let (a, b) = (pos[x as usize], pos[y as usize]);
            (0..3).map(|i| (a[i] - b[i]) * (a[i] - b[i])).sum::<f64>()
        };
        d2(f[1], f[3]) < d2(f[0], f[2])
    };
    let mut at = 0usize;
    let mut polygons = 0usize;
    for (i, f) in p.faces().enumerate() {
        let k = f.len();
        polygons += usize::from(k > 3);
        let preferred = usize::from(k == 4 && shorter_13(f));
        let new = |s: usize| {
            (2..k - 1).all(|j| {
                let (a, b) = (f[s], f[(s + j) % k]);
                a != b && !edges.contains(&pair(a, b))
            })
        };
        let start = if k <= 3 || new(preferred) {
            preferred
        } else {
            (0..k.min(MAX_FAN_STARTS))
                .find(|&s| s != preferred && new(s))
                .unwrap_or(preferred)
        };
        let fan: Vec<[u32; 3]> = (1..k - 1)
            .map(|j| [f[start], f[(start + j) % k], f[(start + j + 1) % k]])
            .collect();
        assert_eq!(
            t.mesh.faces.get(at..at + k - 2),
            Some(&fan[..]),
            "polygon {i} {f:?}: not the fan from corner {start}"
        );
        assert!(
            t.origin[at..at + k - 2].iter().all(|&o| o as usize == i),
            "polygon {i}: origins"
        );
        for j in 2..k - 1 {
            edges.insert(pair(f[start], f[(start + j) % k]));
        }
        at += k - 2;
    }
    assert_eq!(t.mesh.faces.len(), at, "triangle count");
    assert_eq!(t.origin.len(), at, "origin count");
    assert_eq!(t.polygons, polygons, "polygon count");
}

/// Welding the positions of `p` with several tolerances (0: bitwise-equal positions;
/// fractions of the bounding-box diagonal; absolute ones; one drawn from `hash`):
/// [`contractible::mesh::weld_map`] refuses a negative or non-finite tolerance, and
/// otherwise groups the vertices into classes represented by their lowest index, kept in
/// increasing order; with at most [`WELD_NAIVE_MAX`] vertices the classes are exactly
/// the connected components of "bitwise equal" (tolerance 0) or "squared distance ≤
/// tolerance²" (all pairs compared here); `PolyMesh::welded_within` and `welded_by` give
/// the mesh renamed by the map (faces, their lines and count kept, positions of the kept
/// vertices), the merged count, and for a triangle mesh what `TriMesh::welded_within`
/// gives; `coincident_vertex_count` is what tolerance 0 merges. Without positions,
/// welding changes nothing.
pub fn check_welds(p: &contractible::io::PolyMesh, hash: u64) {
    use contractible::mesh::weld_map;
    let Some(pos) = &p.positions else {
        assert_eq!(
            p.welded_within(0.0),
            Some((p.clone(), 0)),
            "welding without positions"
        );
        assert_eq!(
            p.welded_within(1.0),
            Some((p.clone(), 0)),
            "welding without positions"
        );
        return;
    };
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        assert!(
            weld_map(pos, bad).is_none(),
            "weld_map accepted tolerance {bad}"
        );
        assert!(
            p.welded_within(bad).is_none(),
            "welded_within accepted tolerance {bad}"
        );
    }
    let d = diagonal(pos);
    let base = if d.is_finite() && d > 0.0 { d } else { 1.0 };
    let mut tolerances = vec![0.0, 1.0, base * 1e-12, base * 1e-6, base * 0.25];
    tolerances.push(base * 10f64.powi(-((hash % 16) as i32)));
    for tol in tolerances {
        check_weld(p, pos, tol);
    }
}

fn check_weld(p: &contractible::io::PolyMesh, pos: &[[f64; 3]], tol: f64) {
    use contractible::mesh::weld_map;
    let label = format!("weld within {tol:e}");
    let n = pos.len();
    let w = weld_map(pos, tol).unwrap_or_else(|| panic!("{label}: refused"));
    assert_eq!(w.new_id.len(), n, "{label}: new_id");
    assert!(
        w.kept.windows(2).all(|x| x[0] < x[1]),
        "{label}: kept not increasing"
    );
    for (k, &v) in w.kept.iter().enumerate() {
        assert_eq!(w.new_id[v as usize] as usize, k, "{label}: kept vertex {v}");
    }
    for (v, &id) in w.new_id.iter().enumerate() {
        let r = *w
            .kept
            .get(id as usize)
            .unwrap_or_else(|| panic!("{label}: new id {id} of {v}"));
        assert!(r as usize <= v, "{label}: {v} represented by the later {r}");
        if tol == 0.0 {
            assert_eq!(
                pos[v].map(f64::to_bits),
                pos[r as usize].map(f64::to_bits),
                "{label}: {v} welded to {r} at another position"
            );
        }
    }
    if n <= WELD_NAIVE_MAX {
        let mut parent: Vec<u32> = (0..n as u32).collect();
        // The documented comparison: differences scaled by the power of two `s` that
        // brings the tolerance near 1, so that neither square overflows nor underflows.
        let s = if tol > 0.0 {
            2f64.powi(-(tol.log2().floor() as i32).clamp(-1000, 1000))
        } else {
            1.0
        };
        let t2 = (tol * s) * (tol * s);
        for a in 0..n {
            for b in a + 1..n {
                let (x, y) = (pos[a], pos[b]);
                let close = if tol == 0.0 {
                    x.map(f64::to_bits) == y.map(f64::to_bits)
                } else {
                    (0..3)
                        .map(|i| ((x[i] - y[i]) * s) * ((x[i] - y[i]) * s))
                        .sum::<f64>()
                        <= t2
                };
                if close {
                    uf_union(&mut parent, a as u32, b as u32);
                }
            }
        }
        let mut low = vec![u32::MAX; n];
        for v in 0..n {
            let r = uf_find(&mut parent, v as u32) as usize;
            low[r] = low[r].min(v as u32);
        }
        for (v, p) in pos.iter().enumerate() {
            let r = uf_find(&mut parent, v as u32) as usize;
            let got = w.kept[w.new_id[v] as usize];
            assert_eq!(
                got, low[r],
                "{label}: vertex {v} {p:?} represented by {got}, the oracle's class by {}",
                low[r]
            );
        }
    }
    let (m, merged) = p
        .welded_within(tol)
        .unwrap_or_else(|| panic!("{label}: welded_within refused"));
    assert_eq!(merged, n - w.kept.len(), "{label}: merged");
    assert_eq!(
        p.welded_by(&w).as_ref(),
        Some(&m),
        "{label}: welded_by differs"
    );
    assert_eq!(m.vertex_count, w.kept.len(), "{label}: vertex count");
    let kept: Vec<[u64; 3]> = w
        .kept
        .iter()
        .map(|&v| pos[v as usize].map(f64::to_bits))
        .collect();
    let got: Option<Vec<[u64; 3]>> = m
        .positions
        .as_ref()
        .map(|q| q.iter().map(|x| x.map(f64::to_bits)).collect());
    assert_eq!(got, Some(kept), "{label}: positions of the kept vertices");
    assert_eq!(m.face_count(), p.face_count(), "{label}: faces");
    assert_eq!(m.lines(), p.lines(), "{label}: face lines");
    for (f, g) in p.faces().zip(m.faces()) {
        let renamed: Vec<u32> = f.iter().map(|&v| w.new_id[v as usize]).collect();
        assert_eq!(g, &renamed[..], "{label}: face {f:?} renamed");
    }
    if tol == 0.0 {
        let t = contractible::TriMesh::with_positions(pos.to_vec(), Vec::new());
        assert_eq!(
            t.coincident_vertex_count(),
            merged,
            "{label}: coincident vertices"
        );
    }
    if p.is_triangle_mesh() {
        let t = p.clone().into_tri_mesh().expect("triangles");
        let expect = m.clone().into_tri_mesh().expect("triangles");
        assert_eq!(
            t.welded_within(tol),
            Some((expect, merged)),
            "{label}: TriMesh::welded_within differs"
        );
    }
}

/// The triangle soup of `t`: three new vertices per face, at its corners' positions (a
/// mesh without positions gives none).
fn soup(t: &contractible::TriMesh) -> contractible::TriMesh {
    let p = t.positions.as_deref().unwrap_or_default();
    let positions = t.faces.iter().flatten().map(|&v| p[v as usize]).collect();
    let faces = (0..t.faces.len() as u32)
        .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
        .collect();
    contractible::TriMesh::with_positions(positions, faces)
}

/// `read_poly_mesh_bytes(bytes, Some(Format::Stl))` (`poly`; `plain`: the bytes when
/// not compressed) against what the STL module documents:
///
/// - a binary payload (length `84 + 50 n` for the count `n` at bytes 80..84) is decoded
///   here independently: a non-finite coordinate is refused at its byte offset,
///   otherwise the mesh is that triangle soup welded by [`contractible::Mesh::welded`];
/// - input that is neither binary of a consistent size nor starts with `solid` is
///   refused;
/// - any mesh read is a welded soup: triangles, positions, every vertex used, numbered
///   in order of first appearance, no two at bitwise-equal positions, equal to its own
///   soup welded; written as binary STL it reads back as its soup with positions rounded
///   to `f32` and welded (itself when every coordinate is an `f32`), unless a
///   coordinate is beyond the `f32` range, which the writer refuses before writing.
pub fn check_stl(bytes: &[u8], plain: Option<&[u8]>, poly: Option<&contractible::io::PolyMesh>) {
    use contractible::io::{write_mesh_to, Location, ReadErrorKind};
    let read = contractible::io::read_tri_mesh_bytes(bytes, Some(Format::Stl));
    assert_eq!(
        read.is_ok(),
        poly.is_some(),
        "STL: the triangle and polygon readers disagree"
    );
    if let Some(data) = plain {
        let count = data
            .get(80..84)
            .map(|c| u64::from(u32::from_le_bytes([c[0], c[1], c[2], c[3]])));
        let binary = count.is_some_and(|n| (data.len() - 84) as u64 == 50 * n);
        if binary {
            let mut corners = Vec::new();
            let mut bad = None;
            for (i, t) in data[84..].chunks_exact(50).enumerate() {
                for k in 0..9 {
                    let at = 12 + 4 * k;
                    let x = f32::from_le_bytes([t[at], t[at + 1], t[at + 2], t[at + 3]]);
                    if !x.is_finite() && bad.is_none() {
                        bad = Some((84 + 50 * i + at) as u64);
                    }
                    corners.push(f64::from(x));
                }
            }
            match (&read, bad) {
                (Err(e), Some(at)) => {
                    assert!(
                        matches!(e.kind, ReadErrorKind::BadNumber { .. }),
                        "STL: {e}"
                    );
                    assert_eq!(e.location, Location::ByteOffset(at), "STL: {e}");
                }
                (Ok(m), None) => {
                    let positions: Vec<[f64; 3]> = corners
                        .chunks_exact(3)
                        .map(|c| [c[0], c[1], c[2]])
                        .collect();
                    let faces = (0..positions.len() as u32 / 3)
                        .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
                        .collect();
                    let expect = contractible::TriMesh::with_positions(positions, faces)
                        .welded()
                        .expect("a soup welds")
                        .0;
                    assert_eq!(*m, expect, "STL: binary payload read otherwise");
                }
                (r, bad) => panic!("STL: binary payload, non-finite at {bad:?}, read {r:?}"),
            }
        } else {
            let text = data.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(data);
            let start = text
                .iter()
                .position(|&b| !matches!(b, b' ' | b'\t' | b'\r' | b'\n' | 0x0b | 0x0c))
                .map_or(&text[text.len()..], |i| &text[i..]);
            let solid = start.len() >= 5 && start[..5].eq_ignore_ascii_case(b"solid");
            if !solid {
                assert!(read.is_err(), "STL: neither binary nor ASCII, yet read");
            }
        }
    }
    let Ok(m) = read else {
        return;
    };
    let p = m.positions.as_deref().expect("STL has positions");
    assert_eq!(p.len(), m.vertex_count);
    let mut next = 0u32;
    for &v in m.faces.iter().flatten() {
        assert!(v <= next, "STL: vertex {v} before {next}");
        if v == next {
            next += 1;
        }
    }
    assert_eq!(next as usize, m.vertex_count, "STL: an unused vertex");
    let distinct: std::collections::HashSet<[u64; 3]> =
        p.iter().map(|q| q.map(f64::to_bits)).collect();
    assert_eq!(distinct.len(), p.len(), "STL: two vertices at one position");
    let s = soup(&m);
    assert_eq!(
        s.welded(),
        Some((m.clone(), 3 * m.faces.len() - m.vertex_count)),
        "STL: not its own soup welded"
    );
    let mut out = Vec::new();
    let written = write_mesh_to(&mut out, &m, Format::Stl, true);
    if p.iter().flatten().any(|&x| !(x as f32).is_finite()) {
        assert!(
            written.is_err() && out.is_empty(),
            "STL: beyond f32 written"
        );
        return;
    }
    written.unwrap_or_else(|e| panic!("STL: writing refused: {e}"));
    let back = contractible::io::read_tri_mesh_bytes(&out, Some(Format::Stl))
        .unwrap_or_else(|e| panic!("STL: written file refused: {e}"));
    let mut rounded = s;
    if let Some(q) = &mut rounded.positions {
        for x in q.iter_mut().flatten() {
            *x = f64::from(*x as f32);
        }
    }
    assert_eq!(
        Some(back.clone()),
        rounded.welded().map(|w| w.0),
        "STL: written and read back"
    );
    if p.iter().flatten().all(|&x| f64::from(x as f32) == x) {
        assert_eq!(back, m, "STL: f32 positions not read back exactly");
    }
}

/// A triangle mesh with at least one face written in every format (OFF, OBJ, ASCII and
/// binary little-endian PLY, big-endian PLY; STL in [`check_stl`]) and read back as that
/// format: the same mesh, positions bit for bit (`0 0 0` for a mesh without positions).
pub fn check_round_trip(t: &contractible::TriMesh) {
    use contractible::io::{write_mesh_to, write_ply_to, PlyEncoding};
    if t.faces.is_empty() {
        return;
    }
    let mut expect = t.clone();
    if expect.positions.is_none() {
        expect.positions = Some(vec![[0.0; 3]; t.vertex_count]);
    }
    let bits = |m: &contractible::TriMesh| {
        m.positions
            .as_ref()
            .map(|p| p.iter().map(|x| x.map(f64::to_bits)).collect::<Vec<_>>())
    };
    let cases = [
        ("OFF", Format::Off, None),
        ("OBJ", Format::Obj, None),
        ("PLY ascii", Format::Ply, Some(PlyEncoding::Ascii)),
        (
            "PLY binary",
            Format::Ply,
            Some(PlyEncoding::BinaryLittleEndian),
        ),
        (
            "PLY big-endian",
            Format::Ply,
            Some(PlyEncoding::BinaryBigEndian),
        ),
    ];
    for (name, format, encoding) in cases {
        let mut out = Vec::new();
        match encoding {
            None => write_mesh_to(&mut out, t, format, false),
            Some(e) => write_ply_to(&mut out, t, e),
        }
        .unwrap_or_else(|e| panic!("{name}: writing a read mesh refused: {e}"));
        let back = read_tri_mesh_bytes(&out, Some(format))
            .unwrap_or_else(|e| panic!("{name}: the written file refused: {e}"));
        assert_eq!(
            back.vertex_count, expect.vertex_count,
            "{name}: vertex count"
        );
        assert_eq!(back.faces, expect.faces, "{name}: faces");
        assert_eq!(bits(&back), bits(&expect), "{name}: positions");
    }
}

/// At most this many contraction picks in `check`.
pub const CHECK_PICKS: usize = 256;
/// At most this many edits in `check`.
pub const CHECK_EDITS: usize = 8;

/// The input of `check`: a surface grown by vertex splits (the checker's input), an
/// answer made from it by contractions that pass the link condition (some, or until
/// irreducible: a right or a wrong reduction), perhaps corrupted by edits, perhaps
/// written with a compacted vertex list (matched by position).
#[derive(Arbitrary, Clone, Debug, PartialEq, Eq)]
pub struct CheckInput {
    /// The input surface.
    pub base: SurfaceInput,
    /// `(vertex, k)`: contract `[vertex, link(vertex)[k]]` when it passes the link
    /// condition (ids mod capacity, `k` mod degree; at most [`CHECK_PICKS`]).
    pub picks: Vec<(u16, u8)>,
    /// Then contract until irreducible.
    pub finish: bool,
    /// Edits of the answer's faces (at most [`CHECK_EDITS`]).
    pub edits: Vec<Edit>,
    /// Write the answer with only the vertices its faces use.
    pub compact: bool,
    /// Edits of the contraction history `(kind, i, j)` (at most [`CHECK_EDITS`]): kind mod
    /// 4 is 0 drop step i, 1 repeat step i, 2 swap steps i and j, 3 replace step i by
    /// `[i, j]` as vertex ids (mod capacity); indices mod the steps.
    pub history_edits: Vec<(u8, u16, u16)>,
}

/// `check::reduce` on a contracted, maybe edited, answer: never a panic or an error (the
/// input is a closed surface); on an unedited answer the verdict is exactly the core's
/// naive link predicate (the contractible edges counted, nothing else wrong); and a
/// verdict that passes is confirmed by the core: the answer, rebuilt, is a closed
/// irreducible triangulation of the input's surface. With the contractions made as a
/// history, maybe edited (`check::reduce_history`): the unedited history adds no reason
/// to an unedited answer's verdict, and a replay the checker accepts is confirmed by the
/// core (every step an edge passing its naive link condition, contracted by the core,
/// ending at the answer's faces).
pub fn check_check(input: &CheckInput) {
    use contractible::check::{self, FailureKind};
    let tri = build_surface(&input.base);
    let n = tri.vertex_capacity();
    // Distinct positions, so that a compacted answer is matched back exactly.
    let positions: Vec<[f64; 3]> = (0..n)
        .map(|v| [v as f64, ((v * 7) % 13) as f64, 0.5])
        .collect();
    let source = contractible::TriMesh::with_positions(positions.clone(), tri.face_list());
    let mut t = tri.clone();
    let mut scratch = Vec::new();
    // The contractions made, `[kept, removed]`.
    let mut steps: Vec<[u32; 2]> = Vec::new();
    for &(v, k) in input.picks.iter().take(CHECK_PICKS) {
        let u = VertexId(u32::from(v) % n as u32);
        if !t.is_vertex(u) {
            continue;
        }
        let link: Vec<VertexId> = t.link(u).collect();
        let w = link[usize::from(k) % link.len()];
        if t.link_condition_naive(u, w) {
            t.collapse(u, w, &mut scratch);
            steps.push([u.0, w.0]);
        }
    }
    if input.finish {
        loop {
            let next = t.edges().find(|&(a, b, _)| t.link_condition_naive(a, b));
            let Some((a, b, _)) = next else { break };
            t.collapse(a, b, &mut scratch);
            steps.push([a.0, b.0]);
        }
    }
    let mut faces = t.face_list();
    let unedited = faces.clone();
    apply_edits(&mut faces, n as u32, input.edits.iter().take(CHECK_EDITS));
    let edited = faces != unedited;
    let answer = contractible::TriMesh::with_positions(positions.clone(), faces.clone());
    let (answer, compacted) = match answer.compacted() {
        Some((c, dropped)) if input.compact && dropped > 0 => (c, true),
        _ => (answer, false),
    };
    let v = check::reduce(&source, &answer).expect("a closed input is judged");
    if !edited {
        let contractible_edges = t
            .edges()
            .filter(|&(a, b, _)| t.link_condition_naive(a, b))
            .count();
        let kinds: Vec<FailureKind> = v.counts.iter().map(|&(k, _)| k).collect();
        if contractible_edges == 0 {
            assert!(v.passed(), "an irreducible answer fails: {v:?}");
        } else {
            assert_eq!(kinds, [FailureKind::ContractibleEdge], "{v:?}");
            assert_eq!(v.counts[0].1, contractible_edges);
        }
    }
    if v.passed() {
        // The answer in the input's ids, rebuilt by the core.
        let faces_in_input_ids: Vec<[u32; 3]> = if compacted {
            let pos = answer.positions.as_ref().expect("positions");
            answer
                .faces
                .iter()
                .map(|f| f.map(|x| pos[x as usize][0] as u32))
                .collect()
        } else {
            faces.clone()
        };
        let rebuilt =
            Surfaces::from_mesh(&contractible::TriMesh::combinatorial(n, faces_in_input_ids))
                .unwrap_or_else(|e| panic!("a passing answer is no closed surface: {e}"));
        assert_eq!(rebuilt.components.len(), 1, "one surface in, one out");
        let r = &rebuilt.components[0].tri;
        assert!(r.is_irreducible_naive(), "a passing answer is reducible");
        assert_eq!(r.euler_characteristic(), tri.euler_characteristic());
        assert_eq!(r.is_orientable(), tri.is_orientable());
    }
    // The history, maybe edited.
    let mut history = steps.clone();
    for &(kind, i, j) in input.history_edits.iter().take(CHECK_EDITS) {
        if history.is_empty() {
            break;
        }
        let (i, j) = (
            usize::from(i) % history.len(),
            usize::from(j) % history.len(),
        );
        match kind % 4 {
            0 => {
                history.remove(i);
            }
            1 => history.insert(i, history[i]),
            2 => history.swap(i, j),
            _ => history[i] = [i as u32 % n as u32, j as u32 % n as u32],
        }
    }
    let vh = check::reduce_history(&source, &answer, &history).expect("a closed input is judged");
    if history == steps && !edited {
        assert_eq!(
            vh.counts, v.counts,
            "the true history adds a reason: {vh:?}"
        );
    }
    // The replay was judged in full (every step, and the end against the answer's faces)
    // unless the answer is no closed surface on matched vertices; then, with no replay
    // reason, the core must replay it to the answer's faces.
    let judged_in_full = vh.counts.iter().all(|(k, _)| {
        matches!(
            k,
            FailureKind::ContractibleEdge
                | FailureKind::SurfaceChanged
                | FailureKind::ComponentLost
                | FailureKind::ComponentSplit
                | FailureKind::ComponentsMerged
        )
    });
    if judged_in_full {
        let mut c = tri.clone();
        for &[a, b] in &history {
            let (a, b) = (VertexId(a), VertexId(b));
            assert!(
                c.is_vertex(a) && c.is_vertex(b) && c.link_condition_naive(a, b),
                "an accepted step [{}, {}] is no contractible edge",
                a.0,
                b.0
            );
            c.collapse(a, b, &mut scratch);
        }
        let sorted = |fs: &[[u32; 3]]| {
            let mut fs: Vec<[u32; 3]> = fs
                .iter()
                .map(|f| {
                    let mut f = *f;
                    f.sort_unstable();
                    f
                })
                .collect();
            fs.sort_unstable();
            fs
        };
        assert_eq!(
            sorted(&c.face_list()),
            sorted(&faces),
            "an accepted history does not end at the answer"
        );
    }
}

/// The component types (χ, orientability, boundary loops) of `m` rebuilt by the core as a
/// surface with boundary, sorted: a multiset (panics naming the defect when `m` is no
/// surface with boundary: for the checkers' passing answers, that is the finding).
fn component_types(m: &contractible::TriMesh) -> Vec<(i64, bool, usize)> {
    let s = contractible::ConedSurfaces::from_mesh(m)
        .unwrap_or_else(|e| panic!("a passing answer is no surface with boundary: {e}"));
    let mut t: Vec<(i64, bool, usize)> = s
        .components
        .iter()
        .map(|c| {
            let t = c.surface_type();
            (
                t.euler_characteristic(),
                t.is_orientable(),
                t.boundary_loops(),
            )
        })
        .collect();
    t.sort_unstable();
    t
}

/// A `simplify` answer judged by `check::simplify`: the library's own run on a
/// [`SimplifyInput`] case (a surface with holes, positions, ε and the run's options),
/// then edits of the answer's faces.
#[derive(Arbitrary, Clone, Debug)]
pub struct CheckSimplifyInput {
    /// The input, ε and the run's options.
    pub case: SimplifyInput,
    /// Edits of the answer's faces (at most [`CHECK_EDITS`]).
    pub edits: Vec<Edit>,
}

/// `check::simplify` on the library's own answer and on edited ones: never a panic; the
/// checker refuses exactly the inputs the task refuses; the library's answer passes; and
/// an edited answer that passes is confirmed by the core: rebuilt as a surface with
/// boundary, it has the input's component types (χ, orientability, boundary loops) as a
/// multiset and, when the run had no geometry guard, no edge shorter than ε (by a
/// relative margin of 1e-9) that passes the core's link condition of the surface with
/// boundary.
pub fn check_simplify_check(input: &CheckSimplifyInput) {
    use contractible::check::{self, SimplifyCheck};
    use contractible::simplify::Mode;
    use contractible::ConedSurfaces;
    let s = &input.case;
    let case = simplify_mesh(s);
    let lower = simplify_options(s, case.eps);
    let opts = contractible::SimplifyOptions {
        eps: if s.relative {
            contractible::Eps::Relative(case.fraction)
        } else {
            contractible::Eps::Absolute(case.eps)
        },
        mode: if s.nested { Mode::Nested } else { Mode::Naive },
        side: lower.side,
        position: lower.position,
        allow_foldover: !s.guard,
        ..contractible::SimplifyOptions::default()
    };
    let judge = SimplifyCheck {
        eps: opts.eps,
        position: opts.position,
        allow_foldover: opts.allow_foldover,
    };
    let r = match contractible::simplify(&case.mesh, &opts) {
        Ok(r) => r,
        Err(e) => {
            assert!(
                check::simplify(&case.mesh, &case.mesh, &judge).is_err(),
                "the task refuses the input ({e}) but the checker judges it"
            );
            return;
        }
    };
    let v = check::simplify(&case.mesh, &r.mesh, &judge)
        .unwrap_or_else(|e| panic!("the task accepts the input, the checker refuses it: {e}"));
    assert!(v.passed(), "the library's own answer fails: {v:?}");
    let mut faces = r.mesh.faces.clone();
    apply_edits(
        &mut faces,
        r.mesh.vertex_count as u32,
        input.edits.iter().take(CHECK_EDITS),
    );
    if faces == r.mesh.faces {
        return;
    }
    let pos = r.mesh.positions.clone().expect("simplify gives positions");
    let answer = contractible::TriMesh::with_positions(pos.clone(), faces);
    let v = check::simplify(&case.mesh, &answer, &judge).expect("an accepted input is judged");
    if !v.passed() {
        return;
    }
    assert_eq!(
        component_types(&answer),
        component_types(&case.mesh),
        "a passing answer changed the surfaces"
    );
    if opts.allow_foldover {
        let bound = r.eps * r.eps * (1.0 - 1e-9);
        let s = ConedSurfaces::from_mesh(&answer).expect("rebuilt above");
        for c in &s.components {
            for (a, b, _) in c.tri().edges() {
                if c.is_virtual(a) || c.is_virtual(b) {
                    continue;
                }
                let (x, y) = (
                    pos[c.vertex_origin[a.index()] as usize],
                    pos[c.vertex_origin[b.index()] as usize],
                );
                let d2: f64 = (0..3).map(|k| (x[k] - y[k]) * (x[k] - y[k])).sum();
                assert!(
                    !(d2 < bound && c.is_contractible(a, b)),
                    "a passing answer keeps a short contractible edge"
                );
            }
        }
    }
}

/// A `quad` answer judged by `check::quad`: the library's conversion of a surface grown
/// by vertex splits (any algorithm), with or without its statements (K, the pairs),
/// then edits of the quads.
#[derive(Arbitrary, Clone, Debug)]
pub struct CheckQuadInput {
    /// The input surface.
    pub base: SurfaceInput,
    /// The algorithm (mod the number of algorithms) and its seed.
    pub algorithm: u8,
    pub seed: u8,
    /// State K; state the pairs.
    pub state_k: bool,
    pub state_pairs: bool,
    /// `(quad, kind, value)` edits of the quads (at most [`CHECK_EDITS`]): swap two
    /// corners, set a corner to a vertex (maybe out of range), copy another quad, remove
    /// the quad, rotate it.
    pub edits: Vec<(u16, u8, u16)>,
}

/// `check::quad` on the library's conversion and on edited answers: never a panic; the
/// library's answer passes with its statements, and without them when K has the input's
/// triangles; and an answer that passes is confirmed by the core: with K built as a
/// `Triangulation`, each quad is two faces of K across one of its diagonals (found by the
/// core's edge lookup), and the faces so found are each of K's faces exactly once.
pub fn check_quad_check(input: &CheckQuadInput) {
    use contractible::check::{self, QuadCheck};
    use contractible::quad::Algorithm;
    let tri = build_surface(&input.base);
    let n = tri.vertex_capacity();
    let mesh = contractible::TriMesh::combinatorial(n, tri.face_list());
    let algorithm = Algorithm::ALL[usize::from(input.algorithm) % Algorithm::ALL.len()];
    let opts = contractible::QuadOptions {
        algorithm,
        seed: u64::from(input.seed),
        ..contractible::QuadOptions::default()
    };
    let r = contractible::quadrangulate(&mesh, &opts).expect("a closed surface converts");
    let full = QuadCheck {
        triangles: Some(&r.triangles),
        pairs: Some(&r.pairs),
    };
    let v = check::quad(&mesh, &r.mesh, &full).expect("a closed input is judged");
    assert!(v.passed(), "the library's answer fails: {v:?}");
    // Without K the quads are judged against the input's faces: they pass when K has the
    // input's triangles (a flip may also give a quad its original cycle back: LRS
    // pairing the two faces of an edge it flipped, so the converse does not hold).
    let bare = check::quad(&mesh, &r.mesh, &QuadCheck::default()).expect("judged");
    let triangle_set = |faces: &[[u32; 3]]| {
        let mut s: Vec<[u32; 3]> = faces
            .iter()
            .map(|f| {
                let mut t = *f;
                t.sort_unstable();
                t
            })
            .collect();
        s.sort_unstable();
        s
    };
    if triangle_set(&r.triangles) == triangle_set(&mesh.faces) {
        assert!(bare.passed(), "{bare:?}");
    }
    let stated = QuadCheck {
        triangles: input.state_k.then_some(r.triangles.as_slice()),
        pairs: (input.state_k && input.state_pairs).then_some(r.pairs.as_slice()),
    };
    let mut quads = r.mesh.faces.clone();
    for &(i, kind, value) in input.edits.iter().take(CHECK_EDITS) {
        if quads.is_empty() {
            break;
        }
        let i = usize::from(i) % quads.len();
        let k = usize::from(value) % 4;
        match kind % 5 {
            0 => quads[i].swap(k, (k + 1 + usize::from(kind / 5) % 3) % 4),
            1 => quads[i][k] = u32::from(value) % (n as u32 + 2),
            2 => quads[i] = quads[usize::from(value) % quads.len()],
            3 => {
                quads.remove(i);
            }
            _ => quads[i].rotate_left(1 + k % 3),
        }
    }
    let answer = contractible::QuadMesh {
        vertex_count: n,
        positions: None,
        faces: quads.clone(),
    };
    let v = check::quad(&mesh, &answer, &stated).expect("a closed input is judged");
    if !v.passed() {
        return;
    }
    let k_faces: &[[u32; 3]] = stated.triangles.unwrap_or(&mesh.faces);
    let k = Triangulation::from_faces(n, k_faces)
        .unwrap_or_else(|e| panic!("a passing answer's K is no closed surface: {e}"));
    assert_eq!(k.euler_characteristic(), tri.euler_characteristic());
    assert_eq!(k.is_orientable(), tri.is_orientable());
    let mut used = vec![0u32; k_faces.len()];
    let mut ambiguous = Vec::new();
    for q in &quads {
        let found: Vec<[usize; 2]> = [(0, 2), (1, 3)]
            .into_iter()
            .filter_map(|(a, b)| {
                let [c, d] = k.edge_corners(VertexId(q[a]), VertexId(q[b]))?;
                let others = [k.vertex(c).0, k.vertex(d).0];
                let (x, y) = (q[(a + 1) % 4], q[(a + 3) % 4]);
                (others == [x, y] || others == [y, x]).then(|| [c.face().index(), d.face().index()])
            })
            .collect();
        match found.as_slice() {
            [] => panic!("a passing quad {q:?} is not two faces of K"),
            [f] => f.iter().for_each(|&x| used[x] += 1),
            _ => ambiguous.push(found),
        }
    }
    for found in ambiguous {
        let f = found
            .iter()
            .find(|f| f.iter().all(|&x| used[x] == 0))
            .unwrap_or(&found[0]);
        f.iter().for_each(|&x| used[x] += 1);
    }
    assert!(
        used.iter().all(|&u| u == 1),
        "a passing answer does not use every face of K once: {used:?}"
    );
}

/// A `decimate` answer judged by `check::decimate`: the library's own run on a
/// [`DecimateInput`] case (any target, cap, placement, guard, locks, schedule), then
/// edits of the answer's faces and maps.
#[derive(Arbitrary, Clone, Debug)]
pub struct CheckDecimateInput {
    /// The input and the run's options.
    pub case: DecimateInput,
    /// State the maps.
    pub maps: bool,
    /// Edits of the answer's faces (at most [`CHECK_EDITS`]).
    pub edits: Vec<Edit>,
    /// `(map, index, value)` edits of the maps (at most [`CHECK_EDITS`]): vertex_map,
    /// collapse_map or face_origin (`map % 3`), entry `index` set to `value` (mod the
    /// map's range plus two).
    pub map_edits: Vec<(u8, u16, u16)>,
}

/// `check::decimate` on the library's own answer and on edited ones: never a panic; the
/// checker refuses exactly the inputs the task refuses; the library's answer passes,
/// with and without its maps; and an edited answer that passes is confirmed by the
/// core: rebuilt as a surface with boundary, it has the input's component types (χ,
/// orientability, boundary loops) as a multiset, at least the target (or the input's
/// count, if smaller) less one face,
/// and, for an unguarded, uncapped run without locks above its target, no edge that
/// passes the core's link condition of the surface with boundary.
pub fn check_decimate_check(input: &CheckDecimateInput) {
    use contractible::check::{self, DecimateCheck};
    use contractible::ConedSurfaces;
    type Maps<'a> = Option<(&'a [u32], &'a [u32], &'a [u32])>;
    fn judge<'a>(o: &'a contractible::DecimateOptions, maps: Maps<'a>) -> DecimateCheck<'a> {
        DecimateCheck {
            vertex_map: maps.map(|m| m.0),
            collapse_map: maps.map(|m| m.1),
            face_origin: maps.map(|m| m.2),
            ..DecimateCheck::of_run(o)
        }
    }
    let (mesh, o) = decimate_case(&input.case);
    let r = match contractible::decimate(&mesh, &o) {
        Ok(r) => r,
        Err(e) => {
            let refused = check::decimate(&mesh, &mesh, &judge(&o, None));
            // The checker validates what it reads (positions, faces, keep, locks); the
            // task also refuses a bad cap, which the checker does not evaluate.
            assert!(
                refused.is_err() || e.kind() == "bad_option",
                "the task refuses the input ({e}) but the checker judges it"
            );
            return;
        }
    };
    let full = (
        r.vertex_map.as_slice(),
        r.collapse_map.as_slice(),
        r.face_origin.as_slice(),
    );
    for maps in [Some(full), None] {
        let v = check::decimate(&mesh, &r.mesh, &judge(&o, maps))
            .unwrap_or_else(|e| panic!("the task accepts the input, the checker refuses it: {e}"));
        assert!(v.passed(), "the library's own answer fails: {v:?}");
    }
    let mut faces = r.mesh.faces.clone();
    apply_edits(
        &mut faces,
        r.mesh.vertex_count as u32,
        input.edits.iter().take(CHECK_EDITS),
    );
    let (mut vm, mut cm, mut fo) = (
        r.vertex_map.clone(),
        r.collapse_map.clone(),
        r.face_origin.clone(),
    );
    for &(which, i, value) in input.map_edits.iter().take(CHECK_EDITS) {
        let (map, range) = match which % 3 {
            0 => (&mut vm, mesh.vertex_count),
            1 => (&mut cm, r.mesh.vertex_count),
            _ => (&mut fo, mesh.faces.len()),
        };
        if map.is_empty() {
            continue;
        }
        let k = usize::from(i) % map.len();
        map[k] = u32::from(value) % (range as u32 + 2);
    }
    let edited_maps = (vm.as_slice(), cm.as_slice(), fo.as_slice());
    let pos = r.mesh.positions.clone().expect("decimate gives positions");
    let answer = contractible::TriMesh::with_positions(pos, faces);
    let v = check::decimate(
        &mesh,
        &answer,
        &judge(&o, input.maps.then_some(edited_maps)),
    )
    .expect("an accepted input is judged");
    if !v.passed() {
        return;
    }
    assert_eq!(
        component_types(&answer),
        component_types(&mesh),
        "a passing answer changed the surfaces"
    );
    let by_fraction = o
        .keep
        .map(|k| (k * mesh.faces.len() as f64).ceil() as usize);
    let target = match (o.faces, by_fraction) {
        (Some(a), Some(b)) => a.max(b),
        (a, b) => a.or(b).unwrap_or(0),
    };
    // A run stops at the first count at or below the target (an input already there
    // collapses nothing); a collapse removes at most two faces.
    assert!(
        answer.faces.len() + 1 >= target.min(mesh.faces.len()),
        "a passing answer has {} faces for a target of {target}",
        answer.faces.len()
    );
    let unlocked = o.locked.is_empty() && !o.lock_boundary;
    if answer.faces.len() > target && o.allow_foldover && o.max_error.is_none() && unlocked {
        let s = ConedSurfaces::from_mesh(&answer).expect("rebuilt above");
        for c in &s.components {
            for (a, b, _) in c.tri().edges() {
                assert!(
                    c.is_virtual(a) || c.is_virtual(b) || !c.is_contractible(a, b),
                    "a passing answer above its target keeps a contractible edge"
                );
            }
        }
    }
}
