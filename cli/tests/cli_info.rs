//! `contractible info` against a mesh manifest (the repository's, and with
//! `-- --ignored ::corpus::` the real-mesh corpus's): every closed mesh, through the binary,
//! must report exactly the manifest's counts, components, genera, χ and orientability.

use crate::cli_common;
use crate::common;

use std::path::Path;

use cli_common::{data_closed, data_meshes, int, run, run_json, run_ok};
use common::{data_manifest, ManifestRow};

/// The genus of one `component_list` entry as the manifest writes it (`N<h>` for a
/// non-orientable one).
fn genus_code(c: &serde_json::Value) -> String {
    match c["genus"].as_i64() {
        Some(g) => g.to_string(),
        None => format!("N{}", int(c, "euler_genus")),
    }
}

fn check_row(meshes: &Path, row: &ManifestRow) {
    let path = meshes.join(&row.file);
    let v = run_json(&[std::ffi::OsStr::new("info"), path.as_os_str()]);
    let what = &row.name;
    assert_eq!(int(&v, "vertices") as usize, row.v, "{what}: V");
    assert_eq!(int(&v, "edges") as usize, row.e, "{what}: E");
    assert_eq!(int(&v, "faces") as usize, row.f, "{what}: F");
    assert_eq!(int(&v, "components") as usize, row.components, "{what}");
    assert_eq!(int(&v, "euler_characteristic"), row.euler, "{what}: χ");
    assert_eq!(v["orientable"].as_bool(), Some(row.orientable), "{what}");
    let list = v["component_list"].as_array().expect("component_list");
    assert_eq!(list.len(), row.components, "{what}");
    let mut genera: Vec<String> = list.iter().map(genus_code).collect();
    genera.sort();
    assert_eq!(genera, row.genus, "{what}: genus per component");
    // Per-component consistency: the parts add up, V - E + F = χ, histogram sums to V.
    let sum = |k: &str| list.iter().map(|c| int(c, k)).sum::<i64>();
    assert_eq!(sum("vertices"), int(&v, "vertices"), "{what}");
    assert_eq!(sum("faces"), int(&v, "faces"), "{what}");
    for c in list {
        assert_eq!(
            int(c, "vertices") - int(c, "edges") + int(c, "faces"),
            int(c, "euler_characteristic"),
            "{what}"
        );
        assert_eq!(2 - int(c, "euler_characteristic"), int(c, "euler_genus"));
        let h: Vec<i64> = c["degree_histogram"]
            .as_array()
            .expect("histogram")
            .iter()
            .map(|x| x.as_i64().expect("count"))
            .collect();
        assert_eq!(h.iter().sum::<i64>(), int(c, "vertices"), "{what}");
        assert_eq!(h.len() as i64 - 1, int(c, "degree_max"), "{what}");
        assert!(h[int(c, "degree_min") as usize] > 0, "{what}");
        assert!(int(c, "degree_min") >= 3, "{what}");
    }
    for k in ["file", "dropped_vertices", "seconds_read", "seconds_build"] {
        assert!(v.get(k).is_some(), "{what}: key {k}");
    }
}

/// Every closed mesh of the manifest under `meshes` (at least `min_rows` of them, and
/// every file of `closed/` listed) through `info`, in parallel.
fn info_matches_the_manifest(meshes: &Path, rows: Vec<ManifestRow>, min_rows: usize) {
    let rows: Vec<ManifestRow> = rows.into_iter().filter(|r| r.set == "closed").collect();
    // Every file in closed/ is in the manifest (so none is skipped silently).
    let mut files: Vec<String> = std::fs::read_dir(meshes.join("closed"))
        .expect("closed/")
        .map(|e| format!("closed/{}", e.expect("entry").file_name().to_string_lossy()))
        .collect();
    files.sort();
    let mut listed: Vec<String> = rows.iter().map(|r| r.file.clone()).collect();
    listed.sort();
    assert_eq!(files, listed, "closed/ and the manifest disagree");
    assert!(rows.len() >= min_rows, "only {} closed meshes", rows.len());

    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    let chunk = rows.len().div_ceil(threads);
    std::thread::scope(|s| {
        for part in rows.chunks(chunk) {
            s.spawn(move || part.iter().for_each(|r| check_row(meshes, r)));
        }
    });
}

/// The repository's closed real meshes (`tests/data/meshes`).
#[test]
fn info_matches_the_manifest_for_every_in_repo_closed_mesh() {
    info_matches_the_manifest(&data_meshes(), data_manifest(), 9);
}

#[test]
fn info_human_output_and_quiet() {
    let path = data_closed("box_stl");
    let out = run_ok(&[std::ffi::OsStr::new("info"), path.as_os_str()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("components=10"), "{text}");
    assert!(text.contains("orientable genus 6"), "{text}");
    assert!(text.contains("torus (genus 1)"), "{text}");

    let out = run_ok(&[
        std::ffi::OsStr::new("--quiet"),
        std::ffi::OsStr::new("info"),
        path.as_os_str(),
    ]);
    assert!(out.stdout.is_empty(), "--quiet printed on stdout");
}

#[test]
fn info_warns_about_unused_vertices() {
    let dir = cli_common::Scratch::new("unused");
    let p = dir.path("t.off");
    // A tetrahedron plus two vertices no face uses.
    std::fs::write(
        &p,
        "OFF\n6 4 0\n0 0 0\n1 0 0\n9 9 9\n0 1 0\n0 0 1\n8 8 8\n3 0 1 3\n3 0 3 4\n3 0 4 1\n3 1 4 3\n",
    )
    .unwrap();
    let out = run(&["--json".as_ref(), "info".as_ref(), p.as_os_str()]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(int(&v, "dropped_vertices"), 2);
    assert_eq!(int(&v, "vertices"), 4);
    assert!(
        cli_common::stderr(&out).contains("warning: t.off: 2 unused vertices dropped")
            || cli_common::stderr(&out).contains("2 unused vertices dropped"),
        "{}",
        cli_common::stderr(&out)
    );
}

/// Over the real-mesh corpus (ignored unless asked for: `-- --ignored ::corpus::`).
mod corpus {
    use super::*;
    use crate::cli_common::corpus_meshes;
    use crate::common::corpus_manifest;

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn info_matches_the_manifest_for_every_closed_mesh() {
        info_matches_the_manifest(&corpus_meshes(), corpus_manifest(), 91);
    }
}
