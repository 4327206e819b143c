//! The native half of the `contractible` Python package: NumPy arrays in, NumPy arrays
//! and plain dicts out, over the library's task calls ([`contractible::describe`],
//! [`contractible::reduce`], [`contractible::quadrangulate`],
//! [`contractible::simplify`], [`contractible::decimate`]) and its file I/O. The validation, the per-component work,
//! the independent check of every output, the reassembly and the statistics are the
//! library's; this layer copies arrays in and out and maps errors to exceptions.
//!
//! # Guarantees
//! - Every function validates its arrays before any work: shapes and dtypes raise
//!   `ValueError`; a face naming a vertex out of range (negative included), a NaN or
//!   infinite coordinate, and every problem the library finds in a mesh or a file
//!   (non-manifold edge, boundary where a closed surface is required, a component too
//!   large for the algorithm, a file's bad line...) raise `contractible.MeshError` with
//!   `kind` (the library's `Error::kind`) and `location` (face, vertex, edge, component,
//!   line). A wrong option (unknown algorithm name, ε not > 0, a fraction kept outside
//!   `[0, 1]`, no positions for `simplify` or `decimate`) raises `ValueError`; a file
//!   that cannot be opened or written raises `OSError` (with its errno:
//!   `FileNotFoundError`...). An output that fails the
//!   library's independent check raises `RuntimeError` (a defect of the library; it is
//!   never returned). Nothing input-derived can panic or crash the interpreter.
//! - The GIL is released while the library works (validation, the algorithm, the
//!   check, file I/O), so threads run concurrently; the arrays are copied into Rust first.
//! - Results are the library's task calls' results: checked independently before they
//!   are returned, deterministic for a given input and seed, and equal to the command
//!   line's for the same mesh (the same per-component order, by smallest face index; the
//!   same vertex renumbering of outputs, survivors in input order; the statistics with
//!   the keys of its `--json` output, timings of reading and writing files aside).
//!
//! The public Python API (`python/contractible/__init__.py`) wraps these functions: it
//! passes int64, int32 and uint32 faces and float64 and float32 vertices as they are
//! (C-contiguous), converts other dtypes, accepts trimesh-like objects and builds the
//! result objects.

use std::path::{Path, PathBuf};

use contractible::core::MAX_VERTICES;
use contractible::io::{self, Location, ReadErrorKind, WriteError};
use contractible::task::{ComponentDescription, ReducedComponent};
use contractible::{
    decimate, irreducible, quad, simplify, BuildError, DecimateOptions, Description, Eps, Error,
    MaxError, Mesh, QuadOptions, ReduceOptions, SimplifyOptions, Triangulation,
};
use numpy::ndarray::{Array1, Array2};
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Raises `contractible.MeshError(message, kind, location)` (the class lives in
/// `contractible._errors`, so that it is a plain Python class users can catch and
/// subclass).
fn mesh_error(py: Python<'_>, kind: &str, message: String, location: &[(&str, i64)]) -> PyErr {
    let made = (|| -> PyResult<PyErr> {
        let class = py.import("contractible._errors")?.getattr("MeshError")?;
        let loc = PyDict::new(py);
        for (k, v) in location {
            loc.set_item(*k, *v)?;
        }
        let err = class.call1((message.clone(), kind, loc))?;
        Ok(PyErr::from_value(err))
    })();
    // Only a broken installation (no `contractible._errors`) lands here.
    made.unwrap_or_else(|e| e)
}

fn int(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

/// The location of an edge `[a, b]` found at `face`.
fn edge(face: usize, a: u32, b: u32) -> Vec<(&'static str, i64)> {
    vec![
        ("face", int(face)),
        ("a", i64::from(a)),
        ("b", i64::from(b)),
    ]
}

/// Where a validation error is, from its fields.
fn build_location(e: &BuildError) -> Vec<(&'static str, i64)> {
    match e {
        BuildError::TooLarge { count, .. } => vec![("count", int(*count))],
        BuildError::VertexOutOfRange { face, vertex, .. } => {
            vec![("face", int(*face)), ("vertex", i64::from(*vertex))]
        }
        BuildError::DegenerateFace { face, .. } => vec![("face", int(*face))],
        BuildError::DuplicateFace { face, first, .. } => {
            vec![("face", int(*face)), ("first", int(*first))]
        }
        BuildError::BoundaryEdge { a, b, face }
        | BuildError::NonManifoldEdge { a, b, face, .. }
        | BuildError::MultipleEdges { a, b, face, .. } => edge(*face, *a, *b),
        BuildError::VertexLinkNotCycle { vertex, .. }
        | BuildError::PinchedBoundaryVertex { vertex, .. }
        | BuildError::VertexDegreeTooLow { vertex, .. }
        | BuildError::UnusedVertex { vertex } => vec![("vertex", i64::from(*vertex))],
        _ => vec![],
    }
}

/// An `OSError` for a failed system call on `path`: with the errno when there is one,
/// so that Python picks the subclass (`FileNotFoundError`, `PermissionError`...).
fn os_error(err: &std::io::Error, path: Option<&Path>, message: String) -> PyErr {
    match (err.raw_os_error(), path) {
        (Some(code), Some(p)) => {
            let text = err.to_string();
            let suffix = format!(" (os error {code})");
            let text = text.strip_suffix(&suffix).unwrap_or(&text).to_string();
            PyOSError::new_err((code, text, p.display().to_string()))
        }
        _ => PyOSError::new_err(message),
    }
}

/// The one mapping of the library's errors to Python exceptions:
/// - `OSError` for a failed system call (reading or writing `file`);
/// - `ValueError` for a wrong option: an unknown name, an ε out of range, no positions
///   for a geometric task, a file name or mesh a file format cannot take;
/// - `RuntimeError` for what is not the input's fault (an output that failed its
///   check, a cancelled call);
/// - `contractible.MeshError` (a `ValueError`) for every problem of a mesh or of a
///   file's content, with `kind = e.kind()` and the location the error carries.
fn raise(py: Python<'_>, e: &Error, file: Option<&Path>) -> PyErr {
    let message = e.to_string();
    let location: Vec<(&str, i64)> = match e {
        Error::Read(r) => {
            if let ReadErrorKind::Io(err) = &r.kind {
                return os_error(err, r.path.as_deref().or(file), message);
            }
            match r.location {
                Location::Line(n) => vec![("line", int(n))],
                Location::ByteOffset(b) => {
                    vec![("byte_offset", i64::try_from(b).unwrap_or(i64::MAX))]
                }
                Location::Face(f) => vec![("face", int(f))],
                _ => vec![],
            }
        }
        Error::Write(w) => {
            let message = match file {
                Some(p) => format!("{}: {message}", p.display()),
                None => message,
            };
            return match w {
                WriteError::Io(err) => os_error(err, file, message),
                _ => PyValueError::new_err(message),
            };
        }
        Error::MissingPositions { .. } | Error::BadOption { .. } | Error::UnknownName(_) => {
            return PyValueError::new_err(message)
        }
        e if !e.is_input() => return PyRuntimeError::new_err(message),
        Error::Mesh(b) => build_location(b),
        Error::NotClosed { a, b, face, .. } => edge(*face, *a, *b),
        Error::NonFiniteCoordinate { vertex, .. } => vec![("vertex", int(*vertex))],
        Error::TooLarge { component, .. } => vec![("component", int(*component))],
        _ => vec![],
    };
    mesh_error(py, e.kind(), message, &location)
}

/// Face indices as the caller's array holds them (int64, int32 or uint32, C-contiguous
/// or not), read where they are: no converted copy is made before they are narrowed to
/// the library's `u32`.
#[derive(FromPyObject)]
enum Indices<'py> {
    I64(PyReadonlyArray2<'py, i64>),
    I32(PyReadonlyArray2<'py, i32>),
    U32(PyReadonlyArray2<'py, u32>),
}

impl Indices<'_> {
    fn shape(&self) -> [usize; 2] {
        let s = match self {
            Indices::I64(a) => a.shape(),
            Indices::I32(a) => a.shape(),
            Indices::U32(a) => a.shape(),
        };
        [s[0], s[1]]
    }
}

/// Vertex positions as the caller's array holds them (float64 or float32), read where
/// they are into the library's `f64` positions.
#[derive(FromPyObject)]
enum Coordinates<'py> {
    F64(PyReadonlyArray2<'py, f64>),
    F32(PyReadonlyArray2<'py, f32>),
}

/// The caller's `(n, 3)` positions, checked finite, copied out as `f64`.
fn positions(
    py: Python<'_>,
    vertices: Option<&Coordinates<'_>>,
) -> PyResult<Option<Vec<[f64; 3]>>> {
    match vertices {
        None => Ok(None),
        Some(Coordinates::F64(v)) => positions_of(py, v).map(Some),
        Some(Coordinates::F32(v)) => positions_of(py, v).map(Some),
    }
}

fn positions_of<T: numpy::Element + Copy + Into<f64>>(
    py: Python<'_>,
    v: &PyReadonlyArray2<'_, T>,
) -> PyResult<Vec<[f64; 3]>> {
    let s = v.shape();
    if s[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "vertices must have shape (n, 3), got ({}, {})",
            s[0], s[1]
        )));
    }
    let mut out = Vec::with_capacity(s[0]);
    for (vertex, row) in v.as_array().outer_iter().enumerate() {
        let p: [f64; 3] = [row[0].into(), row[1].into(), row[2].into()];
        if let Some(k) = (0..3).find(|&k| !p[k].is_finite()) {
            let e = Error::NonFiniteCoordinate {
                vertex,
                axis: ['x', 'y', 'z'][k],
                value: p[k],
            };
            return Err(raise(py, &e, None));
        }
        out.push(p);
    }
    Ok(out)
}

/// The caller's indices as one flat slice when C-contiguous (the wrapper passes them so),
/// else copied row by row, given to `f`.
fn with_values<T: numpy::Element + Copy, R>(
    a: &PyReadonlyArray2<'_, T>,
    f: impl FnOnce(&[T]) -> R,
) -> R {
    let view = a.as_array();
    match view.as_slice() {
        Some(s) => f(s),
        None => f(&view.iter().copied().collect::<Vec<T>>()),
    }
}

/// One more than the largest index (0 for none; negative indices count as none).
fn implied_vertex_count<T: Copy + Into<i64>>(values: &[T]) -> usize {
    let max = values.iter().map(|&x| x.into()).max().unwrap_or(-1);
    usize::try_from(max.saturating_add(1)).unwrap_or(0)
}

/// The faces of `values` (rows of `N` indices), every index checked in `0..n`.
fn face_list<const N: usize, T: Copy + Into<i64>>(
    py: Python<'_>,
    values: &[T],
    n: usize,
) -> PyResult<Vec<[u32; N]>> {
    let mut list = Vec::with_capacity(values.len() / N);
    for (i, row) in values.chunks_exact(N).enumerate() {
        let mut f = [0u32; N];
        for (slot, &x) in f.iter_mut().zip(row) {
            let x: i64 = x.into();
            *slot = match u32::try_from(x) {
                Ok(x) if (x as usize) < n => x,
                // The index may not fit the library's type: located here.
                _ => {
                    return Err(mesh_error(
                        py,
                        "vertex_out_of_range",
                        format!("face {i}: vertex index {x} out of range (vertex count {n})"),
                        &[("face", int(i)), ("vertex", x)],
                    ))
                }
            };
        }
        list.push(f);
    }
    Ok(list)
}

/// A mesh of `N`-corner faces copied out of the caller's arrays, checked: `faces` is
/// `(m, N)`, `vertices` (when given) `(n, 3)` and finite, every index in `0..n`. Without
/// vertices, `n` is `vertex_count` or one more than the largest index.
fn mesh<const N: usize>(
    py: Python<'_>,
    vertices: Option<&Coordinates<'_>>,
    faces: &Indices<'_>,
    vertex_count: Option<usize>,
) -> PyResult<Mesh<N>> {
    let shape = faces.shape();
    if shape[1] != N {
        return Err(PyValueError::new_err(format!(
            "faces must have shape (m, {N}), got ({}, {})",
            shape[0], shape[1]
        )));
    }
    let positions = positions(py, vertices)?;
    let n = match (&positions, vertex_count) {
        (Some(p), _) => p.len(),
        (None, Some(n)) => n,
        (None, None) => match faces {
            Indices::I64(a) => with_values(a, implied_vertex_count),
            Indices::I32(a) => with_values(a, implied_vertex_count),
            Indices::U32(a) => with_values(a, implied_vertex_count),
        },
    };
    if n > MAX_VERTICES {
        let e = BuildError::TooLarge {
            what: "vertices",
            count: n,
            max: MAX_VERTICES,
        };
        return Err(raise(py, &Error::Mesh(e), None));
    }
    let list = match faces {
        Indices::I64(a) => with_values(a, |v| face_list::<N, i64>(py, v, n)),
        Indices::I32(a) => with_values(a, |v| face_list::<N, i32>(py, v, n)),
        Indices::U32(a) => with_values(a, |v| face_list::<N, u32>(py, v, n)),
    }?;
    Ok(Mesh {
        vertex_count: n,
        positions,
        faces: list,
    })
}

fn vertices_array<'py>(py: Python<'py>, p: &[[f64; 3]]) -> Bound<'py, PyArray2<f64>> {
    let flat: Vec<f64> = p.iter().flatten().copied().collect();
    Array2::from_shape_vec((p.len(), 3), flat)
        .unwrap_or_else(|_| Array2::zeros((0, 3)))
        .into_pyarray(py)
}

fn index_array<'py, const N: usize>(py: Python<'py>, f: &[[u32; N]]) -> Bound<'py, PyArray2<i64>> {
    let flat: Vec<i64> = f.iter().flatten().map(|&x| i64::from(x)).collect();
    Array2::from_shape_vec((f.len(), N), flat)
        .unwrap_or_else(|_| Array2::zeros((0, N)))
        .into_pyarray(py)
}

fn vector<'py>(py: Python<'py>, v: &[u32]) -> Bound<'py, PyArray1<i64>> {
    Array1::from_iter(v.iter().map(|&x| i64::from(x))).into_pyarray(py)
}

/// A library statistics struct as a dict with its serialised (command-line JSON) keys.
fn dict<'py, T: serde::Serialize>(py: Python<'py>, value: &T) -> PyResult<Bound<'py, PyDict>> {
    pythonize::pythonize(py, value)
        .map_err(|e| PyValueError::new_err(e.to_string()))?
        .cast_into::<PyDict>()
        .map_err(|e| PyValueError::new_err(e.to_string()))
}

/// A choice named by a string (`ValueError` listing the names when it is none).
fn choice<T>(py: Python<'_>, name: &str) -> PyResult<T>
where
    T: std::str::FromStr<Err = contractible::UnknownName>,
{
    name.parse()
        .map_err(|e| raise(py, &Error::UnknownName(e), None))
}

/// `read`'s result: positions (if the file has any), faces, vertex count.
type ReadResult<'py> = (
    Option<Bound<'py, PyArray2<f64>>>,
    Bound<'py, PyArray2<i64>>,
    usize,
);

/// Reads a mesh file (OFF, OBJ, PLY, STL, optionally gzipped; format by content, else
/// extension). Returns `(vertices or None, faces, vertex count)`.
#[pyfunction]
fn read(py: Python<'_>, path: PathBuf) -> PyResult<ReadResult<'_>> {
    let m = py
        .detach(|| io::read_tri_mesh(&path))
        .map_err(|e| raise(py, &Error::Read(e), Some(&path)))?;
    let v = m.positions.as_deref().map(|p| vertices_array(py, p));
    Ok((v, index_array(py, &m.faces), m.vertex_count))
}

/// Writes triangles (`(m, 3)`) or quads (`(m, 4)`) to `path` (format by extension;
/// `.gz` compresses), through a temporary file renamed into place.
#[pyfunction]
#[pyo3(signature = (path, vertices, faces, vertex_count=None))]
fn write(
    py: Python<'_>,
    path: PathBuf,
    vertices: Option<Coordinates<'_>>,
    faces: Indices<'_>,
    vertex_count: Option<usize>,
) -> PyResult<()> {
    let r = match faces.shape()[1] {
        3 => {
            let m = mesh::<3>(py, vertices.as_ref(), &faces, vertex_count)?;
            py.detach(|| io::write_mesh(&path, &m))
        }
        4 => {
            let m = mesh::<4>(py, vertices.as_ref(), &faces, vertex_count)?;
            py.detach(|| io::write_mesh(&path, &m))
        }
        c => {
            return Err(PyValueError::new_err(format!(
                "faces must have shape (m, 3) or (m, 4), got (m, {c})"
            )))
        }
    };
    r.map_err(|e| raise(py, &Error::Write(e), Some(&path)))
}

/// The topology of every component (surfaces with boundary allowed), as `info --json`
/// reports it.
#[pyfunction]
#[pyo3(signature = (vertices, faces, vertex_count=None))]
fn info<'py>(
    py: Python<'py>,
    vertices: Option<Coordinates<'py>>,
    faces: Indices<'py>,
    vertex_count: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let mesh = mesh::<3>(py, vertices.as_ref(), &faces, vertex_count)?;
    let described = py
        .detach(|| contractible::describe(&mesh))
        .map_err(|e| raise(py, &e, None))?;
    let (components, dropped) = match described {
        Description::Surfaces {
            components,
            dropped_vertices,
        } => (components, dropped_vertices),
        // `describe` lists every problem; the exception names the first one the
        // validation meets, located (the same as the other functions raise).
        Description::Problems { first, .. } => return Err(raise(py, &Error::Mesh(first), None)),
    };
    let list = PyList::empty(py);
    for c in &components {
        list.append(dict(py, c)?)?;
    }
    let sum = |f: fn(&ComponentDescription) -> usize| components.iter().map(f).sum::<usize>();
    let d = PyDict::new(py);
    d.set_item("vertices", sum(|c| c.vertices))?;
    d.set_item("edges", sum(|c| c.edges))?;
    d.set_item("faces", sum(|c| c.faces))?;
    d.set_item("components", components.len())?;
    d.set_item(
        "euler_characteristic",
        components
            .iter()
            .map(|c| c.surface.euler_characteristic())
            .sum::<i64>(),
    )?;
    d.set_item(
        "orientable",
        components.iter().all(|c| c.surface.is_orientable()),
    )?;
    let loops = sum(|c| c.surface.boundary_loops());
    if loops > 0 {
        d.set_item("boundary_loops", loops)?;
    }
    d.set_item("dropped_vertices", dropped)?;
    d.set_item("component_list", list)?;
    Ok(d)
}

/// The contraction history of a `reduce` call: replays vertex splits.
#[pyclass(module = "contractible._native", frozen)]
struct History {
    parts: Vec<ReducedComponent>,
}

#[pymethods]
impl History {
    /// Number of contractions over all components.
    fn __len__(&self) -> usize {
        self.parts.iter().map(|p| p.reduction.history.len()).sum()
    }

    /// `(k, 5)` int64: per contraction, oldest first (components in order), `component,
    /// u, v, x, y`: `v` was contracted into `u`, and `x`, `y` were the two vertices of
    /// the link of the edge `uv` (input vertex ids).
    fn records<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        let mut flat = Vec::new();
        for (c, p) in self.parts.iter().enumerate() {
            let o = &p.vertex_origin;
            for r in p.reduction.history.records() {
                let id = |v: contractible::VertexId| i64::from(o[v.index()]);
                flat.extend([int(c), id(r.u), id(r.v), id(r.link[0]), id(r.link[1])]);
            }
        }
        let k = flat.len() / 5;
        Array2::from_shape_vec((k, 5), flat)
            .unwrap_or_else(|_| Array2::zeros((0, 5)))
            .into_pyarray(py)
    }

    /// `(k, 2)` int64: the contractions as `u, v` (`v` contracted into `u`, input vertex
    /// ids), oldest first, components in order: the library's
    /// `ReduceResult::contractions`, what `reduce --history` writes and `check("reduce",
    /// ..., history=)` replays.
    fn contractions<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray2<i64>> {
        let mut flat = Vec::new();
        for p in &self.parts {
            let o = &p.vertex_origin;
            for r in p.reduction.history.records() {
                flat.extend([i64::from(o[r.u.index()]), i64::from(o[r.v.index()])]);
            }
        }
        let k = flat.len() / 2;
        Array2::from_shape_vec((k, 2), flat)
            .unwrap_or_else(|_| Array2::zeros((0, 2)))
            .into_pyarray(py)
    }

    /// The faces (input vertex ids, `(m, 3)`) after undoing the last `steps` contractions
    /// by vertex splits (all of them when `None`: the input's faces, in input order and
    /// orientation; 0: the reduced output's faces, in input face order).
    #[pyo3(signature = (steps=None))]
    fn expand<'py>(&self, py: Python<'py>, steps: Option<usize>) -> Bound<'py, PyArray2<i64>> {
        let mut left = steps.unwrap_or(usize::MAX);
        let mut tris: Vec<Triangulation> =
            self.parts.iter().map(|p| p.reduction.tri.clone()).collect();
        for (p, t) in self.parts.iter().zip(tris.iter_mut()).rev() {
            let mut h = p.reduction.history.clone();
            while left > 0 && h.undo(t).is_some() {
                left -= 1;
            }
        }
        let mut faces: Vec<(u32, [u32; 3])> = Vec::new();
        for (p, t) in self.parts.iter().zip(&tris) {
            for f in t.faces() {
                let vs = t.face_vertices(f).map(|v| p.vertex_origin[v.index()]);
                faces.push((p.face_origin[f.index()], vs));
            }
        }
        faces.sort_unstable_by_key(|&(o, _)| o);
        let list: Vec<[u32; 3]> = faces.into_iter().map(|(_, f)| f).collect();
        index_array(py, &list)
    }
}

/// The statistics of a task over components, in the order of the command line's JSON:
/// the seed and counts, the totals' keys, then `component_list`.
fn task_stats<'py, 'a, T: serde::Serialize + 'a>(
    py: Python<'py>,
    seed: u64,
    dropped_vertices: usize,
    totals: &T,
    components: impl ExactSizeIterator<Item = &'a T>,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("seed", seed)?;
    d.set_item("components", components.len())?;
    d.set_item("dropped_vertices", dropped_vertices)?;
    d.update(dict(py, totals)?.as_mapping())?;
    let list = PyList::empty(py);
    for c in components {
        list.append(dict(py, c)?)?;
    }
    d.set_item("component_list", list)?;
    Ok(d)
}

/// Irreducible triangulations of every component (closed surfaces only). Returns a dict:
/// `vertices` (survivors' positions or None), `faces` (over the survivors, renumbered
/// in input order), `vertex_map` (input id of each survivor), `stats` (the command
/// line's `reduce --json` totals and `component_list`), `history`.
#[pyfunction]
#[pyo3(signature = (vertices, faces, algo="rs", seed=0, vertex_count=None, count_retests=false, parallel=false))]
#[allow(clippy::too_many_arguments)]
fn reduce<'py>(
    py: Python<'py>,
    vertices: Option<Coordinates<'py>>,
    faces: Indices<'py>,
    algo: &str,
    seed: u64,
    vertex_count: Option<usize>,
    count_retests: bool,
    parallel: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let options = ReduceOptions {
        algorithm: choice::<irreducible::Algorithm>(py, algo)?,
        seed,
        count_retests,
        parallel,
        ..ReduceOptions::default()
    };
    let mesh = mesh::<3>(py, vertices.as_ref(), &faces, vertex_count)?;
    let r = py
        .detach(|| contractible::reduce(&mesh, &options))
        .map_err(|e| raise(py, &e, None))?;
    let stats = task_stats(
        py,
        seed,
        r.dropped_vertices,
        &r.totals,
        r.components.iter().map(|c| &c.stats),
    )?;
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        r.mesh.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("faces", index_array(py, &r.mesh.faces))?;
    d.set_item("vertex_map", vector(py, &r.vertex_map))?;
    d.set_item("stats", stats)?;
    d.set_item(
        "history",
        Py::new(
            py,
            History {
                parts: r.components,
            },
        )?,
    )?;
    Ok(d)
}

/// A perfect pairing of the triangles of every component (closed surfaces only). Returns
/// a dict: `quads` (`(m/2, 4)`, input vertex ids), `triangles` (the paired triangulation
/// K, `(m, 3)`, row `i` is input face `i` after LRS's flips), `pairs` (`(m/2, 2)` rows of
/// `triangles`), `vertices` (the input's, or None), `stats`.
#[pyfunction(name = "quad")]
#[pyo3(signature = (vertices, faces, algo="lrs", seed=0, vertex_count=None, parallel=false))]
fn quad_py<'py>(
    py: Python<'py>,
    vertices: Option<Coordinates<'py>>,
    faces: Indices<'py>,
    algo: &str,
    seed: u64,
    vertex_count: Option<usize>,
    parallel: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let options = QuadOptions {
        algorithm: choice::<quad::Algorithm>(py, algo)?,
        seed,
        parallel,
        ..QuadOptions::default()
    };
    let mesh = mesh::<3>(py, vertices.as_ref(), &faces, vertex_count)?;
    let q = py
        .detach(|| contractible::quadrangulate(&mesh, &options))
        .map_err(|e| raise(py, &e, None))?;
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        q.mesh.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("quads", index_array(py, &q.mesh.faces))?;
    d.set_item("triangles", index_array(py, &q.triangles))?;
    d.set_item("pairs", index_array(py, &q.pairs))?;
    let stats = task_stats(
        py,
        seed,
        q.dropped_vertices,
        &q.totals,
        q.components.iter().map(|c| &c.stats),
    )?;
    d.set_item("stats", stats)?;
    Ok(d)
}

/// Contracts every edge shorter than ε without changing the surface (closed or with
/// boundary). `eps` is absolute, or with `relative=True` a fraction of the bounding-box
/// diagonal of the vertices the faces use. Returns a dict: `vertices`, `faces`, `stats`.
#[pyfunction(name = "simplify")]
#[pyo3(signature = (vertices, faces, eps, relative=false, mode="nested", side="count", position="midpoint", guard=true, parallel=false))]
#[allow(clippy::too_many_arguments)]
fn simplify_py<'py>(
    py: Python<'py>,
    vertices: Option<Coordinates<'py>>,
    faces: Indices<'py>,
    eps: f64,
    relative: bool,
    mode: &str,
    side: &str,
    position: &str,
    guard: bool,
    parallel: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let options = SimplifyOptions {
        eps: if relative {
            Eps::Relative(eps)
        } else {
            Eps::Absolute(eps)
        },
        mode: choice::<simplify::Mode>(py, mode)?,
        side: choice::<simplify::Side>(py, side)?,
        position: choice::<simplify::Position>(py, position)?,
        allow_foldover: !guard,
        parallel,
        ..SimplifyOptions::default()
    };
    let mesh = mesh::<3>(py, vertices.as_ref(), &faces, None)?;
    let s = py
        .detach(|| contractible::simplify(&mesh, &options))
        .map_err(|e| raise(py, &e, None))?;
    let stats = PyDict::new(py);
    stats.set_item("eps", s.eps)?;
    stats.set_item("eps_rel", s.eps_rel)?;
    stats.set_item("bbox_diagonal", s.bbox_diagonal)?;
    stats.set_item("mode", options.mode.to_string())?;
    stats.set_item("side", options.side.to_string())?;
    stats.set_item("position", options.position.to_string())?;
    stats.set_item("guard", guard)?;
    stats.update(dict(py, &s.stats)?.as_mapping())?;
    stats.set_item("dropped_vertices", s.dropped_vertices)?;
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        s.mesh.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("faces", index_array(py, &s.mesh.faces))?;
    d.set_item("stats", stats)?;
    Ok(d)
}

/// Collapses edges, cheapest quadric error first, to a face target (`target_faces`, or
/// `keep` a fraction of the faces kept) or an error cap (`max_error`, absolute, or with
/// `relative=True` a fraction of the bounding-box diagonal), every collapse passing the
/// link condition, so that every component keeps its topology. `locked` (uint32 input
/// vertex ids) survive at their input positions. Returns a dict: `vertices`, `faces`,
/// `vertex_map` (per output vertex, the input vertex surviving as it), `collapse_map`
/// (per input vertex, the output vertex it went into; -1 for a vertex no face uses),
/// `face_origin` (per output face, the input face it descends from), `stats`.
#[pyfunction(name = "decimate")]
#[pyo3(signature = (vertices, faces, target_faces=None, keep=None, max_error=None, relative=false, placement="optimal", guard=true, lock_boundary=false, locked=None, schedule="exact"))]
#[allow(clippy::too_many_arguments)]
fn decimate_py<'py>(
    py: Python<'py>,
    vertices: Option<Coordinates<'py>>,
    faces: Indices<'py>,
    target_faces: Option<usize>,
    keep: Option<f64>,
    max_error: Option<f64>,
    relative: bool,
    placement: &str,
    guard: bool,
    lock_boundary: bool,
    locked: Option<PyReadonlyArray1<'py, u32>>,
    schedule: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let options = DecimateOptions {
        faces: target_faces,
        keep,
        max_error: max_error.map(|e| {
            if relative {
                MaxError::Relative(e)
            } else {
                MaxError::Absolute(e)
            }
        }),
        placement: choice::<decimate::Placement>(py, placement)?,
        schedule: choice::<decimate::Schedule>(py, schedule)?,
        allow_foldover: !guard,
        lock_boundary,
        locked: locked.map(|l| l.as_array().to_vec()).unwrap_or_default(),
        ..DecimateOptions::default()
    };
    let mesh = mesh::<3>(py, vertices.as_ref(), &faces, None)?;
    let r = py
        .detach(|| contractible::decimate(&mesh, &options))
        .map_err(|e| raise(py, &e, None))?;
    // The keys of the command line's `decimate --json`, but for its files and timings.
    let targets = PyDict::new(py);
    targets.set_item("faces", target_faces)?;
    targets.set_item("keep", keep)?;
    targets.set_item("max_error", if relative { None } else { max_error })?;
    targets.set_item("max_error_rel", if relative { max_error } else { None })?;
    let mut locked = options.locked.clone();
    locked.sort_unstable();
    locked.dedup();
    let stats = PyDict::new(py);
    stats.set_item("targets", targets)?;
    stats.set_item("bbox_diagonal", r.bbox_diagonal)?;
    stats.set_item("placement", options.placement.name())?;
    stats.set_item("schedule", options.schedule.name())?;
    stats.set_item("guard", guard)?;
    stats.set_item("lock_boundary", lock_boundary)?;
    stats.set_item("locked", locked)?;
    stats.update(dict(py, &r.stats)?.as_mapping())?;
    stats.set_item("verified", r.verified)?;
    stats.set_item("dropped_vertices", r.dropped_vertices)?;
    let collapse_map = Array1::from_iter(r.collapse_map.iter().map(|&o| {
        if o == decimate::NO_VERTEX {
            -1
        } else {
            i64::from(o)
        }
    }));
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        r.mesh.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("faces", index_array(py, &r.mesh.faces))?;
    d.set_item("vertex_map", vector(py, &r.vertex_map))?;
    d.set_item("collapse_map", collapse_map.into_pyarray(py))?;
    d.set_item("face_origin", vector(py, &r.face_origin))?;
    d.set_item("stats", stats)?;
    Ok(d)
}

/// The verdict of `contractible::check` on `(out_vertices, out_faces)` as an output of
/// `task` on `(vertices, faces)`: the keys of `contractible check --json` but for the
/// file names (`task`, `passed`, `counts`, `failures`).
#[pyfunction(name = "check")]
/// For `simplify`: `eps` (absolute, or with `relative=True` a fraction of the
/// bounding-box diagonal), the run's `position` and `guard`. For `quad` (`out_faces`
/// `(m, 4)`): the stated `triangles` K (in the output's ids) and `pairs` (rows of K).
/// For `decimate`: the run's `target_faces`, `keep`, `max_error` (with `relative`),
/// `placement`, `guard`, `lock_boundary`, `locked`, and the maps. For `reduce`: the
/// `history` (`(k, 2)`, `u, v` per contraction), replayed when given.
#[pyo3(signature = (task, vertices, faces, vertex_count, out_vertices, out_faces, out_vertex_count, eps=None, relative=false, position="midpoint", guard=true, triangles=None, pairs=None, target_faces=None, keep=None, placement="optimal", lock_boundary=false, locked=None, vertex_map=None, collapse_map=None, face_origin=None, history=None))]
#[allow(clippy::too_many_arguments)]
fn check_py<'py>(
    py: Python<'py>,
    task: &str,
    vertices: Option<Coordinates<'py>>,
    faces: Indices<'py>,
    vertex_count: Option<usize>,
    out_vertices: Option<Coordinates<'py>>,
    out_faces: Indices<'py>,
    out_vertex_count: Option<usize>,
    eps: Option<f64>,
    relative: bool,
    position: &str,
    guard: bool,
    triangles: Option<Indices<'py>>,
    pairs: Option<Indices<'py>>,
    target_faces: Option<usize>,
    keep: Option<f64>,
    placement: &str,
    lock_boundary: bool,
    locked: Option<Vec<u32>>,
    vertex_map: Option<Vec<i64>>,
    collapse_map: Option<Vec<i64>>,
    face_origin: Option<Vec<i64>>,
    history: Option<Indices<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let input = mesh::<3>(py, vertices.as_ref(), &faces, vertex_count)?;
    if task == "decimate" {
        let output = mesh::<3>(py, out_vertices.as_ref(), &out_faces, out_vertex_count)?;
        // Ids as the library's maps hold them: -1 (a vertex no face uses) is NO_VERTEX;
        // anything else outside u32 is a ValueError.
        let ids = |name: &str, v: Option<Vec<i64>>| -> PyResult<Option<Vec<u32>>> {
            v.map(|v| {
                v.iter()
                    .enumerate()
                    .map(|(i, &x)| match x {
                        -1 => Ok(decimate::NO_VERTEX),
                        x => u32::try_from(x)
                            .ok()
                            .filter(|&x| x != decimate::NO_VERTEX)
                            .ok_or_else(|| {
                                PyValueError::new_err(format!("{name}[{i}] = {x} is no id"))
                            }),
                    })
                    .collect()
            })
            .transpose()
        };
        let (vm, cm, fo) = (
            ids("vertex_map", vertex_map)?,
            ids("collapse_map", collapse_map)?,
            ids("face_origin", face_origin)?,
        );
        let locked = locked.unwrap_or_default();
        let options = contractible::check::DecimateCheck {
            faces: target_faces,
            keep,
            max_error: eps.map(|e| {
                if relative {
                    contractible::MaxError::Relative(e)
                } else {
                    contractible::MaxError::Absolute(e)
                }
            }),
            placement: choice::<decimate::Placement>(py, placement)?,
            allow_foldover: !guard,
            lock_boundary,
            locked: &locked,
            vertex_map: vm.as_deref(),
            collapse_map: cm.as_deref(),
            face_origin: fo.as_deref(),
        };
        let verdict = py
            .detach(|| contractible::check::decimate(&input, &output, &options))
            .map_err(|e| raise(py, &e, None))?;
        return verdict_dict(py, &verdict);
    }
    if task == "quad" {
        let output = mesh::<4>(py, out_vertices.as_ref(), &out_faces, out_vertex_count)?;
        let k = match &triangles {
            Some(t) => Some(mesh::<3>(py, None, t, Some(output.vertex_count))?.faces),
            None => None,
        };
        let pairs = match &pairs {
            Some(p) => Some(index_pairs(p, "pairs", "face index")?),
            None => None,
        };
        let stated = contractible::check::QuadCheck {
            triangles: k.as_deref(),
            pairs: pairs.as_deref(),
        };
        let verdict = py
            .detach(|| contractible::check::quad(&input, &output, &stated))
            .map_err(|e| raise(py, &e, None))?;
        return verdict_dict(py, &verdict);
    }
    let output = mesh::<3>(py, out_vertices.as_ref(), &out_faces, out_vertex_count)?;
    let verdict = match task {
        "reduce" => match &history {
            Some(h) => {
                let steps = index_pairs(h, "history", "vertex id")?;
                py.detach(|| contractible::check::reduce_history(&input, &output, &steps))
            }
            None => py.detach(|| contractible::check::reduce(&input, &output)),
        },
        "simplify" => {
            let Some(e) = eps else {
                return Err(PyValueError::new_err(
                    "check: \"simplify\" needs the run's eps or eps_rel",
                ));
            };
            let options = contractible::check::SimplifyCheck {
                eps: if relative {
                    Eps::Relative(e)
                } else {
                    Eps::Absolute(e)
                },
                position: choice::<simplify::Position>(py, position)?,
                allow_foldover: !guard,
            };
            py.detach(|| contractible::check::simplify(&input, &output, &options))
        }
        other => {
            return Err(PyValueError::new_err(format!(
                "check: unknown task {other:?} (expected \"reduce\", \"quad\", \"simplify\" or \"decimate\")"
            )))
        }
    }
    .map_err(|e| raise(py, &e, None))?;
    verdict_dict(py, &verdict)
}

/// An `(m, 2)` array of ids (`name`: `pairs`, `history`), each row two `what`s (a
/// `ValueError` naming the row for one outside u32).
fn index_pairs(p: &Indices<'_>, name: &str, what: &str) -> PyResult<Vec<[u32; 2]>> {
    if p.shape()[1] != 2 {
        return Err(PyValueError::new_err(format!(
            "{name} must have shape (m, 2), got ({}, {})",
            p.shape()[0],
            p.shape()[1]
        )));
    }
    /// The rows, or the first row and value that is no u32.
    fn rows<T: Copy + Into<i64>>(values: &[T]) -> Result<Vec<[u32; 2]>, (usize, i64)> {
        values
            .chunks_exact(2)
            .enumerate()
            .map(|(i, r)| {
                let get = |x: T| {
                    let x: i64 = x.into();
                    u32::try_from(x).map_err(|_| (i, x))
                };
                Ok([get(r[0])?, get(r[1])?])
            })
            .collect()
    }
    let r = match p {
        Indices::I64(a) => with_values(a, rows),
        Indices::I32(a) => with_values(a, rows),
        Indices::U32(a) => with_values(a, rows),
    };
    r.map_err(|(i, x)| PyValueError::new_err(format!("{name}[{i}]: {x} is no {what}")))
}

/// A verdict as the dict `contractible check --json` prints, without the file names.
fn verdict_dict<'py>(
    py: Python<'py>,
    verdict: &contractible::check::Verdict,
) -> PyResult<Bound<'py, PyDict>> {
    let counts = PyDict::new(py);
    let mut sorted = verdict.counts.clone();
    sorted.sort_by_key(|&(k, _)| k.name());
    for (k, n) in sorted {
        counts.set_item(k.name(), n)?;
    }
    let failures = pyo3::types::PyList::empty(py);
    for f in &verdict.failures {
        let d = PyDict::new(py);
        d.set_item("kind", f.kind.name())?;
        d.set_item("message", &f.message)?;
        if let Some(x) = f.face {
            d.set_item("face", x)?;
        }
        if let Some(e) = f.edge {
            d.set_item("edge", e.to_vec())?;
        }
        if let Some(v) = f.vertex {
            d.set_item("vertex", v)?;
        }
        if let Some(c) = f.component {
            d.set_item("component", c)?;
        }
        failures.append(d)?;
    }
    let d = PyDict::new(py);
    d.set_item("task", verdict.task)?;
    d.set_item("passed", verdict.passed())?;
    d.set_item("counts", counts)?;
    d.set_item("failures", failures)?;
    Ok(d)
}

/// The native module; `contractible/__init__.py` is the public face.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(write, m)?)?;
    m.add_function(wrap_pyfunction!(info, m)?)?;
    m.add_function(wrap_pyfunction!(reduce, m)?)?;
    m.add_function(wrap_pyfunction!(quad_py, m)?)?;
    m.add_function(wrap_pyfunction!(simplify_py, m)?)?;
    m.add_function(wrap_pyfunction!(decimate_py, m)?)?;
    m.add_function(wrap_pyfunction!(check_py, m)?)?;
    m.add_class::<History>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
