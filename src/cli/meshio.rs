//! Reading, validating and writing meshes with CLI-style error messages.

use std::path::{Path, PathBuf};
use std::time::Instant;

use contractible::io::{self, Location, ReadError, WriteError};
use contractible::{BuildError, ConedSurfaces, Mesh, Surfaces, TriMesh};

use super::progress::spinner;
use super::{CliError, Ui};

/// `FILE: LOCATION: MESSAGE` (location left out when unknown).
pub fn read_error_message(path: &Path, e: &ReadError) -> String {
    match e.location {
        Location::Unknown => format!("{}: {}", path.display(), e.kind),
        loc => format!("{}: {loc}: {}", path.display(), e.kind),
    }
}

/// `FILE: MESSAGE` for a mesh that is not a union of closed surfaces (or, for `info`,
/// of surfaces with boundary).
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

/// Reads an input mesh (see [`read`]); with `weld`, merges its vertices at bitwise-equal
/// positions ([`Mesh::welded`]) and says how many on stderr (unless quiet). Returns the
/// mesh, the seconds taken (welding included) and the number of vertices merged (`Some`
/// exactly when `weld`).
pub fn read_input(
    path: &Path,
    weld: bool,
    ui: Ui,
) -> Result<(TriMesh, f64, Option<usize>), CliError> {
    let t = Instant::now();
    let (mesh, _) = read(path, ui)?;
    if !weld {
        return Ok((mesh, t.elapsed().as_secs_f64(), None));
    }
    let before = mesh.vertex_count;
    let (mesh, merged) = mesh.welded().ok_or_else(|| {
        CliError::Failure(format!(
            "{}: inconsistent mesh after reading",
            path.display()
        ))
    })?;
    if !ui.quiet {
        eprintln!(
            "{}: --weld merged {merged} vertices at identical positions ({before} -> {} vertices)",
            path.display(),
            mesh.vertex_count
        );
    }
    Ok((mesh, t.elapsed().as_secs_f64(), Some(merged)))
}

/// A vertex count is "many" coincident vertices from this fraction of all vertices on.
const SOUP_COINCIDENT_FRACTION: usize = 10;
/// Welding that makes more than this fraction of the faces degenerate is no cure.
const SOUP_DEGENERATE_FRACTION: usize = 100;

/// One line saying that `mesh` looks like an unwelded triangle soup, and what to do, when
/// it does: some vertices sit at the position of another (bitwise) and either every edge
/// is a boundary edge (each in one face, over two faces or more) or at least a tenth of
/// the vertices are such duplicates, and welding makes at most one face in a hundred
/// degenerate. `None` otherwise (welding cannot help a mesh without coincident
/// positions, nor one whose positions do not tell its vertices apart).
pub fn soup_hint(mesh: &TriMesh, path: &Path) -> Option<String> {
    let coincident = mesh.coincident_vertex_count();
    if coincident == 0 {
        return None;
    }
    let mut uses: std::collections::HashMap<(u32, u32), u32> =
        std::collections::HashMap::with_capacity(mesh.faces.len() * 3 / 2);
    for f in &mesh.faces {
        for i in 0..3 {
            let (a, b) = (f[i], f[(i + 1) % 3]);
            *uses.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    let all_boundary = mesh.faces.len() >= 2 && uses.values().all(|&n| n == 1);
    let many = coincident * SOUP_COINCIDENT_FRACTION >= mesh.vertex_count;
    if !(all_boundary || many) {
        return None;
    }
    // Welding must help: a mesh whose positions do not separate its vertices (all at
    // 0 0 0, as `gen random` writes them) would collapse, so it is no soup.
    let degenerate = mesh.welded().map_or(usize::MAX, |(w, _)| {
        w.faces
            .iter()
            .filter(|f| f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
            .count()
    });
    if degenerate.saturating_mul(SOUP_DEGENERATE_FRACTION) > mesh.faces.len() {
        return None;
    }
    let why = if all_boundary {
        "every edge is a boundary edge and "
    } else {
        ""
    };
    Some(format!(
        "{}: this looks like an unwelded triangle soup ({why}{coincident} of {} vertices sit at \
         the position of another vertex): try --weld, which merges vertices at identical positions",
        path.display(),
        mesh.vertex_count
    ))
}

/// An invalid-input error for `mesh` with `message`, followed by the soup hint when the
/// mesh looks like an unwelded soup.
fn invalid(mesh: &TriMesh, path: &Path, message: String) -> CliError {
    match soup_hint(mesh, path) {
        Some(hint) => CliError::Input(format!("{message}\n{hint}")),
        None => CliError::Input(message),
    }
}

/// Validates and splits a mesh into closed surfaces (with a spinner); returns them and
/// the seconds taken. `path` names the source in messages.
pub fn build(mesh: &TriMesh, path: &Path, ui: Ui) -> Result<(Surfaces, f64), CliError> {
    let t = Instant::now();
    let pb = spinner(ui, format!("checking {} faces", mesh.faces.len()));
    let r = Surfaces::from_mesh(mesh);
    pb.finish_and_clear();
    let s = r.map_err(|e| CliError::Input(build_error_message(path, &e)))?;
    warn_dropped(path, s.dropped_vertices.len(), ui);
    Ok((s, t.elapsed().as_secs_f64()))
}

/// [`build`] for a command that needs closed surfaces (`command` names it): a mesh
/// whose only problem is its boundary is refused with a message that says so and how
/// many boundary loops it has.
pub fn build_closed(
    mesh: &TriMesh,
    path: &Path,
    ui: Ui,
    command: &str,
) -> Result<(Surfaces, f64), CliError> {
    let t = Instant::now();
    let pb = spinner(ui, format!("checking {} faces", mesh.faces.len()));
    let r = Surfaces::from_mesh(mesh);
    let r = match r {
        Err(BuildError::BoundaryEdge { a, b, face }) => {
            // The boundary edge is the first problem found; say whether the mesh is a
            // surface with boundary (which `info` describes) or broken in another way.
            let open = Surfaces::from_mesh_with_boundary(mesh);
            pb.finish_and_clear();
            let why = match open {
                Ok(s) => {
                    let n = s.loop_count();
                    let loops = if n == 1 { "loop" } else { "loops" };
                    format!("this mesh has {n} boundary {loops}; `info` describes it")
                }
                Err(e) => format!("nor is it a surface with boundary: {e}"),
            };
            return Err(invalid(
                mesh,
                path,
                format!(
                    "{}: edge [{a}, {b}] is a boundary edge (face {face}): `{command}` needs closed surfaces ({why})",
                    path.display()
                ),
            ));
        }
        r => r,
    };
    pb.finish_and_clear();
    let s = r.map_err(|e| invalid(mesh, path, build_error_message(path, &e)))?;
    warn_dropped(path, s.dropped_vertices.len(), ui);
    Ok((s, t.elapsed().as_secs_f64()))
}

/// Validates and splits a mesh into compact surfaces that may have boundary, each
/// closed by coning (with a spinner); returns them and the seconds taken. A valid mesh
/// with boundary that looks like an unwelded soup (every triangle its own disc, say) gets
/// the soup hint as a warning; an invalid one gets it in the error.
pub fn build_open(mesh: &TriMesh, path: &Path, ui: Ui) -> Result<(ConedSurfaces, f64), CliError> {
    let t = Instant::now();
    let pb = spinner(ui, format!("checking {} faces", mesh.faces.len()));
    let r = Surfaces::from_mesh_with_boundary(mesh);
    pb.finish_and_clear();
    let s = r.map_err(|e| invalid(mesh, path, build_error_message(path, &e)))?;
    // A valid mesh of closed surfaces is no soup (a soup's triangles are open discs),
    // and skipping it spares the position hashing on every large closed input.
    if !ui.quiet && !s.is_closed() {
        if let Some(hint) = soup_hint(mesh, path) {
            ui.warn(&hint);
        }
    }
    warn_dropped(path, s.dropped_vertices.len(), ui);
    Ok((s, t.elapsed().as_secs_f64()))
}

fn warn_dropped(path: &Path, dropped: usize, ui: Ui) {
    if dropped > 0 {
        ui.warn(&format!(
            "{}: {} unused vertices dropped",
            path.display(),
            dropped
        ));
    }
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
