//! The input side of the command line: every problem at once (`info` on broken meshes,
//! checked against counts made here from the raw faces), polygon files (`--triangulate`,
//! `info` on quads, the tri-quad output round-tripping through `info`), `--weld=EPS`,
//! standard input, content sniffing, BOM, skipped OBJ statements.

use crate::cli_common;
use crate::common;

use std::collections::HashMap;
use std::ffi::OsStr;
use std::fmt::Write as _;
use std::io::Write as _;
use std::process::{Command, Output, Stdio};

use cli_common::{
    data_closed, data_meshes, genus_two_file, grid_torus, int, read_mesh, run, run_json, run_ok,
    stderr, with_duplicate_faces, write_off_text, Scratch,
};
use common::{data_manifest, ManifestRow};

/// Runs `contractible ARGS...` with `input` on its standard input.
fn run_stdin(args: &[&str], input: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_contractible"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(input)
        .expect("write stdin");
    child.wait_with_output().expect("wait")
}

/// Runs `info --json FILE` expecting exit code `code`; the parsed stdout.
fn info_json(file: &std::path::Path, extra: &[&str], code: i32) -> serde_json::Value {
    let mut args: Vec<&OsStr> = vec![OsStr::new("--json"), OsStr::new("info")];
    args.extend(extra.iter().map(OsStr::new));
    args.push(file.as_os_str());
    let out = run(&args);
    assert_eq!(out.status.code(), Some(code), "{}", stderr(&out));
    serde_json::from_slice(&out.stdout).expect("JSON on stdout")
}

/// The `count` of problem `kind` in an `info --json` report (0 when absent).
fn problem_count(report: &serde_json::Value, kind: &str) -> i64 {
    report["problems"]
        .as_array()
        .expect("problems")
        .iter()
        .find(|p| p["kind"] == kind)
        .map_or(0, |p| int(p, "count"))
}

/// Independent counts from the raw faces: duplicate faces (same vertex set as an
/// earlier face) and edges in 3 or more faces.
fn raw_counts(m: &contractible::TriMesh) -> (usize, usize) {
    let mut sets: HashMap<[u32; 3], usize> = HashMap::new();
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for f in &m.faces {
        let mut s = *f;
        s.sort_unstable();
        *sets.entry(s).or_default() += 1;
        for i in 0..3 {
            let (a, b) = (f[i], f[(i + 1) % 3]);
            *edges.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let dups = sets.values().map(|&n| n - 1).sum();
    let nonmanifold = edges.values().filter(|&&n| n >= 3).count();
    (dups, nonmanifold)
}

/// `info` on an OFF file with duplicate faces and non-manifold edges (laid out as `OFF`,
/// `V F 0`, then one line per vertex and per face): the counts made here from the raw
/// faces, five examples of duplicates located by line, an edge shared by 4 faces, one
/// summary line on stderr; `reduce` stops at the first problem and points at `info`.
fn lists_every_duplicate_face_and_non_manifold_edge(file: &std::path::Path) {
    let mesh = read_mesh(file);
    let (dups, nonmanifold) = raw_counts(&mesh);
    let v = mesh.vertex_count as i64;
    assert!(dups > 5, "{}: {dups} duplicate faces", file.display());
    let r = info_json(file, &[], 2);
    assert_eq!(problem_count(&r, "duplicate_face") as usize, dups, "{r}");
    assert_eq!(
        problem_count(&r, "non_manifold_edge") as usize,
        nonmanifold,
        "{r}"
    );
    assert_eq!(r["surface"], false);
    let dup = r["problems"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["kind"] == "duplicate_face")
        .unwrap();
    assert_eq!(dup["examples"].as_array().unwrap().len(), 5);
    // Each example names a face and the earlier one it repeats, with their lines
    // (faces start at line 2 + V + 1 of the OFF: 0-based face f is on line V + 3 + f).
    for e in dup["examples"].as_array().unwrap() {
        let faces: Vec<i64> = e["faces"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_i64().unwrap())
            .collect();
        let lines: Vec<i64> = e["lines"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_i64().unwrap())
            .collect();
        assert!(faces[0] > faces[1], "{e}");
        assert_eq!(lines, vec![v + 3 + faces[0], v + 3 + faces[1]], "{e}");
        // The two faces really have the same vertex set.
        let set = |f: i64| {
            let mut s = mesh.faces[f as usize];
            s.sort_unstable();
            s
        };
        assert_eq!(set(faces[0]), set(faces[1]), "{e}");
    }

    // Human-readable: the counts, one hint per kind, stderr's summary.
    let out = run(&[OsStr::new("info"), file.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains(&format!(
            "{dups} duplicate faces: the same face is listed more than once"
        )),
        "{text}"
    );
    assert!(
        text.contains(&format!(
            "{nonmanifold} non-manifold edges: more than two faces meet"
        )),
        "{text}"
    );
    assert!(
        text.contains("is non-manifold, shared by 4 faces"),
        "{text}"
    );
    assert!(text.contains(&format!("… and {} more", dups - 5)), "{text}");
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains(&format!(
            "not a surface: {dups} duplicate faces, {nonmanifold} non-manifold edges"
        )),
        "{err}"
    );

    // The other commands still stop at the first problem, and point at `info`.
    let out = run(&[OsStr::new("reduce"), file.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("`contractible info` lists every problem"),
        "{}",
        stderr(&out)
    );
}

/// A real mesh (the repository's genus-3 surface) with the faces around two vertices
/// listed a second time after the others.
#[test]
fn info_lists_every_duplicate_face_and_non_manifold_edge() {
    let d = Scratch::new("duplicates");
    let (mesh, _) = with_duplicate_faces(&read_mesh(&data_closed("high_genus_3")));
    let file = d.path("duplicates.off");
    write_off_text(&file, &mesh);
    lists_every_duplicate_face_and_non_manifold_edge(&file);
}

/// `info` on every invalid mesh of a manifest (at least `min_rows`): the problem counts
/// made here from the raw faces, the manifest's E and F, a hint and 1 to 5 examples per
/// group; open surfaces are described (exit 0) with their loops.
fn every_invalid_mesh_matches_raw_counts(
    meshes: &std::path::Path,
    rows: Vec<ManifestRow>,
    min_rows: usize,
) {
    let rows: Vec<_> = rows.into_iter().filter(|r| r.set == "invalid").collect();
    assert!(rows.len() >= min_rows, "only {} invalid meshes", rows.len());
    for r in rows {
        let path = meshes.join(&r.file);
        let mesh = contractible::io::read_tri_mesh(&path).unwrap();
        let (dups, nonmanifold) = raw_counts(&mesh);
        let open = r.name.starts_with("open_");
        let rep = info_json(&path, &[], if open { 0 } else { 2 });
        if open {
            // Surfaces with boundary are described, their loops counted.
            assert!(int(&rep, "boundary_loops") >= 1, "{}: {rep}", r.name);
            continue;
        }
        assert_eq!(
            problem_count(&rep, "duplicate_face") as usize,
            dups,
            "{}",
            r.name
        );
        assert_eq!(
            problem_count(&rep, "non_manifold_edge") as usize,
            nonmanifold,
            "{}",
            r.name
        );
        assert!(dups + nonmanifold > 0, "{}: nothing found", r.name);
        // V, F as in the manifest (E there counts distinct edges too).
        assert_eq!(int(&rep, "faces") as usize, r.f, "{}", r.name);
        assert_eq!(int(&rep, "edges") as usize, r.e, "{}", r.name);
        // Every group has a hint and at most 5 examples, each with a message.
        for p in rep["problems"].as_array().unwrap() {
            assert!(!p["hint"].as_str().unwrap().is_empty());
            let ex = p["examples"].as_array().unwrap();
            assert!(!ex.is_empty() && ex.len() <= 5, "{p}");
            assert!(ex
                .iter()
                .all(|e| !e["message"].as_str().unwrap().is_empty()));
        }
    }
}

/// The repository's invalid real meshes (a duplicate face, a non-manifold edge).
#[test]
fn every_invalid_in_repo_mesh_gets_a_multi_problem_report_matching_raw_counts() {
    every_invalid_mesh_matches_raw_counts(&data_meshes(), data_manifest(), 2);
}

#[test]
fn pinches_boundaries_and_degenerate_faces_are_listed_together() {
    let d = Scratch::new("multi-problem");
    // Two triangles pinched at vertex 1 (OBJ, 1-based), one degenerate face, and the
    // open boundary around them.
    let p = d.path("pinch.obj");
    std::fs::write(
        &p,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n# comment\nf 1 2 3\nf 2 4 5\nf 3 3 1\n",
    )
    .unwrap();
    let r = info_json(&p, &[], 2);
    assert_eq!(r["index_base"], 1);
    assert_eq!(problem_count(&r, "pinched_vertex"), 1, "{r}");
    assert_eq!(problem_count(&r, "degenerate_face"), 1, "{r}");
    assert_eq!(problem_count(&r, "boundary"), 1, "{r}");
    let text =
        String::from_utf8_lossy(&run(&[OsStr::new("info"), p.as_os_str()]).stdout).into_owned();
    // OBJ numbering: vertex 2 is where the sheets meet, face 3 is on line 9.
    assert!(
        text.contains("vertex 2: 2 surface sheets meet here"),
        "{text}"
    );
    assert!(
        text.contains("face 3 (line 9) uses vertex 3 twice"),
        "{text}"
    );
    assert!(text.contains("open surface, 1 boundary loop"), "{text}");
}

/// `q` quads of a cube as OBJ (1-based), with positions.
fn cube_quads_obj() -> String {
    let mut s = String::new();
    for i in 0..8 {
        writeln!(s, "v {} {} {}", i & 1, (i >> 1) & 1, (i >> 2) & 1).unwrap();
    }
    for q in crate::cli_common::CUBE_QUADS {
        writeln!(s, "f {} {} {} {}", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1).unwrap();
    }
    s
}

#[test]
fn polygon_files_are_described_refused_with_a_hint_or_triangulated() {
    let d = Scratch::new("polygons");
    let obj = d.path("cube.obj");
    std::fs::write(&obj, cube_quads_obj()).unwrap();
    // info describes the quads as they are.
    let r = info_json(&obj, &[], 0);
    assert_eq!(
        (int(&r, "vertices"), int(&r, "edges"), int(&r, "faces")),
        (8, 12, 6)
    );
    assert_eq!(int(&r, "euler_characteristic"), 2);
    assert_eq!(
        (r["orientable"].clone(), r["closed"].clone()),
        (true.into(), true.into())
    );
    assert_eq!(r["polygons"], true);
    // reduce refuses them, naming the first (1-based, with its line) and the flag.
    let out = run(&[OsStr::new("reduce"), obj.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(err.contains("line 9: face 1 has 4 corners"), "{err}");
    assert!(err.contains("--triangulate"), "{err}");
    // With --triangulate: 12 triangles, a sphere (independently: V - E + F = 8 - 18 + 12).
    let r = run_json(&["info", "--triangulate", obj.to_str().unwrap()]);
    assert_eq!(
        (int(&r, "vertices"), int(&r, "edges"), int(&r, "faces")),
        (8, 18, 12)
    );
    assert_eq!(int(&r, "triangulated_polygons"), 6);
    let r = run_json(&["reduce", "--triangulate", obj.to_str().unwrap()]);
    assert_eq!(r["component_list"][0]["vertices_out"], 4, "{r}");

    // OFF and PLY polygons too.
    let off = d.path("cube.off");
    run_ok(&[
        "convert",
        "--triangulate",
        obj.to_str().unwrap(),
        off.to_str().unwrap(),
    ]);
    let tri = contractible::io::read_tri_mesh(&off).unwrap();
    assert_eq!(tri.faces.len(), 12);
    // Each quad of a unit cube face has equal diagonals: cut along corners 0-2.
    assert_eq!(tri.faces[0], [0, 2, 3]);
    assert_eq!(tri.faces[1], [0, 3, 1]);
    let off_quads = d.path("quads.off");
    let mut s = String::from("OFF\n8 6 0\n");
    for i in 0..8 {
        writeln!(s, "{} {} {}", i & 1, (i >> 1) & 1, (i >> 2) & 1).unwrap();
    }
    s.push_str("4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n");
    std::fs::write(&off_quads, &s).unwrap();
    let out = run(&[OsStr::new("quad"), off_quads.as_os_str()]);
    assert!(
        stderr(&out).contains("line 11: face 0 has 4 corners"),
        "{}",
        stderr(&out)
    );
    let r = info_json(&off_quads, &[], 0);
    assert_eq!(int(&r, "faces"), 6);
}

#[test]
fn tri_quad_output_round_trips_through_info() {
    let d = Scratch::new("quad-round-trip");
    for name in ["round_stl", "high_genus_3", "bunny_npm"] {
        let input = data_closed(name);
        let t = run_json(&[OsStr::new("info"), input.as_os_str()]);
        let (v, e, f) = (int(&t, "vertices"), int(&t, "edges"), int(&t, "faces"));
        for ext in ["obj", "off"] {
            let out = d.path(&format!("{name}.{ext}"));
            run_ok(&[
                OsStr::new("quad"),
                input.as_os_str(),
                OsStr::new("-o"),
                out.as_os_str(),
            ]);
            let q = info_json(&out, &[], 0);
            // Independently: the pairing keeps V, halves F, and removes one edge per quad.
            assert_eq!(int(&q, "vertices"), v, "{name}.{ext}");
            assert_eq!(int(&q, "faces"), f / 2, "{name}.{ext}");
            assert_eq!(int(&q, "edges"), e - f / 2, "{name}.{ext}");
            assert_eq!(
                int(&q, "euler_characteristic"),
                int(&t, "euler_characteristic")
            );
            assert_eq!(q["orientable"], t["orientable"], "{name}.{ext}");
            assert_eq!(
                (q["closed"].clone(), q["polygons"].clone()),
                (true.into(), true.into())
            );
            assert_eq!((int(&q, "corners_min"), int(&q, "corners_max")), (4, 4));
        }
    }
}

#[test]
fn weld_with_a_tolerance_merges_near_copies_and_reports_collapsed_faces() {
    let d = Scratch::new("weld-eps");
    // A genus-2 surface whose vertices are at least 0.5 apart.
    let m = read_mesh(&genus_two_file(&d));
    let p = m.positions.as_ref().unwrap();
    // A soup whose copies of a vertex differ by up to 1e-9 (as float noise does).
    let mut s = String::new();
    let mut k = 0u32;
    for f in &m.faces {
        for &v in f {
            k += 1;
            let [x, y, z] = p[v as usize];
            let jitter = f64::from(k % 7) * 1e-10;
            writeln!(s, "v {} {y} {z}", x + jitter).unwrap();
        }
    }
    for i in 0..m.faces.len() {
        writeln!(s, "f {} {} {}", 3 * i + 1, 3 * i + 2, 3 * i + 3).unwrap();
    }
    let soup = d.path("noisy.obj");
    std::fs::write(&soup, &s).unwrap();
    let soup_s = soup.to_str().unwrap();
    // Exact welding leaves it open; within 1e-6 it is the genus-2 surface again.
    let exact = run(&["reduce", "--weld", soup_s]);
    assert_eq!(exact.status.code(), Some(2), "{}", stderr(&exact));
    let out = run_ok(&["info", "--weld=1e-6", soup_s]);
    let merged = 3 * m.faces.len() - m.vertex_count;
    assert!(
        stderr(&out).contains(&format!("--weld=0.000001 merged {merged} vertices within")),
        "{}",
        stderr(&out)
    );
    let r = run_json(&["info", "--weld=1e-6", soup_s]);
    assert_eq!(int(&r, "welded_vertices") as usize, merged);
    assert_eq!(int(&r, "euler_characteristic"), -2);
    assert_eq!(int(&r, "vertices") as usize, m.vertex_count);
    // A tolerance as large as the mesh collapses faces: an error naming them.
    let (lo, hi) = p
        .iter()
        .fold(([f64::MAX; 3], [f64::MIN; 3]), |(lo, hi), q| {
            (
                [lo[0].min(q[0]), lo[1].min(q[1]), lo[2].min(q[2])],
                [hi[0].max(q[0]), hi[1].max(q[1]), hi[2].max(q[2])],
            )
        });
    let diag = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2) + (hi[2] - lo[2]).powi(2)).sqrt();
    let huge = format!("--weld={}", 2.0 * diag);
    let out = run(&["reduce", &huge, soup_s]);
    assert_eq!(out.status.code(), Some(2));
    let err = stderr(&out);
    assert!(err.contains("faces became degenerate"), "{err}");
    assert!(err.contains("is degenerate"), "{err}");
    assert!(err.contains("(line "), "{err}");
    let r = info_json(&soup, &[&huge], 2);
    assert!(problem_count(&r, "degenerate_face") > 0, "{r}");
    // Not a distance: refused by the parser.
    let out = run(&["info", "--weld=-1", soup_s]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn standard_input_sniffing_bom_and_skipped_statements() {
    let tet = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n";
    // `-` reads standard input; the content names its format.
    let out = run_stdin(&["--json", "info", "-"], tet.as_bytes());
    assert!(out.status.success(), "{}", stderr(&out));
    let r: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!((int(&r, "vertices"), int(&r, "faces")), (4, 4));
    assert_eq!(r["file"], "<stdin>");
    // Gzip on standard input too.
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    gz.write_all(tet.as_bytes()).unwrap();
    let out = run_stdin(&["info", "--format", "off", "-"], &gz.finish().unwrap());
    assert!(out.status.success(), "{}", stderr(&out));
    // Content that names nothing: --format is needed, and said so.
    let obj = "# no statement tells\nf 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    let bare = "1 2 3\n";
    let out = run_stdin(&["info", "-"], bare.as_bytes());
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("<stdin>") && stderr(&out).contains("--format"),
        "{}",
        stderr(&out)
    );
    let out = run_stdin(&["--json", "info", "--format", "obj", "-"], obj.as_bytes());
    assert!(out.status.success(), "{}", stderr(&out));

    let d = Scratch::new("sniff");
    // OFF content under an .obj name: read as OFF, with a warning.
    let wrong = d.path("tet.obj");
    std::fs::write(&wrong, tet).unwrap();
    let out = run_ok(&[OsStr::new("info"), wrong.as_os_str()]);
    assert!(
        stderr(&out).contains("the content is OFF, not OBJ as the file name says"),
        "{}",
        stderr(&out)
    );
    // A UTF-8 BOM before OFF and OBJ.
    let bom = d.path("bom.off");
    std::fs::write(&bom, [b"\xEF\xBB\xBF".as_slice(), tet.as_bytes()].concat()).unwrap();
    let r = run_json(&[OsStr::new("info"), bom.as_os_str()]);
    assert_eq!(int(&r, "faces"), 4);
    let bom_obj = d.path("bom.obj");
    let obj_tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n";
    std::fs::write(
        &bom_obj,
        [b"\xEF\xBB\xBF".as_slice(), obj_tet.as_bytes()].concat(),
    )
    .unwrap();
    let out = run_ok(&[OsStr::new("info"), bom_obj.as_os_str()]);
    assert!(!stderr(&out).contains("warning"), "{}", stderr(&out));
    // Statements the reader does not use are counted in one warning.
    let skipped = d.path("skipped.obj");
    std::fs::write(
        &skipped,
        format!("vn 0 0 1\nl 1 2\nl 2 3\ncurv 0 1 1 2\n{obj_tet}p 1\n"),
    )
    .unwrap();
    let out = run_ok(&[OsStr::new("info"), skipped.as_os_str()]);
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("skipped 4 OBJ statements")
            && err.contains("`l` ×2 (first at line 2)")
            && err.contains("`curv` ×1")
            && err.contains("`p` ×1"),
        "{err}"
    );
}

/// `quad --algo ALGO` on `input` (a closed torus of `vertices` vertices and `faces`
/// faces), then `info --triangulate` on the quads, for the four initial-pairing
/// algorithms: a closed torus again each time. `scratch` names the working directory.
fn triangulated_quads_are_a_torus(input: &str, vertices: i64, faces: i64, scratch: &str) {
    let d = Scratch::new(scratch);
    let quads = d.path("quads.off");
    for algo in ["lrs", "ps", "sg", "matching"] {
        run_ok(&["quad", "--algo", algo, input, "-o", quads.to_str().unwrap()]);
        let r = run_json(&["info", "--triangulate", quads.to_str().unwrap()]);
        assert!(r.get("problems").is_none(), "{algo}: {r}");
        assert_eq!(r["orientable"], true, "{algo}: {r}");
        assert_eq!(int(&r["component_list"][0], "genus"), 1, "{algo}: {r}");
        let (v, e, f) = (int(&r, "vertices"), int(&r, "edges"), int(&r, "faces"));
        assert_eq!((v, f), (vertices, faces), "{algo}: {r}");
        assert_eq!(v - e + f, 0, "{algo}: {r}");
        assert_eq!(int(&r, "triangulated_polygons"), faces / 2, "{algo}");
    }
}

/// The duplicate faces a cut of every quad along its shorter diagonal alone would make
/// (an independent count on the quads `quad` writes: the reason the choice of diagonal
/// must also avoid existing edges).
fn shorter_diagonal_duplicates(input: &str, algo: &str, dir: &Scratch) -> usize {
    let quads = dir.path("plain.off");
    run_ok(&["quad", "--algo", algo, input, "-o", quads.to_str().unwrap()]);
    let text = std::fs::read_to_string(&quads).unwrap();
    let mut nums = text
        .lines()
        .skip(1)
        .flat_map(str::split_whitespace)
        .map(|x| x.parse::<f64>().unwrap());
    let mut next = || nums.next().unwrap();
    let (nv, nf, _) = (next() as usize, next() as usize, next());
    let p: Vec<[f64; 3]> = (0..nv).map(|_| [next(), next(), next()]).collect();
    let dist = |a: u32, b: u32| -> f64 {
        let (x, y) = (p[a as usize], p[b as usize]);
        (0..3).map(|k| (x[k] - y[k]).powi(2)).sum::<f64>()
    };
    let mut seen = std::collections::HashSet::new();
    let mut dups = 0;
    for _ in 0..nf {
        assert_eq!(next() as usize, 4);
        let [a, b, c, d] = [next(), next(), next(), next()].map(|x| x as u32);
        let cut = if dist(a, c) <= dist(b, d) {
            [[a, b, c], [a, c, d]]
        } else {
            [[a, b, d], [b, c, d]]
        };
        for mut t in cut {
            t.sort_unstable();
            dups += usize::from(!seen.insert(t));
        }
    }
    dups
}

/// `--triangulate` never folds a quad surface it can cut cleanly: on a coarse torus's
/// quads, cutting by the shorter diagonal alone gives duplicate faces and non-manifold
/// edges (checked here on a 24 × 6 grid torus whose tube is as thick as its hole is
/// wide); with the diagonal choice that avoids existing edges, the triangles are a
/// closed torus again (checked by `info`'s own validation, and V − E + F = 0 from its
/// counts).
#[test]
fn triangulating_quads_of_a_coarse_torus_gives_a_torus() {
    let d = Scratch::new("coarse_torus");
    let torus = d.path("torus.off");
    let (n, m) = (24, 6);
    contractible::io::write_mesh(&torus, &grid_torus(n, m, 2.0, 1.0)).unwrap();
    let input = torus.to_str().unwrap();
    let naive: Vec<usize> = ["lrs", "ps", "sg", "matching"]
        .iter()
        .map(|algo| shorter_diagonal_duplicates(input, algo, &d))
        .collect();
    assert!(naive.iter().any(|&x| x > 0), "{naive:?}");
    let v = i64::from(n * m);
    triangulated_quads_are_a_torus(input, v, 2 * v, "coarse_torus_quads");
}

/// Over the real-mesh corpus (ignored unless asked for: `-- --ignored ::corpus::`).
mod corpus {
    use super::*;
    use crate::cli_common::corpus_meshes;
    use crate::common::corpus_manifest;

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn info_lists_every_duplicate_face_and_non_manifold_edge_of_the_crank() {
        let file = corpus_meshes().join("invalid/dupfaces_crank.off.gz");
        // The manifest's notes: "12 duplicate faces, 24 non-manifold edges".
        let mesh = read_mesh(&file);
        assert_eq!(raw_counts(&mesh), (12, 24));
        assert_eq!(mesh.vertex_count, 49986);
        lists_every_duplicate_face_and_non_manifold_edge(&file);
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_invalid_mesh_gets_a_multi_problem_report_matching_raw_counts() {
        every_invalid_mesh_matches_raw_counts(&corpus_meshes(), corpus_manifest(), 7);
    }

    /// The coarse torus of the corpus (288 vertices, 576 faces): its quads cut by the
    /// shorter diagonal alone gave 48 duplicate faces and non-manifold edges.
    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn triangulating_quads_of_a_coarse_torus_gives_a_torus() {
        let input = corpus_meshes().join("closed/torus_288.off.gz");
        triangulated_quads_are_a_torus(
            input.to_str().unwrap(),
            288,
            576,
            "coarse_torus_quads-corpus",
        );
    }
}
