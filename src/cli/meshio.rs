//! Reading, validating and writing meshes with CLI-style error messages.

use std::path::{Path, PathBuf};
use std::time::Instant;

use contractible::io::{self, Location, ReadError, ReadErrorKind, WriteError};
use contractible::{BuildError, ConedSurfaces, Mesh, Surfaces, TriMesh};

use super::progress::{byte_spinner, bytes_bar, spinner};
use super::signals;
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

/// Reads a triangle mesh: the file's bytes with a bar showing the bytes read and the
/// percentage, then the parsing with a spinner; returns it and the seconds taken. Same
/// result and errors as [`io::read_tri_mesh`].
pub fn read(path: &Path, ui: Ui) -> Result<(TriMesh, f64), CliError> {
    let t = Instant::now();
    let r = read_bytes(path, ui).and_then(|bytes| {
        let pb = spinner(
            ui,
            format!("parsing {} ({} bytes)", path.display(), bytes.len()),
        );
        let (format, gz) = io::Format::from_path(path);
        let r = if gz && !bytes.starts_with(&[0x1f, 0x8b]) {
            Err(ReadError::new(
                ReadErrorKind::Decompress(
                    "file name ends in .gz but the content is not gzip".into(),
                ),
                Location::ByteOffset(0),
            ))
        } else {
            io::read_tri_mesh_bytes(&bytes, format)
        };
        pb.finish_and_clear();
        r
    });
    let mesh = r
        .map_err(|e| e.with_path(path))
        .map_err(|e| CliError::Input(read_error_message(path, &e)))?;
    Ok((mesh, t.elapsed().as_secs_f64()))
}

/// The bytes of `path`, read with a bar over the file's size.
fn read_bytes(path: &Path, ui: Ui) -> Result<Vec<u8>, ReadError> {
    use std::io::Read;
    let io_error = |e| ReadError::new(ReadErrorKind::Io(e), Location::Unknown);
    let file = std::fs::File::open(path).map_err(io_error)?;
    let len = file.metadata().map_err(io_error)?.len();
    let pb = bytes_bar(ui, len, format!("reading {}", path.display()));
    // The size is a hint for the allocation only: the file may change while read.
    let mut bytes = Vec::with_capacity(usize::try_from(len).unwrap_or(0));
    let r = pb.wrap_read(file).read_to_end(&mut bytes);
    pb.finish_and_clear();
    r.map_err(io_error)?;
    Ok(bytes)
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

/// Why an output cannot be written, found before any work (exit code 2).
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error("{path}: the directory {dir} does not exist")]
    MissingDirectory { path: String, dir: String },
    #[error("{path}: {dir} is not a directory")]
    NotADirectory { path: String, dir: String },
    #[error("{path}: is a directory")]
    IsADirectory { path: String },
    #[error("{path}: cannot create a file in {dir}: {source}")]
    NotWritable {
        path: String,
        dir: String,
        source: std::io::Error,
    },
    #[error("{path}: {source}")]
    UnknownFormat { path: String, source: WriteError },
    #[error("{path}: this is the input file; write the output to another file")]
    SameAsInput { path: String },
    #[error("-: writing to stdout needs --output-format (off, obj, ply or stl)")]
    StdoutNeedsFormat,
    #[error("{path}: --output-format {given} disagrees with the file name, which says {named}")]
    FormatMismatch {
        path: String,
        given: &'static str,
        named: &'static str,
    },
}

impl From<OutputError> for CliError {
    fn from(e: OutputError) -> Self {
        CliError::Input(e.to_string())
    }
}

/// The name of a format as `--output-format` spells it.
pub fn format_name(f: io::Format) -> &'static str {
    match f {
        io::Format::Off => "off",
        io::Format::Obj => "obj",
        io::Format::Ply => "ply",
        io::Format::Stl => "stl",
    }
}

/// Where a mesh goes, checked by [`check_output`]: a file (format by extension, `.gz`
/// compresses) or stdout (`-`, format from `--output-format`).
#[derive(Clone, Debug)]
pub struct Output {
    /// `None`: stdout.
    pub path: Option<PathBuf>,
    pub format: io::Format,
    pub gz: bool,
}

impl Output {
    /// How the output is named in messages and JSON (`-` for stdout).
    pub fn display(&self) -> String {
        match &self.path {
            Some(p) => p.display().to_string(),
            None => "-".to_string(),
        }
    }
}

/// Checks an output before any long work: `-` needs `format` (and then means stdout,
/// where the human or JSON report gives way to the mesh and goes to stderr); a file
/// needs a known extension (agreeing with `format` when given), a parent directory that
/// exists and in which a file can be created (tried with the temporary file the write
/// will use, removed at once), and must not be one of `inputs`.
pub fn check_output(
    out: &Path,
    format: Option<io::Format>,
    inputs: &[&Path],
) -> Result<Output, CliError> {
    let path = out.display().to_string();
    if out.as_os_str() == "-" {
        let format = format.ok_or(OutputError::StdoutNeedsFormat)?;
        super::report_to_stderr();
        return Ok(Output {
            path: None,
            format,
            gz: false,
        });
    }
    if out.is_dir() {
        return Err(OutputError::IsADirectory { path }.into());
    }
    let (named, gz) = io::Format::from_path(out);
    let named = named.ok_or_else(|| OutputError::UnknownFormat {
        path: path.clone(),
        source: WriteError::UnknownFormat(out.to_path_buf()),
    })?;
    if let Some(given) = format {
        if given != named {
            return Err(OutputError::FormatMismatch {
                path,
                given: format_name(given),
                named: format_name(named),
            }
            .into());
        }
    }
    check_side_file(out, inputs)?;
    Ok(Output {
        path: Some(out.to_path_buf()),
        format: named,
        gz,
    })
}

/// The checks of [`check_output`] that do not depend on the format, for any file the
/// command will write (`quad --pairs` too): not a directory, in an existing directory
/// where a file can be created, not one of `inputs`.
pub fn check_side_file(out: &Path, inputs: &[&Path]) -> Result<(), CliError> {
    let path = out.display().to_string();
    if out.is_dir() {
        return Err(OutputError::IsADirectory { path }.into());
    }
    let dir = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let dir_name = dir.display().to_string();
    match std::fs::metadata(&dir) {
        Err(_) => {
            return Err(OutputError::MissingDirectory {
                path,
                dir: dir_name,
            }
            .into())
        }
        Ok(m) if !m.is_dir() => {
            return Err(OutputError::NotADirectory {
                path,
                dir: dir_name,
            }
            .into())
        }
        Ok(_) => {}
    }
    if out.exists() {
        if let Ok(o) = out.canonicalize() {
            for input in inputs {
                if input.canonicalize().is_ok_and(|i| i == o) {
                    return Err(OutputError::SameAsInput { path }.into());
                }
            }
        }
    }
    // Writability: permissions, read-only file systems and the like are only known by
    // trying.
    let tmp = signals::TempFile::register(&temp_path(out));
    std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(tmp.path())
        .map_err(|source| OutputError::NotWritable {
            path,
            dir: dir_name,
            source,
        })?;
    drop(tmp);
    Ok(())
}

/// Writes a text file through `fill` the way [`write`] writes a mesh file: into a
/// temporary file (removed on failure or on SIGINT/SIGTERM) renamed into place.
pub fn write_side_file(
    path: &Path,
    fill: impl FnOnce(&mut dyn std::io::Write) -> std::io::Result<()>,
) -> Result<(), CliError> {
    use std::io::Write;
    let tmp = signals::TempFile::register(&temp_path(path));
    let r = (|| -> std::io::Result<()> {
        let mut w = std::io::BufWriter::new(std::fs::File::create(tmp.path())?);
        fill(&mut w)?;
        w.flush()
    })();
    r.and_then(|()| tmp.persist(path))
        .map_err(|e| CliError::Failure(format!("{}: {e}", path.display())))
}

/// Writes `mesh` to `out` (checked by [`check_output`]), with a spinner counting the
/// bytes written. A file goes through a temporary file renamed into place, so that a
/// failed or interrupted write (SIGINT, SIGTERM) leaves nothing behind; stdout gets the
/// mesh directly (a reader that went away ends the process as SIGPIPE does). Returns
/// the seconds taken.
pub fn write<const N: usize>(out: &Output, mesh: &Mesh<N>, ui: Ui) -> Result<f64, CliError> {
    use std::io::Write;
    let t = Instant::now();
    let pb = byte_spinner(ui, format!("writing {}", out.display()));
    let Some(path) = &out.path else {
        let stdout = std::io::stdout().lock();
        let r = io::write_mesh_to(pb.wrap_write(stdout), mesh, out.format, true);
        pb.finish_and_clear();
        return match r {
            Ok(()) => Ok(t.elapsed().as_secs_f64()),
            Err(WriteError::Io(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                signals::die_of_broken_pipe()
            }
            Err(e) => Err(CliError::Failure(format!("-: cannot write to stdout: {e}"))),
        };
    };
    let tmp = signals::TempFile::register(&temp_path(path));
    let r = (|| -> Result<(), WriteError> {
        io::check_mesh(mesh)?;
        let file = std::fs::File::create(tmp.path())?;
        let file = pb.wrap_write(file);
        if out.gz {
            let mut enc = flate2::write::GzEncoder::new(file, flate2::Compression::default());
            io::write_mesh_to(&mut enc, mesh, out.format, true)?;
            enc.finish()?.flush()?;
        } else {
            io::write_mesh_to(file, mesh, out.format, true)?;
        }
        Ok(())
    })();
    pb.finish_and_clear();
    r.map_err(|e| CliError::Failure(format!("{}: {e}", path.display())))?;
    // Dropping `tmp` on an error above removed the temporary file.
    tmp.persist(path)
        .map_err(|e| CliError::Failure(format!("{}: {e}", path.display())))?;
    Ok(t.elapsed().as_secs_f64())
}
