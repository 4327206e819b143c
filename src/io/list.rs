//! The surface-list format of published enumerations of small triangulations
//! (the published lists of `tests/data/irreducible/*.txt`): one surface per non-blank line,
//! `NAME: [[a,b,c],[d,e,f],...]`, vertices numbered from 0, each triple a triangle.
//!
//! Guarantees: any input text gives either every surface of the file, in file order, or a
//! [`ReadError`] at the 1-based line of the first malformed entry; nothing panics, and no
//! allocation exceeds the size of the text. Manifoldness is not checked here (build a
//! [`Triangulation`](crate::Triangulation) from the faces for that).

use std::path::Path;

use super::error::{ReadError, ReadErrorKind};

/// One named surface of a list: a face list over the vertices `0..vertex_count`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NamedSurface {
    /// The name before the colon, trimmed (e.g. `torus_T1_n7`).
    pub name: String,
    /// One more than the largest vertex number used (0 for an empty list).
    pub vertex_count: usize,
    /// The triangles in the order written.
    pub faces: Vec<[u32; 3]>,
    /// The 1-based line the surface was read from.
    pub line: usize,
}

/// Reads a surface list from a file. See [`parse_surface_list`].
pub fn read_surface_list(path: &Path) -> Result<Vec<NamedSurface>, ReadError> {
    let text = std::fs::read_to_string(path).map_err(|e| {
        ReadError::new(ReadErrorKind::Io(e), super::Location::Unknown).with_path(path)
    })?;
    parse_surface_list(&text).map_err(|e| e.with_path(path))
}

/// Parses a surface list: every non-blank line is `NAME: [[a,b,c],...]`.
///
/// The bracket structure is checked exactly (two levels, triples inside), numbers must fit
/// in `u32`, and names must be non-empty and unique within the file.
pub fn parse_surface_list(text: &str) -> Result<Vec<NamedSurface>, ReadError> {
    let mut out: Vec<NamedSurface> = Vec::new();
    let mut names = std::collections::HashSet::new();
    for (i, raw) in text.lines().enumerate() {
        let line = i + 1;
        let trimmed = raw.trim();
        if trimmed.is_empty() {
            continue;
        }
        let err = |msg: String| ReadError::at_line(ReadErrorKind::List(msg), line);
        let (name, rest) = trimmed
            .split_once(':')
            .ok_or_else(|| err("expected `NAME: [[a,b,c],...]`".into()))?;
        let name = name.trim();
        if name.is_empty() {
            return Err(err("empty surface name".into()));
        }
        if !names.insert(name.to_string()) {
            return Err(err(format!(
                "surface name {name:?} repeats an earlier line"
            )));
        }
        let faces = parse_triples(rest.trim()).map_err(err)?;
        let vertex_count = faces.iter().flatten().max().map_or(0, |&m| m as usize + 1);
        out.push(NamedSurface {
            name: name.to_string(),
            vertex_count,
            faces,
            line,
        });
    }
    Ok(out)
}

/// Parses `[[a,b,c],...]` (white space allowed between tokens).
fn parse_triples(s: &str) -> Result<Vec<[u32; 3]>, String> {
    let mut p = Cursor {
        bytes: s.as_bytes(),
        at: 0,
    };
    p.expect(b'[')?;
    let mut faces = Vec::new();
    if p.peek() == Some(b']') {
        p.at += 1;
    } else {
        loop {
            p.expect(b'[')?;
            let a = p.number()?;
            p.expect(b',')?;
            let b = p.number()?;
            p.expect(b',')?;
            let c = p.number()?;
            p.expect(b']')?;
            faces.push([a, b, c]);
            match p.next_token() {
                Some(b',') => continue,
                Some(b']') => break,
                other => return Err(p.unexpected(other, "`,` or `]`")),
            }
        }
    }
    match p.peek() {
        None => Ok(faces),
        Some(_) => Err(format!(
            "unexpected text after the list at column {}",
            p.at + 1
        )),
    }
}

/// A byte cursor over one list; columns in messages are 1-based within the list text.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Cursor<'_> {
    fn skip_space(&mut self) {
        while self.bytes.get(self.at).is_some_and(u8::is_ascii_whitespace) {
            self.at += 1;
        }
    }

    fn peek(&mut self) -> Option<u8> {
        self.skip_space();
        self.bytes.get(self.at).copied()
    }

    fn next_token(&mut self) -> Option<u8> {
        let b = self.peek();
        if b.is_some() {
            self.at += 1;
        }
        b
    }

    fn unexpected(&self, got: Option<u8>, want: &str) -> String {
        match got {
            Some(b) => format!(
                "expected {want} at column {}, found {:?}",
                self.at,
                char::from(b)
            ),
            None => format!("expected {want}, found the end of the line"),
        }
    }

    fn expect(&mut self, want: u8) -> Result<(), String> {
        match self.next_token() {
            Some(b) if b == want => Ok(()),
            other => Err(self.unexpected(other, &format!("`{}`", char::from(want)))),
        }
    }

    fn number(&mut self) -> Result<u32, String> {
        self.skip_space();
        let start = self.at;
        while self.bytes.get(self.at).is_some_and(u8::is_ascii_digit) {
            self.at += 1;
        }
        if start == self.at {
            let got = self.bytes.get(self.at).copied();
            return Err(self.unexpected(got, "a vertex number"));
        }
        // The slice holds ASCII digits only, so it is valid UTF-8.
        let digits = std::str::from_utf8(&self.bytes[start..self.at]).unwrap_or("");
        digits.parse::<u32>().map_err(|_| {
            format!(
                "vertex number {digits} at column {} does not fit in u32",
                start + 1
            )
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::Location;

    #[test]
    fn reads_names_faces_and_lines() {
        let text = "\nA: [[0,1,2],[0,2,3]]\n\n B : [ [ 4 , 5 , 6 ] ]\nC: []\n";
        let l = parse_surface_list(text).expect("valid");
        assert_eq!(l.len(), 3);
        assert_eq!(l[0].name, "A");
        assert_eq!(l[0].faces, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!((l[0].vertex_count, l[0].line), (4, 2));
        assert_eq!(
            (l[1].name.as_str(), l[1].vertex_count, l[1].line),
            ("B", 7, 4)
        );
        assert_eq!((l[2].faces.len(), l[2].vertex_count), (0, 0));
    }

    #[test]
    fn malformed_lines_are_reported_at_their_line() {
        for (text, line, needle) in [
            ("A: [[0,1,2]]\nno colon here", 2, "NAME"),
            ("A: [[0,1,2]]\n: [[0,1,2]]", 2, "empty surface name"),
            ("A: [[0,1,2]]\nA: [[0,1,2]]", 2, "repeats"),
            ("A: [[0,1]]", 1, "`,`"),
            ("A: [[0,1,2,3]]", 1, "`]`"),
            ("A: [[0,1,2]", 1, "end of the line"),
            ("A: [[0,1,2]] x", 1, "after the list"),
            ("A: [[0,-1,2]]", 1, "vertex number"),
            ("A: [[0,1,99999999999]]", 1, "u32"),
            ("A: [0,1,2]", 1, "`[`"),
        ] {
            let e = parse_surface_list(text).expect_err(text);
            assert_eq!(e.location, Location::Line(line), "{text}");
            assert!(e.to_string().contains(needle), "{text}: {e}");
        }
    }
}
