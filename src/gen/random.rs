//! Random closed triangulations of any surface, grown by random vertex splits.

use super::GenError;
use crate::core::{Triangulation, VertexId, MAX_FACES};
use crate::rng::Rng;

pub use crate::core::topology::SurfaceKind;

/// Parameters of [`random`].
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct RandomParams {
    /// The surface.
    pub surface: SurfaceKind,
    /// Grow until the triangulation has at least this many faces.
    pub min_faces: usize,
    /// After each split, flip a random edge (if flippable) with probability
    /// `flip_percent / 100`.
    pub flip_percent: u32,
    /// The seed of the documented stream in [`crate::rng`].
    pub seed: u64,
}

/// Connected sum of two face lists, in place: removes the *last* face of `a` and of `b`,
/// identifies their vertices in order and renumbers `b`'s other vertices after `a`'s.
/// The result is a simplicial closed surface with χ = χ(a) + χ(b) − 2: the only edges
/// between identified vertices are the glued triangle's, and no face survives on all
/// three of them. O(|b|) (appending, so a chain of `g` sums is O(g·|b|), not O(g²)).
fn connected_sum_into(a: &mut Vec<[u32; 3]>, a_vertices: u32, b: &[[u32; 3]], b_vertices: u32) {
    let Some(removed_a) = a.pop() else {
        return;
    };
    let removed_b = b[b.len() - 1];
    let mut map = vec![u32::MAX; b_vertices as usize];
    for k in 0..3 {
        map[removed_b[k] as usize] = removed_a[k];
    }
    let mut next = a_vertices;
    for m in map.iter_mut() {
        if *m == u32::MAX {
            *m = next;
            next += 1;
        }
    }
    // Glue b in with the opposite orientation of its removed face relative to a's, so an
    // orientable sum of consistently oriented pieces stays consistently oriented.
    a.extend(
        b[..b.len() - 1]
            .iter()
            .map(|f| [map[f[0] as usize], map[f[2] as usize], map[f[1] as usize]]),
    );
}

/// `faces` with faces reversed as needed so neighbours agree (when orientable).
fn consistently_oriented(faces: &[[u32; 3]], vertices: u32) -> Vec<[u32; 3]> {
    let t = Triangulation::from_faces(vertices as usize, faces).expect("valid seed piece");
    match t.orientation() {
        Some(flip) => faces
            .iter()
            .zip(flip)
            .map(|(f, r)| if r { [f[0], f[2], f[1]] } else { *f })
            .collect(),
        None => faces.to_vec(),
    }
}

/// The smallest seed triangulation this generator uses for `surface`: T4 for the sphere,
/// connected sums of `g` 7-vertex tori, or of `h` 6-vertex projective planes.
/// Vertices `4`, `7g − 3(g−1)`, `6h − 3(h−1)` respectively; faces `4`, `12g + 2`,
/// `8h + 2`.
///
/// # Errors
/// [`GenError::TooLarge`] if those counts exceed what the core holds.
pub fn seed_surface(surface: SurfaceKind) -> Result<Triangulation, GenError> {
    let (faces, vertices) = seed_counts(surface);
    GenError::check_size("seed surface", faces, vertices)?;
    let (mesh, count) = match surface {
        SurfaceKind::Orientable(0) => (super::tetrahedron(), 1),
        SurfaceKind::Orientable(g) => (super::torus7(), g),
        SurfaceKind::NonOrientable(h) => (super::projective_plane6(), h.max(1)),
    };
    let piece_v = mesh.vertex_count as u32;
    let piece = consistently_oriented(&mesh.faces, piece_v);
    let piece = &piece[..];
    let mut faces = piece.to_vec();
    let mut nv = piece_v;
    faces.reserve((count as usize - 1) * (piece.len() - 2));
    for _ in 1..count {
        connected_sum_into(&mut faces, nv, piece, piece_v);
        nv += piece_v - 3;
    }
    // Connected sums of simplicial surfaces are simplicial surfaces, and the counts fit
    // (checked above), so the build cannot fail; a failure would be reported, not hidden.
    Triangulation::from_faces(nv as usize, &faces).map_err(|_| GenError::TooLarge {
        what: "seed surface",
        unit: "faces",
        count: faces.len() as u128,
        max: MAX_FACES,
    })
}

/// The faces and vertices of [`seed_surface`]`(surface)`.
fn seed_counts(surface: SurfaceKind) -> (u128, u128) {
    match surface {
        SurfaceKind::Orientable(0) => (4, 4),
        SurfaceKind::Orientable(g) => (12 * g as u128 + 2, 4 * g as u128 + 3),
        SurfaceKind::NonOrientable(h) => {
            let h = h.max(1) as u128;
            (8 * h + 2, 3 * h + 3)
        }
    }
}

/// A random triangulation of `params.surface` with at least `params.min_faces` faces.
///
/// Starts from [`seed_surface`] and repeats until the face count is reached: pick a
/// vertex `u = below(V)` (ids are dense), list its link in star order from
/// `corner_of(u)`, pick `i = below(d)` and `j = (i + 1 + below(d − 1)) mod d`, split `u`
/// along link vertices `i` and `j` ([`Triangulation::split_vertex`]); then with
/// probability `flip_percent`% pick a face `below(F)` and slot `below(3)` and flip the edge
/// opposite that corner if it is flippable. Deterministic for a given `params`.
/// O(F · average degree).
///
/// # Errors
/// [`GenError::TooLarge`] if the seed surface or `min_faces` (plus the 2 faces a split
/// may overshoot by) exceeds what the core holds.
pub fn random(params: &RandomParams) -> Result<Triangulation, GenError> {
    if params.min_faces > MAX_FACES - 2 {
        return Err(GenError::TooLarge {
            what: "random",
            unit: "faces",
            count: params.min_faces as u128,
            max: MAX_FACES - 2,
        });
    }
    let mut tri = seed_surface(params.surface)?;
    let mut rng = Rng::new(params.seed);
    while tri.face_count() < params.min_faces {
        let u = VertexId(rng.index(tri.vertex_capacity()) as u32);
        let link: Vec<VertexId> = tri.link(u).collect();
        let d = link.len();
        let i = rng.index(d);
        let j = (i + 1 + rng.index(d - 1)) % d;
        // `link[i]` and `link[j]` are distinct link vertices of the live vertex `u`, and
        // the face count stays below MAX_FACES (checked above), so the split succeeds.
        if tri.split_vertex(u, link[i], link[j]).is_err() {
            break;
        }
        if params.flip_percent > 0 && rng.chance(params.flip_percent as u64, 100) {
            let f = crate::core::FaceId(rng.index(tri.face_capacity()) as u32);
            let c = f.corner(rng.index(3) as u32);
            let [a, b] = tri.edge_endpoints(c);
            if tri.is_flippable(a, b) {
                // Checked flippable: cannot fail.
                let _ = tri.flip(a, b);
            }
        }
    }
    Ok(tri)
}
