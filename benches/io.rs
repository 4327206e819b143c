//! Reader throughput: each format of the ~4.2M-triangle paper brick B0 (with its
//! coordinates) parsed from memory, beside the Rust readers a user would otherwise pick
//! (`tobj` for OBJ, `ply-rs-bw` for PLY, `stl_io` for STL) on the same bytes. Divan
//! reports medians and bytes/s. Run: `cargo bench --bench io`.
//!
//! The peers do less or other work than these readers (none checks face indices against
//! the vertex count with a located error; `tobj` and `stl_io` keep `f32` coordinates;
//! `ply-rs-bw` builds a map per record), so the comparison is of the call a user makes,
//! not of identical work.

use std::io::Cursor;
use std::sync::OnceLock;

use contractible::gen::paper_family;
use contractible::io::{self, Format};
use contractible::TriMesh;
use divan::counter::BytesCount;

fn b0() -> &'static TriMesh {
    static M: OnceLock<TriMesh> = OnceLock::new();
    M.get_or_init(|| paper_family('B', 0).expect("valid brick parameters"))
}

/// B0 written in each format once.
struct Files {
    off: Vec<u8>,
    obj: Vec<u8>,
    ply_ascii: Vec<u8>,
    ply_binary: Vec<u8>,
    stl: Vec<u8>,
}

fn files() -> &'static Files {
    static F: OnceLock<Files> = OnceLock::new();
    F.get_or_init(|| {
        let m = b0();
        let write = |format, binary| {
            let mut out = Vec::new();
            io::write_mesh_to(&mut out, m, format, binary).expect("B0 is writable");
            out
        };
        Files {
            off: write(Format::Off, false),
            obj: write(Format::Obj, false),
            ply_ascii: write(Format::Ply, false),
            ply_binary: write(Format::Ply, true),
            stl: write(Format::Stl, true),
        }
    })
}

fn main() {
    let f = files();
    eprintln!(
        "B0: {} faces; OFF {} B, OBJ {} B, PLY ascii {} B, PLY binary {} B, STL {} B",
        b0().faces.len(),
        f.off.len(),
        f.obj.len(),
        f.ply_ascii.len(),
        f.ply_binary.len(),
        f.stl.len()
    );
    divan::main();
}

fn ours(b: divan::Bencher, bytes: &'static [u8], format: Format) {
    b.counter(BytesCount::new(bytes.len()))
        .bench(|| io::read_tri_mesh_bytes(bytes, Some(format)).expect("B0 reads back"));
}

#[divan::bench(sample_count = 5)]
fn off(b: divan::Bencher) {
    ours(b, &files().off, Format::Off);
}

#[divan::bench(sample_count = 5)]
fn obj(b: divan::Bencher) {
    ours(b, &files().obj, Format::Obj);
}

#[divan::bench(sample_count = 5)]
fn ply_ascii(b: divan::Bencher) {
    ours(b, &files().ply_ascii, Format::Ply);
}

#[divan::bench(sample_count = 5)]
fn ply_binary(b: divan::Bencher) {
    ours(b, &files().ply_binary, Format::Ply);
}

#[divan::bench(sample_count = 5)]
fn stl_binary(b: divan::Bencher) {
    ours(b, &files().stl, Format::Stl);
}

/// A file of four triangles (the tetrahedron as binary STL, 284 bytes): the cost of a
/// reader's set-up, which small files and fuzzing pay on every call.
#[divan::bench(sample_count = 100)]
fn stl_binary_tetrahedron(b: divan::Bencher) {
    static T: OnceLock<Vec<u8>> = OnceLock::new();
    let bytes = T.get_or_init(|| {
        let mut out = Vec::new();
        let m = contractible::gen::tetrahedron();
        io::write_mesh_to(&mut out, &m, Format::Stl, true).expect("writable");
        out
    });
    ours(b, bytes, Format::Stl);
}

/// `tobj::load_obj_buf` with the options that keep the file's faces (triangles, one
/// index per corner).
#[divan::bench(sample_count = 5)]
fn peer_tobj_obj(b: divan::Bencher) {
    let bytes: &[u8] = &files().obj;
    let opts = tobj::LoadOptions {
        single_index: false,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    };
    b.counter(BytesCount::new(bytes.len())).bench(|| {
        tobj::load_obj_buf(&mut Cursor::new(bytes), &opts, |_| {
            Ok((Vec::new(), Default::default()))
        })
        .expect("B0 reads back")
    });
}

fn peer_ply(b: divan::Bencher, bytes: &'static [u8]) {
    b.counter(BytesCount::new(bytes.len())).bench(|| {
        let parser = ply_rs_bw::parser::Parser::<ply_rs_bw::ply::DefaultElement>::new();
        parser
            .read_ply(&mut Cursor::new(bytes))
            .expect("B0 reads back")
    });
}

/// `ply_rs_bw::parser::Parser::read_ply` (a map of properties per record).
#[divan::bench(sample_count = 5)]
fn peer_ply_rs_ascii(b: divan::Bencher) {
    peer_ply(b, &files().ply_ascii);
}

/// As [`peer_ply_rs_ascii`], binary.
#[divan::bench(sample_count = 5)]
fn peer_ply_rs_binary(b: divan::Bencher) {
    peer_ply(b, &files().ply_binary);
}

/// `stl_io::read_stl` (welds corners into an indexed mesh, as this reader does).
#[divan::bench(sample_count = 5)]
fn peer_stl_io_binary(b: divan::Bencher) {
    let bytes: &[u8] = &files().stl;
    b.counter(BytesCount::new(bytes.len()))
        .bench(|| stl_io::read_stl(&mut Cursor::new(bytes)).expect("B0 reads back"));
}

/// The coordinate tokens of B0's OFF text (its vertex lines), for the float parsers.
fn float_tokens() -> &'static Vec<&'static [u8]> {
    static T: OnceLock<Vec<&'static [u8]>> = OnceLock::new();
    T.get_or_init(|| {
        let off: &'static [u8] = &files().off;
        off.split(|&b| b == b'\n')
            .skip(2)
            .take(b0().vertex_count)
            .flat_map(|l| l.split(|&b| b == b' ').filter(|t| !t.is_empty()))
            .collect()
    })
}

/// The readers' float parser, `fast_float2::parse`, on B0's coordinate tokens.
#[divan::bench(sample_count = 5)]
fn floats_fast_float2(b: divan::Bencher) {
    let toks = float_tokens();
    b.counter(divan::counter::ItemsCount::new(toks.len()))
        .bench(|| {
            toks.iter()
                .map(|t| fast_float2::parse::<f64, _>(t).expect("a number"))
                .sum::<f64>()
        });
}

/// The standard library's, `str::parse::<f64>` after a UTF-8 check, on the same tokens.
#[divan::bench(sample_count = 5)]
fn floats_std(b: divan::Bencher) {
    let toks = float_tokens();
    b.counter(divan::counter::ItemsCount::new(toks.len()))
        .bench(|| {
            toks.iter()
                .map(|t| {
                    std::str::from_utf8(t)
                        .expect("text")
                        .parse::<f64>()
                        .expect("a number")
                })
                .sum::<f64>()
        });
}
