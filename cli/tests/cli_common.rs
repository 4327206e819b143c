//! Shared code of the command-line tests: run the binary, parse its JSON, scratch dirs.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use contractible::{Surfaces, TriMesh};

/// The small real meshes the repository carries, `tests/data/meshes` (`closed/`,
/// `invalid/`, `manifest.csv`).
pub fn data_meshes() -> PathBuf {
    crate::common::data_meshes()
}

/// The opt-in real-mesh corpus's meshes (ignored unless asked for; panics, naming the place,
/// when the corpus is absent).
pub fn corpus_meshes() -> PathBuf {
    crate::common::corpus_meshes()
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

// Inputs made at test time: the generic meshes the command-line tests need (a
// tetrahedron, a genus-2 surface, many components, an open surface, duplicate faces, a
// large surface), from the project's generators, the repository's own real meshes and
// a few lines of code here, so that the tests run on a fresh checkout.

/// Runs `contractible -q gen ARGS -o DIR/FILE` and returns the written path.
pub fn gen_file(dir: &Scratch, file: &str, args: &[&str]) -> PathBuf {
    let out = dir.path(file);
    let mut all: Vec<&std::ffi::OsStr> = vec!["-q".as_ref(), "gen".as_ref()];
    all.extend(args.iter().map(std::ffi::OsStr::new));
    all.extend(["-o".as_ref(), out.as_os_str()]);
    run_ok(&all);
    out
}

/// The tetrahedron, as `gen tetrahedron` writes it (with positions).
pub fn tetrahedron_file(dir: &Scratch) -> PathBuf {
    gen_file(dir, "tetrahedron.off", &["tetrahedron"])
}

/// A genus-2 surface with positions on a half-integer grid (pairwise distinct, exact in
/// `f32`): the brick with two through-holes at the coarsest resolution (72 vertices,
/// 148 faces).
pub fn genus_two_file(dir: &Scratch) -> PathBuf {
    gen_file(
        dir,
        "genus2.off",
        &[
            "brick",
            "--cavities",
            "2",
            "--holes",
            "2",
            "--resolution",
            "1",
        ],
    )
}

/// A mid-sized closed surface with positions: the marching-tetrahedra sphere at
/// resolution 60 (about 65,000 faces, gzip-compressed).
pub fn mid_surface_file(dir: &Scratch) -> PathBuf {
    gen_file(
        dir,
        "mid.off.gz",
        &["isosurface", "--surface", "sphere", "--resolution", "60"],
    )
}

/// One of the repository's closed real meshes, `tests/data/meshes/closed/NAME.off.gz`.
pub fn data_closed(name: &str) -> PathBuf {
    data_meshes().join("closed").join(format!("{name}.off.gz"))
}

/// One of the repository's invalid real meshes, `tests/data/meshes/invalid/NAME.off.gz`.
pub fn data_invalid(name: &str) -> PathBuf {
    data_meshes().join("invalid").join(format!("{name}.off.gz"))
}

/// Reads a mesh file (no validation).
pub fn read_mesh(path: &Path) -> TriMesh {
    contractible::io::read_tri_mesh(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Writes `mesh` (with positions) as plain OFF laid out as `OFF`, `V F 0`, one line per
/// vertex, one per face: face `f` (0-based) is on line `V + 3 + f`.
pub fn write_off_text(path: &Path, mesh: &TriMesh) {
    use std::fmt::Write as _;
    let p = mesh.positions.as_ref().expect("positions");
    let mut s = format!("OFF\n{} {} 0\n", mesh.vertex_count, mesh.faces.len());
    for [x, y, z] in p {
        writeln!(s, "{x} {y} {z}").unwrap();
    }
    for [a, b, c] in &mesh.faces {
        writeln!(s, "3 {a} {b} {c}").unwrap();
    }
    std::fs::write(path, s).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
}

/// The six squares of the unit cube's boundary over its corners `i` at
/// `(i & 1, i >> 1 & 1, i >> 2 & 1)`, each oriented outward.
pub const CUBE_QUADS: [[u32; 4]; 6] = [
    [0, 2, 3, 1],
    [4, 5, 7, 6],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
];

/// The unit cube's boundary: 8 vertices at the corners of `[0, 1]³` (vertex `i` at
/// `(i & 1, i >> 1 & 1, i >> 2 & 1)`), each square cut into two triangles, oriented
/// outward (12 faces).
pub fn cube_mesh() -> TriMesh {
    let positions = (0..8)
        .map(|i| [i & 1, (i >> 1) & 1, (i >> 2) & 1].map(f64::from))
        .collect();
    let mut faces = Vec::new();
    for [a, b, c, d] in CUBE_QUADS {
        faces.push([a, b, c]);
        faces.push([a, c, d]);
    }
    TriMesh::with_positions(positions, faces)
}

/// `n` disjoint copies of the tetrahedron (`contractible::gen::tetrahedron`), the `k`-th
/// moved by `(4k, 0, 0)`: `n` components, each irreducible.
pub fn disjoint_tetrahedra(n: usize) -> TriMesh {
    let t = contractible::gen::tetrahedron();
    let p = t.positions.as_ref().expect("positions");
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for k in 0..n {
        let base = positions.len() as u32;
        positions.extend(p.iter().map(|q| [q[0] + 4.0 * k as f64, q[1], q[2]]));
        faces.extend(t.faces.iter().map(|f| f.map(|v| v + base)));
    }
    TriMesh::with_positions(positions, faces)
}

/// A torus of revolution sampled on an `n × m` grid (`n` steps around the axis, `m`
/// around the tube; radii `major` and `minor`), each grid square cut along the same
/// diagonal: `n·m` vertices, `2·n·m` faces, consistently oriented.
pub fn grid_torus(n: u32, m: u32, major: f64, minor: f64) -> TriMesh {
    let id = |i: u32, j: u32| (i % n) * m + (j % m);
    let mut positions = Vec::new();
    for i in 0..n {
        let phi = std::f64::consts::TAU * f64::from(i) / f64::from(n);
        for j in 0..m {
            let theta = std::f64::consts::TAU * f64::from(j) / f64::from(m);
            let w = major + minor * theta.cos();
            positions.push([w * phi.cos(), w * phi.sin(), minor * theta.sin()]);
        }
    }
    let mut faces = Vec::new();
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            faces.push([a, b, c]);
            faces.push([a, c, d]);
        }
    }
    TriMesh::with_positions(positions, faces)
}

/// Graph distances (in edges) from `sources` to every vertex of `mesh` (`usize::MAX`
/// where unreachable).
fn distances(mesh: &TriMesh, sources: &[u32]) -> Vec<usize> {
    let mut adj = vec![Vec::new(); mesh.vertex_count];
    for f in &mesh.faces {
        for k in 0..3 {
            adj[f[k] as usize].push(f[(k + 1) % 3]);
            adj[f[(k + 1) % 3] as usize].push(f[k]);
        }
    }
    let mut dist = vec![usize::MAX; mesh.vertex_count];
    let mut queue = std::collections::VecDeque::new();
    for &s in sources {
        dist[s as usize] = 0;
        queue.push_back(s);
    }
    while let Some(v) = queue.pop_front() {
        for &w in &adj[v as usize] {
            if dist[w as usize] == usize::MAX {
                dist[w as usize] = dist[v as usize] + 1;
                queue.push_back(w);
            }
        }
    }
    dist
}

/// A closed one-component surface with `holes` holes cut in it: the stars of `holes`
/// vertices at pairwise graph distance at least 3 removed (so the holes' boundaries, the
/// removed vertices' links, are disjoint cycles), unused vertices dropped. Each hole
/// lowers χ by one and adds one boundary loop; the genus stays.
pub fn with_holes(closed: &TriMesh, holes: usize) -> TriMesh {
    let mut centres: Vec<u32> = vec![0];
    while centres.len() < holes {
        // The vertex farthest from the centres so far (lowest index among ties).
        let d = distances(closed, &centres);
        let (far, &dist) = d
            .iter()
            .enumerate()
            .filter(|&(_, &x)| x != usize::MAX)
            .max_by_key(|&(v, &x)| (x, std::cmp::Reverse(v)))
            .expect("a vertex");
        assert!(dist >= 3, "no room for {holes} separate holes");
        centres.push(far as u32);
    }
    let faces = closed
        .faces
        .iter()
        .filter(|f| !f.iter().any(|v| centres.contains(v)))
        .copied()
        .collect();
    let cut = TriMesh {
        vertex_count: closed.vertex_count,
        positions: closed.positions.clone(),
        faces,
    };
    cut.compacted().expect("valid indices").0
}

/// `mesh` followed by a second copy of the faces around vertex 0 and around the vertex
/// farthest from it (both stars, never a face twice): every edge at vertex 0 then lies
/// in 4 faces, the star's outer edges in 3. Returns the mesh and the number of
/// duplicated faces.
pub fn with_duplicate_faces(mesh: &TriMesh) -> (TriMesh, usize) {
    let d = distances(mesh, &[0]);
    let far = (0..mesh.vertex_count)
        .filter(|&v| d[v] != usize::MAX)
        .max_by_key(|&v| (d[v], std::cmp::Reverse(v)))
        .expect("a vertex") as u32;
    assert!(d[far as usize] >= 2, "the two stars share a face");
    let copies: Vec<[u32; 3]> = mesh
        .faces
        .iter()
        .filter(|f| f.contains(&0) || f.contains(&far))
        .copied()
        .collect();
    let n = copies.len();
    let mut out = mesh.clone();
    out.faces.extend(copies);
    (out, n)
}

/// A JSON value without its timings (keys starting with `seconds` or ending in
/// `_seconds`), recursively, so that two runs can be compared.
pub fn untimed(v: &serde_json::Value) -> serde_json::Value {
    use serde_json::Value;
    match v {
        Value::Object(m) => Value::Object(
            m.iter()
                .filter(|(k, _)| !k.starts_with("seconds") && !k.ends_with("_seconds"))
                .map(|(k, v)| (k.clone(), untimed(v)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.iter().map(untimed).collect()),
        v => v.clone(),
    }
}
