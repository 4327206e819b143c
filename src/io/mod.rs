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
//!   for binary PLY, byte offsets then count from after it.
//! - STL has no shared vertices: its reader welds corners at bitwise-equal positions
//!   (see the `stl` module's docs); [`Mesh::welded`] does the same for any mesh.
//!
//! Inputs are read completely into memory (and decompressed when gzip) before parsing.

mod error;
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
pub use ply::PlyEncoding;
pub use poly::{PolyMesh, SkippedStatements, Triangulated};

use crate::mesh::{Mesh, TriMesh};

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
        if stl::sniff(bytes) {
            return Some(Format::Stl);
        }
        let bytes = strip_bom(bytes);
        if bytes.starts_with(b"ply") {
            return Some(Format::Ply);
        }
        let mut lines = text::Lines::new(bytes);
        let (_, line) = lines.next_data_line(b'#')?;
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

/// Decompresses `bytes` if they start with the gzip magic; otherwise borrows them.
fn maybe_gunzip(bytes: &[u8]) -> Result<std::borrow::Cow<'_, [u8]>, ReadError> {
    if !bytes.starts_with(&GZIP_MAGIC) {
        return Ok(std::borrow::Cow::Borrowed(bytes));
    }
    let mut out = Vec::new();
    flate2::read::MultiGzDecoder::new(bytes)
        .read_to_end(&mut out)
        .map_err(|e| ReadError::new(ReadErrorKind::Decompress(e.to_string()), Location::Unknown))?;
    Ok(std::borrow::Cow::Owned(out))
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
    let data = maybe_gunzip(bytes)?;
    let format = Format::sniff(&data)
        .or(declared)
        .ok_or_else(|| ReadError::new(ReadErrorKind::UnknownFormat, Location::Unknown))?;
    let mesh = parse(&data, format)?;
    Ok(Decoded {
        mesh,
        format,
        declared,
    })
}

fn parse(data: &[u8], format: Format) -> Result<PolyMesh, ReadError> {
    match format {
        Format::Off => off::parse_off(strip_bom(data)),
        Format::Obj => obj::parse_obj(strip_bom(data)),
        Format::Ply => ply::parse_ply(strip_bom(data)),
        // The STL reader skips a BOM itself where it applies (ASCII only).
        Format::Stl => stl::parse_stl(data).map(PolyMesh::from),
    }
}

/// Reads a mesh file as [`decode`] does, the declared format being `format` or else the
/// extension's (`.off`/`.obj`/`.ply`/`.stl`, case-insensitive, optionally `.gz`); gzip
/// content is detected by its magic bytes whatever the name (a `.gz` name without them is
/// a `Decompress` error). Errors carry `path`.
pub fn read_poly_mesh(path: &Path, format: Option<Format>) -> Result<Decoded, ReadError> {
    std::fs::read(path)
        .map_err(|e| ReadError::new(ReadErrorKind::Io(e), Location::Unknown).with_path(path))
        .and_then(|bytes| decode_named(path, &bytes, format))
}

/// [`read_poly_mesh`] on the bytes of the file `path` already read (by a caller that
/// shows the reading's progress, say): the same checks, format rules and errors.
pub fn decode_named(
    path: &Path,
    bytes: &[u8],
    format: Option<Format>,
) -> Result<Decoded, ReadError> {
    let (from_name, gz) = Format::from_path(path);
    let result = if gz && !bytes.starts_with(&GZIP_MAGIC) {
        Err(ReadError::new(
            ReadErrorKind::Decompress("file name ends in .gz but the content is not gzip".into()),
            Location::ByteOffset(0),
        ))
    } else {
        decode(bytes, format.or(from_name))
    };
    result.map_err(|e| e.with_path(path))
}

/// Reads a triangle mesh from a file: [`read_poly_mesh`] (the content decides the format
/// when it can, else the extension), then [`PolyMesh::into_tri_mesh`] (a face with other
/// than 3 corners is `NonTriangleFace`). Errors carry `path`.
pub fn read_tri_mesh(path: &Path) -> Result<TriMesh, ReadError> {
    read_poly_mesh(path, None).and_then(|d| d.mesh.into_tri_mesh().map_err(|e| e.with_path(path)))
}

/// Reads a triangle mesh in `format` from a reader (read to the end; gzip content is
/// detected by its magic bytes and decompressed). Same guarantees as [`read_tri_mesh_bytes`].
pub fn read_tri_mesh_from(mut reader: impl Read, format: Format) -> Result<TriMesh, ReadError> {
    let mut bytes = Vec::new();
    reader
        .read_to_end(&mut bytes)
        .map_err(|e| ReadError::new(ReadErrorKind::Io(e), Location::Unknown))?;
    read_tri_mesh_bytes(&bytes, Some(format))
}

/// Reads a polygon mesh from in-memory bytes in `format` (gzip detected by magic bytes;
/// the format sniffed from the content when `format` is `None`).
///
/// Guarantees: never panics and never allocates more than a small multiple of the
/// (decompressed) input size, whatever the bytes; suitable as a fuzzing entry point.
pub fn read_poly_mesh_bytes(bytes: &[u8], format: Option<Format>) -> Result<PolyMesh, ReadError> {
    let data = maybe_gunzip(bytes)?;
    let format = match format {
        Some(f) => f,
        None => Format::sniff(&data)
            .ok_or_else(|| ReadError::new(ReadErrorKind::UnknownFormat, Location::Unknown))?,
    };
    parse(&data, format)
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
