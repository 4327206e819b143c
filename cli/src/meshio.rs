//! Reading, validating and writing meshes with CLI-style error messages.

use std::path::{Path, PathBuf};
use std::time::Instant;

// `temp_path`: the temporary file the library's writer uses beside an output, registered
// here so that SIGINT and SIGTERM remove it too.
use contractible::io::{self, temp_path, Location, PolyMesh, ReadError, ReadErrorKind, WriteError};
use contractible::{BuildError, ConedSurfaces, Mesh, Surfaces, TriMesh};

use super::args::InputOpts;
use super::progress::{byte_spinner, bytes_bar, spinner};
use super::signals;
use super::{CliError, Ui};

/// How messages name the faces and vertices of an input: as its file does (from 1 in
/// OBJ, from 0 elsewhere), with the file line of each face when the format is text,
/// through triangulation (a triangle is named by its polygon) and welding (a merged
/// vertex by its lowest-numbered original).
#[derive(Clone, Debug, Default)]
pub struct Names {
    /// The input as shown in messages (`<stdin>` for `-`).
    pub shown: String,
    one_based: bool,
    lines: Option<Vec<u32>>,
    face_origin: Option<Vec<u32>>,
    vertex_origin: Option<Vec<u32>>,
    /// With `--weld`: per vertex of the file, the mesh vertex it was merged into.
    vertex_new_id: Option<Vec<u32>>,
}

impl Names {
    /// Names for `path`, before anything is known about its content.
    pub fn of_path(path: &Path) -> Self {
        Names {
            shown: shown(path),
            ..Names::default()
        }
    }

    /// The face of the file that face `f` of the mesh comes from (0-based).
    fn file_face(&self, f: usize) -> usize {
        match &self.face_origin {
            Some(o) => o.get(f).map_or(f, |&p| p as usize),
            None => f,
        }
    }

    /// The face number as the file counts, and its line when known.
    pub fn face_number(&self, f: usize) -> (usize, Option<usize>) {
        let p = self.file_face(f);
        let line = self
            .lines
            .as_ref()
            .and_then(|l| l.get(p))
            .map(|&n| n as usize);
        (p + usize::from(self.one_based), line)
    }

    /// `face N (line L)`.
    pub fn face(&self, f: usize) -> String {
        match self.face_number(f) {
            (n, Some(l)) => format!("face {n} (line {l})"),
            (n, None) => format!("face {n}"),
        }
    }

    /// The vertex number as the file counts.
    pub fn vertex_number(&self, v: u32) -> u64 {
        let v = match &self.vertex_origin {
            Some(o) => o.get(v as usize).copied().unwrap_or(v),
            None => v,
        };
        u64::from(v) + u64::from(self.one_based)
    }

    /// `[a, b]` with file vertex numbers.
    pub fn edge(&self, a: u32, b: u32) -> String {
        format!("[{}, {}]", self.vertex_number(a), self.vertex_number(b))
    }

    /// Whether vertices and faces are counted from 1 (OBJ).
    pub fn one_based(&self) -> bool {
        self.one_based
    }

    /// The number of vertices in the file (before `--weld`), for a mesh of
    /// `mesh_vertices` read from it.
    pub fn file_vertex_count(&self, mesh_vertices: usize) -> usize {
        self.vertex_new_id.as_ref().map_or(mesh_vertices, Vec::len)
    }

    /// The mesh vertex that the file's vertex `v` (0-based, in every format) became
    /// (with `--weld`, its group's vertex); `None` when the file has no such vertex.
    pub fn mesh_vertex(&self, v: u32, mesh_vertices: usize) -> Option<u32> {
        match &self.vertex_new_id {
            Some(new_id) => new_id.get(v as usize).copied(),
            None => ((v as usize) < mesh_vertices).then_some(v),
        }
    }

    /// The file's vertex (0-based, in every format) that mesh vertex `v` is (with
    /// `--weld`, its group's lowest-numbered vertex).
    pub fn file_vertex(&self, v: u32) -> u32 {
        match &self.vertex_origin {
            Some(o) => o.get(v as usize).copied().unwrap_or(v),
            None => v,
        }
    }

    /// The file's face (0-based, in every format) that mesh face `f` comes from (with
    /// `--triangulate`, the polygon it was cut from).
    pub fn file_face_index(&self, f: usize) -> usize {
        self.file_face(f)
    }
}

/// How the input is shown in messages: `<stdin>` for `-`.
pub fn shown(path: &Path) -> String {
    if is_stdin(path) {
        "<stdin>".into()
    } else {
        path.display().to_string()
    }
}

fn is_stdin(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// `FILE: LOCATION: MESSAGE` (location left out when unknown).
pub fn read_error_message(path: &Path, e: &ReadError) -> String {
    let shown = shown(path);
    let hint = match e.kind {
        ReadErrorKind::NonTriangleFace { corners, .. } if corners > 3 => {
            " (use --triangulate to split polygons into triangles; `info` describes polygon meshes as they are)"
        }
        ReadErrorKind::UnknownFormat if is_stdin(path) => " (use --format to name it)",
        _ => "",
    };
    match e.location {
        Location::Unknown => format!("{shown}: {}{hint}", e.kind),
        loc => format!("{shown}: {loc}: {}{hint}", e.kind),
    }
}

/// `FILE: MESSAGE` for a mesh that is not a union of closed surfaces (or, for `info`,
/// of surfaces with boundary), with faces and vertices named as the file does.
pub fn build_error_message(names: &Names, e: &BuildError) -> String {
    format!("{}: {}", names.shown, describe_build_error(names, e))
}

/// A validation error in words, faces and vertices named as the file does.
fn describe_build_error(names: &Names, e: &BuildError) -> String {
    let v = |x: u32| names.vertex_number(x);
    let f = |x: usize| names.face(x);
    let m = match e {
        BuildError::VertexOutOfRange {
            face,
            vertex,
            vertex_count,
        } => format!(
            "{}: vertex index {} out of range (vertex count {vertex_count})",
            f(*face),
            u64::from(*vertex) + u64::from(names.one_based)
        ),
        BuildError::DegenerateFace { face, vertices } => format!(
            "{} is degenerate: vertices [{}, {}, {}]",
            f(*face),
            v(vertices[0]),
            v(vertices[1]),
            v(vertices[2])
        ),
        BuildError::DuplicateFace {
            face,
            first,
            vertices,
        } => format!(
            "{} duplicates {} (vertices [{}, {}, {}])",
            f(*face),
            f(*first),
            v(vertices[0]),
            v(vertices[1]),
            v(vertices[2])
        ),
        BuildError::BoundaryEdge { a, b, face } => format!(
            "edge {} is a boundary edge: it lies only in {}",
            names.edge(*a, *b),
            f(*face)
        ),
        // One wording for both (an odd and an even number of faces at an edge), the
        // one `info` uses for every such edge.
        BuildError::NonManifoldEdge { a, b, faces, face }
        | BuildError::MultipleEdges {
            a, b, faces, face, ..
        } => format!(
            "edge {} is non-manifold, shared by {faces} faces (first: {})",
            names.edge(*a, *b),
            f(*face)
        ),
        BuildError::VertexLinkNotCycle {
            vertex,
            cycles,
            faces,
        } => format!(
            "vertex {}: its link is not one cycle but {cycles} cycles (faces around it: {faces})",
            v(*vertex)
        ),
        BuildError::PinchedBoundaryVertex {
            vertex,
            boundary_edges,
        } => format!(
            "vertex {} is pinched: {boundary_edges} boundary edges meet there (a manifold boundary vertex has 2)",
            v(*vertex)
        ),
        BuildError::VertexDegreeTooLow { vertex, degree } => format!(
            "vertex {} has degree {degree} (at least 3 required)",
            v(*vertex)
        ),
        e => e.to_string(),
    };
    m
}

/// The command line's message for an error of a library task call on `mesh` (read from
/// the input `names` describes; `command` is the subcommand): faces and vertices named
/// as the file does, the pointer to `info`, the soup hint where it applies; input
/// errors are exit code 2, the rest 1.
pub fn task_error(
    mesh: &TriMesh,
    names: &Names,
    command: &str,
    e: contractible::Error,
) -> CliError {
    use contractible::Error;
    match e {
        Error::Mesh(b) => invalid(
            mesh,
            names,
            format!("{}{SEE_INFO}", build_error_message(names, &b)),
        ),
        Error::NotClosed {
            a,
            b,
            face,
            boundary_loops,
            ..
        } => {
            let why = match boundary_loops {
                Some(n) => {
                    let loops = if n == 1 { "loop" } else { "loops" };
                    format!("this mesh has {n} boundary {loops}; `info` describes it")
                }
                None => match Surfaces::from_mesh_with_boundary(mesh) {
                    Err(e) => format!(
                        "nor is it a surface with boundary: {}{SEE_INFO}",
                        describe_build_error(names, &e)
                    ),
                    Ok(_) => "`info` describes it".to_string(),
                },
            };
            invalid(
                mesh,
                names,
                format!(
                    "{}: edge {} is a boundary edge, only in {}: `{command}` needs closed surfaces ({why})",
                    names.shown,
                    names.edge(a, b),
                    names.face(face)
                ),
            )
        }
        Error::NonFiniteCoordinate { vertex, axis, value } => CliError::Input(format!(
            "{}: vertex {} has a non-finite coordinate {axis} = {value}",
            names.shown,
            names.vertex_number(vertex as u32)
        )),
        Error::NoCoordinates { vertices, point } => CliError::Input(format!(
            "{}: all {vertices} vertices are at the same point ({}, {}, {}): the file carries \
             no coordinates (as `gen random` writes its surfaces); `{command}` needs vertex \
             positions",
            names.shown, point[0], point[1], point[2]
        )),
        Error::TooLarge {
            algorithm: contractible::quad::Algorithm::DsNaive,
            faces,
            limit,
            ..
        } => CliError::Input(format!(
            "{}: --algo ds-naive is quadratic and refuses components above {limit} faces (this one has {faces}); use --algo ds or --algo frink-lct",
            names.shown
        )),
        e if e.is_input() => CliError::Input(format!("{}: {e}", names.shown)),
        e => CliError::Failure(format!("{}: {e}; nothing written", names.shown)),
    }
}

/// What other commands add to a validation error: where to see every problem.
const SEE_INFO: &str = "; `contractible info` lists every problem";

/// An input read as its file has it (polygons kept), welded when asked.
pub struct Loaded {
    /// The faces, welded when asked.
    pub poly: PolyMesh,
    /// How messages name its faces and vertices.
    pub names: Names,
    /// Vertices merged by `--weld` (`Some` exactly when `--weld`).
    pub welded: Option<usize>,
}

/// Reads the input (a file, with a bar over its bytes, or standard input for `-`): the content
/// decides the format when it can, else `--format`, else the extension; a disagreement
/// and skipped OBJ statements are warned about. Then `--weld` if asked, with its count on
/// stderr (unless quiet).
pub fn load(path: &Path, opts: &InputOpts, ui: Ui) -> Result<Loaded, CliError> {
    let declared = opts.format.map(io::Format::from);
    let r = if is_stdin(path) {
        let pb = spinner(ui, format!("reading {}", shown(path)));
        let r = io::decode_reader(std::io::stdin().lock(), declared);
        pb.finish_and_clear();
        r
    } else {
        // Streamed: the bar follows the file bytes read while parsing (the size is a hint
        // for the bar only: the file may change while read).
        let len = std::fs::metadata(path).map(|m| m.len()).unwrap_or(0);
        let pb = bytes_bar(ui, len, format!("reading {}", path.display()));
        let r = io::read_poly_mesh_observed(path, declared, &mut |n| pb.set_position(n));
        pb.finish_and_clear();
        r
    };
    let decoded = r.map_err(|e| CliError::Input(read_error_message(path, &e)))?;
    let mut names = Names::of_path(path);
    if let Some(d) = decoded.disagreement() {
        let by = if opts.format.is_some() {
            "--format"
        } else {
            "the file name"
        };
        ui.warn(&format!(
            "{}: the content is {}, not {d} as {by} says: reading it as {}",
            names.shown, decoded.format, decoded.format
        ));
    }
    let poly = decoded.mesh;
    let skipped = poly.skipped_statements();
    if skipped.total() > 0 {
        let mut kinds: Vec<String> = skipped
            .kinds
            .iter()
            .map(|(k, n, line)| format!("`{k}` ×{n} (first at line {line})"))
            .collect();
        if skipped.others > 0 {
            kinds.push(format!("{} others", skipped.others));
        }
        ui.warn(&format!(
            "{}: skipped {} OBJ statements this tool does not use: {}",
            names.shown,
            skipped.total(),
            kinds.join(", ")
        ));
    }
    names.one_based = poly.one_based();
    names.lines = poly.lines().map(<[u32]>::to_vec);
    let Some(eps) = opts.weld else {
        return Ok(Loaded {
            poly,
            names,
            welded: None,
        });
    };
    let Some(positions) = &poly.positions else {
        return Err(CliError::Input(format!(
            "{}: --weld needs vertex positions, and this mesh has none",
            names.shown
        )));
    };
    let map = contractible::mesh::weld_map(positions, eps).ok_or_else(|| {
        CliError::Input(format!("{}: cannot weld: too many vertices", names.shown))
    })?;
    let welded = poly.welded_by(&map).ok_or_else(|| {
        CliError::Failure(format!("{}: inconsistent mesh after reading", names.shown))
    })?;
    let repeats = |f: &[u32]| {
        let mut g = f.to_vec();
        g.sort_unstable();
        g.windows(2).any(|w| w[0] == w[1])
    };
    let degenerate_by_weld = poly
        .faces()
        .zip(welded.faces())
        .filter(|(a, b)| !repeats(a) && repeats(b))
        .count();
    let merged = poly.vertex_count - welded.vertex_count;
    if !ui.quiet {
        let how = if eps == 0.0 {
            "--weld merged {merged} vertices at identical positions"
                .replace("{merged}", &merged.to_string())
        } else {
            format!("--weld={eps} merged {merged} vertices within {eps} of another")
        };
        let broken = match degenerate_by_weld {
            0 => String::new(),
            n => format!("; {n} faces became degenerate (their corners merged)"),
        };
        eprintln!(
            "{}: {how} ({} -> {} vertices){broken}",
            names.shown, poly.vertex_count, welded.vertex_count
        );
    }
    names.vertex_origin = Some(map.kept);
    names.vertex_new_id = Some(map.new_id);
    Ok(Loaded {
        poly: welded,
        names,
        welded: Some(merged),
    })
}

/// The loaded faces as triangles: cut when `--triangulate` (the count of polygons cut on
/// stderr unless quiet), else refused at the first polygon with a hint.
pub fn triangles(
    l: Loaded,
    opts: &InputOpts,
    path: &Path,
    ui: Ui,
) -> Result<(TriMesh, Names), CliError> {
    let mut names = l.names;
    if opts.triangulate {
        let t = l.poly.triangulated();
        if t.polygons > 0 && !ui.quiet {
            eprintln!(
                "{}: --triangulate split {} polygons into triangles ({} -> {} faces)",
                names.shown,
                t.polygons,
                l.poly.face_count(),
                t.mesh.faces.len()
            );
        }
        names.face_origin = Some(t.origin);
        return Ok((t.mesh, names));
    }
    let mesh = l
        .poly
        .into_tri_mesh()
        .map_err(|e| CliError::Input(read_error_message(path, &e)))?;
    Ok((mesh, names))
}

/// Reads an input triangle mesh ([`load`], then [`triangles`]). Returns the mesh, the
/// seconds taken (welding included), the number of vertices merged (`Some` exactly when
/// `--weld`) and the names for messages.
pub fn read_input(
    path: &Path,
    opts: &InputOpts,
    ui: Ui,
) -> Result<(TriMesh, f64, Option<usize>, Names), CliError> {
    let t = Instant::now();
    let l = load(path, opts, ui)?;
    let welded = l.welded;
    let (mesh, names) = triangles(l, opts, path, ui)?;
    Ok((mesh, t.elapsed().as_secs_f64(), welded, names))
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
pub fn soup_hint(mesh: &TriMesh, names: &Names) -> Option<String> {
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
        names.shown, mesh.vertex_count
    ))
}

/// An invalid-input error for `mesh` with `message`, followed by the soup hint when the
/// mesh looks like an unwelded soup.
fn invalid(mesh: &TriMesh, names: &Names, message: String) -> CliError {
    match soup_hint(mesh, names) {
        Some(hint) => CliError::Input(format!("{message}\n{hint}")),
        None => CliError::Input(message),
    }
}

/// Validates and splits a mesh into closed surfaces (with a spinner); returns them and
/// the seconds taken. `path` names the source in messages.
pub fn build(mesh: &TriMesh, names: &Names, ui: Ui) -> Result<(Surfaces, f64), CliError> {
    let t = Instant::now();
    let pb = spinner(ui, format!("checking {} faces", mesh.faces.len()));
    let r = Surfaces::from_mesh(mesh);
    pb.finish_and_clear();
    let s =
        r.map_err(|e| CliError::Input(format!("{}{SEE_INFO}", build_error_message(names, &e))))?;
    warn_dropped(names, s.dropped_vertices.len(), ui);
    Ok((s, t.elapsed().as_secs_f64()))
}

/// Validates and splits a mesh into compact surfaces that may have boundary, each
/// closed by coning (with a spinner); returns them and the seconds taken. A valid mesh
/// with boundary that looks like an unwelded soup (every triangle its own disc, say) gets
/// the soup hint as a warning; an invalid one gets it in the error.
pub fn build_open(mesh: &TriMesh, names: &Names, ui: Ui) -> Result<(ConedSurfaces, f64), CliError> {
    let t = Instant::now();
    let s = try_build_open(mesh, ui).map_err(|e| {
        invalid(
            mesh,
            names,
            format!("{}{SEE_INFO}", build_error_message(names, &e)),
        )
    })?;
    warn_soup_and_dropped(mesh, &s, names, ui);
    Ok((s, t.elapsed().as_secs_f64()))
}

/// [`Surfaces::from_mesh_with_boundary`] with a spinner.
pub fn try_build_open(mesh: &TriMesh, ui: Ui) -> Result<ConedSurfaces, BuildError> {
    let pb = spinner(ui, format!("checking {} faces", mesh.faces.len()));
    let r = Surfaces::from_mesh_with_boundary(mesh);
    pb.finish_and_clear();
    r
}

/// After a successful [`try_build_open`]: the soup hint for an open mesh and the count
/// of unused vertices, as warnings.
pub fn warn_soup_and_dropped(mesh: &TriMesh, s: &ConedSurfaces, names: &Names, ui: Ui) {
    // A valid mesh of closed surfaces is no soup (a soup's triangles are open discs),
    // and skipping it spares the position hashing on every large closed input.
    if !ui.quiet && !s.is_closed() {
        if let Some(hint) = soup_hint(mesh, names) {
            ui.warn(&hint);
        }
    }
    warn_dropped(names, s.dropped_vertices.len(), ui);
}

pub fn warn_dropped(names: &Names, dropped: usize, ui: Ui) {
    if dropped > 0 {
        ui.warn(&format!(
            "{}: {dropped} unused vertices dropped",
            names.shown
        ));
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

/// Checks where a file of index pairs will go (`quad --pairs`, `reduce --history`,
/// named `flag`): `-` is stdout, which the main output must then not take
/// (`output_on_stdout`), and the report moves to stderr; a path must be writable and no
/// input.
pub fn check_index_pairs_output(
    path: &Path,
    flag: &str,
    output_on_stdout: bool,
    inputs: &[&Path],
) -> Result<(), CliError> {
    if path.as_os_str() != "-" {
        return check_side_file(path, inputs);
    }
    if output_on_stdout {
        return Err(CliError::Input(format!(
            "-o - and {flag} - would both write to stdout: send one to a file"
        )));
    }
    super::report_to_stderr();
    Ok(())
}

/// Writes a file of index pairs, one `A B` line each (`quad --pairs`, `reduce
/// --history`), atomically (temporary file renamed into place), or to stdout for `-`.
pub fn write_index_pairs(path: &Path, lines: &[[u32; 2]]) -> Result<(), CliError> {
    if path.as_os_str() == "-" {
        use std::io::Write;
        let mut w = std::io::BufWriter::new(std::io::stdout().lock());
        let r = lines
            .iter()
            .try_for_each(|[f, g]| writeln!(w, "{f} {g}"))
            .and_then(|()| w.flush());
        return match r {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => signals::die_of_broken_pipe(),
            Err(e) => Err(CliError::Failure(format!("-: cannot write to stdout: {e}"))),
        };
    }
    write_side_file(path, |w| {
        for [f, g] in lines {
            writeln!(w, "{f} {g}")?;
        }
        Ok(())
    })
}
