//! `contractible info FILE`: validation and topology per component. Surfaces with
//! boundary are described (χ, orientability, genus, boundary loops and their lengths);
//! a closed mesh's report has no boundary field at all.
//!
//! A mesh that is not a surface gets every problem at once ([`contractible::diagnose`]):
//! a count per kind with a hint in plain words and the first few located examples, on
//! stdout (or as `problems` in the JSON), and exit code 2. A polygon mesh (faces with
//! more than 3 corners, read without `--triangulate`) is described as it is: V, E, F, χ,
//! components, orientability, boundary loops, and whether it is a closed manifold
//! polygon surface.

use std::path::Path;

use contractible::diagnose::{diagnose, Diagnosis, Problem, ProblemKind};
use contractible::{ConedSurfaces, Surfaces};
use serde::Serialize;

use super::args::InfoArgs;
use super::meshio::Names;
use super::{meshio, print_json, CliError, Ui};

/// Topology of one connected surface: the library's description (the same JSON keys).
pub type ComponentInfo = contractible::task::ComponentDescription;

/// The JSON result of `info` (also printed by `gen --json`).
#[derive(Serialize, Debug, Clone)]
pub struct Report {
    pub file: String,
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    pub components: usize,
    pub euler_characteristic: i64,
    /// True when every component is orientable.
    pub orientable: bool,
    /// Boundary loops over all components; left out when every component is closed.
    #[serde(skip_serializing_if = "is_zero")]
    pub boundary_loops: usize,
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,
    /// Faces with more than 3 corners cut by `--triangulate` (present only with it).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub triangulated_polygons: Option<usize>,
    pub component_list: Vec<ComponentInfo>,
    /// Reading the file (absent for a mesh that was not read: built-in and generated).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_read: Option<f64>,
    /// Validating it (absent when not timed).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_build: Option<f64>,
}

fn is_zero(n: &usize) -> bool {
    *n == 0
}

impl Report {
    pub fn of(
        file: &Path,
        s: &Surfaces,
        seconds_read: Option<f64>,
        seconds_build: Option<f64>,
    ) -> Self {
        let list: Vec<ComponentInfo> = s
            .components
            .iter()
            .map(|c| ComponentInfo::of(&c.tri))
            .collect();
        Self::of_list(
            file,
            list,
            s.dropped_vertices.len(),
            seconds_read,
            seconds_build,
        )
    }

    /// The report of a mesh that may have boundary (`info`'s).
    pub fn of_coned(
        file: &Path,
        s: &ConedSurfaces,
        seconds_read: Option<f64>,
        seconds_build: Option<f64>,
    ) -> Self {
        let list: Vec<ComponentInfo> = s.components.iter().map(ComponentInfo::of_coned).collect();
        Self::of_list(
            file,
            list,
            s.dropped_vertices.len(),
            seconds_read,
            seconds_build,
        )
    }

    fn of_list(
        file: &Path,
        list: Vec<ComponentInfo>,
        dropped_vertices: usize,
        seconds_read: Option<f64>,
        seconds_build: Option<f64>,
    ) -> Self {
        Report {
            file: file.display().to_string(),
            vertices: list.iter().map(|c| c.vertices).sum(),
            edges: list.iter().map(|c| c.edges).sum(),
            faces: list.iter().map(|c| c.faces).sum(),
            components: list.len(),
            euler_characteristic: list.iter().map(|c| c.surface.euler_characteristic()).sum(),
            orientable: list.iter().all(|c| c.surface.is_orientable()),
            boundary_loops: list.iter().map(|c| c.surface.boundary_loops()).sum(),
            dropped_vertices,
            welded_vertices: None,
            triangulated_polygons: None,
            component_list: list,
            seconds_read,
            seconds_build,
        }
    }

    /// Human-readable summary; lists at most `max_rows` components one per line and
    /// groups the rest by surface.
    pub fn print_human(&self, max_rows: usize) {
        let boundary = match self.boundary_loops {
            0 => String::new(),
            n => format!(" boundary loops={n}"),
        };
        outln!(
            "{}: V={} E={} F={} χ={} components={} {}{boundary}",
            self.file,
            self.vertices,
            self.edges,
            self.faces,
            self.euler_characteristic,
            self.components,
            if self.orientable {
                "orientable"
            } else {
                "non-orientable"
            }
        );
        if self.dropped_vertices > 0 {
            outln!("  unused vertices dropped: {}", self.dropped_vertices);
        }
        if let Some(n) = self.welded_vertices {
            outln!("  vertices merged by --weld: {n}");
        }
        for (i, c) in self.component_list.iter().enumerate().take(max_rows) {
            let lengths = if c.boundary_loop_lengths.is_empty() {
                String::new()
            } else {
                format!(
                    "; boundary loop lengths {}",
                    join_lengths(&c.boundary_loop_lengths, 20)
                )
            };
            outln!(
                "  component {i}: V={} E={} F={} χ={} {}; degree min {} max {} mean {:.2}{lengths}",
                c.vertices,
                c.edges,
                c.faces,
                c.surface.euler_characteristic(),
                c.surface,
                c.degree_min,
                c.degree_max,
                c.degree_mean
            );
        }
        if self.components > max_rows {
            let mut kinds: Vec<(String, usize)> = Vec::new();
            for c in &self.component_list[max_rows..] {
                let n = c.surface.name();
                match kinds.iter_mut().find(|(k, _)| *k == n) {
                    Some((_, count)) => *count += 1,
                    None => kinds.push((n, 1)),
                }
            }
            let rest: Vec<String> = kinds.iter().map(|(k, n)| format!("{n} × {k}")).collect();
            outln!(
                "  ... {} more components: {}",
                self.components - max_rows,
                rest.join(", ")
            );
        }
    }
}

/// At most `max` lengths, comma-separated, then `… (N more)` (the JSON has them all).
fn join_lengths(lengths: &[usize], max: usize) -> String {
    let shown: Vec<String> = lengths.iter().take(max).map(|n| n.to_string()).collect();
    let mut s = shown.join(", ");
    if lengths.len() > max {
        s.push_str(&format!(", … ({} more)", lengths.len() - max));
    }
    s
}

/// How many located examples of each kind of problem are shown.
const EXAMPLES: usize = 5;

/// One located example of a problem, as printed and in JSON: faces and vertices
/// numbered as the file does (`index_base` in the report), with the faces' lines when
/// the format is text.
#[derive(Serialize, Debug)]
struct ExampleJson {
    message: String,
    faces: Vec<usize>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    lines: Vec<usize>,
    vertices: Vec<u64>,
    /// Faces at a non-manifold edge, sheets at a pinched vertex, edges of a boundary
    /// loop; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    multiplicity: Option<usize>,
}

#[derive(Serialize, Debug)]
struct ProblemJson {
    kind: &'static str,
    count: usize,
    /// What it means, in plain words.
    hint: String,
    examples: Vec<ExampleJson>,
}

/// `info`'s result for a mesh that is not a surface, or for a polygon mesh.
#[derive(Serialize, Debug)]
pub struct DiagnosisReport {
    file: String,
    /// Whether the faces form a union of surfaces (possibly with boundary).
    surface: bool,
    /// Whether it is a union of closed surfaces.
    closed: bool,
    /// Whether faces have more than 3 corners.
    polygons: bool,
    corners_min: usize,
    corners_max: usize,
    /// Vertices used by faces.
    vertices: usize,
    edges: usize,
    faces: usize,
    components: usize,
    euler_characteristic: i64,
    /// Absent when a non-manifold edge makes orientability meaningless (so the key is a
    /// bool wherever it appears, as in every other report).
    #[serde(skip_serializing_if = "Option::is_none")]
    orientable: Option<bool>,
    boundary_loops: usize,
    unused_vertices: usize,
    /// 1 for OBJ (its own numbering), 0 otherwise.
    index_base: u8,
    #[serde(skip_serializing_if = "Option::is_none")]
    welded_vertices: Option<usize>,
    problems: Vec<ProblemJson>,
    /// The unwelded-soup hint, when the mesh looks like one.
    #[serde(skip_serializing_if = "Option::is_none")]
    soup: Option<String>,
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// The kind's count in words (`12 duplicate faces`).
fn count_words(kind: ProblemKind, n: usize) -> String {
    match kind {
        ProblemKind::NoFaces => "no faces".into(),
        ProblemKind::IndexOutOfRange => plural(
            n,
            "face with a missing vertex",
            "faces with a missing vertex",
        ),
        ProblemKind::DegenerateFace => plural(n, "degenerate face", "degenerate faces"),
        ProblemKind::DuplicateFace => plural(n, "duplicate face", "duplicate faces"),
        ProblemKind::NonManifoldEdge => plural(n, "non-manifold edge", "non-manifold edges"),
        ProblemKind::PinchedVertex => plural(n, "pinched vertex", "pinched vertices"),
        ProblemKind::Boundary => format!(
            "open surface, {}",
            plural(n, "boundary loop", "boundary loops")
        ),
    }
}

fn hint(kind: ProblemKind, welded: bool) -> String {
    match kind {
        ProblemKind::NoFaces => "the file has no faces at all".into(),
        ProblemKind::IndexOutOfRange => "faces refer to vertices the file does not have".into(),
        ProblemKind::DegenerateFace => {
            let mut h = String::from("a face uses the same vertex twice, so it has no area");
            if welded {
                h.push_str("; --weld merged its corners: a smaller tolerance keeps them apart");
            }
            h
        }
        ProblemKind::DuplicateFace => {
            "the same face is listed more than once (same vertices); delete the copies".into()
        }
        ProblemKind::NonManifoldEdge => {
            "more than two faces meet along each of these edges (a fin, or surfaces glued along an edge)".into()
        }
        ProblemKind::PinchedVertex => {
            "the surface touches itself at these vertices: separate surface sheets meet at one point".into()
        }
        ProblemKind::Boundary => {
            "the surface has holes; `info`, `convert` and `simplify` accept that, `reduce` and `quad` need closed surfaces".into()
        }
    }
}

fn example(p: &Problem, names: &Names, vertex_count: usize) -> ExampleJson {
    let face = |f: usize| names.face_number(f);
    let mut faces = Vec::new();
    let mut lines = Vec::new();
    let mut add_face = |f: usize| {
        let (n, l) = face(f);
        faces.push(n);
        if let Some(l) = l {
            lines.push(l);
        }
    };
    let (message, vertices, multiplicity) = match *p {
        Problem::NoFaces => ("the mesh has no faces".to_string(), vec![], None),
        Problem::IndexOutOfRange { face: f, vertex } => {
            add_face(f);
            let v = u64::from(vertex) + u64::from(names.one_based());
            (
                format!(
                    "{} refers to vertex {v}, but there are {vertex_count} vertices",
                    names.face(f)
                ),
                vec![v],
                None,
            )
        }
        Problem::DegenerateFace { face: f, vertex } => {
            add_face(f);
            (
                format!(
                    "{} uses vertex {} twice",
                    names.face(f),
                    names.vertex_number(vertex)
                ),
                vec![names.vertex_number(vertex)],
                None,
            )
        }
        Problem::DuplicateFace { face: f, first } => {
            add_face(f);
            add_face(first);
            (
                format!(
                    "{} repeats the vertices of {}",
                    names.face(f),
                    names.face(first)
                ),
                vec![],
                None,
            )
        }
        Problem::NonManifoldEdge {
            a,
            b,
            faces: k,
            first_face,
        } => {
            add_face(first_face);
            (
                format!(
                    "edge {} is non-manifold, shared by {k} faces (first: {})",
                    names.edge(a, b),
                    names.face(first_face)
                ),
                vec![names.vertex_number(a), names.vertex_number(b)],
                Some(k),
            )
        }
        Problem::PinchedVertex { vertex, sheets } => (
            format!(
                "vertex {}: {sheets} surface sheets meet here",
                names.vertex_number(vertex)
            ),
            vec![names.vertex_number(vertex)],
            Some(sheets),
        ),
        Problem::BoundaryLoop {
            a,
            b,
            face: f,
            edges,
        } => {
            add_face(f);
            (
                format!(
                    "a loop of {} through edge {} ({})",
                    plural(edges, "edge", "edges"),
                    names.edge(a, b),
                    names.face(f)
                ),
                vec![names.vertex_number(a), names.vertex_number(b)],
                Some(edges),
            )
        }
    };
    ExampleJson {
        message,
        faces,
        lines,
        vertices,
        multiplicity,
    }
}

impl DiagnosisReport {
    fn of(
        d: &Diagnosis,
        names: &Names,
        vertex_count: usize,
        corners: (usize, usize),
        welded_vertices: Option<usize>,
        soup: Option<String>,
    ) -> Self {
        let welded = welded_vertices.is_some();
        DiagnosisReport {
            file: names.shown.clone(),
            surface: d.is_surface(),
            closed: d.is_closed_surface(),
            polygons: corners.1 > 3,
            corners_min: corners.0,
            corners_max: corners.1,
            vertices: d.vertices,
            edges: d.edges,
            faces: d.faces,
            components: d.components,
            euler_characteristic: d.euler_characteristic,
            orientable: d.orientable,
            boundary_loops: d.boundary_loops,
            unused_vertices: d.unused_vertices,
            index_base: u8::from(names.one_based()),
            welded_vertices,
            problems: d
                .groups
                .iter()
                .map(|g| ProblemJson {
                    kind: g.kind.name(),
                    count: g.count,
                    hint: hint(g.kind, welded),
                    examples: g
                        .examples
                        .iter()
                        .map(|p| example(p, names, vertex_count))
                        .collect(),
                })
                .collect(),
            soup,
        }
    }

    /// The problems other than the boundary, in words (`12 duplicate faces, ...`).
    fn summary(&self, d: &Diagnosis) -> String {
        let words: Vec<String> = d
            .groups
            .iter()
            .filter(|g| g.kind != ProblemKind::Boundary)
            .map(|g| count_words(g.kind, g.count))
            .collect();
        words.join(", ")
    }

    fn print_human(&self, d: &Diagnosis) {
        let orient = match self.orientable {
            Some(true) => " orientable",
            Some(false) => " non-orientable",
            None => "",
        };
        let kind = if self.polygons {
            format!(
                "polygon mesh (faces of {} to {} corners)",
                self.corners_min, self.corners_max
            )
        } else {
            "triangle mesh".into()
        };
        outln!(
            "{}: {kind}: V={} E={} F={} χ={} components={}{orient}",
            self.file,
            self.vertices,
            self.edges,
            self.faces,
            self.euler_characteristic,
            self.components
        );
        if self.unused_vertices > 0 {
            outln!("  unused vertices: {}", self.unused_vertices);
        }
        if let Some(n) = self.welded_vertices {
            outln!("  vertices merged by --weld: {n}");
        }
        let what = if self.polygons { "polygon" } else { "triangle" };
        if self.closed {
            outln!("  a closed manifold {what} surface");
        } else if self.surface {
            outln!(
                "  a manifold {what} surface with boundary ({})",
                plural(self.boundary_loops, "boundary loop", "boundary loops")
            );
        } else {
            outln!(
                "  not a surface: {}",
                plural(
                    d.groups
                        .iter()
                        .filter(|g| g.kind != ProblemKind::Boundary)
                        .count(),
                    "kind of problem",
                    "kinds of problems"
                )
            );
        }
        for (g, p) in d.groups.iter().zip(&self.problems) {
            if self.surface && g.kind == ProblemKind::Boundary {
                continue;
            }
            outln!("  {}: {}", count_words(g.kind, g.count), p.hint);
            for e in &p.examples {
                outln!("    {}", e.message);
            }
            if g.count > p.examples.len() && g.kind != ProblemKind::NoFaces {
                outln!("    … and {} more", g.count - p.examples.len());
            }
        }
        if let Some(s) = &self.soup {
            outln!("  {s}");
        }
    }
}

/// The diagnosis made final: a mesh the builder refused although the diagnosis accepts
/// it (a case it does not classify) is never called a surface. Returns the report and,
/// for a non-surface, the error.
fn finish_diagnosis(
    mut report: DiagnosisReport,
    d: &Diagnosis,
    names: &Names,
    core_error: Option<String>,
) -> (DiagnosisReport, Option<CliError>) {
    if let (true, Some(e)) = (report.surface, &core_error) {
        report.surface = false;
        report.closed = false;
        report.problems.push(ProblemJson {
            kind: "other",
            count: 1,
            hint: "the mesh is not a surface for another reason".into(),
            examples: vec![ExampleJson {
                message: e.clone(),
                faces: vec![],
                lines: vec![],
                vertices: vec![],
                multiplicity: None,
            }],
        });
    }
    if report.surface {
        return (report, None);
    }
    let mut summary = report.summary(d);
    if let Some(e) = core_error.filter(|_| summary.is_empty()) {
        summary = e;
    }
    let err = CliError::Input(format!("{}: not a surface: {summary}", names.shown));
    (report, Some(err))
}

/// What `info` found: the description of a surface (with or without boundary), or the
/// diagnosis of a mesh that is not one (or of a polygon mesh) with its error.
pub enum Outcome {
    /// A surface.
    Surface(Box<Report>),
    /// Every problem (or a polygon mesh's description); `error` is set for a non-surface.
    Diagnosis {
        /// The report.
        report: Box<DiagnosisReport>,
        /// What the human-readable listing needs.
        diagnosis: Box<Diagnosis>,
        /// The error (exit code 2) of a non-surface.
        error: Option<CliError>,
    },
}

/// Runs `info` without printing anything but warnings (unless quiet).
pub fn compute(a: &InfoArgs, ui: Ui) -> Result<Outcome, CliError> {
    let diagnosis = |report, d: Diagnosis, names: &Names, core| {
        let (report, error) = finish_diagnosis(report, &d, names, core);
        Outcome::Diagnosis {
            report: Box::new(report),
            diagnosis: Box::new(d),
            error,
        }
    };
    let t = std::time::Instant::now();
    let loaded = meshio::load(&a.file, &a.input_opts, ui)?;
    if !loaded.poly.is_triangle_mesh() && !a.input_opts.triangulate {
        let corners = loaded.poly.corner_range();
        let d = diagnose(&loaded.poly, EXAMPLES);
        let report = DiagnosisReport::of(
            &d,
            &loaded.names,
            loaded.poly.vertex_count,
            corners,
            loaded.welded,
            None,
        );
        return Ok(diagnosis(report, d, &loaded.names, None));
    }
    let welded = loaded.welded;
    let polygons_before = (!loaded.poly.is_triangle_mesh())
        .then(|| loaded.poly.faces().filter(|f| f.len() > 3).count());
    let (mesh, names) = meshio::triangles(loaded, &a.input_opts, &a.file, ui)?;
    let seconds_read = t.elapsed().as_secs_f64();
    let t = std::time::Instant::now();
    let surfaces = match meshio::try_build_open(&mesh, ui) {
        Ok(s) => s,
        Err(e) => {
            let d = diagnose(&mesh, EXAMPLES);
            let soup = meshio::soup_hint(&mesh, &names);
            let report = DiagnosisReport::of(&d, &names, mesh.vertex_count, (3, 3), welded, soup);
            let core = meshio::build_error_message(&names, &e);
            return Ok(diagnosis(report, d, &names, Some(core)));
        }
    };
    meshio::warn_soup_and_dropped(&mesh, &surfaces, &names, ui);
    let seconds_build = t.elapsed().as_secs_f64();
    let mut report = Report::of_coned(
        Path::new(&names.shown),
        &surfaces,
        Some(seconds_read),
        Some(seconds_build),
    );
    report.welded_vertices = welded;
    report.triangulated_polygons = a
        .input_opts
        .triangulate
        .then_some(polygons_before.unwrap_or(0));
    Ok(Outcome::Surface(Box::new(report)))
}

pub fn run(a: &InfoArgs, ui: Ui) -> Result<(), CliError> {
    match compute(a, ui)? {
        Outcome::Surface(report) => {
            if ui.json {
                print_json(&report)?;
            } else if !ui.quiet {
                report.print_human(20);
            }
            Ok(())
        }
        Outcome::Diagnosis {
            report,
            diagnosis,
            error,
        } => {
            if ui.json {
                print_json(&report)?;
            } else if !ui.quiet {
                report.print_human(&diagnosis);
            }
            error.map_or(Ok(()), Err)
        }
    }
}
