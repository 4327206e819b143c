//! `gen isosurface`: closed outputs round-trip through `info`; the presets have the
//! paper's sizes; the open hyperboloid is checked here by a hand-written OFF parser and
//! an independent edge/component/boundary count; bad `--surface` values are refused.

use crate::cli_common;

use std::collections::HashMap;
use std::ffi::OsStr;

use cli_common::{int, run, run_json, stderr, Scratch};

fn gen_json(out: &std::path::Path, args: &[&str]) -> serde_json::Value {
    let mut all: Vec<&OsStr> = vec![OsStr::new("gen"), OsStr::new("isosurface")];
    all.extend(args.iter().map(OsStr::new));
    all.extend([OsStr::new("-o"), out.as_os_str()]);
    run_json(&all)
}

#[test]
fn closed_isosurfaces_round_trip_through_info() {
    let d = Scratch::new("gen-iso-closed");
    let cases: [(&[&str], i64); 5] = [
        (&["--surface", "sphere", "--resolution", "16"], 2),
        (&["--surface", "torus", "--tessellation", "bcc"], 0),
        (&["--surface", "genus:2", "--resolution", "60"], -2),
        (
            &[
                "--surface",
                "genus:3",
                "--resolution",
                "80",
                "--tessellation",
                "bcc",
            ],
            -4,
        ),
        (&["--surface", "genus:0", "--resolution", "20"], 2),
    ];
    for (i, (args, chi)) in cases.iter().enumerate() {
        let out = d.path(&format!("s{i}.ply"));
        let g = gen_json(&out, args);
        let info = run_json(&[OsStr::new("info"), out.as_os_str()]);
        for v in [&g, &info] {
            assert_eq!(int(v, "components"), 1, "{args:?}");
            assert_eq!(int(v, "euler_characteristic"), *chi, "{args:?}");
            assert_eq!(v["orientable"].as_bool(), Some(true), "{args:?}");
        }
        for k in ["vertices", "edges", "faces"] {
            assert_eq!(g[k], info[k], "{args:?}: {k}");
        }
    }
}

#[test]
fn paper_torus_preset_has_table_1_size() {
    let d = Scratch::new("gen-iso-paper-torus");
    for tess in ["six", "bcc"] {
        let out = d.path(&format!("t-{tess}.off"));
        let g = gen_json(&out, &["--preset", "paper-torus", "--tessellation", tess]);
        let info = run_json(&[OsStr::new("info"), out.as_os_str()]);
        for v in [&g, &info] {
            assert_eq!(int(v, "vertices"), 16_772, "{tess}");
            assert_eq!(int(v, "faces"), 33_544, "{tess}");
            assert_eq!(int(v, "euler_characteristic"), 0, "{tess}");
        }
    }
}

/// A minimal OFF parser (triangles only), independent of the library's readers.
fn parse_off(text: &str) -> (usize, Vec<[u32; 3]>) {
    let mut tokens = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .flat_map(str::split_whitespace);
    assert_eq!(tokens.next(), Some("OFF"));
    let mut num = || tokens.next().expect("token").to_owned();
    let nv: usize = num().parse().expect("vertex count");
    let nf: usize = num().parse().expect("face count");
    let _edges = num();
    for _ in 0..3 * nv {
        let x: f64 = num().parse().expect("coordinate");
        assert!(x.is_finite());
    }
    let faces = (0..nf)
        .map(|_| {
            assert_eq!(num(), "3");
            [0; 3].map(|_| num().parse::<u32>().expect("index"))
        })
        .collect();
    (nv, faces)
}

#[test]
fn hyperboloid_is_written_as_two_discs() {
    let d = Scratch::new("gen-iso-hyperboloid");
    let cases: [&[&str]; 3] = [
        &["--surface", "hyperboloid", "--resolution", "24"],
        &["--surface", "hyperboloid", "--tessellation", "bcc"],
        &["--preset", "paper-hyperboloid", "--tessellation", "bcc"],
    ];
    for args in cases {
        let out = d.path("h.off");
        let g = gen_json(&out, args);
        let (nv, faces) = parse_off(&std::fs::read_to_string(&out).expect("read output"));
        // Edge incidences and directions.
        let mut edges: HashMap<(u32, u32), Vec<bool>> = HashMap::new();
        for f in &faces {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                edges.entry((a.min(b), a.max(b))).or_default().push(a < b);
            }
        }
        assert!(
            edges.values().all(|d| d.len() <= 2),
            "{args:?}: edge in > 2 faces"
        );
        assert!(
            edges.values().all(|d| d.len() == 1 || d[0] != d[1]),
            "{args:?}: inconsistent orientation"
        );
        // Components (over vertices of faces) and boundary loops.
        let mut parent: Vec<usize> = (0..nv).collect();
        fn root(p: &mut [usize], mut x: usize) -> usize {
            while p[x] != x {
                p[x] = p[p[x]];
                x = p[x];
            }
            x
        }
        for &(a, b) in edges.keys() {
            let (ra, rb) = (root(&mut parent, a as usize), root(&mut parent, b as usize));
            parent[ra] = rb;
        }
        let mut chi: HashMap<usize, i64> = HashMap::new();
        for v in 0..nv {
            *chi.entry(root(&mut parent, v)).or_default() += 1;
        }
        for &(a, _) in edges.keys() {
            *chi.entry(root(&mut parent, a as usize)).or_default() -= 1;
        }
        for f in &faces {
            *chi.entry(root(&mut parent, f[0] as usize)).or_default() += 1;
        }
        assert_eq!(chi.len(), 2, "{args:?}: two sheets");
        assert!(chi.values().all(|&c| c == 1), "{args:?}: discs, χ {chi:?}");
        let mut bparent: Vec<usize> = (0..nv).collect();
        let mut bverts = Vec::new();
        let mut boundary = 0;
        for (&(a, b), d) in &edges {
            if d.len() == 1 {
                boundary += 1;
                let (ra, rb) = (
                    root(&mut bparent, a as usize),
                    root(&mut bparent, b as usize),
                );
                bparent[ra] = rb;
                bverts.push(a as usize);
            }
        }
        let mut loops: Vec<usize> = bverts.iter().map(|&v| root(&mut bparent, v)).collect();
        loops.sort_unstable();
        loops.dedup();
        assert_eq!(loops.len(), 2, "{args:?}: one boundary loop per sheet");
        // The JSON agrees with what was written.
        assert_eq!(int(&g, "vertices"), nv as i64);
        assert_eq!(int(&g, "faces"), faces.len() as i64);
        assert_eq!(int(&g, "edges"), edges.len() as i64);
        assert_eq!(int(&g, "boundary_edges"), boundary);
        assert_eq!(int(&g, "components"), 2);
        assert_eq!(int(&g, "euler_characteristic"), 2);
        if args.contains(&"paper-hyperboloid") {
            assert_eq!((nv, faces.len()), (56_288, 111_140));
        }
    }
}

#[test]
fn bad_surfaces_and_resolutions_are_refused() {
    let d = Scratch::new("gen-iso-bad");
    let out = d.path("x.off");
    for args in [
        &["--surface", "cube"][..],
        &["--surface", "genus:"],
        &["--surface", "genus:-1"],
        &["--surface", "sphere", "--resolution", "0"],
        &["--surface", "sphere", "--resolution", "100000"],
    ] {
        let mut all: Vec<&OsStr> = vec![OsStr::new("gen"), OsStr::new("isosurface")];
        all.extend(args.iter().map(OsStr::new));
        all.extend([OsStr::new("-o"), out.as_os_str()]);
        let o = run(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains("--"), "{args:?}: {}", stderr(&o));
        assert!(!out.exists(), "{args:?} wrote a file");
    }
}
