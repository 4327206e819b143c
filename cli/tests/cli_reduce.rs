//! `reduce` and `demo` through the binary: counters, JSON keys, the output file (original
//! coordinates, irreducible per component by the naive test, same χ per component).
//! Every algorithm (`rs`, `schipper`, `brute`) is exercised.

use crate::cli_common;

use std::ffi::OsStr;
use std::path::{Path, PathBuf};

use cli_common::{
    data_closed, disjoint_tetrahedra, genus_two_file, int, load, read_mesh, run, run_json, run_ok,
    tetrahedron_file, with_holes, Scratch,
};

const KEYS: [&str; 14] = [
    "algo",
    "vertices_in",
    "edges_in",
    "faces_in",
    "euler_characteristic",
    "orientable",
    "genus",
    "euler_genus",
    "vertices_out",
    "faces_out",
    "link_tests",
    "edges_tested_more_than_once",
    "contractions",
    "seconds",
];

/// Runs `reduce --json --algo ALGO IN -o OUT` and checks everything about the result.
fn check_reduce(input: &Path, algo: &str, dir: &Scratch, out_name: &str) -> serde_json::Value {
    let out = dir.path(out_name);
    let j = run_json(&[
        OsStr::new("reduce"),
        OsStr::new("--algo"),
        OsStr::new(algo),
        OsStr::new("--seed"),
        OsStr::new("3"),
        input.as_os_str(),
        OsStr::new("-o"),
        out.as_os_str(),
    ]);
    let what = format!("{} ({algo})", input.display());
    for k in KEYS {
        assert!(j.get(k).is_some(), "{what}: top-level key {k} missing");
    }
    assert_eq!(j["algo"], algo);
    assert_eq!(j["irreducible"], true, "{what}");
    let comps = j["component_list"].as_array().expect("component_list");
    assert_eq!(comps.len() as i64, int(&j, "components"));
    for c in comps {
        for k in KEYS {
            assert!(c.get(k).is_some(), "{what}: component key {k} missing");
        }
        assert_eq!(
            int(c, "contractions"),
            int(c, "vertices_in") - int(c, "vertices_out"),
            "{what}"
        );
        if algo == "rs" {
            // ℓ ≤ E for RS (every edge tested at most once).
            assert!(int(c, "link_tests") <= int(c, "edges_in"), "{what}");
        }
    }
    let sum = |k: &str| comps.iter().map(|c| int(c, k)).sum::<i64>();
    for k in [
        "vertices_in",
        "vertices_out",
        "faces_out",
        "contractions",
        "link_tests",
    ] {
        assert_eq!(sum(k), int(&j, k), "{what}: total {k}");
    }
    if algo == "rs" {
        assert_eq!(
            int(&j, "edges_tested_more_than_once"),
            0,
            "{what}: ε_RS = 0"
        );
    }

    // The output reloads, has the same components with the same χ and orientability,
    // each irreducible, and its vertices sit at original input coordinates.
    let (in_mesh, in_s) = load(input);
    let (out_mesh, out_s) = load(&out);
    assert_eq!(in_s.components.len(), out_s.components.len(), "{what}");
    let mut chi_in: Vec<(i64, bool)> = in_s
        .components
        .iter()
        .map(|c| (c.tri.euler_characteristic(), c.tri.is_orientable()))
        .collect();
    let mut chi_out: Vec<(i64, bool)> = out_s
        .components
        .iter()
        .map(|c| (c.tri.euler_characteristic(), c.tri.is_orientable()))
        .collect();
    chi_in.sort();
    chi_out.sort();
    assert_eq!(chi_in, chi_out, "{what}: χ per component");
    for c in &out_s.components {
        assert!(c.tri.is_irreducible_naive(), "{what}: output reducible");
    }
    assert_eq!(out_mesh.vertex_count as i64, int(&j, "vertices_out"));
    assert_eq!(out_mesh.faces.len() as i64, int(&j, "faces_out"));
    let pin = in_mesh.positions.expect("input positions");
    let pout = out_mesh.positions.expect("output positions");
    let bits = |p: &[f64; 3]| p.map(f64::to_bits);
    let known: std::collections::HashSet<[u64; 3]> = pin.iter().map(bits).collect();
    assert!(
        pout.iter().all(|p| known.contains(&bits(p))),
        "{what}: an output vertex has coordinates not in the input"
    );
    j
}

/// 167 disjoint tetrahedra (each irreducible), written as `DIR/tetrahedra.off.gz`.
fn tetrahedra_file(dir: &Scratch) -> PathBuf {
    let path = dir.path("tetrahedra.off.gz");
    contractible::io::write_mesh(&path, &disjoint_tetrahedra(167)).unwrap();
    path
}

/// The vertex count an OFF file's header declares (its second line, `V F E`).
fn off_vertices(path: &Path) -> i64 {
    let text = std::fs::read_to_string(path).unwrap();
    let header = text.lines().nth(1).expect("counts line");
    header.split_whitespace().next().unwrap().parse().unwrap()
}

#[test]
fn reduce_tetrahedron_does_nothing() {
    let d = Scratch::new("reduce-tet");
    let tet = tetrahedron_file(&d);
    let j = check_reduce(&tet, "rs", &d, "t.off");
    assert_eq!(int(&j, "contractions"), 0);
    assert_eq!(int(&j, "vertices_out"), 4);
    let (a, _) = load(&tet);
    let (b, _) = load(&d.path("t.off"));
    assert_eq!(a, b, "T4 must come back unchanged");
}

#[test]
fn reduce_generated_torus_and_klein_bottle() {
    let d = Scratch::new("reduce-torus");
    let t = d.path("torus.ply");
    run_ok(&[
        OsStr::new("-q"),
        OsStr::new("gen"),
        OsStr::new("random"),
        OsStr::new("--genus"),
        OsStr::new("1"),
        OsStr::new("--faces"),
        OsStr::new("3000"),
        OsStr::new("--flips"),
        OsStr::new("30"),
        OsStr::new("-o"),
        t.as_os_str(),
    ]);
    let j = check_reduce(&t, "rs", &d, "torus_red.off");
    assert_eq!(int(&j, "genus"), 1);
    assert!(int(&j, "vertices_out") >= 7 && int(&j, "vertices_out") <= 10);

    let k = d.path("klein.off");
    run_ok(&[
        OsStr::new("-q"),
        OsStr::new("gen"),
        OsStr::new("random"),
        OsStr::new("--crosscaps"),
        OsStr::new("2"),
        OsStr::new("--faces"),
        OsStr::new("1000"),
        OsStr::new("-o"),
        k.as_os_str(),
    ]);
    let j = check_reduce(&k, "rs", &d, "klein_red.obj");
    assert!(j["genus"].is_null());
    assert_eq!(int(&j, "euler_genus"), 2);
    assert_eq!(j["orientable"], false);
}

#[test]
fn reduce_double_torus() {
    let d = Scratch::new("reduce-dt");
    let input = genus_two_file(&d);
    let j = check_reduce(&input, "rs", &d, "dt.off");
    assert_eq!(int(&j, "genus"), 2);
    assert_eq!(int(&j, "vertices_in"), off_vertices(&input));
}

#[test]
fn reduce_167_tetrahedra() {
    let d = Scratch::new("reduce-mctet");
    let j = check_reduce(&tetrahedra_file(&d), "rs", &d, "m.off.gz");
    assert_eq!(int(&j, "components"), 167);
    assert_eq!(int(&j, "contractions"), 0);
}

#[test]
fn reduce_quiet_prints_nothing_and_human_prints_a_table() {
    let d = Scratch::new("reduce-quiet");
    let input = genus_two_file(&d);
    let out = run_ok(&[
        OsStr::new("--quiet"),
        OsStr::new("reduce"),
        input.as_os_str(),
    ]);
    assert!(out.stdout.is_empty());
    assert!(out.stderr.is_empty(), "{}", cli_common::stderr(&out));
    let out = run_ok(&[OsStr::new("reduce"), input.as_os_str()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("total"), "{text}");
    assert!(text.contains("g=2"), "{text}");
}

#[test]
fn reduce_rejects_invalid_input_with_exit_2() {
    // A real mesh with a hole cut in it.
    let d = Scratch::new("reduce-open");
    let open = d.path("open.off.gz");
    contractible::io::write_mesh(&open, &with_holes(&read_mesh(&data_closed("bunny_npm")), 1))
        .unwrap();
    let out = run(&[OsStr::new("reduce"), open.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
}

#[test]
fn reduce_schipper() {
    let d = Scratch::new("reduce-schipper");
    check_reduce(&genus_two_file(&d), "schipper", &d, "a.off");
    check_reduce(&tetrahedra_file(&d), "schipper", &d, "b.off");
    // A real CAD model of genus 5.
    check_reduce(&data_closed("plate_holes_stl"), "schipper", &d, "c.off");
}

#[test]
fn reduce_brute() {
    let d = Scratch::new("reduce-brute");
    check_reduce(&genus_two_file(&d), "brute", &d, "a.off");
    check_reduce(&tetrahedra_file(&d), "brute", &d, "b.off");
    // A real CAD model of genus 5.
    check_reduce(&data_closed("plate_holes_stl"), "brute", &d, "c.off");
}

#[test]
fn demo_rs_only_verifies() {
    let out = run_ok(&["demo", "--algos", "rs"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("verified irreducible by the naive link test"),
        "{text}"
    );
    let j = run_json(&["demo", "--algos", "rs", "--seed", "1"]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["inputs"].as_array().map(Vec::len), Some(3));
}

#[test]
fn demo_exits_0() {
    let out = run(&["demo", "--quiet"]);
    assert_eq!(out.status.code(), Some(0), "{}", cli_common::stderr(&out));
    assert!(out.stdout.is_empty());
}

/// `--jobs`: the components of a mesh (here 5 surfaces of both orientabilities)
/// reduced and paired one after another and three at once give the same files and the
/// same statistics, timings aside; `--jobs 0` is refused as bad input.
#[test]
fn jobs_change_nothing_but_the_time() {
    use contractible::gen;
    let d = Scratch::new("reduce-jobs");
    let parts = [
        gen::subdivide(&gen::icosahedron(), 2).unwrap(),
        gen::subdivide(&gen::torus7(), 2).unwrap(),
        gen::subdivide(&gen::klein_bottle(), 2).unwrap(),
        gen::subdivide(&gen::projective_plane6(), 3).unwrap(),
        gen::octahedron(),
    ];
    let (mut faces, mut n) = (Vec::new(), 0u32);
    for p in &parts {
        faces.extend(p.faces.iter().map(|f| f.map(|v| v + n)));
        n += p.vertex_count as u32;
    }
    let input = d.path("five.off");
    contractible::io::write_mesh(
        &input,
        &contractible::TriMesh::combinatorial(n as usize, faces),
    )
    .unwrap();
    for (task, extra) in [("reduce", &[][..]), ("quad", &["--algo", "ds"][..])] {
        let mut seen = Vec::new();
        for jobs in ["1", "3"] {
            let out = d.path(&format!("{task}-{jobs}.off"));
            let mut args: Vec<&OsStr> = vec![
                OsStr::new(task),
                input.as_os_str(),
                OsStr::new("-o"),
                out.as_os_str(),
                OsStr::new("--jobs"),
                OsStr::new(jobs),
            ];
            args.extend(extra.iter().map(OsStr::new));
            let mut j = run_json(&args);
            j.as_object_mut().map(|o| o.remove("output"));
            assert_eq!(
                j["component_list"].as_array().map(Vec::len),
                Some(5),
                "{task}"
            );
            seen.push((cli_common::untimed(&j), std::fs::read(&out).unwrap()));
        }
        assert_eq!(seen[0], seen[1], "{task}");
    }
    // simplify, on three marching-tetrahedra surfaces side by side.
    let shapes = [
        gen::Implicit::Sphere { radius: 1.0 },
        gen::Implicit::Torus {
            major: 1.0,
            minor: 0.4,
        },
        gen::Implicit::GenusG { g: 2 },
    ];
    let (mut positions, mut faces) = (Vec::new(), Vec::new());
    for (k, shape) in shapes.into_iter().enumerate() {
        let params = gen::IsoParams::new(shape, gen::Tessellation::SixTetrahedra, 12);
        let m = gen::isosurface(&params).unwrap();
        let n = positions.len() as u32;
        let shift = 6.0 * k as f64;
        positions.extend(
            m.positions
                .unwrap()
                .iter()
                .map(|p| [p[0] + shift, p[1], p[2]]),
        );
        faces.extend(m.faces.iter().map(|f| f.map(|v| v + n)));
    }
    let input = d.path("three.off");
    contractible::io::write_mesh(
        &input,
        &contractible::TriMesh::with_positions(positions, faces),
    )
    .unwrap();
    let mut seen = Vec::new();
    for jobs in ["1", "3"] {
        let out = d.path(&format!("simplify-{jobs}.off"));
        let mut j = run_json(&[
            OsStr::new("simplify"),
            input.as_os_str(),
            OsStr::new("-o"),
            out.as_os_str(),
            OsStr::new("--eps-rel"),
            OsStr::new("0.02"),
            OsStr::new("--jobs"),
            OsStr::new(jobs),
        ]);
        j.as_object_mut().map(|o| o.remove("output"));
        assert_eq!(j["components"].as_u64(), Some(3), "{j}");
        assert!(j["edges_contracted"].as_u64() > Some(0), "{j}");
        seen.push((cli_common::untimed(&j), std::fs::read(&out).unwrap()));
    }
    assert_eq!(seen[0], seen[1], "simplify");
    let out = run(&[
        OsStr::new("reduce"),
        input.as_os_str(),
        OsStr::new("--jobs"),
        OsStr::new("0"),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        cli_common::stderr(&out).contains("--jobs"),
        "{}",
        cli_common::stderr(&out)
    );
}
