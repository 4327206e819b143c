//! `contractible batch`: one line per file in input order, the task's own report (equal
//! to the single-file command's), located errors that never stop the batch, outputs
//! under OUTDIR, `--resume`, and the same lines whatever `--jobs`.

use std::path::{Path, PathBuf};

use serde_json::Value;

use crate::cli_common::{
    data_closed, data_meshes, read_mesh, run, run_json, stderr, untimed, with_duplicate_faces,
    write_off_text, Scratch,
};

/// The lines of a JSON-lines text.
fn lines(text: &str) -> Vec<Value> {
    text.lines()
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect()
}

/// Every mesh file of `dir` (one level), sorted: what batch must list.
fn files_of(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("dir")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.to_string_lossy().ends_with(".off.gz"))
        .collect();
    v.sort();
    v
}

/// `batch --task reduce` over a folder of meshes (`closed/` and `invalid/` below it): one
/// line per file in sorted order, the invalid ones failing with a located input error
/// (exit code 1 for the batch, with a summary), the valid ones irreducible, and each
/// result equal to the single-file command's for the files named in `spread`. At least
/// `min_files` files are checked; `scratch` names the working directory.
fn reduce_over_a_mesh_folder(meshes: &Path, spread: &[&str], min_files: usize, scratch: &str) {
    let d = Scratch::new(scratch);
    let jsonl = d.path("r.jsonl");
    let out = run(&[
        "batch".as_ref(),
        meshes.as_os_str(),
        "--task".as_ref(),
        "reduce".as_ref(),
        "--jsonl".as_ref(),
        jsonl.as_os_str(),
        "-j".as_ref(),
        "2".as_ref(),
    ]);
    // Some files are invalid: exit 1, with a summary.
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(stderr(&out).contains("files failed"), "{}", stderr(&out));
    let got = lines(&std::fs::read_to_string(&jsonl).expect("jsonl"));
    let mut expected: Vec<PathBuf> = files_of(&meshes.join("closed"));
    expected.extend(files_of(&meshes.join("invalid")));
    expected.sort();
    assert!(
        expected.len() >= min_files,
        "only {} files under {}",
        expected.len(),
        meshes.display()
    );
    let names: Vec<String> = got
        .iter()
        .map(|l| l["file"].as_str().unwrap().to_string())
        .collect();
    let want: Vec<String> = expected.iter().map(|p| p.display().to_string()).collect();
    assert_eq!(names, want);
    let mut invalid_seen = 0;
    for l in &got {
        let file = l["file"].as_str().unwrap();
        let invalid = file.contains("/invalid/");
        assert_eq!(l["ok"], !invalid, "{l}");
        assert_eq!(l["task"], "reduce");
        if invalid {
            invalid_seen += 1;
            let e = &l["error"];
            assert_eq!(e["kind"], "input", "{l}");
            assert_eq!(e["exit_code"], 2, "{l}");
            let m = e["message"].as_str().unwrap();
            assert!(m.starts_with(file), "{m}");
            assert!(
                m.contains("face") || m.contains("vertex") || m.contains("edge"),
                "{m}"
            );
        } else {
            assert_eq!(l["result"]["irreducible"], true, "{l}");
        }
    }
    assert!(
        invalid_seen >= 1,
        "no invalid file under {}",
        meshes.display()
    );
    // The results are the single-file command's, for a spread of files.
    for name in spread {
        let file = meshes.join("closed").join(format!("{name}.off.gz"));
        let line = got
            .iter()
            .find(|l| l["file"] == file.display().to_string())
            .expect("line");
        let alone = run_json(&["reduce".as_ref(), file.as_os_str()]);
        assert_eq!(untimed(&line["result"]), untimed(&alone), "{name}");
    }
}

/// Over the repository's real meshes: every closed and invalid one, one line each.
#[test]
fn reduce_over_all_in_repo_meshes_gives_one_line_per_file_and_located_errors() {
    reduce_over_a_mesh_folder(
        &data_meshes(),
        &["plate_holes_stl", "box_stl", "bunny_npm", "two_objects"],
        11,
        "batch-all",
    );
}

#[test]
fn lines_do_not_depend_on_the_number_of_jobs_and_resume_completes_a_cut_run() {
    let d = Scratch::new("batch-resume");
    // The repository's meshes converted from STL: a glob that picks 5 of its 9 files.
    let pattern = data_meshes().join("closed").join("*_stl.off.gz");
    let one = d.path("one.jsonl");
    let two = d.path("two.jsonl");
    for (jobs, path) in [("1", &one), ("2", &two)] {
        let out = run(&[
            "batch".as_ref(),
            pattern.as_os_str(),
            "--task".as_ref(),
            "quad".as_ref(),
            "--jsonl".as_ref(),
            path.as_os_str(),
            "-j".as_ref(),
            jobs.as_ref(),
            "--".as_ref(),
            "--algo".as_ref(),
            "sg".as_ref(),
            "--seed".as_ref(),
            "7".as_ref(),
        ]);
        assert!(out.status.success(), "{}", stderr(&out));
    }
    let a = lines(&std::fs::read_to_string(&one).unwrap());
    let b = lines(&std::fs::read_to_string(&two).unwrap());
    assert_eq!(a.len(), 5);
    assert_eq!(
        a.iter().map(untimed).collect::<Vec<_>>(),
        b.iter().map(untimed).collect::<Vec<_>>()
    );
    // Cut the file after two lines plus half a line, as an interruption would.
    let text = std::fs::read_to_string(&one).unwrap();
    let kept: Vec<&str> = text.lines().take(2).collect();
    let half = &text.lines().nth(2).unwrap()[..20];
    std::fs::write(&one, format!("{}\n{half}", kept.join("\n"))).unwrap();
    let out = run(&[
        "--quiet".as_ref(),
        "batch".as_ref(),
        pattern.as_os_str(),
        "--task".as_ref(),
        "quad".as_ref(),
        "--jsonl".as_ref(),
        one.as_os_str(),
        "--resume".as_ref(),
        "--".as_ref(),
        "--algo".as_ref(),
        "sg".as_ref(),
        "--seed".as_ref(),
        "7".as_ref(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let text = std::fs::read_to_string(&one).unwrap();
    // The cut line stays as it was (unparseable) and its file runs again.
    let resumed: Vec<Value> = text
        .lines()
        .filter_map(|l| serde_json::from_str(l).ok())
        .collect();
    assert_eq!(resumed.len(), a.len());
    assert_eq!(
        resumed.iter().map(untimed).collect::<Vec<_>>(),
        a.iter().map(untimed).collect::<Vec<_>>()
    );
}

#[test]
fn outputs_go_under_outdir_and_info_reports_problems_with_the_error() {
    let d = Scratch::new("batch-out");
    let outdir = d.path("out");
    let names = ["high_genus_3", "plate_holes_stl"];
    let files = names.map(data_closed);
    let out = run(&[
        "batch".as_ref(),
        files[0].as_os_str(),
        files[1].as_os_str(),
        "--task".as_ref(),
        "simplify".as_ref(),
        "-o".as_ref(),
        outdir.as_os_str(),
        "--".as_ref(),
        "--eps-rel".as_ref(),
        "0.02".as_ref(),
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let got = lines(&String::from_utf8_lossy(&out.stdout));
    assert_eq!(got.len(), names.len());
    for (name, l) in names.iter().zip(got) {
        let written = outdir.join(format!("{name}.simplify.off.gz"));
        assert_eq!(l["result"]["output"], written.display().to_string());
        let info = run_json(&["info".as_ref(), written.as_os_str()]);
        assert_eq!(info["faces"], l["result"]["faces_out"]);
    }
    // info on a broken mesh (a real mesh with two vertex stars listed twice): the
    // problems and the error, in one line.
    let (broken, dups) = with_duplicate_faces(&read_mesh(&data_closed("high_genus_3")));
    assert!(dups > 1);
    let broken_file = d.path("duplicates.off");
    write_off_text(&broken_file, &broken);
    let out = run(&[
        "batch".as_ref(),
        broken_file.as_os_str(),
        "--task".as_ref(),
        "info".as_ref(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let l = &lines(&String::from_utf8_lossy(&out.stdout))[0];
    assert_eq!(l["ok"], false);
    assert!(
        l["error"]["message"]
            .as_str()
            .unwrap()
            .contains(&format!("{dups} duplicate faces")),
        "{l}"
    );
    let problems = l["result"]["problems"].as_array().expect("problems");
    assert!(problems.iter().any(|p| p["count"] == dups), "{l}");
}

#[test]
fn bad_arguments_fail_before_any_work() {
    let closed = data_meshes().join("closed");
    let cases: [&[&str]; 5] = [
        &["--task", "reduce", "--", "--algo", "nope"],
        &["--task", "simplify"],
        &["--task", "info", "-o", "/tmp/x"],
        &["--task", "reduce", "--resume"],
        &["--task", "reduce", "--", "--no-such-flag"],
    ];
    for extra in cases {
        let mut args: Vec<&std::ffi::OsStr> = vec!["batch".as_ref(), closed.as_os_str()];
        args.extend(extra.iter().map(std::ffi::OsStr::new));
        let t = std::time::Instant::now();
        let out = run(&args);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {}", stderr(&out));
        assert!(out.stdout.is_empty(), "{extra:?}");
        assert!(t.elapsed().as_secs_f64() < 5.0);
    }
    let out = run(&["batch", "/no/such/dir/*.off", "--task", "info"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("no file matches"), "{}", stderr(&out));
}

/// Over the real-mesh corpus (ignored unless asked for: `-- --ignored ::corpus::`).
mod corpus {
    use super::*;
    use crate::cli_common::corpus_meshes;

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn reduce_over_all_shared_meshes_gives_one_line_per_file_and_located_errors() {
        reduce_over_a_mesh_folder(
            &corpus_meshes(),
            &["socket", "footbones", "tetrahedron", "two_objects"],
            100,
            "batch-all-corpus",
        );
    }
}
