//! Kani harnesses: the harness bodies.
//!
//! Each `pub fn` here is the body of one Kani harness, written as a plain function of its
//! bounded input (a small triangulation and a few indices), so that the same statement
//! runs two ways:
//!
//! - under Kani (`#[cfg(kani)]` entry points at the bottom of this file), where the
//!   surface is chosen by `kani::any()` among the 57 embedded surfaces of
//!   [`crate::surfaces::SURFACES`] and the indices are symbolic;
//! - under `cargo test --test core proofs::`, whose bounded exhaustive tests call the same
//!   function for every value of the bounded input (see `tests/core/proofs.rs`).
//!
//! Every statement is checked against references that share no logic with the code under
//! test beyond the vertex-link walk: the naive link condition (by definition,
//! O(d_u·d_v)), the critical cycles of `spec::oracle`, and the face set itself (critical
//! cycles recounted here from the face list alone, [`critical_cycles_from_faces`]).
//!
//! Each body returns whether its hypothesis held, so the exhaustive tests can count the
//! cases in which the statement had content (a test that only ever meets vacuous cases
//! fails).
#![allow(dead_code)]

use std::collections::BTreeSet;

use contractible::irreducible::{reduce, Algorithm, Options};
use contractible::spec::oracle::{
    contractible_by_theorem_3, critical_cycles_through, is_trapped_naive,
};
use contractible::{ContractError, History, LinkTester, Triangulation, VertexId};

/// The `e`-th edge of [`Triangulation::edges`] as `(a, b)` with `a < b`.
pub fn nth_edge(t: &Triangulation, e: usize) -> (VertexId, VertexId) {
    t.edges()
        .nth(e)
        .map(|(a, b, _)| (a, b))
        .unwrap_or_else(|| panic!("edge index {e} out of range ({})", t.edge_count()))
}

/// The `i`-th live vertex.
pub fn nth_vertex(t: &Triangulation, i: usize) -> VertexId {
    t.vertices()
        .nth(i)
        .unwrap_or_else(|| panic!("vertex index {i} out of range ({})", t.vertex_count()))
}

/// The face set as sorted triples.
pub fn face_set(t: &Triangulation) -> BTreeSet<[u32; 3]> {
    t.face_list()
        .into_iter()
        .map(|mut f| {
            f.sort_unstable();
            f
        })
        .collect()
}

/// The face set with vertex `from` renamed `to`, faces containing both dropped.
fn renamed(faces: &BTreeSet<[u32; 3]>, from: VertexId, to: VertexId) -> BTreeSet<[u32; 3]> {
    faces
        .iter()
        .filter(|f| !(f.contains(&from.0) && f.contains(&to.0)))
        .map(|f| {
            let mut g = f.map(|z| if z == from.0 { to.0 } else { z });
            g.sort_unstable();
            g
        })
        .collect()
}

/// The edge set (sorted pairs) of a face set.
fn edge_set(faces: &BTreeSet<[u32; 3]>) -> BTreeSet<(u32, u32)> {
    faces
        .iter()
        .flat_map(|&[a, b, c]| [(a, b), (a, c), (b, c)])
        .collect()
}

/// Whether the face set is T4 (4 vertices, 4 faces), from the face list alone.
pub fn is_t4_from_faces(faces: &BTreeSet<[u32; 3]>) -> bool {
    let vs: BTreeSet<u32> = faces.iter().flatten().copied().collect();
    vs.len() == 4 && faces.len() == 4
}

/// Critical 3-cycles through `[a, b]` counted from the face list alone: vertices `z`
/// adjacent to both with `{a, b, z}` not a face (RS Sec. 2).
pub fn critical_cycles_from_faces(faces: &BTreeSet<[u32; 3]>, a: VertexId, b: VertexId) -> usize {
    let edges = edge_set(faces);
    let adj = |p: u32, q: u32| edges.contains(&(p.min(q), p.max(q)));
    let vs: BTreeSet<u32> = faces.iter().flatten().copied().collect();
    vs.into_iter()
        .filter(|&z| z != a.0 && z != b.0 && adj(a.0, z) && adj(b.0, z))
        .filter(|&z| {
            let mut f = [a.0, b.0, z];
            f.sort_unstable();
            !faces.contains(&f)
        })
        .count()
}

/// Whether the triple is a critical cycle of `t` (a 3-cycle that bounds no face).
fn is_critical_cycle(t: &Triangulation, c: [VertexId; 3]) -> bool {
    let [p, q, r] = c;
    if p == q || q == r || p == r {
        return false;
    }
    if !(t.has_edge(p, q) && t.has_edge(q, r) && t.has_edge(p, r)) {
        return false;
    }
    let mut f = [p.0, q.0, r.0];
    f.sort_unstable();
    !face_set(t).contains(&f)
}

/// **Link conditions agree.** For edge `e`, in both directions: the naive link condition
/// (by definition), the per-call marked test (`is_contractible`), the marked
/// `LinkTester` (mark once, test in O(d_v)) and the Theorem 3 oracle all give the same
/// answer. Returns that answer.
pub fn link_conditions_agree(t: &Triangulation, e: usize) -> bool {
    let (a, b) = nth_edge(t, e);
    let naive = t.link_condition_naive(a, b);
    assert_eq!(
        naive,
        t.link_condition_naive(b, a),
        "naive not symmetric on {a}-{b}"
    );
    assert_eq!(naive, t.is_contractible(a, b), "is_contractible({a},{b})");
    assert_eq!(naive, t.is_contractible(b, a), "is_contractible({b},{a})");
    let mut tester = LinkTester::new(t.vertex_capacity());
    tester.mark(t, a);
    assert_eq!(naive, tester.test_marked(t, a, b), "test_marked({a},{b})");
    tester.mark(t, b);
    assert_eq!(naive, tester.test_marked(t, b, a), "test_marked({b},{a})");
    assert_eq!(naive, tester.test(t, a, b), "LinkTester::test({a},{b})");
    assert_eq!(
        naive,
        contractible_by_theorem_3(t, a, b),
        "Theorem 3 oracle on {a}-{b}"
    );
    naive
}

/// **Theorem 3.** `[a, b]` satisfies the link condition iff it lies on no critical cycle
/// and the surface is not T4. Critical cycles are counted twice, by `spec::oracle` and
/// from the face list alone, and must agree. Returns whether the edge is contractible.
pub fn theorem3(t: &Triangulation, e: usize) -> bool {
    let (a, b) = nth_edge(t, e);
    let faces = face_set(t);
    let cc = critical_cycles_from_faces(&faces, a, b);
    assert_eq!(
        critical_cycles_through(t, a, b),
        Some(cc),
        "critical cycles through {a}-{b}"
    );
    let t4 = is_t4_from_faces(&faces);
    assert_eq!(t4, t.is_tetrahedron(), "is_tetrahedron");
    let naive = t.link_condition_naive(a, b);
    assert_eq!(
        naive,
        cc == 0 && !t4,
        "Theorem 3 on {a}-{b}: link condition {naive}, {cc} critical cycles, T4 {t4}"
    );
    naive
}

/// **Contraction is exactly undone; a split inverts it.** Contract edge `e` (keeping the
/// smaller endpoint, or the larger if `direction`). If the edge fails the link
/// condition, `contract` must refuse with `NotContractible` and change nothing.
/// Otherwise: the result is valid, has one vertex and two faces fewer, the same χ and
/// orientability, exactly the face set predicted (faces of `v` renamed to `u`, the two
/// faces of the edge gone), the predicted degrees; `split_vertex(u, x, y)` or
/// `split_vertex(u, y, x)` restores the face set with `v` renamed to the new vertex; and
/// `History::undo` restores the triangulation exactly (`==`). Returns whether it
/// contracted.
pub fn contract_then_split_is_identity(t: &Triangulation, e: usize, direction: bool) -> bool {
    let (a, b) = nth_edge(t, e);
    let (u, v) = if direction { (b, a) } else { (a, b) };
    let before = t.clone();
    let faces_in = face_set(t);
    let contractible = t.link_condition_naive(u, v);
    let mut work = t.clone();
    let mut history = History::new();
    match work.contract(u, v, &mut history) {
        Err(err) => {
            assert!(
                !contractible,
                "contract({u},{v}) refused a contractible edge"
            );
            assert_eq!(err, ContractError::NotContractible { u, v });
            assert_eq!(
                work, before,
                "a refused contraction changed the triangulation"
            );
            assert!(history.is_empty());
            false
        }
        Ok(rec) => {
            assert!(
                contractible,
                "contract({u},{v}) accepted a non-contractible edge"
            );
            assert_eq!((rec.u, rec.v), (u, v));
            let [x, y] = rec.link;
            let link: BTreeSet<VertexId> = t.edge_link(u, v).expect("edge").into_iter().collect();
            assert_eq!(link, [x, y].into_iter().collect(), "record link");
            work.validate()
                .unwrap_or_else(|err| panic!("contract({u},{v}): {err}"));
            assert!(!work.is_vertex(v) && work.is_vertex(u));
            assert_eq!(work.vertex_count() + 1, t.vertex_count());
            assert_eq!(work.face_count() + 2, t.face_count());
            assert_eq!(work.euler_characteristic(), t.euler_characteristic());
            assert_eq!(work.is_orientable(), t.is_orientable());
            assert_eq!(face_set(&work), renamed(&faces_in, v, u), "face set");
            assert_eq!(work.degree(u), t.degree(u) + t.degree(v) - 4);
            assert_eq!(work.degree(x) + 1, t.degree(x));
            assert_eq!(work.degree(y) + 1, t.degree(y));

            // A vertex split along {x, y} (one of the two sides) is the inverse.
            let mut inverted = 0;
            for (p, q) in [(x, y), (y, x)] {
                let mut s = work.clone();
                let w = s.split_vertex(u, p, q).expect("x, y are neighbours of u");
                s.validate()
                    .unwrap_or_else(|err| panic!("split_vertex({u},{p},{q}): {err}"));
                assert_eq!(s.vertex_count(), t.vertex_count());
                assert_eq!(s.euler_characteristic(), t.euler_characteristic());
                assert!(
                    s.link_condition_naive(u, w),
                    "split edge fails the link condition"
                );
                // w is new, so no face holds both v and w: a pure renaming.
                if face_set(&s) == renamed(&faces_in, v, w) {
                    inverted += 1;
                }
            }
            assert_eq!(
                inverted, 1,
                "exactly one side of the split inverts contract({u},{v})"
            );

            let undone = history.undo(&mut work).expect("one record");
            assert_eq!(undone, rec);
            assert!(history.is_empty());
            assert_eq!(
                work, before,
                "undo after contract({u},{v}) is not the identity"
            );
            true
        }
    }
}

/// **Lemma 5.** If vertex `w` is trapped (no edge at it is contractible) and edge `e` is
/// contractible, then `w` is still trapped after contracting `e` (either way round).
/// Returns whether the hypothesis held.
pub fn lemma5_trapped_stays_trapped(
    t: &Triangulation,
    trapped_vertex: usize,
    contractible_edge: usize,
) -> bool {
    let w = nth_vertex(t, trapped_vertex);
    let (a, b) = nth_edge(t, contractible_edge);
    if !is_trapped_naive(t, w) || !t.link_condition_naive(a, b) {
        return false;
    }
    assert!(a != w && b != w, "a trapped vertex has a contractible edge");
    for (u, v) in [(a, b), (b, a)] {
        let mut k = t.clone();
        k.contract(u, v, &mut History::new())
            .expect("naively contractible");
        assert!(k.is_vertex(w));
        assert!(
            is_trapped_naive(&k, w),
            "Lemma 5: trapped {w} is loose after contracting [{u}, {v}]"
        );
    }
    true
}

/// **Proposition 6.** If `v` has degree 3: on T4 no edge is contractible, otherwise every
/// edge at `v` is. Returns whether `v` has degree 3.
pub fn prop6_degree3_edges_contractible_unless_t4(t: &Triangulation, v: usize) -> bool {
    let v = nth_vertex(t, v);
    if t.degree(v) != 3 {
        return false;
    }
    let t4 = is_t4_from_faces(&face_set(t));
    for w in t.link(v) {
        assert_eq!(
            t.link_condition_naive(v, w),
            !t4,
            "Proposition 6 on [{v}, {w}] (T4: {t4})"
        );
    }
    if t4 {
        assert!(t.edges().all(|(a, b, _)| !t.link_condition_naive(a, b)));
    }
    true
}

/// What [`prop7`] met.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Prop7Case {
    /// `f` not contractible, `e` contractible, or `e == f`: nothing to check.
    Vacuous,
    /// `e` stays non-contractible in `K - f` (nothing more to check).
    Stays,
    /// `e` became contractible: the conclusions were checked.
    Became,
}

/// **Proposition 7.** Let `f` be contractible and `e` non-contractible in `K`. If `e`
/// becomes contractible in `K - f`, then `f` is incident on a degree-3 vertex `c` of `K`,
/// `e` is an edge of `lk(c, K)`, `e` lies on exactly one critical cycle of `K` (the one
/// of `lk(c, K)`), and that cycle is not critical in `K - f`. Checked for both
/// contraction directions of `f` (which give isomorphic results, so the case must agree).
pub fn prop7(t: &Triangulation, f_edge: usize, e_edge: usize) -> Prop7Case {
    let (fa, fb) = nth_edge(t, f_edge);
    let (ea, eb) = nth_edge(t, e_edge);
    if f_edge == e_edge || !t.link_condition_naive(fa, fb) || t.link_condition_naive(ea, eb) {
        return Prop7Case::Vacuous;
    }
    let mut cases = Vec::new();
    for (u, v) in [(fa, fb), (fb, fa)] {
        let mut k = t.clone();
        k.contract(u, v, &mut History::new())
            .expect("naively contractible");
        let m = |z: VertexId| if z == v { u } else { z };
        let (p, q) = (m(ea), m(eb));
        assert!(
            p != q && k.has_edge(p, q),
            "e = [{ea}, {eb}] survives as an edge"
        );
        if !k.link_condition_naive(p, q) {
            cases.push(Prop7Case::Stays);
            continue;
        }
        cases.push(Prop7Case::Became);
        let label = format!("Proposition 7: f = [{u}, {v}], e = [{ea}, {eb}]");
        // e lies on exactly one critical cycle (ea, eb, z) of K ...
        assert_eq!(critical_cycles_through(t, ea, eb), Some(1), "{label}");
        let [x, y] = t.edge_link(ea, eb).expect("edge");
        let na: BTreeSet<VertexId> = t.link(ea).collect();
        let z: Vec<VertexId> = t
            .link(eb)
            .filter(|w| na.contains(w) && *w != x && *w != y)
            .collect();
        assert_eq!(z.len(), 1, "{label}");
        let z = z[0];
        // ... which is lk(c, K) for a degree-3 endpoint c of f.
        let cycle: BTreeSet<VertexId> = [ea, eb, z].into_iter().collect();
        let centre = [fa, fb]
            .into_iter()
            .find(|&c| t.degree(c) == 3 && t.link(c).collect::<BTreeSet<_>>() == cycle);
        assert!(
            centre.is_some(),
            "{label}: f has no degree-3 endpoint whose link is the critical cycle {cycle:?}"
        );
        // And the cycle is no longer critical in K - f.
        assert!(
            !is_critical_cycle(&k, [p, q, m(z)]),
            "{label}: the cycle of lk(c) is still critical in K - f"
        );
    }
    assert_eq!(cases[0], cases[1], "the two directions of f disagree");
    cases[0]
}

/// **RS output is irreducible.** The Ramaswami–Siqueira reduction of `t` is a valid
/// triangulation of the same surface in which every vertex is trapped (naive test),
/// every edge lies on a critical cycle (or the result is T4), a sphere gives T4, and
/// `expand()` gives back `t` exactly. Returns the output vertex count.
pub fn rs_output_irreducible(t: &Triangulation) -> usize {
    let r = reduce(t.clone(), Algorithm::Rs, &Options::default());
    let out = &r.tri;
    out.validate()
        .unwrap_or_else(|err| panic!("RS output: {err}"));
    assert_eq!(out.euler_characteristic(), t.euler_characteristic());
    assert_eq!(out.is_orientable(), t.is_orientable());
    assert!(out.is_irreducible_naive(), "RS output is reducible");
    for v in out.vertices() {
        assert!(is_trapped_naive(out, v), "RS output vertex {v} is loose");
    }
    let faces = face_set(out);
    let t4 = is_t4_from_faces(&faces);
    for (a, b, _) in out.edges() {
        assert!(
            t4 || critical_cycles_from_faces(&faces, a, b) > 0,
            "RS output edge {a}-{b} on no critical cycle"
        );
    }
    if t.euler_characteristic() == 2 {
        assert!(t4, "a sphere must reduce to T4");
    }
    assert_eq!(r.history.len(), t.vertex_count() - out.vertex_count());
    assert!(r.expand() == *t, "expand() is not the input");
    out.vertex_count()
}

// ---- Kani entry points. The surface is any of the 57 embedded ones; indices are
// symbolic within range. The unwind bound covers the longest loop over the embedded
// surfaces: 3F <= 48 corners (F <= 16), degrees <= 7, edges <= 24.

#[cfg(kani)]
fn any_surface() -> Triangulation {
    let i: usize = kani::any();
    kani::assume(i < crate::surfaces::SURFACES.len());
    crate::surfaces::SURFACES[i].triangulation()
}

#[cfg(kani)]
fn any_below(n: usize) -> usize {
    let i: usize = kani::any();
    kani::assume(i < n);
    i
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_link_conditions_agree() {
    let t = any_surface();
    let e = any_below(t.edge_count());
    link_conditions_agree(&t, e);
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_theorem3() {
    let t = any_surface();
    let e = any_below(t.edge_count());
    theorem3(&t, e);
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_contract_then_split_is_identity() {
    let t = any_surface();
    let e = any_below(t.edge_count());
    contract_then_split_is_identity(&t, e, kani::any());
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_lemma5_trapped_stays_trapped() {
    let t = any_surface();
    let w = any_below(t.vertex_count());
    let e = any_below(t.edge_count());
    lemma5_trapped_stays_trapped(&t, w, e);
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_prop6_degree3_edges_contractible_unless_t4() {
    let t = any_surface();
    let v = any_below(t.vertex_count());
    prop6_degree3_edges_contractible_unless_t4(&t, v);
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_prop7() {
    let t = any_surface();
    let f = any_below(t.edge_count());
    let e = any_below(t.edge_count());
    prop7(&t, f, e);
}

#[cfg(kani)]
#[kani::proof]
#[kani::unwind(50)]
fn kani_rs_output_irreducible() {
    let t = any_surface();
    rs_output_irreducible(&t);
}
