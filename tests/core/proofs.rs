//! The bounded exhaustive tests of the Kani harnesses in `proofs/harnesses.rs`: the same
//! harness bodies, called for every value of their bounded input instead of a symbolic
//! one. These tests are what has run; the harnesses themselves have not been run under
//! Kani (see `proofs/README.md` for what that needs).
//!
//! - every one of the 57 closed surfaces with at most 8 vertices
//!   (`proofs/surfaces.rs`, generated from `tests/data/irreducible/surfaces-upto-8-vertices.txt`
//!   and checked against it by `surfaces_table_matches_the_published_list`), every edge in both
//!   directions, every (trapped vertex, contractible edge) pair for Lemma 5, every
//!   degree-3 vertex for Prop. 6, every ordered pair of edges for Prop. 7;
//! - every maximal contraction sequence from each of the 57 surfaces (DFS, memoised on the
//!   exact labelled state, so every sequence is covered once per distinct state), with
//!   contract/undo identity at each step and irreducibility of every leaf;
//! - every sequence of one or two vertex splits of T4, the 7-vertex torus and the
//!   6-vertex projective plane.
//!
//! Each test prints how many cases it covered and asserts a lower bound on the number of
//! non-vacuous ones, so it cannot silently cover nothing.

use crate::common;
use crate::{harnesses, surfaces};

use std::collections::{BTreeSet, HashMap};

use contractible::gen::{projective_plane6, tetrahedron, torus7};
use contractible::irreducible::reduce;
use contractible::{History, LinkTester, Triangulation, VertexId};
use harnesses::Prop7Case;
use surfaces::SURFACES;

// ---- The embedded surface table.

const SURFACES_FILE: &str = "surfaces-upto-8-vertices.txt";

/// The text `proofs/surfaces.rs` must have, rendered from the published list.
fn render_surfaces_table() -> String {
    let list = common::read_surface_list(SURFACES_FILE);
    let mut s = String::new();
    s.push_str(
        "//! GENERATED FILE: do not edit. The closed triangulated surfaces with at most 8\n\
         //! vertices of `tests/data/irreducible/surfaces-upto-8-vertices.txt`, one entry per line\n\
         //! of that file in order, embedded for the Kani harnesses of `proofs/harnesses.rs`.\n\
         //!\n\
         //! Regenerate with\n\
         //! `CONTRACTIBLE_REGEN_SURFACES=1 cargo test --test core surfaces_table_matches_the_published_list`;\n\
         //! without the variable that test fails if this file and the list differ.\n\
         #![allow(dead_code)]\n\
         \n\
         use contractible::Triangulation;\n\
         \n\
         /// One embedded surface: its name in the list and its faces.\n\
         pub struct SmallSurface {\n    \
             /// `SURFACE_nV_irr_K` or `SURFACE_nV_red_K` (see `tests/data/irreducible/README.md`).\n    \
             pub name: &'static str,\n    \
             /// Vertices `0..vertex_count`.\n    \
             pub vertex_count: usize,\n    \
             /// The triangles.\n    \
             pub faces: &'static [[u32; 3]],\n\
         }\n\
         \n\
         impl SmallSurface {\n    \
             /// The triangulation (the list is known valid: this cannot fail).\n    \
             pub fn triangulation(&self) -> Triangulation {\n        \
                 Triangulation::from_faces(self.vertex_count, self.faces).expect(\"embedded surface\")\n    \
             }\n\
         }\n\
         \n",
    );
    s.push_str(&format!(
        "/// The {} surfaces.\n#[rustfmt::skip]\npub const SURFACES: [SmallSurface; {}] = [\n",
        list.len(),
        list.len()
    ));
    for n in &list {
        let faces: Vec<String> = n
            .faces
            .iter()
            .map(|f| format!("[{},{},{}]", f[0], f[1], f[2]))
            .collect();
        s.push_str(&format!(
            "    SmallSurface {{ name: {:?}, vertex_count: {}, faces: &[{}] }},\n",
            n.name,
            n.vertex_count,
            faces.join(",")
        ));
    }
    s.push_str("];\n");
    s
}

#[test]
fn surfaces_table_matches_the_published_list() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/proofs/surfaces.rs");
    let want = render_surfaces_table();
    if std::env::var_os("CONTRACTIBLE_REGEN_SURFACES").is_some() {
        std::fs::write(path, &want).expect("write proofs/surfaces.rs");
    }
    let have = std::fs::read_to_string(path).expect("read proofs/surfaces.rs");
    assert!(
        have == want,
        "proofs/surfaces.rs differs from {SURFACES_FILE}: regenerate it \
         (CONTRACTIBLE_REGEN_SURFACES=1 cargo test --test core surfaces_table_matches_the_published_list)"
    );
    // And the compiled table is what the file says.
    let list = common::read_surface_list(SURFACES_FILE);
    assert_eq!(SURFACES.len(), 57);
    assert_eq!(list.len(), SURFACES.len());
    for (s, n) in SURFACES.iter().zip(&list) {
        assert_eq!(s.name, n.name);
        assert_eq!(s.vertex_count, n.vertex_count);
        assert_eq!(s.faces, &n.faces[..]);
        s.triangulation().validate().unwrap();
    }
}

fn small_surfaces() -> Vec<(&'static str, Triangulation)> {
    SURFACES
        .iter()
        .map(|s| (s.name, s.triangulation()))
        .collect()
}

// ---- Canonical forms (isomorphism classes, mirror images identified).

/// A canonical form of a small triangulation's face set: the lexicographically least
/// relabelled sorted face list over all 6F starting flags, where from a flag `(a, b, c)`
/// (a face in one of its 6 vertex orders, labelled 0, 1, 2) the labelling grows
/// deterministically: among the edges of fully labelled faces whose other face has an
/// unlabelled third vertex, take the edge with the least label pair and label that
/// vertex next. Isomorphic triangulations get equal forms; two faces sharing an edge
/// make the growth reach every vertex of a connected surface.
fn canonical(faces: &[[u32; 3]]) -> Vec<[u32; 3]> {
    let n = faces.iter().flatten().max().map_or(0, |&m| m as usize + 1);
    let mut edge_faces: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for (p, q) in [(f[0], f[1]), (f[1], f[2]), (f[0], f[2])] {
            edge_faces.entry((p.min(q), p.max(q))).or_default().push(i);
        }
    }
    let mut best: Option<Vec<[u32; 3]>> = None;
    const NONE: u32 = u32::MAX;
    // Only flags starting at a vertex of least degree (an isomorphism-invariant choice).
    let mut degree = vec![0usize; n];
    for f in faces {
        for &z in f {
            degree[z as usize] += 1; // faces at z = degree of z
        }
    }
    let min_degree = faces
        .iter()
        .flatten()
        .map(|&z| degree[z as usize])
        .min()
        .unwrap_or(0);
    for f in faces {
        for perm in [
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ] {
            if degree[f[perm[0]] as usize] != min_degree {
                continue;
            }
            let mut label = vec![NONE; n];
            for (k, &p) in perm.iter().enumerate() {
                label[f[p] as usize] = k as u32;
            }
            let mut next = 3;
            loop {
                let mut cand: Option<((u32, u32), u32)> = None;
                for g in faces {
                    if g.iter().any(|&z| label[z as usize] == NONE) {
                        continue;
                    }
                    for (p, q) in [(g[0], g[1]), (g[1], g[2]), (g[0], g[2])] {
                        for &h in &edge_faces[&(p.min(q), p.max(q))] {
                            let r = faces[h]
                                .into_iter()
                                .find(|&z| z != p && z != q)
                                .expect("triangle");
                            if label[r as usize] == NONE {
                                let (lp, lq) = (label[p as usize], label[q as usize]);
                                let key = (lp.min(lq), lp.max(lq));
                                if cand.is_none_or(|(k, _)| key < k) {
                                    cand = Some((key, r));
                                }
                            }
                        }
                    }
                }
                match cand {
                    Some((_, r)) => {
                        label[r as usize] = next;
                        next += 1;
                    }
                    None => break,
                }
            }
            let mut g: Vec<[u32; 3]> = faces
                .iter()
                .map(|f| {
                    let mut h = f.map(|z| label[z as usize]);
                    h.sort_unstable();
                    h
                })
                .collect();
            assert!(g.iter().flatten().all(|&z| z != NONE), "disconnected input");
            g.sort_unstable();
            if best.as_ref().is_none_or(|b| g < *b) {
                best = Some(g);
            }
        }
    }
    best.unwrap_or_default()
}

#[test]
fn canonical_form_separates_exactly_the_isomorphism_classes() {
    // The 57 small surfaces are pairwise non-isomorphic, as are the published lists; a
    // random relabelling of each keeps its form.
    let mut lists: Vec<Vec<[u32; 3]>> = SURFACES.iter().map(|s| s.faces.to_vec()).collect();
    lists.extend(
        common::read_surface_list("torus.txt")
            .into_iter()
            .map(|s| s.faces),
    );
    lists.extend(
        common::read_surface_list("projective-plane.txt")
            .into_iter()
            .map(|s| s.faces),
    );
    let forms: Vec<_> = lists.iter().map(|f| canonical(f)).collect();
    let distinct: BTreeSet<_> = forms.iter().collect();
    // 57 + 21 + 2, minus the entries of the small list that reappear in the published
    // ones (the 7-vertex torus, 8-vertex irreducible tori, 6/7-vertex RP²): each such
    // coincidence must be a true isomorphism.
    for i in 0..lists.len() {
        for j in i + 1..lists.len() {
            if forms[i] == forms[j] {
                assert!(common::is_isomorphic(&lists[i], &lists[j]), "{i} ~ {j}");
            }
        }
    }
    let mut rng = contractible::rng::Rng::new(5);
    for (f, form) in lists.iter().zip(&forms) {
        let n = f.iter().flatten().max().unwrap() + 1;
        let mut perm: Vec<u32> = (0..n).collect();
        rng.shuffle(&mut perm);
        let g: Vec<[u32; 3]> = f
            .iter()
            .map(|t| {
                [
                    perm[t[2] as usize],
                    perm[t[0] as usize],
                    perm[t[1] as usize],
                ]
            })
            .collect();
        assert_eq!(&canonical(&g), form);
    }
    println!(
        "canonical forms: {} lists, {} classes",
        lists.len(),
        distinct.len()
    );
    assert!(distinct.len() >= 57 + 21 + 2 - 8);
}

// ---- Bounded exhaustive tests over the 57 surfaces.

#[test]
fn exhaustive_link_conditions_agree_and_theorem3() {
    let (mut cases, mut contractible) = (0, 0);
    for (name, t) in small_surfaces() {
        for e in 0..t.edge_count() {
            let a = harnesses::link_conditions_agree(&t, e);
            let b = harnesses::theorem3(&t, e);
            assert_eq!(a, b, "{name} edge {e}");
            cases += 1;
            contractible += a as usize;
        }
    }
    println!("link conditions / Theorem 3: {cases} edges, {contractible} contractible");
    assert!(cases >= 900 && contractible >= 200);
}

#[test]
fn exhaustive_contract_then_split_is_identity() {
    let (mut cases, mut contracted) = (0, 0);
    for (_, t) in small_surfaces() {
        for e in 0..t.edge_count() {
            for dir in [false, true] {
                contracted += harnesses::contract_then_split_is_identity(&t, e, dir) as usize;
                cases += 1;
            }
        }
    }
    println!("contract/split/undo: {cases} directed edges, {contracted} contracted");
    assert!(cases >= 1800 && contracted >= 400);
}

#[test]
fn exhaustive_lemma5_trapped_stays_trapped() {
    let (mut cases, mut applicable) = (0, 0);
    for (_, t) in small_surfaces() {
        for w in 0..t.vertex_count() {
            for e in 0..t.edge_count() {
                applicable += harnesses::lemma5_trapped_stays_trapped(&t, w, e) as usize;
                cases += 1;
            }
        }
    }
    println!(
        "Lemma 5: {cases} (vertex, edge) pairs, {applicable} with w trapped and e contractible"
    );
    assert!(cases >= 5000 && applicable >= 10);
}

#[test]
fn exhaustive_prop6_degree3_edges_contractible_unless_t4() {
    let (mut cases, mut degree3) = (0, 0);
    for (_, t) in small_surfaces() {
        for v in 0..t.vertex_count() {
            degree3 += harnesses::prop6_degree3_edges_contractible_unless_t4(&t, v) as usize;
            cases += 1;
        }
    }
    println!("Proposition 6: {cases} vertices, {degree3} of degree 3");
    assert!(cases >= 400 && degree3 >= 20);
}

#[test]
fn exhaustive_prop7() {
    let (mut cases, mut stays, mut became) = (0, 0, 0);
    for (_, t) in small_surfaces() {
        for f in 0..t.edge_count() {
            for e in 0..t.edge_count() {
                match harnesses::prop7(&t, f, e) {
                    Prop7Case::Vacuous => {}
                    Prop7Case::Stays => stays += 1,
                    Prop7Case::Became => became += 1,
                }
                cases += 1;
            }
        }
    }
    println!("Proposition 7: {cases} (f, e) pairs, {stays} stay non-contractible, {became} become contractible");
    assert!(cases >= 15000 && stays >= 100 && became >= 10);
}

#[test]
fn exhaustive_rs_output_irreducible() {
    let mut cases = 0;
    for (_, t) in small_surfaces() {
        harnesses::rs_output_irreducible(&t);
        cases += 1;
    }
    println!("RS output irreducible: {cases} surfaces");
    assert_eq!(cases, 57);
}

// ---- Every maximal contraction sequence.

/// The exact labelled state: corner slots (face list in id order) and each vertex's
/// stored corner. With the simplicial invariants, this determines the whole corner table,
/// so two equal keys behave identically under every further contraction.
type StateKey = (Vec<[u32; 3]>, Vec<u32>);

fn state_key(t: &Triangulation) -> StateKey {
    (
        t.face_list(),
        t.vertices().map(|v| t.corner_of(v).0).collect(),
    )
}

#[derive(Default, Debug)]
struct SeqStats {
    states: u64,
    memo_hits: u64,
    contractions: u64,
    refusals: u64,
    leaves: u64,
}

/// What a leaf must be isomorphic to, per surface code.
struct Leaves {
    published: HashMap<&'static str, Vec<Vec<[u32; 3]>>>,
    seen: HashMap<Vec<[u32; 3]>, ()>,
}

impl Leaves {
    fn new() -> Self {
        let mut published = HashMap::new();
        let t4 = vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
        published.insert("S0", vec![t4]);
        let list = |f: &str| -> Vec<Vec<[u32; 3]>> {
            common::read_surface_list(f)
                .into_iter()
                .map(|s| s.faces)
                .collect()
        };
        published.insert("S1", list("torus.txt"));
        published.insert("N1", list("projective-plane.txt"));
        // Every N2 surface with <= 8 vertices is irreducible (`tests/data/irreducible/README.md`).
        let n2: Vec<Vec<[u32; 3]>> = SURFACES
            .iter()
            .filter(|s| s.name.starts_with("N2"))
            .map(|s| s.faces.to_vec())
            .collect();
        published.insert("N2", n2);
        Leaves {
            published,
            seen: HashMap::new(),
        }
    }

    fn check(&mut self, code: &'static str, t: &Triangulation) {
        let faces = t.face_list();
        let form = canonical(&faces);
        if self.seen.contains_key(&form) {
            return;
        }
        let list = &self.published[code];
        assert!(
            list.iter().any(|p| common::is_isomorphic(&faces, p)),
            "{code}: irreducible leaf {faces:?} is not isomorphic to a published one"
        );
        self.seen.insert(form, ());
    }
}

/// DFS over every contraction in both directions from `t`; returns the number of
/// maximal sequences from this state. The history `h` is shared down the recursion, so
/// each undo pops the newest of a stack of records.
fn explore(
    t: &mut Triangulation,
    h: &mut History,
    code: &'static str,
    memo: &mut HashMap<StateKey, u128>,
    stats: &mut SeqStats,
    leaves: &mut Leaves,
) -> u128 {
    let key = state_key(t);
    if let Some(&n) = memo.get(&key) {
        stats.memo_hits += 1;
        return n;
    }
    stats.states += 1;
    let chi = t.euler_characteristic();
    let orientable = t.is_orientable();
    let depth = h.len();
    let edges: Vec<(VertexId, VertexId)> = t.edges().map(|(a, b, _)| (a, b)).collect();
    let mut sequences = 0u128;
    let mut any = false;
    for (a, b) in edges {
        for (u, v) in [(a, b), (b, a)] {
            let before = t.clone();
            let naive = t.link_condition_naive(u, v);
            match t.contract(u, v, h) {
                Ok(_) => {
                    assert!(naive, "contracted non-contractible [{u}, {v}]");
                    any = true;
                    stats.contractions += 1;
                    assert_eq!(h.len(), depth + 1);
                    t.validate().unwrap_or_else(|e| panic!("[{u}, {v}]: {e}"));
                    assert_eq!(t.euler_characteristic(), chi);
                    assert_eq!(t.is_orientable(), orientable);
                    sequences += explore(t, h, code, memo, stats, leaves);
                    let rec = h.undo(t).expect("record");
                    assert_eq!((rec.u, rec.v), (u, v));
                    assert_eq!(h.len(), depth);
                    assert!(*t == before, "undo of [{u}, {v}] is not the identity");
                }
                Err(_) => {
                    assert!(!naive, "refused contractible [{u}, {v}]");
                    stats.refusals += 1;
                    assert!(*t == before);
                }
            }
        }
    }
    if !any {
        assert!(t.is_irreducible_naive() && t.is_irreducible());
        leaves.check(code, t);
        stats.leaves += 1;
        sequences = 1;
    }
    memo.insert(key, sequences);
    sequences
}

#[test]
fn every_contraction_sequence_undoes_exactly_and_ends_irreducible() {
    let mut stats = SeqStats::default();
    let mut leaves = Leaves::new();
    let mut total_sequences = 0u128;
    for s in SURFACES.iter() {
        let code: &'static str = &s.name[..2];
        let mut t = s.triangulation();
        let start = t.clone();
        let mut h = History::new();
        let mut memo = HashMap::new();
        let n = explore(&mut t, &mut h, code, &mut memo, &mut stats, &mut leaves);
        assert!(t == start && h.is_empty());
        if s.name.contains("_irr_") {
            assert_eq!(n, 1, "{}: irreducible, one empty sequence", s.name);
        } else {
            assert!(n > 1, "{}: reducible", s.name);
        }
        total_sequences += n;
    }
    println!(
        "contraction sequences: {total_sequences} maximal sequences over {} distinct labelled \
         states ({} memo hits), {} contractions undone, {} refusals, {} leaves, {} leaf classes",
        stats.states,
        stats.memo_hits,
        stats.contractions,
        stats.refusals,
        stats.leaves,
        leaves.seen.len()
    );
    assert!(total_sequences >= 1000 && stats.states >= 500 && stats.contractions >= 1000);
}

// ---- Every sequence of one or two vertex splits of the three seed surfaces.

#[derive(Default, Debug)]
struct SplitStats {
    results: u64,
    classes: u64,
    edge_checks: u64,
    lemma5: u64,
    prop6: u64,
    prop7_became: u64,
}

/// Checks every split result; the per-isomorphism-class checks (Lemma 5, Prop. 6,
/// Prop. 7, the three reductions) run once per class.
struct SplitChecker {
    base_chi: i64,
    base_orientable: bool,
    published: Vec<Vec<[u32; 3]>>,
    classes: BTreeSet<Vec<[u32; 3]>>,
    stats: SplitStats,
}

impl SplitChecker {
    fn check(&mut self, t: &Triangulation, u: VertexId, w: VertexId) {
        self.stats.results += 1;
        t.validate().unwrap();
        assert_eq!(t.euler_characteristic(), self.base_chi, "χ");
        assert_eq!(t.is_orientable(), self.base_orientable, "orientability");
        assert!(
            t.link_condition_naive(u, w),
            "the split edge [{u}, {w}] is contractible"
        );
        // Layout-dependent checks on every result (the corner layout differs between
        // results of the same class): the marked link test against the naive one, and
        // contract + undo == identity on every edge in both directions.
        let mut tester = LinkTester::new(t.vertex_capacity());
        let mut work = t.clone();
        let mut h = History::new();
        for a in t.vertices() {
            tester.mark(t, a);
            for b in t.link(a) {
                let naive = t.link_condition_naive(a, b);
                assert_eq!(tester.test_marked(t, a, b), naive, "[{a}, {b}]");
                if work.contract(a, b, &mut h).is_ok() {
                    assert!(naive, "contracted [{a}, {b}]");
                    h.undo(&mut work).expect("record");
                    assert!(work == *t, "contract/undo [{a}, {b}]");
                } else {
                    assert!(!naive, "refused [{a}, {b}]");
                }
                self.stats.edge_checks += 1;
            }
        }
        // Isomorphism-invariant statements (and the full harnesses) once per class.
        // Isomorphism-invariant statements once per class.
        if !self.classes.insert(canonical(&t.face_list())) {
            return;
        }
        self.stats.classes += 1;
        for e in 0..t.edge_count() {
            harnesses::theorem3(t, e);
            harnesses::link_conditions_agree(t, e);
            harnesses::contract_then_split_is_identity(t, e, false);
            harnesses::contract_then_split_is_identity(t, e, true);
            for w in 0..t.vertex_count() {
                self.stats.lemma5 += harnesses::lemma5_trapped_stays_trapped(t, w, e) as u64;
            }
            for f in 0..t.edge_count() {
                self.stats.prop7_became += (harnesses::prop7(t, f, e) == Prop7Case::Became) as u64;
            }
        }
        for v in 0..t.vertex_count() {
            self.stats.prop6 += harnesses::prop6_degree3_edges_contractible_unless_t4(t, v) as u64;
        }
        harnesses::rs_output_irreducible(t);
        for alg in common::ALL {
            let r = reduce(t.clone(), alg, &common::options(7));
            common::check(t, &r, alg, "split result");
            let faces = r.tri.face_list();
            assert!(
                self.published
                    .iter()
                    .any(|p| common::is_isomorphic(&faces, p)),
                "{}: output {faces:?} not isomorphic to a published irreducible triangulation",
                alg.name()
            );
        }
    }
}

/// Every split `(u, x, y)`: every live vertex, every ordered pair of distinct link
/// vertices (the two orders move complementary sides of the link).
fn all_splits(t: &Triangulation) -> Vec<(VertexId, VertexId, VertexId)> {
    let mut out = Vec::new();
    for u in t.vertices() {
        let link: Vec<VertexId> = t.link(u).collect();
        for &x in &link {
            for &y in &link {
                if x != y {
                    out.push((u, x, y));
                }
            }
        }
    }
    out
}

fn split_sequences(name: &str, base: Triangulation, published: Vec<Vec<[u32; 3]>>) -> SplitStats {
    let mut c = SplitChecker {
        base_chi: base.euler_characteristic(),
        base_orientable: base.is_orientable(),
        published,
        classes: BTreeSet::new(),
        stats: SplitStats::default(),
    };
    for (u, x, y) in all_splits(&base) {
        let mut t1 = base.clone();
        let w1 = t1.split_vertex(u, x, y).expect("valid split");
        c.check(&t1, u, w1);
        for (u2, x2, y2) in all_splits(&t1) {
            let mut t2 = t1.clone();
            let w2 = t2.split_vertex(u2, x2, y2).expect("valid split");
            c.check(&t2, u2, w2);
        }
    }
    println!("{name}: {:?}", c.stats);
    c.stats
}

#[test]
fn split_sequences_of_the_tetrahedron() {
    let t4 = vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]];
    let base = Triangulation::from_faces(4, &tetrahedron().faces).unwrap();
    let s = split_sequences("T4", base, vec![t4]);
    // 4 vertices x 6 ordered pairs, then every split of each 5-vertex result.
    assert!(s.results >= 24 + 24 * 40, "{s:?}");
    assert!(
        s.classes >= 3 && s.prop6 >= 4 && s.prop7_became >= 1,
        "{s:?}"
    );
}

#[test]
fn split_sequences_of_the_torus7() {
    let base = Triangulation::from_faces(7, &torus7().faces).unwrap();
    let published = common::read_surface_list("torus.txt")
        .into_iter()
        .map(|s| s.faces)
        .collect();
    let s = split_sequences("torus7", base, published);
    assert!(s.results >= 210 + 210 * 200, "{s:?}");
    assert!(
        s.classes >= 10 && s.lemma5 >= 10 && s.prop7_became >= 1,
        "{s:?}"
    );
}

#[test]
fn split_sequences_of_the_projective_plane6() {
    let base = Triangulation::from_faces(6, &projective_plane6().faces).unwrap();
    let published = common::read_surface_list("projective-plane.txt")
        .into_iter()
        .map(|s| s.faces)
        .collect();
    let s = split_sequences("RP2_6", base, published);
    assert!(s.results >= 120 + 120 * 100, "{s:?}");
    assert!(
        s.classes >= 5 && s.lemma5 >= 5 && s.prop7_became >= 1,
        "{s:?}"
    );
}
