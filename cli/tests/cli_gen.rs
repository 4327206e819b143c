//! `gen` → `info` round trips for every generator kind, and `convert` round trips.

use crate::cli_common;

use std::ffi::OsStr;

use cli_common::{data_closed, genus_two_file, int, load, run_json, run_ok, Scratch};
use contractible::gen;

/// Expected topology of a generated file.
struct Want {
    vertices: Option<i64>,
    faces: Option<i64>,
    chi: i64,
    orientable: bool,
}

fn gen_and_check(dir: &Scratch, file: &str, args: &[&str], want: Want) -> serde_json::Value {
    let out = dir.path(file);
    let mut all: Vec<&OsStr> = vec![OsStr::new("gen")];
    all.extend(args.iter().map(OsStr::new));
    all.extend([OsStr::new("-o"), out.as_os_str()]);
    let g = run_json(&all);
    let i = run_json(&[OsStr::new("info"), out.as_os_str()]);
    for v in [&g, &i] {
        let what = format!("gen {args:?}");
        assert_eq!(int(v, "components"), 1, "{what}");
        assert_eq!(int(v, "euler_characteristic"), want.chi, "{what}");
        assert_eq!(v["orientable"].as_bool(), Some(want.orientable), "{what}");
        if let Some(n) = want.vertices {
            assert_eq!(int(v, "vertices"), n, "{what}");
        }
        if let Some(n) = want.faces {
            assert_eq!(int(v, "faces"), n, "{what}");
        }
        let c = &v["component_list"][0];
        assert_eq!(int(c, "euler_genus"), 2 - want.chi, "{what}");
        if want.orientable {
            assert_eq!(int(c, "genus"), (2 - want.chi) / 2, "{what}");
        } else {
            assert!(c["genus"].is_null(), "{what}");
        }
    }
    // gen --json reports what info then reads back.
    for k in ["vertices", "edges", "faces", "euler_characteristic"] {
        assert_eq!(g[k], i[k], "{args:?}: {k}");
    }
    i
}

fn exact(v: i64, f: i64, chi: i64, orientable: bool) -> Want {
    Want {
        vertices: Some(v),
        faces: Some(f),
        chi,
        orientable,
    }
}

#[test]
fn standard_surfaces_round_trip() {
    let d = Scratch::new("gen-standard");
    gen_and_check(&d, "t.off", &["tetrahedron"], exact(4, 4, 2, true));
    gen_and_check(&d, "o.obj", &["octahedron"], exact(6, 8, 2, true));
    gen_and_check(&d, "i.ply", &["icosahedron"], exact(12, 20, 2, true));
    gen_and_check(&d, "t7.off.gz", &["torus7"], exact(7, 14, 0, true));
    gen_and_check(&d, "rp2.ply.gz", &["rp2"], exact(6, 10, 1, false));
    gen_and_check(&d, "k.obj.gz", &["klein"], exact(9, 18, 0, false));
}

#[test]
fn random_surfaces_round_trip_and_are_deterministic() {
    let d = Scratch::new("gen-random");
    let args = [
        "random", "--genus", "3", "--faces", "2000", "--flips", "20", "--seed", "5",
    ];
    let i = gen_and_check(
        &d,
        "g3.off",
        &args,
        Want {
            vertices: None,
            faces: None,
            chi: -4,
            orientable: true,
        },
    );
    assert!(int(&i, "faces") >= 2000);
    // Same seed, same file; another seed, another surface.
    gen_and_check(
        &d,
        "g3b.off",
        &args,
        Want {
            vertices: None,
            faces: None,
            chi: -4,
            orientable: true,
        },
    );
    let a = std::fs::read(d.path("g3.off")).unwrap();
    assert_eq!(a, std::fs::read(d.path("g3b.off")).unwrap());
    let mut other = args;
    other[8] = "6";
    gen_and_check(
        &d,
        "g3c.off",
        &other,
        Want {
            vertices: None,
            faces: None,
            chi: -4,
            orientable: true,
        },
    );
    assert_ne!(a, std::fs::read(d.path("g3c.off")).unwrap());
    // No coordinates: every vertex is written at the origin.
    let (mesh, _) = load(&d.path("g3.off"));
    assert!(mesh.positions.unwrap().iter().all(|p| *p == [0.0; 3]));

    let i = gen_and_check(
        &d,
        "n3.ply",
        &["random", "--crosscaps", "3", "--faces", "500"],
        Want {
            vertices: None,
            faces: None,
            chi: -1,
            orientable: false,
        },
    );
    assert!(int(&i, "faces") >= 500);
    gen_and_check(
        &d,
        "s.obj",
        &["random", "--faces", "300"],
        Want {
            vertices: None,
            faces: None,
            chi: 2,
            orientable: true,
        },
    );
}

#[test]
fn bricks_round_trip() {
    let d = Scratch::new("gen-brick");
    let (v, _, f) = gen::brick_counts(&gen::BrickParams {
        cavities: 5,
        holes: 2,
        resolution: 2,
    })
    .expect("valid brick parameters");
    gen_and_check(
        &d,
        "b.off",
        &[
            "brick",
            "--cavities",
            "5",
            "--holes",
            "2",
            "--resolution",
            "2",
        ],
        exact(v as i64, f as i64, -2, true),
    );
    let target = gen::brick_with_target(10, 3, 5000).expect("valid brick parameters");
    let i = gen_and_check(
        &d,
        "bt.ply",
        &[
            "brick",
            "--cavities",
            "10",
            "--holes",
            "3",
            "--faces",
            "5000",
        ],
        exact(
            target.vertex_count as i64,
            target.faces.len() as i64,
            -4,
            true,
        ),
    );
    assert!((int(&i, "faces") - 5000).abs() < 500, "{i}");
    let b9 = gen::paper_family('B', 9).expect("valid brick parameters");
    gen_and_check(
        &d,
        "b9.off.gz",
        &["brick", "--paper", "B9"],
        exact(b9.vertex_count as i64, b9.faces.len() as i64, 2, true),
    );
    // Real coordinates, not all zero.
    let (mesh, _) = load(&d.path("b9.off.gz"));
    assert_eq!(mesh.positions, b9.positions);
}

#[test]
fn subdivide_round_trips_and_keeps_positions() {
    let d = Scratch::new("gen-subdivide");
    let input = genus_two_file(&d);
    let faces_in = load(&input).0.faces.len() as i64;
    let out = d.path("s.off");
    let g = run_json(&[
        OsStr::new("gen"),
        OsStr::new("subdivide"),
        OsStr::new("--input"),
        input.as_os_str(),
        OsStr::new("--levels"),
        OsStr::new("2"),
        OsStr::new("-o"),
        out.as_os_str(),
    ]);
    assert_eq!(int(&g, "faces"), faces_in * 16);
    assert_eq!(int(&g, "euler_characteristic"), -2);
    assert_eq!(int(&g["component_list"][0], "genus"), 2);
    let (orig, _) = load(&input);
    let (sub, _) = load(&out);
    let (p, q) = (orig.positions.unwrap(), sub.positions.unwrap());
    assert_eq!(
        &q[..p.len()],
        &p[..],
        "original vertices keep their positions"
    );
}

#[test]
fn convert_round_trip_off_ply_obj_off_keeps_counts_and_coordinates() {
    let d = Scratch::new("convert");
    let src = data_closed("bunny_npm");
    let chain = [
        src.clone(),
        d.path("a.ply"),
        d.path("b.obj"),
        d.path("c.ply.gz"),
        d.path("d.off"),
    ];
    for w in chain.windows(2) {
        run_ok(&[
            OsStr::new("--quiet"),
            OsStr::new("convert"),
            w[0].as_os_str(),
            w[1].as_os_str(),
        ]);
    }
    let (a, sa) = load(&src);
    let (b, sb) = load(&chain[4]);
    assert_eq!(a, b, "mesh changed in the round trip");
    assert_eq!(sa.counts(), sb.counts());
    // The manifest's counts of bunny_npm.
    let i = run_json(&[OsStr::new("info"), chain[4].as_os_str()]);
    assert_eq!(int(&i, "vertices"), 1839);
    assert_eq!(int(&i, "faces"), 3674);

    // Several components survive (box_stl: 10 in the manifest); unused vertices are
    // dropped and the rest renumbered.
    let multi = data_closed("box_stl");
    let out = d.path("g.obj");
    run_ok(&[
        OsStr::new("-q"),
        OsStr::new("convert"),
        multi.as_os_str(),
        out.as_os_str(),
    ]);
    let i = run_json(&[OsStr::new("info"), out.as_os_str()]);
    assert_eq!(int(&i, "components"), 10);

    let unused = d.path("u.off");
    std::fs::write(
        &unused,
        "OFF\n6 4 0\n0 0 0\n1 0 0\n9 9 9\n0 1 0\n0 0 1\n8 8 8\n3 0 1 3\n3 0 3 4\n3 0 4 1\n3 1 4 3\n",
    )
    .unwrap();
    let out = d.path("u.ply");
    let j = run_json(&[OsStr::new("convert"), unused.as_os_str(), out.as_os_str()]);
    assert_eq!(int(&j, "dropped_vertices"), 2);
    let m = contractible::io::read_tri_mesh(&out).unwrap();
    assert_eq!(m.vertex_count, 4);
    assert_eq!(
        m.positions.unwrap(),
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0]
        ]
    );
    assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3], [0, 3, 1], [1, 3, 2]]);
}
