//! `contractible info FILE`: validation and topology per component.

use std::path::Path;

use contractible::{SurfaceType, Surfaces, Triangulation};
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
    /// for a non-orientable surface) and `euler_genus` (`2 - χ`).
    #[serde(flatten)]
    pub surface: SurfaceType,
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
            degree_min,
            degree_max,
            degree_mean: 2.0 * t.edge_count() as f64 / t.vertex_count().max(1) as f64,
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
    pub dropped_vertices: usize,
    pub component_list: Vec<ComponentInfo>,
    pub seconds_read: f64,
    pub seconds_build: f64,
}

impl Report {
    pub fn of(file: &Path, s: &Surfaces, seconds_read: f64, seconds_build: f64) -> Self {
        let list: Vec<ComponentInfo> = s
            .components
            .iter()
            .map(|c| ComponentInfo::of(&c.tri))
            .collect();
        let (v, e, f) = s.counts();
        Report {
            file: file.display().to_string(),
            vertices: v,
            edges: e,
            faces: f,
            components: list.len(),
            euler_characteristic: list.iter().map(|c| c.surface.euler_characteristic()).sum(),
            orientable: list.iter().all(|c| c.surface.is_orientable()),
            dropped_vertices: s.dropped_vertices.len(),
            component_list: list,
            seconds_read,
            seconds_build,
        }
    }

    /// Human-readable summary; lists at most `max_rows` components one per line and
    /// groups the rest by surface.
    pub fn print_human(&self, max_rows: usize) {
        outln!(
            "{}: V={} E={} F={} χ={} components={} {}",
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
        for (i, c) in self.component_list.iter().enumerate().take(max_rows) {
            outln!(
                "  component {i}: V={} E={} F={} χ={} {}; degree min {} max {} mean {:.2}",
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

pub fn run(a: &InfoArgs, ui: Ui) -> Result<(), CliError> {
    let (mesh, seconds_read) = meshio::read(&a.file, ui)?;
    let (surfaces, seconds_build) = meshio::build(&mesh, &a.file, ui)?;
    let report = Report::of(&a.file, &surfaces, seconds_read, seconds_build);
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        report.print_human(20);
    }
    Ok(())
}
