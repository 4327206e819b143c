//! The core on real meshes: the manifest's counts, genus per component and orientability;
//! both link-condition implementations agree on every edge; every invalid mesh is
//! rejected with the error kind its manifest note names. By default on the small meshes
//! the repository carries (`tests/data/meshes`); with `-- --ignored ::corpus::`, on every
//! mesh of the real-mesh corpus too.

use std::path::Path;

use crate::common::{self, ManifestRow};

use contractible::{BuildError, LinkTester, Surfaces};

fn rows_of(rows: &[ManifestRow], set: &str) -> Vec<ManifestRow> {
    rows.iter().filter(|r| r.set == set).cloned().collect()
}

/// Every closed mesh of `rows` (files under `dir`) has the manifest's V, E, F, components,
/// χ, orientability and genus per component, and validates.
fn closed_meshes_match(rows: &[ManifestRow], dir: &Path) {
    for row in rows {
        let path = dir.join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let s = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let (v, e, f) = s.counts();
        assert_eq!((v, e, f), (row.v, row.e, row.f), "{}: V, E, F", row.name);
        assert_eq!(
            s.components.len(),
            row.components,
            "{}: components",
            row.name
        );
        let chi: i64 = s
            .components
            .iter()
            .map(|c| c.tri.euler_characteristic())
            .sum();
        assert_eq!(chi, row.euler, "{}: Euler characteristic", row.name);
        let orientable = s.components.iter().all(|c| c.tri.is_orientable());
        assert_eq!(orientable, row.orientable, "{}: orientability", row.name);
        let mut genus: Vec<String> = s
            .components
            .iter()
            .map(|c| match c.tri.genus() {
                Some(g) => g.to_string(),
                None => format!("N{}", c.tri.euler_genus()),
            })
            .collect();
        genus.sort();
        assert_eq!(genus, row.genus, "{}: genus per component", row.name);
        for c in &s.components {
            c.tri
                .validate()
                .unwrap_or_else(|e| panic!("{}: {e}", row.name));
        }
    }
}

/// The naive link condition and the marked `LinkTester` agree on every directed edge of
/// every mesh of `rows`; returns (edges, contractible edges).
fn link_tests_agree(rows: &[ManifestRow], dir: &Path) -> (usize, usize) {
    let mut edges = 0usize;
    let mut contractible = 0usize;
    for row in rows {
        let path = dir.join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let s = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        for c in &s.components {
            let t = &c.tri;
            let mut lt = LinkTester::new(t.vertex_capacity());
            for (a, b, _) in t.edges() {
                let naive = t.link_condition_naive(a, b);
                assert_eq!(naive, lt.test(t, a, b), "{}: edge [{a}, {b}]", row.name);
                assert_eq!(naive, lt.test(t, b, a), "{}: edge [{b}, {a}]", row.name);
                edges += 1;
                contractible += naive as usize;
            }
        }
    }
    (edges, contractible)
}

/// Every invalid mesh of `rows` reads, and validation rejects it with the error kind its
/// manifest row names.
fn invalid_meshes_rejected(rows: &[ManifestRow], dir: &Path) {
    for row in rows {
        let path = dir.join(&row.file);
        let mesh =
            contractible::io::read_tri_mesh(&path).unwrap_or_else(|e| panic!("{}: {e}", row.name));
        let err = Surfaces::from_mesh(&mesh).expect_err(&row.name);
        let ok = match row.name.as_str() {
            "open_camelhead" | "open_bunny_stanford" => {
                matches!(err, BuildError::BoundaryEdge { .. })
            }
            "nonmanifold_dino" => matches!(
                err,
                BuildError::NonManifoldEdge { .. } | BuildError::MultipleEdges { .. }
            ),
            "dupfaces_crank" | "joined_tetrahedra" | "happy_vrip_res4" => {
                matches!(err, BuildError::DuplicateFace { .. })
            }
            "shared_edge_stl" => matches!(
                err,
                BuildError::NonManifoldEdge { .. } | BuildError::MultipleEdges { .. }
            ),
            other => panic!("unexpected invalid mesh {other}"),
        };
        assert!(ok, "{}: unexpected error kind: {err}", row.name);
    }
}

#[test]
fn closed_meshes_match_the_manifest() {
    let rows = rows_of(&common::data_manifest(), "closed");
    assert_eq!(rows.len(), 9, "closed meshes in tests/data/meshes");
    closed_meshes_match(&rows, &common::data_meshes());
}

#[test]
fn both_link_tests_agree_on_every_edge_of_every_mesh() {
    let rows = rows_of(&common::data_manifest(), "closed");
    let (edges, contractible) = link_tests_agree(&rows, &common::data_meshes());
    assert!(edges > 45_000, "only {edges} edges checked");
    assert!(contractible > 0 && contractible < edges);
}

#[test]
fn invalid_meshes_are_rejected_with_the_right_error() {
    let rows = rows_of(&common::data_manifest(), "invalid");
    assert_eq!(rows.len(), 2);
    invalid_meshes_rejected(&rows, &common::data_meshes());
}

/// Each structural error of `Triangulation::from_faces`, on a minimal input.
#[test]
fn every_build_error_kind_is_reported_where_it_happens() {
    use contractible::Triangulation as T;
    const T4: [[u32; 3]; 4] = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
    assert_eq!(T::from_faces(0, &[]), Err(BuildError::Empty));
    // A vertex count beyond the 32-bit index space is refused before any allocation.
    assert!(matches!(
        T::from_faces(usize::MAX, &T4),
        Err(BuildError::TooLarge {
            what: "vertices",
            ..
        })
    ));
    assert!(matches!(
        T::from_faces(3, &[[0, 1, 5]]),
        Err(BuildError::VertexOutOfRange {
            face: 0,
            vertex: 5,
            ..
        })
    ));
    assert!(matches!(
        T::from_faces(4, &[[0, 1, 2], [1, 1, 3]]),
        Err(BuildError::DegenerateFace { face: 1, .. })
    ));
    let mut dup = T4.to_vec();
    dup.push([2, 1, 0]);
    assert!(matches!(
        T::from_faces(4, &dup),
        Err(BuildError::DuplicateFace {
            face: 4,
            first: 0,
            ..
        })
    ));
    assert!(matches!(
        T::from_faces(4, &T4[..3]),
        Err(BuildError::BoundaryEdge { .. })
    ));
    // Three tetrahedron faces on edge [0, 1] plus a fourth: edge [0,1] in 3 faces.
    let mut nm = T4.to_vec();
    nm.push([0, 1, 4]);
    assert!(matches!(
        T::from_faces(5, &nm),
        Err(BuildError::NonManifoldEdge {
            a: 0,
            b: 1,
            faces: 3,
            ..
        })
    ));
    // Two tetrahedra glued along edge [0, 1] only: the edge lies in 4 faces.
    let mut two = T4.to_vec();
    two.extend([[0, 1, 4], [0, 5, 1], [0, 4, 5], [1, 5, 4]]);
    assert!(matches!(
        T::from_faces(6, &two),
        Err(BuildError::MultipleEdges {
            a: 0,
            b: 1,
            edges: 2,
            ..
        })
    ));
    // Two tetrahedra sharing vertex 0: a pinched vertex whose link is two cycles.
    let mut pinch = T4.to_vec();
    pinch.extend([[0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]]);
    assert!(matches!(
        T::from_faces(7, &pinch),
        Err(BuildError::VertexLinkNotCycle {
            vertex: 0,
            cycles: 2,
            ..
        })
    ));
    assert!(matches!(
        T::from_faces(5, &T4),
        Err(BuildError::UnusedVertex { vertex: 4 })
    ));
    let mut apart = T4.to_vec();
    apart.extend(T4.iter().map(|f| f.map(|v| v + 4)));
    assert!(matches!(
        T::from_faces(8, &apart),
        Err(BuildError::Disconnected { components: 2 })
    ));
    // The lenient path drops the unused vertex and splits the components, in order.
    let s = Surfaces::from_faces(9, &apart).unwrap();
    assert_eq!(s.dropped_vertices, vec![8]);
    assert_eq!(s.components.len(), 2);
    assert_eq!(s.components[1].vertex_origin, vec![4, 5, 6, 7]);
    assert_eq!(s.components[1].face_origin, vec![4, 5, 6, 7]);
}

/// The same checks over the real-mesh corpus.
mod corpus {
    use super::*;

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn closed_meshes_match_the_manifest() {
        let rows = rows_of(&common::corpus_manifest(), "closed");
        assert!(
            rows.len() >= 90,
            "manifest lists {} closed meshes",
            rows.len()
        );
        closed_meshes_match(&rows, &common::corpus_meshes());
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn both_link_tests_agree_on_every_edge_of_every_mesh() {
        let rows = rows_of(&common::corpus_manifest(), "closed");
        let (edges, contractible) = link_tests_agree(&rows, &common::corpus_meshes());
        assert!(edges > 1_000_000, "only {edges} edges checked");
        assert!(contractible > 0 && contractible < edges);
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn invalid_meshes_are_rejected_with_the_right_error() {
        let rows = rows_of(&common::corpus_manifest(), "invalid");
        assert_eq!(rows.len(), 7);
        invalid_meshes_rejected(&rows, &common::corpus_meshes());
    }
}
