//! `contractible check`: the library's verdict (`contractible::check`) on files, exit
//! codes 0 (a correct output), 1 (wrong, every reason printed) and 2 (unreadable files,
//! an input the task refuses), and the JSON report equal to the library's verdict.

use contractible::check;

use crate::cli_common::{data_closed, read_mesh, run, run_json, stderr, write_off_text, Scratch};

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
