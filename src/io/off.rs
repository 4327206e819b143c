//! ASCII OFF reading and writing.
//!
//! Accepted input: an `OFF` keyword (optionally prefixed by `ST`, `C`, `N` letters, as in
//! `COFF`, `NOFF`, `STCNOFF`; the extra per-vertex values are ignored), the counts
//! `V F [E]` on the keyword line or the next data line, then one vertex per line
//! (`x y z [ignored...]`) and one face per line (`k a b c ... [ignored colour...]`, any
//! `k >= 3`; [`super::PolyMesh`] keeps polygons, the triangle readers refuse them).
//! `#` starts a comment anywhere; blank lines are skipped. Not supported (clear errors):
//! `OFF BINARY`, `4OFF`/`nOFF` (other dimensions), records split across several lines.

use std::io::Write;

use super::error::Location;
use super::error::{token_string, ReadError, ReadErrorKind as K};
use super::fmt_f64_triple;
use super::input::Input;
use super::poly::PolyMesh;
use super::text::{parse_f64, parse_i64, parse_u64, Tokens};
use crate::mesh::Mesh;

/// Smallest possible vertex line: `0 0 0` plus a newline.
const MIN_VERTEX_BYTES: u64 = 6;
/// Smallest possible face line: `3 0 0 0` plus a newline.
const MIN_FACE_BYTES: u64 = 8;

/// Parses ASCII OFF into a polygon mesh; see the module docs for the accepted syntax.
pub(crate) fn parse_off(input: &mut Input<'_>) -> Result<PolyMesh, ReadError> {
    let Some((hline, header)) = input.next_data_line(b'#')? else {
        return Err(ReadError::at_line(
            K::BadHeader("empty input, expected an OFF header".into()),
            input.line().max(1),
        ));
    };
    let mut toks = Tokens::new(header);
    let keyword = toks.next().unwrap_or_default();
    check_keyword(keyword).map_err(|k| ReadError::at_line(k, hline))?;

    // Counts: rest of the header line, or the next data line. At most four tokens are
    // kept (more than three is an error whatever follows).
    let mut count_line = hline;
    let mut counts: Vec<Vec<u8>> = toks.take(4).map(<[u8]>::to_vec).collect();
    if counts.is_empty() {
        let Some((n, l)) = input.next_data_line(b'#')? else {
            return Err(ReadError::at_line(
                K::BadHeader("missing vertex/face counts".into()),
                input.line(),
            ));
        };
        count_line = n;
        counts = Tokens::new(l).take(4).map(<[u8]>::to_vec).collect();
    }
    if counts
        .first()
        .is_some_and(|t| t.eq_ignore_ascii_case(b"BINARY"))
    {
        return Err(ReadError::at_line(
            K::BadHeader("binary OFF is not supported".into()),
            count_line,
        ));
    }
    if counts.len() < 2 || counts.len() > 3 {
        return Err(ReadError::at_line(
            K::BadHeader(format!(
                "expected `V F [E]` counts, found {} values",
                counts.len()
            )),
            count_line,
        ));
    }
    let mut parsed = [0u64; 3];
    for (slot, tok) in parsed.iter_mut().zip(&counts) {
        *slot = parse_u64(tok).ok_or_else(|| {
            ReadError::at_line(
                K::BadNumber {
                    token: token_string(tok),
                },
                count_line,
            )
        })?;
    }
    let [nv, nf, _ne] = parsed;

    // Vertices must be addressable by u32 indices.
    if nv > u64::from(u32::MAX) {
        return Err(ReadError::at_line(
            K::CountTooLarge {
                what: "vertices",
                declared: nv,
            },
            count_line,
        ));
    }
    // Nor more faces than a triangulation can index (their corners would overflow u32):
    // said here, before any record is read.
    if let Some(k) = K::past_face_limit("faces", nf) {
        return Err(ReadError::at_line(k, count_line));
    }
    // Never trust the counts for allocation: reserve at most what the remaining bytes could
    // hold at the smallest possible record size. The loops below consume at least one line
    // per record, so a count larger than the input ends in a located `CountMismatch`.
    let nv_cap = input.reserve_for(nv, MIN_VERTEX_BYTES);
    let nf_cap = input.reserve_for(nf, MIN_FACE_BYTES);

    let mut positions = Vec::with_capacity(nv_cap);
    for i in 0..nv {
        let Some((n, line)) = input.next_data_line(b'#')? else {
            return Err(ReadError::at_line(
                K::CountMismatch {
                    what: "vertices",
                    declared: nv,
                    found: i,
                },
                input.line(),
            ));
        };
        let mut t = Tokens::new(line);
        let mut p = [0.0; 3];
        for (c, name) in p
            .iter_mut()
            .zip(["x coordinate", "y coordinate", "z coordinate"])
        {
            let tok = t
                .next()
                .ok_or_else(|| ReadError::at_line(K::MissingValue { expected: name }, n))?;
            *c = parse_f64(tok).ok_or_else(|| {
                ReadError::at_line(
                    K::BadNumber {
                        token: token_string(tok),
                    },
                    n,
                )
            })?;
        }
        positions.push(p);
    }

    let mut mesh = PolyMesh::new(nv as usize, Some(positions), true, false);
    mesh.reserve(nf_cap);
    let mut face: Vec<u32> = Vec::new();
    for f in 0..nf {
        let Some((n, line)) = input.next_data_line(b'#')? else {
            return Err(ReadError::at_line(
                K::CountMismatch {
                    what: "faces",
                    declared: nf,
                    found: f,
                },
                input.line(),
            ));
        };
        let mut t = Tokens::new(line);
        // A data line always has a first token.
        let ktok = t.next().unwrap_or_default();
        let k = parse_u64(ktok).ok_or_else(|| {
            ReadError::at_line(
                K::BadNumber {
                    token: token_string(ktok),
                },
                n,
            )
        })?;
        if k < 3 {
            return Err(ReadError::at_line(
                K::NonTriangleFace {
                    face: f as usize,
                    corners: k,
                },
                n,
            ));
        }
        face.clear();
        // Each index is a token of this line, so `k` is bounded by the input.
        for _ in 0..k {
            let tok = t.next().ok_or_else(|| {
                ReadError::at_line(
                    K::MissingValue {
                        expected: "vertex index",
                    },
                    n,
                )
            })?;
            let idx = parse_i64(tok).ok_or_else(|| {
                ReadError::at_line(
                    K::BadNumber {
                        token: token_string(tok),
                    },
                    n,
                )
            })?;
            face.push(match u32::try_from(idx) {
                Ok(v) if u64::from(v) < nv => v,
                _ => {
                    return Err(ReadError::at_line(
                        K::IndexOutOfRange {
                            face: f as usize,
                            index: idx,
                            vertex_count: nv as usize,
                        },
                        n,
                    ))
                }
            });
        }
        mesh.push_face(&face, Location::Line(n))?;
    }

    // More records than declared is an error; trailing blank lines and comments are not.
    if let Some((first, _)) = input.next_data_line(b'#')? {
        let mut extra = 1u64;
        while input.next_data_line(b'#')?.is_some() {
            extra += 1;
        }
        return Err(ReadError::at_line(
            K::CountMismatch {
                what: "faces",
                declared: nf,
                found: nf.saturating_add(extra),
            },
            first,
        ));
    }
    Ok(mesh)
}

/// Accepts `OFF` with an optional prefix made of the letters `S`, `T`, `C`, `N`.
fn check_keyword(kw: &[u8]) -> Result<(), K> {
    let Some(prefix) = kw.strip_suffix(b"OFF") else {
        return Err(K::BadHeader(format!(
            "expected `OFF`, found {:?}",
            token_string(kw)
        )));
    };
    if prefix
        .iter()
        .all(|b| matches!(b, b'S' | b'T' | b'C' | b'N'))
    {
        Ok(())
    } else {
        Err(K::BadHeader(format!(
            "unsupported OFF variant {:?} (only 3D OFF/COFF/NOFF/STOFF)",
            token_string(kw)
        )))
    }
}

/// Writes ASCII OFF: `OFF`, `V F 0`, one `x y z` line per vertex (`0 0 0` without
/// positions), one `N a b c ...` line per face. The mesh must pass [`super::check_mesh`].
pub(crate) fn write_off<const N: usize>(w: &mut impl Write, mesh: &Mesh<N>) -> std::io::Result<()> {
    writeln!(w, "OFF")?;
    writeln!(w, "{} {} 0", mesh.vertex_count, mesh.faces.len())?;
    let mut buf = String::with_capacity(96);
    for i in 0..mesh.vertex_count {
        buf.clear();
        fmt_f64_triple(&mut buf, mesh.positions.as_ref().and_then(|p| p.get(i)));
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
    Ok(())
}
