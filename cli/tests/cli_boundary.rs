//! Surfaces with boundary on the command line: `info` describes them (boundary loops
//! checked by counting and walking boundary edges here), `reduce` and `quad` refuse them
//! with exit code 2 and a message that says they need closed surfaces, closed reports
//! carry no boundary field.

use crate::cli_common;

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::OsStr;
use std::path::Path;

use cli_common::{
    data_closed, int, read_mesh, run, run_json, run_ok, stderr, tetrahedron_file, with_holes,
    Scratch,
};
use contractible::TriMesh;

/// Boundary loop lengths (sorted) and χ of a face list, from edge counts alone: an edge
/// in one face is a boundary edge; loops are walked vertex to vertex.
fn loops_and_chi(faces: &[[u32; 3]]) -> (Vec<usize>, i64) {
    let mut count: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    for f in faces {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let mut adj: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    for (&(a, b), &n) in &count {
        if n == 1 {
            adj.entry(a).or_default().push(b);
            adj.entry(b).or_default().push(a);
        }
    }
    let mut seen = BTreeSet::new();
    let mut lengths = Vec::new();
    for &start in adj.keys() {
        if !seen.insert(start) {
            continue;
        }
        let (mut prev, mut cur, mut len) = (start, adj[&start][0], 1);
        while cur != start {
            seen.insert(cur);
            let n = &adj[&cur];
            assert_eq!(n.len(), 2, "vertex {cur} is on {} boundary edges", n.len());
            let next = if n[0] == prev { n[1] } else { n[0] };
            (prev, cur, len) = (cur, next, len + 1);
        }
        lengths.push(len);
    }
    lengths.sort_unstable();
    let vertices: BTreeSet<u32> = faces.iter().flatten().copied().collect();
    let chi = vertices.len() as i64 - count.len() as i64 + faces.len() as i64;
    (lengths, chi)
}

fn sorted_lengths(c: &serde_json::Value) -> Vec<usize> {
    let mut v: Vec<usize> = c["boundary_loop_lengths"]
        .as_array()
        .expect("boundary_loop_lengths")
        .iter()
        .map(|x| x.as_u64().unwrap() as usize)
        .collect();
    v.sort_unstable();
    v
}

/// `info --json` on a one-component open surface agrees with the face list.
fn check_info(path: &Path, orientable: bool) -> serde_json::Value {
    let mesh = contractible::io::read_tri_mesh(path).unwrap();
    let (lengths, chi) = loops_and_chi(&mesh.faces);
    let b = lengths.len() as i64;
    let j = run_json(&[OsStr::new("info"), path.as_os_str()]);
    assert_eq!(int(&j, "boundary_loops"), b, "{}", path.display());
    assert_eq!(int(&j, "euler_characteristic"), chi);
    assert_eq!(j["orientable"], orientable);
    let c = &j["component_list"][0];
    assert_eq!(int(c, "boundary_loops"), b);
    assert_eq!(sorted_lengths(c), lengths);
    assert_eq!(int(c, "euler_characteristic"), chi);
    assert_eq!(int(c, "euler_genus"), 2 - chi - b);
    if orientable {
        assert_eq!(int(c, "genus") * 2, 2 - chi - b);
    } else {
        assert!(c["genus"].is_null());
    }
    let used: BTreeSet<u32> = mesh.faces.iter().flatten().copied().collect();
    assert_eq!(int(c, "vertices"), used.len() as i64);
    assert_eq!(int(c, "faces"), mesh.faces.len() as i64);
    let hist: i64 = c["degree_histogram"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_i64().unwrap())
        .sum();
    assert_eq!(
        hist,
        used.len() as i64,
        "every real vertex in the histogram"
    );
    j
}

/// A real open surface: the repository's genus-0 bunny with `holes` holes cut in it,
/// written as `DIR/NAME.off.gz`. The face list's own count says it has `holes` boundary
/// loops and χ = 2 − `holes`.
fn open_bunny(dir: &Scratch, name: &str, holes: usize) -> std::path::PathBuf {
    let open = with_holes(&read_mesh(&data_closed("bunny_npm")), holes);
    let (lengths, chi) = loops_and_chi(&open.faces);
    assert_eq!((lengths.len(), chi), (holes, 2 - holes as i64), "{name}");
    let path = dir.path(&format!("{name}.off.gz"));
    contractible::io::write_mesh(&path, &open).unwrap();
    path
}

#[test]
fn info_describes_open_meshes() {
    let d = Scratch::new("boundary-open");
    for (name, loops, genus) in [("disc_bunny", 1, 0), ("holed_bunny", 5, 0)] {
        let path = open_bunny(&d, name, loops as usize);
        let j = check_info(&path, true);
        assert_eq!(int(&j, "boundary_loops"), loops, "{name}");
        assert_eq!(int(&j["component_list"][0], "genus"), genus, "{name}");
        let out = run_ok(&[OsStr::new("info"), path.as_os_str()]);
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(
            text.lines()
                .next()
                .unwrap()
                .ends_with(&format!("orientable boundary loops={loops}")),
            "{text}"
        );
        assert!(text.contains("; boundary loop lengths "), "{text}");
    }
}

/// Writes `faces` over `n` vertices (all at the origin) as an OFF file.
fn write_off(path: &Path, n: usize, faces: &[[u32; 3]]) {
    let mesh = TriMesh::combinatorial(n, faces.to_vec());
    contractible::io::write_mesh(path, &mesh).unwrap();
}

fn without_star(mesh: &TriMesh, v: u32) -> Vec<[u32; 3]> {
    mesh.faces
        .iter()
        .filter(|f| !f.contains(&v))
        .copied()
        .collect()
}

#[test]
fn info_names_a_moebius_band_and_a_punctured_torus() {
    let d = Scratch::new("boundary-named");
    let mob = d.path("moebius.off");
    write_off(
        &mob,
        6,
        &without_star(&contractible::gen::projective_plane6(), 0),
    );
    let j = check_info(&mob, false);
    assert_eq!(int(&j["component_list"][0], "euler_genus"), 1);
    let out = run_ok(&[OsStr::new("info"), mob.as_os_str()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("χ=0 Möbius band (non-orientable genus 1, 1 boundary loop)"),
        "{text}"
    );
    assert!(text.contains("boundary loop lengths 5"), "{text}");
    // The unused vertex 0 is dropped with the usual warning.
    assert!(stderr(&out).contains("1 unused vertices dropped"));

    let tor = d.path("torus.off");
    write_off(&tor, 7, &without_star(&contractible::gen::torus7(), 3));
    check_info(&tor, true);
    let out = run_ok(&[OsStr::new("info"), tor.as_os_str()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("χ=-1 orientable genus 1, 1 boundary loop;"),
        "{text}"
    );
}

#[test]
fn closed_reports_have_no_boundary_fields() {
    let d = Scratch::new("boundary-closed");
    for path in [tetrahedron_file(&d), data_closed("box_stl")] {
        let j = run_json(&[OsStr::new("info"), path.as_os_str()]);
        let m = path.display();
        assert!(j.get("boundary_loops").is_none(), "{m}");
        for c in j["component_list"].as_array().unwrap() {
            assert!(c.get("boundary_loops").is_none(), "{m}");
            assert!(c.get("boundary_loop_lengths").is_none(), "{m}");
        }
        let out = run_ok(&[OsStr::new("info"), path.as_os_str()]);
        // (The path itself may contain the word, as this checkout's does.)
        assert!(!String::from_utf8_lossy(&out.stdout).contains("boundary loop"));
    }
}

#[test]
fn reduce_and_quad_refuse_open_meshes() {
    let d = Scratch::new("boundary-refuse");
    let mob = d.path("moebius.off");
    write_off(
        &mob,
        6,
        &without_star(&contractible::gen::projective_plane6(), 0),
    );
    let bunny = open_bunny(&d, "holed_bunny", 5);
    for cmd in ["reduce", "quad"] {
        for (input, loops) in [
            (bunny.as_path(), "5 boundary loops"),
            (&mob, "1 boundary loop"),
        ] {
            let out_path = d.path("out.off");
            let out = run(&[
                OsStr::new(cmd),
                input.as_os_str(),
                OsStr::new("-o"),
                out_path.as_os_str(),
            ]);
            let err = stderr(&out);
            assert_eq!(out.status.code(), Some(2), "{cmd}: {err}");
            assert!(out.stdout.is_empty(), "{cmd}");
            assert!(!out_path.exists(), "{cmd}: wrote an output");
            assert_eq!(err.lines().count(), 1, "{cmd}: {err}");
            let want = format!(
                "`{cmd}` needs closed surfaces (this mesh has {loops}; `info` describes it)"
            );
            assert!(
                err.starts_with(&format!("error: {}: edge [", input.display())),
                "{err}"
            );
            assert!(err.contains("] is a boundary edge, only in face "), "{err}");
            assert!(err.trim_end().ends_with(&want), "{cmd}: {err}");
        }
    }
    // The located boundary edge really is one: in exactly one face of the file.
    let out = run(&[OsStr::new("reduce"), mob.as_os_str()]);
    let err = stderr(&out);
    let inner = &err[err.find("edge [").unwrap() + 6..];
    let nums: Vec<u32> = inner[..inner.find(']').unwrap()]
        .split(", ")
        .map(|x| x.parse().unwrap())
        .collect();
    let face: usize = {
        let s = &inner[inner.find("only in face ").unwrap() + 13..];
        s[..s.find(' ').unwrap()].parse().unwrap()
    };
    let faces = without_star(&contractible::gen::projective_plane6(), 0);
    let holding: Vec<usize> = (0..faces.len())
        .filter(|&f| faces[f].contains(&nums[0]) && faces[f].contains(&nums[1]))
        .collect();
    assert_eq!(holding, vec![face], "{err}");
}

#[test]
fn pinched_meshes_stay_errors_everywhere() {
    let d = Scratch::new("boundary-pinch");
    let p = d.path("bowtie.off");
    write_off(&p, 5, &[[0, 1, 2], [0, 3, 4]]);
    for cmd in ["reduce", "quad"] {
        let out = run(&[OsStr::new(cmd), p.as_os_str()]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{cmd}: {err}");
        assert!(out.stdout.is_empty());
        assert!(
            err.contains("vertex 0 is pinched: 4 boundary edges meet there"),
            "{cmd}: {err}"
        );
    }
    // `info` lists the problem with the others (here: alone, and the boundary).
    let out = run(&[OsStr::new("info"), p.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("not a surface: 1 pinched vertex"));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("vertex 0: 2 surface sheets meet here"),
        "{text}"
    );
}

/// `convert` validates surfaces with boundary like `info` (they are valid input), keeps
/// them face for face, reports their loops, and still refuses what is not a surface.
#[test]
fn convert_keeps_open_meshes_and_refuses_pinched_ones() {
    let d = Scratch::new("boundary-convert");
    let src = open_bunny(&d, "holed_bunny", 5);
    let out = d.path("bunny.ply");
    let j = run_json(&[
        OsStr::new("convert"),
        src.as_os_str(),
        out.as_os_str(),
        OsStr::new("--json"),
    ]);
    assert_eq!(int(&j, "boundary_loops"), 5);
    assert_eq!(int(&j, "components"), 1);
    let before = contractible::io::read_tri_mesh(&src).expect("readable");
    let after = contractible::io::read_tri_mesh(&out).expect("readable");
    assert_eq!(after.faces.len(), before.faces.len());
    let (loops_before, chi_before) = loops_and_chi(&before.faces);
    assert_eq!(loops_and_chi(&after.faces), (loops_before, chi_before));
    let p = d.path("bowtie.off");
    write_off(&p, 5, &[[0, 1, 2], [0, 3, 4]]);
    let q = d.path("bowtie.obj");
    let r = run(&[OsStr::new("convert"), p.as_os_str(), q.as_os_str()]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    assert!(stderr(&r).contains("vertex 0 is pinched"), "{}", stderr(&r));
    assert!(!q.exists(), "no output for a refused input");
}
