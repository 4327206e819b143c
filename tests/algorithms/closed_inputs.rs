//! Generated closed surfaces for the sweeps that run over every closed mesh, alongside the
//! repository's real meshes (`tests/data/meshes`): the real meshes are all orientable and
//! few, so these add what breadth needs — several orientable genera and cross-cap
//! numbers, a brick with through-holes and one with cavities only, subdivisions,
//! a marching-tetrahedra surface, and one mesh of several components of mixed
//! orientability. Every input has positions (the simplifier needs them) and is known by
//! construction: the surface of each component is what its generator promises, not what
//! the code under test reports. Each component has at most about 5,000 faces, so that the
//! quadratic strategies stay quick.

use contractible::gen::{
    brick, brick_shaped, isosurface, klein_bottle, projective_plane6, random, subdivide,
    tetrahedron, torus7, BrickParams, BrickShape, Implicit, IsoParams, RandomParams, SurfaceKind,
    Tessellation,
};
use contractible::rng::Rng;
use contractible::{TriMesh, Triangulation};

use crate::common;

/// How many meshes [`closed_surfaces`] makes: twelve surfaces and one mesh of four.
pub const MESHES: usize = 13;

/// How many components they have in all.
pub const COMPONENTS: usize = 12 + 4;

/// A generated closed mesh and, per component, the surface its construction makes.
pub struct Generated {
    /// What it is, for failure messages.
    pub name: String,
    /// The mesh, with positions.
    pub mesh: TriMesh,
    /// The surface of each component, in no particular order.
    pub surfaces: Vec<SurfaceKind>,
}

impl Generated {
    /// Per component (χ, orientable), sorted: what an independent classification of the
    /// mesh must find.
    pub fn types(&self) -> Vec<(i64, bool)> {
        let mut t: Vec<_> = self
            .surfaces
            .iter()
            .map(|s| (s.euler_characteristic(), s.is_orientable()))
            .collect();
        t.sort_unstable();
        t
    }

    /// The number of components.
    pub fn components(&self) -> usize {
        self.surfaces.len()
    }
}

/// `t` with positions: seeded points of the unit cube, smoothed over the triangulation
/// so that the surface is crumpled rather than scattered.
fn with_positions(t: &Triangulation, seed: u64) -> TriMesh {
    let mut rng = Rng::new(seed ^ 0x00c0_ffee);
    let mut unit = || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
    let mut pos: Vec<[f64; 3]> = (0..t.vertex_capacity())
        .map(|_| [unit(), unit(), unit()])
        .collect();
    crate::harness::smooth_positions(t, &mut pos, 3);
    TriMesh::with_positions(pos, t.face_list())
}

/// `gen::random` of `surface` with positions ([`with_positions`]).
fn random_with_positions(surface: SurfaceKind, min_faces: usize, seed: u64) -> TriMesh {
    let t = random(&RandomParams {
        surface,
        min_faces,
        flip_percent: 30,
        seed,
    })
    .expect("a random surface within the limits");
    with_positions(&t, seed)
}

/// A combinatorial mesh (no positions: the Klein bottle and the projective plane do not
/// embed in R³) with positions ([`with_positions`]).
fn placed(mesh: &TriMesh, seed: u64) -> TriMesh {
    let t = Triangulation::from_faces(mesh.vertex_count, &mesh.faces).expect("a surface");
    with_positions(&t, seed)
}

/// The disjoint union of `parts`, each moved by 3 along `x` from the previous one.
pub fn union(parts: &[&TriMesh]) -> TriMesh {
    let (mut pos, mut faces) = (Vec::new(), Vec::new());
    for (k, m) in parts.iter().enumerate() {
        let n = pos.len() as u32;
        let shift = 3.0 * k as f64;
        let p = m.positions.as_deref().expect("positions");
        pos.extend(p.iter().map(|q| [q[0] + shift, q[1], q[2]]));
        faces.extend(m.faces.iter().map(|f| f.map(|v| v + n)));
    }
    TriMesh::with_positions(pos, faces)
}

/// The generated closed inputs (see the module documentation), in a fixed order.
pub fn closed_surfaces() -> Vec<Generated> {
    use SurfaceKind::{NonOrientable as N, Orientable as O};
    let mut out = Vec::new();
    let mut push = |name: &str, mesh: TriMesh, surfaces: Vec<SurfaceKind>| {
        out.push(Generated {
            name: name.to_string(),
            mesh,
            surfaces,
        });
    };
    for (k, (surface, faces)) in [
        (O(0), 2_000),
        (O(3), 2_000),
        (O(7), 3_000),
        (N(1), 1_500),
        (N(2), 2_000),
        (N(5), 3_000),
    ]
    .into_iter()
    .enumerate()
    {
        let mesh = random_with_positions(surface, faces, 900 + k as u64);
        push(&format!("random {surface:?}"), mesh, vec![surface]);
    }
    // Three of six sites are through-holes: genus 3.
    let holes = brick(&BrickParams {
        cavities: 6,
        holes: 3,
        resolution: 2,
    })
    .expect("valid brick parameters");
    push("brick 6 sites 3 holes", holes, vec![O(3)]);
    // Cavities only, pyramidal dents and a fan bottom: a sphere with high-degree vertices.
    let dents = brick_shaped(
        4,
        0,
        &BrickShape {
            site: 2,
            gap: 1,
            pit_segments: 0,
            tunnel_segments: 2,
            side_segments: 1,
            fan_bottom: true,
        },
    )
    .expect("valid brick parameters");
    push("brick 4 dents fan bottom", dents, vec![O(0)]);
    // Subdivision keeps the surface of the 9-vertex Klein bottle, the 7-vertex torus and
    // the 6-vertex projective plane.
    push(
        "Klein bottle subdivided 3 times",
        subdivide(&placed(&klein_bottle(), 1), 3).expect("a valid mesh within the limits"),
        vec![N(2)],
    );
    push(
        "torus7 subdivided 3 times",
        subdivide(&torus7(), 3).expect("a valid mesh within the limits"),
        vec![O(1)],
    );
    push(
        "RP2_6 subdivided 3 times",
        subdivide(&placed(&projective_plane6(), 2), 3).expect("a valid mesh within the limits"),
        vec![N(1)],
    );
    // A slab with two holes by marching tetrahedra, cells of about 0.2.
    let implicit = Implicit::GenusG { g: 2 };
    let (min, max) = implicit.default_box();
    let longest = (0..3).map(|k| max[k] - min[k]).fold(0.0, f64::max);
    let params = IsoParams::new(
        implicit,
        Tessellation::SixTetrahedra,
        (longest / 0.2).ceil() as u32,
    );
    push(
        "genus 2 isosurface",
        isosurface(&params).expect("a valid isosurface"),
        vec![O(2)],
    );
    // Four components in one mesh: orientable and not, of four genera.
    let parts = [
        random_with_positions(N(3), 800, 77),
        subdivide(&torus7(), 1).expect("a valid mesh within the limits"),
        tetrahedron(),
        brick(&BrickParams {
            cavities: 4,
            holes: 2,
            resolution: 1,
        })
        .expect("valid brick parameters"),
    ];
    push(
        "four components",
        union(&parts.iter().collect::<Vec<_>>()),
        vec![N(3), O(1), O(0), O(2)],
    );
    out
}

/// The components of `mesh` as triangulations (`Surfaces::from_mesh`), panicking with
/// `name` if it is not a closed surface.
pub fn components(mesh: &TriMesh, name: &str) -> Vec<Triangulation> {
    contractible::Surfaces::from_mesh(mesh)
        .unwrap_or_else(|e| panic!("{name}: {e}"))
        .components
        .into_iter()
        .map(|c| c.tri)
        .collect()
}

/// The number of faces of each connected component of `faces` (faces joined through a
/// shared edge), by union–find over the face list alone, in no particular order.
pub fn component_sizes(faces: &[[u32; 3]]) -> Vec<usize> {
    let mut by_edge = std::collections::HashMap::new();
    let mut parent: Vec<usize> = (0..faces.len()).collect();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            match by_edge.entry((a.min(b), a.max(b))) {
                std::collections::hash_map::Entry::Occupied(e) => {
                    common::union(&mut parent, i, *e.get());
                }
                std::collections::hash_map::Entry::Vacant(e) => {
                    e.insert(i);
                }
            }
        }
    }
    let mut size = std::collections::BTreeMap::new();
    for i in 0..faces.len() {
        *size.entry(common::find(&mut parent, i)).or_insert(0) += 1;
    }
    size.into_values().collect()
}

/// The generator promises what [`closed_surfaces`] records: the independent face-list
/// classifier of the fuzz harness finds, per component, the recorded χ and
/// orientability, and no boundary.
#[test]
fn generated_closed_surfaces_are_what_their_construction_makes() {
    let all = closed_surfaces();
    assert_eq!(all.len(), MESHES);
    assert_eq!(
        all.iter().map(Generated::components).sum::<usize>(),
        COMPONENTS
    );
    for g in &all {
        let topo = crate::harness::surface_topology(&g.mesh.faces)
            .unwrap_or_else(|e| panic!("{}: {e}", g.name));
        let mut found: Vec<(i64, bool)> = topo
            .components
            .iter()
            .map(|c| (c.euler, c.orientable))
            .collect();
        found.sort_unstable();
        assert_eq!(found, g.types(), "{}", g.name);
        assert_eq!(topo.boundary_edges, 0, "{}", g.name);
        assert_eq!(
            component_sizes(&g.mesh.faces).len(),
            g.components(),
            "{}",
            g.name
        );
        let pos = g.mesh.positions.as_deref().expect("positions");
        assert_eq!(pos.len(), g.mesh.vertex_count, "{}", g.name);
        assert!(
            component_sizes(&g.mesh.faces).iter().all(|&f| f <= 5_000),
            "{}: a component above 5,000 faces",
            g.name
        );
    }
}
