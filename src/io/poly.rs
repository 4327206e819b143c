//! Polygon meshes as files hold them: faces with any number (at least 3) of corners,
//! with the file line of each face when the format is text.
//!
//! The library's algorithms work on triangle meshes ([`TriMesh`]); a [`PolyMesh`] is what
//! the readers produce before that restriction is applied, so that a quad file can be
//! described ([`crate::diagnose`]) or triangulated ([`PolyMesh::triangulated`]) rather
//! than refused.

use super::error::{Location, ReadError, ReadErrorKind as K};
use crate::mesh::{Mesh, TriMesh};

/// An indexed mesh whose faces have 3 or more corners each, with where each face came
/// from in its file.
///
/// Guarantees (for meshes from the readers): every corner is `< vertex_count`; every face
/// has at least 3 corners; `positions`, when present, has `vertex_count` entries;
/// `face_line(i)` is the 1-based line of face `i` for text formats (OFF, OBJ, ascii PLY).
/// Faces are stored flat: one `u32` per corner, and, once a face has more than 3
/// corners, one per face for where it ends; so a triangle file costs what its
/// [`TriMesh`] does.
#[derive(Clone, Debug, PartialEq)]
pub struct PolyMesh {
    /// Number of vertices.
    pub vertex_count: usize,
    /// Vertex coordinates, if the file has any.
    pub positions: Option<Vec<[f64; 3]>>,
    /// Corners of all faces, face after face.
    corners: Vec<u32>,
    /// `ends[i]` is one past the last corner of face `i`; empty while every face is a
    /// triangle (face `i` is then `corners[3i..3i + 3]`), which saves 4 bytes a face
    /// on the meshes nearly every file holds.
    ends: Vec<u32>,
    /// The 1-based file line of each face (text formats only).
    lines: Option<Vec<u32>>,
    /// Whether the file numbers vertices and faces from 1 (OBJ).
    one_based: bool,
    /// The first face with more than 3 corners, with its most precise location.
    first_polygon: Option<(usize, u64, Location)>,
    /// OBJ statements the reader did not use (see [`SkippedStatements`]).
    pub(crate) skipped: SkippedStatements,
}

/// How many of each OBJ statement the reader skipped without using it (`l`, `p`, curves,
/// anything unknown; the statements it knows and deliberately ignores, `vn`, `vt`, `vp`,
/// `o`, `g`, `s`, `usemtl`, `mtllib`, are not counted).
///
/// Guarantees: at most [`SkippedStatements::MAX_KINDS`] keywords are kept, in order of
/// first appearance; the rest are added up in `others`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SkippedStatements {
    /// `(keyword, count, first line)` per kept keyword.
    pub kinds: Vec<(String, usize, usize)>,
    /// Skipped statements whose keyword is not kept.
    pub others: usize,
}

impl SkippedStatements {
    /// How many distinct keywords are kept.
    pub const MAX_KINDS: usize = 8;

    /// Counts one skipped statement.
    pub(crate) fn add(&mut self, keyword: &[u8], line: usize) {
        if let Some(k) = self.kinds.iter_mut().find(|k| k.0.as_bytes() == keyword) {
            k.1 += 1;
        } else if self.kinds.len() < Self::MAX_KINDS {
            let kw = super::error::token_string(keyword);
            self.kinds.push((kw, 1, line));
        } else {
            self.others += 1;
        }
    }

    /// Total number of skipped statements.
    pub fn total(&self) -> usize {
        self.kinds.iter().map(|k| k.1).sum::<usize>() + self.others
    }
}

/// How many fan starts [`PolyMesh::triangulated`] tries for one polygon (bounding its
/// work on polygons with very many corners).
pub const MAX_FAN_STARTS: usize = 8;

/// Which vertex pairs are edges while [`PolyMesh::triangulated`] cuts polygons: the
/// polygon sides, bucketed under their smaller endpoint (a counting sort), plus the
/// diagonals cut so far, in a list per smaller endpoint. About 8 bytes per corner.
struct EdgeIndex {
    /// Sides at smaller endpoint `a`: `side_other[side_start[a]..side_start[a + 1]]`.
    side_start: Vec<u32>,
    side_other: Vec<u32>,
    /// Diagonals at smaller endpoint `a`: a list from `diag_head[a]` through `diag_next`.
    diag_head: Vec<u32>,
    diag_next: Vec<u32>,
    diag_other: Vec<u32>,
}

impl EdgeIndex {
    const NIL: u32 = u32::MAX;

    fn new(m: &PolyMesh) -> Self {
        let n = m.vertex_count;
        let sides = || {
            m.faces().flat_map(|f| {
                (0..f.len()).map(move |j| {
                    let (a, b) = (f[j], f[(j + 1) % f.len()]);
                    (a.min(b), a.max(b))
                })
            })
        };
        let mut side_start = vec![0u32; n + 1];
        for (a, _) in sides() {
            // Corners are < vertex_count for meshes from the readers; others are skipped.
            if let Some(c) = side_start.get_mut(a as usize + 1) {
                *c += 1;
            }
        }
        for i in 0..n {
            side_start[i + 1] += side_start[i];
        }
        let mut fill = side_start.clone();
        let mut side_other = vec![0u32; side_start[n] as usize];
        for (a, b) in sides() {
            if let Some(slot) = fill.get_mut(a as usize) {
                side_other[*slot as usize] = b;
                *slot += 1;
            }
        }
        EdgeIndex {
            side_start,
            side_other,
            diag_head: vec![Self::NIL; n],
            diag_next: Vec::new(),
            diag_other: Vec::new(),
        }
    }

    /// Whether `[a, b]` is a side or a diagonal cut so far (true for `a == b`, which is
    /// no diagonal either).
    fn contains(&self, a: u32, b: u32) -> bool {
        let (a, b) = (a.min(b), a.max(b));
        if a == b {
            return true;
        }
        let (Some(&lo), Some(&hi)) = (
            self.side_start.get(a as usize),
            self.side_start.get(a as usize + 1),
        ) else {
            return false;
        };
        if self.side_other[lo as usize..hi as usize].contains(&b) {
            return true;
        }
        let mut d = self.diag_head[a as usize];
        while d != Self::NIL {
            if self.diag_other[d as usize] == b {
                return true;
            }
            d = self.diag_next[d as usize];
        }
        false
    }

    fn add(&mut self, a: u32, b: u32) {
        let (a, b) = (a.min(b), a.max(b));
        let Some(head) = self.diag_head.get_mut(a as usize) else {
            return;
        };
        self.diag_next.push(*head);
        self.diag_other.push(b);
        *head = (self.diag_other.len() - 1) as u32;
    }
}

/// A triangle mesh made from a [`PolyMesh`], with the polygon each triangle comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct Triangulated {
    /// The triangles, polygon after polygon, each polygon's triangles in fan order.
    pub mesh: TriMesh,
    /// `origin[t]` is the polygon face triangle `t` was cut from.
    pub origin: Vec<u32>,
    /// How many faces had more than 3 corners.
    pub polygons: usize,
}

impl PolyMesh {
    /// An empty mesh on `vertex_count` vertices, ready for a reader to fill.
    pub(crate) fn new(
        vertex_count: usize,
        positions: Option<Vec<[f64; 3]>>,
        text: bool,
        one_based: bool,
    ) -> Self {
        PolyMesh {
            vertex_count,
            positions,
            corners: Vec::new(),
            ends: Vec::new(),
            lines: text.then(Vec::new),
            one_based,
            first_polygon: None,
            skipped: SkippedStatements::default(),
        }
    }

    /// A mesh from face lists (no file lines, 0-based numbering). Faces with fewer than
    /// 3 corners are an error naming the first; indices are *not* checked here (the
    /// validation reports them).
    pub fn from_faces<F: AsRef<[u32]>>(
        vertex_count: usize,
        positions: Option<Vec<[f64; 3]>>,
        faces: impl IntoIterator<Item = F>,
    ) -> Result<Self, ReadError> {
        let mut m = PolyMesh::new(vertex_count, positions, false, false);
        for (i, f) in faces.into_iter().enumerate() {
            m.push_face(f.as_ref(), Location::Face(i))?;
        }
        Ok(m)
    }

    /// Reserves room for `faces` more faces (of 3 corners).
    pub(crate) fn reserve(&mut self, faces: usize) {
        if self.first_polygon.is_some() {
            self.ends.reserve(faces);
        }
        self.corners.reserve(faces.saturating_mul(3));
        if let Some(l) = &mut self.lines {
            l.reserve(faces);
        }
    }

    /// Appends a face read at `at` (its line when text). Faces with fewer than 3 corners
    /// are refused (`NonTriangleFace`); more corners than `u32` can count are refused.
    pub(crate) fn push_face(&mut self, corners: &[u32], at: Location) -> Result<(), ReadError> {
        let face = self.face_count();
        if corners.len() < 3 {
            return Err(ReadError::new(
                K::NonTriangleFace {
                    face: self.number(face),
                    corners: corners.len() as u64,
                },
                at,
            ));
        }
        if corners.len() > 3 && self.first_polygon.is_none() {
            self.first_polygon = Some((face, corners.len() as u64, at));
            // The faces so far are triangles: their ends, written out now. They fit
            // `u32`, as the corner count does.
            self.ends = (1..=face).map(|i| (3 * i) as u32).collect();
        }
        self.corners.extend_from_slice(corners);
        let end = u32::try_from(self.corners.len()).map_err(|_| {
            ReadError::new(
                K::CountTooLarge {
                    what: "face corners",
                    declared: self.corners.len() as u64,
                },
                at,
            )
        })?;
        if self.first_polygon.is_some() {
            self.ends.push(end);
        }
        if let (Some(lines), Location::Line(n)) = (&mut self.lines, at) {
            lines.push(u32::try_from(n).unwrap_or(u32::MAX));
        }
        Ok(())
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        if self.first_polygon.is_none() {
            self.corners.len() / 3
        } else {
            self.ends.len()
        }
    }

    /// The corners of face `i` (empty if there is no such face).
    pub fn face(&self, i: usize) -> &[u32] {
        if self.first_polygon.is_none() {
            let start = i.saturating_mul(3);
            return self
                .corners
                .get(start..start.saturating_add(3))
                .unwrap_or(&[]);
        }
        let start = match i.checked_sub(1) {
            None => 0,
            Some(j) => self.ends.get(j).map_or(0, |&e| e as usize),
        };
        let end = self.ends.get(i).map_or(start, |&e| e as usize);
        self.corners.get(start..end).unwrap_or(&[])
    }

    /// The faces in file order.
    pub fn faces(&self) -> impl Iterator<Item = &[u32]> + '_ {
        (0..self.face_count()).map(|i| self.face(i))
    }

    /// The 1-based file line of face `i` (text formats).
    pub fn face_line(&self, i: usize) -> Option<usize> {
        self.lines.as_ref()?.get(i).map(|&n| n as usize)
    }

    /// Whether the file numbers vertices and faces from 1 (OBJ): messages about it should
    /// too.
    pub fn one_based(&self) -> bool {
        self.one_based
    }

    /// Face `i` as the file counts it (`i + 1` for OBJ).
    pub fn number(&self, i: usize) -> usize {
        i + usize::from(self.one_based)
    }

    /// Whether every face is a triangle.
    pub fn is_triangle_mesh(&self) -> bool {
        self.first_polygon.is_none()
    }

    /// The smallest and largest corner counts of a face (`(0, 0)` without faces).
    pub fn corner_range(&self) -> (usize, usize) {
        let mut r: Option<(usize, usize)> = None;
        for f in self.faces() {
            let n = f.len();
            r = Some(r.map_or((n, n), |(a, b)| (a.min(n), b.max(n))));
        }
        r.unwrap_or((0, 0))
    }

    /// OBJ statements the reader skipped.
    pub fn skipped_statements(&self) -> &SkippedStatements {
        &self.skipped
    }

    /// The triangle mesh, when every face is a triangle; otherwise `NonTriangleFace`
    /// naming the first polygon (as the file numbers it) at its line or byte offset.
    pub fn into_tri_mesh(self) -> Result<TriMesh, ReadError> {
        if let Some((face, corners, at)) = self.first_polygon {
            return Err(ReadError::new(
                K::NonTriangleFace {
                    face: self.number(face),
                    corners,
                },
                at,
            ));
        }
        // Every face is a triangle, so the corner list read three at a time is the face
        // list: its allocation is reused when its capacity is a whole number of faces
        // (after the readers' exact reservations, or once shrunk), which saves writing a
        // second copy of the largest array; otherwise it is copied.
        let mut corners = self.corners;
        if corners.capacity() % 3 != 0 {
            corners.shrink_to_fit();
        }
        let faces = bytemuck::allocation::try_cast_vec::<u32, [u32; 3]>(corners)
            .unwrap_or_else(|(_, c)| c.chunks_exact(3).map(|c| [c[0], c[1], c[2]]).collect());
        Ok(Mesh {
            vertex_count: self.vertex_count,
            positions: self.positions,
            faces,
        })
    }

    /// Every face cut into triangles, orientation kept, without creating an edge twice
    /// where that can be avoided: a quad along its shorter diagonal (corners 0–2 unless
    /// 1–3 is strictly shorter; 0–2 without positions), any other polygon as a fan from
    /// its first corner; but if that cut's diagonals include a vertex pair that is
    /// already an edge (a polygon side, or a diagonal of an earlier polygon), the first
    /// other start (of the first `MAX_FAN_STARTS`) whose diagonals are all new is
    /// taken instead. So a closed quad surface whose quads can be cut into a
    /// triangulated surface greedily is (the shorter-diagonal rule alone folds coarse
    /// meshes: on a 288-quad torus it made 48 duplicate faces). Triangles keep the
    /// polygons' order; deterministic. O(corners) for bounded polygon sizes and vertex
    /// degrees.
    pub fn triangulated(&self) -> Triangulated {
        let mut faces =
            Vec::with_capacity(self.corners.len().saturating_sub(2 * self.face_count()));
        let mut origin = Vec::with_capacity(faces.capacity());
        let mut polygons = 0;
        let mut edges = EdgeIndex::new(self);
        for (i, f) in self.faces().enumerate() {
            let k = f.len();
            if k > 3 {
                polygons += 1;
            }
            let preferred = if k == 4 && self.shorter_diagonal_is_13(f) {
                1
            } else {
                0
            };
            let fan_is_new = |s: usize| (2..k - 1).all(|j| !edges.contains(f[s], f[(s + j) % k]));
            let start = if k <= 3 || fan_is_new(preferred) {
                preferred
            } else {
                (0..k.min(MAX_FAN_STARTS))
                    .find(|&s| s != preferred && fan_is_new(s))
                    .unwrap_or(preferred)
            };
            for j in 2..k.saturating_sub(1) {
                edges.add(f[start], f[(start + j) % k]);
            }
            for j in 1..k - 1 {
                faces.push([f[start], f[(start + j) % k], f[(start + j + 1) % k]]);
                // Face numbers fit u32: the corner count does.
                origin.push(i as u32);
            }
        }
        Triangulated {
            mesh: Mesh {
                vertex_count: self.vertex_count,
                positions: self.positions.clone(),
                faces,
            },
            origin,
            polygons,
        }
    }

    /// For a quad `f`: whether the diagonal from corner 1 to 3 is strictly shorter than
    /// the one from 0 to 2 (false without positions).
    fn shorter_diagonal_is_13(&self, f: &[u32]) -> bool {
        let Some(p) = &self.positions else {
            return false;
        };
        let at = |i: usize| p.get(f[i] as usize);
        let (Some(a), Some(b), Some(c), Some(d)) = (at(0), at(1), at(2), at(3)) else {
            return false;
        };
        let d2 = |x: &[f64; 3], y: &[f64; 3]| {
            (x[0] - y[0]).powi(2) + (x[1] - y[1]).powi(2) + (x[2] - y[2]).powi(2)
        };
        d2(b, d) < d2(a, c)
    }

    /// The mesh with its corners renamed by `new_id` (welding), `vertex_count` and
    /// `positions` replaced. `None` if a corner has no entry in `new_id`.
    pub(crate) fn renamed(
        &self,
        new_id: &[u32],
        vertex_count: usize,
        positions: Option<Vec<[f64; 3]>>,
    ) -> Option<Self> {
        let corners = self
            .corners
            .iter()
            .map(|&v| new_id.get(v as usize).copied())
            .collect::<Option<Vec<_>>>()?;
        Some(PolyMesh {
            vertex_count,
            positions,
            corners,
            ends: self.ends.clone(),
            lines: self.lines.clone(),
            one_based: self.one_based,
            first_polygon: self.first_polygon,
            skipped: self.skipped.clone(),
        })
    }

    /// The 1-based file line of every face (text formats).
    pub fn lines(&self) -> Option<&[u32]> {
        self.lines.as_deref()
    }

    /// The mesh with its vertices merged by `map` (from [`crate::mesh::weld_map`] of its
    /// positions): corners renamed, positions those of the kept vertices, faces and their
    /// lines unchanged. `None` if a corner or a kept vertex has no entry in the map or
    /// the positions.
    pub fn welded_by(&self, map: &crate::mesh::WeldMap) -> Option<Self> {
        let positions = match &self.positions {
            Some(p) => Some(
                map.kept
                    .iter()
                    .map(|&v| p.get(v as usize).copied())
                    .collect::<Option<Vec<_>>>()?,
            ),
            None => None,
        };
        self.renamed(&map.new_id, map.kept.len(), positions)
    }

    /// The mesh with vertices merged as [`Mesh::welded_within`] does (`tolerance` 0:
    /// bitwise-equal positions), and the number of vertices merged away. A mesh without
    /// positions is returned unchanged. `None` if a corner is out of range or
    /// `tolerance` is negative or not finite.
    pub fn welded_within(&self, tolerance: f64) -> Option<(Self, usize)> {
        let Some(p) = &self.positions else {
            return self
                .corners
                .iter()
                .all(|&v| (v as usize) < self.vertex_count)
                .then(|| (self.clone(), 0));
        };
        let w = crate::mesh::weld_map(p, tolerance)?;
        let kept: Vec<[f64; 3]> = w.kept.iter().map(|&v| p[v as usize]).collect();
        let merged = self.vertex_count - kept.len();
        let n = kept.len();
        Some((self.renamed(&w.new_id, n, Some(kept))?, merged))
    }
}

impl From<TriMesh> for PolyMesh {
    /// The triangle mesh as a polygon mesh (no file lines, 0-based numbering).
    fn from(m: TriMesh) -> Self {
        PolyMesh {
            vertex_count: m.vertex_count,
            positions: m.positions,
            corners: m.faces.into_iter().flatten().collect(),
            ends: Vec::new(),
            lines: None,
            one_based: false,
            first_polygon: None,
            skipped: SkippedStatements::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Skipped statements are counted per keyword, eight keywords at most in order of
    /// first appearance (with the line of the first), the rest added up together.
    #[test]
    fn skipped_statements_keep_eight_keywords_and_add_up_the_rest() {
        let mut skipped = SkippedStatements::default();
        let keywords: [&[u8]; 10] = [
            b"l", b"p", b"curv", b"l", b"k0", b"k1", b"k2", b"k3", b"k4", b"k5",
        ];
        for (line, kw) in keywords.iter().enumerate() {
            skipped.add(kw, line + 1);
        }
        // `k5` is the ninth distinct keyword; more `l` and `k5` after it.
        skipped.add(b"l", 20);
        skipped.add(b"k5", 21);
        skipped.add(b"k6", 22);
        let kept: Vec<(&str, usize, usize)> = skipped
            .kinds
            .iter()
            .map(|(k, n, l)| (k.as_str(), *n, *l))
            .collect();
        assert_eq!(
            kept,
            [
                ("l", 3, 1),
                ("p", 1, 2),
                ("curv", 1, 3),
                ("k0", 1, 5),
                ("k1", 1, 6),
                ("k2", 1, 7),
                ("k3", 1, 8),
                ("k4", 1, 9),
            ]
        );
        assert_eq!(skipped.others, 3);
        assert_eq!(skipped.total(), 13);
    }

    /// Faces read back as given, whether every face is a triangle (no face ends kept)
    /// or polygons come first, after triangles, or between them.
    #[test]
    fn faces_read_back_as_given_with_or_without_polygons() {
        let tri = |k: u32| vec![k, k + 1, k + 2];
        let cases: Vec<Vec<Vec<u32>>> = vec![
            vec![],
            vec![tri(0), tri(3), tri(6)],
            vec![vec![0, 1, 2, 3], tri(4), tri(7)],
            vec![
                tri(0),
                tri(3),
                vec![6, 7, 8, 9, 10],
                tri(1),
                vec![2, 3, 4, 5],
            ],
            vec![tri(0), vec![1, 2, 3, 4]],
        ];
        for faces in cases {
            let m = PolyMesh::from_faces(12, None, &faces).expect("faces of 3 or more");
            let triangles = faces.iter().all(|f| f.len() == 3);
            assert_eq!(m.face_count(), faces.len(), "{faces:?}");
            assert!(m.faces().eq(faces.iter().map(|f| &f[..])), "{faces:?}");
            assert_eq!(m.face(faces.len()), &[] as &[u32], "{faces:?}");
            assert_eq!(m.is_triangle_mesh(), triangles, "{faces:?}");
            assert_eq!(m.ends.capacity() == 0, triangles, "{faces:?}");
            let (lo, hi) = m.corner_range();
            let lens = faces.iter().map(Vec::len);
            assert_eq!(
                (lo, hi),
                (lens.clone().min().unwrap_or(0), lens.max().unwrap_or(0))
            );
        }
    }

    /// A triangle-only polygon mesh becomes the triangle mesh of its faces in order,
    /// whatever capacity its corner list grew to (reused or copied).
    #[test]
    fn triangles_become_the_face_list_whatever_the_corner_capacity() {
        for faces in 0..40u32 {
            for reserve in [0, faces as usize, faces as usize + 1] {
                let mut m = PolyMesh::new(faces as usize + 2, None, false, false);
                m.reserve(reserve);
                let want: Vec<[u32; 3]> = (0..faces).map(|i| [i, i + 1, i + 2]).collect();
                for f in &want {
                    m.push_face(f, Location::Unknown).expect("a triangle");
                }
                // The readers' reservation holds every face they announce.
                assert!(m.corners.capacity() >= 3 * reserve, "{reserve} reserved");
                let capacity = m.corners.capacity();
                let exact = capacity == 3 * faces as usize && faces > 0;
                let before = m.corners.as_ptr() as usize;
                let t = m.into_tri_mesh().expect("triangles only");
                assert_eq!(t.faces, want, "{faces} faces, {reserve} reserved");
                if exact {
                    assert_eq!(t.faces.as_ptr() as usize, before, "an exact list is reused");
                }
                // A capacity of whole faces is kept as it is, not shrunk.
                if capacity % 3 == 0 {
                    assert_eq!(t.faces.capacity(), capacity / 3, "{faces}, {reserve}");
                }
            }
        }
    }

    #[test]
    fn quads_are_cut_along_the_shorter_diagonal_and_polygons_fanned() {
        // A unit square stretched along x: diagonal 0-2 and 1-3 equal -> 0-2; then a
        // kite whose 1-3 diagonal is shorter.
        let p = vec![
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
            [-5.0, 0.5, 0.0],
        ];
        // Alone, the kite is cut along its shorter diagonal [0, 3].
        let kite = PolyMesh::from_faces(5, Some(p.clone()), [vec![4, 0, 2, 3]]).unwrap();
        assert_eq!(kite.triangulated().mesh.faces, vec![[0, 2, 3], [0, 3, 4]]);
        let m = PolyMesh::from_faces(
            5,
            Some(p),
            [vec![0, 1, 2, 3], vec![4, 0, 2, 3], vec![0, 1, 2, 3, 4]],
        )
        .unwrap();
        assert!(!m.is_triangle_mesh());
        assert_eq!(m.corner_range(), (4, 5));
        let t = m.triangulated();
        assert_eq!(
            t.mesh.faces,
            vec![
                // Equal diagonals prefer 0-2, but [0, 2] is a side of face 1: cut 1-3.
                [1, 2, 3],
                [1, 3, 0],
                // |0-3| = 1 < |4-2| = 7.02 prefers corner 1 (vertex 0), but [0, 3] is a
                // side of face 0: the other diagonal [4, 2] is new.
                [4, 0, 2],
                [4, 2, 3],
                // Every fan of the pentagon cuts an existing pair (these faces are not a
                // surface): the first corner's fan is kept.
                [0, 1, 2],
                [0, 2, 3],
                [0, 3, 4]
            ]
        );
        assert_eq!(t.origin, vec![0, 0, 1, 1, 2, 2, 2]);
        assert_eq!(t.polygons, 3);
        let e = m.clone().into_tri_mesh().unwrap_err();
        assert!(matches!(
            e.kind,
            K::NonTriangleFace {
                face: 0,
                corners: 4
            }
        ));
        assert!(PolyMesh::from_faces(3, None, [vec![0, 1]]).is_err());
    }

    /// A quad alone is cut along its strictly shorter diagonal (0–2 on a tie), on random
    /// quads in space against the squared lengths summed here coordinate by coordinate.
    #[test]
    fn a_lone_quad_is_cut_along_its_shorter_diagonal_in_space() {
        let mut rng = crate::rng::Rng::new(7);
        let mut coordinate = || rng.index(9) as f64 - 4.0;
        let (mut along_13, mut ties) = (0, 0);
        for _ in 0..2000 {
            let p: Vec<[f64; 3]> = (0..4)
                .map(|_| [coordinate(), coordinate(), coordinate()])
                .collect();
            let length2 = |i: usize, j: usize| -> f64 {
                (0..3)
                    .map(|c| (p[i][c] - p[j][c]) * (p[i][c] - p[j][c]))
                    .sum()
            };
            let want = if length2(1, 3) < length2(0, 2) {
                along_13 += 1;
                vec![[1, 2, 3], [1, 3, 0]]
            } else {
                ties += usize::from(length2(1, 3) == length2(0, 2));
                vec![[0, 1, 2], [0, 2, 3]]
            };
            let quad = PolyMesh::from_faces(4, Some(p.clone()), [vec![0, 1, 2, 3]]).unwrap();
            assert_eq!(quad.triangulated().mesh.faces, want, "{p:?}");
        }
        assert!(
            along_13 > 500 && ties > 10,
            "{along_13} cut 1-3, {ties} ties"
        );
    }

    /// The diagonals a fan cuts count as existing edges for the polygons after it: a
    /// pentagon's, then a hexagon's, push later quads to their other diagonal.
    #[test]
    fn diagonals_of_fanned_polygons_steer_later_cuts() {
        // No positions, so every quad prefers its diagonal from corner 0.
        let m = PolyMesh::from_faces(
            12,
            None,
            [
                vec![0, 1, 2, 3, 4],
                vec![0, 7, 2, 8],
                vec![0, 9, 3, 10],
                vec![5, 6, 11, 1, 4, 9],
                vec![5, 2, 1, 10],
            ],
        )
        .unwrap();
        let t = m.triangulated();
        assert_eq!(
            t.mesh.faces,
            vec![
                // The pentagon fans from 0: diagonals 0-2 and 0-3.
                [0, 1, 2],
                [0, 2, 3],
                [0, 3, 4],
                // 0-2 is the pentagon's diagonal: 7-8 instead.
                [7, 2, 8],
                [7, 8, 0],
                // 0-3 likewise: 9-10.
                [9, 3, 10],
                [9, 10, 0],
                // The hexagon fans from 5: 5-11, 5-1, 5-4, all new.
                [5, 6, 11],
                [5, 11, 1],
                [5, 1, 4],
                [5, 4, 9],
                // 5-1 is the hexagon's diagonal: 2-10 instead.
                [2, 1, 10],
                [2, 10, 5],
            ]
        );
        assert_eq!(t.polygons, 5);
    }

    /// Without positions, welding changes nothing but checks the corners: `None` as soon
    /// as one is not below the vertex count.
    #[test]
    fn welding_without_positions_checks_the_corners() {
        let m = PolyMesh::from_faces(4, None, [vec![0, 1, 2, 3]]).unwrap();
        assert_eq!(m.welded_within(0.0), Some((m.clone(), 0)));
        for corner in [4, 5] {
            let mut bad = m.clone();
            bad.corners[3] = corner;
            assert_eq!(bad.welded_within(0.0), None, "corner {corner}");
        }
    }

    #[test]
    fn triangle_meshes_convert_both_ways() {
        let t = TriMesh::combinatorial(4, vec![[0, 1, 2], [0, 2, 3]]);
        let p = PolyMesh::from(t.clone());
        assert!(p.is_triangle_mesh());
        assert_eq!(p.face(1), &[0, 2, 3]);
        assert_eq!(p.face(2), &[] as &[u32]);
        assert_eq!(p.triangulated().mesh, t);
        assert_eq!(p.into_tri_mesh().unwrap(), t);
    }
}
