//! STL through the binary: files written here (binary and ASCII, independently of the
//! library's writer) describe the same surface as the OFF they came from; `--weld` on an
//! OBJ triangle soup; located errors for malformed STL.

use std::collections::HashSet;
use std::fmt::Write as _;
use std::path::Path;

use crate::cli_common::{
    cube_mesh, data_closed, genus_two_file, int, read_mesh, run, run_json, run_ok, stderr, Scratch,
};

/// The keys of `info --json` that describe the surface (not the file or the timings).
const TOPOLOGY_KEYS: [&str; 6] = [
    "vertices",
    "edges",
    "faces",
    "euler_characteristic",
    "components",
    "orientable",
];

fn topology(v: &serde_json::Value) -> Vec<serde_json::Value> {
    TOPOLOGY_KEYS
        .iter()
        .map(|k| {
            v.get(*k)
                .cloned()
                .unwrap_or_else(|| panic!("missing {k:?} in {v}"))
        })
        .collect()
}

/// A binary STL written byte by byte: 80-byte header, count, then per triangle a zero
/// normal, the corners as little-endian `f32`, a zero attribute count.
fn binary_stl(m: &contractible::TriMesh, header: &[u8]) -> Vec<u8> {
    let p = m.positions.as_ref().expect("positions");
    let mut b = header.to_vec();
    b.resize(80, b' ');
    b.extend_from_slice(&(m.faces.len() as u32).to_le_bytes());
    for f in &m.faces {
        b.extend_from_slice(&[0u8; 12]);
        for &v in f {
            for x in p[v as usize] {
                b.extend_from_slice(&(x as f32).to_le_bytes());
            }
        }
        b.extend_from_slice(&[0, 0]);
    }
    b
}

/// An ASCII STL with the positions in full `f64` precision.
fn ascii_stl(m: &contractible::TriMesh) -> String {
    let p = m.positions.as_ref().expect("positions");
    let mut s = String::from("solid test mesh\n");
    for f in &m.faces {
        s.push_str(" facet normal 0 0 0\n  outer loop\n");
        for &v in f {
            let [x, y, z] = p[v as usize];
            writeln!(s, "   vertex {x:e} {y:e} {z:e}").unwrap();
        }
        s.push_str("  endloop\n endfacet\n");
    }
    s.push_str("endsolid test mesh\n");
    s
}

/// Every face as its own three OBJ vertices (an unwelded soup).
fn soup_obj(m: &contractible::TriMesh) -> String {
    let p = m.positions.as_ref().expect("positions");
    let mut s = String::new();
    for f in &m.faces {
        for &v in f {
            let [x, y, z] = p[v as usize];
            writeln!(s, "v {x} {y} {z}").unwrap();
        }
    }
    for i in 0..m.faces.len() {
        writeln!(s, "f {} {} {}", 3 * i + 1, 3 * i + 2, 3 * i + 3).unwrap();
    }
    s
}

#[test]
fn stl_binary_and_ascii_give_the_same_info_as_the_off() {
    // A real mesh of genus 3 (χ = −4 in the manifest).
    let off = data_closed("high_genus_3");
    let m = read_mesh(&off);
    // Precondition of the comparison: the vertices stay distinct in f32, and every vertex
    // is used (STL cannot hold an unused vertex).
    let p = m.positions.as_ref().unwrap();
    let distinct: HashSet<[u32; 3]> = p.iter().map(|q| q.map(|x| (x as f32).to_bits())).collect();
    assert_eq!(distinct.len(), m.vertex_count);
    let expected = run_json(&[Path::new("info"), &off]);
    assert_eq!(int(&expected, "dropped_vertices"), 0);
    assert_eq!(int(&expected, "euler_characteristic"), -4);

    let dir = Scratch::new("stl-round-trip");
    let bin = dir.path("hg3_binary.stl");
    // A header starting with `solid`, as many exporters write it.
    std::fs::write(&bin, binary_stl(&m, b"solid hg3 (binary)")).unwrap();
    let asc = dir.path("hg3_ascii.STL");
    std::fs::write(&asc, ascii_stl(&m)).unwrap();
    let unnamed = dir.path("hg3_ascii_stl_content.mesh");
    std::fs::write(&unnamed, ascii_stl(&m)).unwrap();
    // The library's writer, plain and gzip, through `convert`.
    let converted = dir.path("hg3_converted.stl");
    let converted_gz = dir.path("hg3_converted.stl.gz");
    run_ok(&[Path::new("convert"), &off, &converted]);
    run_ok(&[Path::new("convert"), &off, &converted_gz]);
    assert_eq!(
        std::fs::metadata(&converted).unwrap().len(),
        84 + 50 * m.faces.len() as u64
    );
    for file in [&bin, &asc, &unnamed, &converted, &converted_gz] {
        let got = run_json(&[Path::new("info"), file]);
        assert_eq!(
            topology(&got),
            topology(&expected),
            "{}: {got}",
            file.display()
        );
        assert!(got.get("welded_vertices").is_none(), "{got}");
    }
}

#[test]
fn obj_soup_fails_with_the_soup_hint_and_succeeds_with_weld() {
    let dir = Scratch::new("stl-soup");
    // A genus-2 surface whose vertices all have distinct positions.
    let off = genus_two_file(&dir);
    let m = read_mesh(&off);
    let expected = run_json(&[Path::new("info"), &off]);
    let soup = dir.path("soup.obj");
    std::fs::write(&soup, soup_obj(&m)).unwrap();
    let soup_s = soup.to_str().unwrap();

    // Commands that need closed surfaces refuse it, saying it looks like a soup.
    for command in ["reduce", "quad"] {
        let out = run(&[command, soup_s]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{command}: {err}");
        assert!(err.contains("boundary edge"), "{command}: {err}");
        assert!(
            err.contains("unwelded triangle soup") && err.contains("try --weld"),
            "{command}: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
    // `info` accepts it (each triangle is a disc) but warns.
    let out = run_ok(&["info", soup_s]);
    assert!(
        stderr(&out).contains("unwelded triangle soup"),
        "{}",
        stderr(&out)
    );

    // With --weld: the OFF's surface, the merge count on stderr and in the JSON.
    let merged = (3 * m.faces.len() - m.vertex_count) as i64;
    let out = run_ok(&["info", "--weld", soup_s]);
    let err = stderr(&out);
    assert!(
        err.contains(&format!("--weld merged {merged} vertices")),
        "{err}"
    );
    assert!(!err.contains("unwelded"), "{err}");
    let got = run_json(&["info", "--weld", soup_s]);
    assert_eq!(topology(&got), topology(&expected));
    assert_eq!(int(&got, "welded_vertices"), merged);

    let r = run_json(&["reduce", "--weld", soup_s]);
    assert_eq!(int(&r, "welded_vertices"), merged);
    assert_eq!(int(&r, "euler_characteristic"), -2);
    assert_eq!(r["irreducible"], serde_json::Value::Bool(true));

    let q = run_json(&["quad", "--weld", soup_s]);
    assert_eq!(int(&q, "welded_vertices"), merged);
    assert_eq!(int(&q, "quads") * 2, m.faces.len() as i64);

    let welded_off = dir.path("welded.off");
    let c = run_json(&["convert", "--weld", soup_s, welded_off.to_str().unwrap()]);
    assert_eq!(int(&c, "welded_vertices"), merged);
    assert_eq!(int(&c, "vertices"), m.vertex_count as i64);
    let got = run_json(&[Path::new("info"), &welded_off]);
    assert_eq!(topology(&got), topology(&expected));

    let simplified = dir.path("simplified.off");
    let s = run_json(&[
        "simplify",
        "--weld",
        soup_s,
        "-o",
        simplified.to_str().unwrap(),
        "--eps-rel",
        "0.01",
    ]);
    assert_eq!(int(&s, "welded_vertices"), merged);
    // Without --weld, the key is absent.
    let plain = run_json(&[Path::new("info"), &off]);
    assert!(plain.get("welded_vertices").is_none());
}

/// Runs `info` on `bytes` written to `name`; asserts exit code 2, no panic, and that the
/// output (stdout and stderr) contains every one of `needles`.
fn assert_refused(dir: &Scratch, name: &str, bytes: &[u8], needles: &[&str]) {
    let path = dir.path(name);
    std::fs::write(&path, bytes).unwrap();
    let out = run(&[Path::new("info"), &path]);
    // Syntax errors are on stderr; problems of the surface are listed on stdout.
    let err = format!("{}{}", String::from_utf8_lossy(&out.stdout), stderr(&out));
    assert_eq!(out.status.code(), Some(2), "{name}: {err}");
    assert!(!err.contains("panicked"), "{name}: {err}");
    for n in needles {
        assert!(err.contains(n), "{name}: expected {n:?} in {err}");
    }
}

#[test]
fn malformed_stl_gives_located_errors() {
    let m = cube_mesh();
    let good = binary_stl(&m, b"cube");
    let dir = Scratch::new("stl-malformed");
    // Cut 10 bytes into triangle 3.
    assert_refused(
        &dir,
        "truncated.stl",
        &good[..84 + 3 * 50 + 10],
        &["byte offset 234", "truncated"],
    );
    assert_refused(
        &dir,
        "header_only.stl",
        &good[..40],
        &["byte offset 40", "truncated"],
    );
    // The count says 13 (or 4 billion) triangles, the file holds 12.
    for count in [13u32, u32::MAX] {
        let mut bad = good.clone();
        bad[80..84].copy_from_slice(&count.to_le_bytes());
        assert_refused(
            &dir,
            "bad_count.stl",
            &bad,
            &["byte offset 80", &format!("declares {count}, found 12")],
        );
    }
    let mut bad = good.clone();
    bad[80..84].copy_from_slice(&11u32.to_le_bytes());
    assert_refused(
        &dir,
        "long.stl",
        &bad,
        &["byte offset 634", "unexpected data"],
    );
    // NaN as the x of triangle 5's second corner: 84 + 5·50 + 12 + 12.
    let mut bad = good.clone();
    bad[358..362].copy_from_slice(&f32::NAN.to_le_bytes());
    assert_refused(&dir, "nan.stl", &bad, &["byte offset 358", "bad number"]);
    // ASCII: NaN, cut before `endsolid`, a misspelt keyword; and gzip-compressed.
    let text = ascii_stl(&m);
    let nan = text.replacen("vertex ", "vertex NaN ", 1);
    assert_refused(
        &dir,
        "nan_ascii.stl",
        nan.as_bytes(),
        &["line 4", "bad number \"NaN\""],
    );
    let lines: Vec<&str> = text.lines().collect();
    let cut = lines[..lines.len() - 1].join("\n");
    assert_refused(
        &dir,
        "cut_ascii.stl",
        cut.as_bytes(),
        &[&format!("line {}", lines.len() - 1), "truncated"],
    );
    let typo = text.replacen("endloop", "endlop", 1);
    assert_refused(
        &dir,
        "typo.stl",
        typo.as_bytes(),
        &["line 7", "found \"endlop\""],
    );
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    std::io::Write::write_all(&mut gz, nan.as_bytes()).unwrap();
    assert_refused(
        &dir,
        "nan_ascii.stl.gz",
        &gz.finish().unwrap(),
        &["line 4", "bad number"],
    );
    // A degenerate triangle (two corners at one position) is refused by validation,
    // naming the face, as for the other formats.
    let mut degenerate = m.clone();
    degenerate.faces[7][1] = degenerate.faces[7][0];
    assert_refused(
        &dir,
        "degenerate.stl",
        &binary_stl(&degenerate, b"cube"),
        &["face 7", "degenerate"],
    );
}
