//! `contractible convert IN OUT`: format conversion by extension.

use serde::Serialize;

use super::args::ConvertArgs;
use super::{meshio, print_json, CliError, Ui};

#[derive(Serialize)]
struct ConvertReport {
    input: String,
    output: String,
    vertices: usize,
    faces: usize,
    /// Components found by validation (absent with `--no-validate`).
    #[serde(skip_serializing_if = "Option::is_none")]
    components: Option<usize>,
    /// Boundary loops found by validation (absent with `--no-validate`).
    #[serde(skip_serializing_if = "Option::is_none")]
    boundary_loops: Option<usize>,
    dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    welded_vertices: Option<usize>,
    validated: bool,
    seconds_read: f64,
    /// Validating the input (absent with `--no-validate`).
    #[serde(skip_serializing_if = "Option::is_none")]
    seconds_build: Option<f64>,
    seconds_write: f64,
}

pub fn run(a: &ConvertArgs, ui: Ui) -> Result<(), CliError> {
    let output = meshio::check_output(&a.output, a.output_format.map(Into::into), &[&a.input])?;
    let (mesh, seconds_read, welded, names) = meshio::read_input(&a.input, &a.input_opts, ui)?;
    // Surfaces with boundary are valid input: validation refuses only what is not a
    // surface (non-manifold edges or vertices, bad faces), with its location.
    let (components, boundary_loops, seconds_build) = if a.no_validate {
        (None, None, None)
    } else {
        let (s, t) = meshio::build_open(&mesh, &names, ui)?;
        (Some(s.components.len()), Some(s.loop_count()), Some(t))
    };
    // The readers reject out-of-range indices and give one position per vertex.
    let (out, dropped) = mesh.compacted().ok_or_else(|| {
        CliError::Failure(format!(
            "{}: inconsistent mesh after reading",
            a.input.display()
        ))
    })?;
    if a.no_validate && dropped > 0 {
        ui.warn(&format!(
            "{}: {dropped} unused vertices dropped",
            a.input.display()
        ));
    }
    let seconds_write = meshio::write(&output, &out, ui)?;
    let report = ConvertReport {
        input: a.input.display().to_string(),
        output: output.display(),
        vertices: out.vertex_count,
        faces: out.faces.len(),
        components,
        boundary_loops,
        dropped_vertices: dropped,
        welded_vertices: welded,
        validated: !a.no_validate,
        seconds_read,
        seconds_build,
        seconds_write,
    };
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!(
            "wrote {}: {} vertices, {} faces{}{}",
            report.output,
            report.vertices,
            report.faces,
            components.map_or(String::new(), |c| format!(", {c} components")),
            boundary_loops
                .filter(|&b| b > 0)
                .map_or(String::new(), |b| format!(", {b} boundary loops"))
        );
    }
    Ok(())
}
