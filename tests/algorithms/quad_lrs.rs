//! The LRS initial pairing (`quad::lrs`, tri-quad paper Sec. 3.3) checked by independent
//! code: `K` validates and has the input's vertex set and counts, differs from the input
//! by exactly `flips` edges (edge sets compared as vertex pairs), the pairing pairs
//! faces that share two vertices in `K`'s face lists, and exactly `n'_f` faces stay
//! unpaired, within the paper's bound (4 for genus 0, `56g − 12` for orientable genus
//! `g > 0`, `28h − 12` for Euler genus `h` non-orientable, from Joret–Wood's
//! `n'_v ≤ 13h − 4`).

use std::collections::HashSet;

use crate::common;
use contractible::gen::{random, RandomParams, SurfaceKind};
use contractible::quad::lrs::{initial_pairing, initial_pairing_variant, Expansion, Variant};
use contractible::{FaceId, Surfaces, Triangulation};

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
    assert_eq!(
        ex.cases.splits,
        (k.face_count() - ex.reduced_faces) / 2,
        "{label}"
    );
    unpaired
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
                });
                let label = format!("{surface:?} seed {seed} faces {min_faces}");
                let ex = initial_pairing(t.clone());
                check(&t, &ex, &label);
                let c = ex.cases;
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
}
