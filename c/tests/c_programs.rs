//! C programs against the static library, compiled by the system's compiler with
//! warnings as errors and run: the examples (`file_to_file.c` and the C++
//! `decimate_file.cpp` write the Rust call's bytes), `tests/c/abi_test.c` (every
//! function, right and wrong calls, also compiled as C++: the header's `extern "C"`),
//! `tests/c/hpp_test.cpp` (the C++ layer), the conformance adapter over the whole suite,
//! a build through the pkg-config file, and all of them under valgrind's memcheck when it
//! is installed (no leak, no invalid access, the error paths included).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The folder of this test's executable (`target/<profile>/deps`), where cargo puts the
/// static library it built for this run.
fn deps() -> PathBuf {
    let exe = std::env::current_exe().expect("the test's path");
    exe.parent().expect("deps").to_path_buf()
}

fn crate_dir() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn scratch(name: &str) -> PathBuf {
    let d = deps().join(format!("c-tests-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("scratch folder");
    d
}

/// Compiles `source` with `compiler` (`cc` or `c++`), warnings as errors, against the
/// static library; the executable's path.
fn compile(compiler: &str, std: &str, source: &Path, out: &Path) -> PathBuf {
    let lib = deps().join("libcontractible_c.a");
    assert!(lib.exists(), "{} not built", lib.display());
    let mut cmd = Command::new(compiler);
    if compiler == "c++" {
        cmd.args(["-x", "c++"]);
    }
    cmd.arg(format!("-std={std}"))
        .args(["-Wall", "-Wextra", "-Werror", "-pedantic", "-g", "-O1"])
        .arg("-I")
        .arg(crate_dir().join("include"))
        .arg(source)
        .args(["-x", "none"])
        .arg(&lib)
        .args(["-lm", "-lpthread", "-ldl", "-o"])
        .arg(out);
    let o = cmd.output().expect("the system C compiler runs");
    assert!(
        o.status.success(),
        "{compiler} failed:\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    out.to_path_buf()
}

fn run(exe: &Path, args: &[&Path]) -> std::process::Output {
    Command::new(exe).args(args).output().expect("runs")
}

/// Runs `exe args` under memcheck when valgrind is installed: no error, no leak.
fn memcheck(exe: &Path, args: &[&Path]) {
    let Ok(v) = Command::new("valgrind").arg("--version").output() else {
        eprintln!(
            "valgrind is not installed: the memory check of {} is skipped",
            exe.display()
        );
        return;
    };
    assert!(v.status.success());
    let o = Command::new("valgrind")
        .args([
            "--error-exitcode=99",
            "--leak-check=full",
            // Not "possible": rayon's global pool (the `parallel` feature, on when the
            // workspace builds the command line too) keeps its threads to the end, and
            // memcheck reports their thread-local blocks as possibly lost.
            "--show-leak-kinds=definite,indirect",
            "--errors-for-leak-kinds=definite,indirect",
            "-q",
        ])
        .arg(exe)
        .args(args)
        .output()
        .expect("valgrind runs");
    assert_ne!(
        o.status.code(),
        Some(99),
        "memcheck found errors in {}:\n{}",
        exe.display(),
        String::from_utf8_lossy(&o.stderr)
    );
}

#[test]
fn the_abi_test_passes_in_c_and_cpp_and_under_memcheck() {
    let d = scratch("abi");
    let source = crate_dir().join("tests").join("c").join("abi_test.c");
    for (compiler, std, name) in [("cc", "c11", "abi_test"), ("c++", "c++17", "abi_test_cpp")] {
        let exe = compile(compiler, std, &source, &d.join(name));
        let o = run(&exe, &[&d]);
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(
            o.status.success(),
            "{name}: {out}\n{}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert!(out.contains("checks passed"), "{out}");
        if compiler == "cc" {
            memcheck(&exe, &[&d]);
        }
    }
}

#[test]
fn the_cpp_layer_test_passes_and_under_memcheck() {
    let d = scratch("hpp");
    let source = crate_dir().join("tests").join("c").join("hpp_test.cpp");
    let exe = compile("c++", "c++17", &source, &d.join("hpp_test"));
    let o = run(&exe, &[]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{out}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(out.contains("checks passed"), "{out}");
    memcheck(&exe, &[]);
}

#[test]
fn file_to_file_writes_what_the_rust_call_writes() {
    let d = scratch("example");
    let source = crate_dir().join("examples").join("file_to_file.c");
    let exe = compile("cc", "c11", &source, &d.join("file_to_file"));
    let input = crate_dir()
        .join("..")
        .join("tests/data/meshes/closed/high_genus_3.off.gz");
    let out = d.join("reduced.off");
    let o = run(&exe, &[&input, &out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("1660 vertices") && text.contains("17 vertices"),
        "{text}"
    );
    // The Rust call's output, written the same way: the same bytes.
    let mesh = contractible::io::read_tri_mesh(&input).expect("reads");
    let r = contractible::reduce(&mesh, &Default::default()).expect("reduces");
    let theirs = d.join("rust.off");
    contractible::io::write_mesh(&theirs, &r.mesh).expect("writes");
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&theirs).unwrap()
    );
    memcheck(&exe, &[&input, &d.join("again.off")]);

    // Errors: a clear message and the error's code as the exit code.
    let o = run(&exe, &[&d.join("missing.off"), &out]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).starts_with("error (io): "));
    // A mesh reduce refuses: exit 2, the kind named.
    let invalid = crate_dir()
        .join("..")
        .join("tests/data/meshes/invalid/shared_edge_stl.off.gz");
    let o = run(&exe, &[&invalid, &out]);
    assert_eq!(o.status.code(), Some(2));
    let kind = match contractible::reduce(
        &contractible::io::read_tri_mesh(&invalid).unwrap(),
        &Default::default(),
    ) {
        Err(e) => e.kind(),
        Ok(_) => panic!("{} reduces", invalid.display()),
    };
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(stderr.starts_with(&format!("error ({kind}): ")), "{stderr}");
    memcheck(&exe, &[&invalid, &out]);
    memcheck(&exe, &[&d.join("missing.off"), &out]);
    let o = run(&exe, &[&input]);
    assert_eq!(o.status.code(), Some(2));
}

/// Installed as docs/c.md says (the header and the static library under a prefix, the
/// pkg-config file from `contractible.pc.in`), a program builds with `pkg-config
/// --cflags --libs --static contractible` alone and runs.
#[test]
fn pkg_config_builds_a_program_against_an_installed_prefix() {
    if Command::new("pkg-config")
        .arg("--version")
        .output()
        .is_err()
    {
        eprintln!("pkg-config is not installed: the installed-prefix build is skipped");
        return;
    }
    let d = scratch("pkg-config");
    let prefix = d.join("prefix");
    for sub in ["include", "lib/pkgconfig"] {
        std::fs::create_dir_all(prefix.join(sub)).expect("the prefix's folders");
    }
    std::fs::copy(
        crate_dir().join("include/contractible.h"),
        prefix.join("include/contractible.h"),
    )
    .expect("installs the header");
    std::fs::copy(
        deps().join("libcontractible_c.a"),
        prefix.join("lib/libcontractible_c.a"),
    )
    .expect("installs the library");
    let template =
        std::fs::read_to_string(crate_dir().join("contractible.pc.in")).expect("the template");
    let pc = template
        .replace("@PREFIX@", prefix.to_str().expect("a UTF-8 path"))
        .replace("@VERSION@", env!("CARGO_PKG_VERSION"));
    std::fs::write(prefix.join("lib/pkgconfig/contractible.pc"), pc).expect("writes it");
    let flags = Command::new("pkg-config")
        .args(["--cflags", "--libs", "--static", "contractible"])
        .env("PKG_CONFIG_PATH", prefix.join("lib/pkgconfig"))
        .output()
        .expect("pkg-config runs");
    assert!(
        flags.status.success(),
        "{}",
        String::from_utf8_lossy(&flags.stderr)
    );
    let flags = String::from_utf8(flags.stdout).expect("UTF-8 flags");
    assert!(
        flags.contains("-lcontractible_c") && flags.contains("-lpthread"),
        "{flags}"
    );
    let version = Command::new("pkg-config")
        .args(["--modversion", "contractible"])
        .env("PKG_CONFIG_PATH", prefix.join("lib/pkgconfig"))
        .output()
        .expect("pkg-config runs");
    assert_eq!(
        String::from_utf8_lossy(&version.stdout).trim(),
        env!("CARGO_PKG_VERSION")
    );
    let exe = d.join("file_to_file");
    let o = Command::new("cc")
        .args(["-std=c11", "-Wall", "-Wextra", "-Werror", "-pedantic"])
        .arg(crate_dir().join("examples/file_to_file.c"))
        .args(flags.split_whitespace())
        .arg("-o")
        .arg(&exe)
        .output()
        .expect("cc runs");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let input = crate_dir()
        .join("..")
        .join("tests/data/meshes/closed/high_genus_3.off.gz");
    let o = run(&exe, &[&input, &d.join("out.off")]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("17 vertices"));
}

#[test]
fn the_cpp_layer_gives_values_and_exceptions() {
    let d = scratch("cpp");
    let source = crate_dir().join("examples").join("reduce_vectors.cpp");
    let exe = compile("c++", "c++17", &source, &d.join("reduce_vectors"));
    let o = run(&exe, &[]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{out}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // The Rust call on the same octahedron: the same counts and contractions.
    let octahedron = contractible::gen::octahedron();
    let r = contractible::reduce(&octahedron, &Default::default()).expect("reduces");
    let first = format!(
        "octahedron: chi 2, 6 vertices -> {} vertices, {} faces, {} contractions",
        r.mesh.vertex_count,
        r.mesh.faces.len(),
        r.contractions().len()
    );
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines[0], first, "{out}");
    for (line, [kept, removed]) in lines[1..].iter().zip(r.contractions()) {
        assert_eq!(*line, format!("  contracted {removed} into {kept}"));
    }
    assert!(
        lines
            .last()
            .is_some_and(|l| l.starts_with("refused (non_manifold_edge, face ")),
        "{out}"
    );
    memcheck(&exe, &[]);
}

#[test]
fn the_cpp_decimation_writes_what_the_rust_call_writes_and_passes_the_checker() {
    let d = scratch("cpp-decimate");
    let source = crate_dir().join("examples").join("decimate_file.cpp");
    let exe = compile("c++", "c++17", &source, &d.join("decimate_file"));
    let input = crate_dir()
        .join("..")
        .join("tests/data/meshes/closed/high_genus_3.off.gz");
    let out = d.join("decimated.off");
    let o = run(&exe, &[&input, &out, Path::new("1000")]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        o.status.success(),
        "{text}\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // The Rust call: the same file, the same report.
    let mesh = contractible::io::read_tri_mesh(&input).expect("reads");
    let r = contractible::decimate(&mesh, &contractible::DecimateOptions::faces(1000))
        .expect("decimates");
    let theirs = d.join("rust.off");
    contractible::io::write_mesh(&theirs, &r.mesh).expect("writes");
    assert_eq!(
        std::fs::read(&out).unwrap(),
        std::fs::read(&theirs).unwrap()
    );
    assert!(
        text.contains(&format!(
            "3328 faces -> {}: {} faces (target reached), largest error",
            out.display(),
            r.mesh.faces.len()
        )) && text.trim_end().ends_with("checked"),
        "{text}"
    );
    memcheck(&exe, &[&input, &d.join("again.off"), Path::new("600")]);
    // An input decimate refuses: the error's code, its kind named.
    let invalid = crate_dir()
        .join("..")
        .join("tests/data/meshes/invalid/shared_edge_stl.off.gz");
    let o = run(&exe, &[&invalid, &out, Path::new("10")]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        String::from_utf8_lossy(&o.stderr).starts_with("error ("),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    memcheck(&exe, &[&invalid, &out, Path::new("10")]);
}

/// The command line built beside this test (the workspace's test command builds it).
fn command_line() -> PathBuf {
    let exe = deps()
        .parent()
        .expect("the profile folder")
        .join(format!("contractible{}", std::env::consts::EXE_SUFFIX));
    assert!(
        exe.exists(),
        "{} is not built: run the workspace's test command, which builds it, or `cargo \
         build --release -p contractible-cli` first",
        exe.display()
    );
    exe
}

/// The harness's JSON report of `impl_` over the whole suite, with `--exact`.
fn conformance(impl_: &str) -> serde_json::Value {
    let o = Command::new(command_line())
        .args(["--json", "conformance", "--exact", "-j", "2"])
        .arg("--suite")
        .arg(crate_dir().join("..").join("spec"))
        .arg("--impl")
        .arg(impl_)
        .output()
        .expect("the harness runs");
    assert!(
        o.status.success(),
        "{impl_}: {}\n{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).expect("the JSON report")
}

#[test]
fn the_c_adapter_passes_the_whole_suite_as_the_command_line_s_does() {
    let d = scratch("adapter");
    let source = crate_dir().join("examples").join("conformance_adapter.c");
    let adapter = compile("cc", "c11", &source, &d.join("conformance_adapter"));
    let ours = conformance(adapter.to_str().expect("a UTF-8 path"));
    let cli = format!("{} answer", command_line().display());
    let theirs = conformance(&cli);
    // Every case of every task, valid and invalid, passes with --exact: the same verdicts
    // case by case as the library's own adapter.
    let verdicts = |r: &serde_json::Value| -> Vec<(String, String)> {
        r["cases"]
            .as_array()
            .expect("cases")
            .iter()
            .map(|c| (c["id"].to_string(), c["verdict"].to_string()))
            .collect()
    };
    assert_eq!(verdicts(&ours), verdicts(&theirs));
    let cases = ours["cases"].as_array().expect("cases");
    assert!(cases.len() > 1500, "{}", cases.len());
    assert!(cases.iter().all(|c| c["verdict"] == "passed"));
    for task in ["reduce", "quad", "simplify", "decimate"] {
        for class in ["", "invalid/"] {
            let prefix = format!("{class}{task}/");
            assert!(
                cases
                    .iter()
                    .any(|c| c["id"].as_str().unwrap().starts_with(&prefix)),
                "no case {prefix}"
            );
        }
    }

    // Under memcheck, case by case: a valid case of each task, every invalid input of the
    // suite (refused with the suite's kind), a task it does not know, and bytes that are no
    // JSON: no memory error or leak on any path.
    let octahedron = r#"{"protocol": 1, "id": "o", "task": "reduce", "options": {"algorithm": "schipper"}, "vertex_count": 6, "faces": [[0,2,4],[2,1,4],[1,3,4],[3,0,4],[2,0,5],[1,2,5],[3,1,5],[0,3,5]], "positions": [[1,0,0],[-1,0,0],[0,1,0],[0,-1,0],[0,0,1],[0,0,-1]]}"#;
    let as_task = |task: &str, options: &str| {
        octahedron
            .replace("\"reduce\"", &format!("\"{task}\""))
            .replace(r#"{"algorithm": "schipper"}"#, options)
    };
    let mut cases: Vec<(String, i32, String)> = vec![
        (octahedron.to_string(), 0, "\"history\": [[".to_string()),
        (
            as_task("quad", r#"{"algorithm": "ps", "seed": 1}"#),
            0,
            "\"pairs\": [[".to_string(),
        ),
        (
            as_task("simplify", r#"{"eps": 2, "guard": false}"#),
            0,
            "\"positions\": [[".to_string(),
        ),
        (
            as_task("decimate", r#"{"faces": 4, "locked": [0, 5]}"#),
            0,
            "\"collapse_map\": [".to_string(),
        ),
        (
            as_task("decimate", r#"{"placement": "nowhere"}"#),
            2,
            "unknown_name".to_string(),
        ),
        (as_task("flatten", "{}"), 2, "unsupported".to_string()),
        ("{\"task\": [1, 2".to_string(), 2, "protocol".to_string()),
    ];
    let invalid = std::fs::read_to_string(crate_dir().join("../spec/suite/invalid.jsonl"))
        .expect("the suite's invalid cases");
    for line in invalid.lines() {
        let v: serde_json::Value = serde_json::from_str(line).expect("JSON");
        let kind = v["kind"].as_str().expect("kind").to_string();
        cases.push((line.to_string(), 2, format!("\"kind\": \"{kind}\"")));
    }
    assert!(cases.len() >= 30);
    let valgrind = Command::new("valgrind").arg("--version").output().is_ok();
    for (case, code, shown) in &cases {
        let mut cmd = if valgrind {
            let mut c = Command::new("valgrind");
            c.args([
                "--error-exitcode=99",
                "--leak-check=full",
                "--errors-for-leak-kinds=definite,indirect",
                "-q",
            ])
            .arg(&adapter);
            c
        } else {
            Command::new(&adapter)
        };
        let mut child = cmd
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("starts");
        use std::io::Write;
        child
            .stdin
            .take()
            .expect("stdin")
            .write_all(case.as_bytes())
            .expect("writes the case");
        let o = child.wait_with_output().expect("ends");
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(
            o.status.code(),
            Some(*code),
            "{case:.80}: {out}\n{}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert!(out.contains(shown.as_str()), "{case:.80}: {out}");
    }
}
