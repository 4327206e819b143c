//! Helpers for the command-line tests: run the binary, parse its JSON, scratch dirs.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use contractible::{Surfaces, TriMesh};

/// `../shared/meshes`.
pub fn meshes() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/meshes"))
}

/// Runs `contractible ARGS...`.
pub fn run<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_contractible"))
        .args(args)
        .output()
        .expect("run contractible")
}

/// Runs and asserts exit code 0; returns the output.
pub fn run_ok<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Output {
    let out = run(args);
    assert!(
        out.status.success(),
        "contractible {:?} failed ({:?}):\n{}",
        args.iter()
            .map(|a| a.as_ref().to_owned())
            .collect::<Vec<_>>(),
        out.status.code(),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// Runs with `--json`, asserts success, and parses stdout.
pub fn run_json<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> serde_json::Value {
    let mut all: Vec<std::ffi::OsString> = vec!["--json".into()];
    all.extend(args.iter().map(|a| a.as_ref().to_owned()));
    let out = run_ok(&all);
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "stdout is not JSON ({e}):\n{}",
            String::from_utf8_lossy(&out.stdout)
        )
    })
}

/// Stderr as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// A scratch directory removed on drop.
pub struct Scratch(pub PathBuf);

impl Scratch {
    pub fn new(name: &str) -> Self {
        let p = std::env::temp_dir().join(format!(
            "contractible-cli-test-{}-{name}",
            std::process::id()
        ));
        let _ = std::fs::remove_dir_all(&p);
        std::fs::create_dir_all(&p).expect("scratch dir");
        Scratch(p)
    }

    pub fn path(&self, file: &str) -> PathBuf {
        self.0.join(file)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Reads and validates a mesh in-process.
pub fn load(path: &Path) -> (TriMesh, Surfaces) {
    let mesh = contractible::io::read_tri_mesh(path).unwrap_or_else(|e| panic!("{e}"));
    let s = Surfaces::from_mesh(&mesh).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (mesh, s)
}

/// A JSON number field as i64 (panics with the key name when missing).
pub fn int(v: &serde_json::Value, key: &str) -> i64 {
    v.get(key)
        .and_then(|x| x.as_i64())
        .unwrap_or_else(|| panic!("missing integer {key:?} in {v}"))
}
