//! `contractible simplify IN -o OUT (--eps X | --eps-rel F)`: topology-preserving
//! short-edge simplification (Pepko–Borisenko) of every component, closed or with
//! boundary.
//!
//! Input problems are exit code 2 and write nothing: an unreadable or malformed file
//! (the readers already refuse NaN and infinite coordinates, located), faces that are not
//! a 2-manifold possibly with boundary (located), a bad ε, and a mesh without usable
//! positions. A mesh read from a file always has positions (every format requires
//! them); one whose vertices all lie at a single point — what `gen random` writes, since
//! its surfaces have no coordinates — is refused as carrying none: every edge would have
//! length 0, so ε could not select anything and `--eps-rel` would give ε = 0.
//!
//! The output is checked before it is written, independently of the algorithm: it is
//! rebuilt from its face list and must be a union of surfaces with the input's number of
//! components and the same multiset of (χ, orientability, boundary loops), with no
//! unused vertex. A mismatch is an internal error (exit code 1) and writes nothing.

use std::path::Path;
use std::time::Instant;

use contractible::simplify::{
    self, bbox_diagonal, Mode, Options, PassReport, Position, Side, Simplified, SimplifyError,
    Stats,
};
use contractible::{ConedSurfaces, Surfaces, TriMesh};
use serde::Serialize;

use super::args::SimplifyArgs;
use super::progress::{spinner, StageBar};
use super::reduce::component_prefix;
use super::{meshio, print_json, CliError, Ui};

/// The JSON result of `simplify`: the options, every [`Stats`] field (flattened), and
/// the I/O around them.
#[derive(Serialize, Debug)]
pub struct SimplifyReport {
    pub file: String,
    pub output: String,
    /// The ε used (absolute).
    pub eps: f64,
    /// `--eps-rel` when given, else `null`.
    pub eps_rel: Option<f64>,
    /// Diagonal of the bounding box of the vertices the faces use.
    pub bbox_diagonal: f64,
    pub mode: &'static str,
    pub side: &'static str,
    pub position: &'static str,
    /// Whether the fold-over guard was on (`--allow-foldover` turns it off).
    pub guard: bool,
    #[serde(flatten)]
    pub stats: Stats,
    /// Unused input vertices (dropped, as every command does).
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,

    pub seconds_read: f64,
    /// Validating the input (faces and positions).
    pub seconds_build: f64,
    /// The independent topology check of the output.
    pub seconds_verify: f64,
    pub seconds_write: f64,
}

pub fn mode_name(m: Mode) -> &'static str {
    match m {
        Mode::Naive => "naive",
        Mode::Nested => "nested",
    }
}

pub fn side_name(s: Side) -> &'static str {
    match s {
        Side::Count => "count",
        Side::Path => "path",
        Side::Euclidean => "euclidean",
    }
}

pub fn position_name(p: Position) -> &'static str {
    match p {
        Position::Midpoint => "midpoint",
        Position::Quadric => "quadric",
    }
}

/// A component's topological type as a sortable key: (χ, orientable, boundary loops).
pub type TypeKey = (i64, bool, usize);

/// The topological types of the components of `s`, sorted (a multiset).
pub fn component_types(s: &ConedSurfaces) -> Vec<TypeKey> {
    let mut v: Vec<TypeKey> = s
        .components
        .iter()
        .map(|c| {
            let t = c.surface_type();
            (
                t.euler_characteristic(),
                t.is_orientable(),
                t.boundary_loops(),
            )
        })
        .collect();
    v.sort_unstable();
    v
}

/// The independent check of an output: rebuilt from its face list (not from anything
/// the algorithm kept), it must be a union of surfaces possibly with boundary, use every
/// vertex, and have exactly the components `input` lists (as a multiset of types).
pub fn verify(input: &[TypeKey], out: &TriMesh) -> Result<(), String> {
    let s = Surfaces::from_mesh_with_boundary(out)
        .map_err(|e| format!("the output is not a surface: {e}"))?;
    if !s.dropped_vertices.is_empty() {
        return Err(format!(
            "the output has {} unused vertices",
            s.dropped_vertices.len()
        ));
    }
    let output = component_types(&s);
    if output != input {
        let show = |v: &[TypeKey]| {
            v.iter()
                .map(|(chi, o, b)| {
                    format!(
                        "χ={chi} {} b={b}",
                        if *o { "orientable" } else { "non-orientable" }
                    )
                })
                .collect::<Vec<_>>()
                .join("; ")
        };
        return Err(format!(
            "the output's components ({}: {}) differ from the input's ({}: {})",
            output.len(),
            show(&output),
            input.len(),
            show(input)
        ));
    }
    Ok(())
}

/// [`simplify::simplify_surfaces_observed`] with a bar that follows the scan of every
/// pass of every component (the message names the component and the pass).
pub fn simplify_with_progress(
    surfaces: ConedSurfaces,
    positions: &[[f64; 3]],
    options: &Options,
    ui: Ui,
) -> Result<Simplified, SimplifyError> {
    let mode = mode_name(options.mode);
    let n = surfaces.components.len();
    let bar = std::cell::RefCell::new(StageBar::new(
        ui,
        component_prefix("simplifying", mode, 0, n) + ", pass 1",
    ));
    let mut contracted = 0usize;
    let mut on_pass = |r: &PassReport| {
        contracted = if r.pass == 1 { 0 } else { contracted } + r.contracted;
        // Short enough for one terminal line.
        bar.borrow_mut().set_prefix(format!(
            "{}, pass {} ({} contracted so far, {} faces)",
            component_prefix("simplifying", mode, r.component, n),
            r.pass + 1,
            contracted,
            r.faces
        ));
    };
    let r = simplify::simplify_surfaces_observed(
        surfaces,
        positions,
        options,
        &mut on_pass,
        &mut |p| bar.borrow_mut().observe(p),
    );
    bar.borrow().finish();
    r
}

/// A length for people: 6 significant digits, scientific outside [1e-3, 1e6).
pub fn fmt_len(x: f64) -> String {
    if x == 0.0 || (1e-3..1e6).contains(&x.abs()) {
        let digits = if x == 0.0 {
            0
        } else {
            (5 - x.abs().log10().floor() as i32).max(0) as usize
        };
        format!("{x:.digits$}")
    } else {
        format!("{x:.5e}")
    }
}

fn check_eps(flag: &str, what: &str, v: f64) -> Result<(), CliError> {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        Err(CliError::Input(format!(
            "{flag} {v:?}: {what} must be a finite number > 0"
        )))
    }
}

/// The vertices the faces use, in id order.
fn used_vertices(mesh: &TriMesh) -> Vec<usize> {
    let mut used = vec![false; mesh.vertex_count];
    for f in &mesh.faces {
        for &v in f {
            // The readers and the build check every index against the vertex count.
            if let Some(u) = used.get_mut(v as usize) {
                *u = true;
            }
        }
    }
    (0..mesh.vertex_count).filter(|&v| used[v]).collect()
}

/// The positions of `mesh` and the vertices its faces use, or the input error: no
/// positions, a count that does not match, a non-finite coordinate (the checks
/// `simplify` makes), or every used vertex at one point (no usable coordinates: what a
/// surface generated without them, like `gen random`'s, looks like in a file).
fn checked_positions<'a>(
    mesh: &'a TriMesh,
    path: &Path,
) -> Result<(&'a [[f64; 3]], Vec<usize>), CliError> {
    // ε = 1 stands for any valid ε: only the positions are checked here (the real ε may
    // depend on them).
    let positions = simplify::check_input(mesh, 1.0)
        .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    let used = used_vertices(mesh);
    if let Some(&first) = used.first() {
        let p = positions[first];
        if used.iter().all(|&v| positions[v] == p) {
            return Err(CliError::Input(format!(
                "{}: all {} vertices are at the same point ({}, {}, {}): the file carries \
                 no coordinates (as `gen random` writes its surfaces); `simplify` needs \
                 vertex positions",
                path.display(),
                used.len(),
                p[0],
                p[1],
                p[2]
            )));
        }
    }
    Ok((positions, used))
}

/// Runs the command without printing its report (warnings and bars follow `ui`).
pub fn compute(a: &SimplifyArgs, ui: Ui) -> Result<SimplifyReport, CliError> {
    let output = meshio::check_output(&a.output, a.output_format.map(Into::into), &[&a.input])?;
    if let Some(e) = a.eps {
        check_eps("--eps", "ε", e)?;
    }
    if let Some(r) = a.eps_rel {
        check_eps("--eps-rel", "the fraction of the bounding-box diagonal", r)?;
    }
    let path = &a.input;
    let (mesh, seconds_read, welded_vertices, names) = meshio::read_input(path, &a.input_opts, ui)?;
    let t = Instant::now();
    let (positions, used) = checked_positions(&mesh, path)?;
    let (surfaces, _) = meshio::build_open(&mesh, &names, ui)?;
    let dropped_vertices = surfaces.dropped_vertices.len();
    let input_types = component_types(&surfaces);
    let diagonal = bbox_diagonal(used.iter().map(|&v| positions[v]));
    drop(used);
    let eps = match (a.eps, a.eps_rel) {
        (Some(e), _) => e,
        (None, Some(r)) => {
            let e = r * diagonal;
            if !(e.is_finite() && e > 0.0) {
                return Err(CliError::Input(format!(
                    "--eps-rel {r:?} times the bounding-box diagonal {diagonal:?} gives \
                     ε = {e:?}, not a finite number > 0"
                )));
            }
            e
        }
        // clap's required group gives one of the two.
        (None, None) => {
            return Err(CliError::Input(
                "one of --eps and --eps-rel is required".into(),
            ))
        }
    };
    let seconds_build = t.elapsed().as_secs_f64();
    let options = Options {
        eps,
        mode: a.mode.into(),
        side: a.side.into(),
        position: a.position.into(),
        guard: !a.allow_foldover,
    };
    // The faces are in `surfaces` now; only the positions are still needed.
    let TriMesh {
        positions: mesh_positions,
        faces,
        ..
    } = mesh;
    drop(faces);
    let positions = mesh_positions.as_deref().unwrap_or(&[]);
    let out = simplify_with_progress(surfaces, positions, &options, ui)
        .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
    drop(mesh_positions);
    let t = Instant::now();
    let pb = spinner(
        ui,
        format!(
            "verifying: the output ({} faces) rebuilt from its faces has the input's topology",
            out.mesh.faces.len()
        ),
    );
    let checked = verify(&input_types, &out.mesh);
    pb.finish_and_clear();
    checked.map_err(|e| {
        CliError::Failure(format!(
            "internal error: {}: {e}; nothing written",
            path.display()
        ))
    })?;
    let seconds_verify = t.elapsed().as_secs_f64();
    let seconds_write = meshio::write(&output, &out.mesh, ui)?;
    let report = SimplifyReport {
        file: path.display().to_string(),
        output: output.display(),
        eps,
        eps_rel: a.eps_rel,
        bbox_diagonal: diagonal,
        mode: mode_name(options.mode),
        side: side_name(options.side),
        position: position_name(options.position),
        guard: options.guard,
        stats: out.stats,
        dropped_vertices,
        welded_vertices,
        seconds_read,
        seconds_build,
        seconds_verify,
        seconds_write,
    };
    Ok(report)
}

pub fn run(a: &SimplifyArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        print_human(&report);
    }
    Ok(())
}

fn print_human(r: &SimplifyReport) {
    let s = &r.stats;
    outln!(
        "{} -> {}: {} mode, {} side, {} positions, fold-over guard {}",
        r.file,
        r.output,
        r.mode,
        r.side,
        r.position,
        if r.guard { "on" } else { "off" }
    );
    match r.eps_rel {
        Some(rel) => outln!(
            "  ε = {} ({} × the bounding-box diagonal {})",
            fmt_len(r.eps),
            rel,
            fmt_len(r.bbox_diagonal)
        ),
        None => outln!(
            "  ε = {} (bounding-box diagonal {})",
            fmt_len(r.eps),
            fmt_len(r.bbox_diagonal)
        ),
    }
    let plural =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    outln!(
        "  vertices {} -> {}, faces {} -> {}; {}, {} (kept, checked independently)",
        s.vertices_in,
        s.vertices_out,
        s.faces_in,
        s.faces_out,
        plural(s.components, "component", "components"),
        plural(s.boundary_loops, "boundary loop", "boundary loops")
    );
    outln!(
        "  contractions {}; discs removed {} ({} vertices inside); passes {}",
        s.edges_contracted,
        s.discs_removed,
        s.vertices_removed_inside,
        s.passes
    );
    outln!(
        "  skipped (events over all passes): link condition {}, non-disc {}, fold-over {}, \
         frozen {}",
        s.skipped.link_condition,
        s.skipped.non_disc,
        s.skipped.foldover,
        s.skipped.frozen
    );
    outln!(
        "  edges shorter than ε remaining: {} (link condition {}, non-disc {}, fold-over {})",
        s.short_edges_remaining,
        s.remaining.link_condition,
        s.remaining.non_disc,
        s.remaining.foldover
    );
    outln!(
        "  shortest remaining edge {}; {:.4} s",
        s.shortest_remaining_edge
            .map_or_else(|| "-".to_string(), fmt_len),
        s.seconds
    );
    outln!(
        "  time: read {:.3} s, check input {:.3} s, simplify {:.3} s, verify {:.3} s, write {:.3} s",
        r.seconds_read,
        r.seconds_build,
        s.seconds,
        r.seconds_verify,
        r.seconds_write
    );
    outln!("wrote {}", r.output);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(r: Result<(&[[f64; 3]], Vec<usize>), CliError>) -> String {
        match r {
            Err(CliError::Input(m)) => m,
            Err(CliError::Failure(m)) => panic!("not an input error: {m}"),
            Ok(_) => panic!("accepted"),
        }
    }

    // Files always carry positions (the readers need them), so these cases cannot be
    // reached through the binary: checked here.
    #[test]
    fn positions_are_required_finite_and_not_all_at_one_point() {
        let faces = contractible::gen::tetrahedron().faces;
        let p = Path::new("in.off");
        let none = TriMesh::combinatorial(4, faces.clone());
        assert_eq!(
            message(checked_positions(&none, p)),
            "in.off: the mesh has no vertex positions; simplification needs coordinates"
        );
        let mut pts = vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        ];
        let mut nan = TriMesh::with_positions(pts.clone(), faces.clone());
        if let Some(q) = nan.positions.as_mut() {
            q[2][1] = f64::NAN;
        }
        assert_eq!(
            message(checked_positions(&nan, p)),
            "in.off: vertex 2 has a non-finite coordinate y = NaN"
        );
        let short = TriMesh {
            vertex_count: 4,
            positions: Some(pts[..3].to_vec()),
            faces: faces.clone(),
        };
        assert_eq!(
            message(checked_positions(&short, p)),
            "in.off: the mesh has 4 vertices but 3 positions"
        );
        // An unused vertex elsewhere does not make the used ones distinct.
        let same = TriMesh::with_positions(vec![[2.0, 3.0, 4.0]; 4], faces.clone());
        let m = message(checked_positions(&same, p));
        assert!(
            m.starts_with("in.off: all 4 vertices are at the same point (2, 3, 4)"),
            "{m}"
        );
        pts.push([9.0, 9.0, 9.0]);
        let mut with_unused = TriMesh::with_positions(vec![[0.0; 3]; 4], faces.clone());
        if let Some(q) = with_unused.positions.as_mut() {
            q.push([9.0, 9.0, 9.0]);
        }
        with_unused.vertex_count = 5;
        assert!(message(checked_positions(&with_unused, p)).contains("all 4 vertices"));
        let ok = TriMesh::with_positions(pts, faces);
        let (q, used) = checked_positions(&ok, p).expect("valid positions");
        assert_eq!((q.len(), used), (5, vec![0, 1, 2, 3]));
    }

    fn types_of(m: &TriMesh) -> Vec<TypeKey> {
        component_types(&ConedSurfaces::from_mesh(m).expect("a surface"))
    }

    #[test]
    fn the_output_check_can_fail() {
        use contractible::gen;
        let torus = gen::torus7();
        let tetra = gen::tetrahedron();
        assert_eq!(verify(&types_of(&torus), &torus), Ok(()));
        // Another surface.
        let e = verify(&types_of(&torus), &tetra).unwrap_err();
        assert_eq!(
            e,
            "the output's components (1: χ=2 orientable b=0) differ from the input's \
             (1: χ=0 orientable b=0)"
        );
        // A component more (two tetrahedra) or less.
        let mut two = tetra.faces.clone();
        two.extend(tetra.faces.iter().map(|f| f.map(|v| v + 4)));
        let two = TriMesh::combinatorial(8, two);
        assert!(verify(&types_of(&tetra), &two).is_err());
        assert!(verify(&types_of(&two), &tetra).is_err());
        // A boundary loop more (a face removed): same component count, other type.
        let open = TriMesh::combinatorial(4, tetra.faces[1..].to_vec());
        let e = verify(&types_of(&tetra), &open).unwrap_err();
        assert!(e.contains("χ=1 orientable b=1"), "{e}");
        // Not a surface, or with an unused vertex.
        let bowtie = TriMesh::combinatorial(5, vec![[0, 1, 2], [0, 3, 4]]);
        let e = verify(&types_of(&tetra), &bowtie).unwrap_err();
        assert!(e.starts_with("the output is not a surface: "), "{e}");
        let unused = TriMesh::combinatorial(5, tetra.faces.clone());
        assert_eq!(
            verify(&types_of(&tetra), &unused),
            Err("the output has 1 unused vertices".to_string())
        );
    }
}
