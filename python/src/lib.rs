//! The native half of the `contractible` Python package: NumPy arrays in, NumPy arrays
//! and plain dicts out, over the library's mesh-level operations.
//!
//! # Guarantees
//! - Every function validates its arrays before any work: shapes and dtypes raise
//!   `ValueError`; a face naming a vertex out of range (negative included), a NaN or
//!   infinite coordinate, and every error the library reports (non-manifold edge, boundary
//!   where a closed surface is required, a file's bad line...) raise
//!   `contractible.MeshError` with `kind` and `location` (face, vertex, edge, line). Nothing
//!   input-derived can panic or crash the interpreter.
//! - The GIL is released while the library works (building, the algorithm, verification),
//!   so threads run concurrently; the arrays are copied into Rust first.
//! - Results are deterministic for a given input and seed, and equal to the command line's
//!   for the same mesh: the same per-component order (by smallest face index), the same
//!   vertex renumbering of outputs (survivors in input order), the same statistics keys.
//!
//! The public Python API (`python/contractible/__init__.py`) wraps these functions: it
//! converts dtypes, accepts trimesh-like objects and builds the result objects.

use std::path::PathBuf;

use contractible::io::{self, Location, ReadError, WriteError};
use contractible::irreducible::{self, Reduction};
use contractible::simplify::{self, Mode, Position, Side, SimplifyError};
use contractible::{
    quad, BuildError, ConedSurfaces, Mesh, QuadMesh, SurfaceType, Surfaces, TriMesh, Triangulation,
};
use numpy::ndarray::{Array1, Array2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::{PyOSError, PyValueError};
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

/// The `MeshError` of a construction error, located.
fn build_error(py: Python<'_>, e: &BuildError) -> PyErr {
    let (kind, loc): (&str, Vec<(&str, i64)>) = match e {
        BuildError::Empty => ("empty", vec![]),
        BuildError::TooLarge { count, .. } => ("too_large", vec![("count", int(*count))]),
        BuildError::VertexOutOfRange { face, vertex, .. } => (
            "vertex_out_of_range",
            vec![("face", int(*face)), ("vertex", i64::from(*vertex))],
        ),
        BuildError::DegenerateFace { face, .. } => ("degenerate_face", vec![("face", int(*face))]),
        BuildError::DuplicateFace { face, first, .. } => (
            "duplicate_face",
            vec![("face", int(*face)), ("first", int(*first))],
        ),
        BuildError::BoundaryEdge { a, b, face } => ("boundary_edge", edge(*face, *a, *b)),
        BuildError::NonManifoldEdge { a, b, face, .. } => {
            ("non_manifold_edge", edge(*face, *a, *b))
        }
        BuildError::MultipleEdges { a, b, face, .. } => ("multiple_edges", edge(*face, *a, *b)),
        BuildError::VertexLinkNotCycle { vertex, .. } => {
            ("pinched_vertex", vec![("vertex", i64::from(*vertex))])
        }
        BuildError::PinchedBoundaryVertex { vertex, .. } => (
            "pinched_boundary_vertex",
            vec![("vertex", i64::from(*vertex))],
        ),
        BuildError::VertexDegreeTooLow { vertex, .. } => (
            "vertex_degree_too_low",
            vec![("vertex", i64::from(*vertex))],
        ),
        BuildError::UnusedVertex { vertex } => {
            ("unused_vertex", vec![("vertex", i64::from(*vertex))])
        }
        BuildError::Disconnected { .. } => ("disconnected", vec![]),
        _ => ("invalid_mesh", vec![]),
    };
    mesh_error(py, kind, e.to_string(), &loc)
}

/// The `MeshError` of a reading error, located by line, byte offset or face.
fn read_error(py: Python<'_>, path: &std::path::Path, e: &ReadError) -> PyErr {
    let loc: Vec<(&str, i64)> = match e.location {
        Location::Line(n) => vec![("line", int(n))],
        Location::ByteOffset(b) => vec![("byte_offset", i64::try_from(b).unwrap_or(i64::MAX))],
        Location::Face(f) => vec![("face", int(f))],
        _ => vec![],
    };
    let message = match e.location {
        Location::Unknown => format!("{}: {}", path.display(), e.kind),
        l => format!("{}: {l}: {}", path.display(), e.kind),
    };
    if let io::ReadErrorKind::Io(err) = &e.kind {
        return PyOSError::new_err(format!("{message} ({err})"));
    }
    mesh_error(py, "read", message, &loc)
}

/// The caller's `(n, 3)` positions, checked finite, copied out.
fn positions(
    py: Python<'_>,
    vertices: Option<&PyReadonlyArray2<'_, f64>>,
) -> PyResult<Option<Vec<[f64; 3]>>> {
    Ok(match vertices {
        None => None,
        Some(v) => {
            let s = v.shape();
            if s[1] != 3 {
                return Err(PyValueError::new_err(format!(
                    "vertices must have shape (n, 3), got ({}, {})",
                    s[0], s[1]
                )));
            }
            let mut out = Vec::with_capacity(s[0]);
            for (i, row) in v.as_array().outer_iter().enumerate() {
                let p = [row[0], row[1], row[2]];
                if let Some(k) = (0..3).find(|&k| !p[k].is_finite()) {
                    return Err(mesh_error(
                        py,
                        "non_finite_coordinate",
                        format!(
                            "vertex {i} has a non-finite coordinate {} = {}",
                            ['x', 'y', 'z'][k],
                            p[k]
                        ),
                        &[("vertex", int(i))],
                    ));
                }
                out.push(p);
            }
            Some(out)
        }
    })
}

/// A triangle mesh copied out of the caller's arrays, checked: `faces` is `(m, 3)`,
/// `vertices` (when given) `(n, 3)` and finite, every index in `0..n`. Without vertices,
/// `n` is `vertex_count` or one more than the largest index.
fn tri_mesh(
    py: Python<'_>,
    vertices: Option<&PyReadonlyArray2<'_, f64>>,
    faces: &PyReadonlyArray2<'_, i64>,
    vertex_count: Option<usize>,
) -> PyResult<TriMesh> {
    let shape = faces.shape();
    if shape[1] != 3 {
        return Err(PyValueError::new_err(format!(
            "faces must have shape (m, 3), got ({}, {})",
            shape[0], shape[1]
        )));
    }
    let positions = positions(py, vertices)?;
    let n = match (&positions, vertex_count) {
        (Some(p), _) => p.len(),
        (None, Some(n)) => n,
        (None, None) => {
            let max = faces.as_array().iter().copied().max().unwrap_or(-1);
            usize::try_from(max.saturating_add(1)).unwrap_or(0)
        }
    };
    if u32::try_from(n).is_err() {
        return Err(mesh_error(
            py,
            "too_large",
            format!("{n} vertices: too many for 32-bit vertex ids"),
            &[("count", int(n))],
        ));
    }
    let mut list = Vec::with_capacity(shape[0]);
    let view = faces.as_array();
    // The wrapper passes C-contiguous arrays: read them as one flat slice (fast); any
    // other layout row by row.
    let flat: Vec<i64>;
    let values: &[i64] = match view.as_slice() {
        Some(s) => s,
        None => {
            flat = view.iter().copied().collect();
            &flat
        }
    };
    for (i, row) in values.chunks_exact(3).enumerate() {
        let mut f = [0u32; 3];
        for k in 0..3 {
            let x = row[k];
            f[k] = match u32::try_from(x) {
                Ok(x) if (x as usize) < n => x,
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
    Ok(TriMesh {
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

/// The surface-type keys of the command line's JSON (`euler_characteristic`,
/// `orientable`, `genus`, `euler_genus`, and `boundary_loops` for a surface with
/// boundary).
fn put_surface(d: &Bound<'_, PyDict>, s: SurfaceType) -> PyResult<()> {
    d.set_item("euler_characteristic", s.euler_characteristic())?;
    d.set_item("orientable", s.is_orientable())?;
    d.set_item("genus", s.orientable_genus())?;
    d.set_item("euler_genus", s.euler_genus())?;
    if !s.is_closed() {
        d.set_item("boundary_loops", s.boundary_loops())?;
    }
    Ok(())
}

/// `read`'s result: positions (if the file has any), faces, vertex count.
type ReadResult<'py> = (
    Option<Bound<'py, PyArray2<f64>>>,
    Bound<'py, PyArray2<i64>>,
    usize,
);

/// Reads a mesh file (OFF, OBJ, PLY, STL, optionally gzipped; format by extension, else
/// sniffed). Returns `(vertices or None, faces, vertex count)`.
#[pyfunction]
fn read(py: Python<'_>, path: PathBuf) -> PyResult<ReadResult<'_>> {
    let r = py.detach(|| io::read_tri_mesh(&path));
    let m = r.map_err(|e| read_error(py, &path, &e))?;
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
    vertices: Option<PyReadonlyArray2<'_, f64>>,
    faces: PyReadonlyArray2<'_, i64>,
    vertex_count: Option<usize>,
) -> PyResult<()> {
    let corners = faces.shape()[1];
    let tri = match corners {
        3 => tri_mesh(py, vertices.as_ref(), &faces, vertex_count)?,
        4 => {
            // Validate as triangles (two per quad, same indices) for the shared checks.
            let q = quad_list(py, &faces)?;
            let n = match (&vertices, vertex_count) {
                (Some(v), _) => v.shape()[0],
                (None, Some(n)) => n,
                (None, None) => q
                    .iter()
                    .flatten()
                    .map(|&x| x as usize + 1)
                    .max()
                    .unwrap_or(0),
            };
            let positions = positions(py, vertices.as_ref())?;
            for (i, f) in q.iter().enumerate() {
                if let Some(&x) = f.iter().find(|&&x| x as usize >= n) {
                    return Err(mesh_error(
                        py,
                        "vertex_out_of_range",
                        format!("face {i}: vertex index {x} out of range (vertex count {n})"),
                        &[("face", int(i)), ("vertex", i64::from(x))],
                    ));
                }
            }
            let quads = QuadMesh {
                vertex_count: n,
                positions,
                faces: q,
            };
            return write_any(py, &path, &quads);
        }
        c => {
            return Err(PyValueError::new_err(format!(
                "faces must have shape (m, 3) or (m, 4), got (m, {c})"
            )))
        }
    };
    write_any(py, &path, &tri)
}

fn quad_list(py: Python<'_>, faces: &PyReadonlyArray2<'_, i64>) -> PyResult<Vec<[u32; 4]>> {
    let mut out = Vec::with_capacity(faces.shape()[0]);
    for (i, row) in faces.as_array().outer_iter().enumerate() {
        let mut f = [0u32; 4];
        for k in 0..4 {
            f[k] = u32::try_from(row[k]).map_err(|_| {
                mesh_error(
                    py,
                    "vertex_out_of_range",
                    format!("face {i}: vertex index {} out of range", row[k]),
                    &[("face", int(i)), ("vertex", row[k])],
                )
            })?;
        }
        out.push(f);
    }
    Ok(out)
}

fn write_any<const N: usize>(
    py: Python<'_>,
    path: &std::path::Path,
    mesh: &Mesh<N>,
) -> PyResult<()> {
    if io::Format::from_path(path).0.is_none() {
        return Err(PyValueError::new_err(format!(
            "{}: {}",
            path.display(),
            WriteError::UnknownFormat(path.to_path_buf())
        )));
    }
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = path.with_file_name(format!(".contractible-{}-{name}", std::process::id()));
    let r = py.detach(|| {
        io::write_mesh(&tmp, mesh).and_then(|()| std::fs::rename(&tmp, path).map_err(Into::into))
    });
    match r {
        Ok(()) => Ok(()),
        Err(e) => {
            let _ = std::fs::remove_file(&tmp);
            match e {
                WriteError::Io(err) => {
                    Err(PyOSError::new_err(format!("{}: {err}", path.display())))
                }
                e => Err(PyValueError::new_err(format!("{}: {e}", path.display()))),
            }
        }
    }
}

/// The topology of every component (surfaces with boundary allowed), as `info --json`
/// reports it.
#[pyfunction]
#[pyo3(signature = (vertices, faces, vertex_count=None))]
fn info<'py>(
    py: Python<'py>,
    vertices: Option<PyReadonlyArray2<'py, f64>>,
    faces: PyReadonlyArray2<'py, i64>,
    vertex_count: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let mesh = tri_mesh(py, vertices.as_ref(), &faces, vertex_count)?;
    let s = py
        .detach(|| ConedSurfaces::from_mesh(&mesh))
        .map_err(|e| build_error(py, &e))?;
    let d = PyDict::new(py);
    let list = PyList::empty(py);
    let (mut v, mut e, mut f, mut chi, mut loops) = (0, 0, 0, 0i64, 0);
    let mut orientable = true;
    for c in &s.components {
        let (cv, ce, cf) = c.open_counts();
        let st = c.surface_type();
        let cd = PyDict::new(py);
        cd.set_item("vertices", cv)?;
        cd.set_item("edges", ce)?;
        cd.set_item("faces", cf)?;
        put_surface(&cd, st)?;
        if !st.is_closed() {
            cd.set_item("boundary_loop_lengths", c.loop_lengths())?;
        }
        list.append(cd)?;
        v += cv;
        e += ce;
        f += cf;
        chi += st.euler_characteristic();
        loops += st.boundary_loops();
        orientable &= st.is_orientable();
    }
    d.set_item("vertices", v)?;
    d.set_item("edges", e)?;
    d.set_item("faces", f)?;
    d.set_item("components", s.components.len())?;
    d.set_item("euler_characteristic", chi)?;
    d.set_item("orientable", orientable)?;
    if loops > 0 {
        d.set_item("boundary_loops", loops)?;
    }
    d.set_item("dropped_vertices", s.dropped_vertices.len())?;
    d.set_item("component_list", list)?;
    Ok(d)
}

/// Validates a mesh as closed surfaces, with the command line's message for a boundary.
fn closed_surfaces(py: Python<'_>, mesh: &TriMesh, what: &str) -> PyResult<Surfaces> {
    match py.detach(|| Surfaces::from_mesh(mesh)) {
        Ok(s) => Ok(s),
        Err(e @ BuildError::BoundaryEdge { .. }) => {
            let loops = py
                .detach(|| Surfaces::from_mesh_with_boundary(mesh))
                .map(|s| s.loop_count())
                .ok();
            let err = build_error(py, &e);
            let why = match loops {
                Some(n) => format!("this mesh has {n} boundary loop(s); `info` describes it"),
                None => "nor is it a surface with boundary".to_string(),
            };
            let msg = format!("{e}: `{what}` needs closed surfaces ({why})");
            let value = err.value(py);
            value.setattr("args", (msg.clone(),))?;
            value.setattr("message", msg)?;
            Err(err)
        }
        Err(e) => Err(build_error(py, &e)),
    }
}

/// One reduced component: the library's result with its vertex origin.
struct Part {
    reduction: Reduction,
    vertex_origin: Vec<u32>,
    face_origin: Vec<u32>,
}

/// The contraction history of a `reduce` call: replays vertex splits.
#[pyclass(module = "contractible._native", frozen)]
struct History {
    parts: Vec<Part>,
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

fn reduce_algorithm(name: &str) -> PyResult<irreducible::Algorithm> {
    match name {
        "rs" => Ok(irreducible::Algorithm::Rs),
        "schipper" => Ok(irreducible::Algorithm::Schipper),
        "brute" => Ok(irreducible::Algorithm::Brute),
        other => Err(PyValueError::new_err(format!(
            "unknown algo {other:?}: expected 'rs', 'schipper' or 'brute'"
        ))),
    }
}

/// Irreducible triangulations of every component (closed surfaces only). Returns a dict:
/// `vertices` (survivors' positions or None), `faces` (over the survivors, renumbered
/// in input order), `vertex_map` (input id of each survivor), `stats` (the command
/// line's `reduce --json` totals and `component_list`), `history`.
#[pyfunction]
#[pyo3(signature = (vertices, faces, algo="rs", seed=0, vertex_count=None, count_retests=false))]
fn reduce<'py>(
    py: Python<'py>,
    vertices: Option<PyReadonlyArray2<'py, f64>>,
    faces: PyReadonlyArray2<'py, i64>,
    algo: &str,
    seed: u64,
    vertex_count: Option<usize>,
    count_retests: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let algorithm = reduce_algorithm(algo)?;
    let mesh = tri_mesh(py, vertices.as_ref(), &faces, vertex_count)?;
    let surfaces = closed_surfaces(py, &mesh, "reduce")?;
    let options = irreducible::Options {
        seed,
        count_retests,
    };
    let dropped = surfaces.dropped_vertices.len();
    let (parts, inputs) = py.detach(|| {
        let mut parts = Vec::with_capacity(surfaces.components.len());
        let mut inputs = Vec::with_capacity(surfaces.components.len());
        for c in surfaces.components {
            inputs.push(SurfaceType::of(&c.tri));
            let reduction = irreducible::reduce(c.tri, algorithm, &options);
            parts.push(Part {
                reduction,
                vertex_origin: c.vertex_origin,
                face_origin: c.face_origin,
            });
        }
        (parts, inputs)
    });
    let out = TriMesh::reassemble(
        mesh.vertex_count,
        mesh.positions.clone(),
        parts
            .iter()
            .map(|p| (&p.reduction.tri, &p.vertex_origin[..])),
    )
    .ok_or_else(|| PyValueError::new_err("inconsistent mesh after validation"))?;
    let mut survivors: Vec<u32> = parts
        .iter()
        .flat_map(|p| {
            p.reduction
                .tri
                .vertices()
                .map(|v| p.vertex_origin[v.index()])
        })
        .collect();
    survivors.sort_unstable();
    let comps = PyList::empty(py);
    let mut totals = irreducible::Stats::default();
    for (p, input) in parts.iter().zip(&inputs) {
        let s = &p.reduction.stats;
        let d = PyDict::new(py);
        reduce_stats(&d, algo, s, p.reduction.tri.edge_count(), *input)?;
        comps.append(d)?;
        totals.vertices_in += s.vertices_in;
        totals.edges_in += s.edges_in;
        totals.faces_in += s.faces_in;
        totals.vertices_out += s.vertices_out;
        totals.faces_out += s.faces_out;
        totals.link_tests += s.link_tests;
        totals.edges_tested_more_than_once += s.edges_tested_more_than_once;
        totals.contractions += s.contractions;
        totals.seconds += s.seconds;
    }
    let chi: i64 = inputs.iter().map(|s| s.euler_characteristic()).sum();
    let orientable = inputs.iter().all(|s| s.is_orientable());
    let stats = PyDict::new(py);
    stats.set_item("algo", algo)?;
    stats.set_item("seed", seed)?;
    stats.set_item("components", parts.len())?;
    stats.set_item("dropped_vertices", dropped)?;
    stats.set_item("vertices_in", totals.vertices_in)?;
    stats.set_item("edges_in", totals.edges_in)?;
    stats.set_item("faces_in", totals.faces_in)?;
    stats.set_item("euler_characteristic", chi)?;
    stats.set_item("orientable", orientable)?;
    stats.set_item(
        "genus",
        orientable.then(|| {
            inputs
                .iter()
                .filter_map(|s| s.orientable_genus())
                .sum::<i64>()
        }),
    )?;
    stats.set_item(
        "euler_genus",
        inputs.iter().map(|s| s.euler_genus()).sum::<i64>(),
    )?;
    stats.set_item("vertices_out", totals.vertices_out)?;
    stats.set_item(
        "edges_out",
        parts
            .iter()
            .map(|p| p.reduction.tri.edge_count())
            .sum::<usize>(),
    )?;
    stats.set_item("faces_out", totals.faces_out)?;
    stats.set_item("link_tests", totals.link_tests)?;
    stats.set_item(
        "edges_tested_more_than_once",
        totals.edges_tested_more_than_once,
    )?;
    stats.set_item("contractions", totals.contractions)?;
    stats.set_item("seconds", totals.seconds)?;
    stats.set_item("component_list", comps)?;
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        out.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("faces", index_array(py, &out.faces))?;
    d.set_item("vertex_map", vector(py, &survivors))?;
    d.set_item("stats", stats)?;
    d.set_item("history", Py::new(py, History { parts })?)?;
    Ok(d)
}

fn reduce_stats(
    d: &Bound<'_, PyDict>,
    algo: &str,
    s: &irreducible::Stats,
    edges_out: usize,
    input: SurfaceType,
) -> PyResult<()> {
    d.set_item("algo", algo)?;
    d.set_item("vertices_in", s.vertices_in)?;
    d.set_item("edges_in", s.edges_in)?;
    d.set_item("faces_in", s.faces_in)?;
    put_surface(d, input)?;
    d.set_item("vertices_out", s.vertices_out)?;
    d.set_item("edges_out", edges_out)?;
    d.set_item("faces_out", s.faces_out)?;
    d.set_item("link_tests", s.link_tests)?;
    d.set_item("edges_tested_more_than_once", s.edges_tested_more_than_once)?;
    d.set_item("contractions", s.contractions)?;
    d.set_item("seconds", s.seconds)?;
    Ok(())
}

fn quad_algorithm(name: &str) -> PyResult<quad::Algorithm> {
    match name {
        "lrs" => Ok(quad::Algorithm::Lrs),
        "ps" => Ok(quad::Algorithm::Ps),
        "sg" => Ok(quad::Algorithm::Sg),
        "matching" => Ok(quad::Algorithm::Matching),
        "frink-lct" => Ok(quad::Algorithm::FrinkLct),
        "ds" => Ok(quad::Algorithm::Ds),
        "bbdl" => Ok(quad::Algorithm::Bbdl),
        "ds-naive" => Ok(quad::Algorithm::DsNaive),
        other => Err(PyValueError::new_err(format!(
            "unknown algo {other:?}: expected 'lrs', 'ps', 'sg', 'matching', 'ds', 'bbdl', 'frink-lct' or 'ds-naive'"
        ))),
    }
}

/// A perfect pairing of the triangles of every component (closed surfaces only). Returns
/// a dict: `quads` (`(m/2, 4)`, input vertex ids), `triangles` (the paired triangulation
/// K, `(m, 3)`, row `i` is input face `i` after LRS's flips), `pairs` (`(m/2, 2)` rows of
/// `triangles`), `vertices` (the input's, or None), `stats`.
#[pyfunction(name = "quad")]
#[pyo3(signature = (vertices, faces, algo="lrs", seed=0, vertex_count=None))]
fn quad_py<'py>(
    py: Python<'py>,
    vertices: Option<PyReadonlyArray2<'py, f64>>,
    faces: PyReadonlyArray2<'py, i64>,
    algo: &str,
    seed: u64,
    vertex_count: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let algorithm = quad_algorithm(algo)?;
    let mesh = tri_mesh(py, vertices.as_ref(), &faces, vertex_count)?;
    let surfaces = closed_surfaces(py, &mesh, "quad")?;
    if algorithm == quad::Algorithm::DsNaive {
        if let Some(c) = surfaces
            .components
            .iter()
            .find(|c| c.tri.face_count() > quad::DS_NAIVE_MAX_FACES)
        {
            return Err(PyValueError::new_err(format!(
                "algo 'ds-naive' is quadratic and refuses components above {} faces (this one has {}); use 'ds' or 'frink-lct'",
                quad::DS_NAIVE_MAX_FACES,
                c.tri.face_count()
            )));
        }
    }
    let options = quad::Options { seed };
    let dropped = surfaces.dropped_vertices.len();
    let m = mesh.faces.len();
    let (stats_list, quads, pairs, k_faces) = py.detach(|| {
        let mut stats = Vec::new();
        let mut quads: Vec<[u32; 4]> = Vec::with_capacity(m / 2);
        let mut pairs: Vec<[u32; 2]> = Vec::with_capacity(m / 2);
        let mut k_faces = mesh.faces.clone();
        for c in surfaces.components {
            let input = SurfaceType::of(&c.tri);
            let q = quad::convert(c.tri, algorithm, &options);
            for (f, g) in q.pairing.pairs() {
                if let Some(qd) = quad::quad_of(&q.tri, f, g) {
                    quads.push(qd.map(|v| c.vertex_origin[v as usize]));
                }
                pairs.push([c.face_origin[f.index()], c.face_origin[g.index()]]);
            }
            for f in q.tri.faces() {
                let vs = q.tri.face_vertices(f).map(|v| c.vertex_origin[v.index()]);
                k_faces[c.face_origin[f.index()] as usize] = vs;
            }
            stats.push((q.stats, q.pairing.len(), input));
        }
        (stats, quads, pairs, k_faces)
    });
    let comps = PyList::empty(py);
    let (mut faces_total, mut unpaired, mut flips, mut paths, mut phases) = (0, 0, 0, 0, 0);
    let (mut a, mut dsec, mut e) = (0.0, 0.0, 0.0);
    for (s, nq, input) in &stats_list {
        let d = PyDict::new(py);
        quad_stats(&d, algo, s, *nq, *input)?;
        comps.append(d)?;
        faces_total += s.faces;
        unpaired += s.initial_unpaired;
        flips += s.flips;
        paths += s.augmenting_paths;
        phases = phases.max(s.phases);
        a += s.initial_seconds;
        dsec += s.completion_seconds;
        e += s.total_seconds;
    }
    let stats = PyDict::new(py);
    stats.set_item("algo", algo)?;
    stats.set_item("seed", seed)?;
    stats.set_item("components", stats_list.len())?;
    stats.set_item("dropped_vertices", dropped)?;
    stats.set_item("faces", faces_total)?;
    stats.set_item("quads", quads.len())?;
    stats.set_item(
        "euler_characteristic",
        stats_list
            .iter()
            .map(|s| s.2.euler_characteristic())
            .sum::<i64>(),
    )?;
    stats.set_item("orientable", stats_list.iter().all(|s| s.2.is_orientable()))?;
    stats.set_item("initial_seconds", a)?;
    stats.set_item(
        "initial_paired_percent",
        if faces_total == 0 {
            100.0
        } else {
            100.0 * (faces_total - unpaired) as f64 / faces_total as f64
        },
    )?;
    stats.set_item("initial_unpaired", unpaired)?;
    stats.set_item("completion_seconds", dsec)?;
    stats.set_item("total_seconds", e)?;
    stats.set_item("flips", flips)?;
    stats.set_item("augmenting_paths", paths)?;
    stats.set_item("phases", phases)?;
    stats.set_item("component_list", comps)?;
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        mesh.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("quads", index_array(py, &quads))?;
    d.set_item("triangles", index_array(py, &k_faces))?;
    d.set_item("pairs", index_array(py, &pairs))?;
    d.set_item("stats", stats)?;
    Ok(d)
}

fn quad_stats(
    d: &Bound<'_, PyDict>,
    algo: &str,
    s: &quad::Stats,
    quads: usize,
    input: SurfaceType,
) -> PyResult<()> {
    d.set_item("algo", algo)?;
    d.set_item("faces", s.faces)?;
    d.set_item("quads", quads)?;
    d.set_item("euler_characteristic", input.euler_characteristic())?;
    d.set_item("orientable", input.is_orientable())?;
    d.set_item("initial_seconds", s.initial_seconds)?;
    d.set_item("initial_paired_percent", s.initial_paired_percent)?;
    d.set_item("initial_unpaired", s.initial_unpaired)?;
    d.set_item("completion_seconds", s.completion_seconds)?;
    d.set_item("total_seconds", s.total_seconds)?;
    d.set_item("flips", s.flips)?;
    d.set_item("augmenting_paths", s.augmenting_paths)?;
    d.set_item("phases", s.phases)?;
    Ok(())
}

fn simplify_error(py: Python<'_>, e: &SimplifyError) -> PyErr {
    match e {
        SimplifyError::Build(b) => build_error(py, b),
        SimplifyError::NonFiniteCoordinate { vertex, .. } => mesh_error(
            py,
            "non_finite_coordinate",
            e.to_string(),
            &[("vertex", int(*vertex))],
        ),
        SimplifyError::MissingPositions => {
            PyValueError::new_err("simplify needs vertex positions (vertices is None)")
        }
        e => PyValueError::new_err(e.to_string()),
    }
}

/// Contracts every edge shorter than ε without changing the surface (closed or with
/// boundary). `eps` is absolute, or with `relative=True` a fraction of the bounding-box
/// diagonal of the vertices the faces use. Returns a dict: `vertices`, `faces`, `stats`.
#[pyfunction(name = "simplify")]
#[pyo3(signature = (vertices, faces, eps, relative=false, mode="nested", side="count", position="midpoint", guard=true))]
#[allow(clippy::too_many_arguments)]
fn simplify_py<'py>(
    py: Python<'py>,
    vertices: Option<PyReadonlyArray2<'py, f64>>,
    faces: PyReadonlyArray2<'py, i64>,
    eps: f64,
    relative: bool,
    mode: &str,
    side: &str,
    position: &str,
    guard: bool,
) -> PyResult<Bound<'py, PyDict>> {
    let mode_v = match mode {
        "nested" => Mode::Nested,
        "naive" => Mode::Naive,
        o => {
            return Err(PyValueError::new_err(format!(
                "unknown mode {o:?}: expected 'nested' or 'naive'"
            )))
        }
    };
    let side_v = match side {
        "count" => Side::Count,
        "path" => Side::Path,
        "euclidean" => Side::Euclidean,
        o => {
            return Err(PyValueError::new_err(format!(
                "unknown side {o:?}: expected 'count', 'path' or 'euclidean'"
            )))
        }
    };
    let position_v = match position {
        "midpoint" => Position::Midpoint,
        "quadric" => Position::Quadric,
        o => {
            return Err(PyValueError::new_err(format!(
                "unknown position {o:?}: expected 'midpoint' or 'quadric'"
            )))
        }
    };
    if vertices.is_none() {
        return Err(simplify_error(py, &SimplifyError::MissingPositions));
    }
    let mesh = tri_mesh(py, vertices.as_ref(), &faces, None)?;
    if !(eps.is_finite() && eps > 0.0) {
        return Err(PyValueError::new_err(format!(
            "eps must be a finite number > 0, got {eps}"
        )));
    }
    let r = py.detach(|| {
        let abs = if relative {
            let mut used = vec![false; mesh.vertex_count];
            for f in &mesh.faces {
                for &v in f {
                    used[v as usize] = true;
                }
            }
            let p = mesh.positions.as_deref().unwrap_or(&[]);
            let diag =
                simplify::bbox_diagonal(p.iter().zip(&used).filter(|(_, &u)| u).map(|(q, _)| *q));
            (eps * diag, diag)
        } else {
            (eps, f64::NAN)
        };
        let options = simplify::Options {
            eps: abs.0,
            mode: mode_v,
            side: side_v,
            position: position_v,
            guard,
        };
        (simplify::simplify(&mesh, &options), abs)
    });
    let (out, (abs, _diag)) = (r.0.map_err(|e| simplify_error(py, &e))?, r.1);
    let stats = pythonize::pythonize(py, &out.stats)
        .map_err(|e| PyValueError::new_err(e.to_string()))?
        .cast_into::<PyDict>()
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    stats.set_item("eps", abs)?;
    stats.set_item("eps_rel", relative.then_some(eps))?;
    stats.set_item("mode", mode)?;
    stats.set_item("side", side)?;
    stats.set_item("position", position)?;
    stats.set_item("guard", guard)?;
    let d = PyDict::new(py);
    d.set_item(
        "vertices",
        out.mesh.positions.as_deref().map(|p| vertices_array(py, p)),
    )?;
    d.set_item("faces", index_array(py, &out.mesh.faces))?;
    d.set_item("stats", stats)?;
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
    m.add_class::<History>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
