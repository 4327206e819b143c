//! `quad` and the tri-quad part of `demo` through the binary. The written quad mesh is
//! parsed here by a minimal OFF reader of the test's own and checked without the
//! library: 4 distinct vertices per quad, the input's vertex positions, a closed
//! 2-manifold (every edge in two quads, every vertex link one cycle) with the input's χ
//! and, for an oriented input, a consistent orientation. The `--pairs` file is checked
//! against the input's triangles.

use crate::cli_common;

use std::collections::HashMap;
use std::ffi::OsStr;
use std::path::Path;

use cli_common::{
    cube_mesh, data_closed, data_invalid, genus_two_file, grid_torus, int, load, mid_surface_file,
    read_mesh, run, run_json, run_ok, stderr, with_holes, Scratch,
};

const ALGOS: [&str; 8] = [
    "lrs",
    "ps",
    "sg",
    "matching",
    "ds-naive",
    "frink-lct",
    "ds",
    "bbdl",
];

/// Vertex positions and quads of an ASCII OFF file.
fn read_quad_off(path: &Path) -> (Vec<[f64; 3]>, Vec<[u32; 4]>) {
    let text = std::fs::read_to_string(path).expect("read output");
    let mut tokens = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .flat_map(str::split_whitespace);
    assert_eq!(tokens.next(), Some("OFF"));
    let mut num = || {
        tokens
            .next()
            .expect("token")
            .parse::<f64>()
            .expect("number")
    };
    let (nv, nf) = (num() as usize, num() as usize);
    let _ne = num();
    let positions = (0..nv).map(|_| [num(), num(), num()]).collect();
    let quads = (0..nf)
        .map(|_| {
            assert_eq!(num() as usize, 4, "a face that is not a quad");
            [num() as u32, num() as u32, num() as u32, num() as u32]
        })
        .collect();
    (positions, quads)
}

/// χ = V − E + F of a closed 2-manifold quad mesh (V counting the used vertices), and
/// whether its quads are consistently oriented. Panics where it is not a closed
/// 2-manifold.
fn closed_quad_manifold(quads: &[[u32; 4]]) -> (i64, bool) {
    let mut edges: HashMap<(u32, u32), Vec<(u32, u32)>> = HashMap::new();
    let mut corners: HashMap<u32, Vec<(u32, u32)>> = HashMap::new();
    for q in quads {
        let mut s = *q;
        s.sort_unstable();
        assert!(
            s.windows(2).all(|w| w[0] != w[1]),
            "quad {q:?} repeats a vertex"
        );
        for i in 0..4 {
            let (a, b) = (q[i], q[(i + 1) % 4]);
            edges.entry((a.min(b), a.max(b))).or_default().push((a, b));
            // The corner at b sees its two neighbours a and c: one edge of b's link.
            let c = q[(i + 2) % 4];
            corners.entry(b).or_default().push((a, c));
        }
    }
    let mut oriented = true;
    for (e, uses) in &edges {
        assert_eq!(uses.len(), 2, "edge {e:?} lies in {} quads", uses.len());
        oriented &= uses[0] != uses[1];
    }
    // Each vertex's link (a graph on its neighbours, one edge per corner) is one cycle.
    for (v, link) in &corners {
        let mut deg: HashMap<u32, usize> = HashMap::new();
        for &(a, c) in link {
            *deg.entry(a).or_default() += 1;
            *deg.entry(c).or_default() += 1;
        }
        assert!(
            deg.values().all(|&d| d == 2),
            "vertex {v}: link not 2-regular"
        );
        // Connected: walk from one corner.
        let mut seen = vec![false; link.len()];
        let mut stack = vec![0];
        seen[0] = true;
        while let Some(i) = stack.pop() {
            let (a, c) = link[i];
            for (j, &(x, y)) in link.iter().enumerate() {
                if !seen[j] && [x, y].iter().any(|w| *w == a || *w == c) {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
        assert!(
            seen.iter().all(|&s| s),
            "vertex {v}: link is several cycles"
        );
    }
    let v = corners.len() as i64;
    (v - edges.len() as i64 + quads.len() as i64, oriented)
}

fn check_quad(input: &Path, algo: &str, dir: &Scratch) {
    let name = input
        .file_name()
        .unwrap()
        .to_string_lossy()
        .replace('.', "_");
    let out = dir.path(&format!("{name}.{algo}.off"));
    let pairs = dir.path(&format!("{name}.{algo}.pairs"));
    let j = run_json(&[
        OsStr::new("quad"),
        input.as_os_str(),
        OsStr::new("--algo"),
        OsStr::new(algo),
        OsStr::new("--seed"),
        OsStr::new("2"),
        OsStr::new("-o"),
        out.as_os_str(),
        OsStr::new("--pairs"),
        pairs.as_os_str(),
    ]);
    let (mesh, surfaces) = load(input);
    let label = format!("{} {algo}", input.display());
    for key in [
        "initial_seconds",
        "initial_paired_percent",
        "initial_unpaired",
        "completion_seconds",
        "total_seconds",
        "flips",
        "augmenting_paths",
        "phases",
    ] {
        assert!(j.get(key).is_some(), "{label}: missing {key}");
    }
    assert_eq!(j["verified"], true, "{label}");
    assert_eq!(j["algo"], algo);
    let faces = mesh.faces.len();
    assert_eq!(int(&j, "faces") as usize, faces, "{label}");
    assert_eq!(int(&j, "quads") as usize, faces / 2, "{label}");
    assert_eq!(int(&j, "components") as usize, surfaces.components.len());
    if algo != "lrs" {
        assert_eq!(int(&j, "flips"), 0, "{label}: only LRS flips");
    }
    if algo == "ds-naive" || algo == "frink-lct" || algo == "ds" || algo == "bbdl" {
        // Frink's reduction is perfect by construction: (c) = 0, no completion, (d) = 0.
        assert_eq!(int(&j, "initial_unpaired"), 0, "{label}: (c)");
        assert_eq!(j["completion_seconds"].as_f64(), Some(0.0), "{label}: (d)");
        assert_eq!(int(&j, "augmenting_paths"), 0, "{label}");
        assert_eq!(j["initial_paired_percent"].as_f64(), Some(100.0), "{label}");
    }

    let (positions, quads) = read_quad_off(&out);
    assert_eq!(
        positions.len(),
        mesh.vertex_count,
        "{label}: same vertex set"
    );
    if let Some(p) = &mesh.positions {
        for (a, b) in positions.iter().zip(p) {
            for k in 0..3 {
                assert!((a[k] - b[k]).abs() <= 1e-9 * (1.0 + b[k].abs()), "{label}");
            }
        }
    }
    assert_eq!(quads.len(), faces / 2);
    let (chi, oriented) = closed_quad_manifold(&quads);
    let chi_in: i64 = surfaces
        .components
        .iter()
        .map(|c| c.tri.euler_characteristic())
        .sum();
    assert_eq!(chi, chi_in, "{label}: χ");
    let orientable_in = surfaces.components.iter().all(|c| c.tri.is_orientable());
    let oriented_in = surfaces
        .components
        .iter()
        .all(|c| c.tri.orientation().is_some_and(|f| f.iter().all(|&x| !x)));
    if oriented_in {
        assert!(oriented, "{label}: an oriented input gives oriented quads");
    }
    if !orientable_in {
        assert!(
            !oriented,
            "{label}: a non-orientable surface cannot be oriented"
        );
    }

    // Pairs: every input face exactly once; for the algorithms that do not flip, the two
    // input triangles share an edge and span exactly the quad's four vertices.
    let text = std::fs::read_to_string(&pairs).expect("pairs file");
    let lines: Vec<(usize, usize)> = text
        .lines()
        .map(|l| {
            let mut it = l
                .split_whitespace()
                .map(|x| x.parse::<usize>().expect("index"));
            (it.next().expect("f"), it.next().expect("g"))
        })
        .collect();
    assert_eq!(lines.len(), quads.len());
    let mut seen = vec![false; faces];
    for (k, &(f, g)) in lines.iter().enumerate() {
        for h in [f, g] {
            assert!(!seen[h], "{label}: face {h} in two quads");
            seen[h] = true;
        }
        if algo != "lrs" {
            let (a, b) = (mesh.faces[f], mesh.faces[g]);
            assert_eq!(a.iter().filter(|v| b.contains(v)).count(), 2, "{label}");
            let mut span: Vec<u32> = a.iter().chain(b.iter()).copied().collect();
            span.sort_unstable();
            span.dedup();
            let mut q = quads[k].to_vec();
            q.sort_unstable();
            assert_eq!(span, q, "{label}: quad {k} is not its two triangles");
        }
    }
}

#[test]
fn every_algorithm_writes_a_closed_quad_manifold_on_the_input_vertices() {
    let dir = Scratch::new("quad");
    let cube = dir.path("cube.off");
    contractible::io::write_mesh(&cube, &cube_mesh()).unwrap();
    let torus = dir.path("torus.off");
    contractible::io::write_mesh(&torus, &grid_torus(24, 12, 3.0, 1.0)).unwrap();
    // A cube, a coarse torus, a genus-2 brick and real meshes: genus 0, several
    // components, genus 3.
    for m in [
        cube,
        torus,
        genus_two_file(&dir),
        data_closed("bunny_npm"),
        data_closed("box_stl"),
        data_closed("high_genus_3"),
    ] {
        for algo in ALGOS {
            check_quad(&m, algo, &dir);
        }
    }
}

#[test]
fn non_orientable_inputs_convert_too() {
    let dir = Scratch::new("quad-nonorientable");
    for (g, k) in [("klein", "kb"), ("rp2", "rp2")] {
        let path = dir.path(&format!("{k}.off"));
        let out = run(&[
            OsStr::new("gen"),
            OsStr::new(g),
            OsStr::new("-o"),
            path.as_os_str(),
        ]);
        assert!(out.status.success());
        for algo in ALGOS {
            check_quad(&path, algo, &dir);
        }
    }
    let path = dir.path("random_h3.off");
    let out = run(&[
        OsStr::new("gen"),
        OsStr::new("random"),
        OsStr::new("--crosscaps"),
        OsStr::new("3"),
        OsStr::new("--faces"),
        OsStr::new("3000"),
        OsStr::new("--flips"),
        OsStr::new("20"),
        OsStr::new("-o"),
        path.as_os_str(),
    ]);
    assert!(out.status.success());
    for algo in ALGOS {
        check_quad(&path, algo, &dir);
    }
}

/// `--algo ds-naive` is quadratic: a component above 100,000 faces is refused up front
/// (exit 2, the size and the alternative named), and `frink-lct` converts it.
#[test]
fn ds_naive_refuses_large_components() {
    let dir = Scratch::new("quad-ds-naive");
    let path = dir.path("big.off");
    let out = run(&[
        OsStr::new("gen"),
        OsStr::new("random"),
        OsStr::new("--faces"),
        OsStr::new("100100"),
        OsStr::new("-o"),
        path.as_os_str(),
    ]);
    assert!(out.status.success());
    let out = run(&[
        OsStr::new("quad"),
        path.as_os_str(),
        OsStr::new("--algo"),
        OsStr::new("ds-naive"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("ds-naive") && err.contains("100000") && err.contains("frink-lct"),
        "{err}"
    );
    let j = run_json(&[
        OsStr::new("quad"),
        path.as_os_str(),
        OsStr::new("--algo"),
        OsStr::new("frink-lct"),
    ]);
    assert_eq!(j["verified"], true);
    assert_eq!(int(&j, "quads") as usize, int(&j, "faces") as usize / 2);
}

#[test]
fn open_and_non_manifold_meshes_are_refused_with_their_location() {
    let dir = Scratch::new("quad-invalid");
    // A real mesh with one hole cut in it, and one with a non-manifold edge.
    let open = dir.path("open_bunny.off.gz");
    contractible::io::write_mesh(&open, &with_holes(&read_mesh(&data_closed("bunny_npm")), 1))
        .unwrap();
    let non_manifold = data_invalid("shared_edge_stl");
    for (path, m, what) in [
        (&open, "open_bunny.off.gz", "boundary edge"),
        (
            &non_manifold,
            "invalid/shared_edge_stl.off.gz",
            "is non-manifold, shared by 4 faces",
        ),
    ] {
        let out_path = dir.path("out.off");
        let out = run(&[
            OsStr::new("quad"),
            path.as_os_str(),
            OsStr::new("-o"),
            out_path.as_os_str(),
        ]);
        assert_eq!(out.status.code(), Some(2), "{m}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(what) && err.contains(m), "{m}: {err}");
        assert!(!out_path.exists(), "{m}: no output on error");
    }
}

#[test]
fn demo_converts_its_surfaces_with_every_algorithm() {
    // The demo runs the paper's initial-pairing algorithms and its graph-matching method
    // (Frink's reduction with the Diks–Stańczyk strategy), not the other Frink strategies.
    let j = run_json(&["demo", "--algos", "rs"]);
    assert_eq!(j["verified"], true);
    for input in j["inputs"].as_array().expect("inputs") {
        let quads = input["quad_runs"].as_array().expect("quad_runs");
        let names: Vec<&str> = quads.iter().map(|q| q["algo"].as_str().unwrap()).collect();
        assert_eq!(names, ["lrs", "ps", "sg", "matching", "ds", "bbdl"]);
        for q in quads {
            assert_eq!(q["verified"], true);
            assert_eq!(int(q, "quads") * 2, int(q, "faces"));
        }
    }
}

#[test]
fn a_closed_stdout_ends_the_run_without_a_panic() {
    use std::process::{Command, Stdio};
    let dir = Scratch::new("quad-closed-stdout");
    let path = mid_surface_file(&dir);
    for args in [vec!["--json", "info"], vec!["info"], vec!["--json", "quad"]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_contractible"))
            .args(&args)
            .arg(&path)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("spawn");
        drop(child.stdout.take()); // the reader goes away before anything is printed
        let out = child.wait_with_output().expect("wait");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        // Killed by SIGPIPE, as `yes | head` (or done before the first write).
        use std::os::unix::process::ExitStatusExt;
        assert!(
            out.status.code() == Some(0) || out.status.signal() == Some(13),
            "{args:?}: {:?}",
            out.status
        );
    }
}

/// `convert` passes the quad meshes `quad` writes through (to OBJ and PLY, read back
/// with the same quads and positions) and refuses STL, which holds triangles only.
#[test]
fn convert_passes_quad_meshes_through() {
    let dir = Scratch::new("quad-convert");
    let quads = dir.path("q.off");
    let input = data_closed("bunny_npm");
    run_ok(&[
        OsStr::new("quad"),
        input.as_os_str(),
        OsStr::new("-o"),
        quads.as_os_str(),
    ]);
    let (positions, faces) = read_quad_off(&quads);
    for ext in ["obj", "ply"] {
        let out = dir.path(&format!("q.{ext}"));
        run_ok(&[OsStr::new("convert"), quads.as_os_str(), out.as_os_str()]);
        let back = contractible::io::read_poly_mesh(&out, None).expect("readable");
        let got: Vec<Vec<u32>> = back.mesh.faces().map(<[u32]>::to_vec).collect();
        let want: Vec<Vec<u32>> = faces.iter().map(|q| q.to_vec()).collect();
        assert_eq!(got, want, "{ext}");
        assert_eq!(
            back.mesh.positions.as_deref(),
            Some(&positions[..]),
            "{ext}"
        );
    }
    let stl = dir.path("q.stl");
    let out = run(&[OsStr::new("convert"), quads.as_os_str(), stl.as_os_str()]);
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("STL holds triangles only"));
    assert!(!stl.exists());
}
