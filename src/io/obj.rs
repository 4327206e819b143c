//! Wavefront OBJ reading (positions and faces) and writing.
//!
//! Why a hand parser rather than the `tobj` crate: `tobj` 4 (a) stores positions
//! as `f32` unless its `use_f64` feature is enabled, so coordinates would not round-trip;
//! (b) with `single_index: false` it still *renumbers* vertices per model in order of first
//! use and drops unreferenced ones, so the mesh would not have "indices as in the file";
//! (c) its errors carry no line number. The subset needed here is small: `v x y z [...]`
//! lines give positions, `f` lines give faces (`i`, `i/t`, `i//n`, `i/t/n`; negative indices
//! are relative to the vertices read so far; faces may have any number `>= 3` of corners).
//! `vn`, `vt`, `vp`, `o`, `g`, `s`, `usemtl`, `mtllib` carry nothing the topology needs
//! and are ignored; every other statement (`l`, `p`, curves, unknown keywords) is skipped
//! and *counted* ([`super::SkippedStatements`]), so that callers can say what was left
//! out. All objects/groups form one mesh. Not supported: `\` line continuations.
//!
//! OBJ numbers vertices and faces from 1, so do its errors: face numbers count `f`
//! statements from 1, and an out-of-range index is reported as written (1-based, or
//! negative when relative).

use std::io::Write;

use super::error::{token_string, Location, ReadError, ReadErrorKind as K};
use super::fmt_f64_triple;
use super::input::Input;
use super::poly::PolyMesh;
use super::text::{parse_f64, parse_i64, Tokens};
use crate::mesh::Mesh;

/// The error for one more vertex at `line` when `count` are read already, if it would
/// pass the `u32` index limit: `CountTooLarge` with the count it would make.
fn vertex_past_limit(count: usize, line: usize) -> Option<ReadError> {
    (count >= u32::MAX as usize).then(|| {
        ReadError::at_line(
            K::CountTooLarge {
                what: "vertices",
                declared: count as u64 + 1,
            },
            line,
        )
    })
}

/// Parses OBJ into a polygon mesh; see the module docs for the accepted subset.
pub(crate) fn parse_obj(input: &mut Input<'_>) -> Result<PolyMesh, ReadError> {
    let mut positions: Vec<[f64; 3]> = Vec::new();
    let mut mesh = PolyMesh::new(0, None, true, true);
    let mut face: Vec<u32> = Vec::new();
    // Face indices are checked against the final vertex count (forward references are
    // tolerated by most tools); `max_index` finds out cheaply whether any is out of range.
    let mut max_index: u64 = 0;
    while let Some((n, line)) = input.next_data_line(b'#')? {
        let mut t = Tokens::new(line);
        let keyword = t.next().unwrap_or_default();
        match keyword {
            b"v" => {
                let mut p = [0.0; 3];
                for (c, name) in p
                    .iter_mut()
                    .zip(["x coordinate", "y coordinate", "z coordinate"])
                {
                    let tok = t
                        .next()
                        .ok_or_else(|| ReadError::at_line(K::MissingValue { expected: name }, n))?;
                    *c = parse_f64(tok).ok_or_else(|| bad_number(tok, n))?;
                }
                if let Some(e) = vertex_past_limit(positions.len(), n) {
                    return Err(e);
                }
                positions.push(p);
            }
            b"f" => {
                let face_no = mesh.face_count() + 1;
                face.clear();
                for tok in t {
                    let v = parse_ref(tok, positions.len(), face_no, n)?;
                    max_index = max_index.max(u64::from(v));
                    face.push(v);
                }
                mesh.push_face(&face, Location::Line(n))?;
            }
            b"vn" | b"vt" | b"vp" | b"o" | b"g" | b"s" | b"usemtl" | b"mtllib" => {}
            other => mesh.skipped.add(other, n),
        }
    }
    if mesh.face_count() > 0 && max_index >= positions.len() as u64 {
        return Err(locate_bad_face(&mesh, positions.len()));
    }
    mesh.vertex_count = positions.len();
    mesh.positions = Some(positions);
    Ok(mesh)
}

fn bad_number(tok: &[u8], line: usize) -> ReadError {
    ReadError::at_line(
        K::BadNumber {
            token: token_string(tok),
        },
        line,
    )
}

/// The 0-based position index of one face corner `i[/t[/n]]` (`face` is 1-based; an
/// out-of-range index is reported as written).
fn parse_ref(tok: &[u8], seen: usize, face: usize, line: usize) -> Result<u32, ReadError> {
    let vtok = tok.split(|&b| b == b'/').next().unwrap_or_default();
    if tok.split(|&b| b == b'/').count() > 3 {
        return Err(ReadError::at_line(
            K::Obj(format!(
                "face corner {:?} has more than 3 `/`-separated parts",
                token_string(tok)
            )),
            line,
        ));
    }
    let i = parse_i64(vtok).ok_or_else(|| bad_number(vtok, line))?;
    let out_of_range = |index: i64| {
        ReadError::at_line(
            K::IndexOutOfRange {
                face,
                index,
                vertex_count: seen,
            },
            line,
        )
    };
    let zero_based: i64 = match i {
        0 => {
            return Err(ReadError::at_line(
                K::Obj("vertex index 0 is invalid (OBJ indices start at 1)".into()),
                line,
            ))
        }
        // Relative: -1 is the last vertex read so far.
        i if i < 0 => i64::try_from(seen)
            .ok()
            .and_then(|s| s.checked_add(i))
            .ok_or_else(|| out_of_range(i))?,
        i => i - 1,
    };
    if zero_based < 0 {
        return Err(out_of_range(i));
    }
    u32::try_from(zero_based).map_err(|_| out_of_range(i))
}

/// Error for the first face with an index `>= vertex_count`, at its line (1-based face
/// number and index, as the file writes them).
fn locate_bad_face(mesh: &PolyMesh, vertex_count: usize) -> ReadError {
    for (i, f) in mesh.faces().enumerate() {
        if let Some(&v) = f.iter().find(|&&v| v as usize >= vertex_count) {
            let kind = K::IndexOutOfRange {
                face: i + 1,
                index: i64::from(v) + 1,
                vertex_count,
            };
            return match mesh.face_line(i) {
                Some(n) => ReadError::at_line(kind, n),
                None => ReadError::new(kind, Location::Face(i + 1)),
            };
        }
    }
    // Unreachable by construction; still a typed error rather than a panic.
    ReadError::new(
        K::Obj("internal: no bad face found".into()),
        Location::Unknown,
    )
}

/// Writes OBJ: one `v x y z` line per vertex (`0 0 0` without positions) and one
/// `f a b c ...` line per face with 1-based indices. The mesh must pass
/// [`super::check_mesh`].
pub(crate) fn write_obj<const N: usize>(w: &mut impl Write, mesh: &Mesh<N>) -> std::io::Result<()> {
    let mut buf = String::with_capacity(96);
    for i in 0..mesh.vertex_count {
        buf.clear();
        buf.push_str("v ");
        fmt_f64_triple(&mut buf, mesh.positions.as_ref().and_then(|p| p.get(i)));
        buf.push('\n');
        w.write_all(buf.as_bytes())?;
    }
    for f in &mesh.faces {
        w.write_all(b"f")?;
        for v in f {
            write!(w, " {}", u64::from(*v) + 1)?;
        }
        writeln!(w)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Vertex `2^32` (one past the last `u32` index) is refused, with its number; the one
    /// before it is not (a file that large cannot be built in a test, so the check is
    /// tested alone).
    #[test]
    fn the_vertex_past_the_index_limit_is_refused_with_its_number() {
        assert!(vertex_past_limit(u32::MAX as usize - 1, 7).is_none());
        let e = vertex_past_limit(u32::MAX as usize, 7).expect("past the limit");
        assert!(
            matches!(e.kind, K::CountTooLarge { what: "vertices", declared } if declared == 1 << 32),
            "{e}"
        );
        assert_eq!(e.location, Location::Line(7));
    }
}
