//! Tests of the mesh file readers and writers (`contractible::io`).

use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use contractible::io::{
    read_tri_mesh, read_tri_mesh_bytes, read_tri_mesh_from, write_mesh, write_mesh_to,
    write_ply_to, Format, Location, PlyEncoding, ReadError, ReadErrorKind as K, WriteError,
};
use contractible::{Mesh, QuadMesh, TriMesh};

// The reader handing out 1 to 7 bytes per call, shared with the fuzz harness.
use crate::fuzz_regressions::harness::Trickle;

/// A predicate on an error kind.
type KindCheck = fn(&K) -> bool;

/// The small real meshes the repository carries (the corpus run reads the corpus's).
const MESHES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/meshes");

/// Coordinates that stress shortest-round-trip formatting.
fn tricky_positions(n: usize) -> Vec<[f64; 3]> {
    let special = [
        0.1,
        -0.0,
        1e300,
        -1e-300,
        5e-324,
        std::f64::consts::PI,
        f64::MAX,
        f64::MIN_POSITIVE,
        123_456_789.123_456_78,
        -2.5,
        1.0 / 3.0,
        7.0,
    ];
    (0..n)
        .map(|i| {
            [
                special[i % special.len()],
                special[(i * 5 + 1) % special.len()],
                (i as f64) * 0.7 - 3.0,
            ]
        })
        .collect()
}

/// An octahedron (closed, 6 vertices, 8 triangles) with tricky coordinates.
fn octahedron() -> TriMesh {
    Mesh::with_positions(tricky_positions(6), contractible::gen::octahedron().faces)
}

/// A cube as 6 quads.
fn cube() -> QuadMesh {
    let faces = vec![
        [0, 1, 3, 2],
        [4, 6, 7, 5],
        [0, 4, 5, 1],
        [2, 3, 7, 6],
        [0, 2, 6, 4],
        [1, 5, 7, 3],
    ];
    Mesh::with_positions(tricky_positions(8), faces)
}

fn bits(p: &[[f64; 3]]) -> Vec<[u64; 3]> {
    p.iter().map(|q| q.map(f64::to_bits)).collect()
}

fn assert_same(a: &TriMesh, b: &TriMesh) {
    assert_eq!(a.vertex_count, b.vertex_count);
    assert_eq!(a.faces, b.faces);
    assert_eq!(
        bits(a.positions.as_ref().unwrap()),
        bits(b.positions.as_ref().unwrap())
    );
}

fn to_bytes<const N: usize>(mesh: &Mesh<N>, format: Format, ply_binary: bool) -> Vec<u8> {
    let mut out = Vec::new();
    write_mesh_to(&mut out, mesh, format, ply_binary).unwrap();
    out
}

fn tmp(name: &str) -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("io_formats_{name}"))
}

/// The error reading `bytes` as `format` gives, which must be the same (kind and
/// location) whether the bytes are read from memory (their length known) or streamed in
/// dribs and drabs from a reader (their length unknown).
fn err(bytes: &[u8], format: Format) -> ReadError {
    let e = match read_tri_mesh_bytes(bytes, Some(format)) {
        Ok(m) => panic!("expected an error, read {m:?}"),
        Err(e) => e,
    };
    let streamed =
        read_tri_mesh_from(Trickle::new(bytes), format).expect_err("the same error when streamed");
    assert_eq!(
        (format!("{:?}", streamed.kind), streamed.location),
        (format!("{:?}", e.kind), e.location),
        "streamed and in-memory reading disagree"
    );
    e
}

// ---------------------------------------------------------------- round trips

#[test]
fn tri_round_trip_all_formats_in_memory() {
    let m = octahedron();
    for (format, binary) in [
        (Format::Off, false),
        (Format::Obj, false),
        (Format::Ply, false),
        (Format::Ply, true),
    ] {
        let bytes = to_bytes(&m, format, binary);
        let back = read_tri_mesh_bytes(&bytes, Some(format)).unwrap();
        assert_same(&m, &back);
        // Sniffing finds the same format.
        assert_eq!(Format::sniff(&bytes), Some(format));
        assert_same(&m, &read_tri_mesh_bytes(&bytes, None).unwrap());
        assert_same(
            &m,
            &read_tri_mesh_from(Trickle::new(&bytes), format).unwrap(),
        );
    }
    for enc in [
        PlyEncoding::Ascii,
        PlyEncoding::BinaryLittleEndian,
        PlyEncoding::BinaryBigEndian,
    ] {
        let mut bytes = Vec::new();
        write_ply_to(&mut bytes, &m, enc).unwrap();
        assert_same(&m, &read_tri_mesh_bytes(&bytes, Some(Format::Ply)).unwrap());
    }
}

#[test]
fn tri_round_trip_files_with_and_without_gzip() {
    let m = octahedron();
    for name in [
        "t.off", "t.obj", "t.ply", "t.off.gz", "t.OBJ.GZ", "t.Ply.gz", "t.OFF",
    ] {
        let path = tmp(name);
        write_mesh(&path, &m).unwrap();
        let raw = std::fs::read(&path).unwrap();
        assert_eq!(
            raw.starts_with(&[0x1f, 0x8b]),
            name.to_ascii_lowercase().ends_with(".gz"),
            "{name}"
        );
        assert_same(&m, &read_tri_mesh(&path).unwrap());
        // gzip also detected in memory / from a reader by its magic bytes.
        let format = Format::from_path(&path).0.unwrap();
        assert_same(&m, &read_tri_mesh_from(&raw[..], format).unwrap());
    }
    // Unknown extension: content is sniffed, gzip detected by magic.
    let path = tmp("t.off.gz");
    let renamed = tmp("t.mesh");
    std::fs::copy(&path, &renamed).unwrap();
    assert_same(&m, &read_tri_mesh(&renamed).unwrap());
}

#[test]
fn combinatorial_mesh_written_with_zero_positions() {
    let m = TriMesh::combinatorial(4, vec![[0, 1, 2], [0, 3, 1], [1, 3, 2], [2, 3, 0]]);
    for (format, binary) in [
        (Format::Off, false),
        (Format::Obj, false),
        (Format::Ply, false),
        (Format::Ply, true),
    ] {
        let back = read_tri_mesh_bytes(&to_bytes(&m, format, binary), Some(format)).unwrap();
        assert_eq!(back.faces, m.faces);
        assert_eq!(back.positions, Some(vec![[0.0; 3]; 4]));
    }
}

/// Reads quads written by our writers back with an independent parser: ply-rs-bw for PLY,
/// a few lines of splitting for OFF and OBJ.
#[test]
fn quad_round_trip_all_formats() {
    let m = cube();
    let pos = bits(m.positions.as_ref().unwrap());

    // OFF
    let text = String::from_utf8(to_bytes(&m, Format::Off, false)).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("OFF"));
    assert_eq!(lines.next(), Some("8 6 0"));
    let lines: Vec<&str> = lines.collect();
    let read_pos: Vec<[f64; 3]> = lines[..8].iter().map(|l| xyz(l.split(' '))).collect();
    assert_eq!(bits(&read_pos), pos);
    let read_faces: Vec<Vec<u32>> = lines[8..]
        .iter()
        .map(|l| l.split(' ').map(|t| t.parse().unwrap()).collect())
        .collect();
    for (f, r) in m.faces.iter().zip(&read_faces) {
        assert_eq!(r[0], 4);
        assert_eq!(&r[1..], f);
    }

    // OBJ
    let text = String::from_utf8(to_bytes(&m, Format::Obj, false)).unwrap();
    let vs: Vec<[f64; 3]> = text
        .lines()
        .filter_map(|l| l.strip_prefix("v "))
        .map(|l| xyz(l.split(' ')))
        .collect();
    assert_eq!(bits(&vs), pos);
    let fs: Vec<Vec<u32>> = text
        .lines()
        .filter_map(|l| l.strip_prefix("f "))
        .map(|l| {
            l.split(' ')
                .map(|t| t.parse::<u32>().unwrap() - 1)
                .collect()
        })
        .collect();
    assert_eq!(fs, m.faces.iter().map(|f| f.to_vec()).collect::<Vec<_>>());

    // PLY, every encoding, read by ply-rs-bw.
    for enc in [
        PlyEncoding::Ascii,
        PlyEncoding::BinaryLittleEndian,
        PlyEncoding::BinaryBigEndian,
    ] {
        let mut bytes = Vec::new();
        write_ply_to(&mut bytes, &m, enc).unwrap();
        let (p, f) = read_with_ply_rs(&bytes);
        assert_eq!(bits(&p), pos, "{enc:?}");
        assert_eq!(f, m.faces.iter().map(|f| f.to_vec()).collect::<Vec<_>>());
        // Our own reader rejects the quads, naming face 0.
        let e = err(&bytes, Format::Ply);
        assert!(
            matches!(
                e.kind,
                K::NonTriangleFace {
                    face: 0,
                    corners: 4
                }
            ),
            "{e}"
        );
    }

    // Quads to files (with gzip) also round-trip through ply-rs-bw.
    let path = tmp("cube.ply.gz");
    write_mesh(&path, &m).unwrap();
    let mut raw = Vec::new();
    use std::io::Read;
    flate2::read::GzDecoder::new(std::fs::File::open(&path).unwrap())
        .read_to_end(&mut raw)
        .unwrap();
    assert!(raw.starts_with(b"ply\nformat binary_little_endian 1.0\n"));
    assert_eq!(bits(&read_with_ply_rs(&raw).0), pos);
}

fn xyz<'a>(mut t: impl Iterator<Item = &'a str>) -> [f64; 3] {
    [(); 3].map(|_| t.next().unwrap().parse().unwrap())
}

fn read_with_ply_rs(bytes: &[u8]) -> (Vec<[f64; 3]>, Vec<Vec<u32>>) {
    use ply_rs_bw::parser::Parser;
    use ply_rs_bw::ply::{DefaultElement, Property};
    let ply = Parser::<DefaultElement>::new()
        .read_ply(&mut &bytes[..])
        .unwrap();
    let num = |p: &Property| match p {
        Property::Double(x) => *x,
        other => panic!("{other:?}"),
    };
    let pos = ply.payload["vertex"]
        .iter()
        .map(|v| [num(&v["x"]), num(&v["y"]), num(&v["z"])])
        .collect();
    let faces = ply.payload["face"]
        .iter()
        .map(|f| match &f["vertex_indices"] {
            Property::ListUInt(l) => l.clone(),
            other => panic!("{other:?}"),
        })
        .collect();
    (pos, faces)
}

/// A PLY file written by ply-rs-bw (float coordinates, `int` indices, an extra element and
/// extra properties) reads with our reader, in all three encodings.
#[test]
fn reads_ply_written_by_ply_rs_bw() {
    use ply_rs_bw::ply::{
        Addable, DefaultElement, ElementDef, Encoding, Ply, Property, PropertyDef, PropertyType,
        ScalarType,
    };
    use ply_rs_bw::writer::Writer;
    let mut m = octahedron();
    // Coordinates representable as finite f32.
    for (i, p) in m.positions.as_mut().unwrap().iter_mut().enumerate() {
        *p = [i as f64 * 0.1, -(i as f64) / 3.0, 1e-3 * i as f64];
    }
    for enc in [
        Encoding::Ascii,
        Encoding::BinaryLittleEndian,
        Encoding::BinaryBigEndian,
    ] {
        let mut ply = Ply::<DefaultElement>::new();
        ply.header.encoding = enc;
        let mut v = ElementDef::new("vertex".into());
        for n in ["x", "y", "z"] {
            v.properties.add(PropertyDef::new(
                n.into(),
                PropertyType::Scalar(ScalarType::Float),
            ));
        }
        v.properties.add(PropertyDef::new(
            "red".into(),
            PropertyType::Scalar(ScalarType::UChar),
        ));
        v.count = m.vertex_count;
        ply.header.elements.add(v);
        let mut e = ElementDef::new("edge".into());
        e.properties.add(PropertyDef::new(
            "ends".into(),
            PropertyType::List(ScalarType::UShort, ScalarType::Double),
        ));
        e.count = 2;
        ply.header.elements.add(e);
        let mut f = ElementDef::new("face".into());
        f.properties.add(PropertyDef::new(
            "vertex_index".into(),
            PropertyType::List(ScalarType::UChar, ScalarType::Int),
        ));
        f.count = m.faces.len();
        ply.header.elements.add(f);

        let p = m.positions.as_ref().unwrap();
        let verts = p
            .iter()
            .map(|q| {
                let mut el = DefaultElement::new();
                for (n, x) in ["x", "y", "z"].iter().zip(q) {
                    el.insert((*n).into(), Property::Float(*x as f32));
                }
                el.insert("red".into(), Property::UChar(200));
                el
            })
            .collect();
        ply.payload.insert("vertex".into(), verts);
        let edges = (0..2)
            .map(|i| {
                let mut el = DefaultElement::new();
                el.insert("ends".into(), Property::ListDouble(vec![1.5; i * 3]));
                el
            })
            .collect();
        ply.payload.insert("edge".into(), edges);
        let faces = m
            .faces
            .iter()
            .map(|f| {
                let mut el = DefaultElement::new();
                el.insert(
                    "vertex_index".into(),
                    Property::ListInt(f.iter().map(|&i| i as i32).collect()),
                );
                el
            })
            .collect();
        ply.payload.insert("face".into(), faces);
        let mut bytes = Vec::new();
        Writer::new().write_ply(&mut bytes, &mut ply).unwrap();

        let back = read_tri_mesh_bytes(&bytes, None).unwrap();
        assert_eq!(back.faces, m.faces, "{enc:?}");
        // Binary: the f32 value widened; ascii: the decimal text ply-rs-bw wrote, read as f64.
        let expect: Vec<[f64; 3]> = p
            .iter()
            .map(|q| {
                q.map(|x| match enc {
                    Encoding::Ascii => (x as f32).to_string().parse().unwrap(),
                    _ => f64::from(x as f32),
                })
            })
            .collect();
        assert_eq!(bits(back.positions.as_ref().unwrap()), bits(&expect));
    }
}

#[test]
fn writer_rejects_inconsistent_meshes_before_writing() {
    let mut m = octahedron();
    m.faces[3][1] = 6;
    let mut out = Vec::new();
    let e = write_mesh_to(&mut out, &m, Format::Off, false).unwrap_err();
    assert!(matches!(
        e,
        WriteError::IndexOutOfRange {
            face: 3,
            index: 6,
            vertex_count: 6
        }
    ));
    assert!(out.is_empty());
    let mut m = octahedron();
    m.positions.as_mut().unwrap()[2][1] = f64::NAN;
    let e = write_mesh_to(&mut out, &m, Format::Obj, false).unwrap_err();
    assert!(matches!(e, WriteError::NonFinitePosition { vertex: 2 }));
    let mut m = octahedron();
    m.vertex_count = 7;
    let e = write_mesh_to(&mut out, &m, Format::Ply, true).unwrap_err();
    assert!(matches!(
        e,
        WriteError::PositionCountMismatch {
            vertex_count: 7,
            positions: 6
        }
    ));
    let e = write_mesh(&tmp("x.xyz"), &octahedron()).unwrap_err();
    assert!(matches!(e, WriteError::UnknownFormat(_)));
    // STL holds only triangles with coordinates.
    let e = write_mesh_to(&mut out, &m, Format::Stl, true).unwrap_err();
    assert!(matches!(e, WriteError::PositionCountMismatch { .. }), "{e}");
    let no_positions = contractible::TriMesh::combinatorial(3, vec![[0, 1, 2]]);
    let e = write_mesh_to(&mut out, &no_positions, Format::Stl, true).unwrap_err();
    assert!(matches!(e, WriteError::Unrepresentable { .. }), "{e}");
    assert!(out.is_empty());
}

// ---------------------------------------------------------------- real meshes

struct ManifestRow {
    file: String,
    v: usize,
    f: usize,
}

/// The rows of `dir/manifest.csv`, parsed here (not by the tests' common code) from
/// the first columns only.
fn manifest(dir: &str) -> Vec<ManifestRow> {
    let text = std::fs::read_to_string(format!("{dir}/manifest.csv")).unwrap();
    let mut lines = text.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| head.iter().position(|h| *h == n).unwrap();
    let (cf, cv, cfa) = (col("file"), col("V"), col("F"));
    assert!(
        cf < 6 && cv < 6 && cfa < 6,
        "only the first columns are parsed"
    );
    lines
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let c: Vec<&str> = l.splitn(7, ',').collect();
            ManifestRow {
                file: c[cf].to_string(),
                v: c[cv].parse().unwrap(),
                f: c[cfa].parse().unwrap(),
            }
        })
        .collect()
}

/// Every closed mesh of `dir` is listed in its manifest and reads with the manifest's
/// face and used-vertex counts; returns how many were read.
fn closed_meshes_read_with_manifest_counts(dir: &str) -> usize {
    let rows = manifest(dir);
    let closed: Vec<&ManifestRow> = rows
        .iter()
        .filter(|r| r.file.starts_with("closed/"))
        .collect();
    let on_disk = std::fs::read_dir(format!("{dir}/closed"))
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .file_name()
                .to_string_lossy()
                .ends_with(".off.gz")
        })
        .count();
    assert!(on_disk > 0);
    assert_eq!(closed.len(), on_disk, "manifest lists every closed file");
    for r in &closed {
        let path = PathBuf::from(format!("{dir}/{}", r.file));
        let m = read_tri_mesh(&path).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.faces.len(), r.f, "{}", r.file);
        let used: HashSet<u32> = m.faces.iter().flatten().copied().collect();
        assert_eq!(used.len(), r.v, "{}", r.file);
        assert!(r.v <= m.vertex_count, "{}", r.file);
        assert_eq!(m.positions.as_ref().unwrap().len(), m.vertex_count);
    }
    closed.len()
}

/// Every invalid mesh of `dir` is a well-formed file: rejecting it is the job of
/// validation, not of the reader. Returns how many were read (all the manifest lists).
fn invalid_meshes_parse(dir: &str) -> usize {
    let listed = manifest(dir)
        .iter()
        .filter(|r| r.file.starts_with("invalid/"))
        .count();
    let mut read = 0;
    for e in std::fs::read_dir(format!("{dir}/invalid")).unwrap() {
        let path = e.unwrap().path();
        let m = read_tri_mesh(&path).unwrap_or_else(|e| panic!("{e}"));
        assert!(!m.faces.is_empty(), "{}", path.display());
        read += 1;
    }
    assert_eq!(read, listed, "manifest lists every invalid file");
    read
}

#[test]
fn every_closed_real_mesh_reads_with_manifest_counts() {
    assert_eq!(closed_meshes_read_with_manifest_counts(MESHES), 9);
}

#[test]
fn invalid_real_meshes_still_parse() {
    assert_eq!(invalid_meshes_parse(MESHES), 2);
}

/// The same over the real-mesh corpus.
mod corpus {
    use super::*;

    fn dir() -> String {
        crate::common::corpus_meshes().display().to_string()
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn every_closed_shared_mesh_reads_with_manifest_counts() {
        assert!(closed_meshes_read_with_manifest_counts(&dir()) >= 90);
    }

    #[test]
    #[ignore = "reads the real-mesh corpus: run with `-- --ignored ::corpus::`"]
    fn invalid_shared_meshes_still_parse() {
        assert_eq!(invalid_meshes_parse(&dir()), 7);
    }
}

// ---------------------------------------------------------------- malformed OFF

fn off_err(s: &str) -> ReadError {
    err(s.as_bytes(), Format::Off)
}

#[test]
fn off_accepts_variants_comments_and_colours() {
    let s = "# leading comment\n\nCOFF 4 2 0 # counts here\n\
             0 0 0 255 0 0 255\n1 0 0 1 1 1 1\n\n0 1 0 1 1 1 1\r\n0 0 1 1 1 1 1\n\
             3 0 1 2 0.5 0.5 0.5\n# mid comment\n3 0 2 3\n\n# trailing\n   \n";
    let m = read_tri_mesh_bytes(s.as_bytes(), Some(Format::Off)).unwrap();
    assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.positions.unwrap()[3], [0.0, 0.0, 1.0]);
    let m = read_tri_mesh_bytes(
        b"NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2",
        None,
    )
    .unwrap();
    assert_eq!(m.faces, vec![[0, 1, 2]]);
}

#[test]
fn off_quad_face_is_non_triangle_with_line() {
    let e = off_err("OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n4 0 1 2 3\n");
    assert!(
        matches!(
            e.kind,
            K::NonTriangleFace {
                face: 1,
                corners: 4
            }
        ),
        "{e}"
    );
    assert_eq!(e.location, Location::Line(8));
    assert_eq!(
        e.to_string(),
        "line 8: face 1 has 4 corners, only triangles are accepted"
    );
}

#[test]
fn off_errors_have_kind_and_line() {
    let cases: Vec<(&str, KindCheck, usize)> = vec![
        ("", |k| matches!(k, K::BadHeader(_)), 1),
        ("# only a comment\n", |k| matches!(k, K::BadHeader(_)), 1),
        ("PLY\n", |k| matches!(k, K::BadHeader(_)), 1),
        ("4OFF\n1 0 0\n", |k| matches!(k, K::BadHeader(_)), 1),
        ("OFF BINARY\n", |k| matches!(k, K::BadHeader(_)), 1),
        ("OFF\n", |k| matches!(k, K::BadHeader(_)), 1),
        ("OFF\n3\n", |k| matches!(k, K::BadHeader(_)), 2),
        ("OFF\n1 2 3 4\n", |k| matches!(k, K::BadHeader(_)), 2),
        (
            "OFF\n-3 1 0\n",
            |k| matches!(k, K::BadNumber { token } if token == "-3"),
            2,
        ),
        (
            "OFF\n3 x 0\n",
            |k| matches!(k, K::BadNumber { token } if token == "x"),
            2,
        ),
        // A vertex with a non-numeric, a non-finite, or a missing coordinate.
        (
            "OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n",
            |k| matches!(k, K::BadNumber { token } if token == "zero"),
            4,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n",
            |k| matches!(k, K::BadNumber { .. }),
            4,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n",
            |k| matches!(k, K::BadNumber { .. }),
            4,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n",
            |k| {
                matches!(
                    k,
                    K::MissingValue {
                        expected: "z coordinate"
                    }
                )
            },
            4,
        ),
        // Faces: missing index, non-numeric, negative, out of range, beyond u32 / i64.
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
            |k| matches!(k, K::MissingValue { .. }),
            6,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 two\n",
            |k| matches!(k, K::BadNumber { token } if token == "two"),
            6,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3.0 0 1 2\n",
            |k| matches!(k, K::BadNumber { .. }),
            6,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
            |k| {
                matches!(
                    k,
                    K::IndexOutOfRange {
                        face: 0,
                        index: -1,
                        vertex_count: 3
                    }
                )
            },
            6,
        ),
        (
            "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n",
            |k| {
                matches!(
                    k,
                    K::IndexOutOfRange {
                        face: 1,
                        index: 3,
                        ..
                    }
                )
            },
            7,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967296\n",
            |k| {
                matches!(
                    k,
                    K::IndexOutOfRange {
                        index: 4294967296,
                        ..
                    }
                )
            },
            6,
        ),
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 99999999999999999999\n",
            |k| matches!(k, K::BadNumber { .. }),
            6,
        ),
        // Fewer records than declared.
        // The face line is taken as the 4th vertex (extra values ignored); then no face.
        (
            "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
            |k| {
                matches!(
                    k,
                    K::CountMismatch {
                        what: "faces",
                        declared: 1,
                        found: 0
                    }
                )
            },
            6,
        ),
        (
            "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n# no more\n",
            |k| {
                matches!(
                    k,
                    K::CountMismatch {
                        what: "faces",
                        declared: 2,
                        found: 1
                    }
                )
            },
            7,
        ),
        (
            "OFF\n3 0 0\n0 0 0\n1 0 0\n",
            |k| {
                matches!(
                    k,
                    K::CountMismatch {
                        what: "vertices",
                        declared: 3,
                        found: 2
                    }
                )
            },
            4,
        ),
        // More faces than declared.
        (
            "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n\n3 0 2 1\n3 1 2 0\n",
            |k| {
                matches!(
                    k,
                    K::CountMismatch {
                        what: "faces",
                        declared: 1,
                        found: 3
                    }
                )
            },
            8,
        ),
        // Impossible counts.
        (
            "OFF\n1000000000000 1 0\n0 0 0\n",
            |k| {
                matches!(
                    k,
                    K::CountTooLarge {
                        what: "vertices",
                        ..
                    }
                )
            },
            2,
        ),
        // More faces than a triangulation indexes: refused at the count, before reading.
        (
            "OFF 3 18446744073709551615 0\n0 0 0\n1 0 0\n0 1 0\n",
            |k| {
                matches!(
                    k,
                    K::CountTooLarge {
                        what: "faces",
                        declared: u64::MAX,
                    }
                )
            },
            1,
        ),
        (
            "OFF\n3 1431655765 0\n0 0 0\n1 0 0\n0 1 0\n",
            |k| {
                matches!(
                    k,
                    K::CountTooLarge {
                        what: "faces",
                        declared: 1431655765,
                    }
                )
            },
            2,
        ),
        // One face fewer is within the limit: read until the input ends.
        (
            "OFF\n3 1431655764 0\n0 0 0\n1 0 0\n0 1 0\n",
            |k| {
                matches!(
                    k,
                    K::CountMismatch {
                        what: "faces",
                        declared: 1431655764,
                        found: 0
                    }
                )
            },
            5,
        ),
        (
            "OFF\n4294967295 1431655764\n0 0 0\n1 1 1",
            |k| {
                matches!(
                    k,
                    K::CountMismatch {
                        what: "vertices",
                        declared: 4294967295,
                        found: 2
                    }
                )
            },
            4,
        ),
        (
            "OFF\n3 1 0 99999999999999999999\n",
            |k| matches!(k, K::BadHeader(_)),
            2,
        ),
    ];
    for (input, kind_ok, line) in cases {
        let e = off_err(input);
        assert!(kind_ok(&e.kind), "{input:?}: {e:?}");
        assert_eq!(e.location, Location::Line(line), "{input:?}: {e}");
    }
}

#[test]
fn huge_header_counts_fail_fast_without_allocating() {
    let inputs: Vec<(Vec<u8>, Format)> = vec![
        (
            b"OFF\n1000000000000 1000000000000 0\n0 0 0\n".to_vec(),
            Format::Off,
        ),
        (
            b"OFF\n4000000000 4000000000 0\n0 0 0\n".to_vec(),
            Format::Off,
        ),
        (
            b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n\
              property float x\nproperty float y\nproperty float z\nend_header\n0123456789"
                .to_vec(),
            Format::Ply,
        ),
        (
            b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
              property float z\nelement face 18446744073709551615\n\
              property list uchar int vertex_indices\nend_header\n0 0 0\n"
                .to_vec(),
            Format::Ply,
        ),
        (
            b"ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\n\
              property float y\nproperty float z\nelement junk 18446744073709551615\n\
              property double w\nend_header\n"
                .to_vec(),
            Format::Ply,
        ),
    ];
    for (bytes, format) in inputs {
        let t = Instant::now();
        let e = read_tri_mesh_bytes(&bytes, Some(format)).unwrap_err();
        assert!(
            matches!(
                e.kind,
                K::CountTooLarge { .. } | K::CountMismatch { .. } | K::Truncated { .. }
            ),
            "{}: {e}",
            String::from_utf8_lossy(&bytes)
        );
        assert_ne!(e.location, Location::Unknown);
        assert!(t.elapsed() < Duration::from_millis(100));
    }
}

// ---------------------------------------------------------------- malformed OBJ

#[test]
fn obj_features_and_indices_as_in_file() {
    let s = "# comment\nmtllib x.mtl\no a\nv 0 0 0\nv 1 0 0 1.0\nv 0 1 0 0.5 0.5 0.5\n\
             vn 0 0 1\nvt 0 0\nv 9 9 9\ng g1\nusemtl m\ns off\nf 1/1/1 2/1/1 3/1/1\n\
             o b\nv 0 0 1\nf -4//1 -2 -1\nf 2/1 5 1\n";
    let m = read_tri_mesh_bytes(s.as_bytes(), Some(Format::Obj)).unwrap();
    // Vertex 4 (9 9 9) is unreferenced and kept; indices stay as in the file.
    assert_eq!(m.vertex_count, 5);
    assert_eq!(m.faces, vec![[0, 1, 2], [1, 3, 4], [1, 4, 0]]);
    assert_eq!(m.positions.unwrap()[4], [0.0, 0.0, 1.0]);
}

/// OBJ counts from 1, and so do its messages: face numbers count `f` statements from 1,
/// indices are reported as written.
#[test]
fn obj_errors_have_kind_and_line() {
    let cases: Vec<(&str, KindCheck, Location)> = vec![
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n",
            |k| {
                matches!(
                    k,
                    K::NonTriangleFace {
                        face: 1,
                        corners: 4
                    }
                )
            },
            Location::Line(5),
        ),
        (
            "v 0 0 0\nv 1 0 0\nf 1 2\n",
            |k| {
                matches!(
                    k,
                    K::NonTriangleFace {
                        face: 1,
                        corners: 2
                    }
                )
            },
            Location::Line(3),
        ),
        (
            "v 0 0 0\nv 1 0 x\n",
            |k| matches!(k, K::BadNumber { token } if token == "x"),
            Location::Line(2),
        ),
        (
            "v 0 0 0\nv 1 0 NaN\n",
            |k| matches!(k, K::BadNumber { .. }),
            Location::Line(2),
        ),
        (
            "v 0 0\n",
            |k| {
                matches!(
                    k,
                    K::MissingValue {
                        expected: "z coordinate"
                    }
                )
            },
            Location::Line(1),
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 a\n",
            |k| matches!(k, K::BadNumber { token } if token == "a"),
            Location::Line(5),
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
            |k| matches!(k, K::Obj(_)),
            Location::Line(4),
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n",
            |k| {
                matches!(
                    k,
                    K::IndexOutOfRange {
                        face: 1,
                        index: -4,
                        vertex_count: 3
                    }
                )
            },
            Location::Line(4),
        ),
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# x\n\nf 1 2 4\nf 1 2 3\n",
            |k| {
                matches!(
                    k,
                    K::IndexOutOfRange {
                        face: 2,
                        index: 4,
                        vertex_count: 3
                    }
                )
            },
            Location::Line(7),
        ),
        (
            "v 0 0 0\nf 1 1 9999999999\n",
            |k| matches!(k, K::IndexOutOfRange { face: 1, .. }),
            Location::Line(2),
        ),
        (
            "v 0 0 0\nf 1/1/1/1 1 1\n",
            |k| matches!(k, K::Obj(_)),
            Location::Line(2),
        ),
    ];
    for (input, kind_ok, loc) in cases {
        let e = err(input.as_bytes(), Format::Obj);
        assert!(kind_ok(&e.kind), "{input:?}: {e:?}");
        assert_eq!(e.location, loc, "{input:?}: {e}");
    }
}

// ---------------------------------------------------------------- malformed PLY

const PLY_HEAD: &str = "ply\nformat ascii 1.0\ncomment c\nelement vertex 3\nproperty float x\n\
    property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n\
    end_header\n";

#[test]
fn ply_errors_have_kind_and_location() {
    let ok = format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    assert_eq!(
        read_tri_mesh_bytes(ok.as_bytes(), None).unwrap().faces,
        vec![[0, 1, 2]]
    );
    let cases: Vec<(String, KindCheck, Location)> = vec![
        // More faces than a triangulation indexes: refused at the element line.
        (
            format!(
                "{}0 0 0\n",
                PLY_HEAD.replace("element face 1", "element face 1431655765")
            ),
            |k| {
                matches!(
                    k,
                    K::CountTooLarge {
                        what: "faces",
                        declared: 1431655765
                    }
                )
            },
            Location::Line(8),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n4 0 1 2 0\n"),
            |k| {
                matches!(
                    k,
                    K::NonTriangleFace {
                        face: 0,
                        corners: 4
                    }
                )
            },
            Location::Line(14),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 q\n0 1 0\n3 0 1 2\n"),
            |k| matches!(k, K::BadNumber { token } if token == "q"),
            Location::Line(12),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n"),
            |k| matches!(k, K::BadNumber { .. }),
            Location::Line(12),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            |k| {
                matches!(
                    k,
                    K::IndexOutOfRange {
                        face: 0,
                        index: 3,
                        vertex_count: 3
                    }
                )
            },
            Location::Line(14),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n"),
            |k| matches!(k, K::IndexOutOfRange { index: -1, .. }),
            Location::Line(14),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
            |k| matches!(k, K::Truncated { .. }),
            Location::Line(14),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n"),
            |k| matches!(k, K::TrailingData { .. }),
            Location::Line(15),
        ),
        (
            format!("{PLY_HEAD}0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n"),
            |k| matches!(k, K::BadNumber { .. }),
            Location::Line(14),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float x\n".into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(5),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\n".into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(4),
        ),
        (
            "ply\nformat ascii 2.0\n".into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(2),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex -1\n".into(),
            |k| matches!(k, K::BadNumber { .. }),
            Location::Line(3),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
             end_header\n0 0\n"
                .into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(3),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n".into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(5),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n\
             property float z\nelement face 0\nproperty list uchar float vertex_indices\n"
                .into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(8),
        ),
        (
            "ply\nformat ascii 1.0\nproperty float x\n".into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(3),
        ),
        (
            "ply\nformat ascii 1.0\nelement vertex 0\nproperty flot x\n".into(),
            |k| matches!(k, K::BadHeader(_)),
            Location::Line(4),
        ),
    ];
    for (input, kind_ok, loc) in cases {
        let e = err(input.as_bytes(), Format::Ply);
        assert!(kind_ok(&e.kind), "{input:?}: {e:?}");
        assert_eq!(e.location, loc, "{input:?}: {e}");
    }
}

fn binary_ply(body: &[u8], nv: usize, nf: usize) -> Vec<u8> {
    let mut b = format!(
        "ply\nformat binary_little_endian 1.0\nelement vertex {nv}\nproperty float x\n\
         property float y\nproperty float z\nelement face {nf}\n\
         property list uchar int vertex_indices\nend_header\n"
    )
    .into_bytes();
    b.extend_from_slice(body);
    b
}

#[test]
fn binary_ply_errors_have_byte_offsets() {
    let mut body = Vec::new();
    for p in [[0f32, 0., 0.], [1., 0., 0.], [0., 1., 0.]] {
        for x in p {
            body.extend_from_slice(&x.to_le_bytes());
        }
    }
    let header_len = binary_ply(&[], 3, 1).len();
    let face = |n: u8, idx: [i32; 3]| {
        let mut f = vec![n];
        for i in idx {
            f.extend_from_slice(&i.to_le_bytes());
        }
        f
    };
    let good = [body.clone(), face(3, [0, 1, 2])].concat();
    assert_eq!(
        read_tri_mesh_bytes(&binary_ply(&good, 3, 1), None)
            .unwrap()
            .faces,
        vec![[0, 1, 2]]
    );

    // Truncated in the middle of the last index.
    let e = err(&binary_ply(&good[..good.len() - 2], 3, 1), Format::Ply);
    assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
    assert_eq!(
        e.location,
        Location::ByteOffset((header_len + 36 + 1 + 8) as u64)
    );

    // Index out of range, at the offset of the bad index.
    let e = err(
        &binary_ply(&[body.clone(), face(3, [0, 7, 2])].concat(), 3, 1),
        Format::Ply,
    );
    assert!(
        matches!(
            e.kind,
            K::IndexOutOfRange {
                face: 0,
                index: 7,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(
        e.location,
        Location::ByteOffset((header_len + 36 + 1 + 4) as u64)
    );

    // Quad: reported at the list count.
    let mut quad = face(4, [0, 1, 2]);
    quad.extend_from_slice(&0i32.to_le_bytes());
    let e = err(
        &binary_ply(&[body.clone(), quad].concat(), 3, 1),
        Format::Ply,
    );
    assert!(
        matches!(
            e.kind,
            K::NonTriangleFace {
                face: 0,
                corners: 4
            }
        ),
        "{e}"
    );
    assert_eq!(e.location, Location::ByteOffset((header_len + 36) as u64));

    // Non-finite coordinate.
    let mut nan = body.clone();
    nan[16..20].copy_from_slice(&f32::INFINITY.to_le_bytes());
    let e = err(
        &binary_ply(&[nan, face(3, [0, 1, 2])].concat(), 3, 1),
        Format::Ply,
    );
    assert!(matches!(e.kind, K::BadNumber { .. }), "{e}");
    assert_eq!(e.location, Location::ByteOffset((header_len + 16) as u64));

    // Trailing garbage (whitespace is tolerated).
    let mut tail = binary_ply(&good, 3, 1);
    tail.extend_from_slice(b"\n \n");
    assert!(read_tri_mesh_bytes(&tail, None).is_ok());
    tail.push(0);
    let e = err(&tail, Format::Ply);
    assert!(matches!(e.kind, K::TrailingData { .. }), "{e}");

    // A list count byte claiming 255 items of an ignored list: truncation, not a hang.
    let mut b = b"ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\n\
        property float y\nproperty float z\nelement junk 1\nproperty list uint double w\n\
        end_header\n"
        .to_vec();
    b.extend_from_slice(&u32::MAX.to_le_bytes());
    b.extend_from_slice(&[0; 16]);
    let t = Instant::now();
    let e = err(&b, Format::Ply);
    assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
    assert!(t.elapsed() < Duration::from_secs(1));
}

// ---------------------------------------------------------------- format selection, gzip

#[test]
fn unknown_format_and_bad_gzip() {
    let e = read_tri_mesh_bytes(b"mesh cube\nfacet normal 0 0 1\n", None).unwrap_err();
    assert!(matches!(e.kind, K::UnknownFormat));
    // `solid` is sniffed as ASCII STL, so this cut file is a located STL error.
    let e = read_tri_mesh_bytes(b"solid cube\nfacet normal 0 0 1\n", None).unwrap_err();
    assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
    assert_eq!(e.location, Location::Line(2));
    let e = read_tri_mesh_bytes(&[0x1f, 0x8b, 8, 0, 1, 2], None).unwrap_err();
    assert!(matches!(e.kind, K::Decompress(_)));
    let path = tmp("not_gzip.off.gz");
    std::fs::write(&path, "OFF\n0 0 0\n").unwrap();
    let e = read_tri_mesh(&path).unwrap_err();
    assert!(matches!(e.kind, K::Decompress(_)), "{e}");
    assert_eq!(e.path.as_deref(), Some(path.as_path()));
    let e = read_tri_mesh(&tmp("does_not_exist.off")).unwrap_err();
    assert!(matches!(e.kind, K::Io(_)));
    // Errors read from a path show it.
    let path = tmp("bad.off");
    std::fs::write(&path, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 0\n").unwrap();
    let e = read_tri_mesh(&path).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "{}:line 6: face 0 has 4 corners, only triangles are accepted",
            path.display()
        )
    );
}

/// `bytes` gzip-compressed.
fn gzip(bytes: &[u8]) -> Vec<u8> {
    use std::io::Write;
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    enc.write_all(bytes).unwrap();
    enc.finish().unwrap()
}

/// A reader that is interrupted before every read it serves, serves one byte at a time,
/// and fails with `fail` once `fail_at` bytes are out.
struct Stutter<'a> {
    bytes: &'a [u8],
    interrupted: bool,
    fail_at: usize,
    fail: std::io::ErrorKind,
}

impl std::io::Read for Stutter<'_> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        if !buf.is_empty() {
            self.interrupted = !self.interrupted;
            if self.interrupted {
                return Err(std::io::ErrorKind::Interrupted.into());
            }
        }
        if self.fail_at == 0 {
            return Err(self.fail.into());
        }
        let n = buf.len().min(self.bytes.len()).min(1);
        buf[..n].copy_from_slice(&self.bytes[..n]);
        self.bytes = &self.bytes[n..];
        self.fail_at -= n;
        Ok(n)
    }
}

/// A stream is read through interruptions and one-byte reads, gzip or not, and any other
/// error of the stream is reported as an `Io` error, whether it comes before, inside or
/// after the two bytes that tell gzip apart.
#[test]
fn streams_retry_interrupted_reads_and_report_other_errors() {
    let off = to_bytes(&octahedron(), Format::Off, false);
    let want = contractible::io::decode(&off, None).unwrap();
    for bytes in [off.clone(), gzip(&off)] {
        let stutter = |fail_at| Stutter {
            bytes: &bytes,
            interrupted: false,
            fail_at,
            fail: std::io::ErrorKind::Other,
        };
        let got = contractible::io::decode_reader(stutter(usize::MAX), None).unwrap();
        assert_eq!((got.format, &got.mesh), (Format::Off, &want.mesh));
        for fail_at in [0, 1, 2, 40] {
            let e = contractible::io::decode_reader(stutter(fail_at), None).unwrap_err();
            assert!(matches!(e.kind, K::Io(_)), "failing at {fail_at}: {e}");
        }
    }
}

/// OFF faces of more than three corners are read as the polygons they are; fewer than
/// three is an error at the face's line.
#[test]
fn off_polygons_read_as_polygons() {
    let off = b"OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 2 0\n4 0 1 2 3\n5 0 1 2 3 4\n";
    let d = contractible::io::decode(off, None).unwrap();
    assert_eq!(d.mesh.face(0), [0, 1, 2, 3]);
    assert_eq!(d.mesh.face(1), [0, 1, 2, 3, 4]);
    let e =
        contractible::io::decode(b"OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n2 0 1\n", None).unwrap_err();
    assert!(
        matches!(
            e.kind,
            K::NonTriangleFace {
                face: 0,
                corners: 2
            }
        ),
        "{e}"
    );
    assert_eq!(e.location, Location::Line(6));
}

/// Sniffing a stream reads no further than its first data line needs: a data error near
/// the start is reported as such even when the stream would fail a megabyte later.
#[test]
fn sniffing_reads_no_further_than_the_first_data_line() {
    let mut bytes = b"OFF\n4 4 0\n0 0 0\n1 0 x\n".to_vec();
    while bytes.len() < 2 << 20 {
        bytes.extend_from_slice(b"# padding after the error\n");
    }
    for declared in [None, Some(Format::Off)] {
        let stream = Stutter {
            bytes: &bytes,
            interrupted: true,
            fail_at: 1 << 20,
            fail: std::io::ErrorKind::Other,
        };
        let e = contractible::io::decode_reader(stream, declared).unwrap_err();
        assert!(matches!(e.kind, K::BadNumber { .. }), "{declared:?}: {e}");
        assert_eq!(e.location, Location::Line(4));
    }
}

/// A binary STL whose header starts with `solid`, or like another format (`OFF`, `ply`),
/// is told by its length, also when gzip hides the length (measured by a first pass over
/// the content), from memory and from a file.
#[test]
fn gzip_binary_stl_with_a_misleading_header_is_read_by_its_length() {
    let octahedron = contractible::gen::octahedron();
    let headers: [&[u8]; 3] = [
        b"solid octahedron, binary all the same",
        b"OFF\n6 8 0\n",
        b"ply\nformat ascii 1.0\n",
    ];
    for (i, header) in headers.into_iter().enumerate() {
        let mut stl = to_bytes(&octahedron, Format::Stl, true);
        stl[..80].fill(b' ');
        stl[..header.len()].copy_from_slice(header);
        let plain = contractible::io::decode(&stl, None).unwrap();
        assert_eq!((plain.format, plain.mesh.face_count()), (Format::Stl, 8));
        let gz = gzip(&stl);
        let packed = contractible::io::decode(&gz, None).unwrap();
        assert_eq!((packed.format, &packed.mesh), (Format::Stl, &plain.mesh));
        let path = tmp(&format!("misleading_header_{i}.stl.gz"));
        std::fs::write(&path, &gz).unwrap();
        let from_file = contractible::io::read_poly_mesh(&path, None).unwrap();
        assert_eq!(
            (from_file.format, &from_file.mesh),
            (Format::Stl, &plain.mesh)
        );
    }
}

/// A UTF-8 byte order mark is skipped before text formats, declared or sniffed, and
/// kept in a binary STL header, where it is just a header byte.
#[test]
fn a_byte_order_mark_is_skipped_before_text_and_kept_in_binary_stl() {
    const BOM: &[u8] = b"\xEF\xBB\xBF";
    let m = contractible::gen::octahedron();
    for format in [Format::Off, Format::Obj, Format::Ply] {
        let text = [BOM, &to_bytes(&m, format, false)].concat();
        for declared in [None, Some(format)] {
            let d = contractible::io::decode(&text, declared).unwrap();
            assert_eq!((d.format, d.mesh.face_count()), (format, 8), "{format}");
        }
    }
    let mut stl = to_bytes(&m, Format::Stl, true);
    stl[..3].copy_from_slice(BOM);
    let want = read_tri_mesh_bytes(&to_bytes(&m, Format::Stl, true), None).unwrap();
    for declared in [None, Some(Format::Stl)] {
        let got = read_tri_mesh_bytes(&stl, declared).unwrap();
        assert_eq!(got, want, "{declared:?}");
    }
}

/// `read_poly_mesh_observed` reports the file bytes read so far, growing, ending at the
/// file's length (the compressed length for gzip).
#[test]
fn observed_reading_reports_the_file_bytes_read() {
    let off = to_bytes(&octahedron(), Format::Off, false);
    for (name, bytes) in [
        ("observed.off", off.clone()),
        ("observed.off.gz", gzip(&off)),
    ] {
        let path = tmp(name);
        std::fs::write(&path, &bytes).unwrap();
        let mut seen = Vec::new();
        let d =
            contractible::io::read_poly_mesh_observed(&path, None, &mut |n| seen.push(n)).unwrap();
        assert_eq!(d.mesh.face_count(), 8);
        assert!(seen.windows(2).all(|w| w[0] <= w[1]), "{name}: {seen:?}");
        assert_eq!(seen.last(), Some(&(bytes.len() as u64)), "{name}");
    }
}

/// The OBJ statements the reader skipped are reported with the mesh it read.
#[test]
fn skipped_obj_statements_come_with_the_mesh() {
    let obj = b"v 0 0 0\nv 1 0 0\nv 0 1 0\ncurv 0 1 1 2\nf 1 2 3\nl 1 2\nl 2 3\n";
    let d = contractible::io::decode(obj, None).unwrap();
    let skipped = d.mesh.skipped_statements();
    assert_eq!(skipped.total(), 3);
    let kinds: Vec<(&str, usize, usize)> = skipped
        .kinds
        .iter()
        .map(|(k, n, line)| (k.as_str(), *n, *line))
        .collect();
    assert_eq!(kinds, [("curv", 1, 4), ("l", 2, 6)]);
}

/// Formats display as their usual upper-case names.
#[test]
fn formats_display_their_names() {
    let names = [Format::Off, Format::Obj, Format::Ply, Format::Stl].map(|f| f.to_string());
    assert_eq!(names, ["OFF", "OBJ", "PLY", "STL"]);
}

/// A write goes through a temporary file in the output's own directory, named after it.
#[test]
fn temporary_files_sit_beside_the_output() {
    let pid = std::process::id();
    assert_eq!(
        contractible::io::temp_path(Path::new("out/sub/mesh.off.gz")),
        Path::new(&format!("out/sub/.contractible-{pid}-mesh.off.gz"))
    );
    assert_eq!(
        contractible::io::temp_path(Path::new("mesh.ply")),
        Path::new(&format!(".contractible-{pid}-mesh.ply"))
    );
}

/// An I/O failure keeps the operating system's error as its source; a data error has none.
#[test]
fn io_errors_keep_their_cause() {
    use std::error::Error;
    let e = read_tri_mesh(&tmp("no_such_file.off")).unwrap_err();
    let cause = e.source().expect("the I/O error");
    let io = cause
        .downcast_ref::<std::io::Error>()
        .expect("an io::Error");
    assert_eq!(io.kind(), std::io::ErrorKind::NotFound);
    let e = read_tri_mesh_bytes(b"OFF\n3 1 0\n0 0 0\n", None).unwrap_err();
    assert!(e.source().is_none(), "{e}");
}

/// A file with no statements, or only comments, is an empty mesh in every text format
/// that allows one.
#[test]
fn an_empty_obj_is_an_empty_mesh() {
    for text in [&b""[..], b"# nothing here\n", b"\n\n  \n"] {
        let m = read_tri_mesh_bytes(text, Some(Format::Obj)).unwrap();
        assert_eq!((m.vertex_count, m.faces.len()), (0, 0));
    }
}

/// The surface lists the repository carries read with the published counts: 21
/// irreducible triangulations of the torus (Lavrenchenko) and 2 of the projective plane
/// (Barnette); a missing list is an I/O error naming its path.
#[test]
fn published_surface_lists_read_with_their_counts() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/irreducible");
    for (file, count) in [("torus.txt", 21), ("projective-plane.txt", 2)] {
        let list = contractible::io::list::read_surface_list(&dir.join(file)).unwrap();
        assert_eq!(list.len(), count, "{file}");
        assert!(list.iter().all(|s| !s.faces.is_empty()), "{file}");
    }
    let missing = dir.join("no-such-list.txt");
    let e = contractible::io::list::read_surface_list(&missing).unwrap_err();
    assert!(matches!(e.kind, K::Io(_)), "{e}");
    assert_eq!(e.path.as_deref(), Some(missing.as_path()));
}

// ---------------------------------------------------------------- no panics

/// Every prefix and many single-byte corruptions of valid files in each format, with and
/// without a format hint: the readers must return (Ok or Err), never panic.
#[test]
fn corrupted_inputs_never_panic() {
    let m = octahedron();
    let mut samples = vec![
        to_bytes(&m, Format::Off, false),
        to_bytes(&m, Format::Obj, false),
        to_bytes(&m, Format::Ply, false),
        to_bytes(&m, Format::Ply, true),
    ];
    let mut be = Vec::new();
    write_ply_to(&mut be, &m, PlyEncoding::BinaryBigEndian).unwrap();
    samples.push(be);
    let mut gz = Vec::new();
    {
        use std::io::Write;
        let mut enc = flate2::write::GzEncoder::new(&mut gz, flate2::Compression::fast());
        enc.write_all(&samples[0]).unwrap();
        enc.finish().unwrap();
    }
    samples.push(gz);
    let replacements = [0u8, b'\n', b' ', b'-', b'9', b'#', 0xff, b'4', b'e'];
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut rng = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    };
    for s in &samples {
        for cut in 0..s.len() {
            for f in [
                None,
                Some(Format::Off),
                Some(Format::Obj),
                Some(Format::Ply),
            ] {
                let _ = read_tri_mesh_bytes(&s[..cut], f);
            }
        }
        for _ in 0..3000 {
            let mut c = s.clone();
            for _ in 0..=(rng() % 3) {
                let i = (rng() % c.len() as u64) as usize;
                c[i] = replacements[(rng() % replacements.len() as u64) as usize];
            }
            let _ = read_tri_mesh_bytes(&c, None);
        }
    }
}

/// `write_mesh` leaves nothing behind when it fails: not the file, not its temporary
/// twin (quads to STL, a NaN position, a missing directory), and replaces an existing
/// file only when the new one is complete.
#[test]
fn a_failed_write_leaves_no_file() {
    let dir = std::env::temp_dir().join(format!("contractible-write-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let listing = || {
        let mut v: Vec<_> = std::fs::read_dir(&dir)
            .expect("listable")
            .map(|e| e.expect("entry").file_name())
            .collect();
        v.sort();
        v
    };
    let quads = QuadMesh::with_positions(
        vec![[0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
        vec![[0, 1, 2, 3]],
    );
    assert!(write_mesh(&dir.join("q.stl"), &quads).is_err());
    let mut nan = contractible::gen::tetrahedron();
    nan.positions = Some(vec![[f64::NAN; 3]; 4]);
    assert!(write_mesh(&dir.join("t.off"), &nan).is_err());
    assert!(write_mesh(
        &dir.join("missing/t.off"),
        &contractible::gen::tetrahedron()
    )
    .is_err());
    assert!(listing().is_empty(), "{:?}", listing());
    // A good write replaces the file whole, through a temporary file that is gone after.
    let good = dir.join("q.obj");
    write_mesh(&good, &quads).expect("writable");
    write_mesh(&good, &quads).expect("replaceable");
    assert_eq!(listing(), vec![std::ffi::OsString::from("q.obj")]);
    std::fs::remove_dir_all(&dir).ok();
}

/// A binary STL declaring more triangles than a triangulation indexes is refused at its
/// header, before any triangle is read: shown on a sparse file of the declared length
/// (72 GB apparent, nothing written but the header). A short one gets the length error,
/// from memory and read once alike.
#[test]
fn a_binary_stl_count_past_the_face_limit_is_refused_at_the_header() {
    let declared = contractible::core::MAX_FACES as u64 + 1;
    let mut head = vec![0u8; 80];
    head.extend_from_slice(&(declared as u32).to_le_bytes());
    let dir = std::env::temp_dir().join(format!("contractible-stl-limit-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("huge.stl");
    let mut file = std::fs::File::create(&path).unwrap();
    std::io::Write::write_all(&mut file, &head).unwrap();
    file.set_len(84 + 50 * declared).unwrap();
    drop(file);
    let e = contractible::io::read_tri_mesh(&path).unwrap_err();
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        matches!(e.kind, K::CountTooLarge { what: "triangles", declared: d } if d == declared),
        "{e}"
    );
    assert_eq!(e.location, contractible::io::Location::ByteOffset(80));

    let mut stl = to_bytes(&contractible::gen::octahedron(), Format::Stl, true);
    stl[80..84].copy_from_slice(&(declared as u32).to_le_bytes());
    let a = contractible::io::read_tri_mesh_bytes(&stl, Some(Format::Stl)).unwrap_err();
    let b = contractible::io::read_tri_mesh_from(Trickle::new(&stl), Format::Stl).unwrap_err();
    assert_eq!(
        (format!("{:?}", a.kind), a.location),
        (format!("{:?}", b.kind), b.location)
    );
    assert!(!matches!(a.kind, K::CountTooLarge { .. }), "{a}");
}

/// A stream read once has no length for the binary STL rule: content no header names is
/// read as binary STL when its length matches the count, and is `UnknownFormat` when it
/// does not, as from memory.
#[test]
fn read_once_streams_recognise_binary_stl_by_its_length() {
    let m = contractible::gen::octahedron();
    let stl = to_bytes(&m, Format::Stl, true);
    let from_memory = contractible::io::decode(&stl, None).unwrap();
    let streamed = contractible::io::decode_reader(Trickle::new(&stl), None).unwrap();
    assert_eq!(
        (from_memory.format, streamed.format),
        (Format::Stl, Format::Stl)
    );
    assert_eq!(from_memory.mesh, streamed.mesh);
    for bad in [
        &stl[..stl.len() - 1],
        &[&stl[..], &[0u8; 50][..]].concat()[..],
        &stl[..40],
    ] {
        let a = contractible::io::decode(bad, None).unwrap_err();
        let b = contractible::io::decode_reader(Trickle::new(bad), None).unwrap_err();
        assert!(matches!(a.kind, K::UnknownFormat), "{a}");
        assert!(matches!(b.kind, K::UnknownFormat), "{b}");
    }
    // A non-finite coordinate is reported when the length matches.
    let mut nan = stl.clone();
    nan[84 + 12..84 + 16].copy_from_slice(&f32::NAN.to_le_bytes());
    let a = contractible::io::decode(&nan, None).unwrap_err();
    let b = contractible::io::decode_reader(Trickle::new(&nan), None).unwrap_err();
    assert_eq!(
        (format!("{:?}", a.kind), a.location),
        (format!("{:?}", b.kind), b.location)
    );
    assert!(matches!(a.kind, K::BadNumber { .. }), "{a}");
}

/// Binary STL welding on more vertices than the reader's cache of recent lookups holds,
/// with the triangles in random order (so most lookups go to the table), against an
/// oracle written here: vertices numbered in order of first appearance, merged exactly
/// when the `f32` positions written are bitwise equal (`0.0` and `-0.0` apart).
#[test]
fn binary_stl_welds_many_scattered_vertices_by_bitwise_position() {
    use std::collections::BTreeMap;
    let mut rng = contractible::rng::Rng::new(11);
    let distinct = 60_000usize;
    let mut positions: Vec<[f64; 3]> = (0..distinct)
        .map(|i| {
            [
                (i % 97) as f64,
                ((i / 97) % 89) as f64,
                (i / (97 * 89)) as f64 + 0.5,
            ]
        })
        .collect();
    // Copies of some positions (welded into one vertex), and signed zeros (kept apart).
    for i in 0..5_000 {
        positions.push(positions[rng.index(distinct)]);
        positions.push([if i % 2 == 0 { 0.0 } else { -0.0 }, i as f64, 0.25]);
    }
    let n = positions.len() as u32;
    let faces: Vec<[u32; 3]> = (0..150_000)
        .map(|_| {
            let a = rng.index(n as usize) as u32;
            [
                a,
                (a + 1 + rng.index(100) as u32) % n,
                (a + 200 + rng.index(100) as u32) % n,
            ]
        })
        .collect();
    let mesh = TriMesh::with_positions(positions.clone(), faces.clone());
    let bytes = to_bytes(&mesh, Format::Stl, true);

    let mut ids: BTreeMap<[u64; 3], u32> = BTreeMap::new();
    let mut want_positions = Vec::new();
    let want_faces: Vec<[u32; 3]> = faces
        .iter()
        .map(|f| {
            f.map(|v| {
                let p = positions[v as usize].map(|x| f64::from(x as f32));
                *ids.entry(p.map(f64::to_bits)).or_insert_with(|| {
                    want_positions.push(p);
                    want_positions.len() as u32 - 1
                })
            })
        })
        .collect();
    assert!(
        want_positions.len() > 60_000,
        "{} vertices",
        want_positions.len()
    );

    let got = contractible::io::read_tri_mesh_bytes(&bytes, Some(Format::Stl)).unwrap();
    assert_eq!(got.faces, want_faces);
    let got_positions = got.positions.expect("STL has positions");
    assert_eq!(got_positions.len(), want_positions.len());
    for (g, w) in got_positions.iter().zip(&want_positions) {
        assert_eq!(g.map(f64::to_bits), w.map(f64::to_bits));
    }
    let streamed = contractible::io::read_tri_mesh_from(Trickle::new(&bytes), Format::Stl).unwrap();
    assert_eq!(streamed.faces, want_faces);
}
