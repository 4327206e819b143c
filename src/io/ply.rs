//! PLY reading (ascii, binary little/big endian) and writing.
//!
//! Why a hand parser rather than `ply-rs-bw` (a dev-dependency, used in the tests as an
//! independent cross-check): its header model is an `IndexMap` keyed by name, so a header
//! that repeats an element or property name is silently collapsed (a repeated element even
//! takes the *earlier* position and later properties attach to the wrong element). For
//! binary files that changes the record layout, and the payload is then misread without an
//! error. Its binary errors also carry only an element ordinal, not a byte offset. (Its
//! preallocation *is* capped, so huge header counts are not an allocation hazard there.)
//! The format is small: this reader rejects duplicate names, bounds every declared count by
//! the bytes actually present before reserving anything, and reports byte offsets (binary)
//! or line numbers (ascii, header).
//!
//! Read: element `vertex` with scalar properties `x`, `y`, `z` (any numeric type; must be
//! finite) and optional element `face` with a list property `vertex_indices` or
//! `vertex_index` of integer type. Every other element and property is parsed and skipped.

use std::collections::HashSet;
use std::io::Write;

use super::error::{token_string, Location, ReadError, ReadErrorKind as K};
use super::fmt_f64_triple;
use super::input::Input;
use super::poly::PolyMesh;
use super::text::{is_space, parse_any_f64, parse_i64, Tokens};
use crate::mesh::Mesh;

/// How a PLY file encodes its payload.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlyEncoding {
    /// Whitespace-separated decimal text.
    Ascii,
    /// Binary, least significant byte first.
    BinaryLittleEndian,
    /// Binary, most significant byte first.
    BinaryBigEndian,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(s: &[u8]) -> Option<Scalar> {
        Some(match s {
            b"char" | b"int8" => Scalar::I8,
            b"uchar" | b"uint8" => Scalar::U8,
            b"short" | b"int16" => Scalar::I16,
            b"ushort" | b"uint16" => Scalar::U16,
            b"int" | b"int32" => Scalar::I32,
            b"uint" | b"uint32" => Scalar::U32,
            b"float" | b"float32" => Scalar::F32,
            b"double" | b"float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    fn is_int(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum PropType {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

/// What a property means to this reader.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    Ignore,
    Coord(usize),
    Corners,
}

#[derive(Debug)]
struct Property {
    name: String,
    ty: PropType,
    role: Role,
}

#[derive(Debug)]
struct Element {
    name: String,
    count: u64,
    kind: ElementKind,
    properties: Vec<Property>,
    line: usize,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum ElementKind {
    Vertex,
    Face,
    Other,
}

struct Header {
    encoding: PlyEncoding,
    elements: Vec<Element>,
    /// Number of header lines (the payload's first line is `lines + 1`).
    lines: usize,
}

/// Most elements and properties one header may declare: far above any real file, low
/// enough that a header cannot make every record's decoding arbitrarily slow or the header
/// model arbitrarily large.
const MAX_HEADER_ITEMS: usize = 1 << 16;

fn bad_header(msg: impl Into<String>, line: usize) -> ReadError {
    ReadError::at_line(K::BadHeader(msg.into()), line)
}

fn parse_header(input: &mut Input<'_>) -> Result<Header, ReadError> {
    match input.next_line()? {
        Some((_, l)) if trim(l) == b"ply" => {}
        _ => return Err(bad_header("missing `ply` magic line", 1)),
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut items = 0usize;
    // Names seen, to refuse repeats in time linear in the header (a scan of the earlier
    // names would cost `MAX_HEADER_ITEMS`² / 2 comparisons, seconds, on a hostile header).
    let mut element_names: HashSet<String> = HashSet::new();
    let mut property_names: HashSet<String> = HashSet::new();
    loop {
        let last = input.line();
        let Some((n, line)) = input.next_line()? else {
            return Err(bad_header("missing `end_header`", last.max(1)));
        };
        let mut t = Tokens::new(line);
        if matches!(t.clone().next(), Some(b"element" | b"property")) {
            items += 1;
            if items > MAX_HEADER_ITEMS {
                return Err(bad_header(
                    format!("more than {MAX_HEADER_ITEMS} elements and properties"),
                    n,
                ));
            }
        }
        match t.next() {
            None => continue,
            Some(b"comment" | b"obj_info") => continue,
            Some(b"end_header") => break,
            Some(b"format") => {
                if encoding.is_some() {
                    return Err(bad_header("repeated `format` line", n));
                }
                let enc = match t.next() {
                    Some(b"ascii") => PlyEncoding::Ascii,
                    Some(b"binary_little_endian") => PlyEncoding::BinaryLittleEndian,
                    Some(b"binary_big_endian") => PlyEncoding::BinaryBigEndian,
                    other => {
                        return Err(bad_header(
                            format!(
                                "unknown PLY format {:?}",
                                token_string(other.unwrap_or_default())
                            ),
                            n,
                        ))
                    }
                };
                if t.next() != Some(b"1.0") {
                    return Err(bad_header("expected version 1.0", n));
                }
                encoding = Some(enc);
            }
            Some(b"element") => {
                let (Some(name), Some(count), None) = (t.next(), t.next(), t.next()) else {
                    return Err(bad_header("expected `element <name> <count>`", n));
                };
                let count = super::text::parse_u64(count).ok_or_else(|| {
                    ReadError::at_line(
                        K::BadNumber {
                            token: token_string(count),
                        },
                        n,
                    )
                })?;
                let name = String::from_utf8_lossy(name).into_owned();
                if !element_names.insert(name.clone()) {
                    return Err(bad_header(format!("element `{name}` declared twice"), n));
                }
                property_names.clear();
                let kind = match name.as_str() {
                    "vertex" => ElementKind::Vertex,
                    "face" => ElementKind::Face,
                    _ => ElementKind::Other,
                };
                elements.push(Element {
                    name,
                    count,
                    kind,
                    properties: Vec::new(),
                    line: n,
                });
            }
            Some(b"property") => {
                let Some(elem) = elements.last_mut() else {
                    return Err(bad_header("`property` before any `element`", n));
                };
                let toks: Vec<&[u8]> = t.collect();
                let scalar = |s: &[u8]| {
                    Scalar::parse(s).ok_or_else(|| {
                        bad_header(format!("unknown property type {:?}", token_string(s)), n)
                    })
                };
                let (ty, name) = match toks.as_slice() {
                    [b"list", c, i, name] => {
                        let count = scalar(c)?;
                        if !count.is_int() {
                            return Err(bad_header("list count type must be an integer", n));
                        }
                        (
                            PropType::List {
                                count,
                                item: scalar(i)?,
                            },
                            name,
                        )
                    }
                    [ty, name] => (PropType::Scalar(scalar(ty)?), name),
                    _ => return Err(bad_header("expected `property <type> <name>`", n)),
                };
                let name = String::from_utf8_lossy(name).into_owned();
                if !property_names.insert(name.clone()) {
                    return Err(bad_header(
                        format!("property `{name}` declared twice in `{}`", elem.name),
                        n,
                    ));
                }
                let role = match (elem.kind, name.as_str(), ty) {
                    (ElementKind::Vertex, "x", PropType::Scalar(_)) => Role::Coord(0),
                    (ElementKind::Vertex, "y", PropType::Scalar(_)) => Role::Coord(1),
                    (ElementKind::Vertex, "z", PropType::Scalar(_)) => Role::Coord(2),
                    (ElementKind::Face, "vertex_indices" | "vertex_index", _) => match ty {
                        PropType::List { item, .. } if item.is_int() => Role::Corners,
                        _ => {
                            return Err(bad_header(
                                format!("`{name}` must be a list of integers"),
                                n,
                            ))
                        }
                    },
                    _ => Role::Ignore,
                };
                if role == Role::Corners && elem.properties.iter().any(|p| p.role == Role::Corners)
                {
                    return Err(bad_header(
                        "both `vertex_indices` and `vertex_index` declared",
                        n,
                    ));
                }
                elem.properties.push(Property { name, ty, role });
            }
            Some(other) => {
                return Err(bad_header(
                    format!("unknown header keyword {:?}", token_string(other)),
                    n,
                ))
            }
        }
    }
    let header_lines = input.line();
    let encoding = encoding.ok_or_else(|| bad_header("missing `format` line", header_lines))?;
    let Some(vertex) = elements.iter().find(|e| e.kind == ElementKind::Vertex) else {
        return Err(bad_header("no `vertex` element", header_lines));
    };
    for c in 0..3 {
        if !vertex.properties.iter().any(|p| p.role == Role::Coord(c)) {
            return Err(bad_header(
                format!("`vertex` has no scalar property `{}`", ["x", "y", "z"][c]),
                vertex.line,
            ));
        }
    }
    if vertex.count > u64::from(u32::MAX) {
        return Err(ReadError::at_line(
            K::CountTooLarge {
                what: "vertices",
                declared: vertex.count,
            },
            vertex.line,
        ));
    }
    if let Some(face) = elements.iter().find(|e| e.kind == ElementKind::Face) {
        // More faces than a triangulation can index (their corners would overflow u32):
        // said here, before any record is read.
        if let Some(k) = K::past_face_limit("faces", face.count) {
            return Err(ReadError::at_line(k, face.line));
        }
        if !face.properties.iter().any(|p| p.role == Role::Corners) {
            return Err(bad_header(
                "`face` has no `vertex_indices` list property",
                face.line,
            ));
        }
    }
    Ok(Header {
        encoding,
        elements,
        lines: header_lines,
    })
}

/// Fewest bytes one property can occupy in `encoding` (face corner lists hold 3 items).
fn min_bytes(encoding: PlyEncoding, p: &Property) -> usize {
    let items = if p.role == Role::Corners { 3 } else { 0 };
    match (encoding, p.ty) {
        // A token plus a separator.
        (PlyEncoding::Ascii, PropType::Scalar(_)) => 2,
        (PlyEncoding::Ascii, PropType::List { .. }) => 2 + 2 * items,
        (_, PropType::Scalar(s)) => s.size(),
        (_, PropType::List { count, item }) => count.size() + items * item.size(),
    }
}

fn trim(s: &[u8]) -> &[u8] {
    let start = s.iter().position(|b| !is_space(*b)).unwrap_or(s.len());
    let end = s
        .iter()
        .rposition(|b| !is_space(*b))
        .map_or(start, |i| i + 1);
    s.get(start..end).unwrap_or_default()
}

/// A numeric value as read from the payload.
#[derive(Clone, Copy)]
enum Value {
    Int(i64),
    Float(f64),
}

impl Value {
    fn as_f64(self) -> f64 {
        match self {
            Value::Int(i) => i as f64,
            Value::Float(f) => f,
        }
    }
}

/// The value of type `s` at the start of `b` (which holds at least its size).
#[inline(always)]
fn decode(b: &[u8], s: Scalar, big_endian: bool) -> Value {
    macro_rules! num {
        ($t:ty, $n:literal) => {{
            let mut a = [0u8; $n];
            a.copy_from_slice(&b[..$n]);
            if big_endian {
                <$t>::from_be_bytes(a)
            } else {
                <$t>::from_le_bytes(a)
            }
        }};
    }
    match s {
        Scalar::I8 => Value::Int(i64::from(b[0] as i8)),
        Scalar::U8 => Value::Int(i64::from(b[0])),
        Scalar::I16 => Value::Int(i64::from(num!(i16, 2))),
        Scalar::U16 => Value::Int(i64::from(num!(u16, 2))),
        Scalar::I32 => Value::Int(i64::from(num!(i32, 4))),
        Scalar::U32 => Value::Int(i64::from(num!(u32, 4))),
        Scalar::F32 => Value::Float(f64::from(num!(f32, 4))),
        Scalar::F64 => Value::Float(num!(f64, 8)),
    }
}

/// The fixed record layout of a binary element, for [`Payload::batch`]: every
/// property a scalar, except in faces one corner list, which has a fixed length when it
/// holds 3 corners. Records of other shapes (polygons, other lists) and records with a
/// problem go through the value-by-value decoder, which gives the located errors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Layout {
    /// A vertex record of `len` bytes, coordinate `c` at `coords[c]` (offset, type).
    Vertex {
        len: usize,
        coords: [(usize, Scalar); 3],
    },
    /// A face record of `len` bytes when its list holds 3 corners: the count at
    /// `count_at`, the corners from `items_at`.
    Face {
        len: usize,
        count_at: usize,
        count: Scalar,
        items_at: usize,
        item: Scalar,
    },
    /// A record of `len` bytes that nothing reads.
    Skip { len: usize },
}

impl Layout {
    /// The layout of `e`'s records when it is fixed (binary encodings only).
    fn of(encoding: PlyEncoding, e: &Element) -> Option<Layout> {
        if encoding == PlyEncoding::Ascii {
            return None;
        }
        let mut at = 0;
        let mut coords = [None; 3];
        let mut list = None;
        for p in &e.properties {
            match (p.ty, p.role) {
                (PropType::Scalar(s), Role::Coord(c)) => {
                    coords[c] = Some((at, s));
                    at += s.size();
                }
                (PropType::Scalar(s), _) => at += s.size(),
                (PropType::List { count, item }, Role::Corners) => {
                    list = Some((at, count, at + count.size(), item));
                    at += count.size() + 3 * item.size();
                }
                (PropType::List { .. }, _) => return None,
            }
        }
        let len = at;
        Some(match (e.kind, list) {
            (ElementKind::Vertex, None) => Layout::Vertex {
                len,
                coords: [coords[0]?, coords[1]?, coords[2]?],
            },
            (ElementKind::Face, Some((count_at, count, items_at, item))) => Layout::Face {
                len,
                count_at,
                count,
                items_at,
                item,
            },
            (ElementKind::Other, None) if len > 0 => Layout::Skip { len },
            _ => return None,
        })
    }

    /// Bytes per record.
    fn len(&self) -> usize {
        match *self {
            Layout::Vertex { len, .. } | Layout::Face { len, .. } | Layout::Skip { len } => len,
        }
    }
}

/// Source of payload values, positioned for error messages.
trait Payload {
    /// Reads one value of type `s`; `what` describes it for truncation errors.
    fn value(&mut self, s: Scalar, what: &dyn Fn() -> String) -> Result<Value, ReadError>;
    /// Where the most recently read value starts.
    fn last(&self) -> Location;
    /// Error unless only whitespace remains.
    fn finish(&mut self) -> Result<(), ReadError>;
    /// How many of `declared` records of at least `min_bytes` each to reserve room for
    /// ([`Input::reserve_for`]).
    fn reserve_for(&self, declared: u64, min_bytes: u64) -> usize;
    /// Decodes up to `max` records of `layout` from the bytes at hand, appending
    /// vertices to `positions` and faces to `mesh` exactly as the value-by-value path
    /// would; stops before the first record that is incomplete, of another shape or
    /// wrong (never consuming it), and returns how many it decoded. By default (text
    /// payloads) it decodes none.
    fn batch(
        &mut self,
        _layout: &Layout,
        _max: u64,
        _nv: usize,
        _positions: &mut Vec<[f64; 3]>,
        _mesh: &mut PolyMesh,
    ) -> Result<u64, ReadError> {
        Ok(0)
    }
}

struct Binary<'i, 'r> {
    input: &'i mut Input<'r>,
    last: u64,
    big_endian: bool,
}

impl Payload for Binary<'_, '_> {
    fn value(&mut self, s: Scalar, what: &dyn Fn() -> String) -> Result<Value, ReadError> {
        let size = s.size();
        let at = self.input.offset();
        let raw = self.input.peek(size)?;
        if raw.len() < size {
            return Err(ReadError::new(
                K::Truncated { expected: what() },
                Location::ByteOffset(at),
            ));
        }
        let v = decode(raw, s, self.big_endian);
        self.input.consume(size);
        self.last = at;
        Ok(v)
    }

    fn batch(
        &mut self,
        layout: &Layout,
        max: u64,
        nv: usize,
        positions: &mut Vec<[f64; 3]>,
        mesh: &mut PolyMesh,
    ) -> Result<u64, ReadError> {
        let big = self.big_endian;
        let base = self.input.offset();
        let buf = self.input.fill_at_least(layout.len())?;
        let (mut at, mut n) = (0usize, 0u64);
        match *layout {
            Layout::Vertex { len, coords } => {
                while n < max {
                    let Some(r) = buf.get(at..at + len) else {
                        break;
                    };
                    let xyz = coords.map(|(o, s)| decode(&r[o..], s, big).as_f64());
                    if !xyz.iter().all(|x| x.is_finite()) {
                        break;
                    }
                    positions.push(xyz);
                    (at, n) = (at + len, n + 1);
                }
            }
            Layout::Face {
                len,
                count_at,
                count,
                items_at,
                item,
            } => {
                let step = item.size();
                while n < max {
                    let Some(r) = buf.get(at..at + len) else {
                        break;
                    };
                    if !matches!(decode(&r[count_at..], count, big), Value::Int(3)) {
                        break;
                    }
                    let mut face = [0u32; 3];
                    let mut valid = true;
                    for (k, slot) in face.iter_mut().enumerate() {
                        let v = match decode(&r[items_at + k * step..], item, big) {
                            Value::Int(v) => u32::try_from(v).ok().filter(|&v| (v as usize) < nv),
                            Value::Float(_) => None,
                        };
                        valid &= v.is_some();
                        *slot = v.unwrap_or(0);
                    }
                    if !valid {
                        break;
                    }
                    // Where the value-by-value path would locate the face: its last
                    // corner.
                    let last = base + (at + items_at + 2 * step) as u64;
                    mesh.push_face(&face, Location::ByteOffset(last))?;
                    (at, n) = (at + len, n + 1);
                }
            }
            Layout::Skip { len } => {
                n = max.min((buf.len() / len) as u64);
                at = n as usize * len;
            }
        }
        self.input.consume(at);
        Ok(n)
    }

    fn last(&self) -> Location {
        Location::ByteOffset(self.last)
    }

    fn reserve_for(&self, declared: u64, min_bytes: u64) -> usize {
        self.input.reserve_for(declared, min_bytes)
    }

    fn finish(&mut self) -> Result<(), ReadError> {
        loop {
            let at = self.input.offset();
            let rest = self.input.fill_at_least(1)?;
            if rest.is_empty() {
                return Ok(());
            }
            if let Some(i) = rest.iter().position(|b| !b.is_ascii_whitespace()) {
                return Err(ReadError::new(
                    K::TrailingData { what: "element" },
                    Location::ByteOffset(at + i as u64),
                ));
            }
            let n = rest.len();
            self.input.consume(n);
        }
    }
}

struct Ascii<'i, 'r> {
    input: &'i mut Input<'r>,
    /// The line of the last token (the payload's first line before any).
    line: usize,
}

impl Payload for Ascii<'_, '_> {
    fn value(&mut self, s: Scalar, what: &dyn Fn() -> String) -> Result<Value, ReadError> {
        let Some((n, tok)) = self.input.next_token()? else {
            let line = self.line.max(self.input.token_line()).max(1);
            return Err(ReadError::at_line(K::Truncated { expected: what() }, line));
        };
        self.line = n;
        let bad = || {
            ReadError::at_line(
                K::BadNumber {
                    token: token_string(tok),
                },
                n,
            )
        };
        if s.is_int() {
            let v = parse_i64(tok).ok_or_else(bad)?;
            let (lo, hi): (i64, i64) = match s {
                Scalar::I8 => (i8::MIN.into(), i8::MAX.into()),
                Scalar::U8 => (0, u8::MAX.into()),
                Scalar::I16 => (i16::MIN.into(), i16::MAX.into()),
                Scalar::U16 => (0, u16::MAX.into()),
                Scalar::I32 => (i32::MIN.into(), i32::MAX.into()),
                _ => (0, u32::MAX.into()),
            };
            if v < lo || v > hi {
                return Err(bad());
            }
            Ok(Value::Int(v))
        } else {
            // Any float syntax (NaN too) for ignored properties; coordinates are checked later.
            Ok(Value::Float(parse_any_f64(tok).ok_or_else(bad)?))
        }
    }

    fn last(&self) -> Location {
        Location::Line(self.line.max(1))
    }

    fn reserve_for(&self, declared: u64, min_bytes: u64) -> usize {
        self.input.reserve_for(declared, min_bytes)
    }

    fn finish(&mut self) -> Result<(), ReadError> {
        match self.input.next_token()? {
            None => Ok(()),
            Some((n, _)) => Err(ReadError::at_line(K::TrailingData { what: "element" }, n)),
        }
    }
}

/// Parses PLY (ascii or binary) into a polygon mesh; see the module docs.
pub(crate) fn parse_ply(input: &mut Input<'_>) -> Result<PolyMesh, ReadError> {
    parse_ply_with(input, true)
}

/// [`parse_ply`], with or without the batch decoder of fixed binary layouts (the tests
/// compare the two).
fn parse_ply_with(input: &mut Input<'_>, batched: bool) -> Result<PolyMesh, ReadError> {
    let header = parse_header(input)?;
    match header.encoding {
        PlyEncoding::Ascii => {
            let line = header.lines + 1;
            let mut p = Ascii { input, line };
            read_payload(&header, &mut p, batched)
        }
        enc => {
            let last = input.offset();
            let mut p = Binary {
                input,
                last,
                big_endian: enc == PlyEncoding::BinaryBigEndian,
            };
            read_payload(&header, &mut p, batched)
        }
    }
}

/// Reads the elements' records in header order: a binary element of fixed layout
/// in batches straight from the buffer when `batched` ([`Layout`]), every other record
/// (and every record when not `batched`) value by value.
fn read_payload(
    header: &Header,
    src: &mut impl Payload,
    batched: bool,
) -> Result<PolyMesh, ReadError> {
    let nv = header
        .elements
        .iter()
        .find(|e| e.kind == ElementKind::Vertex)
        .map_or(0, |e| e.count as usize);
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut mesh = PolyMesh::new(nv, None, header.encoding == PlyEncoding::Ascii, false);
    let mut face: Vec<u32> = Vec::new();
    for e in &header.elements {
        if e.properties.is_empty() {
            continue;
        }
        // Never trust the counts for allocation: reserve at most as many records as the
        // payload could hold at their smallest encoding. Every record consumes at least one
        // byte (or token), so a larger count ends in a located `Truncated` error.
        let min_record: usize = e
            .properties
            .iter()
            .map(|p| min_bytes(header.encoding, p))
            .sum();
        let cap = src.reserve_for(e.count, min_record as u64);
        match e.kind {
            ElementKind::Vertex => positions.reserve_exact(cap),
            ElementKind::Face => mesh.reserve(cap),
            ElementKind::Other => {}
        }
        let layout = if batched {
            Layout::of(header.encoding, e)
        } else {
            None
        };
        let mut i = 0;
        while i < e.count {
            if let Some(layout) = &layout {
                i += src.batch(layout, e.count - i, nv, &mut positions, &mut mesh)?;
                if i == e.count {
                    break;
                }
            }
            let mut xyz = [0.0; 3];
            let mut corners: Option<Location> = None;
            for p in &e.properties {
                let what = || format!("{} {i} of {} (property `{}`)", e.name, e.count, p.name);
                match p.ty {
                    PropType::Scalar(s) => {
                        let v = src.value(s, &what)?;
                        let loc = src.last();
                        if let Role::Coord(c) = p.role {
                            let x = v.as_f64();
                            if !x.is_finite() {
                                return Err(ReadError::new(
                                    K::BadNumber {
                                        token: x.to_string(),
                                    },
                                    loc,
                                ));
                            }
                            xyz[c] = x;
                        }
                    }
                    PropType::List { count: cs, item } => {
                        let n = src.value(cs, &what)?;
                        let loc = src.last();
                        let n = match n {
                            Value::Int(n) if n >= 0 => n as u64,
                            Value::Int(n) => {
                                return Err(ReadError::new(
                                    K::BadNumber {
                                        token: n.to_string(),
                                    },
                                    loc,
                                ))
                            }
                            Value::Float(_) => unreachable_float(loc)?,
                        };
                        if p.role == Role::Corners {
                            if n < 3 {
                                return Err(ReadError::new(
                                    K::NonTriangleFace {
                                        face: i as usize,
                                        corners: n,
                                    },
                                    loc,
                                ));
                            }
                            face.clear();
                            // Each item consumes at least one byte (or token), so this
                            // loop is bounded by the input length.
                            for _ in 0..n {
                                let idx = src.value(item, &what)?;
                                let loc = src.last();
                                let idx = match idx {
                                    Value::Int(v) => v,
                                    Value::Float(_) => unreachable_float(loc)?,
                                };
                                face.push(match u32::try_from(idx) {
                                    Ok(v) if (v as usize) < nv => v,
                                    _ => {
                                        return Err(ReadError::new(
                                            K::IndexOutOfRange {
                                                face: i as usize,
                                                index: idx,
                                                vertex_count: nv,
                                            },
                                            loc,
                                        ))
                                    }
                                });
                            }
                            corners = Some(loc);
                        } else {
                            // Each item consumes at least one byte, so this loop is bounded by
                            // the input length (truncation ends it early).
                            for _ in 0..n {
                                src.value(item, &what)?;
                            }
                        }
                    }
                }
            }
            match e.kind {
                ElementKind::Vertex => positions.push(xyz),
                ElementKind::Face => {
                    if let Some(at) = corners {
                        mesh.push_face(&face, at)?;
                    }
                }
                ElementKind::Other => {}
            }
            i += 1;
        }
    }
    src.finish()?;
    mesh.vertex_count = positions.len();
    mesh.positions = Some(positions);
    Ok(mesh)
}

/// Integer-typed values never decode as floats; typed error instead of a panic anyway.
fn unreachable_float<T>(loc: Location) -> Result<T, ReadError> {
    Err(ReadError::new(
        K::Ply("internal: integer property decoded as float".into()),
        loc,
    ))
}

/// Writes PLY with `double` coordinates and `list uchar uint vertex_indices` faces
/// (`0 0 0` for every vertex when the mesh has no positions). The mesh must pass
/// [`super::check_mesh`].
pub(crate) fn write_ply<const N: usize>(
    w: &mut impl Write,
    mesh: &Mesh<N>,
    encoding: PlyEncoding,
) -> std::io::Result<()> {
    let fmt = match encoding {
        PlyEncoding::Ascii => "ascii",
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
        PlyEncoding::BinaryBigEndian => "binary_big_endian",
    };
    write!(
        w,
        "ply\nformat {fmt} 1.0\ncomment written by contractible\n\
         element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        mesh.vertex_count,
        mesh.faces.len()
    )?;
    let pos = |i: usize| mesh.positions.as_ref().and_then(|p| p.get(i));
    match encoding {
        PlyEncoding::Ascii => {
            let mut buf = String::with_capacity(96);
            for i in 0..mesh.vertex_count {
                buf.clear();
                fmt_f64_triple(&mut buf, pos(i));
                buf.push('\n');
                w.write_all(buf.as_bytes())?;
            }
            for f in &mesh.faces {
                write!(w, "{N}")?;
                for v in f {
                    write!(w, " {v}")?;
                }
                writeln!(w)?;
            }
        }
        enc => {
            let be = enc == PlyEncoding::BinaryBigEndian;
            for i in 0..mesh.vertex_count {
                for x in pos(i).copied().unwrap_or([0.0; 3]) {
                    w.write_all(&if be { x.to_be_bytes() } else { x.to_le_bytes() })?;
                }
            }
            // N is 3 or 4 in this crate; a larger N would not fit the `uchar` count.
            let n = u8::try_from(N).map_err(|_| {
                std::io::Error::new(std::io::ErrorKind::InvalidInput, "face too large for PLY")
            })?;
            for f in &mesh.faces {
                w.write_all(&[n])?;
                for v in f {
                    w.write_all(&if be { v.to_be_bytes() } else { v.to_le_bytes() })?;
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    const TYPES: [(Scalar, &str); 8] = [
        (Scalar::I8, "char"),
        (Scalar::U8, "uchar"),
        (Scalar::I16, "short"),
        (Scalar::U16, "ushort"),
        (Scalar::I32, "int"),
        (Scalar::U32, "uint"),
        (Scalar::F32, "float"),
        (Scalar::F64, "double"),
    ];

    /// Appends `v` encoded as `s` (wrapping to the type's width, so that out-of-range
    /// and negative values occur for the small types).
    fn put(out: &mut Vec<u8>, s: Scalar, v: f64, big: bool) {
        let i = v as i64;
        macro_rules! b {
            ($x:expr) => {
                if big {
                    out.extend_from_slice(&$x.to_be_bytes())
                } else {
                    out.extend_from_slice(&$x.to_le_bytes())
                }
            };
        }
        match s {
            Scalar::I8 => b!(i as i8),
            Scalar::U8 => b!(i as u8),
            Scalar::I16 => b!(i as i16),
            Scalar::U16 => b!(i as u16),
            Scalar::I32 => b!(i as i32),
            Scalar::U32 => b!(i as u32),
            Scalar::F32 => b!(v as f32),
            Scalar::F64 => b!(v),
        }
    }

    fn any_type(rng: &mut Rng) -> (Scalar, &'static str) {
        TYPES[rng.index(TYPES.len())]
    }

    fn int_type(rng: &mut Rng) -> (Scalar, &'static str) {
        TYPES[rng.index(6)]
    }

    /// A random binary PLY file: coordinates and corners of random types among extra
    /// scalar properties, an optional element nobody reads (with or without a list),
    /// mostly triangles with some polygons and some faulty records (non-finite
    /// coordinates, bad counts, indices out of range), sometimes truncated or followed
    /// by bytes.
    fn random_ply(rng: &mut Rng, records: usize) -> Vec<u8> {
        let big = rng.chance(1, 2);
        let nv = 1 + rng.index(records);
        let nf = rng.index(2 * records);
        let rare = |rng: &mut Rng| rng.chance(1, 1 + 4 * records as u64);
        let mut head = format!(
            "ply\nformat {} 1.0\n",
            if big {
                "binary_big_endian"
            } else {
                "binary_little_endian"
            }
        );
        let mut body = Vec::new();
        // An element nobody reads, before or after the others.
        let other_first = rng.chance(1, 2);
        // (record count, scalar properties, whether a list follows them)
        type Extra = (u64, Vec<(Scalar, &'static str)>, bool);
        let other: Option<Extra> = rng.chance(1, 2).then(|| {
            let props = (0..1 + rng.index(3)).map(|_| any_type(rng)).collect();
            (rng.below(5), props, rng.chance(1, 3))
        });
        let mut other_head = String::new();
        let mut other_body = Vec::new();
        if let Some((count, props, list)) = &other {
            other_head += &format!("element extra {count}\n");
            for (k, (_, name)) in props.iter().enumerate() {
                other_head += &format!("property {name} p{k}\n");
            }
            if *list {
                other_head += "property list uchar int items\n";
            }
            for _ in 0..*count {
                for &(s, _) in props {
                    put(&mut other_body, s, rng.below(300) as f64, big);
                }
                if *list {
                    let n = rng.below(3);
                    put(&mut other_body, Scalar::U8, n as f64, big);
                    for _ in 0..n {
                        put(&mut other_body, Scalar::I32, 7.0, big);
                    }
                }
            }
        }
        if other_first {
            head += &other_head;
            body.extend_from_slice(&other_body);
        }
        // Vertices: x, y, z in a random order among 0-2 extra scalars.
        head += &format!("element vertex {nv}\n");
        let mut vprops: Vec<(Option<usize>, (Scalar, &str))> = Vec::new();
        for c in 0..3 {
            vprops.push((Some(c), any_type(rng)));
        }
        for _ in 0..rng.index(3) {
            vprops.push((None, any_type(rng)));
        }
        rng.shuffle(&mut vprops);
        for (k, (c, (_, name))) in vprops.iter().enumerate() {
            match c {
                Some(c) => head += &format!("property {name} {}\n", ["x", "y", "z"][*c]),
                None => head += &format!("property {name} v{k}\n"),
            }
        }
        for _ in 0..nv {
            for &(c, (s, _)) in &vprops {
                let v = if c.is_some() && rare(rng) {
                    [f64::NAN, f64::INFINITY, f64::NEG_INFINITY][rng.index(3)]
                } else {
                    rng.below(200) as f64 - 100.0 + 0.25 * rng.below(4) as f64
                };
                put(&mut body, s, v, big);
            }
        }
        // Faces: the corner list among 0-2 extra scalars.
        head += &format!("element face {nf}\n");
        let (cs, cname) = int_type(rng);
        let (is, iname) = int_type(rng);
        let before: Vec<_> = (0..rng.index(2)).map(|_| any_type(rng)).collect();
        let after: Vec<_> = (0..rng.index(2)).map(|_| any_type(rng)).collect();
        for (k, (_, name)) in before.iter().enumerate() {
            head += &format!("property {name} b{k}\n");
        }
        let list_name = ["vertex_indices", "vertex_index"][rng.index(2)];
        head += &format!("property list {cname} {iname} {list_name}\n");
        for (k, (_, name)) in after.iter().enumerate() {
            head += &format!("property {name} a{k}\n");
        }
        for _ in 0..nf {
            for &(s, _) in &before {
                put(&mut body, s, rng.below(100) as f64, big);
            }
            let n: i64 = if rare(rng) {
                [-1, 0, 2, 300][rng.index(4)]
            } else if rng.chance(1, 10) {
                4 + rng.below(3) as i64
            } else {
                3
            };
            put(&mut body, cs, n as f64, big);
            for _ in 0..n.clamp(0, 6) {
                let v = if rare(rng) {
                    [-1, nv as i64, 70_000][rng.index(3)]
                } else {
                    rng.index(nv) as i64
                };
                put(&mut body, is, v as f64, big);
            }
            for &(s, _) in &after {
                put(&mut body, s, rng.below(100) as f64, big);
            }
        }
        if !other_first {
            head += &other_head;
            body.extend_from_slice(&other_body);
        }
        head += "end_header\n";
        let mut file = head.into_bytes();
        file.extend_from_slice(&body);
        if rng.chance(1, 8) {
            let cut = rng.index(file.len());
            file.truncate(cut);
        } else if rng.chance(1, 8) {
            file.extend_from_slice([&b" \n"[..], b"x", &[0, 1]][rng.index(3)]);
        }
        file
    }

    fn read(file: &[u8], batched: bool) -> Result<PolyMesh, String> {
        parse_ply_with(&mut Input::from_slice(file), batched).map_err(|e| format!("{e:?}"))
    }

    /// The batch decoder gives what the value-by-value decoder gives, meshes and located
    /// errors alike, on small files of every layout.
    #[test]
    fn batches_decode_as_value_by_value_on_random_files() {
        let (mut ok, mut err) = (0, 0);
        for seed in 0..3000 {
            let file = random_ply(&mut Rng::new(seed), 1 + seed as usize % 12);
            let (fast, slow) = (read(&file, true), read(&file, false));
            assert_eq!(fast, slow, "seed {seed}");
            if fast.is_ok() {
                ok += 1
            } else {
                err += 1
            }
        }
        assert!(ok > 1000 && err > 500, "{ok} read, {err} refused");
    }

    /// As above on files of several buffer lengths (the batches stop and resume at each
    /// refill), with a problem, when there is one, far from the start.
    #[test]
    fn batches_decode_as_value_by_value_across_buffer_refills() {
        let mut long = 0;
        for seed in 0..16 {
            let file = random_ply(&mut Rng::new(10_000 + seed), 40_000);
            long += usize::from(file.len() > 3 * super::super::input::CHUNK);
            let (fast, slow) = (read(&file, true), read(&file, false));
            assert_eq!(fast, slow, "seed {seed}");
        }
        assert!(long >= 8, "{long} files of more than three buffers");
    }

    /// A header of `MAX_HEADER_ITEMS - 4 + extra` items beyond the vertex element's four:
    /// thousands of properties in one element, then elements of one property each.
    fn header_of(extra: usize) -> Vec<u8> {
        let mut h = String::from(
            "ply\nformat binary_little_endian 1.0\nelement vertex 0\n\
             property float x\nproperty float y\nproperty float z\n",
        );
        let props = 30_000;
        for i in 0..props {
            h += &format!("property uchar q{i}\n");
        }
        let mut left = MAX_HEADER_ITEMS - 4 - props + extra;
        let mut i = 0;
        while left > 0 {
            h += &format!("element e{i} 0\n");
            left -= 1;
            if left > 0 {
                h += "property uchar p\n";
                left -= 1;
            }
            i += 1;
        }
        h += "end_header\n";
        h.into_bytes()
    }

    /// Exactly `MAX_HEADER_ITEMS` elements and properties are read (in time linear in
    /// the header: repeated names are found in sets), one more is refused at its line.
    #[test]
    fn a_header_of_the_item_limit_is_read_and_one_more_item_is_refused() {
        let mesh = read(&header_of(0), true).unwrap();
        assert_eq!((mesh.vertex_count, mesh.face_count()), (0, 0));
        let e = parse_err(&header_of(1));
        assert!(matches!(e.kind, K::BadHeader(_)), "{e}");
        assert_eq!(e.location, Location::Line(MAX_HEADER_ITEMS + 3));
    }

    /// The error `parse_ply` gives on `file` (from memory).
    fn parse_err(file: &[u8]) -> ReadError {
        parse_ply(&mut Input::from_slice(file)).unwrap_err()
    }

    fn header_error(file: &[u8]) -> ReadError {
        match parse_header(&mut Input::from_slice(file)) {
            Ok(_) => panic!("header accepted"),
            Err(e) => e,
        }
    }

    /// The magic line, integer corner lists and the `u32` vertex count are checked in
    /// the header, located at their lines.
    #[test]
    fn header_checks_are_located_at_their_lines() {
        let e = header_error(b"plx\nformat ascii 1.0\nend_header\n");
        assert!(
            matches!(e.kind, K::BadHeader(ref m) if m.contains("magic")),
            "{e}"
        );
        assert_eq!(e.location, Location::Line(1));

        let e = header_error(
            b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
              property float z\nelement face 1\nproperty list uchar float vertex_indices\n\
              end_header\n",
        );
        assert!(
            matches!(e.kind, K::BadHeader(ref m) if m.contains("list of integers")),
            "{e}"
        );
        assert_eq!(e.location, Location::Line(8));

        let head = |count: u64| {
            format!(
                "ply\nformat binary_little_endian 1.0\nelement vertex {count}\n\
                 property float x\nproperty float y\nproperty float z\nend_header\n"
            )
            .into_bytes()
        };
        let most = u64::from(u32::MAX);
        let header = parse_header(&mut Input::from_slice(&head(most))).unwrap();
        assert_eq!(header.elements[0].count, most);
        let e = header_error(&head(most + 1));
        assert!(
            matches!(e.kind, K::CountTooLarge { what: "vertices", declared } if declared == most + 1),
            "{e}"
        );
        assert_eq!(e.location, Location::Line(3));
    }

    fn prop(ty: PropType, role: Role) -> Property {
        Property {
            name: String::new(),
            ty,
            role,
        }
    }

    /// The smallest record of each property, which bounds what a count can reserve: a
    /// token and a separator in ASCII (a face's corner list `3 a b c`), the type's size
    /// in binary (a corner list with three items).
    #[test]
    fn min_bytes_is_the_smallest_encoding_of_each_property() {
        use PlyEncoding::{Ascii, BinaryBigEndian as Be, BinaryLittleEndian as Le};
        let list = |count, item| PropType::List { count, item };
        let cases = [
            (
                Ascii,
                prop(PropType::Scalar(Scalar::F64), Role::Coord(0)),
                2,
            ),
            (Ascii, prop(list(Scalar::U8, Scalar::I32), Role::Corners), 8),
            (Ascii, prop(list(Scalar::U8, Scalar::I32), Role::Ignore), 2),
            (Le, prop(PropType::Scalar(Scalar::F64), Role::Coord(1)), 8),
            (Be, prop(PropType::Scalar(Scalar::I16), Role::Ignore), 2),
            (Le, prop(list(Scalar::U8, Scalar::I32), Role::Corners), 13),
            (Be, prop(list(Scalar::U16, Scalar::U8), Role::Corners), 5),
            (Le, prop(list(Scalar::I32, Scalar::F32), Role::Ignore), 4),
        ];
        for (encoding, p, want) in cases {
            assert_eq!(min_bytes(encoding, &p), want, "{encoding:?} {p:?}");
        }
        // The ASCII face record `3 0 1 2` and its terminator: exactly the bound.
        assert_eq!(b"3 0 1 2\n".len(), 8);
    }

    fn element(kind: ElementKind, properties: Vec<Property>) -> Element {
        Element {
            name: String::new(),
            count: 1,
            kind,
            properties,
            line: 1,
        }
    }

    /// Fixed binary layouts: coordinates and corners at their offsets, records that
    /// nothing reads skipped by length; none for ASCII, other lists, missing
    /// coordinates or empty records.
    #[test]
    fn fixed_layouts_are_found_for_binary_records_of_one_shape() {
        use PlyEncoding::{Ascii, BinaryLittleEndian as Le};
        let s = |t| PropType::Scalar(t);
        let vertex = || {
            element(
                ElementKind::Vertex,
                vec![
                    prop(s(Scalar::U8), Role::Ignore),
                    prop(s(Scalar::F32), Role::Coord(0)),
                    prop(s(Scalar::F64), Role::Coord(2)),
                    prop(s(Scalar::I16), Role::Coord(1)),
                ],
            )
        };
        let want = Layout::Vertex {
            len: 15,
            coords: [(1, Scalar::F32), (13, Scalar::I16), (5, Scalar::F64)],
        };
        assert_eq!(Layout::of(Le, &vertex()), Some(want));
        assert_eq!(want.len(), 15);
        assert_eq!(Layout::of(Ascii, &vertex()), None);
        let mut partial = vertex();
        partial.properties.pop();
        assert_eq!(Layout::of(Le, &partial), None);

        let face = element(
            ElementKind::Face,
            vec![
                prop(s(Scalar::I32), Role::Ignore),
                prop(
                    PropType::List {
                        count: Scalar::U16,
                        item: Scalar::U32,
                    },
                    Role::Corners,
                ),
                prop(s(Scalar::U8), Role::Ignore),
            ],
        );
        let want = Layout::Face {
            len: 4 + 2 + 12 + 1,
            count_at: 4,
            count: Scalar::U16,
            items_at: 6,
            item: Scalar::U32,
        };
        assert_eq!(Layout::of(Le, &face), Some(want));
        assert_eq!(want.len(), 19);

        let other = element(ElementKind::Other, vec![prop(s(Scalar::F64), Role::Ignore)]);
        assert_eq!(Layout::of(Le, &other), Some(Layout::Skip { len: 8 }));
        assert_eq!(Layout::Skip { len: 8 }.len(), 8);
        assert_eq!(Layout::of(Le, &element(ElementKind::Other, vec![])), None);
        let listed = element(
            ElementKind::Other,
            vec![prop(
                PropType::List {
                    count: Scalar::U8,
                    item: Scalar::U8,
                },
                Role::Ignore,
            )],
        );
        assert_eq!(Layout::of(Le, &listed), None);
        assert_eq!(Layout::of(Le, &element(ElementKind::Face, vec![])), None);
    }

    fn binary_payload<'i, 'r>(input: &'i mut Input<'r>, big_endian: bool) -> Binary<'i, 'r> {
        Binary {
            input,
            last: 0,
            big_endian,
        }
    }

    /// The batch decoder decodes whole records of its layout from the buffer, up to the
    /// number asked, and stops before a record it must leave to the value-by-value path
    /// (a non-finite coordinate, a face that is not a triangle or names a vertex out of
    /// range) or one that is incomplete.
    #[test]
    fn batches_decode_whole_records_and_stop_before_any_other() {
        let mut body = Vec::new();
        for v in [
            [1.0f32, 2.0, 3.0],
            [4.0, 5.0, 6.0],
            [7.0, 8.0, 9.0],
            [f32::NAN, 0.0, 0.0],
        ] {
            for x in v {
                body.extend_from_slice(&x.to_le_bytes());
            }
        }
        let layout = Layout::Vertex {
            len: 12,
            coords: [(0, Scalar::F32), (4, Scalar::F32), (8, Scalar::F32)],
        };
        let mut input = Input::from_slice(&body);
        let mut src = binary_payload(&mut input, false);
        let (mut positions, mut mesh) = (Vec::new(), PolyMesh::new(3, None, false, false));
        assert_eq!(
            src.batch(&layout, 2, 3, &mut positions, &mut mesh).unwrap(),
            2
        );
        assert_eq!(positions, [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
        assert_eq!(
            src.batch(&layout, 5, 3, &mut positions, &mut mesh).unwrap(),
            1
        );
        assert_eq!(
            src.batch(&layout, 5, 3, &mut positions, &mut mesh).unwrap(),
            0
        );
        assert_eq!(input.offset(), 36);

        let mut body = Vec::new();
        for (k, f) in [
            (3u8, [0u32, 1, 2]),
            (3, [2, 1, 0]),
            (3, [0, 1, 3]),
            (4, [0, 1, 2]),
        ] {
            body.push(k);
            for c in f {
                body.extend_from_slice(&c.to_be_bytes());
            }
        }
        body.extend_from_slice(&[3, 0, 0]);
        let layout = Layout::Face {
            len: 13,
            count_at: 0,
            count: Scalar::U8,
            items_at: 1,
            item: Scalar::U32,
        };
        for (max, want) in [(1, 1), (9, 2)] {
            let mut input = Input::from_slice(&body);
            let mut src = binary_payload(&mut input, true);
            let mut mesh = PolyMesh::new(3, None, false, false);
            let n = src
                .batch(&layout, max, 3, &mut Vec::new(), &mut mesh)
                .unwrap();
            assert_eq!(n, want);
            let faces: Vec<&[u32]> = mesh.faces().collect();
            assert_eq!(faces, [&[0, 1, 2][..], &[2, 1, 0]][..want as usize]);
            assert_eq!(input.offset(), 13 * want);
        }
        // Out of range with 3 vertices, in range with 4: then the quad stops the batch.
        let mut input = Input::from_slice(&body);
        let mut src = binary_payload(&mut input, true);
        let mut mesh = PolyMesh::new(4, None, false, false);
        assert_eq!(
            src.batch(&layout, 9, 4, &mut Vec::new(), &mut mesh)
                .unwrap(),
            3
        );

        let body = [0u8; 45];
        let mut input = Input::from_slice(&body);
        let mut src = binary_payload(&mut input, false);
        let skip = Layout::Skip { len: 8 };
        let mut mesh = PolyMesh::new(0, None, false, false);
        assert_eq!(
            src.batch(&skip, 3, 0, &mut Vec::new(), &mut mesh).unwrap(),
            3
        );
        assert_eq!(
            src.batch(&skip, 9, 0, &mut Vec::new(), &mut mesh).unwrap(),
            2
        );
        assert_eq!(input.offset(), 40);
    }

    /// A file whose counts the payload can hold gets exactly that room: the positions
    /// and faces are reserved once, not grown by doubling.
    #[test]
    fn counts_the_payload_can_hold_are_reserved_exactly() {
        let n = 1000;
        for enc in ["ascii", "binary_little_endian"] {
            let mut file = format!(
                "ply\nformat {enc} 1.0\nelement vertex {n}\nproperty float x\n\
                 property float y\nproperty float z\nelement face {}\n\
                 property list uchar int vertex_indices\nend_header\n",
                n - 2
            )
            .into_bytes();
            for i in 0..n {
                let v = [i as f32, (i * i) as f32, 1.0];
                if enc == "ascii" {
                    file.extend(format!("{} {} {}\n", v[0], v[1], v[2]).bytes());
                } else {
                    v.iter().for_each(|x| file.extend(x.to_le_bytes()));
                }
            }
            for i in 0..n - 2 {
                let f = [i as i32, i as i32 + 1, i as i32 + 2];
                if enc == "ascii" {
                    file.extend(format!("3 {} {} {}\n", f[0], f[1], f[2]).bytes());
                } else {
                    file.push(3);
                    f.iter().for_each(|c| file.extend(c.to_le_bytes()));
                }
            }
            let mesh = read(&file, true).unwrap();
            let positions = mesh.positions.as_ref().unwrap();
            assert_eq!((positions.len(), positions.capacity()), (n, n), "{enc}");
            assert_eq!(mesh.face_count(), n - 2);
        }
    }

    /// Bytes after a binary payload: whitespace is allowed, anything else is refused
    /// at its own offset.
    #[test]
    fn trailing_bytes_are_located_past_the_whitespace() {
        let head = "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\n\
                    property float y\nproperty float z\nend_header\n";
        let mut file = head.as_bytes().to_vec();
        file.extend([0u8; 12]);
        assert!(read(&file, true).is_ok());
        file.extend(b" \n\t x");
        let e = parse_err(&file);
        assert!(matches!(e.kind, K::TrailingData { .. }), "{e}");
        assert_eq!(
            e.location,
            Location::ByteOffset((head.len() + 12 + 4) as u64)
        );
    }

    /// ASCII integers are checked against their declared type's range, both ends
    /// included.
    #[test]
    fn ascii_integers_are_checked_against_their_types_range() {
        let ranges: [(&str, i64, i64); 6] = [
            ("char", -128, 127),
            ("uchar", 0, 255),
            ("short", -32768, 32767),
            ("ushort", 0, 65535),
            ("int", -(1 << 31), (1 << 31) - 1),
            ("uint", 0, (1 << 32) - 1),
        ];
        for (ty, lo, hi) in ranges {
            let file = |v: i64| {
                format!(
                    "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n\
                     property {ty} w\nproperty float y\nproperty float z\nend_header\n\
                     0 {v} 0 0\n"
                )
                .into_bytes()
            };
            for v in [lo, hi] {
                assert!(read(&file(v), true).is_ok(), "{ty} {v}");
            }
            for v in [lo - 1, hi + 1] {
                let e = parse_err(&file(v));
                assert!(matches!(e.kind, K::BadNumber { .. }), "{ty} {v}: {e}");
                assert_eq!(e.location, Location::Line(9));
            }
        }
    }

    /// An ASCII payload that ends before its first value is truncated at the line after
    /// the header; a negative list count is a bad number at its own line, binary or not.
    #[test]
    fn empty_payloads_and_negative_list_counts_are_located() {
        let head = |enc: &str| {
            format!(
                "ply\nformat {enc} 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
                 property float z\nelement face 1\nproperty list char int vertex_indices\n\
                 end_header\n"
            )
            .into_bytes()
        };
        let e = parse_err(&head("ascii"));
        assert!(matches!(e.kind, K::Truncated { .. }), "{e}");
        assert_eq!(e.location, Location::Line(10));

        let mut file = head("ascii");
        file.extend(b"0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n");
        let e = parse_err(&file);
        assert!(
            matches!(e.kind, K::BadNumber { ref token } if token == "-1"),
            "{e}"
        );
        assert_eq!(e.location, Location::Line(13));

        let mut file = head("binary_little_endian");
        let payload = file.len();
        file.extend([0u8; 36]);
        file.push(0xFF);
        file.extend([0u8; 12]);
        let e = parse_err(&file);
        assert!(
            matches!(e.kind, K::BadNumber { ref token } if token == "-1"),
            "{e}"
        );
        assert_eq!(e.location, Location::ByteOffset(payload as u64 + 36));
    }
}
