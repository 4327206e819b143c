//! The verdict on an output of `decimate`: a surface of the input's type per component,
//! with a face count the run's target explains, and provenance maps (when stated) that
//! say truly where every vertex and face went.

use super::simplify_check::{
    input_positions, output_positions, passes_link_condition, same_surface_types,
};
use super::surface::{Analysis, Sets};
use super::{output_surface, same_components, surface_input, Failure, FailureKind, Verdict};
use crate::decimate::{Placement, NO_VERTEX};
use crate::{DecimateOptions, DecimateResult, Error, MaxError, TriMesh};

/// The run being judged and what its answer states besides the mesh: the target and
/// options of [`crate::DecimateOptions`] (same names, same meaning) that decide when a
/// run may stop and where its vertices may go, and the provenance maps of
/// [`crate::DecimateResult`].
///
/// # Example
/// ```
/// use contractible::check::DecimateCheck;
/// // A run with --keep 0.25 --allow-foldover, judged with its vertex map:
/// let vertex_map = [0, 3, 5, 8];
/// let options = DecimateCheck {
///     keep: Some(0.25),
///     allow_foldover: true,
///     vertex_map: Some(&vertex_map),
///     ..DecimateCheck::default()
/// };
/// assert!(options.faces.is_none());
/// ```
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DecimateCheck<'a> {
    /// The run's face target.
    pub faces: Option<usize>,
    /// The run's fraction of the faces kept (`ceil(keep × faces)`; with `faces` too, the
    /// larger count).
    pub keep: Option<f64>,
    /// The run's error cap (a run with one may stop above its target anywhere: the
    /// checker does not recompute errors).
    pub max_error: Option<MaxError>,
    /// The run's placement: with [`Placement::Endpoint`] every output position must be
    /// the input position of a vertex merged into it.
    pub placement: Placement,
    /// The run had the geometry guard off: a run above its target must then have left
    /// no edge that passes the link condition (unless locks or a cap refuse it).
    pub allow_foldover: bool,
    /// The run locked the boundary vertices.
    pub lock_boundary: bool,
    /// The run's locked input vertices.
    pub locked: &'a [u32],
    /// Per output vertex, the input vertex that survives as it.
    pub vertex_map: Option<&'a [u32]>,
    /// Per input vertex, the output vertex it went into ([`NO_VERTEX`] for a vertex no
    /// face uses).
    pub collapse_map: Option<&'a [u32]>,
    /// Per output face, the input face it descends from (its corners renamed by the
    /// collapses, slot by slot).
    pub face_origin: Option<&'a [u32]>,
}

impl<'a> DecimateCheck<'a> {
    /// The check of a run with `options` (its target, cap, placement, guard and locks),
    /// without maps.
    ///
    /// # Example
    /// ```
    /// use contractible::{check::DecimateCheck, DecimateOptions};
    /// let run = DecimateOptions { allow_foldover: true, ..DecimateOptions::keep(0.1) };
    /// let c = DecimateCheck::of_run(&run);
    /// assert_eq!((c.keep, c.allow_foldover, c.vertex_map), (Some(0.1), true, None));
    /// ```
    pub fn of_run(options: &'a DecimateOptions) -> Self {
        DecimateCheck {
            faces: options.faces,
            keep: options.keep,
            max_error: options.max_error,
            placement: options.placement,
            allow_foldover: options.allow_foldover,
            lock_boundary: options.lock_boundary,
            locked: &options.locked,
            vertex_map: None,
            collapse_map: None,
            face_origin: None,
        }
    }

    /// The check of `result`, a run with `options`, with the three maps it states.
    ///
    /// # Example
    /// ```
    /// use contractible::{check, decimate, gen, DecimateOptions};
    /// let mesh = gen::subdivide(&gen::octahedron(), 2)?;
    /// let run = DecimateOptions::faces(40);
    /// let result = decimate(&mesh, &run)?;
    /// let c = check::DecimateCheck::of_result(&run, &result);
    /// assert!(check::decimate(&mesh, &result.mesh, &c)?.passed());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn of_result(options: &'a DecimateOptions, result: &'a DecimateResult) -> Self {
        let mut check = DecimateCheck::of_run(options);
        check.vertex_map = Some(&result.vertex_map);
        check.collapse_map = Some(&result.collapse_map);
        check.face_origin = Some(&result.face_origin);
        check
    }
}

fn bad(option: &'static str, value: String, expected: &str) -> Error {
    Error::BadOption {
        option,
        value,
        expected: expected.to_string(),
    }
}

/// The run's face target, as `decimate` computes it (0 without one).
fn target(options: &DecimateCheck<'_>, faces_in: usize) -> Result<usize, Error> {
    if let Some(k) = options.keep {
        if !(k.is_finite() && (0.0..=1.0).contains(&k)) {
            return Err(bad(
                "keep",
                format!("{k:?}"),
                "the fraction of the faces kept must be in [0, 1]",
            ));
        }
    }
    let by_fraction = options.keep.map(|k| (k * faces_in as f64).ceil() as usize);
    Ok(match (options.faces, by_fraction) {
        (Some(a), Some(b)) => a.max(b),
        (a, b) => a.or(b).unwrap_or(0),
    })
}

fn map_failure(message: String) -> Failure {
    Failure::new(FailureKind::InconsistentMap, message)
}

/// The stated maps checked against each other and the two face lists; per output
/// vertex its input vertex when they say so consistently (`None`: not stated, or
/// wrong).
fn check_maps(
    input: &TriMesh,
    output: &TriMesh,
    options: &DecimateCheck<'_>,
    verdict: &mut Verdict,
) -> Option<Vec<u32>> {
    let before = verdict.failures.len();
    let (n_in, n_out) = (input.vertex_count, output.vertex_count);
    let mut used_in = vec![false; n_in];
    for f in &input.faces {
        for &v in f {
            used_in[v as usize] = true;
        }
    }
    let mut used_out = vec![false; n_out];
    for f in &output.faces {
        for &v in f {
            used_out[v as usize] = true;
        }
    }
    if let Some(vm) = options.vertex_map {
        if vm.len() != n_out {
            verdict.fail(map_failure(format!(
                "vertex_map has {} entries for {n_out} output vertices",
                vm.len()
            )));
        } else {
            let mut seen = vec![false; n_in];
            for (o, &i) in vm.iter().enumerate() {
                match seen.get_mut(i as usize) {
                    None => verdict.fail(
                        map_failure(format!(
                            "vertex_map[{o}] is {i}, beyond the input's {n_in} vertices"
                        ))
                        .vertex(o as u32),
                    ),
                    Some(true) => verdict.fail(
                        map_failure(format!("vertex_map[{o}] is {i}, named twice"))
                            .vertex(o as u32),
                    ),
                    Some(s) => *s = true,
                }
            }
        }
    }
    if let Some(cm) = options.collapse_map {
        if cm.len() != n_in {
            verdict.fail(map_failure(format!(
                "collapse_map has {} entries for {n_in} input vertices",
                cm.len()
            )));
        } else {
            for (i, &o) in cm.iter().enumerate() {
                let ok = if used_in[i] {
                    used_out.get(o as usize) == Some(&true)
                } else {
                    o == NO_VERTEX
                };
                if !ok {
                    verdict.fail(map_failure(format!(
                        "collapse_map[{i}] is {o}: {}",
                        if used_in[i] {
                            "an input vertex a face uses must go to an output vertex a face uses"
                        } else {
                            "an input vertex no face uses goes nowhere (NO_VERTEX)"
                        }
                    )));
                }
            }
        }
    }
    if verdict.failures.len() > before {
        return None;
    }
    if let (Some(vm), Some(cm)) = (options.vertex_map, options.collapse_map) {
        for (o, &i) in vm.iter().enumerate() {
            if used_out[o] && cm[i as usize] != o as u32 {
                verdict.fail(
                    map_failure(format!(
                        "output vertex {o} is input vertex {i} (vertex_map), which \
                         collapse_map sends to {}",
                        cm[i as usize]
                    ))
                    .vertex(o as u32),
                );
            }
        }
    }
    if let Some(cm) = options.collapse_map {
        // Each output vertex's input vertices are joined by input edges: collapses
        // merge the two ends of an edge.
        let mut sets = Sets::new(n_in);
        for f in &input.faces {
            for k in 0..3 {
                let (a, b) = (f[k], f[(k + 1) % 3]);
                if cm[a as usize] == cm[b as usize] {
                    sets.union(a, b);
                }
            }
        }
        let mut root_of = vec![u32::MAX; n_out];
        for (i, &o) in cm.iter().enumerate() {
            if o == NO_VERTEX {
                continue;
            }
            let r = sets.find(i as u32);
            let seen = &mut root_of[o as usize];
            if *seen == u32::MAX {
                *seen = r;
            } else if *seen != r {
                verdict.fail(
                    map_failure(format!(
                        "the input vertices collapse_map sends to output vertex {o} are \
                         not joined by input edges (input vertex {i} is apart)"
                    ))
                    .vertex(o),
                );
                *seen = r;
            }
        }
        if let Some(fo) = options.face_origin {
            check_faces(input, output, cm, fo, verdict);
        }
    }
    if verdict.failures.len() > before {
        return None;
    }
    options.vertex_map.map(<[u32]>::to_vec)
}

/// `face_origin` against the faces: output face `f` is input face `face_origin[f]`
/// renamed by `cm`, slot by slot; every other input face loses a corner (two of its
/// corners go to one output vertex).
fn check_faces(input: &TriMesh, output: &TriMesh, cm: &[u32], fo: &[u32], verdict: &mut Verdict) {
    if fo.len() != output.faces.len() {
        verdict.fail(map_failure(format!(
            "face_origin has {} entries for {} output faces",
            fo.len(),
            output.faces.len()
        )));
        return;
    }
    let mut kept = vec![false; input.faces.len()];
    for (f, &g) in fo.iter().enumerate() {
        let Some(src) = input.faces.get(g as usize) else {
            verdict.fail(
                map_failure(format!(
                    "face_origin[{f}] is {g}, beyond the input's {} faces",
                    input.faces.len()
                ))
                .face(f),
            );
            continue;
        };
        if std::mem::replace(&mut kept[g as usize], true) {
            verdict.fail(map_failure(format!("face_origin[{f}] is {g}, named twice")).face(f));
        }
        let renamed = src.map(|v| cm[v as usize]);
        if renamed != output.faces[f] {
            verdict.fail(
                map_failure(format!(
                    "output face {f} {:?} is not input face {g} {src:?} renamed by \
                     collapse_map ({renamed:?})",
                    output.faces[f]
                ))
                .face(f),
            );
        }
    }
    for (g, src) in input.faces.iter().enumerate() {
        let r = src.map(|v| cm[v as usize]);
        if !kept[g] && r[0] != r[1] && r[1] != r[2] && r[0] != r[2] {
            verdict.fail(map_failure(format!(
                "input face {g} {src:?} keeps three corners under collapse_map ({r:?}) but \
                 no output face descends from it"
            )));
        }
    }
}

/// Judges `output` as a decimation of `input` (the task `decimate`): see
/// [`decimate`](super::decimate()).
pub(super) fn check(
    input: &TriMesh,
    output: &TriMesh,
    options: &DecimateCheck<'_>,
) -> Result<Verdict, Error> {
    let (positions, _) = input_positions(input, "decimate")?;
    let inp = surface_input(input, "decimate")?;
    let t = target(options, input.faces.len())?;
    if let Some(&v) = options
        .locked
        .iter()
        .find(|&&v| v as usize >= input.vertex_count)
    {
        return Err(bad(
            "locked",
            v.to_string(),
            &format!(
                "a locked vertex must be an input vertex (the mesh has {})",
                input.vertex_count
            ),
        ));
    }
    let mut verdict = Verdict::new("decimate");
    let Some(out) = output_surface(output, &mut verdict) else {
        return Ok(verdict);
    };
    let out_positions = output_positions(output, &out, &mut verdict);
    let stated = check_maps(input, output, options, &mut verdict);
    // Per output vertex, its input vertex: stated, or the input's list kept.
    let identity: Option<Vec<u32>> = stated.or_else(|| {
        (output.vertex_count == input.vertex_count)
            .then(|| (0..output.vertex_count as u32).collect())
    });
    match &identity {
        Some(ids) => {
            let to_input = |v: u32| ids.get(v as usize).copied();
            same_components(input, &inp, &out, &to_input, true, true, &mut verdict);
        }
        None => same_surface_types(&inp, &out, &mut verdict),
    }
    // Locked vertices survive where they were.
    let mut locked = vec![false; input.vertex_count];
    for &v in options.locked {
        locked[v as usize] = true;
    }
    if options.lock_boundary {
        for v in (0..input.vertex_count).filter(|&v| inp.loop_of[v] != u32::MAX) {
            locked[v] = true;
        }
    }
    if let (Some(ids), Some(p)) = (&identity, out_positions) {
        let mut survives = vec![u32::MAX; input.vertex_count];
        for part in &out.parts {
            for &o in &part.vertices {
                if let Some(&i) = ids.get(o as usize) {
                    survives[i as usize] = o;
                }
            }
        }
        for i in (0..input.vertex_count).filter(|&i| locked[i]) {
            let used = inp
                .parts
                .iter()
                .any(|q| q.vertices.binary_search(&(i as u32)).is_ok());
            if !used {
                continue;
            }
            let o = survives[i];
            if o == u32::MAX || p[o as usize] != positions[i] {
                verdict.fail(
                    Failure::new(
                        FailureKind::MovedVertex,
                        format!(
                            "locked input vertex {i} at {:?} does not survive there",
                            positions[i]
                        ),
                    )
                    .vertex(if o == u32::MAX { i as u32 } else { o }),
                );
            }
        }
    }
    if options.placement == Placement::Endpoint {
        if let Some(p) = out_positions {
            endpoint_positions(input, positions, p, &out, options, &mut verdict);
        }
    }
    let faces_out = output.faces.len();
    // A run stops at the first count at or below the target: an input already there
    // collapses nothing.
    let floor = t.min(input.faces.len());
    if faces_out + 1 < floor {
        verdict.fail(Failure::new(
            FailureKind::TargetMissed,
            format!(
                "the output has {faces_out} faces, below the target {t} by more than one \
                 collapse's faces: the run went past its target"
            ),
        ));
    }
    if faces_out > t && options.allow_foldover && options.max_error.is_none() {
        // Above the target with no guard and no cap: only the link condition and the
        // locks may have stopped the run.
        let is_locked = |v: u32| -> Option<bool> {
            if options.locked.is_empty() && !options.lock_boundary {
                return Some(false);
            }
            let ids = identity.as_ref()?;
            Some(locked[*ids.get(v as usize)? as usize])
        };
        for &((a, b), opposite, f) in &out.edges {
            if !passes_link_condition(&out, (a, b), opposite, f) {
                continue;
            }
            match (is_locked(a), is_locked(b)) {
                (Some(true), Some(true)) => continue,
                (Some(_), Some(_)) => {}
                // Locks that cannot be told apart: not judged.
                _ => break,
            }
            verdict.fail(
                Failure::new(
                    FailureKind::TargetMissed,
                    format!(
                        "the output has {faces_out} faces, above the target {t}, and edge \
                         [{a}, {b}] passes the link condition with no guard, cap or lock \
                         refusing it: the run stopped early"
                    ),
                )
                .face(f as usize)
                .edge([a, b]),
            );
        }
    }
    Ok(verdict)
}

/// Under [`Placement::Endpoint`], every used output vertex is at the input position of
/// a vertex merged into it (of any input vertex, without `collapse_map`).
fn endpoint_positions(
    input: &TriMesh,
    positions: &[[f64; 3]],
    p: &[[f64; 3]],
    out: &Analysis,
    options: &DecimateCheck<'_>,
    verdict: &mut Verdict,
) {
    let bits = |x: [f64; 3]| x.map(|c| (c + 0.0).to_bits());
    let mut allowed: std::collections::HashMap<[u64; 3], Vec<u32>> =
        std::collections::HashMap::new();
    for (i, &x) in positions.iter().enumerate().take(input.vertex_count) {
        allowed.entry(bits(x)).or_default().push(i as u32);
    }
    for part in &out.parts {
        for &o in &part.vertices {
            let at = allowed.get(&bits(p[o as usize]));
            let ok = match (at, options.collapse_map) {
                (None, _) => false,
                (Some(_), None) => true,
                (Some(is), Some(cm)) => is.iter().any(|&i| cm.get(i as usize) == Some(&o)),
            };
            if !ok {
                verdict.fail(
                    Failure::new(
                        FailureKind::InvalidPosition,
                        format!(
                            "output vertex {o} is at {:?}, the position of no input vertex \
                             merged into it (placement endpoint)",
                            p[o as usize]
                        ),
                    )
                    .vertex(o),
                );
            }
        }
    }
}
