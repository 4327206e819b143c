//! `contractible`: topology-preserving edge contraction on triangulated surfaces,
//! orientable or not, closed or with boundary.
//!
//! Four tasks, each one call from a mesh to a verified result:
//!
//! - [`reduce`]: an *irreducible* triangulation of every component (no edge can be
//!   contracted without changing the surface), by Ramaswami–Siqueira's algorithm
//!   ([`irreducible::rs`]), Schipper's ([`irreducible::schipper`]) or the randomised
//!   brute force ([`irreducible::brute`]);
//! - [`quadrangulate`]: a quad mesh on the same vertices, by a perfect pairing of
//!   adjacent triangles ([`quad`]: the contraction/expansion algorithm of
//!   Lemos–Ramaswami–Siqueira, the greedy heuristics completed by augmenting paths,
//!   Edmonds, and Frink's reduction with the Diks–Stańczyk or
//!   Biedl–Bose–Demaine–Lubiw strategies);
//! - [`simplify()`]: every edge shorter than ε contracted without changing the topology
//!   (Pepko–Borisenko, [`simplify`](mod@simplify));
//! - [`decimate()`]: a face budget (a count or a fraction kept) or an error cap reached by
//!   quadric-error collapses that never change the topology, with a report of why it
//!   stopped and maps from the output back to the input ([`decimate`](mod@decimate)).
//!
//! and [`describe`], which says what a mesh is (each component's surface type) or lists
//! every reason it is not a surface.
//!
//! # Read, run, write
//!
//! ```
//! use contractible::{io, DecimateOptions, SimplifyOptions};
//!
//! # fn main() -> Result<(), contractible::Error> {
//! # let dir = std::env::temp_dir().join(format!("contractible-doc-{}", std::process::id()));
//! # std::fs::create_dir_all(&dir).expect("a temporary directory");
//! # let input = dir.join("sphere.off");
//! # io::write_mesh(&input, &contractible::gen::subdivide(&contractible::gen::icosahedron(), 2).expect("small"))?;
//! let mesh = io::read_tri_mesh(&input)?;
//! println!("{}", contractible::describe(&mesh)?); // component 0: sphere: V=162 …
//!
//! let irreducible = contractible::reduce(&mesh, &Default::default())?;
//! assert_eq!(irreducible.mesh.faces.len(), 4); // a sphere reduces to a tetrahedron
//! io::write_mesh(&dir.join("irreducible.off"), &irreducible.mesh)?;
//!
//! let quads = contractible::quadrangulate(&mesh, &Default::default())?;
//! io::write_mesh(&dir.join("quads.obj"), &quads.mesh)?;
//!
//! let simplified = contractible::simplify(&mesh, &SimplifyOptions::relative(0.05))?;
//! io::write_mesh(&dir.join("simplified.ply"), &simplified.mesh)?;
//!
//! let decimated = contractible::decimate(&mesh, &DecimateOptions::faces(100))?;
//! assert!(decimated.mesh.faces.len() <= 100); // and still a sphere
//! io::write_mesh(&dir.join("decimated.obj"), &decimated.mesh)?;
//! # std::fs::remove_dir_all(&dir).ok();
//! # Ok(())
//! # }
//! ```
//!
//! Every call validates its input and returns a located [`Error`] (face index, vertex,
//! file line) instead of panicking; checks its output independently of the algorithm
//! (the link condition by its definition, a from-scratch rebuild of the output, the
//! pairing against the face lists); handles several components at once; and reports
//! progress and honours cancellation through the options' [`Monitor`]. Outputs are
//! deterministic for a given input and options.
//!
//! # Layers
//!
//! - [`io`] reads and writes OFF, OBJ, PLY and STL (gzip too) into plain [`Mesh`]es;
//!   [`gen`] makes test surfaces.
//! - [`task`] holds the per-task calls above.
//! - The algorithms ([`irreducible`], [`quad`], [`simplify`](mod@simplify)) work on the
//!   core, [`Triangulation`]: a corner table over flat `u32` arrays that supports
//!   orientable and non-orientable surfaces alike, with the link condition (two
//!   independent implementations), contraction with exact undo, vertex splits and flips.
//! - [`spec`] holds the executable specifications checked in debug builds and with the
//!   `invariants` feature.
#![deny(unsafe_code)]
#![warn(missing_docs)]

pub mod check;
pub mod core;
pub mod decimate;
pub mod diagnose;
pub mod dyngraph;
pub mod gen;
pub mod io;
pub mod irreducible;
pub mod mesh;
pub mod names;
pub mod progress;
pub mod quad;
pub mod rng;
pub mod simplify;
pub mod spec;
pub mod task;

pub use crate::core::topology;
pub use crate::core::{
    BuildError, Component, ConedComponent, ConedSurfaces, ContractError, ContractionRecord, Corner,
    Edge, EdgeId, EdgeNumbering, FaceId, FlipError, FlipRecord, History, Journal, LinkTester,
    SplitError, Surfaces, Triangulation, UndoError, ValidationError, VertexId,
};
pub use mesh::{Mesh, QuadMesh, TriMesh};
pub use names::UnknownName;
pub use task::{
    decimate, describe, quadrangulate, reduce, simplify, verify_decimation, DecimateOptions,
    DecimateResult, Description, Eps, Error, MaxError, Monitor, QuadOptions, QuadResult,
    ReduceOptions, ReduceResult, SimplifyOptions, SimplifyResult,
};
pub use topology::SurfaceType;
