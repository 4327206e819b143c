//! The verdict on an output of `simplify`: a surface of the input's type per component,
//! with no edge shorter than ε left that could still be contracted.

use std::collections::HashMap;

use super::surface::{Analysis, Part};
use super::{
    output_surface, same_components, surface_input, surface_name, Failure, FailureKind, Verdict,
};
use crate::simplify::Position;
use crate::{Eps, Error, TriMesh};

/// The run being judged, as [`simplify`](super::simplify()) needs it: with these options
/// the checker flags only short edges that no run of `simplify` with the same ε,
/// placement and guard could have left (an edge shorter than ε that passes the link
/// condition of the surface with boundary and that the geometry guard, when on, would
/// not refuse). The names and defaults are [`crate::SimplifyOptions`]'s; the mode and
/// the side heuristic do not matter (every mode contracts every such edge).
///
/// # Example
/// ```
/// use contractible::check::SimplifyCheck;
/// use contractible::simplify::Position;
/// // A run with --eps-rel 0.02 --position quadric --allow-foldover:
/// let options = SimplifyCheck {
///     position: Position::Quadric,
///     allow_foldover: true,
///     ..SimplifyCheck::relative(0.02)
/// };
/// assert_eq!(options.eps, contractible::Eps::Relative(0.02));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimplifyCheck {
    /// ε, absolute or a fraction of the diagonal of the bounding box of the vertices the
    /// input's faces use.
    pub eps: Eps,
    /// The run's placement of a contracted edge's vertex. The guard's verdict depends on
    /// it: with [`Position::Midpoint`] the checker recomputes it; with
    /// [`Position::Quadric`] (a position that depends on the input faces merged so
    /// far) a guarded run may leave any short edge, so no short edge is flagged unless
    /// `allow_foldover`.
    pub position: Position,
    /// The run had the geometry guard off: every short edge that passes the link
    /// condition is a failure.
    pub allow_foldover: bool,
}

impl Default for SimplifyCheck {
    /// ε 1 % of the bounding-box diagonal, midpoints, the guard on (the library's
    /// defaults).
    fn default() -> Self {
        SimplifyCheck {
            eps: Eps::default(),
            position: Position::default(),
            allow_foldover: false,
        }
    }
}

impl SimplifyCheck {
    /// The default options (midpoints, the guard on) with an absolute ε.
    pub fn absolute(eps: f64) -> Self {
        SimplifyCheck {
            eps: Eps::Absolute(eps),
            ..SimplifyCheck::default()
        }
    }

    /// The default options (midpoints, the guard on) with ε a fraction of the
    /// bounding-box diagonal.
    pub fn relative(fraction: f64) -> Self {
        SimplifyCheck {
            eps: Eps::Relative(fraction),
            ..SimplifyCheck::default()
        }
    }
}

/// A zero-area triangle: `|n| ≤ ZERO_AREA · L²`, `n` twice its area vector, `L` its
/// longest edge (`spec/simplify.md`, decision 8).
const ZERO_AREA: f64 = 1e-10;

/// A power of two `s` such that `x · s` is in [1, 2) (1 for 0 or a non-finite `x`).
fn power_of_two_scale(x: f64) -> f64 {
    if !(x.is_finite() && x > 0.0) {
        return 1.0;
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    // Subnormals have exponent field 0; their value is below 2^−1022.
    let e = if exponent == 0 {
        -1023
    } else {
        exponent - 1023
    };
    2f64.powi(-e)
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The diagonal of the bounding box of `points`, computed at a power-of-two scale so
/// that no square overflows or underflows (0 for no points).
pub(super) fn bbox_diagonal(points: impl Iterator<Item = [f64; 3]>) -> f64 {
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

/// The input's positions, refused as `task` (`simplify`, `decimate`) refuses them:
/// present, one per vertex, finite, and the used vertices not all at one point.
pub(super) fn input_positions<'m>(
    input: &'m TriMesh,
    task: &'static str,
) -> Result<(&'m [[f64; 3]], Vec<usize>), Error> {
    let positions = input
        .positions
        .as_deref()
        .ok_or(Error::MissingPositions { task })?;
    if positions.len() != input.vertex_count {
        return Err(Error::PositionCount {
            vertices: input.vertex_count,
            positions: positions.len(),
        });
    }
    for (vertex, p) in positions.iter().enumerate() {
        if let Some(k) = (0..3).find(|&k| !p[k].is_finite()) {
            return Err(Error::NonFiniteCoordinate {
                vertex,
                axis: ['x', 'y', 'z'][k],
                value: p[k],
            });
        }
    }
    let mut used = vec![false; input.vertex_count];
    for f in &input.faces {
        for &v in f {
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    let used: Vec<usize> = (0..input.vertex_count).filter(|&v| used[v]).collect();
    if let Some(&first) = used.first() {
        let point = positions[first];
        if used.len() > 1 && used.iter().all(|&v| positions[v] == point) {
            return Err(Error::NoCoordinates {
                vertices: used.len(),
                point,
            });
        }
    }
    Ok((positions, used))
}

fn bad_eps(value: String, expected: String) -> Error {
    Error::BadOption {
        option: "eps",
        value,
        expected,
    }
}

/// Judges `output` as a simplification of `input` (the task `simplify`) with the run's
/// `options`: see the [module](super) for what is checked, and `spec/conformance.md`.
pub(super) fn check(
    input: &TriMesh,
    output: &TriMesh,
    options: &SimplifyCheck,
) -> Result<Verdict, Error> {
    let positive = |v: f64| v.is_finite() && v > 0.0;
    match options.eps {
        Eps::Absolute(e) if !positive(e) => {
            return Err(bad_eps(
                format!("{e:?}"),
                "ε must be a finite number > 0".into(),
            ))
        }
        Eps::Relative(r) if !positive(r) => {
            return Err(bad_eps(
                format!("{r:?}"),
                "the fraction of the bounding-box diagonal must be a finite number > 0".into(),
            ))
        }
        _ => {}
    }
    let (positions, used) = input_positions(input, "simplify")?;
    let inp = surface_input(input, "simplify")?;
    let eps = match options.eps {
        Eps::Absolute(e) => e,
        Eps::Relative(r) => {
            let diagonal = bbox_diagonal(used.iter().map(|&v| positions[v]));
            let e = r * diagonal;
            if !positive(e) {
                return Err(bad_eps(
                    format!("Relative({r:?})"),
                    format!(
                        "{r:?} times the bounding-box diagonal {diagonal:?} gives ε = {e:?}, \
                         not a finite number > 0"
                    ),
                ));
            }
            e
        }
    };
    drop(used);
    let mut verdict = Verdict::new("simplify");
    let Some(out) = output_surface(output, &mut verdict) else {
        return Ok(verdict);
    };
    let out_positions = output_positions(output, &out, &mut verdict);
    if output.vertex_count == input.vertex_count {
        // The input's vertex list kept: components matched by vertex id.
        let n = input.vertex_count as u32;
        let to_input = |v: u32| (v < n).then_some(v);
        same_components(input, &inp, &out, &to_input, true, true, &mut verdict);
    } else {
        same_surface_types(&inp, &out, &mut verdict);
    }
    if let Some(p) = out_positions {
        short_contractible_edges(output, &out, p, eps, options, &mut verdict);
    }
    Ok(verdict)
}

/// The output's positions when every vertex a face uses has a finite one; otherwise
/// each missing or non-finite one is an `invalid_position` and `None`.
pub(super) fn output_positions<'m>(
    output: &'m TriMesh,
    out: &Analysis,
    verdict: &mut Verdict,
) -> Option<&'m [[f64; 3]]> {
    let Some(p) = output.positions.as_deref() else {
        verdict.fail(Failure::new(
            FailureKind::InvalidPosition,
            "the output has no vertex positions".into(),
        ));
        return None;
    };
    let mut ok = true;
    for part in &out.parts {
        for &v in &part.vertices {
            match p.get(v as usize) {
                None => {
                    ok = false;
                    verdict.fail(
                        Failure::new(
                            FailureKind::InvalidPosition,
                            format!(
                                "output vertex {v} has no position (the output has {} \
                                 positions)",
                                p.len()
                            ),
                        )
                        .vertex(v),
                    );
                }
                Some(q) if !q.iter().all(|x| x.is_finite()) => {
                    ok = false;
                    verdict.fail(
                        Failure::new(
                            FailureKind::InvalidPosition,
                            format!("output vertex {v} is at {q:?}, not a finite position"),
                        )
                        .vertex(v),
                    );
                }
                Some(_) => {}
            }
        }
    }
    ok.then_some(p)
}

/// The output's components against the input's as multisets of surface types (χ,
/// orientability, boundary loops): each input component is paired with the first
/// unpaired output component of its type, in order; the unpaired ones left are paired
/// in order (`surface_changed`), and those left then are `component_lost` (input) or
/// `component_split` (output: more components than the input has).
pub(super) fn same_surface_types(inp: &Analysis, out: &Analysis, verdict: &mut Verdict) {
    let key = |p: &Part| (p.euler(), p.orientable, p.boundary_loops);
    // Per type, the output components of that type in order, taken from the front:
    // O(components) instead of a scan of the output per input component.
    let mut of_type: HashMap<(i64, bool, usize), std::collections::VecDeque<usize>> =
        HashMap::new();
    for (j, q) in out.parts.iter().enumerate() {
        of_type.entry(key(q)).or_default().push_back(j);
    }
    let mut taken = vec![false; out.parts.len()];
    let mut unpaired: Vec<usize> = Vec::new();
    for (k, p) in inp.parts.iter().enumerate() {
        match of_type.get_mut(&key(p)).and_then(|js| js.pop_front()) {
            Some(j) => taken[j] = true,
            None => unpaired.push(k),
        }
    }
    let mut left = (0..out.parts.len()).filter(|&j| !taken[j]);
    for k in unpaired {
        let p = &inp.parts[k];
        match left.next() {
            Some(j) => {
                let q = &out.parts[j];
                verdict.fail(
                    Failure::new(
                        FailureKind::SurfaceChanged,
                        format!(
                            "input component {k} ({}) has no output component of its surface; \
                             the output component of face {} is {}",
                            surface_name(p, true),
                            q.first_face,
                            surface_name(q, true)
                        ),
                    )
                    .face(q.first_face)
                    .component(k),
                );
            }
            None => verdict.fail(
                Failure::new(
                    FailureKind::ComponentLost,
                    format!(
                        "input component {k} ({}) has no output component",
                        surface_name(p, true)
                    ),
                )
                .component(k),
            ),
        }
    }
    for j in left {
        let q = &out.parts[j];
        verdict.fail(
            Failure::new(
                FailureKind::ComponentSplit,
                format!(
                    "the output component of face {} ({}) is one more than the input's {} \
                     components of its surface",
                    q.first_face,
                    surface_name(q, true),
                    inp.parts
                        .iter()
                        .filter(|p| (p.euler(), p.orientable, p.boundary_loops)
                            == (q.euler(), q.orientable, q.boundary_loops))
                        .count()
                ),
            )
            .face(q.first_face),
        );
    }
}

/// Whether the edge `[a, b]` (with its opposite vertices, `u32::MAX` for a boundary
/// edge's missing one) passes the link condition of the surface with boundary: on the
/// surface with each boundary loop coned to its own apex, the ends' only common
/// neighbours are the edge's two opposite vertices (for a boundary edge: its one
/// opposite vertex and its loop's apex), the coned component is no tetrahedron, and the
/// ends are not on two different boundary loops.
pub(super) fn passes_link_condition(
    out: &Analysis,
    (a, b): (u32, u32),
    opposite: [u32; 2],
    face: u32,
) -> bool {
    let (la, lb) = (out.loop_of[a as usize], out.loop_of[b as usize]);
    let boundary_edge = opposite[1] == u32::MAX;
    if la != u32::MAX && lb != u32::MAX && la != lb {
        // Two loops: contracting would make them touch.
        return false;
    }
    if !boundary_edge && la != u32::MAX && la == lb {
        // A chord of one loop: the loop's apex is a common neighbour not opposite.
        return false;
    }
    let Some(part) = out.part_of_face.get(face as usize).map(|&k| &out.parts[k]) else {
        return false;
    };
    // The coned component: one apex per loop, one cone face per boundary edge
    // (3F = 2E − E_boundary).
    let boundary_edges = (2 * part.edges).saturating_sub(3 * part.faces);
    if part.vertices.len() + part.boundary_loops == 4 && part.faces + boundary_edges == 4 {
        return false;
    }
    out.other_common_neighbour(a, b, opposite).is_none()
}

/// Per vertex, the faces holding it (CSR: `start`, `faces`).
pub(super) fn faces_at(vertex_count: usize, faces: &[[u32; 3]]) -> (Vec<usize>, Vec<u32>) {
    let mut start = vec![0usize; vertex_count + 1];
    for f in faces {
        for &v in f {
            start[v as usize + 1] += 1;
        }
    }
    for v in 0..vertex_count {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut list = vec![0u32; 3 * faces.len()];
    for (i, f) in faces.iter().enumerate() {
        for &v in f {
            list[fill[v as usize]] = i as u32;
            fill[v as usize] += 1;
        }
    }
    (start, list)
}

/// Whether the geometry guard (`spec/simplify.md`, decision 8) lets `[a, b]` contract to
/// `to`: every face at `a` or `b` but the edge's own, with its corner at `a` or `b`
/// moved to `to`, keeps a nonzero area (`|n| > ZERO_AREA · L²`) and, when it had a
/// nonzero normal, turns it by less than 90° (`n_old · n_new > 0`). Positions scaled.
pub(super) fn guard_allows(
    faces: &[[u32; 3]],
    at: &(Vec<usize>, Vec<u32>),
    pos: &dyn Fn(u32) -> [f64; 3],
    (a, b): (u32, u32),
    to: [f64; 3],
) -> bool {
    let (start, list) = at;
    for v in [a, b] {
        let other = if v == a { b } else { a };
        for &fi in &list[start[v as usize]..start[v as usize + 1]] {
            let f = faces[fi as usize];
            if f.contains(&other) {
                continue;
            }
            // The face as (v, p1, p2), its orientation kept.
            let k = f.iter().position(|&x| x == v).unwrap_or(0);
            let (p1, p2) = (pos(f[(k + 1) % 3]), pos(f[(k + 2) % 3]));
            let x = pos(v);
            let e = sub(p2, p1);
            let old = cross(sub(p1, x), e);
            let d = sub(p1, to);
            let new = cross(d, e);
            let l2 = dot(d, d).max(dot(e, e)).max(dot(sub(p2, to), sub(p2, to)));
            if dot(new, new) <= ZERO_AREA * ZERO_AREA * l2 * l2 {
                return false;
            }
            if dot(old, old) != 0.0 && dot(old, new) <= 0.0 {
                return false;
            }
        }
    }
    true
}

/// Every output edge strictly shorter than ε that passes the link condition of the
/// surface with boundary and that the guard, when it was on and the placement is the
/// midpoint, would let contract: `short_contractible_edge`.
fn short_contractible_edges(
    output: &TriMesh,
    out: &Analysis,
    positions: &[[f64; 3]],
    eps: f64,
    options: &SimplifyCheck,
    verdict: &mut Verdict,
) {
    let guarded = !options.allow_foldover;
    if guarded && options.position != Position::Midpoint {
        // The placement cannot be recomputed: a guarded run may leave any short edge.
        return;
    }
    // Lengths compared at a power-of-two scale (exact) that keeps squares in range, as
    // `simplify` compares them: squared length < (ε·s)², the latter at least the
    // smallest positive number (an edge of length 0 is shorter than any ε).
    let largest = out
        .parts
        .iter()
        .flat_map(|p| p.vertices.iter())
        .filter_map(|&v| positions.get(v as usize))
        .flat_map(|p| p.iter().map(|x| x.abs()))
        .fold(0.0f64, f64::max);
    let s = power_of_two_scale(largest);
    let pos = |v: u32| -> [f64; 3] {
        positions
            .get(v as usize)
            .map_or([0.0; 3], |p| p.map(|x| x * s))
    };
    let eps2 = ((eps * s) * (eps * s)).max(f64::from_bits(1));
    let at = faces_at(output.vertex_count, &output.faces);
    for &((a, b), opposite, f) in &out.edges {
        let d = sub(pos(a), pos(b));
        let l2 = dot(d, d);
        if l2 >= eps2 || !passes_link_condition(out, (a, b), opposite, f) {
            continue;
        }
        if guarded {
            let on_boundary = |v: u32| out.loop_of[v as usize] != u32::MAX;
            let to = match (on_boundary(a), on_boundary(b)) {
                (true, false) => pos(a),
                (false, true) => pos(b),
                _ => {
                    let (p, q) = (pos(a), pos(b));
                    [
                        0.5 * (p[0] + q[0]),
                        0.5 * (p[1] + q[1]),
                        0.5 * (p[2] + q[2]),
                    ]
                }
            };
            if !guard_allows(&output.faces, &at, &pos, (a, b), to) {
                continue;
            }
        }
        verdict.fail(
            Failure::new(
                FailureKind::ShortContractibleEdge,
                format!(
                    "output edge [{a}, {b}] of length {:e} < ε = {eps:e} passes the link \
                     condition{}: the simplification stopped early",
                    l2.sqrt() / s,
                    if guarded {
                        " and the geometry guard"
                    } else {
                        ""
                    }
                ),
            )
            .face(f as usize)
            .edge([a, b]),
        );
    }
}
