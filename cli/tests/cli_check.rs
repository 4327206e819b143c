//! `contractible check`: the library's verdict (`contractible::check`) on files, exit
//! codes 0 (a correct output), 1 (wrong, every reason printed) and 2 (unreadable files,
//! an input the task refuses), and the JSON report equal to the library's verdict.

use contractible::check;

use crate::cli_common::{
    data_closed, gen_file, grid_torus, read_mesh, run, run_json, stderr, with_holes,
    write_off_text, Scratch,
};

#[test]
fn check_reduce_accepts_our_reduction_and_names_what_is_wrong_with_others() {
    let d = Scratch::new("check-reduce");
    let input = data_closed("bunny_npm");
    let out = d.path("r.off");
    let r = run(&[
        "reduce",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "-q",
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    // Our output: exit 0, and the same verdict as the library's.
    let ok = run(&[
        "check",
        "reduce",
        input.to_str().unwrap(),
        out.to_str().unwrap(),
    ]);
    assert_eq!(ok.status.code(), Some(0), "{}", stderr(&ok));
    assert!(String::from_utf8_lossy(&ok.stdout).contains("a correct reduce output"));
    let j = run_json(&[
        "check",
        "reduce",
        input.to_str().unwrap(),
        out.to_str().unwrap(),
    ]);
    assert_eq!(j["passed"], true);
    assert_eq!(j["failures"].as_array().map(Vec::len), Some(0));
    // The input as its own answer: reducible; exit 1, the reasons listed with their edges,
    // the count of all, as the library says.
    let mesh = read_mesh(&input);
    let verdict = check::reduce(&mesh, &mesh).expect("a closed input");
    let bad = run(&[
        "check",
        "--json",
        "reduce",
        input.to_str().unwrap(),
        input.to_str().unwrap(),
    ]);
    assert_eq!(bad.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&bad.stdout).expect("JSON");
    assert_eq!(j["passed"], false);
    let listed = j["failures"].as_array().expect("failures");
    assert_eq!(listed.len(), verdict.failures.len());
    assert_eq!(listed.len(), 20, "at most 20 of a kind");
    for (a, b) in listed.iter().zip(&verdict.failures) {
        assert_eq!(a["kind"], "contractible_edge");
        assert_eq!(a["message"], b.message.as_str());
        let e = b.edge.expect("located");
        assert_eq!(a["edge"], serde_json::json!(e));
    }
    assert_eq!(
        j["counts"]["contractible_edge"].as_u64(),
        Some(verdict.counts[0].1 as u64)
    );
    let human = run(&[
        "check",
        "reduce",
        input.to_str().unwrap(),
        input.to_str().unwrap(),
    ]);
    assert_eq!(human.status.code(), Some(1));
    let text = String::from_utf8_lossy(&human.stdout);
    assert!(text.contains("not a correct reduce output"), "{text}");
    assert!(text.contains(&format!(
        "... and {} more contractible_edge",
        verdict.counts[0].1 - 20
    )));
    assert!(stderr(&human).contains("fails the reduce check"));
    // A wrong surface: the reduction with a position moved.
    let mut moved = read_mesh(&out);
    let v = moved.faces[0][0] as usize;
    moved.positions.as_mut().expect("positions")[v][0] += 0.5;
    let moved_path = d.path("moved.off");
    write_off_text(&moved_path, &moved);
    let j = run(&[
        "check",
        "--json",
        "reduce",
        input.to_str().unwrap(),
        moved_path.to_str().unwrap(),
    ]);
    assert_eq!(j.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&j.stdout).expect("JSON");
    assert!(
        j["counts"].get("unknown_vertex").is_some() || j["counts"].get("moved_vertex").is_some(),
        "{j}"
    );
}

#[test]
fn check_reduce_exits_2_on_unreadable_files_and_inputs_reduce_refuses() {
    let d = Scratch::new("check-errors");
    let input = data_closed("bunny_npm");
    let missing = d.path("missing.off");
    let r = run(&[
        "check",
        "reduce",
        input.to_str().unwrap(),
        missing.to_str().unwrap(),
    ]);
    assert_eq!(r.status.code(), Some(2));
    assert!(stderr(&r).contains("missing.off"), "{}", stderr(&r));
    // An open input: `reduce` refuses it, so there is nothing to judge.
    let mut open = read_mesh(&input);
    open.faces.remove(0);
    let open_path = d.path("open.off");
    write_off_text(&open_path, &open);
    let r = run(&[
        "check",
        "--json",
        "reduce",
        open_path.to_str().unwrap(),
        input.to_str().unwrap(),
    ]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    let j: serde_json::Value = serde_json::from_slice(&r.stdout).expect("JSON");
    assert_eq!(j["error"]["kind"], "input");
}

/// The JSON verdict of `check` on two files equals the library's on the meshes.
fn same_as_library(j: &serde_json::Value, verdict: &check::Verdict) {
    assert_eq!(j["task"], verdict.task);
    assert_eq!(j["passed"], verdict.passed());
    let listed = j["failures"].as_array().expect("failures");
    assert_eq!(listed.len(), verdict.failures.len());
    for (a, b) in listed.iter().zip(&verdict.failures) {
        assert_eq!(a["kind"], b.kind.name());
        assert_eq!(a["message"], b.message.as_str());
        assert_eq!(a["edge"], serde_json::json!(b.edge), "{a}");
        assert_eq!(a["face"], serde_json::json!(b.face), "{a}");
    }
    for &(k, n) in &verdict.counts {
        assert_eq!(j["counts"][k.name()].as_u64(), Some(n as u64));
    }
}

#[test]
fn check_simplify_accepts_our_simplifications_and_names_short_edges_left() {
    let d = Scratch::new("check-simplify");
    // A closed surface and one with boundary (a torus with three holes).
    let torus = grid_torus(40, 16, 1.0, 0.3);
    let closed = d.path("torus.off");
    write_off_text(&closed, &torus);
    let holed = d.path("holed.off");
    write_off_text(&holed, &with_holes(&torus, 3));
    for input in [closed, holed] {
        let name = input.display().to_string();
        for (mode, position, foldover) in [
            ("naive", "midpoint", false),
            ("nested", "midpoint", false),
            ("naive", "quadric", true),
        ] {
            let out = d.path("s.off");
            let mut args = vec![
                "simplify",
                input.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "--eps-rel",
                "0.05",
                "--mode",
                mode,
                "--position",
                position,
                "-q",
            ];
            if foldover {
                args.push("--allow-foldover");
            }
            let r = run(&args);
            assert!(r.status.success(), "{}", stderr(&r));
            let mut check_args = vec![
                "check",
                "simplify",
                input.to_str().unwrap(),
                out.to_str().unwrap(),
                "--eps-rel",
                "0.05",
                "--position",
                position,
            ];
            if foldover {
                check_args.push("--allow-foldover");
            }
            let ok = run(&check_args);
            assert_eq!(ok.status.code(), Some(0), "{name} {mode}: {}", stderr(&ok));
            assert!(String::from_utf8_lossy(&ok.stdout).contains("a correct simplify output"));
        }
        // The input as its own answer: short edges left; exit 1, as the library says.
        let mesh = read_mesh(&input);
        let verdict = check::simplify(&mesh, &mesh, &check::SimplifyCheck::relative(0.05))
            .expect("a valid input");
        assert!(!verdict.passed());
        let bad = run(&[
            "check",
            "--json",
            "simplify",
            input.to_str().unwrap(),
            input.to_str().unwrap(),
            "--eps-rel",
            "0.05",
        ]);
        assert_eq!(bad.status.code(), Some(1), "{name}");
        let j: serde_json::Value = serde_json::from_slice(&bad.stdout).expect("JSON");
        same_as_library(&j, &verdict);
        assert!(j["counts"]["short_contractible_edge"].as_u64() > Some(0));
        // An absolute ε below every edge: nothing left to contract.
        let tiny = run(&[
            "check",
            "simplify",
            input.to_str().unwrap(),
            input.to_str().unwrap(),
            "--eps",
            "1e-9",
        ]);
        assert_eq!(tiny.status.code(), Some(0), "{}", stderr(&tiny));
    }
    // A face taken out of a simplification: one boundary loop more.
    let input = d.path("torus.off");
    let out = d.path("s2.off");
    let r = run(&[
        "simplify",
        input.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--eps",
        "0.1",
        "-q",
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    let mut holed = read_mesh(&out);
    holed.faces.remove(0);
    let holed_path = d.path("s2-holed.off");
    write_off_text(&holed_path, &holed);
    let verdict = check::simplify(
        &read_mesh(&input),
        &holed,
        &check::SimplifyCheck::absolute(0.1),
    )
    .expect("a valid input");
    let j = run(&[
        "check",
        "--json",
        "simplify",
        input.to_str().unwrap(),
        holed_path.to_str().unwrap(),
        "--eps",
        "0.1",
    ]);
    assert_eq!(j.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&j.stdout).expect("JSON");
    same_as_library(&j, &verdict);
    assert!(j["counts"]["surface_changed"].as_u64() == Some(1), "{j}");
}

#[test]
fn check_simplify_exits_2_without_eps_and_on_inputs_simplify_refuses() {
    let d = Scratch::new("check-simplify-errors");
    let input = data_closed("bunny_npm");
    let i = input.to_str().unwrap();
    // No ε; an ε for reduce; two of them; a bad one.
    for args in [
        vec!["check", "simplify", i, i],
        vec!["check", "reduce", i, i, "--eps", "0.1"],
        vec![
            "check",
            "simplify",
            i,
            i,
            "--eps",
            "0.1",
            "--eps-rel",
            "0.1",
        ],
        vec!["check", "simplify", i, i, "--eps", "0"],
        vec!["check", "simplify", i, i, "--eps-rel", "nan"],
    ] {
        let r = run(&args);
        assert_eq!(r.status.code(), Some(2), "{args:?}: {}", stderr(&r));
    }
    // Faces that are no surface: `simplify` refuses them.
    let mut bad = read_mesh(&input);
    bad.faces.push(bad.faces[0]);
    let bad_path = d.path("bad.off");
    write_off_text(&bad_path, &bad);
    let r = run(&[
        "check",
        "--json",
        "simplify",
        bad_path.to_str().unwrap(),
        i,
        "--eps",
        "0.1",
    ]);
    assert_eq!(r.status.code(), Some(2), "{}", stderr(&r));
    let j: serde_json::Value = serde_json::from_slice(&r.stdout).expect("JSON");
    assert_eq!(j["error"]["kind"], "input");
}

#[test]
fn check_quad_judges_the_files_quad_writes_with_and_without_k() {
    let d = Scratch::new("check-quad");
    // LRS flips edges on this genus-2 surface (asserted below): without K its quads are
    // not pairs of input faces.
    let input = gen_file(
        &d,
        "g2.off",
        &["random", "--genus", "2", "--faces", "300", "--seed", "1"],
    );
    let (out, k, pairs) = (d.path("q.off"), d.path("k.off"), d.path("p.txt"));
    let s = |p: &std::path::Path| p.to_str().unwrap().to_owned();
    let conv = run_json(&[
        "quad",
        &s(&input),
        "--algo",
        "lrs",
        "-o",
        &s(&out),
        "--triangles",
        &s(&k),
        "--pairs",
        &s(&pairs),
    ]);
    assert!(conv["flips"].as_u64().unwrap_or(0) > 0, "{conv}");
    assert_eq!(conv["triangles"], s(&k));
    let full = [
        "check",
        "quad",
        &s(&input),
        &s(&out),
        "--triangles",
        &s(&k),
        "--pairs",
        &s(&pairs),
    ];
    let ok = run(&full);
    assert_eq!(ok.status.code(), Some(0), "{}", stderr(&ok));
    assert!(String::from_utf8_lossy(&ok.stdout).contains("a correct quad output"));
    // Without K: exit 1, the verdict the library gives on the same meshes.
    let mesh = read_mesh(&input);
    let quads = contractible::io::read_poly_mesh(&out, None)
        .expect("reads")
        .mesh;
    let quads = contractible::QuadMesh {
        vertex_count: quads.vertex_count,
        positions: quads.positions.clone(),
        faces: quads.faces().map(|f| [f[0], f[1], f[2], f[3]]).collect(),
    };
    let verdict = check::quad(&mesh, &quads, &check::QuadCheck::default()).expect("closed");
    assert!(!verdict.passed());
    let bare = run(&["check", "--json", "quad", &s(&input), &s(&out)]);
    assert_eq!(bare.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&bare.stdout).expect("JSON");
    same_as_library(&j, &verdict);
    assert!(j["failures"][0]["message"]
        .as_str()
        .is_some_and(|m| m.contains("must state the triangulation")));
    // Pairs swapped: exit 1 naming the pair.
    let text = std::fs::read_to_string(&pairs).expect("pairs");
    let mut lines: Vec<&str> = text.lines().collect();
    lines.swap(0, 1);
    let swapped = d.path("swapped.txt");
    std::fs::write(&swapped, lines.join("\n")).expect("writes");
    let r = run(&[
        "check",
        "--json",
        "quad",
        &s(&input),
        &s(&out),
        "--triangles",
        &s(&k),
        "--pairs",
        &s(&swapped),
    ]);
    assert_eq!(r.status.code(), Some(1));
    let r: serde_json::Value = serde_json::from_slice(&r.stdout).expect("JSON");
    assert_eq!(r["passed"], false);
    assert_eq!(r["failures"][0]["kind"], "wrong_pair");
    assert_eq!(r["failures"][0]["face"], 0);
}

#[test]
fn check_quad_exits_2_on_files_it_cannot_read_as_an_answer() {
    let d = Scratch::new("check-quad-errors");
    let input = data_closed("bunny_npm");
    let s = |p: &std::path::Path| p.to_str().unwrap().to_owned();
    let (out, pairs) = (d.path("q.off"), d.path("p.txt"));
    let r = run(&[
        "quad",
        &s(&input),
        "--algo",
        "matching",
        "-o",
        &s(&out),
        "-q",
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    // A triangle mesh is no quad answer: located.
    let r = run(&["check", "quad", &s(&input), &s(&input)]);
    assert_eq!(r.status.code(), Some(2));
    assert!(stderr(&r).contains("has 3 corners"), "{}", stderr(&r));
    // A malformed pairs file: its line.
    std::fs::write(&pairs, "0 1\n2 x\n").expect("writes");
    let r = run(&["check", "quad", &s(&input), &s(&out), "--pairs", &s(&pairs)]);
    assert_eq!(r.status.code(), Some(2));
    assert!(stderr(&r).contains("p.txt:2:"), "{}", stderr(&r));
    // Options of another task.
    let r = run(&["check", "quad", &s(&input), &s(&out), "--eps", "0.1"]);
    assert_eq!(r.status.code(), Some(2));
    assert!(
        stderr(&r).contains("--eps is an option of `check simplify`"),
        "{}",
        stderr(&r)
    );
    let r = run(&[
        "check",
        "reduce",
        &s(&input),
        &s(&input),
        "--pairs",
        &s(&pairs),
    ]);
    assert_eq!(r.status.code(), Some(2));
    assert!(
        stderr(&r).contains("--pairs is an option of `check quad`"),
        "{}",
        stderr(&r)
    );
    // `quad --triangles -` is refused before any work.
    let r = run(&["quad", &s(&input), "--triangles", "-"]);
    assert_eq!(r.status.code(), Some(2));
    assert!(
        stderr(&r).contains("--triangles writes a mesh file"),
        "{}",
        stderr(&r)
    );
}

#[test]
fn check_decimate_judges_the_files_decimate_writes_with_its_maps() {
    let d = Scratch::new("check-decimate");
    let input = data_closed("bunny_npm");
    let s = |p: &std::path::Path| p.to_str().unwrap().to_owned();
    let (out, maps) = (d.path("d.off"), d.path("d.maps"));
    let r = run(&[
        "decimate",
        &s(&input),
        "--keep",
        "0.2",
        "-o",
        &s(&out),
        "--maps",
        &s(&maps),
        "-q",
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    let ok = run(&[
        "check",
        "decimate",
        &s(&input),
        &s(&out),
        "--keep",
        "0.2",
        "--maps",
        &s(&maps),
    ]);
    assert_eq!(ok.status.code(), Some(0), "{}", stderr(&ok));
    // Judged against a larger target: gone past it; the JSON is the library's verdict.
    let mesh = read_mesh(&input);
    let output = read_mesh(&out);
    let verdict = check::decimate(
        &mesh,
        &output,
        &check::DecimateCheck {
            keep: Some(0.5),
            ..check::DecimateCheck::default()
        },
    )
    .expect("judged");
    let bad = run(&[
        "check",
        "--json",
        "decimate",
        &s(&input),
        &s(&out),
        "--keep",
        "0.5",
    ]);
    assert_eq!(bad.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&bad.stdout).expect("JSON");
    same_as_library(&j, &verdict);
    assert_eq!(j["failures"][0]["kind"], "target_missed");
    // Maps edited: the first two vertex_map entries swapped.
    let text = std::fs::read_to_string(&maps).expect("maps");
    let mut doc: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let vm = doc["vertex_map"].as_array_mut().expect("vertex_map");
    vm.swap(0, 1);
    let edited = d.path("edited.maps");
    std::fs::write(&edited, doc.to_string()).expect("writes");
    let r = run(&[
        "check",
        "--json",
        "decimate",
        &s(&input),
        &s(&out),
        "--keep",
        "0.2",
        "--maps",
        &s(&edited),
    ]);
    assert_eq!(r.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&r.stdout).expect("JSON");
    assert_eq!(j["failures"][0]["kind"], "inconsistent_map");
    // The input as its own answer of an unguarded run: edges it could still collapse.
    let r = run(&[
        "check",
        "--json",
        "decimate",
        &s(&input),
        &s(&input),
        "--keep",
        "0.2",
        "--allow-foldover",
    ]);
    assert_eq!(r.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&r.stdout).expect("JSON");
    assert!(j["failures"][0]["edge"].is_array());
    // A maps file that is no maps document, and options of other tasks: exit 2.
    std::fs::write(&edited, "{\"vertex_map\": [0, -3]}").expect("writes");
    let r = run(&[
        "check",
        "decimate",
        &s(&input),
        &s(&out),
        "--maps",
        &s(&edited),
    ]);
    assert_eq!(r.status.code(), Some(2));
    assert!(
        stderr(&r).contains("vertex_map: entry 1 is -3"),
        "{}",
        stderr(&r)
    );
    let r = run(&["check", "decimate", &s(&input), &s(&out), "--eps", "0.1"]);
    assert_eq!(r.status.code(), Some(2));
    let r = run(&["check", "reduce", &s(&input), &s(&out), "--keep", "0.1"]);
    assert_eq!(r.status.code(), Some(2));
    assert!(
        stderr(&r).contains("--keep is an option of `check decimate`"),
        "{}",
        stderr(&r)
    );
}

#[test]
fn reduce_history_is_the_library_s_contractions_and_check_replays_it() {
    let d = Scratch::new("check-reduce-history");
    let input = data_closed("bunny_npm");
    let (out, steps) = (d.path("r.off"), d.path("steps.txt"));
    let s = |p: &std::path::Path| p.to_str().unwrap().to_string();
    let r = run(&[
        "reduce",
        &s(&input),
        "-o",
        &s(&out),
        "--history",
        &s(&steps),
        "-q",
    ]);
    assert!(r.status.success(), "{}", stderr(&r));
    // The file is the library's `contractions()`, one `KEPT REMOVED` line each.
    let mesh = read_mesh(&input);
    let ours = contractible::reduce(&mesh, &Default::default()).expect("reduces");
    let text = std::fs::read_to_string(&steps).expect("written");
    let lines: Vec<String> = ours
        .contractions()
        .iter()
        .map(|[u, v]| format!("{u} {v}"))
        .collect();
    assert_eq!(text.lines().collect::<Vec<_>>(), lines);
    assert!(!lines.is_empty());
    // `--history -` writes the same lines to stdout.
    let piped = run(&["reduce", &s(&input), "--history", "-", "-q"]);
    assert_eq!(String::from_utf8_lossy(&piped.stdout), text);
    let both = run(&[
        "reduce",
        &s(&input),
        "-o",
        "-",
        "--output-format",
        "off",
        "--history",
        "-",
    ]);
    assert_eq!(both.status.code(), Some(2), "{}", stderr(&both));

    // The replay passes, as the library's verdict says.
    let ok = run_json(&[
        "check",
        "reduce",
        &s(&input),
        &s(&out),
        "--history",
        &s(&steps),
    ]);
    assert_eq!(ok["passed"], true, "{ok}");
    // A step moved to the end: the same verdict as the library's, exit 1.
    let mut moved = ours.contractions();
    let first = moved.remove(0);
    moved.push(first);
    let edited = d.path("moved.txt");
    let body: String = moved.iter().map(|[u, v]| format!("{u} {v}\n")).collect();
    std::fs::write(&edited, body).unwrap();
    let verdict = check::reduce_history(&mesh, &read_mesh(&out), &moved).expect("closed");
    assert!(!verdict.passed());
    let bad = run(&[
        "check",
        "--json",
        "reduce",
        &s(&input),
        &s(&out),
        "--history",
        &s(&edited),
    ]);
    assert_eq!(bad.status.code(), Some(1));
    let j: serde_json::Value = serde_json::from_slice(&bad.stdout).expect("JSON");
    let listed = j["failures"].as_array().expect("failures");
    assert_eq!(listed.len(), verdict.failures.len());
    for (a, b) in listed.iter().zip(&verdict.failures) {
        assert_eq!(a["kind"], b.kind.name());
        assert_eq!(a["message"], b.message.as_str());
    }
    // A line that is not two ids, and the option on another task: exit 2.
    std::fs::write(&edited, "3 4\n5\n").unwrap();
    let junk = run(&[
        "check",
        "reduce",
        &s(&input),
        &s(&out),
        "--history",
        &s(&edited),
    ]);
    assert_eq!(junk.status.code(), Some(2));
    assert!(
        stderr(&junk).contains(":2: expected two vertex ids"),
        "{}",
        stderr(&junk)
    );
    let other = run(&[
        "check",
        "quad",
        &s(&input),
        &s(&out),
        "--history",
        &s(&steps),
    ]);
    assert_eq!(other.status.code(), Some(2));
    assert!(stderr(&other).contains("--history is an option of `check reduce`"));
}
