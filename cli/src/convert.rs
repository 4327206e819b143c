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

/// A quad mesh read as it is (every face with 4 corners: what `quad` writes), written as
/// quads: validated as a union of polygon surfaces (every problem listed by `info`),
/// unused vertices dropped.
fn convert_quads(
    a: &ConvertArgs,
    output: &meshio::Output,
    loaded: meshio::Loaded,
    seconds_read: f64,
    ui: Ui,
) -> Result<ConvertReport, CliError> {
    let poly = &loaded.poly;
    let t = std::time::Instant::now();
    let (components, boundary_loops, seconds_build) = if a.no_validate {
        (None, None, None)
    } else {
        let d = contractible::diagnose::diagnose(poly, 5);
        if !d.is_surface() {
            return Err(CliError::Input(format!(
                "{}: the quads are not a union of surfaces; `contractible info` lists every problem",
                loaded.names.shown
            )));
        }
        (
            Some(d.components),
            Some(d.boundary_loops),
            Some(t.elapsed().as_secs_f64()),
        )
    };
    if output.format == contractible::io::Format::Stl {
        return Err(CliError::Input(format!(
            "{}: STL holds triangles only; write the quad mesh as .off, .obj or .ply (or \
             convert with --triangulate)",
            output.display()
        )));
    }
    let quads: Vec<[u32; 4]> = poly
        .faces()
        .filter_map(|f| <[u32; 4]>::try_from(f).ok())
        .collect();
    let mesh = contractible::QuadMesh {
        vertex_count: poly.vertex_count,
        positions: poly.positions.clone(),
        faces: quads,
    };
    let (out, dropped) = mesh.compacted().ok_or_else(|| {
        CliError::Failure(format!(
            "{}: inconsistent mesh after reading",
            a.input.display()
        ))
    })?;
    let seconds_write = meshio::write(output, &out, ui)?;
    Ok(ConvertReport {
        input: a.input.display().to_string(),
        output: output.display(),
        vertices: out.vertex_count,
        faces: out.faces.len(),
        components,
        boundary_loops,
        dropped_vertices: dropped,
        welded_vertices: loaded.welded,
        validated: !a.no_validate,
        seconds_read,
        seconds_build,
        seconds_write,
    })
}

pub fn run(a: &ConvertArgs, ui: Ui) -> Result<(), CliError> {
    let output = meshio::check_output(&a.output, a.output_format.map(Into::into), &[&a.input])?;
    let started = std::time::Instant::now();
    let loaded = meshio::load(&a.input, &a.input_opts, ui)?;
    // Polygon meshes pass through when every face is a quad (what `quad` writes);
    // other polygons need --triangulate (the writers hold triangles or quads).
    let all_quads = loaded.poly.face_count() > 0 && loaded.poly.faces().all(|f| f.len() == 4);
    if all_quads && !a.input_opts.triangulate {
        let seconds_read = started.elapsed().as_secs_f64();
        let report = convert_quads(a, &output, loaded, seconds_read, ui)?;
        return print(&report, ui);
    }
    let welded = loaded.welded;
    let (mesh, names) = meshio::triangles(loaded, &a.input_opts, &a.input, ui)?;
    let seconds_read = started.elapsed().as_secs_f64();
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
    print(&report, ui)
}

fn print(report: &ConvertReport, ui: Ui) -> Result<(), CliError> {
    let (components, boundary_loops) = (report.components, report.boundary_loops);
    if ui.json {
        print_json(report)?;
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
