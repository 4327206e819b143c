//! Typed read and write errors that say *where* something went wrong.

use std::fmt;
use std::path::PathBuf;

/// Where in the input a [`ReadError`] was detected.
///
/// Guarantees: line numbers are 1-based lines of the (decompressed) text; byte offsets are
/// 0-based offsets into the decompressed input; face numbers count faces in file order as
/// the file does (from 1 in OBJ, from 0 elsewhere).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Location {
    /// A 1-based line of a text format (OFF, OBJ, ascii PLY, any PLY header).
    Line(usize),
    /// A 0-based byte offset into the decompressed input (binary PLY or STL).
    ByteOffset(u64),
    /// A 0-based face number, when no finer position is known.
    Face(usize),
    /// No position applies (e.g. an I/O error opening the file).
    Unknown,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line(n) => write!(f, "line {n}"),
            Location::ByteOffset(o) => write!(f, "byte offset {o}"),
            Location::Face(i) => write!(f, "face {i}"),
            Location::Unknown => f.write_str("unknown location"),
        }
    }
}

/// What went wrong while reading a mesh. Every variant is produced by at least one reader.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReadErrorKind {
    /// The underlying reader or file failed.
    #[error("I/O error: {0}")]
    Io(#[from] std::io::Error),
    /// The gzip stream could not be decompressed (or a `.gz` file is not gzip).
    #[error("gzip decompression failed: {0}")]
    Decompress(String),
    /// Neither the extension nor the content identifies OFF, OBJ, PLY or STL.
    #[error("unknown mesh format (expected OFF, OBJ, PLY or STL)")]
    UnknownFormat,
    /// The header is malformed or declares something unsupported.
    #[error("bad header: {0}")]
    BadHeader(String),
    /// The input ended (binary PLY or STL, ASCII STL) before the declared data was complete.
    #[error("input truncated: expected {expected}")]
    Truncated {
        /// What was still expected.
        expected: String,
    },
    /// A record line has fewer values than the record needs.
    #[error("missing value: expected {expected}")]
    MissingValue {
        /// Which value was missing.
        expected: &'static str,
    },
    /// A token is not a valid number of the required kind (or a coordinate is not finite).
    #[error("bad number {token:?}")]
    BadNumber {
        /// The offending token (cut to at most 64 bytes).
        token: String,
    },
    /// The number of records found differs from the number declared in the header.
    #[error("{what}: header declares {declared}, found {found}")]
    CountMismatch {
        /// Which records (`"vertices"`, `"faces"`, a PLY element name...).
        what: &'static str,
        /// The count the header declares.
        declared: u64,
        /// The count actually present.
        found: u64,
    },
    /// A declared count cannot possibly fit in the remaining input, or exceeds `u32` indexing.
    #[error("{what}: declared count {declared} is impossible for this input")]
    CountTooLarge {
        /// Which records.
        what: &'static str,
        /// The count the header declares.
        declared: u64,
    },
    /// A face does not have exactly 3 corners (the triangle readers), or fewer than 3
    /// (every reader, [`crate::io::PolyMesh`] included).
    #[error("face {face} has {corners} corners, only triangles are accepted")]
    NonTriangleFace {
        /// Face number as the file counts: from 1 in OBJ, from 0 elsewhere.
        face: usize,
        /// Its number of corners.
        corners: u64,
    },
    /// A face refers to a vertex that does not exist.
    #[error("face {face} refers to vertex {index}, but there are {vertex_count} vertices")]
    IndexOutOfRange {
        /// Face number as the file counts: from 1 in OBJ, from 0 elsewhere.
        face: usize,
        /// The index as written in the file (1-based or negative relative in OBJ, 0-based
        /// and possibly negative for signed PLY indices elsewhere).
        index: i64,
        /// Number of vertices in the file.
        vertex_count: usize,
    },
    /// Non-whitespace data follows the last declared record.
    #[error("unexpected data after the last {what}")]
    TrailingData {
        /// The last record kind.
        what: &'static str,
    },
    /// OBJ-specific structural problem.
    #[error("OBJ: {0}")]
    Obj(String),
    /// PLY-specific structural problem (including what `ply-rs-bw` reported for the header).
    #[error("PLY: {0}")]
    Ply(String),
    /// STL-specific structural problem (an ASCII keyword out of place).
    #[error("STL: {0}")]
    Stl(String),
    /// A text line is longer than the readers accept (see [`crate::io::MAX_LINE`]): no
    /// mesh format needs such a line, and buffering it would let one line take any amount
    /// of memory.
    #[error("line longer than {limit} bytes")]
    LineTooLong {
        /// The limit, in bytes.
        limit: usize,
    },
    /// Malformed line of a surface list (`NAME: [[a,b,c],...]`, see [`crate::io::list`]).
    #[error("surface list: {0}")]
    List(String),
}

impl ReadErrorKind {
    /// `CountTooLarge` for a declared count of `what` (faces, triangles) above
    /// [`crate::core::MAX_FACES`], if it is: more faces than a triangulation indexes
    /// (their corners would overflow `u32`). The readers say it at the header or at the
    /// record past the limit, before the faces are stored.
    pub(crate) fn past_face_limit(what: &'static str, declared: u64) -> Option<Self> {
        (declared > crate::core::MAX_FACES as u64)
            .then_some(ReadErrorKind::CountTooLarge { what, declared })
    }
}

/// A failed read: what ([`ReadErrorKind`]), where ([`Location`]) and in which file.
///
/// Displays as `path:location: message` (path and location omitted when unknown).
#[derive(Debug)]
pub struct ReadError {
    /// What went wrong.
    pub kind: ReadErrorKind,
    /// Where it went wrong.
    pub location: Location,
    /// The file, when reading from a path.
    pub path: Option<PathBuf>,
}

impl ReadError {
    /// An error of `kind` at `location`, with no path yet.
    pub fn new(kind: ReadErrorKind, location: Location) -> Self {
        ReadError {
            kind,
            location,
            path: None,
        }
    }

    /// Shorthand: an error at a 1-based text line.
    pub(crate) fn at_line(kind: ReadErrorKind, line: usize) -> Self {
        Self::new(kind, Location::Line(line))
    }

    /// Shorthand: an error at a byte offset.
    pub(crate) fn at_byte(kind: ReadErrorKind, offset: usize) -> Self {
        Self::new(kind, Location::ByteOffset(offset as u64))
    }

    /// The same error, attributed to `path`.
    pub fn with_path(mut self, path: impl Into<PathBuf>) -> Self {
        self.path = Some(path.into());
        self
    }
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(p) = &self.path {
            write!(f, "{}:", p.display())?;
        }
        if self.location != Location::Unknown {
            write!(f, "{}:", self.location)?;
        }
        if self.path.is_some() || self.location != Location::Unknown {
            f.write_str(" ")?;
        }
        write!(f, "{}", self.kind)
    }
}

impl std::error::Error for ReadError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            ReadErrorKind::Io(e) => Some(e),
            _ => None,
        }
    }
}

/// A failed write. The mesh is checked before anything is written, so a data error
/// (non-finite position, bad index, position count) leaves the output untouched.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum WriteError {
    /// The underlying writer or file failed.
    #[error("I/O error: {0}")]
    Io(#[from] std::io::Error),
    /// The path's extension is not `.off`, `.obj`, `.ply` or `.stl` (optionally followed
    /// by `.gz`).
    #[error(
        "cannot choose a format from the file name {0:?} (use .off, .obj, .ply or .stl, optionally .gz)"
    )]
    UnknownFormat(PathBuf),
    /// The format cannot hold this mesh (STL: no positions, non-triangle faces, more
    /// than `u32::MAX` faces, a coordinate beyond the `f32` range).
    #[error("cannot write {format}: {reason}")]
    Unrepresentable {
        /// The format.
        format: &'static str,
        /// Why.
        reason: String,
    },
    /// `positions` is present but its length differs from `vertex_count`.
    #[error("mesh has vertex_count {vertex_count} but {positions} positions")]
    PositionCountMismatch {
        /// The mesh's `vertex_count`.
        vertex_count: usize,
        /// The length of its `positions`.
        positions: usize,
    },
    /// A position has a NaN or infinite coordinate (the readers would reject it).
    #[error("vertex {vertex} has a non-finite coordinate")]
    NonFinitePosition {
        /// 0-based vertex index.
        vertex: usize,
    },
    /// A face refers to a vertex `>= vertex_count`.
    #[error("face {face} refers to vertex {index}, but there are {vertex_count} vertices")]
    IndexOutOfRange {
        /// 0-based face number.
        face: usize,
        /// The offending index.
        index: u32,
        /// The mesh's `vertex_count`.
        vertex_count: usize,
    },
}

/// Cuts a token for inclusion in an error message (at most 64 bytes, lossy UTF-8).
pub(crate) fn token_string(token: &[u8]) -> String {
    let cut = &token[..token.len().min(64)];
    String::from_utf8_lossy(cut).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_face_limit_is_the_triangulations() {
        let max = crate::core::MAX_FACES as u64;
        assert!(ReadErrorKind::past_face_limit("faces", max).is_none());
        assert!(ReadErrorKind::past_face_limit("faces", 1).is_none());
        assert!(matches!(
            ReadErrorKind::past_face_limit("triangles", max + 1),
            Some(ReadErrorKind::CountTooLarge {
                what: "triangles",
                declared,
            }) if declared == max + 1
        ));
    }
}
