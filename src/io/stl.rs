//! STL reading (binary and ASCII) and binary STL writing.
//!
//! STL stores a list of independent triangles (a normal and three corner positions
//! each); there are no shared vertices. The reader therefore *welds* corners by exact
//! position: two corners are one vertex exactly when their three coordinates are
//! bitwise equal (so `0.0` and `-0.0` stay apart, and nothing is merged within a
//! tolerance). Vertices are numbered in order of first appearance, faces are the
//! triangles in file order (face `i` is triangle `i` of the file). Normals and the binary
//! attribute bytes are ignored (exporters write NaN normals for slivers; they carry
//! nothing the topology needs).
//!
//! A triangle with two corners at the same position becomes a face with a repeated
//! vertex. Like the other readers (which accept `3 0 0 1` in an OFF file), this reader
//! keeps it: validation then refuses the mesh naming that face, which is triangle `i` of
//! the file.
//!
//! **Binary or ASCII.** Many binary files start their free-form 80-byte header with
//! `solid`, so that word alone does not decide. A file is read as binary when its size is
//! exactly `84 + 50·n` for the triangle count `n` stored at bytes 80..84; otherwise as
//! ASCII when it starts with the keyword `solid` (after an optional UTF-8 BOM and
//! whitespace) and its first 512 bytes are text (no control bytes, which the binary
//! count and coordinates nearly always contain); otherwise as binary, whose checks then
//! say what is wrong. Gzip content from memory or a file is measured by a first
//! decompression pass when this rule may need its length: when the binary size its count
//! asks for is within what its compressed size can inflate to (deflate expands at most
//! 1,032-fold; the count of a text file's bytes 80..84 asks for gigabytes, so text meshes
//! of a few megabytes compressed are read once); a gzip stream read once
//! ([`super::decode_reader`]) has no length, and a `solid` start followed by text is then
//! ASCII (a binary file would differ only with a count of at least 538,976,288 triangles
//! whose bytes are all text, at exactly the matching size).
//!
//! **Binary.** The declared count is checked against the input's length *before* anything
//! is reserved (for a stream of unknown length, when it ends, with the same errors): a shorter payload is `Truncated` at the offset of the first incomplete
//! triangle (or a `CountMismatch` at byte 80 when the payload holds a whole number of
//! triangles), a longer one is `TrailingData` at the offset where the declared triangles
//! end. A NaN or infinite coordinate is `BadNumber` at the byte offset of that `f32`.
//! A count above [`crate::core::MAX_FACES`] (more triangles than a triangulation
//! indexes) that passes the length check is `CountTooLarge` at byte 80, before any
//! triangle is read (from a stream of unknown length, once the stream has been read to
//! its end without storing it).
//!
//! **ASCII.** `solid [name]`, then `facet normal nx ny nz`, `outer loop`, three
//! `vertex x y z`, `endloop`, `endfacet` per triangle, and `endsolid [name]`; keywords are
//! case-insensitive and may be split over lines in any way (tokens are read across
//! lines); several `solid ... endsolid` blocks in one file form one mesh. Errors carry the
//! 1-based line: a missing keyword (`Stl`), a missing or non-finite coordinate
//! (`MissingValue`, `BadNumber`), a loop without exactly three vertices
//! (`NonTriangleFace`), input that ends before `endsolid` (`Truncated`), data after the
//! last `endsolid` (`TrailingData`), a facet past [`crate::core::MAX_FACES`]
//! (`CountTooLarge`).
//!
//! **Writing** is binary little-endian: an 80-byte header that does not start with `solid`
//! (so that no reader mistakes it for ASCII), the count, and per face the unit normal of
//! the positions (zero for a degenerate triangle), the corners as `f32`, and a zero
//! attribute count. STL can only hold triangles with coordinates, so a mesh without
//! positions, with non-triangle faces, with more than `u32::MAX` faces or with a
//! coordinate beyond the `f32` range is refused before anything is written. Coordinates
//! are rounded to `f32`: positions that differ only below `f32` precision are one vertex
//! when the file is read back.
//!
//! **Why hand-written.** The maintained crate `stl_io` (0.11) was surveyed: it decides
//! ASCII by a first line starting with `solid ` (so the many binary files whose header
//! starts that way are misread as ASCII, and an ASCII `solid` without a name is refused),
//! never compares the binary triangle count with the input's length (a wrong count reads
//! as an I/O end-of-file error), reports every problem as an `std::io::Error` with no
//! line or byte offset, and stores `f32` only. The format is small enough that a reader
//! with the crate's located errors and allocation rules is shorter than the adaptation
//! around `stl_io` would be.

use std::hash::BuildHasher;
use std::io::Write;

use super::error::{token_string, ReadError, ReadErrorKind as K, WriteError};
use super::input::Input;
use super::text::{is_space, parse_f64};
use crate::mesh::{Mesh, TriMesh};

/// Bytes before the binary payload: the 80-byte header and the `u32` triangle count.
const PAYLOAD_START: usize = 84;
/// Bytes per binary triangle: 12 `f32` (normal, three corners) and a `u16` attribute count.
const TRIANGLE_BYTES: usize = 50;
/// How many leading bytes must be text for a `solid` file to be read as ASCII.
const TEXT_PROBE: usize = 512;
const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";
/// The header of the files written here (padded with spaces to 80 bytes).
const WRITE_HEADER: &[u8] = b"binary STL written by contractible";

/// Welds triangle corners by bitwise-equal position while the triangles are read.
///
/// Vertex ids are given in order of first appearance, so the output does not depend on
/// the hash (whose seed is random, so that a file cannot be made to collide). Two
/// levels:
/// - a direct-mapped cache of recent lookups, which answers most corners: in a mesh's own
///   triangle order a vertex's triangles are near each other in the file (on B0, 10.2 M
///   of 12.6 M corners);
/// - an open-addressing table (linear probing) of the ids, each beside the high half of
///   its position's hash, so that a probe reads positions only on a likely match.
///
/// Why not `hashbrown` (which this reader used, with the same cache in front): a new
/// vertex has to be looked up before it is known to be new, and on a large mesh each
/// such lookup is a cache miss that the processor waits for (three quarters of the
/// welding time on B0). The table here can be warmed: [`Welder::prepare`] computes the
/// hashes of a run of triangles and loads the table slots of the corners the cache will
/// not answer, all independent loads that the processor overlaps, before
/// [`Welder::vertex_hashed`] welds them in order (`docs/benchmarks.md`, readers).
struct Welder {
    /// `(hash >> 32) << 32 | id` per slot, or [`EMPTY`]; a power-of-two length, at
    /// most half full.
    slots: Vec<u64>,
    hasher: foldhash::fast::RandomState,
    /// `recent[h >> recent_shift]` = (hash, id) of the last vertex looked up whose hash
    /// `h` maps there: a hint, confirmed by comparing positions (so the initial zeros
    /// need no sentinel). As long as the table, up to 2^[`RECENT_BITS`] slots, so that
    /// a small file does not allocate and clear 256 KiB.
    recent: Vec<(u64, u32)>,
    /// 64 less log2 of `recent`'s length.
    recent_shift: u32,
    positions: Vec<[f64; 3]>,
    faces: Vec<[u32; 3]>,
    /// The hashes [`Welder::prepare`] computed, one per corner, in file order.
    hashes: Vec<u64>,
}

/// A free slot of [`Welder::slots`]: id `u32::MAX`, which no vertex has (ids stop one
/// below it).
const EMPTY: u64 = u64::MAX;

/// log2 of the largest number of recent-lookup slots: 2^14 × 16 bytes stay in a core's
/// L2 cache.
const RECENT_BITS: u32 = 14;

/// Triangles [`Welder::prepare`] warms at once: their table slots (about one corner in
/// five misses the cache) stay in the L1 and L2 caches until they are welded.
const PREPARE_TRIANGLES: usize = 256;

/// The bits of a position the welder compares.
fn bits(p: &[f64; 3]) -> [u64; 3] {
    p.map(f64::to_bits)
}

impl Welder {
    /// Room for `triangles` faces (a count already checked against the input's size).
    fn with_capacity(triangles: usize) -> Self {
        // A closed triangle mesh has about half as many vertices as faces.
        let vertices = triangles / 2 + 3;
        let slots = Self::slots_for(vertices);
        let recent_bits = Self::recent_bits(slots);
        Welder {
            slots: vec![EMPTY; slots],
            hasher: foldhash::fast::RandomState::default(),
            recent: vec![(0, 0); 1 << recent_bits],
            recent_shift: 64 - recent_bits,
            positions: Vec::with_capacity(vertices),
            faces: Vec::with_capacity(triangles),
            hashes: Vec::new(),
        }
    }

    /// The table length for `vertices` ids: a power of two at least twice as large.
    fn slots_for(vertices: usize) -> usize {
        vertices.saturating_mul(2).max(16).next_power_of_two()
    }

    /// log2 of the recent-lookup cache's length beside a table of `slots` slots (a power
    /// of two): as many, up to 2^[`RECENT_BITS`].
    fn recent_bits(slots: usize) -> u32 {
        slots.trailing_zeros().min(RECENT_BITS)
    }

    fn hash(&self, key: [u64; 3]) -> u64 {
        self.hasher.hash_one((key[0], key[1], key[2]))
    }

    /// The vertex at position `p` (a new one at its first appearance); `None` when a new
    /// vertex would not be addressable by a `u32`.
    fn vertex(&mut self, p: [f64; 3]) -> Option<u32> {
        let h = self.hash(bits(&p));
        self.vertex_hashed(p, h)
    }

    /// [`Welder::vertex`] with the hash of `p` already computed.
    fn vertex_hashed(&mut self, p: [f64; 3], h: u64) -> Option<u32> {
        let key = bits(&p);
        let slot = (h >> self.recent_shift) as usize;
        let same =
            |positions: &[[f64; 3]], v: u32| positions.get(v as usize).map(bits) == Some(key);
        let (seen, v) = self.recent[slot];
        if seen == h && same(&self.positions, v) {
            return Some(v);
        }
        let mask = self.slots.len() - 1;
        let tag = h >> 32;
        let mut i = h as usize & mask;
        let v = loop {
            let s = self.slots[i];
            if s == EMPTY {
                let v = u32::try_from(self.positions.len())
                    .ok()
                    .filter(|&v| v != u32::MAX)?;
                self.positions.push(p);
                if 2 * self.positions.len() > self.slots.len() {
                    self.grow();
                } else {
                    self.slots[i] = tag << 32 | u64::from(v);
                }
                break v;
            }
            if s >> 32 == tag && same(&self.positions, s as u32) {
                break s as u32;
            }
            i = (i + 1) & mask;
        };
        // The cache may have grown with the table since `slot` was computed.
        self.recent[(h >> self.recent_shift) as usize] = (h, v);
        Some(v)
    }

    /// Doubles the table and places every vertex again (the new one included).
    fn grow(&mut self) {
        let len = Self::slots_for(self.positions.len());
        let mut slots = vec![EMPTY; len];
        for (v, p) in self.positions.iter().enumerate() {
            let h = self.hash(bits(p));
            let mut i = h as usize & (len - 1);
            while slots[i] != EMPTY {
                i = (i + 1) & (len - 1);
            }
            slots[i] = (h >> 32) << 32 | v as u64;
        }
        self.slots = slots;
        let recent_bits = Self::recent_bits(len);
        if recent_bits != 64 - self.recent_shift {
            // Hints only: a fresh cache forgets nothing that matters.
            self.recent = vec![(0, 0); 1 << recent_bits];
            self.recent_shift = 64 - recent_bits;
        }
    }

    /// Computes the hashes of the corners of `triangles` (binary STL records) into
    /// [`Welder::hashes`] and loads the table slot of each corner the recent-lookup
    /// cache does not hold, so that welding them next finds those slots in cache. Reads
    /// every corner's bits as they are (a non-finite one is reported by the caller when
    /// it welds it).
    fn prepare(&mut self, triangles: &[u8]) {
        self.hashes.clear();
        for t in triangles.chunks_exact(TRIANGLE_BYTES) {
            for k in 0..3 {
                let h = self.hash(bits(&binary_corner(t, k)));
                self.hashes.push(h);
            }
        }
        let mask = self.slots.len() - 1;
        let mut touched = 0u64;
        for &h in &self.hashes {
            if self.recent[(h >> self.recent_shift) as usize].0 != h {
                touched ^= self.slots[h as usize & mask];
            }
        }
        // The loads are the point: keep them.
        std::hint::black_box(touched);
    }

    fn finish(self) -> TriMesh {
        Mesh::with_positions(self.positions, self.faces)
    }
}

/// Corner `k` of a binary STL triangle record `t` (50 bytes: the normal, then the
/// corners), as `f64` (exact: every `f32` is an `f64`).
fn binary_corner(t: &[u8], k: usize) -> [f64; 3] {
    let mut p = [0.0f64; 3];
    for (j, c) in p.iter_mut().enumerate() {
        let o = 12 + 12 * k + 4 * j;
        *c = f64::from(f32::from_le_bytes([t[o], t[o + 1], t[o + 2], t[o + 3]]));
    }
    p
}

fn too_many_vertices(count: usize) -> K {
    K::CountTooLarge {
        what: "distinct STL vertices",
        declared: count as u64 + 1,
    }
}

/// Whether `len`, the input's length, is exactly that of a binary STL with the count at
/// bytes 80..84 of `head` (`false` when the length is unknown).
fn binary_size_matches(head: &[u8], len: Option<u64>) -> bool {
    match (head.get(80..PAYLOAD_START), len) {
        (Some(&[a, b, c, d]), Some(len)) => {
            let n = u64::from(u32::from_le_bytes([a, b, c, d]));
            len - PAYLOAD_START as u64 == n * TRIANGLE_BYTES as u64
        }
        _ => false,
    }
}

/// The most a deflate stream expands: a 258-byte match coded in two bits gives 1,032
/// bytes out per byte in, and gzip's header and trailer only lower the ratio (each member
/// of a multi-member file is bounded alike).
const MAX_INFLATE_RATIO: u64 = 1032;

/// Whether gzip content of `packed` compressed bytes, starting with `head` (its first
/// bytes, decompressed), may be a binary STL whose length matches its count: the binary
/// size the count at bytes 80..84 asks for is within what `packed` bytes can inflate to.
/// False says for certain that the length cannot decide, so it need not be measured.
pub(crate) fn binary_size_possible(head: &[u8], packed: u64) -> bool {
    match head.get(80..PAYLOAD_START) {
        Some(&[a, b, c, d]) => {
            let n = u64::from(u32::from_le_bytes([a, b, c, d]));
            PAYLOAD_START as u64 + n * TRIANGLE_BYTES as u64
                <= packed.saturating_mul(MAX_INFLATE_RATIO)
        }
        _ => false,
    }
}

/// The content after an optional UTF-8 BOM and leading whitespace.
fn text_start(bytes: &[u8]) -> &[u8] {
    let b = bytes.strip_prefix(UTF8_BOM).unwrap_or(bytes);
    let skip = b
        .iter()
        .position(|&c| !(is_space(c) || c == b'\n'))
        .unwrap_or(b.len());
    &b[skip..]
}

/// Whether `head` (the start of the input, see [`probe`]) starts with the keyword `solid`
/// (case-insensitive, followed by whitespace or the end).
fn starts_with_solid(head: &[u8]) -> bool {
    let b = text_start(head);
    b.get(..5).is_some_and(|k| k.eq_ignore_ascii_case(b"solid"))
        && b.get(5).is_none_or(|&c| is_space(c) || c == b'\n')
}

/// Whether the content is to be read as ASCII STL (see the module docs): `head` is the
/// start of the input ([`probe`]), `len` its length when known.
fn is_ascii(head: &[u8], len: Option<u64>) -> bool {
    starts_with_solid(head)
        && !binary_size_matches(head, len)
        && head
            .iter()
            .take(TEXT_PROBE)
            .all(|&c| c >= 0x20 || is_space(c) || c == b'\n')
}

/// The start of the input the STL decisions look at: the first [`TEXT_PROBE`] bytes, or
/// more while they are only a BOM and whitespace (so that `solid` after a long run of
/// blank lines is still found; at most [`super::MAX_LINE`] bytes).
pub(crate) fn probe<'a>(input: &'a mut Input<'_>) -> Result<&'a [u8], ReadError> {
    let mut want = TEXT_PROBE.max(PAYLOAD_START + 6);
    loop {
        let head = input.peek(want)?;
        if head.len() < want || !text_start(head).is_empty() || want >= super::MAX_LINE {
            break;
        }
        want *= 4;
    }
    input.peek(want)
}

/// Whether the content looks like STL: a binary file of consistent size, or ASCII
/// (`head` as [`is_ascii`] takes it).
pub(crate) fn sniff(head: &[u8], len: Option<u64>) -> bool {
    binary_size_matches(head, len) || is_ascii(head, len)
}

/// Parses STL (binary or ASCII, decided as the module docs say) into a welded triangle
/// mesh.
pub(crate) fn parse_stl(input: &mut Input<'_>) -> Result<TriMesh, ReadError> {
    let len = input.known_len();
    if is_ascii(probe(input)?, len) {
        if input.peek(UTF8_BOM.len())? == UTF8_BOM {
            input.consume(UTF8_BOM.len());
        }
        parse_ascii(input)
    } else {
        parse_binary(input)
    }
}

/// The length check of a binary STL of `len` bytes declaring `declared` triangles: the
/// error for a payload that is not exactly `declared` triangles.
fn binary_length_error(declared: u64, len: u64) -> Option<ReadError> {
    let payload = len.saturating_sub(PAYLOAD_START as u64);
    let per = TRIANGLE_BYTES as u64;
    let whole = payload / per;
    if whole < declared {
        return Some(if payload % per != 0 {
            ReadError::new(
                K::Truncated {
                    expected: format!(
                        "triangle {whole} of {declared} ({TRIANGLE_BYTES} bytes), found {} bytes",
                        payload % per
                    ),
                },
                super::Location::ByteOffset(PAYLOAD_START as u64 + whole * per),
            )
        } else {
            ReadError::at_byte(
                K::CountMismatch {
                    what: "triangles",
                    declared,
                    found: whole,
                },
                80,
            )
        });
    }
    (payload > declared * per).then(|| {
        ReadError::new(
            K::TrailingData { what: "triangle" },
            super::Location::ByteOffset(PAYLOAD_START as u64 + declared * per),
        )
    })
}

/// Reads the rest of `input` without storing it, then makes the length check of a binary
/// STL declaring `declared` triangles on the length read. A stream of unknown length
/// reports a wrong length this way, as the in-memory reader does before reading, in
/// preference to an error met on the way.
fn drained_length_error(
    input: &mut Input<'_>,
    declared: u64,
) -> Result<Option<ReadError>, ReadError> {
    input.drain()?;
    Ok(binary_length_error(declared, input.offset()))
}

fn parse_binary(input: &mut Input<'_>) -> Result<TriMesh, ReadError> {
    let head = input.peek(PAYLOAD_START)?;
    let Some(&[a, b, c, d]) = head.get(80..PAYLOAD_START) else {
        return Err(ReadError::at_byte(
            K::Truncated {
                expected: "an 80-byte header and a 4-byte triangle count (binary STL)".into(),
            },
            head.len(),
        ));
    };
    let declared = u64::from(u32::from_le_bytes([a, b, c, d]));
    // With the length known, the count is checked against it before anything is
    // reserved; otherwise the same checks are made when the input ends, and an error met
    // on the way (a non-finite coordinate) is reported only if the length is right, so
    // that both ways give the same error.
    if let Some(e) = input
        .known_len()
        .and_then(|len| binary_length_error(declared, len))
    {
        return Err(e);
    }
    if let Some(k) = K::past_face_limit("triangles", declared) {
        // Without a length the stream is read to its end, storing nothing, so that a
        // wrong length is reported as it is from memory.
        if input.known_len().is_none() {
            if let Some(e) = drained_length_error(input, declared)? {
                return Err(e);
            }
        }
        return Err(ReadError::at_byte(k, 80));
    }
    input.consume(PAYLOAD_START);
    match read_triangles(input, declared) {
        Ok(mesh) => Ok(mesh),
        Err(e) if input.known_len().is_some() => Err(e),
        Err(e) => Err(drained_length_error(input, declared)?.unwrap_or(e)),
    }
}

/// Reads content that no header names, from a stream of unknown length, as binary STL:
/// the mesh when its length matches the triangle count (what [`sniff`] would have decided
/// with the length known), `UnknownFormat` when it does not, and a binary error (a
/// non-finite coordinate...) only when the length matches.
pub(crate) fn parse_unsniffed(input: &mut Input<'_>) -> Result<TriMesh, ReadError> {
    let unknown = || ReadError::new(K::UnknownFormat, super::Location::Unknown);
    let head = input.peek(PAYLOAD_START)?;
    let Some(&[a, b, c, d]) = head.get(80..PAYLOAD_START) else {
        return Err(unknown());
    };
    let declared = u64::from(u32::from_le_bytes([a, b, c, d]));
    input.consume(PAYLOAD_START);
    match read_triangles(input, declared) {
        Ok(mesh) => Ok(mesh),
        Err(e) => match drained_length_error(input, declared)? {
            None => Err(e),
            Some(_) => Err(unknown()),
        },
    }
}

/// Reads `declared` binary triangles from the payload start, then checks that nothing
/// follows them.
fn read_triangles(input: &mut Input<'_>, declared: u64) -> Result<TriMesh, ReadError> {
    let mut welder = Welder::with_capacity(input.reserve_for(declared, TRIANGLE_BYTES as u64));
    let mut done = 0u64;
    while done < declared {
        let base = input.offset();
        let batch = input.fill_at_least(TRIANGLE_BYTES)?;
        if batch.len() < TRIANGLE_BYTES {
            return Err(drained_length_error(input, declared)?.unwrap_or_else(|| {
                ReadError::at_byte(
                    K::Truncated {
                        expected: "a whole triangle".into(),
                    },
                    base as usize,
                )
            }));
        }
        let take = (batch.len() / TRIANGLE_BYTES)
            .min(usize::try_from(declared - done).unwrap_or(usize::MAX));
        for (r, run) in batch[..take * TRIANGLE_BYTES]
            .chunks(PREPARE_TRIANGLES * TRIANGLE_BYTES)
            .enumerate()
        {
            welder.prepare(run);
            for (i, t) in run.chunks_exact(TRIANGLE_BYTES).enumerate() {
                let at = base + ((r * PREPARE_TRIANGLES + i) * TRIANGLE_BYTES) as u64;
                let mut face = [0u32; 3];
                for (k, slot) in face.iter_mut().enumerate() {
                    // Decoded again rather than kept by `prepare`: the record is in L1, and
                    // keeping 32 bytes a corner measured slower (289 / 286 ms against
                    // 266 / 276 ms on B0, alternating).
                    let p = binary_corner(t, k);
                    if let Some(j) = p.iter().position(|x| !x.is_finite()) {
                        // Corners start after the 12-byte normal.
                        let o = 12 + 12 * k + 4 * j;
                        return Err(ReadError::new(
                            K::BadNumber {
                                token: (p[j] as f32).to_string(),
                            },
                            super::Location::ByteOffset(at + o as u64),
                        ));
                    }
                    let h = welder.hashes[3 * i + k];
                    *slot = welder.vertex_hashed(p, h).ok_or_else(|| {
                        ReadError::new(
                            too_many_vertices(welder.positions.len()),
                            super::Location::ByteOffset(at),
                        )
                    })?;
                }
                welder.faces.push(face);
            }
        }
        input.consume(take * TRIANGLE_BYTES);
        done += take as u64;
    }
    if !input.at_end()? {
        let at = input.offset();
        return Err(drained_length_error(input, declared)?.unwrap_or_else(|| {
            ReadError::new(
                K::TrailingData { what: "triangle" },
                super::Location::ByteOffset(at),
            )
        }));
    }
    Ok(welder.finish())
}

/// Whitespace-separated tokens across lines, each with its 1-based line.
struct TokenStream<'i, 'r> {
    input: &'i mut Input<'r>,
}

impl TokenStream<'_, '_> {
    fn next(&mut self) -> Result<Option<(usize, &[u8])>, ReadError> {
        self.input.next_token()
    }

    /// Drops the rest of the current line (a solid's name).
    fn skip_line(&mut self) {
        self.input.skip_token_line();
    }

    /// The last line read (1 at least), where an unexpected end is reported.
    fn last_line(&self) -> usize {
        self.input.token_line().max(1)
    }

    /// The next token, which must be the keyword `kw` (case-insensitive).
    fn expect(&mut self, kw: &'static str) -> Result<usize, ReadError> {
        match self.input.next_token_span()? {
            Some((n, s, e)) => {
                let t = self.input.bytes(s, e);
                if t.eq_ignore_ascii_case(kw.as_bytes()) {
                    Ok(n)
                } else {
                    Err(ReadError::at_line(
                        K::Stl(format!("expected `{kw}`, found {:?}", token_string(t))),
                        n,
                    ))
                }
            }
            None => Err(ReadError::at_line(
                K::Truncated {
                    expected: format!("`{kw}`"),
                },
                self.last_line(),
            )),
        }
    }

    /// The next token, which must exist (`what` names it in the error).
    fn value(&mut self, what: &'static str) -> Result<(usize, &[u8]), ReadError> {
        match self.input.next_token_span()? {
            Some((n, s, e)) => Ok((n, self.input.bytes(s, e))),
            None => Err(ReadError::at_line(
                K::Truncated {
                    expected: what.into(),
                },
                self.last_line(),
            )),
        }
    }
}

fn is_kw(t: &[u8], kw: &str) -> bool {
    t.eq_ignore_ascii_case(kw.as_bytes())
}

fn parse_ascii(input: &mut Input<'_>) -> Result<TriMesh, ReadError> {
    let mut ts = TokenStream { input };
    ts.expect("solid")?;
    ts.skip_line();
    let mut welder = Welder::with_capacity(0);
    loop {
        let (n, t) = ts.value("`facet` or `endsolid`")?;
        if is_kw(t, "endsolid") {
            ts.skip_line();
            match ts.next()? {
                None => break,
                Some((_, t)) if is_kw(t, "solid") => {
                    ts.skip_line();
                    continue;
                }
                Some((n, _)) => {
                    return Err(ReadError::at_line(K::TrailingData { what: "solid" }, n));
                }
            }
        }
        if !is_kw(t, "facet") {
            return Err(ReadError::at_line(
                K::Stl(format!(
                    "expected `facet` or `endsolid`, found {:?}",
                    token_string(t)
                )),
                n,
            ));
        }
        let face_no = welder.faces.len();
        if let Some(k) = K::past_face_limit("triangles", face_no as u64 + 1) {
            return Err(ReadError::at_line(k, n));
        }
        ts.expect("normal")?;
        // The normal is ignored (its three values must be present).
        for _ in 0..3 {
            ts.value("a normal component")?;
        }
        ts.expect("outer")?;
        ts.expect("loop")?;
        let mut face = [0u32; 3];
        let mut corners = 0u64;
        let end_line = loop {
            let (n, t) = ts.value("`vertex` or `endloop`")?;
            if is_kw(t, "endloop") {
                break n;
            }
            if !is_kw(t, "vertex") {
                return Err(ReadError::at_line(
                    K::Stl(format!(
                        "expected `vertex` or `endloop`, found {:?}",
                        token_string(t)
                    )),
                    n,
                ));
            }
            let mut p = [0.0f64; 3];
            for (c, name) in p
                .iter_mut()
                .zip(["x coordinate", "y coordinate", "z coordinate"])
            {
                let (n, tok) = ts.value(name)?;
                *c = parse_f64(tok).ok_or_else(|| {
                    ReadError::at_line(
                        K::BadNumber {
                            token: token_string(tok),
                        },
                        n,
                    )
                })?;
            }
            if let Some(slot) = usize::try_from(corners).ok().and_then(|i| face.get_mut(i)) {
                *slot = welder.vertex(p).ok_or_else(|| {
                    ReadError::at_line(too_many_vertices(welder.positions.len()), n)
                })?;
            }
            corners += 1;
        };
        if corners != 3 {
            return Err(ReadError::at_line(
                K::NonTriangleFace {
                    face: face_no,
                    corners,
                },
                end_line,
            ));
        }
        ts.expect("endfacet")?;
        welder.faces.push(face);
    }
    Ok(welder.finish())
}

/// What makes `mesh` impossible to write as STL, if anything (checked before writing).
pub(crate) fn unrepresentable<const N: usize>(mesh: &Mesh<N>) -> Option<String> {
    if N != 3 {
        return Some(format!(
            "STL holds triangles only, this mesh has {N}-corner faces"
        ));
    }
    let Some(p) = &mesh.positions else {
        return Some(
            "STL stores triangles by their corner positions and this mesh has none".into(),
        );
    };
    if u32::try_from(mesh.faces.len()).is_err() {
        return Some(format!(
            "{} faces exceed the binary STL count (u32)",
            mesh.faces.len()
        ));
    }
    if let Some(v) = p
        .iter()
        .position(|q| q.iter().any(|&x| !(x as f32).is_finite()))
    {
        return Some(format!("vertex {v} has a coordinate beyond the f32 range"));
    }
    None
}

/// Writes binary little-endian STL (see the module docs). The mesh must pass
/// [`super::check_mesh`]; anything STL cannot hold is refused before the first byte.
pub(crate) fn write_stl<const N: usize>(
    w: &mut impl Write,
    mesh: &Mesh<N>,
) -> Result<(), WriteError> {
    if let Some(reason) = unrepresentable(mesh) {
        return Err(WriteError::Unrepresentable {
            format: "STL",
            reason,
        });
    }
    let (Some(positions), Ok(count)) = (&mesh.positions, u32::try_from(mesh.faces.len())) else {
        // Excluded by `unrepresentable`.
        return Err(WriteError::Unrepresentable {
            format: "STL",
            reason: "no positions or too many faces".into(),
        });
    };
    let mut header = [b' '; 80];
    header[..WRITE_HEADER.len()].copy_from_slice(WRITE_HEADER);
    w.write_all(&header)?;
    w.write_all(&count.to_le_bytes())?;
    let mut rec = [0u8; TRIANGLE_BYTES];
    for f in &mesh.faces {
        let mut corners = [[0.0f64; 3]; 3];
        for (c, &v) in corners.iter_mut().zip(f.iter()) {
            // `check_mesh` guarantees every index is in range.
            *c = positions.get(v as usize).copied().unwrap_or_default();
        }
        let normal = unit_normal(&corners);
        let values = normal.iter().chain(corners.iter().flatten());
        for (i, &x) in values.enumerate() {
            rec[4 * i..4 * i + 4].copy_from_slice(&(x as f32).to_le_bytes());
        }
        // rec[48..50]: attribute byte count, zero.
        w.write_all(&rec)?;
    }
    Ok(())
}

/// The unit normal of a triangle (right-hand rule), or zero when it has no area.
fn unit_normal([a, b, c]: &[[f64; 3]; 3]) -> [f64; 3] {
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 && len.is_finite() {
        n.map(|x| x / len)
    } else {
        [0.0; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_stl(bytes: &[u8]) -> Result<TriMesh, ReadError> {
        super::parse_stl(&mut Input::from_slice(bytes))
    }

    fn sniff(bytes: &[u8]) -> bool {
        let mut input = Input::from_slice(bytes);
        let len = input.known_len();
        super::sniff(probe(&mut input).unwrap(), len)
    }
    use crate::io::Location;

    /// A binary STL of `tris` (corner positions), with `count` in the header.
    fn binary(tris: &[[[f32; 3]; 3]], count: u32) -> Vec<u8> {
        let mut b = b"solid but binary".to_vec();
        b.resize(80, 0);
        b.extend_from_slice(&count.to_le_bytes());
        for t in tris {
            b.extend_from_slice(&[0u8; 12]);
            for c in t.iter().flatten() {
                b.extend_from_slice(&c.to_le_bytes());
            }
            b.extend_from_slice(&[0, 0]);
        }
        b
    }

    const TETRA: [[[f32; 3]; 3]; 4] = [
        [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]],
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]],
        [[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
        [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
    ];

    fn ascii(tris: &[[[f32; 3]; 3]]) -> String {
        let mut s = String::from("solid tetra\n");
        for t in tris {
            s.push_str("  facet normal 0 0 0\n    outer loop\n");
            for [x, y, z] in t {
                s.push_str(&format!("      vertex {x} {y} {z}\n"));
            }
            s.push_str("    endloop\n  endfacet\n");
        }
        s.push_str("endsolid tetra\n");
        s
    }

    fn err(bytes: &[u8]) -> ReadError {
        match parse_stl(bytes) {
            Ok(m) => panic!("accepted: {m:?}"),
            Err(e) => e,
        }
    }

    /// The first pass over gzip content is needed exactly when the count's binary size
    /// is within 1,032 times the compressed size: at the bound and not one byte beyond.
    #[test]
    fn gzip_length_is_measured_only_when_the_count_could_match() {
        let head = |count: [u8; 4]| {
            let mut h = vec![b' '; 80];
            h.extend_from_slice(&count);
            h
        };
        // Eight triangles: 484 bytes, within any compressed size but none.
        let eight = head(8u32.to_le_bytes());
        assert!(binary_size_possible(&eight, 1));
        assert!(!binary_size_possible(&eight, 0));
        assert!(!binary_size_possible(&eight[..83], 1000));
        // Text in bytes 80..84 asks for gigabytes.
        let text = head(*b"0 0 ");
        let size = 84 + 50 * u64::from(u32::from_le_bytes(*b"0 0 "));
        let packed = size.div_ceil(1032);
        assert!(binary_size_possible(&text, packed));
        assert!(!binary_size_possible(&text, packed - 1));
        assert!(!binary_size_possible(&text, 10 << 20));
        // 246 triangles: 12,384 bytes, exactly 12 times 1,032.
        let exact = head(246u32.to_le_bytes());
        assert!(binary_size_possible(&exact, 12));
        assert!(!binary_size_possible(&exact, 11));
    }

    #[test]
    fn binary_with_solid_header_is_welded() {
        let m = parse_stl(&binary(&TETRA, 4)).unwrap();
        assert_eq!(m.vertex_count, 4);
        assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3], [0, 3, 1], [2, 1, 3]]);
        let p = m.positions.unwrap();
        assert_eq!(p[3], [0.0, 0.0, 1.0]);
    }

    #[test]
    fn ascii_matches_binary() {
        let a = parse_stl(ascii(&TETRA).as_bytes()).unwrap();
        assert_eq!(a, parse_stl(&binary(&TETRA, 4)).unwrap());
        // Keywords in any case, split over lines, two solids, BOM, no name.
        let text = "\u{feff}SOLID\nfacet normal 0 0 1 outer loop vertex 0 0 0\nvertex 1 0 0 vertex 0 1 0 endloop\nendfacet ENDSOLID\nsolid b\nfacet normal nan nan nan outer loop vertex 0 0 0 vertex 0 1 0 vertex 0 0 1 endloop endfacet\nendsolid b\n";
        let m = parse_stl(text.as_bytes()).unwrap();
        assert_eq!(m.vertex_count, 4);
        assert_eq!(m.faces, vec![[0, 1, 2], [0, 2, 3]]);
    }

    #[test]
    fn binary_count_checked_against_length() {
        let good = binary(&TETRA, 4);
        // Cut inside triangle 2.
        let e = err(&good[..84 + 2 * 50 + 7]);
        assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
        assert_eq!(e.location, Location::ByteOffset(184));
        // A whole number of triangles, fewer than declared; a count of u32::MAX on a tiny
        // input must not allocate.
        for count in [5, u32::MAX] {
            let e = err(&binary(&TETRA, count));
            assert!(
                matches!(e.kind, K::CountMismatch { declared, found: 4, .. } if declared == u64::from(count)),
                "{e}"
            );
            assert_eq!(e.location, Location::ByteOffset(80));
        }
        // More bytes than declared.
        let e = err(&binary(&TETRA, 3));
        assert!(matches!(e.kind, K::TrailingData { .. }), "{e}");
        assert_eq!(e.location, Location::ByteOffset(84 + 150));
        // Shorter than the header.
        let e = err(&good[..50]);
        assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
        assert_eq!(e.location, Location::ByteOffset(50));
    }

    #[test]
    fn non_finite_coordinates_are_located() {
        let mut t = TETRA;
        t[1][2][1] = f32::NAN;
        let e = err(&binary(&t, 4));
        assert!(matches!(e.kind, K::BadNumber { .. }), "{e}");
        // Triangle 1, corner 2, y: 84 + 50 + 12 + 24 + 4.
        assert_eq!(e.location, Location::ByteOffset(84 + 50 + 40));
        let text = ascii(&TETRA).replacen("vertex 1 0 0", "vertex 1 inf 0", 1);
        let e = err(text.as_bytes());
        assert!(matches!(e.kind, K::BadNumber { .. }), "{e}");
        // solid, facet, outer loop, vertex 0 0 0, vertex 0 1 0, then this one.
        assert_eq!(e.location, Location::Line(6));
        // Past the first runs the welder prepares at once, from memory and streamed.
        let mut many: Vec<[[f32; 3]; 3]> = TETRA.iter().copied().cycle().take(700).collect();
        many[555][1][2] = f32::INFINITY;
        let bytes = binary(&many, 700);
        let streamed = super::parse_stl(&mut Input::new(
            Box::new(std::io::Cursor::new(bytes.clone())),
            false,
            None,
        ));
        for e in [err(&bytes), streamed.unwrap_err()] {
            assert!(matches!(e.kind, K::BadNumber { .. }), "{e}");
            // Triangle 555, corner 1, z: 84 + 555 · 50 + 12 + 12 + 8.
            assert_eq!(e.location, Location::ByteOffset(84 + 555 * 50 + 32));
        }
    }

    #[test]
    fn ascii_errors_are_located() {
        let full = ascii(&TETRA);
        let lines: Vec<&str> = full.lines().collect();
        // Cut after the second facet: `endsolid` missing.
        let cut = lines[..15].join("\n");
        let e = err(cut.as_bytes());
        assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
        assert_eq!(e.location, Location::Line(15));
        // A quad loop.
        let quad = full.replacen("    endloop", "      vertex 5 5 5\n    endloop", 1);
        let e = err(quad.as_bytes());
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
        assert_eq!(e.location, Location::Line(8));
        // A misspelt keyword, a missing coordinate, trailing data.
        let e = err(full.replacen("outer loop", "outer lop", 1).as_bytes());
        assert!(matches!(e.kind, K::Stl(_)), "{e}");
        assert_eq!(e.location, Location::Line(3));
        let e = err(full.replacen("vertex 0 1 0", "vertex 0 1", 1).as_bytes());
        assert!(matches!(e.kind, K::BadNumber { .. }), "{e}");
        let e = err(format!("{full}junk\n").as_bytes());
        assert!(matches!(e.kind, K::TrailingData { .. }), "{e}");
        assert_eq!(e.location, Location::Line(lines.len() + 1));
    }

    #[test]
    fn degenerate_triangle_keeps_its_repeated_vertex() {
        let mut t = TETRA.to_vec();
        t.push([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]);
        let m = parse_stl(&binary(&t, 5)).unwrap();
        assert_eq!(m.faces[4], [0, 0, 2]);
    }

    #[test]
    fn written_binary_reads_back() {
        let m = parse_stl(&binary(&TETRA, 4)).unwrap();
        let mut out = Vec::new();
        write_stl(&mut out, &m).unwrap();
        assert_eq!(out.len(), 84 + 4 * 50);
        assert!(!out.starts_with(b"solid"));
        assert!(sniff(&out));
        assert_eq!(parse_stl(&out).unwrap(), m);
        // The normal of face 0 (corners (0,0,0), (0,1,0), (1,0,0)) is -z.
        let nz = f32::from_le_bytes([out[92], out[93], out[94], out[95]]);
        assert_eq!(nz, -1.0);
    }

    #[test]
    fn unwritable_meshes_are_refused_before_writing() {
        let mut out = Vec::new();
        let no_pos = TriMesh::combinatorial(3, vec![[0, 1, 2]]);
        assert!(matches!(
            write_stl(&mut out, &no_pos),
            Err(WriteError::Unrepresentable { .. })
        ));
        let quad = Mesh::<4>::with_positions(vec![[0.0; 3]; 4], vec![[0, 1, 2, 3]]);
        assert!(write_stl(&mut out, &quad).is_err());
        let huge =
            TriMesh::with_positions(vec![[1e300, 0.0, 0.0], [0.0; 3], [1.0; 3]], vec![[0, 1, 2]]);
        assert!(write_stl(&mut out, &huge).is_err());
        assert!(out.is_empty());
    }

    #[test]
    fn text_that_is_not_stl_is_not_sniffed() {
        assert!(!sniff(b"OFF\n3 1 0\n"));
        assert!(!sniff(b"solidity 1 2 3"));
        assert!(sniff(b"solid x\nendsolid x\n"));
    }

    /// A closed genus-0 mesh of `F` faces has `F/2 + 2` vertices: the welder's room for
    /// them, one to spare, is never outgrown.
    #[test]
    fn the_welder_holds_a_closed_meshs_vertices_without_growing() {
        // An octahedron and a subdivided one: 8 and 32 faces, 6 and 18 vertices.
        let octa = |r: f64| {
            let v = [
                [r, 0.0, 0.0],
                [-r, 0.0, 0.0],
                [0.0, r, 0.0],
                [0.0, -r, 0.0],
                [0.0, 0.0, r],
                [0.0, 0.0, -r],
            ];
            let mut tris = Vec::new();
            for &x in &[0usize, 1] {
                for &y in &[2usize, 3] {
                    for &z in &[4usize, 5] {
                        tris.push([v[x], v[y], v[z]]);
                    }
                }
            }
            tris
        };
        let mid = |a: [f64; 3], b: [f64; 3]| {
            [
                (a[0] + b[0]) / 2.0,
                (a[1] + b[1]) / 2.0,
                (a[2] + b[2]) / 2.0,
            ]
        };
        let split: Vec<[[f64; 3]; 3]> = octa(1.0)
            .into_iter()
            .flat_map(|[a, b, c]| {
                let (ab, bc, ca) = (mid(a, b), mid(b, c), mid(c, a));
                [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
            })
            .collect();
        for (tris, vertices) in [(octa(1.0), 6), (split, 18)] {
            let mut w = Welder::with_capacity(tris.len());
            let room = w.positions.capacity();
            let slots = w.slots.len();
            assert_eq!(room, vertices + 1);
            for t in &tris {
                let f = t.map(|p| w.vertex(p).unwrap());
                w.faces.push(f);
            }
            assert_eq!(w.positions.len(), vertices);
            assert_eq!(w.positions.capacity(), room);
            assert_eq!(w.slots.len(), slots, "the table did not grow");
            assert!(2 * vertices <= slots);
            assert_eq!(w.faces.capacity(), tris.len());
        }
    }

    /// Welding is by exact bits with ids in order of first appearance: against a naive
    /// map on random triangle soups whose corners are drawn from pools small and large (so
    /// that positions repeat near and far, the recent-lookup cache misses, and the table
    /// grows past its estimate of half as many vertices as triangles), with `0.0` and
    /// `-0.0` apart; read from memory and streamed (batches and prepared runs cut
    /// anywhere).
    #[test]
    fn welding_matches_a_naive_map() {
        let mut rng = crate::rng::Rng::new(7);
        for (triangles, pool) in [(1, 3), (40, 5), (700, 60), (3000, 9000), (3000, 400)] {
            let points: Vec<[f32; 3]> = (0..pool)
                .map(|i| match i {
                    0 => [0.0, 0.0, 0.0],
                    1 => [-0.0, 0.0, 0.0],
                    _ => [(); 3].map(|_| rng.below(40) as f32 * 0.375 - 7.0),
                })
                .collect();
            let tris: Vec<[[f32; 3]; 3]> = (0..triangles)
                .map(|_| [(); 3].map(|_| points[rng.index(pool)]))
                .collect();
            let mut ids = std::collections::HashMap::new();
            let mut positions = Vec::new();
            let faces: Vec<[u32; 3]> = tris
                .iter()
                .map(|t| {
                    t.map(|p| {
                        *ids.entry(p.map(f32::to_bits)).or_insert_with(|| {
                            positions.push(p.map(f64::from));
                            positions.len() as u32 - 1
                        })
                    })
                })
                .collect();
            let bytes = binary(&tris, triangles as u32);
            let streamed = super::parse_stl(&mut Input::new(
                Box::new(std::io::Cursor::new(bytes.clone())),
                false,
                None,
            ));
            for mesh in [parse_stl(&bytes).unwrap(), streamed.unwrap()] {
                assert_eq!(
                    mesh.faces, faces,
                    "{triangles} triangles from {pool} points"
                );
                let got = mesh.positions.unwrap();
                assert_eq!(got.len(), positions.len());
                assert!(got.iter().zip(&positions).all(|(a, b)| bits(a) == bits(b)));
            }
        }
    }

    /// The table grows exactly when it would be more than half full, and keeps every
    /// vertex; positions whose hashes collide entirely (the same hash given for each, as
    /// the table's tag and the recent-lookup cache both see it) stay apart, and are found
    /// again.
    #[test]
    fn the_table_grows_past_half_full_and_tells_colliding_positions_apart() {
        let mut w = Welder::with_capacity(10);
        assert_eq!(w.slots.len(), 16);
        let point = |i: usize| [i as f64, 0.5, -0.0];
        for i in 0..8 {
            assert_eq!(w.vertex(point(i)), Some(i as u32));
        }
        assert_eq!(w.slots.len(), 16, "half full: not grown");
        assert_eq!(w.vertex(point(8)), Some(8));
        assert_eq!(w.slots.len(), 32, "more than half full: grown");
        for i in 0..9 {
            assert_eq!(w.vertex(point(i)), Some(i as u32), "kept across the growth");
        }
        let mut w = Welder::with_capacity(2);
        let h = 0x1234_5678_9abc_def0;
        for round in 0..2 {
            for i in 0..5 {
                assert_eq!(
                    w.vertex_hashed(point(i), h),
                    Some(i as u32),
                    "round {round}"
                );
            }
        }
        assert_eq!(w.positions.len(), 5);
    }

    /// The recent-lookup cache is as long as the table up to 2^14 slots: 16 for a small
    /// file, growing with the table to 2^14 and no further, and 2^14 from the start for
    /// a large declared count; every vertex is found again after each growth.
    #[test]
    fn the_recent_lookup_cache_grows_with_the_table_up_to_its_bound() {
        let mut w = Welder::with_capacity(2);
        assert_eq!((w.recent.len(), w.recent_shift), (16, 60));
        let point = |i: usize| [i as f64, -1.5, 2.0];
        for i in 0..20_000 {
            assert_eq!(w.vertex(point(i)), Some(i as u32));
            let expected = w.slots.len().min(1 << RECENT_BITS);
            assert_eq!(w.recent.len(), expected, "after vertex {i}");
            assert_eq!(1 << (64 - w.recent_shift), expected);
        }
        assert_eq!(w.recent.len(), 1 << RECENT_BITS);
        for i in (0..20_000).rev() {
            assert_eq!(w.vertex(point(i)), Some(i as u32));
        }
        let w = Welder::with_capacity(1_000_000);
        assert_eq!(w.recent.len(), 1 << RECENT_BITS);
    }

    /// The count past the `u32` vertex limit is the one the file needs: every vertex
    /// welded so far and the one that does not fit.
    #[test]
    fn the_vertex_count_past_the_limit_includes_the_one_that_does_not_fit() {
        let limit = u32::MAX as usize + 1;
        assert!(matches!(
            too_many_vertices(limit),
            K::CountTooLarge { what: "distinct STL vertices", declared } if declared == limit as u64 + 1
        ));
    }

    /// `solid` after a byte order mark and blank lines is ASCII STL, also when the blank
    /// lines run past the first look at the input.
    #[test]
    fn solid_after_blank_lines_is_ascii_stl() {
        let text = ascii(&TETRA);
        let want = parse_stl(text.as_bytes()).unwrap();
        for blank in [1, 40, 3000, 200_000] {
            let mut file = UTF8_BOM.to_vec();
            file.extend(" \t\r\n".repeat(blank).bytes());
            file.extend(text.bytes());
            assert!(sniff(&file), "{blank}");
            assert_eq!(parse_stl(&file).unwrap(), want, "{blank}");
        }
    }

    /// From a stream of unknown length, a binary STL whose data runs out early is
    /// reported as from memory: by its length (the stream is read to its end), not by
    /// where the reading stopped.
    #[test]
    fn streams_report_a_short_binary_by_its_length() {
        let stream = |bytes: &[u8]| {
            let owned = bytes.to_vec();
            let mut input = Input::new(Box::new(std::io::Cursor::new(owned)), false, None);
            super::parse_stl(&mut input).unwrap_err()
        };
        let good = binary(&TETRA, 4);
        // A non-finite coordinate in a file of the wrong length: the length comes first.
        let mut nan = TETRA;
        nan[1][2][0] = f32::NAN;
        let nan = binary(&nan, 5);
        for cut in [&binary(&TETRA, 5)[..], &good[..84 + 2 * 50 + 7], &nan[..]] {
            let (from_memory, from_stream) = (err(cut), stream(cut));
            assert_eq!(from_stream.location, from_memory.location);
            assert_eq!(
                std::mem::discriminant(&from_stream.kind),
                std::mem::discriminant(&from_memory.kind),
                "{from_stream} / {from_memory}"
            );
        }
        assert!(matches!(
            stream(&binary(&TETRA, 5)).kind,
            K::CountMismatch { .. }
        ));
        assert!(matches!(stream(&nan).kind, K::CountMismatch { .. }));
    }

    /// A single triangle, and a file read in several buffers whose last batch holds one
    /// triangle more than declared: the count decides where reading stops.
    #[test]
    fn the_declared_count_bounds_every_batch() {
        let one = parse_stl(&binary(&TETRA[..1], 1)).unwrap();
        assert_eq!((one.vertex_count, one.faces.len()), (3, 1));
        let n = 6000;
        let tris: Vec<[[f32; 3]; 3]> = (0..=n)
            .map(|i| {
                let x = i as f32;
                [[x, 0.0, 0.0], [x, 1.0, 0.0], [x, 0.0, 1.0]]
            })
            .collect();
        let file = binary(&tris, n as u32);
        assert!(file.len() > super::super::input::CHUNK);
        // From memory the length decides before reading; from a stream, the batches.
        let mut stream = Input::new(Box::new(std::io::Cursor::new(file.clone())), false, None);
        for e in [err(&file), super::parse_stl(&mut stream).unwrap_err()] {
            assert!(matches!(e.kind, K::TrailingData { .. }), "{e}");
            assert_eq!(e.location, Location::ByteOffset(84 + 50 * n as u64));
        }
        let whole = parse_stl(&file[..file.len() - 50]).unwrap();
        assert_eq!(whole.faces.len(), n);
    }

    /// Written facet normals are the unit normals by the right-hand rule, computed here
    /// from the other corner, and zero for triangles without area or whose normal does
    /// not fit a double.
    #[test]
    fn written_normals_are_unit_right_handed_or_zero() {
        let mut rng = crate::rng::Rng::new(5);
        let mut coord = || (rng.index(2001) as f64 - 1000.0) / 64.0;
        let mut tris: Vec<[[f64; 3]; 3]> = (0..200)
            .map(|_| {
                [
                    [coord(), coord(), coord()],
                    [coord(), coord(), coord()],
                    [coord(), coord(), coord()],
                ]
            })
            .collect();
        tris.push([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]);
        let positions: Vec<[f64; 3]> = tris.iter().flatten().copied().collect();
        let faces: Vec<[u32; 3]> = (0..tris.len() as u32)
            .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
            .collect();
        let mut out = Vec::new();
        write_stl(&mut out, &Mesh::with_positions(positions, faces)).unwrap();
        for (i, [a, b, c]) in tris.iter().enumerate() {
            let at = 84 + 50 * i;
            let n: Vec<f64> = (0..3)
                .map(|k| {
                    let o = at + 4 * k;
                    f64::from(f32::from_le_bytes([
                        out[o],
                        out[o + 1],
                        out[o + 2],
                        out[o + 3],
                    ]))
                })
                .collect();
            // (c - b) × (a - b) is the same normal from corner b.
            let (u, v) = (
                [c[0] - b[0], c[1] - b[1], c[2] - b[2]],
                [a[0] - b[0], a[1] - b[1], a[2] - b[2]],
            );
            let m = [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ];
            let len = m.iter().map(|x| x * x).sum::<f64>().sqrt();
            if i + 1 == tris.len() {
                assert_eq!(n, [0.0; 3], "triangle {i}");
            } else {
                assert!(len > 0.0);
                for k in 0..3 {
                    assert!(
                        (n[k] - m[k] / len).abs() < 1e-6,
                        "triangle {i}: {n:?} {m:?}"
                    );
                }
            }
        }
        // Beyond what `write_stl` accepts (f32 coordinates): a normal too long for a double.
        let huge = [[0.0, 0.0, 0.0], [1e300, 0.0, 0.0], [0.0, 1e300, 0.0]];
        assert_eq!(unit_normal(&huge), [0.0; 3]);
    }
}
