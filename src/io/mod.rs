//! Mesh file I/O (OFF, OBJ, PLY ascii/binary, STL binary/ASCII, optionally
//! gzip-compressed).
//!
//! Reading guarantees, for every reader and any input bytes:
//! - no panic, no arithmetic overflow on counts;
//! - no allocation driven by a header count beyond what the input's size can justify (each
//!   declared count is checked against the smallest possible encoding of that many records
//!   in the bytes that remain, before anything is reserved);
//! - every failure is a [`ReadError`] with a typed [`ReadErrorKind`] and a [`Location`]
//!   (1-based line for text, byte offset for binary PLY and STL payloads);
//! - face indices are checked `< vertex_count` and stored 0-based; coordinates must be
//!   finite. Faces need at least 3 corners: [`PolyMesh`] keeps polygons (with the file
//!   line of each face), the triangle readers ([`read_tri_mesh`]...) refuse them naming
//!   the first. Messages number faces and indices as the file does: from 1 in OBJ, from
//!   0 elsewhere. Manifoldness is *not* checked here ([`crate::diagnose`] lists every
//!   problem, [`crate::Surfaces`] builds).
//! - a UTF-8 byte order mark before a text format (OFF, OBJ, PLY, ASCII STL) is skipped;
//!   byte offsets count from the start of the input, the mark included.
//! - STL has no shared vertices: its reader welds corners at bitwise-equal positions
//!   (see the `stl` module's docs); [`Mesh::welded`] does the same for any mesh.
//!
//! Inputs are streamed: a file, a reader or a gzip decoder is read through one buffer that
//! holds the line or record being parsed, so reading needs memory for the mesh, not for the
//! input (a gzip file expanding to gigabytes of blank lines or comments is read in a few
//! hundred kilobytes; a single line longer than [`MAX_LINE`] is refused as
//! [`ReadErrorKind::LineTooLong`]). Allocations follow the records actually read; a
//! header count is only trusted up to what the input's length can hold, or up to 65,536
//! records when the length is not known in advance (compressed or piped input).

mod error;
mod input;
pub mod list;
mod obj;
mod off;
mod ply;
mod poly;
mod stl;
mod text;

use std::fmt::Write as _;
use std::fs::File;
use std::io::{BufWriter, Read, Write};
use std::path::Path;

pub use error::{Location, ReadError, ReadErrorKind, WriteError};
pub use input::MAX_LINE;
pub use ply::PlyEncoding;
pub use poly::{PolyMesh, SkippedStatements, Triangulated};

use crate::mesh::{Mesh, TriMesh};
use input::Input;

/// A mesh file format. Guarantees nothing beyond naming the format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// ASCII Object File Format.
    Off,
    /// Wavefront OBJ.
    Obj,
    /// Stanford PLY (ascii or binary).
    Ply,
    /// STL (binary or ASCII when read; written binary), welded on reading.
    Stl,
}

impl Format {
    /// The format named by a path's extension (`.off`, `.obj`, `.ply`, `.stl`, case-insensitive,
    /// optionally followed by `.gz`), and whether the name ends in `.gz`.
    pub fn from_path(path: &Path) -> (Option<Format>, bool) {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().to_ascii_lowercase())
            .unwrap_or_default();
        let (stem, gz) = match name.strip_suffix(".gz") {
            Some(s) => (s, true),
            None => (name.as_str(), false),
        };
        let format = if stem.ends_with(".off") {
            Some(Format::Off)
        } else if stem.ends_with(".obj") {
            Some(Format::Obj)
        } else if stem.ends_with(".ply") {
            Some(Format::Ply)
        } else if stem.ends_with(".stl") {
            Some(Format::Stl)
        } else {
            None
        };
        (format, gz)
    }

    /// Guesses the format of (decompressed) content: the `ply` magic; a binary STL whose
    /// length matches its triangle count, or an ASCII STL's `solid` keyword; else from the
    /// first non-comment line, an `OFF`-family keyword or an OBJ statement. `None`
    /// otherwise. A UTF-8 byte order mark at the start is skipped.
    pub fn sniff(bytes: &[u8]) -> Option<Format> {
        let mut input = Input::from_slice(bytes);
        sniff_input(&mut input).ok().flatten()
    }
}

/// [`Format::sniff`] on the start of a stream, without consuming anything: looks at as much
/// as the decision needs (the first data line may follow comments; at most [`MAX_LINE`]
/// bytes are looked at). The STL length rule applies when the input's length is known.
fn sniff_input(input: &mut Input<'_>) -> Result<Option<Format>, ReadError> {
    let len = input.known_len();
    if stl::sniff(stl::probe(input)?, len) {
        return Ok(Some(Format::Stl));
    }
    let mut want = 4096;
    loop {
        let head = input.peek(want)?;
        let complete = head.len() < want || want >= MAX_LINE;
        let head = strip_bom(head);
        if head.starts_with(b"ply") {
            return Ok(Some(Format::Ply));
        }
        let mut lines = text::Lines::new(head);
        // A data line counts only when the text after it is there too (it is complete).
        let found = match lines.next_data_line(b'#') {
            Some((_, line)) if complete || lines.remaining() > 0 => Some(line),
            _ => None,
        };
        if let Some(line) = found {
            return Ok(Format::of_first_data_line(line));
        }
        if complete {
            return Ok(None);
        }
        want *= 4;
    }
}

impl Format {
    /// The format the first non-comment line names: an `OFF`-family keyword or an OBJ
    /// statement.
    fn of_first_data_line(line: &[u8]) -> Option<Format> {
        let first = text::Tokens::new(line).next()?;
        if let Some(prefix) = first.strip_suffix(b"OFF") {
            if prefix
                .iter()
                .all(|b| matches!(b, b'S' | b'T' | b'C' | b'N'))
            {
                return Some(Format::Off);
            }
        }
        match first {
            b"v" | b"vn" | b"vt" | b"vp" | b"f" | b"o" | b"g" | b"s" | b"usemtl" | b"mtllib" => {
                Some(Format::Obj)
            }
            _ => None,
        }
    }
}

const GZIP_MAGIC: [u8; 2] = [0x1f, 0x8b];

/// Where a mesh's bytes come from: in memory, a file (both can be read twice, which the
/// STL length rule may need for gzip content), or a reader read once.
enum Source<'a> {
    Bytes(&'a [u8]),
    File {
        path: &'a Path,
        on_read: Option<&'a mut (dyn FnMut(u64) + 'a)>,
    },
    Reader(Box<dyn Read + 'a>),
}

fn io_error(e: std::io::Error) -> ReadError {
    ReadError::new(ReadErrorKind::Io(e), Location::Unknown)
}

/// Reads `reader` through a decoder when its first bytes are the gzip magic.
fn open_stream<'a>(
    mut reader: Box<dyn Read + 'a>,
    len: Option<u64>,
) -> Result<Input<'a>, ReadError> {
    let mut magic = [0u8; 2];
    let mut got = 0;
    while got < magic.len() {
        match reader.read(&mut magic[got..]) {
            Ok(0) => break,
            Ok(n) => got += n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(io_error(e)),
        }
    }
    let prefix = magic.get(..got).unwrap_or_default().to_vec();
    let whole: Box<dyn Read + 'a> = Box::new(std::io::Cursor::new(prefix).chain(reader));
    Ok(if magic == GZIP_MAGIC && got == 2 {
        Input::new(
            Box::new(flate2::read::MultiGzDecoder::new(whole)),
            true,
            None,
        )
    } else {
        Input::new(whole, false, len)
    })
}

/// Counts the file bytes read, for a caller's progress display.
struct Observed<'a, R> {
    inner: R,
    total: u64,
    on_read: &'a mut dyn FnMut(u64),
}

impl<R: Read> Read for Observed<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.total += n as u64;
        (self.on_read)(self.total);
        Ok(n)
    }
}

impl<'a> Source<'a> {
    /// The bytes as a stream (decompressed when gzip).
    fn open(&mut self) -> Result<Input<'_>, ReadError> {
        match self {
            Source::Bytes(b) => open_stream(Box::new(*b), Some(b.len() as u64)),
            Source::File { path, on_read } => {
                let file = File::open(path).map_err(io_error)?;
                let len = file.metadata().map_err(io_error)?.len();
                let file = std::io::BufReader::with_capacity(1 << 16, file);
                match on_read {
                    Some(f) => open_stream(
                        Box::new(Observed {
                            inner: file,
                            total: 0,
                            on_read: &mut **f,
                        }),
                        Some(len),
                    ),
                    None => open_stream(Box::new(file), Some(len)),
                }
            }
            Source::Reader(r) => open_stream(Box::new(r), None),
        }
    }

    /// The length of the bytes as stored (compressed if gzip); `None` for a reader.
    fn packed_len(&self) -> Result<Option<u64>, ReadError> {
        Ok(match self {
            Source::Bytes(b) => Some(b.len() as u64),
            Source::File { path, .. } => Some(std::fs::metadata(path).map_err(io_error)?.len()),
            Source::Reader(_) => None,
        })
    }

    /// The decompressed length of gzip content, by a pass that decompresses it without
    /// keeping it (`None` for a reader, which cannot be read twice).
    fn gunzipped_len(&self) -> Result<Option<u64>, ReadError> {
        let raw: Box<dyn Read + '_> = match self {
            Source::Bytes(b) => Box::new(*b),
            Source::File { path, .. } => Box::new(File::open(path).map_err(io_error)?),
            Source::Reader(_) => return Ok(None),
        };
        std::io::copy(
            &mut flate2::read::MultiGzDecoder::new(raw),
            &mut std::io::sink(),
        )
        .map(Some)
        .map_err(|e| ReadError::new(input::gzip_error(e), Location::Unknown))
    }
}

/// How [`read_source`] settles the format.
#[derive(Clone, Copy)]
enum Pick {
    /// The content's, when [`sniff_input`] recognises it; else the declared one.
    Sniff(Option<Format>),
    /// This one, whatever the content.
    Given(Format),
}

/// The error for a name ending in `.gz` whose content is not gzip.
fn not_gzip() -> ReadError {
    ReadError::new(
        ReadErrorKind::Decompress("file name ends in .gz but the content is not gzip".into()),
        Location::ByteOffset(0),
    )
}

/// Streams `source` and parses it in the format `pick` settles; `named_gz`: the name
/// ends in `.gz`, so the content must be gzip.
fn read_source(mut source: Source<'_>, pick: Pick, named_gz: bool) -> Result<Decoded, ReadError> {
    let declared = match pick {
        Pick::Sniff(declared) => declared,
        Pick::Given(format) => Some(format),
    };
    let packed = source.packed_len()?;
    let mut input = source.open()?;
    if named_gz && !input.is_gzip() {
        return Err(not_gzip());
    }
    let sniff = |input: &mut Input<'_>| match pick {
        Pick::Sniff(_) => sniff_input(input),
        Pick::Given(_) => Ok(None),
    };
    let mut sniffed = sniff(&mut input)?;
    // The binary STL rule compares the length with the triangle count, and decides
    // before any other format (the header of a binary STL may read like one). Compressed
    // content has no length until it is decompressed: when the rule may need it, a first
    // pass measures it (a reader read once goes without, see the `stl` module).
    let stl_allowed = match pick {
        Pick::Sniff(_) => true,
        Pick::Given(format) => format == Format::Stl,
    };
    let measure = match packed {
        Some(packed) if input.is_gzip() && stl_allowed => {
            stl::binary_size_possible(stl::probe(&mut input)?, packed)
        }
        _ => false,
    };
    if measure {
        drop(input);
        let len = source.gunzipped_len()?;
        input = source.open()?;
        input.set_known_len(len);
        sniffed = sniff(&mut input)?;
    }
    let format = match sniffed.or(declared) {
        Some(format) => format,
        // A stream read once has no length for the binary STL rule (a length that
        // matches the count): read it as binary STL, which checks exactly that as it ends.
        None if input.known_len().is_none() => {
            let mesh = stl::parse_unsniffed(&mut input)?;
            return Ok(Decoded {
                mesh: mesh.into(),
                format: Format::Stl,
                declared,
            });
        }
        None => {
            return Err(ReadError::new(
                ReadErrorKind::UnknownFormat,
                Location::Unknown,
            ))
        }
    };
    let mesh = parse(&mut input, format)?;
    Ok(Decoded {
        mesh,
        format,
        declared,
    })
}

/// The UTF-8 byte order mark some editors put at the start of text files.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// `bytes` without a leading UTF-8 byte order mark.
fn strip_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(BOM).unwrap_or(bytes)
}

/// A mesh read by [`decode`] or [`read_poly_mesh`], with the format used and the format
/// the caller (extension or option) declared.
#[derive(Clone, Debug)]
pub struct Decoded {
    /// The faces as the file has them.
    pub mesh: PolyMesh,
    /// The format the content was parsed as.
    pub format: Format,
    /// The format declared by the caller (`None`: nothing declared, the content decided).
    pub declared: Option<Format>,
}

impl Decoded {
    /// The declared format when the content was read as another one (callers should warn).
    pub fn disagreement(&self) -> Option<Format> {
        self.declared.filter(|&d| d != self.format)
    }
}

impl std::fmt::Display for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Format::Off => "OFF",
            Format::Obj => "OBJ",
            Format::Ply => "PLY",
            Format::Stl => "STL",
        })
    }
}

/// Reads a mesh from in-memory bytes whose format was `declared` (by a file extension or
/// an option): the content decides when [`Format::sniff`] recognises it (the result
/// records a disagreement, [`Decoded::disagreement`]), the declared format otherwise.
///
/// Guarantees: as [`read_tri_mesh_bytes`] (no panic, bounded allocation); gzip detected
/// by its magic bytes; `UnknownFormat` when neither decides.
pub fn decode(bytes: &[u8], declared: Option<Format>) -> Result<Decoded, ReadError> {
    read_source(Source::Bytes(bytes), Pick::Sniff(declared), false)
}

/// [`decode`] on a stream read once (standard input, a socket): the same rules, in memory
/// for the mesh only, except where the STL rule needs the length before the stream ends:
/// content that no header names is read as binary STL, kept if its length matches its
/// triangle count (`UnknownFormat` otherwise), and a binary STL whose 80-byte header
/// starts like another format (`ply`, `OFF`, an OBJ statement, `solid` and text) is read
/// as that format (see the `stl` module).
pub fn decode_reader(reader: impl Read, declared: Option<Format>) -> Result<Decoded, ReadError> {
    read_source(
        Source::Reader(Box::new(reader)),
        Pick::Sniff(declared),
        false,
    )
}

fn parse(input: &mut Input<'_>, format: Format) -> Result<PolyMesh, ReadError> {
    // The STL reader skips a BOM itself where it applies (ASCII only).
    if format != Format::Stl && input.peek(BOM.len())? == BOM {
        input.consume(BOM.len());
    }
    match format {
        Format::Off => off::parse_off(input),
        Format::Obj => obj::parse_obj(input),
        Format::Ply => ply::parse_ply(input),
        Format::Stl => stl::parse_stl(input).map(PolyMesh::from),
    }
}

/// Reads a mesh file as [`decode`] does, streaming it (memory for the mesh, not the file),
/// the declared format being `format` or else the extension's (`.off`/`.obj`/`.ply`/`.stl`,
/// case-insensitive, optionally `.gz`); gzip content is detected by its magic bytes
/// whatever the name (a `.gz` name without them is a `Decompress` error). Errors carry
/// `path`.
pub fn read_poly_mesh(path: &Path, format: Option<Format>) -> Result<Decoded, ReadError> {
    read_file(path, format, None)
}

/// [`read_poly_mesh`], calling `on_read` with the number of file bytes read so far as the
/// reading goes (for a progress display; compressed files count compressed bytes).
pub fn read_poly_mesh_observed(
    path: &Path,
    format: Option<Format>,
    on_read: &mut dyn FnMut(u64),
) -> Result<Decoded, ReadError> {
    read_file(path, format, Some(on_read))
}

fn read_file<'a>(
    path: &'a Path,
    format: Option<Format>,
    on_read: Option<&'a mut (dyn FnMut(u64) + 'a)>,
) -> Result<Decoded, ReadError> {
    let (from_name, gz) = Format::from_path(path);
    let result = read_source(
        Source::File { path, on_read },
        Pick::Sniff(format.or(from_name)),
        gz,
    );
    result.map_err(|e| e.with_path(path))
}

/// [`read_poly_mesh`] on the bytes of the file `path` already read: the same checks, format
/// rules and errors.
pub fn decode_named(
    path: &Path,
    bytes: &[u8],
    format: Option<Format>,
) -> Result<Decoded, ReadError> {
    let (from_name, gz) = Format::from_path(path);
    read_source(Source::Bytes(bytes), Pick::Sniff(format.or(from_name)), gz)
        .map_err(|e| e.with_path(path))
}

/// Reads a triangle mesh from a file: [`read_poly_mesh`] (the content decides the format
/// when it can, else the extension), then [`PolyMesh::into_tri_mesh`] (a face with other
/// than 3 corners is `NonTriangleFace`). Errors carry `path`.
pub fn read_tri_mesh(path: &Path) -> Result<TriMesh, ReadError> {
    read_poly_mesh(path, None).and_then(|d| d.mesh.into_tri_mesh().map_err(|e| e.with_path(path)))
}

/// Reads a triangle mesh in `format` from a reader, streaming it (gzip content is detected
/// by its magic bytes and decompressed as it is read). Same guarantees as
/// [`read_tri_mesh_bytes`].
pub fn read_tri_mesh_from(reader: impl Read, format: Format) -> Result<TriMesh, ReadError> {
    read_source(Source::Reader(Box::new(reader)), Pick::Given(format), false)?
        .mesh
        .into_tri_mesh()
}

/// Reads a polygon mesh from in-memory bytes in `format` (gzip detected by magic bytes;
/// the format sniffed from the content when `format` is `None`).
///
/// Guarantees: never panics and never allocates more than a small multiple of the mesh
/// it returns, or of the input's size, whatever the bytes (compressed content included);
/// suitable as a fuzzing entry point.
pub fn read_poly_mesh_bytes(bytes: &[u8], format: Option<Format>) -> Result<PolyMesh, ReadError> {
    let pick = match format {
        Some(f) => Pick::Given(f),
        None => Pick::Sniff(None),
    };
    read_source(Source::Bytes(bytes), pick, false).map(|d| d.mesh)
}

/// Reads a triangle mesh from in-memory bytes: [`read_poly_mesh_bytes`], then
/// [`PolyMesh::into_tri_mesh`]. Same guarantees.
pub fn read_tri_mesh_bytes(bytes: &[u8], format: Option<Format>) -> Result<TriMesh, ReadError> {
    read_poly_mesh_bytes(bytes, format)?.into_tri_mesh()
}

/// Checks what the writers rely on: `positions` (if any) has `vertex_count` finite entries,
/// and every face index is `< vertex_count`.
pub fn check_mesh<const N: usize>(mesh: &Mesh<N>) -> Result<(), WriteError> {
    if let Some(p) = &mesh.positions {
        if p.len() != mesh.vertex_count {
            return Err(WriteError::PositionCountMismatch {
                vertex_count: mesh.vertex_count,
                positions: p.len(),
            });
        }
        if let Some(vertex) = p.iter().position(|q| q.iter().any(|x| !x.is_finite())) {
            return Err(WriteError::NonFinitePosition { vertex });
        }
    }
    for (face, f) in mesh.faces.iter().enumerate() {
        if let Some(&index) = f.iter().find(|&&v| v as usize >= mesh.vertex_count) {
            return Err(WriteError::IndexOutOfRange {
                face,
                index,
                vertex_count: mesh.vertex_count,
            });
        }
    }
    Ok(())
}

/// Writes a mesh to a file; the format comes from the extension (`.off`, `.obj`, `.ply`,
/// `.stl`, case-insensitive), a trailing `.gz` gzip-compresses, PLY and STL are binary
/// little-endian (STL: triangles with positions only, coordinates rounded to `f32`).
///
/// Guarantees: the mesh is checked ([`check_mesh`]) and the format chosen before
/// anything is created; the content goes to a temporary file in the same directory
/// (`.contractible-<pid>-<name>`), renamed over `path` only when complete, so an error
/// never leaves a partial, empty or temporary file behind and a reader never sees one;
/// positions are written with full `f64` precision (they read back bit-exactly); a mesh
/// without positions is written with `0 0 0` for every vertex.
pub fn write_mesh<const N: usize>(path: &Path, mesh: &Mesh<N>) -> Result<(), WriteError> {
    let (format, gz) = Format::from_path(path);
    let format = format.ok_or_else(|| WriteError::UnknownFormat(path.to_path_buf()))?;
    if format == Format::Stl {
        if let Some(reason) = stl::unrepresentable(mesh) {
            return Err(WriteError::Unrepresentable {
                format: "STL",
                reason,
            });
        }
    }
    check_mesh(mesh)?;
    let tmp = temp_path(path);
    let r = (|| -> Result<(), WriteError> {
        let file = BufWriter::with_capacity(1 << 16, File::create(&tmp)?);
        if gz {
            let mut enc = flate2::write::GzEncoder::new(file, flate2::Compression::default());
            write_mesh_to(&mut enc, mesh, format, true)?;
            enc.finish()?.flush()?;
        } else {
            let mut file = file;
            write_mesh_to(&mut file, mesh, format, true)?;
            file.flush()?;
        }
        std::fs::rename(&tmp, path)?;
        Ok(())
    })();
    if r.is_err() {
        // Nothing to report if it is already gone.
        let _ = std::fs::remove_file(&tmp);
    }
    r
}

/// A temporary path beside `out` that keeps its file name (hence its extension):
/// `.contractible-<pid>-<name>` in the same directory, so the final rename stays on one
/// file system.
pub fn temp_path(out: &Path) -> std::path::PathBuf {
    let name = out
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = format!(".contractible-{}-{name}", std::process::id());
    match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.join(tmp),
        _ => std::path::PathBuf::from(tmp),
    }
}

/// Writes a mesh in `format` (PLY binary little-endian when `ply_binary`, else ascii;
/// STL always binary).
///
/// Guarantees: as [`write_mesh`]; nothing is written when [`check_mesh`] fails. Output is
/// buffered internally; the writer is flushed at the end.
pub fn write_mesh_to<const N: usize>(
    w: impl Write,
    mesh: &Mesh<N>,
    format: Format,
    ply_binary: bool,
) -> Result<(), WriteError> {
    check_mesh(mesh)?;
    let mut w = BufWriter::with_capacity(1 << 16, w);
    match format {
        Format::Off => off::write_off(&mut w, mesh)?,
        Format::Obj => obj::write_obj(&mut w, mesh)?,
        Format::Ply => {
            let enc = if ply_binary {
                PlyEncoding::BinaryLittleEndian
            } else {
                PlyEncoding::Ascii
            };
            ply::write_ply(&mut w, mesh, enc)?;
        }
        Format::Stl => stl::write_stl(&mut w, mesh)?,
    }
    w.flush()?;
    Ok(())
}

/// Writes a mesh as PLY with the given encoding (including big-endian binary).
///
/// Guarantees: as [`write_mesh_to`].
pub fn write_ply_to<const N: usize>(
    w: impl Write,
    mesh: &Mesh<N>,
    encoding: PlyEncoding,
) -> Result<(), WriteError> {
    check_mesh(mesh)?;
    let mut w = BufWriter::with_capacity(1 << 16, w);
    ply::write_ply(&mut w, mesh, encoding)?;
    w.flush()?;
    Ok(())
}

/// Appends `x y z` (shortest round-trip decimal forms) or `0 0 0` when `p` is `None`.
fn fmt_f64_triple(buf: &mut String, p: Option<&[f64; 3]>) {
    match p {
        // Writing to a String cannot fail.
        Some([x, y, z]) => {
            let _ = write!(buf, "{x} {y} {z}");
        }
        None => buf.push_str("0 0 0"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sniffing looks past comments of any length up to the line limit, and decides on
    /// a data line only once the line is whole: a keyword cut by the end of the first
    /// look (4,096 bytes) is read again in full.
    #[test]
    fn sniffing_looks_past_long_comments_and_waits_for_a_whole_line() {
        let bodies: [(&[u8], Format); 2] = [
            (b"OFF\n4 4 0\n", Format::Off),
            (b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", Format::Obj),
        ];
        // The look grows fourfold: a comment of megabytes takes a few looks, not a
        // million.
        let pads = (4085..=4100).chain([20_000, 70_000, 3 << 20]);
        for pad in pads {
            for (body, format) in bodies {
                let mut bytes = vec![b'#'];
                bytes.resize(pad - 1, b'x');
                bytes.push(b'\n');
                bytes.extend_from_slice(body);
                assert_eq!(
                    Format::sniff(&bytes),
                    Some(format),
                    "{pad} bytes of comment"
                );
                // A comment alone names no format, however long.
                assert_eq!(Format::sniff(&bytes[..pad]), None, "{pad}");
            }
        }
    }
}
