//! Reading, validating and writing meshes with CLI-style error messages.

use std::path::{Path, PathBuf};
use std::time::Instant;

use contractible::io::{self, Location, ReadError, WriteError};
use contractible::{BuildError, Mesh, Surfaces, TriMesh};

use super::progress::spinner;
use super::{CliError, Ui};

/// `FILE: LOCATION: MESSAGE` (location left out when unknown).
pub fn read_error_message(path: &Path, e: &ReadError) -> String {
    match e.location {
        Location::Unknown => format!("{}: {}", path.display(), e.kind),
        loc => format!("{}: {loc}: {}", path.display(), e.kind),
    }
}

/// `FILE: MESSAGE` for a mesh that is not a union of closed surfaces.
pub fn build_error_message(path: &Path, e: &BuildError) -> String {
    format!("{}: {e}", path.display())
}

/// Reads a triangle mesh (with a spinner); returns it and the seconds taken.
pub fn read(path: &Path, ui: Ui) -> Result<(TriMesh, f64), CliError> {
    let t = Instant::now();
    let pb = spinner(ui, format!("reading {}", path.display()));
    let r = io::read_tri_mesh(path);
    pb.finish_and_clear();
    let mesh = r.map_err(|e| CliError::Input(read_error_message(path, &e)))?;
    Ok((mesh, t.elapsed().as_secs_f64()))
}

/// Validates and splits a mesh into closed surfaces (with a spinner); returns them and
/// the seconds taken. `path` names the source in messages.
pub fn build(mesh: &TriMesh, path: &Path, ui: Ui) -> Result<(Surfaces, f64), CliError> {
    let t = Instant::now();
    let pb = spinner(ui, format!("checking {} faces", mesh.faces.len()));
    let r = Surfaces::from_mesh(mesh);
    pb.finish_and_clear();
    let s = r.map_err(|e| CliError::Input(build_error_message(path, &e)))?;
    if !s.dropped_vertices.is_empty() {
        ui.warn(&format!(
            "{}: {} unused vertices dropped",
            path.display(),
            s.dropped_vertices.len()
        ));
    }
    Ok((s, t.elapsed().as_secs_f64()))
}

/// A temporary path beside `out` that keeps its file name (hence its extension).
fn temp_path(out: &Path) -> PathBuf {
    let name = out
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = format!(".contractible-{}-{name}", std::process::id());
    match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.join(tmp),
        _ => PathBuf::from(tmp),
    }
}

/// Checks that an output name has a supported extension (before any long work).
pub fn check_output(out: &Path) -> Result<(), CliError> {
    if io::Format::from_path(out).0.is_none() {
        return Err(CliError::Input(format!(
            "{}: {}",
            out.display(),
            WriteError::UnknownFormat(out.to_path_buf())
        )));
    }
    Ok(())
}

/// Writes `mesh` to `out` (format by extension) through a temporary file renamed into
/// place, so that a failed write leaves no partial output.
pub fn write<const N: usize>(out: &Path, mesh: &Mesh<N>, ui: Ui) -> Result<f64, CliError> {
    let t = Instant::now();
    check_output(out)?;
    let pb = spinner(ui, format!("writing {}", out.display()));
    let tmp = temp_path(out);
    let r =
        io::write_mesh(&tmp, mesh).and_then(|()| std::fs::rename(&tmp, out).map_err(Into::into));
    pb.finish_and_clear();
    if let Err(e) = r {
        let _ = std::fs::remove_file(&tmp);
        return Err(CliError::Failure(format!("{}: {e}", out.display())));
    }
    Ok(t.elapsed().as_secs_f64())
}
