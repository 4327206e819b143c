//! [`describe`]: what a mesh is (its surfaces' topology), or every reason it is not a
//! surface.

use std::fmt;

use crate::core::{ConedComponent, ConedSurfaces, Triangulation};
use crate::diagnose::{diagnose, Diagnosis};
use crate::mesh::TriMesh;
use crate::topology::SurfaceType;

use super::{Error, Monitor, Step};

/// Topology and degrees of one connected surface (possibly with boundary). The fields
/// are the command line's `info --json` keys of a component.
#[derive(Clone, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct ComponentDescription {
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Its type: serialised as `euler_characteristic`, `orientable`, `genus`
    /// (orientable genus, `null` for a non-orientable surface) and `euler_genus`, then
    /// `boundary_loops` for a surface with boundary only.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub surface: SurfaceType,
    /// The length (in edges) of each boundary loop, in loop order; empty (and not
    /// serialised) for a closed surface.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub boundary_loop_lengths: Vec<usize>,
    /// Smallest vertex degree.
    pub degree_min: usize,
    /// Largest vertex degree.
    pub degree_max: usize,
    /// Mean vertex degree (2E/V).
    pub degree_mean: f64,
    /// Entry `d`: the number of vertices of degree `d`.
    pub degree_histogram: Vec<usize>,
}

impl ComponentDescription {
    /// The description of a closed triangulation.
    pub fn of(t: &Triangulation) -> Self {
        let hist = t.degree_histogram();
        ComponentDescription {
            vertices: t.vertex_count(),
            edges: t.edge_count(),
            faces: t.face_count(),
            surface: SurfaceType::of(t),
            boundary_loop_lengths: Vec::new(),
            degree_min: hist.iter().position(|&n| n > 0).unwrap_or(0),
            degree_max: hist.len().saturating_sub(1),
            degree_mean: 2.0 * t.edge_count() as f64 / t.vertex_count().max(1) as f64,
            degree_histogram: hist,
        }
    }

    /// The description of the surface with boundary a coned component stands for: the
    /// virtual vertices, their edges and the cone faces are left out of every count and
    /// degree. A closed component gives exactly [`Self::of`] of its triangulation.
    pub fn of_coned(c: &ConedComponent) -> Self {
        if c.is_closed() {
            return Self::of(&c.tri);
        }
        let t = &c.tri;
        let mut on_boundary = vec![false; t.vertex_capacity()];
        for w in c.virtual_vertices() {
            for x in t.link(w) {
                on_boundary[x.index()] = true;
            }
        }
        let mut hist: Vec<usize> = Vec::new();
        for v in t.vertices().filter(|&v| !c.is_virtual(v)) {
            // A boundary vertex has exactly one virtual neighbour (its loop's apex).
            let d = t.degree(v) - usize::from(on_boundary[v.index()]);
            if hist.len() <= d {
                hist.resize(d + 1, 0);
            }
            hist[d] += 1;
        }
        let (vertices, edges, faces) = c.open_counts();
        ComponentDescription {
            vertices,
            edges,
            faces,
            surface: c.surface_type(),
            boundary_loop_lengths: c.loop_lengths(),
            degree_min: hist.iter().position(|&n| n > 0).unwrap_or(0),
            degree_max: hist.len().saturating_sub(1),
            degree_mean: 2.0 * edges as f64 / vertices.max(1) as f64,
            degree_histogram: hist,
        }
    }
}

/// What [`describe`] returns: for a union of surfaces, each component; otherwise every
/// problem, counted and located.
#[derive(Clone, Debug)]
pub enum Description {
    /// The faces form a union of surfaces (closed or with boundary).
    Surfaces {
        /// Per component, in the order of their smallest face.
        components: Vec<ComponentDescription>,
        /// Vertices no face uses.
        dropped_vertices: usize,
    },
    /// They do not: every problem at once, with up to 5 located examples of each kind,
    /// and the first problem the validation meets, as the other task calls report it.
    Problems {
        /// Every problem ([`crate::diagnose`]).
        diagnosis: Diagnosis,
        /// The first problem the validation of surfaces (closed or with boundary)
        /// meets: the error [`crate::reduce`] and [`crate::quadrangulate`] return, except
        /// on a mesh that also has a boundary, which those two refuse first
        /// ([`crate::Error::NotClosed`]) when the boundary is found before this problem.
        first: crate::core::BuildError,
    },
}

impl Description {
    /// Whether the faces form a union of surfaces (closed or with boundary).
    pub fn is_surface(&self) -> bool {
        matches!(self, Description::Surfaces { .. })
    }

    /// Whether they form a union of closed surfaces.
    pub fn is_closed(&self) -> bool {
        match self {
            Description::Surfaces { components, .. } => {
                components.iter().all(|c| c.surface.is_closed())
            }
            Description::Problems { .. } => false,
        }
    }

    /// The components (empty when the mesh is not a surface).
    pub fn components(&self) -> &[ComponentDescription] {
        match self {
            Description::Surfaces { components, .. } => components,
            Description::Problems { .. } => &[],
        }
    }
}

impl fmt::Display for Description {
    /// One line per component (`sphere: V=… E=… F=… χ=2`), or one per kind of problem
    /// with its count and first example.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Description::Surfaces { components, .. } => {
                for (i, c) in components.iter().enumerate() {
                    if i > 0 {
                        writeln!(f)?;
                    }
                    write!(
                        f,
                        "component {i}: {}: V={} E={} F={} χ={}",
                        c.surface,
                        c.vertices,
                        c.edges,
                        c.faces,
                        c.surface.euler_characteristic()
                    )?;
                }
                Ok(())
            }
            Description::Problems { diagnosis: d, .. } => {
                write!(f, "not a surface:")?;
                for g in &d.groups {
                    write!(f, "\n  {:?}: {}", g.kind, g.count)?;
                    if let Some(e) = g.examples.first() {
                        write!(f, " (first: {e:?})")?;
                    }
                }
                Ok(())
            }
        }
    }
}

/// Describes `mesh`: when its faces form a union of surfaces (closed or with boundary,
/// orientable or not), the topological type, counts and degrees of each component;
/// otherwise every problem that keeps it from being one, counted and located (a mesh that
/// is not a surface is a description, not an error). O(F log F).
///
/// # Errors
/// [`Error::Mesh`] with [`crate::BuildError::TooLarge`] for more vertices or faces than
/// the core's 32-bit ids hold; [`Error::Cancelled`].
///
/// # Example
/// ```
/// let d = contractible::describe(&contractible::gen::klein_bottle())?;
/// assert_eq!(d.components()[0].surface.euler_characteristic(), 0);
/// assert!(!d.components()[0].surface.is_orientable());
/// # Ok::<(), contractible::Error>(())
/// ```
pub fn describe(mesh: &TriMesh) -> Result<Description, Error> {
    describe_monitored(mesh, &Monitor::default())
}

/// [`describe`] reporting to (and cancelled by) `monitor`.
pub fn describe_monitored(mesh: &TriMesh, monitor: &Monitor) -> Result<Description, Error> {
    use crate::core::{BuildError, MAX_FACES, MAX_VERTICES};
    for (what, count, max) in [
        ("vertices", mesh.vertex_count, MAX_VERTICES),
        ("faces", mesh.faces.len(), MAX_FACES),
    ] {
        if count > max {
            return Err(Error::Mesh(BuildError::TooLarge { what, count, max }));
        }
    }
    monitor.step(Step::Build, 0, 0, mesh.faces.len())?;
    Ok(match ConedSurfaces::from_mesh(mesh) {
        Ok(s) => Description::Surfaces {
            components: s
                .components
                .iter()
                .map(ComponentDescription::of_coned)
                .collect(),
            dropped_vertices: s.dropped_vertices.len(),
        },
        Err(first) => Description::Problems {
            diagnosis: diagnose(mesh, 5),
            first,
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen;

    #[test]
    fn surfaces_are_described_and_the_rest_diagnosed() {
        let d = describe(&gen::torus7()).expect("not cancelled");
        assert!(d.is_closed());
        assert_eq!(d.components()[0].surface.orientable_genus(), Some(1));
        assert!(d.to_string().starts_with("component 0: "), "{d}");
        let open = TriMesh::combinatorial(4, gen::tetrahedron().faces[1..].to_vec());
        let d = describe(&open).expect("not cancelled");
        assert!(d.is_surface() && !d.is_closed());
        assert_eq!(d.components()[0].boundary_loop_lengths, vec![3]);
        let bowtie = TriMesh::combinatorial(5, vec![[0, 1, 2], [0, 3, 4]]);
        let d = describe(&bowtie).expect("not cancelled");
        assert!(!d.is_surface());
        assert!(d.to_string().contains("PinchedVertex"), "{d}");
    }
}
