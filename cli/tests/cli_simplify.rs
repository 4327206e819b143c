//! `simplify` and the simplification part of `demo` through the binary. Every output is
//! read back and checked here without the simplifier: per component χ, orientability
//! and boundary loops computed from the face list by the test's own edge counting,
//! orientation propagation and boundary walking; the edges shorter than ε and the
//! shortest edge measured from the written positions. Bad inputs: exit code 2, the
//! message, nothing on stdout and no file (not even a temporary one) in the directory.

use crate::cli_common;
use crate::common::{find, union};

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::{OsStr, OsString};
use std::path::{Path, PathBuf};

use cli_common::{
    data_closed, data_invalid, int, read_mesh, run, run_json, run_ok, stderr, with_holes, Scratch,
};
use contractible::TriMesh;
use serde_json::Value;

/// (χ, orientable, boundary loops) of one component.
pub(crate) type Topo = (i64, bool, usize);

/// The sorted per-component topology of a face list. Panics unless every edge lies in
/// one or two faces and every boundary vertex on exactly two boundary edges.
pub(crate) fn topology(faces: &[[u32; 3]]) -> Vec<Topo> {
    // Edge -> the faces using it, with the direction each traverses it.
    let mut edges: BTreeMap<(u32, u32), Vec<(usize, bool)>> = BTreeMap::new();
    for (fi, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            assert_ne!(a, b, "face {fi} repeats a vertex");
            edges
                .entry((a.min(b), a.max(b)))
                .or_default()
                .push((fi, a < b));
        }
    }
    let mut parent: Vec<usize> = (0..faces.len()).collect();
    let mut adjacent: Vec<Vec<(usize, bool)>> = vec![Vec::new(); faces.len()];
    for (e, uses) in &edges {
        assert!(uses.len() <= 2, "edge {e:?} in {} faces", uses.len());
        if let [(f, df), (g, dg)] = uses[..] {
            union(&mut parent, f, g);
            // Coherent when the two faces run the edge in opposite directions.
            adjacent[f].push((g, df != dg));
            adjacent[g].push((f, df != dg));
        }
    }
    // Orientation: flip[f] such that every shared edge is run both ways.
    let mut flip: Vec<Option<bool>> = vec![None; faces.len()];
    let mut orientable: BTreeMap<usize, bool> = BTreeMap::new();
    for start in 0..faces.len() {
        if flip[start].is_some() {
            continue;
        }
        flip[start] = Some(false);
        let mut ok = true;
        let mut stack = vec![start];
        while let Some(f) = stack.pop() {
            let sf = flip[f].unwrap();
            for &(g, coherent) in &adjacent[f] {
                let want = if coherent { sf } else { !sf };
                match flip[g] {
                    None => {
                        flip[g] = Some(want);
                        stack.push(g);
                    }
                    Some(s) => ok &= s == want,
                }
            }
        }
        orientable.insert(find(&mut parent, start), ok);
    }
    // Per component: vertices, edges, faces, boundary loops.
    let mut vertices: BTreeMap<usize, BTreeSet<u32>> = BTreeMap::new();
    let mut counts: BTreeMap<usize, (i64, i64)> = BTreeMap::new();
    for (fi, f) in faces.iter().enumerate() {
        let r = find(&mut parent, fi);
        vertices.entry(r).or_default().extend(f);
        counts.entry(r).or_default().1 += 1;
    }
    let mut boundary: BTreeMap<u32, Vec<u32>> = BTreeMap::new();
    let mut root_of_vertex: BTreeMap<u32, usize> = BTreeMap::new();
    for (&(a, b), uses) in &edges {
        let r = find(&mut parent, uses[0].0);
        counts.entry(r).or_default().0 += 1;
        if uses.len() == 1 {
            boundary.entry(a).or_default().push(b);
            boundary.entry(b).or_default().push(a);
            root_of_vertex.insert(a, r);
        }
    }
    let mut loops: BTreeMap<usize, usize> = BTreeMap::new();
    let mut seen = BTreeSet::new();
    for (&v, nb) in &boundary {
        assert_eq!(nb.len(), 2, "vertex {v} on {} boundary edges", nb.len());
        if !seen.insert(v) {
            continue;
        }
        *loops.entry(root_of_vertex[&v]).or_default() += 1;
        let mut stack = vec![v];
        while let Some(x) = stack.pop() {
            for &y in &boundary[&x] {
                if seen.insert(y) {
                    stack.push(y);
                }
            }
        }
    }
    let mut out: Vec<Topo> = counts
        .iter()
        .map(|(r, &(e, f))| {
            let v = vertices[r].len() as i64;
            (v - e + f, orientable[r], loops.get(r).copied().unwrap_or(0))
        })
        .collect();
    out.sort_unstable();
    out
}

fn read(path: &Path) -> TriMesh {
    contractible::io::read_tri_mesh(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn edge_lengths(m: &TriMesh) -> Vec<f64> {
    let p = m.positions.as_ref().expect("positions");
    let mut seen = BTreeSet::new();
    let mut out = Vec::new();
    for f in &m.faces {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            if seen.insert((a.min(b), a.max(b))) {
                let (x, y) = (p[a as usize], p[b as usize]);
                out.push(
                    ((x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2) + (x[2] - y[2]).powi(2)).sqrt(),
                );
            }
        }
    }
    out
}

fn gen_iso(dir: &Scratch, file: &str, args: &[&str]) -> PathBuf {
    let out = dir.path(file);
    let mut all: Vec<&OsStr> = vec![OsStr::new("gen"), OsStr::new("isosurface")];
    all.extend(args.iter().map(OsStr::new));
    all.extend([OsStr::new("-o"), out.as_os_str()]);
    run_ok(&all);
    out
}

fn args_of(input: &Path, output: &Path, extra: &[&str]) -> Vec<OsString> {
    let mut all: Vec<OsString> = vec!["simplify".into(), input.into(), "-o".into(), output.into()];
    all.extend(extra.iter().map(OsString::from));
    all
}

/// Runs `simplify --json`, then checks the written file and the report against each
/// other and against the input, independently of the simplifier. Returns the report.
fn simplify_checked(input: &Path, output: &Path, extra: &[&str]) -> Value {
    let j = run_json(&args_of(input, output, extra));
    let what = format!("{} {extra:?}", input.display());
    let before = read(input);
    let after = read(output);
    let topo_before = topology(&before.faces);
    let topo_after = topology(&after.faces);
    assert_eq!(topo_after, topo_before, "{what}: topology changed");
    // The report.
    assert_eq!(j["file"], input.display().to_string());
    assert_eq!(j["output"], output.display().to_string());
    let used: BTreeSet<u32> = before.faces.iter().flatten().copied().collect();
    assert_eq!(int(&j, "vertices_in"), used.len() as i64, "{what}");
    assert_eq!(int(&j, "faces_in"), before.faces.len() as i64, "{what}");
    assert_eq!(int(&j, "vertices_out"), after.vertex_count as i64, "{what}");
    assert_eq!(int(&j, "faces_out"), after.faces.len() as i64, "{what}");
    assert!(int(&j, "faces_out") <= int(&j, "faces_in"), "{what}");
    assert!(int(&j, "vertices_out") <= int(&j, "vertices_in"));
    assert_eq!(int(&j, "components"), topo_before.len() as i64, "{what}");
    let loops: usize = topo_before.iter().map(|t| t.2).sum();
    assert_eq!(int(&j, "boundary_loops"), loops as i64, "{what}");
    // Every vertex written is used (the simplifier drops the others).
    let used_after: BTreeSet<u32> = after.faces.iter().flatten().copied().collect();
    assert_eq!(used_after.len(), after.vertex_count, "{what}");
    // The remaining short edges: reasons add up, none frozen, and their number is what
    // the written positions give.
    let rem = &j["remaining"];
    let by_reason = ["link_condition", "non_disc", "foldover", "frozen"]
        .map(|k| int(rem, k))
        .iter()
        .sum::<i64>();
    assert_eq!(int(rem, "frozen"), 0, "{what}");
    assert_eq!(int(&j, "short_edges_remaining"), by_reason, "{what}");
    let eps = j["eps"].as_f64().expect("eps");
    let lengths = edge_lengths(&after);
    let short = lengths.iter().filter(|&&l| l < eps).count();
    assert_eq!(int(&j, "short_edges_remaining"), short as i64, "{what}");
    let shortest = lengths.iter().copied().fold(f64::INFINITY, f64::min);
    // (Within rounding: the simplifier may compute the length another way.)
    let reported = j["shortest_remaining_edge"].as_f64().expect("an edge");
    assert!(
        (reported - shortest).abs() <= 1e-12 * shortest,
        "{what}: shortest edge {reported} reported, {shortest} measured"
    );
    // The skip counters are there.
    for k in ["link_condition", "non_disc", "foldover", "frozen"] {
        assert!(j["skipped"][k].is_u64(), "{what}: skipped.{k}");
    }
    for k in [
        "edges_contracted",
        "discs_removed",
        "vertices_removed_inside",
        "passes",
        "dropped_vertices",
    ] {
        assert!(j[k].is_u64(), "{what}: {k}");
    }
    for k in [
        "seconds",
        "seconds_read",
        "seconds_build",
        "seconds_verify",
        "seconds_write",
        "bbox_diagonal",
    ] {
        assert!(j[k].as_f64().is_some_and(|x| x >= 0.0), "{what}: {k}");
    }
    // ε: the given one, or the fraction of the diagonal of the used vertices' box.
    let p = before.positions.as_ref().unwrap();
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for &v in &used {
        for k in 0..3 {
            lo[k] = lo[k].min(p[v as usize][k]);
            hi[k] = hi[k].max(p[v as usize][k]);
        }
    }
    let diag = ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2) + (hi[2] - lo[2]).powi(2)).sqrt();
    let got_diag = j["bbox_diagonal"].as_f64().unwrap();
    assert!(
        (got_diag - diag).abs() <= 1e-12 * diag,
        "{what}: {got_diag} vs {diag}"
    );
    match j["eps_rel"].as_f64() {
        Some(rel) => assert!((eps - rel * diag).abs() <= 1e-12 * eps, "{what}"),
        None => assert!(j["eps_rel"].is_null()),
    }
    j
}

#[test]
fn simplifies_closed_and_open_isosurfaces_keeping_their_topology() {
    let d = Scratch::new("simplify-iso");
    let inputs = [
        gen_iso(
            &d,
            "genus2.off",
            &["--surface", "genus:2", "--resolution", "40"],
        ),
        gen_iso(
            &d,
            "torus.ply",
            &["--surface", "torus", "--tessellation", "bcc"],
        ),
        gen_iso(
            &d,
            "hyperboloid.obj",
            &["--surface", "hyperboloid", "--resolution", "30"],
        ),
    ];
    for input in &inputs {
        let name = input.file_name().unwrap().to_string_lossy().into_owned();
        for rel in ["0.01", "0.03"] {
            let mut contracted = Vec::new();
            for mode in ["naive", "nested"] {
                let out = d.path(&format!("{mode}-{rel}-{name}"));
                let j = simplify_checked(input, &out, &["--eps-rel", rel, "--mode", mode]);
                assert_eq!(j["mode"], mode);
                assert_eq!(j["side"], "count");
                assert_eq!(j["position"], "midpoint");
                assert_eq!(j["guard"], true);
                assert_eq!(j["eps_rel"].as_f64(), Some(rel.parse().unwrap()));
                assert!(
                    int(&j, "faces_out") < int(&j, "faces_in"),
                    "{name}: nothing simplified"
                );
                contracted.push(int(&j, "edges_contracted"));
            }
            assert!(
                contracted[1] >= contracted[0],
                "{name} {rel}: {contracted:?}"
            );
        }
    }
    // The open one really is open (two discs) and stays so.
    let j = simplify_checked(&inputs[2], &d.path("h.off"), &["--eps-rel", "0.02"]);
    assert_eq!(int(&j, "boundary_loops"), 2);
    assert_eq!(int(&j, "components"), 2);
}

#[test]
fn every_option_keeps_the_topology() {
    let d = Scratch::new("simplify-options");
    let input = gen_iso(
        &d,
        "g3.off",
        &["--surface", "genus:3", "--resolution", "48"],
    );
    for extra in [
        &["--side", "path"][..],
        &["--side", "euclidean"],
        &["--position", "quadric"],
        &["--allow-foldover"],
        &[
            "--mode",
            "naive",
            "--position",
            "quadric",
            "--allow-foldover",
        ],
    ] {
        let mut all = vec!["--eps-rel", "0.02"];
        all.extend_from_slice(extra);
        let j = simplify_checked(&input, &d.path("out.off"), &all);
        let has = |flag: &str, value: &str| extra.windows(2).any(|w| w[0] == flag && w[1] == value);
        if has("--side", "path") {
            assert_eq!(j["side"], "path");
        }
        if has("--side", "euclidean") {
            assert_eq!(j["side"], "euclidean");
        }
        if has("--position", "quadric") {
            assert_eq!(j["position"], "quadric");
        }
        if has("--mode", "naive") {
            assert_eq!(j["mode"], "naive");
        }
        if extra.contains(&"--allow-foldover") {
            assert_eq!(j["guard"], false);
            assert_eq!(int(&j["skipped"], "foldover"), 0, "{extra:?}");
            assert_eq!(int(&j["remaining"], "foldover"), 0, "{extra:?}");
        } else {
            assert_eq!(j["guard"], true);
        }
    }
}

#[test]
fn simplifies_real_meshes_closed_open_and_multi_component() {
    let d = Scratch::new("simplify-real");
    // The repository's real meshes (counts from its manifest), and its bunny with a hole.
    let open = d.path("open_bunny.off.gz");
    contractible::io::write_mesh(&open, &with_holes(&read_mesh(&data_closed("bunny_npm")), 1))
        .unwrap();
    for (input, components, loops) in [
        (data_closed("bunny_npm"), 1, 0),
        (data_closed("high_genus_3"), 1, 0),
        (data_closed("box_stl"), 10, 0),
        (open, 1, 1),
    ] {
        let file = input.display();
        for mode in ["naive", "nested"] {
            let out = d.path(&format!("{mode}.ply"));
            let j = simplify_checked(&input, &out, &["--eps-rel", "0.01", "--mode", mode]);
            assert_eq!(int(&j, "components"), components, "{file}");
            assert_eq!(int(&j, "boundary_loops"), loops, "{file}");
        }
    }
}

/// Concatenates meshes (positions and faces) into one multi-component mesh.
fn concat(parts: &[TriMesh]) -> TriMesh {
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for m in parts {
        let base = positions.len() as u32;
        positions.extend_from_slice(m.positions.as_ref().unwrap());
        faces.extend(m.faces.iter().map(|f| f.map(|v| v + base)));
    }
    TriMesh::with_positions(positions, faces)
}

#[test]
fn each_component_is_simplified_on_its_own() {
    let d = Scratch::new("simplify-multi");
    let torus = gen_iso(
        &d,
        "torus.off",
        &["--surface", "torus", "--resolution", "40"],
    );
    let sphere = gen_iso(
        &d,
        "sphere.off",
        &["--surface", "sphere", "--resolution", "24"],
    );
    let hyp = gen_iso(
        &d,
        "hyp.off",
        &["--surface", "hyperboloid", "--resolution", "24"],
    );
    let parts: Vec<TriMesh> = [&torus, &sphere, &hyp].iter().map(|p| read(p)).collect();
    let all = d.path("all.off");
    contractible::io::write_mesh(&all, &concat(&parts)).unwrap();
    // One absolute ε for all, so that each component sees the same ε alone and together.
    let eps = "0.06";
    let whole = simplify_checked(&all, &d.path("all-out.off"), &["--eps", eps]);
    assert_eq!(int(&whole, "components"), 4);
    assert_eq!(int(&whole, "boundary_loops"), 2);
    assert!(whole["eps_rel"].is_null());
    let mut outputs = Vec::new();
    let mut sums = BTreeMap::<&str, i64>::new();
    for (i, p) in [&torus, &sphere, &hyp].iter().enumerate() {
        let out = d.path(&format!("part{i}-out.off"));
        let j = simplify_checked(p, &out, &["--eps", eps]);
        for k in [
            "vertices_out",
            "faces_out",
            "edges_contracted",
            "discs_removed",
            "short_edges_remaining",
        ] {
            *sums.entry(k).or_default() += int(&j, k);
        }
        outputs.push(read(&out));
    }
    for (k, v) in &sums {
        assert_eq!(int(&whole, k), *v, "{k}");
    }
    // Component by component, in input order: the same faces at the same positions as
    // alone (vertex ids may differ: they follow the component's own numbering).
    let by_position = |m: &TriMesh| -> Vec<[[u64; 3]; 3]> {
        let p = m.positions.as_ref().unwrap();
        m.faces
            .iter()
            .map(|f| f.map(|v| p[v as usize].map(f64::to_bits)))
            .collect()
    };
    let together = read(&d.path("all-out.off"));
    let alone = concat(&outputs);
    assert_eq!(together.vertex_count, alone.vertex_count);
    assert!(by_position(&together) == by_position(&alone));
}

#[test]
fn eps_rel_and_the_matching_eps_agree_and_runs_are_deterministic() {
    let d = Scratch::new("simplify-eps");
    let input = gen_iso(
        &d,
        "g2.ply",
        &[
            "--surface",
            "genus:2",
            "--resolution",
            "40",
            "--tessellation",
            "bcc",
        ],
    );
    for ext in ["ply", "off"] {
        let a = d.path(&format!("a.{ext}"));
        let j = simplify_checked(&input, &a, &["--eps-rel", "0.015"]);
        // JSON numbers are printed to round-trip exactly.
        let eps = j["eps"].to_string();
        let b = d.path(&format!("b.{ext}"));
        let k = simplify_checked(&input, &b, &["--eps", &eps]);
        assert_eq!(k["eps"], j["eps"]);
        assert!(k["eps_rel"].is_null());
        for key in [
            "vertices_out",
            "faces_out",
            "edges_contracted",
            "discs_removed",
            "vertices_removed_inside",
            "skipped",
            "remaining",
            "passes",
            "shortest_remaining_edge",
        ] {
            assert_eq!(j[key], k[key], "{key}");
        }
        let (fa, fb) = (std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
        assert!(fa == fb, "--eps-rel and --eps outputs differ ({ext})");
        // The same command twice: byte-identical files.
        let c = d.path(&format!("c.{ext}"));
        run_ok(&args_of(&input, &c, &["--eps-rel", "0.015", "--quiet"]));
        assert!(std::fs::read(&c).unwrap() == fa, "nondeterministic ({ext})");
        let (n1, n2) = (d.path(&format!("n1.{ext}")), d.path(&format!("n2.{ext}")));
        for n in [&n1, &n2] {
            run_ok(&args_of(
                &input,
                n,
                &[
                    "--eps-rel",
                    "0.03",
                    "--side",
                    "euclidean",
                    "--position",
                    "quadric",
                ],
            ));
        }
        assert!(std::fs::read(&n1).unwrap() == std::fs::read(&n2).unwrap());
    }
}

#[test]
fn human_summary_and_quiet() {
    let d = Scratch::new("simplify-human");
    let input = gen_iso(&d, "t.off", &["--surface", "torus", "--resolution", "32"]);
    let out = d.path("o.off");
    let o = run_ok(&args_of(&input, &out, &["--eps-rel", "0.02"]));
    let text = String::from_utf8_lossy(&o.stdout);
    let m = read(&out);
    let before = read(&input);
    for want in [
        format!(
            "{} -> {}: nested mode, count side, midpoint positions, fold-over guard on",
            input.display(),
            out.display()
        ),
        format!(
            "  vertices {} -> {}, faces {} -> {}; 1 component, 0 boundary loops (kept, \
             checked independently)",
            before.vertex_count,
            m.vertex_count,
            before.faces.len(),
            m.faces.len()
        ),
        "  ε = ".into(),
        "(0.02 × the bounding-box diagonal ".into(),
        "  contractions ".into(),
        "  skipped (events over all passes): link condition ".into(),
        "  edges shorter than ε remaining: ".into(),
        "  shortest remaining edge ".into(),
        format!("wrote {}", out.display()),
    ] {
        assert!(text.contains(&want), "missing {want:?} in:\n{text}");
    }
    std::fs::remove_file(&out).unwrap();
    let o = run_ok(&args_of(&input, &out, &["--eps", "0.05", "--quiet"]));
    assert!(o.stdout.is_empty() && o.stderr.is_empty());
    assert!(out.exists());
}

/// Files in `dir` (names), to see that a failed run left nothing behind.
fn listing(dir: &Scratch) -> BTreeSet<String> {
    std::fs::read_dir(&dir.0)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

/// Runs `simplify` expecting exit code 2 with `want` in its one-line message, no stdout
/// and no new file.
fn refused(dir: &Scratch, input: &Path, extra: &[&str], want: &str) {
    let before = listing(dir);
    let out_path = dir.path("out.off");
    for json in [false, true] {
        let mut all = args_of(input, &out_path, extra);
        if json {
            all.insert(0, "--json".into());
        }
        let out = run(&all);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        if json {
            // With --json the error is a JSON object on stdout too.
            let v: serde_json::Value =
                serde_json::from_slice(&out.stdout).expect("one JSON value on stdout");
            assert_eq!(v["error"]["exit_code"], 2, "{v}");
            // "usage" for what the argument parser refuses, "input" for the rest.
            assert!(["input", "usage"].contains(&v["error"]["kind"].as_str().unwrap_or("")));
            let m = v["error"]["message"].as_str().expect("a message");
            let want = want.strip_prefix("error: ").unwrap_or(want);
            assert!(m.contains(want), "{extra:?}: {want:?} not in {m}");
        } else {
            assert!(out.stdout.is_empty(), "{extra:?}: stdout on error");
        }
        assert!(err.starts_with("error: "), "{err}");
        assert!(err.contains(want), "{extra:?}: {want:?} not in {err}");
        assert!(!out_path.exists(), "{extra:?}: wrote an output");
        assert_eq!(listing(dir), before, "{extra:?}: left a file behind");
    }
}

#[test]
fn bad_epsilon_is_refused() {
    let d = Scratch::new("simplify-bad-eps");
    let input = gen_iso(&d, "s.off", &["--surface", "sphere", "--resolution", "8"]);
    for (args, want) in [
        (
            &["--eps", "0"][..],
            "error: --eps 0.0: ε must be a finite number > 0",
        ),
        (
            &["--eps", "-1"],
            "error: --eps -1.0: ε must be a finite number > 0",
        ),
        (
            &["--eps", "nan"],
            "error: --eps NaN: ε must be a finite number > 0",
        ),
        (
            &["--eps", "inf"],
            "error: --eps inf: ε must be a finite number > 0",
        ),
        (
            &["--eps=-inf"],
            "error: --eps -inf: ε must be a finite number > 0",
        ),
        (
            &["--eps-rel", "0"],
            "error: --eps-rel 0.0: the fraction of the bounding-box diagonal must be a \
             finite number > 0",
        ),
        (
            &["--eps-rel", "-0.01"],
            "error: --eps-rel -0.01: the fraction of the bounding-box diagonal must be",
        ),
        (&["--eps-rel", "NaN"], "error: --eps-rel NaN: the fraction"),
        (
            &["--eps-rel", "1e308"],
            "error: --eps-rel 1e308 times the bounding-box diagonal",
        ),
    ] {
        refused(&d, &input, args, want);
    }
    // Exactly one of the two (clap's usage errors, also exit code 2).
    refused(&d, &input, &[], "--eps");
    refused(
        &d,
        &input,
        &["--eps", "1", "--eps-rel", "0.1"],
        "cannot be used with",
    );
}

/// `gen random` writes its surfaces without coordinates (every vertex at 0 0 0).
#[test]
fn missing_positions_are_refused() {
    let d = Scratch::new("simplify-no-positions");
    let random = d.path("random.off");
    run_ok(&[
        "gen",
        "random",
        "--genus",
        "2",
        "--faces",
        "500",
        "-o",
        random.to_str().unwrap(),
    ]);
    let n = read(&random).vertex_count;
    let want = format!(
        "{}: all {n} vertices are at the same point (0, 0, 0): the file carries no \
         coordinates (as `gen random` writes its surfaces); `simplify` needs vertex \
         positions",
        random.display()
    );
    refused(&d, &random, &["--eps", "1"], &want);
    refused(&d, &random, &["--eps-rel", "0.01"], &want);
    // Per format, a file without coordinates does not even parse.
    let ply = d.path("noz.ply");
    std::fs::write(
        &ply,
        "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n\
         element face 4\nproperty list uchar int vertex_indices\nend_header\n\
         0 0\n1 0\n0 1\n1 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n",
    )
    .unwrap();
    refused(
        &d,
        &ply,
        &["--eps", "1"],
        "noz.ply: line 3: bad header: `vertex` has no scalar property `z`",
    );
    let obj = d.path("short.obj");
    std::fs::write(&obj, "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
    refused(
        &d,
        &obj,
        &["--eps", "1"],
        "short.obj: line 1: missing value: expected z coordinate",
    );
}

const TETRA_FACES: &str = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

#[test]
fn non_finite_coordinates_are_refused() {
    let d = Scratch::new("simplify-non-finite");
    let off = d.path("nan.off");
    std::fs::write(
        &off,
        format!("OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n{TETRA_FACES}"),
    )
    .unwrap();
    refused(
        &d,
        &off,
        &["--eps", "0.5"],
        "nan.off: line 5: bad number \"nan\"",
    );
    let obj = d.path("inf.obj");
    std::fs::write(
        &obj,
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 -inf\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n",
    )
    .unwrap();
    refused(
        &d,
        &obj,
        &["--eps-rel", "0.1"],
        "inf.obj: line 4: bad number \"-inf\"",
    );
    // Binary PLY: the float NaN itself, located by byte offset.
    let ply = d.path("nan.ply");
    let mut bytes = b"ply\nformat binary_little_endian 1.0\nelement vertex 4\n\
property float x\nproperty float y\nproperty float z\nelement face 4\n\
property list uchar int vertex_indices\nend_header\n"
        .to_vec();
    let header = bytes.len();
    let coords = [
        [0.0f32, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, f32::NAN],
        [0.0, 0.0, 1.0],
    ];
    for c in coords {
        for x in c {
            bytes.extend_from_slice(&x.to_le_bytes());
        }
    }
    for f in [[0i32, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]] {
        bytes.push(3);
        for v in f {
            bytes.extend_from_slice(&v.to_le_bytes());
        }
    }
    std::fs::write(&ply, bytes).unwrap();
    // Vertex 2's z is the 9th float of the payload.
    let at = header + 8 * 4;
    refused(
        &d,
        &ply,
        &["--eps", "0.5"],
        &format!("nan.ply: byte offset {at}: bad number \"NaN\""),
    );
}

#[test]
fn non_manifold_and_unreadable_inputs_are_refused() {
    let d = Scratch::new("simplify-invalid");
    let bowtie = d.path("bowtie.off");
    std::fs::write(
        &bowtie,
        "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n",
    )
    .unwrap();
    refused(
        &d,
        &bowtie,
        &["--eps", "0.5"],
        "bowtie.off: vertex 0 is pinched: 4 boundary edges meet there",
    );
    // A real mesh, two boxes sharing an edge: its one non-manifold edge (found here by
    // counting) lies in 4 faces, located by its first face and that face's line.
    let two_cubes = data_invalid("shared_edge_stl");
    let mesh = read_mesh(&two_cubes);
    let mut uses: BTreeMap<(u32, u32), Vec<usize>> = BTreeMap::new();
    for (i, f) in mesh.faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            uses.entry((a.min(b), a.max(b))).or_default().push(i);
        }
    }
    let crowded: Vec<_> = uses.iter().filter(|(_, fs)| fs.len() > 2).collect();
    assert_eq!(crowded.len(), 1, "{crowded:?}");
    let (&(a, b), faces) = crowded[0];
    assert_eq!(faces.len(), 4);
    let line = mesh.vertex_count + 3 + faces[0];
    let mut text = String::new();
    std::io::Read::read_to_string(
        &mut flate2::read::GzDecoder::new(std::fs::File::open(&two_cubes).unwrap()),
        &mut text,
    )
    .unwrap();
    let [x, y, z] = mesh.faces[faces[0]];
    assert_eq!(
        text.lines().nth(line - 1).map(str::trim),
        Some(format!("3 {x} {y} {z}").as_str())
    );
    refused(
        &d,
        &two_cubes,
        &["--eps-rel", "0.01"],
        &format!(
            "{}: edge [{a}, {b}] is non-manifold, shared by 4 faces (first: face {} (line {}))",
            two_cubes.display(),
            faces[0],
            line
        ),
    );
    let missing = d.path("missing.off");
    refused(&d, &missing, &["--eps", "1"], "missing.off: I/O error");
    let garbage = d.path("garbage.off");
    std::fs::write(&garbage, "OFF\n3 1 0\n0 0 0\n1 0\n").unwrap();
    refused(&d, &garbage, &["--eps", "1"], "garbage.off: line ");
    let empty = d.path("empty.off");
    std::fs::write(&empty, "OFF\n0 0 0\n").unwrap();
    refused(
        &d,
        &empty,
        &["--eps", "1"],
        "empty.off: the mesh has no faces",
    );
    // An output name without a known format, before any work.
    let input = gen_iso(&d, "s.off", &["--surface", "sphere", "--resolution", "8"]);
    let before = listing(&d);
    let o = run(&[
        OsStr::new("simplify"),
        input.as_os_str(),
        OsStr::new("-o"),
        d.path("out.xyz").as_os_str(),
        OsStr::new("--eps"),
        OsStr::new("1"),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(listing(&d), before);
}

#[test]
fn demo_simplifies_its_isosurfaces_with_both_modes() {
    let j = run_json(&["demo", "--algos", "rs"]);
    assert_eq!(j["verified"], true);
    let simplified = j["simplified"].as_array().expect("simplified");
    assert_eq!(simplified.len(), 2);
    for s in simplified {
        let runs = s["runs"].as_array().expect("runs");
        let modes: Vec<&str> = runs.iter().map(|r| r["mode"].as_str().unwrap()).collect();
        assert_eq!(modes, ["naive", "nested"]);
        assert_eq!(s["eps_rel"].as_f64(), Some(0.01));
        for r in runs {
            assert_eq!(r["verified"], true);
            assert!(int(r, "faces_out") < int(r, "faces_in"));
            assert_eq!(int(r, "faces_in"), int(&s["info"], "faces"));
            assert_eq!(int(r, "components"), int(&s["info"], "components"));
        }
        assert!(int(&runs[1], "edges_contracted") >= int(&runs[0], "edges_contracted"));
    }
    assert_eq!(int(&simplified[1]["info"], "boundary_loops"), 2);
    let out = run_ok(&["demo", "--algos", "rs"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("all simplifications kept every component's χ, orientability and"),
        "{text}"
    );
    assert!(text.contains("simplify at ε = "), "{text}");
}
