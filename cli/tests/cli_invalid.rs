//! Invalid and malformed inputs: exit code 2, one clean located message on stderr; the
//! library's error kind for each invalid real mesh (the repository's, and with
//! `-- --ignored ::corpus::` the corpus's) matches the manifest's notes.

use crate::cli_common;
use crate::common;

use std::ffi::OsStr;
use std::path::Path;

use cli_common::{data_invalid, data_meshes, run, stderr, Scratch};
use common::{data_manifest, ManifestRow};
use contractible::BuildError;

/// The line of `name` (lowercase) in `meshes/manifest.csv`, for its free-text notes.
fn manifest_line(meshes: &Path, name: &str) -> String {
    let text = std::fs::read_to_string(meshes.join("manifest.csv")).unwrap();
    text.lines()
        .find(|l| l.starts_with(&format!("{name},")))
        .unwrap_or_else(|| panic!("{name} not in manifest"))
        .to_lowercase()
}

/// What the library must report for each invalid mesh, and the word the manifest's
/// notes use for it.
fn expected(name: &str) -> (fn(&BuildError) -> bool, &'static str) {
    match name {
        "dupfaces_crank" | "joined_tetrahedra" => (
            |e| matches!(e, BuildError::DuplicateFace { .. }),
            "duplicate face",
        ),
        "nonmanifold_dino" | "shared_edge_stl" => (
            |e| {
                matches!(
                    e,
                    BuildError::NonManifoldEdge { .. } | BuildError::MultipleEdges { .. }
                )
            },
            "non-manifold edge",
        ),
        "open_camelhead" | "open_bunny_stanford" => {
            (|e| matches!(e, BuildError::BoundaryEdge { .. }), "boundary")
        }
        // Heavily broken: whichever problem comes first, as long as it is one of those
        // the notes name.
        "happy_vrip_res4" => (
            |e| {
                matches!(
                    e,
                    BuildError::DuplicateFace { .. }
                        | BuildError::NonManifoldEdge { .. }
                        | BuildError::MultipleEdges { .. }
                )
            },
            "non-manifold",
        ),
        other => panic!("no expectation for invalid mesh {other}"),
    }
}

/// Every invalid mesh of the manifest under `meshes` (at least `min_rows`): the notes
/// name the problem, and the library refuses the mesh with an error of that kind.
fn library_error_kinds_match_the_notes(meshes: &Path, rows: Vec<ManifestRow>, min_rows: usize) {
    let rows: Vec<_> = rows.into_iter().filter(|r| r.set == "invalid").collect();
    assert!(rows.len() >= min_rows, "only {} invalid meshes", rows.len());
    for r in rows {
        let (ok, word) = expected(&r.name);
        assert!(
            manifest_line(meshes, &r.name).contains(word),
            "{}: manifest notes do not mention {word:?}",
            r.name
        );
        let mesh = contractible::io::read_tri_mesh(&meshes.join(&r.file)).unwrap();
        let err = contractible::Surfaces::from_mesh(&mesh)
            .err()
            .unwrap_or_else(|| panic!("{}: accepted", r.name));
        assert!(ok(&err), "{}: unexpected error kind {err:?}", r.name);
    }
}

/// The repository's invalid real meshes.
#[test]
fn library_error_kinds_match_the_in_repo_manifest_notes() {
    library_error_kinds_match_the_notes(&data_meshes(), data_manifest(), 2);
}

/// `info` on every file of `dir` (at least `min_files` that are not open surfaces):
/// exit code 2, "not a surface" on stdout, one located line on stderr naming the kind.
fn info_rejects_every_non_manifold_mesh_in(dir: &Path, min_files: usize) {
    // The open meshes (surfaces with boundary) are described instead: `cli_boundary`.
    // The others get their problems listed on stdout (`cli_input` checks the counts) and
    // one summary line on stderr.
    let mut n = 0;
    for e in std::fs::read_dir(dir).unwrap() {
        let path = e.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let out = run(&[OsStr::new("info"), path.as_os_str()]);
        if name.starts_with("open_") {
            assert_eq!(out.status.code(), Some(0), "{name}: {}", stderr(&out));
            continue;
        }
        assert_eq!(out.status.code(), Some(2), "{name}");
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("not a surface"), "{name}: {text}");
        let err = stderr(&out);
        let lines: Vec<&str> = err.lines().collect();
        assert_eq!(lines.len(), 1, "{name}: {err}");
        assert!(lines[0].starts_with("error: "), "{name}: {err}");
        assert!(lines[0].contains(&name), "{name}: file name missing: {err}");
        let stem = name.trim_end_matches(".off.gz");
        let msg = lines[0].to_lowercase();
        let kind_word = match stem {
            "dupfaces_crank" | "joined_tetrahedra" | "happy_vrip_res4" => "duplicate face",
            _ => "non-manifold edge",
        };
        assert!(msg.contains(kind_word), "{name}: {err}");
        n += 1;
    }
    assert!(
        n >= min_files,
        "only {n} non-manifold meshes in {}",
        dir.display()
    );
}

/// The repository's invalid real meshes.
#[test]
fn info_rejects_every_in_repo_non_manifold_mesh_with_exit_code_2() {
    info_rejects_every_non_manifold_mesh_in(&data_meshes().join("invalid"), 2);
}

/// Writes `content` as `name` and expects `info` to fail with exit 2 and `needle`.
fn rejects(dir: &Scratch, name: &str, content: &[u8], needle: &str) {
    let p = dir.path(name);
    std::fs::write(&p, content).unwrap();
    let out = run(&[OsStr::new("info"), p.as_os_str()]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(2), "{name}: {err}");
    // Syntax errors print nothing on stdout; problems of the surface are listed there.
    assert!(
        out.stdout.is_empty() || err.contains("not a surface"),
        "{name}"
    );
    assert_eq!(err.lines().count(), 1, "{name}: {err}");
    assert!(
        err.starts_with(&format!("error: {}: ", p.display())),
        "{name}: {err}"
    );
    assert!(err.contains(needle), "{name}: expected {needle:?} in {err}");
}

#[test]
fn malformed_files_exit_2_with_a_located_message() {
    let d = Scratch::new("malformed");
    let tet = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
    rejects(
        &d,
        "truncated.off",
        format!("OFF\n4 4 0\n{tet}3 0 1 2\n3 0 1 3\n").as_bytes(),
        "line 8: faces: header declares 4, found 2",
    );
    rejects(
        &d,
        "nonnumeric.off",
        b"OFF\n4 1 0\n0 0 0\n1 0 abc\n",
        "line 4: bad number \"abc\"",
    );
    rejects(
        &d,
        "huge.off",
        b"OFF\n4000000000 1 0\n0 0 0\n",
        "line 3: vertices: header declares 4000000000",
    );
    // More faces than a triangulation indexes: refused at the header, before reading.
    rejects(
        &d,
        "huge_faces.off",
        b"OFF\n4000000000 4000000000 0\n0 0 0\n",
        "line 2: faces: declared count 4000000000 is impossible for this input",
    );
    // A quad: `info` describes polygon meshes; the other commands refuse them, located,
    // naming the flag that would cut them.
    let quad = d.path("quad.off");
    std::fs::write(&quad, format!("OFF\n4 1 0\n{tet}4 0 1 2 3\n")).unwrap();
    let out = run(&[OsStr::new("reduce"), quad.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(err.contains("line 7: face 0 has 4 corners"), "{err}");
    assert!(err.contains("use --triangulate"), "{err}");
    rejects(
        &d,
        "range.off",
        format!("OFF\n4 1 0\n{tet}3 0 1 7\n").as_bytes(),
        "line 7: face 0 refers to vertex 7",
    );
    rejects(
        &d,
        "bad.obj",
        b"v 0 0 0\nv 1 0 0\nf 1 2 x\n",
        "line 3: bad number",
    );
    rejects(
        &d,
        "short.ply",
        b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n",
        "line 11: input truncated",
    );
    rejects(&d, "notgz.off.gz", b"OFF\n", "not gzip");
    rejects(&d, "empty.off", b"", "");
    // Valid syntax, not a surface: two triangles sharing one vertex (a pinch) and a
    // degenerate face.
    rejects(
        &d,
        "pinched.off",
        format!("OFF\n5 2 0\n{tet}0 0 2\n3 0 1 2\n3 0 3 4\n").as_bytes(),
        "not a surface: 1 pinched vertex",
    );
    rejects(
        &d,
        "degenerate.off",
        format!("OFF\n4 1 0\n{tet}3 0 1 1\n").as_bytes(),
        "not a surface: 1 degenerate face",
    );
}

#[test]
fn missing_files_and_bad_arguments_exit_2() {
    let d = Scratch::new("badargs");
    let out = run(&["info", "/nonexistent/x.off"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("/nonexistent/x.off"),
        "{}",
        stderr(&out)
    );

    let o = d.path("x.off");
    let o = o.to_str().unwrap();
    for args in [
        vec!["gen", "brick", "--paper", "X3", "-o", o],
        vec!["gen", "brick", "--paper", "B10", "-o", o],
        vec!["gen", "brick", "--cavities", "3", "--holes", "4", "-o", o],
        vec![
            "gen",
            "brick",
            "--cavities",
            "3",
            "--resolution",
            "0",
            "-o",
            o,
        ],
        vec!["gen", "random", "--crosscaps", "0", "-o", o],
        vec!["gen", "random", "--genus", "1", "--crosscaps", "1", "-o", o],
        vec!["gen", "random", "--flips", "101", "-o", o],
        vec!["gen", "subdivide", "--input", o, "-o", o],
        vec!["gen", "tetrahedron", "-o", "x.xyz"],
        vec!["reduce", "--algo", "fast", o],
        vec!["frobnicate"],
    ] {
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", stderr(&out));
        assert!(
            !o.is_empty() && !std::path::Path::new(o).exists(),
            "{args:?} wrote"
        );
    }
}

#[test]
fn convert_rejects_invalid_input_unless_told_not_to_validate() {
    let d = Scratch::new("convert-invalid");
    let input = data_invalid("joined_tetrahedra");
    let out_path = d.path("j.ply");
    let out = run(&[
        OsStr::new("convert"),
        input.as_os_str(),
        out_path.as_os_str(),
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(!out_path.exists(), "output written despite the error");

    let out = run(&[
        OsStr::new("convert"),
        OsStr::new("--no-validate"),
        input.as_os_str(),
        out_path.as_os_str(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let a = contractible::io::read_tri_mesh(&input).unwrap();
    let b = contractible::io::read_tri_mesh(&out_path).unwrap();
    assert_eq!(a.faces, b.faces);
    assert_eq!(a.positions, b.positions);
}

/// Over the real-mesh corpus (ignored unless asked for: `-- --ignored ::corpus::`).
mod corpus {
    use super::*;
    use crate::cli_common::corpus_meshes;
    use crate::common::corpus_manifest;

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn library_error_kinds_match_the_manifest_notes() {
        library_error_kinds_match_the_notes(&corpus_meshes(), corpus_manifest(), 7);
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn info_rejects_every_non_manifold_mesh_with_exit_code_2() {
        info_rejects_every_non_manifold_mesh_in(&corpus_meshes().join("invalid"), 5);
    }
}
