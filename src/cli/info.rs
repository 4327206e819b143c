//! `contractible info FILE`: validation and topology per component. Surfaces with
//! boundary are described (χ, orientability, genus, boundary loops and their lengths);
//! a closed mesh's report has no boundary field at all, so it is what it was before
//! boundaries were supported.

use std::path::Path;

use contractible::{ConedComponent, ConedSurfaces, SurfaceType, Surfaces, Triangulation};
use serde::Serialize;

use super::args::InfoArgs;
use super::{meshio, print_json, CliError, Ui};

/// Topology of one connected surface.
#[derive(Serialize, Debug, Clone)]
pub struct ComponentInfo {
    pub vertices: usize,
    pub edges: usize,
    pub faces: usize,
    /// Printed as `euler_characteristic`, `orientable`, `genus` (orientable genus, `null`
    /// for a non-orientable surface) and `euler_genus` (`2 - χ - b`), then
    /// `boundary_loops` (b) for a surface with boundary only.
    #[serde(flatten)]
    pub surface: SurfaceType,
    /// The length (number of edges) of each boundary loop, in loop order; left out for
    /// a closed surface.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub boundary_loop_lengths: Vec<usize>,
    pub degree_min: usize,
    pub degree_max: usize,
    pub degree_mean: f64,
    /// Entry `d`: number of vertices of degree `d`.
    pub degree_histogram: Vec<usize>,
}

impl ComponentInfo {
    pub fn of(t: &Triangulation) -> Self {
        let hist = t.degree_histogram();
        let degree_min = hist.iter().position(|&n| n > 0).unwrap_or(0);
        let degree_max = hist.len().saturating_sub(1);
        ComponentInfo {
            vertices: t.vertex_count(),
            edges: t.edge_count(),
            faces: t.face_count(),
            surface: SurfaceType::of(t),
            boundary_loop_lengths: Vec::new(),
            degree_min,
            degree_max,
            degree_mean: 2.0 * t.edge_count() as f64 / t.vertex_count().max(1) as f64,
            degree_histogram: hist,
        }
    }
}

impl ComponentInfo {
    /// The description of the surface with boundary a coned component stands for: the
    /// virtual vertices, their edges and the cone faces are left out of every count and
    /// degree. A closed component gives exactly [`Self::of`] of its triangulation.
    pub fn of_coned(c: &ConedComponent) -> Self {
        if c.is_closed() {
            return Self::of(&c.tri);
        }
        let t = &c.tri;
        let mut on_boundary = vec![false; t.vertex_capacity()];
        for w in c.virtual_vertices() {
            for x in t.link(w) {
                on_boundary[x.index()] = true;
            }
        }
        let mut hist: Vec<usize> = Vec::new();
        for v in t.vertices().filter(|&v| !c.is_virtual(v)) {
            // A boundary vertex has exactly one virtual neighbour (its loop's apex).
            let d = t.degree(v) - usize::from(on_boundary[v.index()]);
            if hist.len() <= d {
                hist.resize(d + 1, 0);
            }
            hist[d] += 1;
        }
        let (vertices, edges, faces) = c.open_counts();
        ComponentInfo {
            vertices,
            edges,
            faces,
            surface: c.surface_type(),
            boundary_loop_lengths: c.loop_lengths(),
            degree_min: hist.iter().position(|&n| n > 0).unwrap_or(0),
            degree_max: hist.len().saturating_sub(1),
            degree_mean: 2.0 * edges as f64 / vertices.max(1) as f64,
            degree_histogram: hist,
        }
    }
}

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

pub fn run(a: &InfoArgs, ui: Ui) -> Result<(), CliError> {
    let (mesh, seconds_read, welded) = meshio::read_input(&a.file, a.weld, ui)?;
    let (surfaces, seconds_build) = meshio::build_open(&mesh, &a.file, ui)?;
    let mut report = Report::of_coned(&a.file, &surfaces, Some(seconds_read), Some(seconds_build));
    report.welded_vertices = welded;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        report.print_human(20);
    }
    Ok(())
}
