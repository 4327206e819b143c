//! The one error type of the task calls.

use crate::core::BuildError;
use crate::io::{ReadError, WriteError};
use crate::names::UnknownName;
use crate::quad;

/// Why a task call produced nothing. Every variant says what and where: faces by their
/// index in the input face list, vertices by their input index (0-based), file
/// positions by line or byte offset.
///
/// [`Error::is_input`] tells the input's fault (the command line's exit code 2) from
/// anything else (exit code 1); [`Error::kind`] is a stable snake-case name for programs
/// (the command line's JSON, the Python package's `MeshError.kind`).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A file could not be read or parsed.
    #[error(transparent)]
    Read(#[from] ReadError),
    /// A file could not be written (nothing is left at its path).
    #[error(transparent)]
    Write(#[from] WriteError),
    /// The faces are not a union of surfaces (closed ones where the task needs them).
    #[error(transparent)]
    Mesh(#[from] BuildError),
    /// The task needs closed surfaces and this edge lies in one face only.
    #[error(
        "edge [{a}, {b}] is a boundary edge, only in face {face}: {task} needs closed surfaces{}",
        match .boundary_loops {
            Some(1) => " (this mesh is a surface with 1 boundary loop)".to_string(),
            Some(n) => format!(" (this mesh is a surface with {n} boundary loops)"),
            None => String::new(),
        }
    )]
    NotClosed {
        /// The task.
        task: &'static str,
        /// Edge endpoint (the smaller index).
        a: u32,
        /// Edge endpoint (the larger index).
        b: u32,
        /// The face the edge lies in.
        face: usize,
        /// The boundary loops, when the mesh is a surface with boundary (`None`: it is
        /// not a surface even with boundary allowed; [`crate::describe`] says why).
        boundary_loops: Option<usize>,
    },
    /// The task needs vertex positions and the mesh has none.
    #[error("the mesh has no vertex positions; {task} needs coordinates")]
    MissingPositions {
        /// The task.
        task: &'static str,
    },
    /// The positions are not one per vertex.
    #[error("the mesh has {vertices} vertices but {positions} positions")]
    PositionCount {
        /// Vertex count.
        vertices: usize,
        /// Position count.
        positions: usize,
    },
    /// A coordinate is NaN or infinite.
    #[error("vertex {vertex} has a non-finite coordinate {axis} = {value}")]
    NonFiniteCoordinate {
        /// The vertex.
        vertex: usize,
        /// `x`, `y` or `z`.
        axis: char,
        /// The value.
        value: f64,
    },
    /// Every vertex the faces use sits at one point: the positions carry no geometry
    /// (what a purely combinatorial mesh written to a file looks like).
    #[error(
        "all {vertices} vertices are at the same point ({}, {}, {}): the mesh carries no coordinates",
        .point[0], .point[1], .point[2]
    )]
    NoCoordinates {
        /// The vertices the faces use.
        vertices: usize,
        /// Their common position.
        point: [f64; 3],
    },
    /// An option's value is out of its range.
    #[error("{option} = {value}: {expected}")]
    BadOption {
        /// The option, as the options struct names it.
        option: &'static str,
        /// The value given.
        value: String,
        /// What is accepted.
        expected: String,
    },
    /// A choice named by a string is none of the choices.
    #[error(transparent)]
    UnknownName(#[from] UnknownName),
    /// A component is larger than the chosen algorithm accepts.
    #[error(
        "component {component} has {faces} faces; {algorithm} accepts at most {limit}{}",
        if *.algorithm == quad::Algorithm::DsNaive {
            " (it is quadratic): use ds or frink-lct"
        } else {
            ""
        }
    )]
    TooLarge {
        /// The algorithm.
        algorithm: quad::Algorithm,
        /// The component (0-based, in task order).
        component: usize,
        /// Its faces.
        faces: usize,
        /// The most the algorithm accepts.
        limit: usize,
    },
    /// The tri-quad conversion failed on a component (only a broken triangulation can
    /// cause it).
    #[error("component {component}: {source}")]
    Convert {
        /// The component.
        component: usize,
        /// What failed.
        source: quad::ConvertError,
    },
    /// The call was cancelled through its [`crate::task::Monitor`].
    #[error("cancelled")]
    Cancelled,
    /// An output failed its independent check: an internal error, reported instead of
    /// returning a wrong result.
    #[error("internal error: the {task} output of component(s) {} failed the independent check: {detail}",
        .components.iter().map(|c| c.to_string()).collect::<Vec<_>>().join(", "))]
    Unverified {
        /// The task.
        task: &'static str,
        /// The components whose output failed.
        components: Vec<usize>,
        /// What the check found.
        detail: String,
    },
}

impl Error {
    /// Whether the input (mesh, file or options) is at fault, rather than the machine
    /// (an I/O failure while writing) or the library (an output that failed its check).
    pub fn is_input(&self) -> bool {
        match self {
            Error::Read(e) => !matches!(e.kind, crate::io::ReadErrorKind::Io(_)),
            Error::Write(_) | Error::Unverified { .. } | Error::Cancelled => false,
            Error::Convert { .. } => false,
            _ => true,
        }
    }

    /// A stable snake-case name of the error's kind (for the problems of a mesh, the
    /// kind of [`BuildError`]: `boundary_edge`, `non_manifold_edge`...).
    pub fn kind(&self) -> &'static str {
        match self {
            Error::Read(e) if matches!(e.kind, crate::io::ReadErrorKind::Io(_)) => "io",
            Error::Read(_) => "read",
            Error::Write(_) => "write",
            Error::Mesh(e) => build_error_kind(e),
            Error::NotClosed { .. } => "boundary_edge",
            Error::MissingPositions { .. } => "missing_positions",
            Error::PositionCount { .. } => "position_count",
            Error::NonFiniteCoordinate { .. } => "non_finite_coordinate",
            Error::NoCoordinates { .. } => "no_coordinates",
            Error::BadOption { .. } => "bad_option",
            Error::UnknownName(_) => "unknown_name",
            Error::TooLarge { .. } => "too_large",
            Error::Convert { .. } => "internal",
            Error::Cancelled => "cancelled",
            Error::Unverified { .. } => "unverified",
        }
    }
}

/// The snake-case kind of a validation error.
pub fn build_error_kind(e: &BuildError) -> &'static str {
    match e {
        BuildError::Empty => "empty",
        BuildError::TooLarge { .. } => "too_large",
        BuildError::VertexOutOfRange { .. } => "vertex_out_of_range",
        BuildError::DegenerateFace { .. } => "degenerate_face",
        BuildError::DuplicateFace { .. } => "duplicate_face",
        BuildError::BoundaryEdge { .. } => "boundary_edge",
        BuildError::NonManifoldEdge { .. } => "non_manifold_edge",
        BuildError::MultipleEdges { .. } => "multiple_edges",
        BuildError::VertexLinkNotCycle { .. } => "pinched_vertex",
        BuildError::PinchedBoundaryVertex { .. } => "pinched_boundary_vertex",
        BuildError::VertexDegreeTooLow { .. } => "vertex_degree_too_low",
        BuildError::UnusedVertex { .. } => "unused_vertex",
        BuildError::Disconnected { .. } => "disconnected",
    }
}
