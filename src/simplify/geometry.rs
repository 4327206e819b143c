//! The geometry of the simplifier: lengths, the new vertex's position (midpoint or the
//! Garland–Heckbert quadric optimum) and the fold-over guard.
//!
//! Everything here is plain `f64` arithmetic on positions that the caller has checked to
//! be finite; nothing here decides topology.

/// A point or vector in space.
pub type Point = [f64; 3];

#[inline]
pub(crate) fn sub(a: Point, b: Point) -> Point {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

#[inline]
pub(crate) fn dot(a: Point, b: Point) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline]
pub(crate) fn cross(a: Point, b: Point) -> Point {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[inline]
pub(crate) fn dist2(a: Point, b: Point) -> f64 {
    let d = sub(a, b);
    dot(d, d)
}

#[inline]
pub(crate) fn midpoint(a: Point, b: Point) -> Point {
    [
        0.5 * (a[0] + b[0]),
        0.5 * (a[1] + b[1]),
        0.5 * (a[2] + b[2]),
    ]
}

/// Twice the area vector of triangle `abc` (its normal scaled by twice its area).
#[inline]
pub(crate) fn area_normal(a: Point, b: Point, c: Point) -> Point {
    cross(sub(b, a), sub(c, a))
}

pub(crate) use crate::mesh::power_of_two_scale;

/// The diagonal of the axis-aligned bounding box of `points` (0 for no point; infinite
/// only when it exceeds the `f64` range). Computed on the box's sides scaled by a power
/// of two, so that their squares neither overflow nor underflow: exactly the plain
/// formula's value wherever that one stays in the normal range.
pub fn bbox_diagonal(points: impl IntoIterator<Item = Point>) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let mut any = false;
    for p in points {
        any = true;
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    if !any {
        return 0.0;
    }
    let sides = sub(hi, lo);
    let s = power_of_two_scale(sides.iter().fold(0.0f64, |m, x| m.max(x.abs())));
    let scaled = sides.map(|x| x * s);
    dot(scaled, scaled).sqrt() / s
}

/// Relative size below which a triangle counts as having zero area: `|n| ≤ ZERO_AREA ·
/// L²`, with `n` twice the area vector and `L` its longest edge (a sliver whose height
/// is below `ZERO_AREA / 2` of its longest edge).
pub const ZERO_AREA: f64 = 1e-10;

/// The fold-over guard for one triangle that moves: `old` is its area normal before,
/// `new_corners` its corners after. Refuses (returns `false`) a triangle of zero area
/// after the move, and one whose normal turns by 90° or more (when it had a normal
/// before: a triangle that was already degenerate only has to end non-degenerate). The
/// reference form of [`fan_move_ok`], which the guard calls.
#[cfg(test)]
pub(crate) fn moved_triangle_ok(old: Point, new_corners: [Point; 3]) -> bool {
    let [a, b, c] = new_corners;
    let n = area_normal(a, b, c);
    let l2 = dist2(a, b).max(dist2(b, c)).max(dist2(c, a));
    let n2 = dot(n, n);
    if n2 <= ZERO_AREA * ZERO_AREA * l2 * l2 {
        return false;
    }
    let old_l2 = dot(old, old);
    old_l2 == 0.0 || dot(old, n) > 0.0
}

/// `moved_triangle_ok` (the reference form, compiled for tests) for the triangle `(x, p1, p2)` whose corner `x` moves to `to`,
/// the form the guard calls: both normals share the edge `e = p2 − p1` (the normal of
/// `(y, p1, p2)` is `(p1 − y) × e`), and the longest edge is only computed when the
/// cheap bound `L² ≤ 2 (|e|² + |p1 − to|²)` cannot rule out a zero area.
#[inline]
pub(crate) fn fan_move_ok(x: Point, to: Point, p1: Point, p2: Point) -> bool {
    let e = sub(p2, p1);
    let old = cross(sub(p1, x), e);
    let d = sub(p1, to);
    let n = cross(d, e);
    let n2 = dot(n, n);
    let bound = 2.0 * (dot(e, e) + dot(d, d));
    if n2 <= ZERO_AREA * ZERO_AREA * bound * bound {
        let l2 = dot(d, d).max(dot(e, e)).max(dist2(p2, to));
        if n2 <= ZERO_AREA * ZERO_AREA * l2 * l2 {
            return false;
        }
    }
    dot(old, old) == 0.0 || dot(old, n) > 0.0
}

/// A symmetric 4×4 error quadric `Q` (Garland–Heckbert): the squared distance of a point
/// to a weighted set of planes is `[p 1] Q [p 1]ᵀ`. Stored as its upper triangle.
#[derive(Copy, Clone, Debug, Default, PartialEq)]
pub struct Quadric([f64; 10]);

impl Quadric {
    /// The quadric of the plane through `p` with unit normal `n`, times `weight`.
    pub fn plane(n: Point, p: Point, weight: f64) -> Self {
        let d = -dot(n, p);
        let [a, b, c] = n;
        Quadric(
            [
                a * a,
                a * b,
                a * c,
                a * d,
                b * b,
                b * c,
                b * d,
                c * c,
                c * d,
                d * d,
            ]
            .map(|x| x * weight),
        )
    }

    /// Adds `other` to this quadric.
    pub fn add(&mut self, other: &Quadric) {
        for (x, y) in self.0.iter_mut().zip(other.0.iter()) {
            *x += y;
        }
    }

    /// The error `[p 1] Q [p 1]ᵀ` at `p`.
    pub fn error(&self, p: Point) -> f64 {
        let q = &self.0;
        let [x, y, z] = p;
        q[0] * x * x
            + 2.0 * q[1] * x * y
            + 2.0 * q[2] * x * z
            + 2.0 * q[3] * x
            + q[4] * y * y
            + 2.0 * q[5] * y * z
            + 2.0 * q[6] * y
            + q[7] * z * z
            + 2.0 * q[8] * z
            + q[9]
    }

    /// The point minimising the error, if the 3×3 system is well conditioned (its
    /// determinant is not negligible against the cube of its mean diagonal entry).
    pub fn minimiser(&self) -> Option<Point> {
        let q = &self.0;
        let m = [[q[0], q[1], q[2]], [q[1], q[4], q[5]], [q[2], q[5], q[7]]];
        let r = [-q[3], -q[6], -q[8]];
        let det = det3(m);
        let scale = (q[0] + q[4] + q[7]) / 3.0;
        // Also refuses a NaN determinant.
        if det.abs().partial_cmp(&(1e-9 * scale * scale * scale))
            != Some(std::cmp::Ordering::Greater)
        {
            return None;
        }
        // Cramer's rule: the system is 3×3 and its conditioning was just checked.
        let mut out = [0.0; 3];
        for (k, o) in out.iter_mut().enumerate() {
            let mut mk = m;
            for row in 0..3 {
                mk[row][k] = r[row];
            }
            *o = det3(mk) / det;
        }
        out.iter().all(|x| x.is_finite()).then_some(out)
    }

    /// Where the merged vertex of an edge `[p, q]` goes under this (summed) quadric: the
    /// minimiser when it exists, otherwise the best of `p`, `q` and their midpoint
    /// (ties: midpoint, then `p`).
    pub fn best_position(&self, p: Point, q: Point) -> Point {
        self.best_position_within(p, q, f64::MAX)
    }

    /// [`Self::best_position`], the minimiser used only when none of its coordinates
    /// exceeds `bound` in magnitude.
    pub fn best_position_within(&self, p: Point, q: Point, bound: f64) -> Point {
        if let Some(x) = self
            .minimiser()
            .filter(|x| x.iter().all(|c| c.abs() <= bound))
        {
            return x;
        }
        let m = midpoint(p, q);
        let mut best = (self.error(m), m);
        for c in [p, q] {
            let e = self.error(c);
            if e < best.0 {
                best = (e, c);
            }
        }
        best.1
    }
}

fn det3(m: [[f64; 3]; 3]) -> f64 {
    m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadric_of_three_planes_meets_at_their_corner() {
        let mut q = Quadric::default();
        q.add(&Quadric::plane([1.0, 0.0, 0.0], [2.0, 0.0, 0.0], 1.0));
        q.add(&Quadric::plane([0.0, 1.0, 0.0], [0.0, -1.0, 0.0], 2.0));
        q.add(&Quadric::plane([0.0, 0.0, 1.0], [0.0, 0.0, 5.0], 3.0));
        let x = q.minimiser().expect("three independent planes");
        for (a, b) in x.iter().zip([2.0, -1.0, 5.0]) {
            assert!((a - b).abs() < 1e-12, "{x:?}");
        }
        assert!(q.error(x).abs() < 1e-12);
    }

    #[test]
    fn one_plane_is_singular_and_falls_back() {
        let q = Quadric::plane([0.0, 0.0, 1.0], [0.0, 0.0, 0.0], 1.0);
        assert_eq!(q.minimiser(), None);
        // p is on the plane, q is not: p wins over the midpoint.
        let best = q.best_position([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]);
        assert_eq!(best, [0.0, 0.0, 0.0]);
    }

    #[test]
    fn guard_refuses_flips_and_slivers() {
        let (a, b, c) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let n = area_normal(a, b, c);
        assert!(moved_triangle_ok(n, [a, b, [0.2, 0.9, 0.0]]));
        assert!(!moved_triangle_ok(n, [a, b, [0.2, -0.9, 0.0]]));
        assert!(!moved_triangle_ok(n, [a, b, [0.5, 0.0, 0.0]]));
        assert!(moved_triangle_ok([0.0; 3], [a, b, c]));
    }

    #[test]
    fn fan_move_agrees_with_the_plain_guard() {
        // A deterministic sweep of moves around a fixed edge, including slivers.
        let (x, p1, p2) = ([0.1, -0.7, 0.2], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let old = area_normal(x, p1, p2);
        let mut disagree = 0;
        for i in 0..40 {
            for j in 0..40 {
                let to = [
                    -1.0 + 0.05 * i as f64,
                    -1.0 + 0.05 * j as f64,
                    0.01 * (i as f64 - j as f64),
                ];
                if fan_move_ok(x, to, p1, p2) != moved_triangle_ok(old, [to, p1, p2]) {
                    disagree += 1;
                }
            }
        }
        // Exactly on the edge's line (zero area) both refuse; elsewhere they agree.
        assert_eq!(disagree, 0);
        assert!(!fan_move_ok(x, [0.5, 0.5, 0.0], p1, p2));
        assert!(fan_move_ok(x, [0.2, -0.5, 0.0], p1, p2));
        assert!(!fan_move_ok(x, [0.8, 0.9, 0.0], p1, p2));
    }

    /// Small integer vectors whose products and sums are exact in `f64`, with no two
    /// entries alike, so that every operator of the vector functions shows in a result.
    const A: Point = [2.0, 3.0, 5.0];
    const B: Point = [7.0, 11.0, 13.0];
    const C: Point = [-17.0, 19.0, 23.0];

    #[test]
    fn vector_functions_compute_exactly_their_formulas() {
        assert_eq!(sub(A, B), [-5.0, -8.0, -8.0]);
        assert_eq!(dot(A, B), 14.0 + 33.0 + 65.0);
        assert_eq!(cross(A, B), [39.0 - 55.0, 35.0 - 26.0, 22.0 - 21.0]);
        assert_eq!(dist2(A, B), 25.0 + 64.0 + 64.0);
        assert_eq!(midpoint(A, B), [4.5, 7.0, 9.0]);
        assert_eq!(midpoint(C, A), [-7.5, 11.0, 14.0]);
        // (B − A) × (C − A) = (5, 8, 8) × (−19, 16, 18).
        assert_eq!(
            area_normal(A, B, C),
            [144.0 - 128.0, -152.0 - 90.0, 80.0 + 152.0]
        );
    }

    /// `det3` against the cofactor expansion done by hand, on a matrix whose every minor
    /// differs from the others.
    #[test]
    fn det3_is_the_determinant() {
        let m = [A, B, C];
        // 2·(11·23 − 13·19) − 3·(7·23 − 13·(−17)) + 5·(7·19 − 11·(−17))
        assert_eq!(det3(m), 2.0 * 6.0 - 3.0 * 382.0 + 5.0 * 320.0);
        assert_eq!(det3([B, A, C]), -det3(m));
    }

    /// The plane's quadric holds the products of `(a, b, c, d)`, `d = −n·p`, times the
    /// weight; its error is `[x 1] Q [x 1]ᵀ` of the full symmetric matrix.
    #[test]
    fn plane_quadric_entries_and_error() {
        let q = Quadric::plane(A, [1.0, -1.0, 2.0], 3.0);
        // d = −(2 − 3 + 10) = −9.
        let expected = [4.0, 6.0, 10.0, -18.0, 9.0, 15.0, -27.0, 25.0, -45.0, 81.0];
        assert_eq!(q.0, expected.map(|x| 3.0 * x));
        // A quadric with ten different entries, against the 4×4 product.
        let q = Quadric([3.0, -1.0, 2.0, 5.0, 7.0, -4.0, 0.5, 11.0, -6.0, 13.0]);
        let full = [
            [q.0[0], q.0[1], q.0[2], q.0[3]],
            [q.0[1], q.0[4], q.0[5], q.0[6]],
            [q.0[2], q.0[5], q.0[7], q.0[8]],
            [q.0[3], q.0[6], q.0[8], q.0[9]],
        ];
        for x in [[1.0, 2.0, 3.0], [-3.0, 0.5, 2.0], [0.0, 0.0, 0.0]] {
            let h = [x[0], x[1], x[2], 1.0];
            let mut want = 0.0;
            for (i, row) in full.iter().enumerate() {
                for (j, v) in row.iter().enumerate() {
                    want += h[i] * v * h[j];
                }
            }
            assert_eq!(q.error(x), want, "at {x:?}");
        }
        // Summing adds entry by entry.
        let mut s = q;
        s.add(&Quadric::plane(A, [1.0, -1.0, 2.0], 1.0));
        for k in 0..10 {
            assert_eq!(
                s.0[k],
                q.0[k] + [4.0, 6.0, 10.0, -18.0, 9.0, 15.0, -27.0, 25.0, -45.0, 81.0][k]
            );
        }
    }

    /// The minimiser solves the full 3×3 system, and exists exactly when the system's
    /// determinant exceeds `1e-9` times the cube of the mean diagonal entry: here the
    /// diagonal `(t, 2, 4)`, mean about 2, so the bound is about `8e-9` against `det = 8t`.
    #[test]
    fn minimiser_solves_the_system_and_refuses_it_at_its_conditioning_bound() {
        // Q's 3×3 block is [A; B'; C'] made symmetric and definite; the right-hand side
        // is chosen so that the solution is (1, −2, 3).
        let m = [[4.0, 1.0, 2.0], [1.0, 5.0, -1.0], [2.0, -1.0, 6.0]];
        let x = [1.0, -2.0, 3.0];
        let r: Vec<f64> = m.iter().map(|row| dot(*row, x)).collect();
        let q = Quadric([
            m[0][0], m[0][1], m[0][2], -r[0], m[1][1], m[1][2], -r[1], m[2][2], -r[2], 1.0,
        ]);
        let got = q.minimiser().expect("a definite system");
        for k in 0..3 {
            assert!((got[k] - x[k]).abs() < 1e-12, "{got:?}");
        }
        let diagonal = |t: f64| Quadric([t, 0.0, 0.0, -t, 2.0, 0.0, 2.0, 4.0, -4.0, 0.0]);
        // Solution (1, −1, 1) whenever the system is accepted.
        assert_eq!(diagonal(1.1e-9).minimiser(), Some([1.0, -1.0, 1.0]));
        assert_eq!(diagonal(0.9e-9).minimiser(), None);
        assert_eq!(Quadric::default().minimiser(), None);
    }

    /// Without a usable minimiser the position is the best of the midpoint, `p` and `q`,
    /// ties going to the midpoint, then to `p`; a minimiser is used only within the
    /// bound, a coordinate equal to it included.
    #[test]
    fn best_position_fallback_tie_rule_and_bound() {
        let (p, q) = ([0.0, 0.0, 2.0], [4.0, 0.0, 2.0]);
        // Every error is 0: the midpoint.
        assert_eq!(Quadric::default().best_position(p, q), [2.0, 0.0, 2.0]);
        // The plane x = 0 (singular): p is on it.
        let plane = Quadric::plane([1.0, 0.0, 0.0], [0.0, 0.0, 0.0], 1.0);
        assert_eq!(plane.best_position(p, q), p);
        assert_eq!(plane.best_position(q, p), p);
        // The plane x = 4: q is on it.
        let plane = Quadric::plane([1.0, 0.0, 0.0], [4.0, 0.0, 0.0], 1.0);
        assert_eq!(plane.best_position(p, q), q);
        // Three planes meeting at (1, −1, 1): used within the bound, refused past it.
        let mut corner = Quadric::default();
        for (n, at) in [
            ([1.0, 0.0, 0.0], 1.0),
            ([0.0, 1.0, 0.0], -1.0),
            ([0.0, 0.0, 1.0], 1.0),
        ] {
            corner.add(&Quadric::plane(n, n.map(|c| c * at), 1.0));
        }
        assert_eq!(corner.best_position(p, q), [1.0, -1.0, 1.0]);
        assert_eq!(corner.best_position_within(p, q, 1.0), [1.0, -1.0, 1.0]);
        assert_eq!(corner.best_position_within(p, q, 0.5), [2.0, 0.0, 2.0]);
    }

    /// The guard refuses a normal turned by exactly 90°, accepts any move of a triangle
    /// that had no area (if it gets one), and refuses slivers by their longest edge: on
    /// the edge `(0,0,0)–(1,0,0)`, a corner moved to height `h` above its middle has
    /// `|n| = h` and longest edge 1, so it is refused for `h ≤ 1e-10` and accepted above.
    #[test]
    fn fan_move_guard_at_its_boundaries() {
        let (p1, p2) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        // Before: normal (0, 1, 0); after: (0, 0, 1).
        let x = [0.0, 0.0, -1.0];
        assert_eq!(cross(sub(p1, x), sub(p2, p1)), [0.0, 1.0, 0.0]);
        assert!(!fan_move_ok(x, [0.0, 1.0, 0.0], p1, p2));
        assert!(fan_move_ok(x, [0.0, 1.0, -1e-3], p1, p2));
        assert!(!fan_move_ok(x, [0.0, 1.0, 1e-3], p1, p2));
        // A triangle without area may move anywhere that gives it one.
        let flat = [0.5, 0.0, 0.0];
        assert!(fan_move_ok(flat, [0.5, 1.0, 0.0], p1, p2));
        assert!(fan_move_ok(flat, [0.5, -1.0, 0.0], p1, p2));
        assert!(!fan_move_ok(flat, [2.0, 0.0, 0.0], p1, p2));
        // Slivers, from the side of the old triangle (x below the edge in y).
        let x = [0.5, 1.0, 0.0];
        for (h, ok) in [
            (0.9e-10, false),
            (1e-10, false),
            (1.1e-10, true),
            (1e-9, true),
        ] {
            let to = [0.5, h, 0.0];
            assert_eq!(fan_move_ok(x, to, p1, p2), ok, "h = {h}");
            assert_eq!(moved_triangle_ok(area_normal(x, p1, p2), [to, p1, p2]), ok);
        }
        // The same slivers with the moved corner on the edge's line outside the edge,
        // where the longest edge is the one from it to the far end: |n| = h, refused for
        // h ≤ 1e-10 · L². Past p2 at x = 10 (L² = 100), and before p1 at x = −1 and −3
        // (L² = 4 and 16), where L² comes close to the cheap bound `2 (|e|² + |p1 − to|²)`
        // (equal to it at −1, where p1 − to = e): a smaller bound would let them through.
        for (along, l2) in [(10.0, 100.0), (-1.0, 4.0), (-3.0, 16.0)] {
            for (h, ok) in [(0.9e-10 * l2, false), (1.1e-10 * l2, true)] {
                let (x, to) = ([along, 1.0, 0.0], [along, h, 0.0]);
                assert_eq!(fan_move_ok(x, to, p1, p2), ok, "at {along}, h = {h}");
                assert_eq!(moved_triangle_ok(area_normal(x, p1, p2), [to, p1, p2]), ok);
            }
        }
    }

    #[test]
    fn bbox_diagonal_of_a_box() {
        let d = bbox_diagonal([[0.0, 0.0, 0.0], [3.0, 4.0, 0.0], [1.0, 1.0, 12.0]]);
        assert!((d - 13.0).abs() < 1e-12);
        assert_eq!(bbox_diagonal([]), 0.0);
        assert_eq!(bbox_diagonal([[-1.0, 2.0, 5.0]]), 0.0);
        // Sides (3, 4, 12) scaled by 2^300 and 2^−300: the plain formula's squares would
        // overflow and underflow.
        for s in [2f64.powi(300), 2f64.powi(-300)] {
            let d = bbox_diagonal([[-s, 0.0, 0.0], [2.0 * s, 4.0 * s, 12.0 * s]]);
            assert_eq!(d, 13.0 * s);
        }
    }
}
