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
    /// Components found by validation (`null` with `--no-validate`).
    components: Option<usize>,
    dropped_vertices: usize,
    validated: bool,
}

pub fn run(a: &ConvertArgs, ui: Ui) -> Result<(), CliError> {
    meshio::check_output(&a.output)?;
    let (mesh, _) = meshio::read(&a.input, ui)?;
    let components = if a.no_validate {
        None
    } else {
        Some(meshio::build(&mesh, &a.input, ui)?.0.components.len())
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
    meshio::write(&a.output, &out, ui)?;
    let report = ConvertReport {
        input: a.input.display().to_string(),
        output: a.output.display().to_string(),
        vertices: out.vertex_count,
        faces: out.faces.len(),
        components,
        dropped_vertices: dropped,
        validated: !a.no_validate,
    };
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!(
            "wrote {}: {} vertices, {} faces{}",
            report.output,
            report.vertices,
            report.faces,
            components.map_or(String::new(), |c| format!(", {c} components"))
        );
    }
    Ok(())
}
