//! Marching tetrahedra: triangulated level sets of implicit functions sampled on a grid.
//!
//! # Guarantee
//!
//! [`isosurface`] samples an [`Implicit`] function `f` on a box split into
//! `cells[0] × cells[1] × cells[2]` cells, splits every cell into tetrahedra (the
//! [`Tessellation`]: the 6-tetrahedra Kuhn split, or the Chan–Purisima body-centred
//! tessellation), and returns the triangles of the level set `f = level` of the
//! tetrahedra, with positions. The output is a 2-manifold (every edge in one or two
//! faces, every vertex link a path or a cycle, no degenerate, duplicate or parallel
//! faces, every vertex used): closed where the level set stays inside the box, with
//! boundary on the box faces where the box cuts it. Every face is oriented with its
//! normal (right-hand rule) pointing from `f <= level` towards `f > level`: outward for
//! the sphere, torus and genus-g solids, towards the plane `z = 0` for the hyperboloid.
//!
//! Why it is a manifold: a surface vertex is a grid edge (a tetrahedron edge) with one
//! end inside and one outside, deduplicated by the edge's key, so all tetrahedra around
//! that edge share it. Each tetrahedron contributes one triangle or a quad split by an
//! interior diagonal; the segments it draws on a tetrahedron face are shared exactly by
//! the (one or two) tetrahedra on that face, because both tessellations are conforming
//! (face-to-face). So every surface edge on a shared tetrahedron face lies in two faces,
//! one on the box surface in one face, and a diagonal in exactly the two triangles of
//! its quad; the faces around a surface vertex follow the tetrahedra around its grid
//! edge, a cycle (interior grid edge) or a path (grid edge on the box surface). This is
//! also the paper's Theorem 3 (no edge `vu` with `|V(v) ∩ V(u)| > 2`).
//!
//! # Degeneracies (values exactly at the level)
//!
//! A sample is *inside* iff `f(p) <= level` and *outside* iff `f(p) > level`; there is no
//! third state, so a sample exactly at the level never produces a vertex on a grid
//! point shared by several grid edges (the classic source of non-manifold output). The
//! interpolation parameter `t = (level − f_in) / (f_out − f_in)` is in `[0, 1)` and is
//! clamped to `[CLAMP, 1 − CLAMP]` (`CLAMP = 1e-3`), so every surface vertex lies strictly
//! inside its grid edge: distinct vertices have distinct positions, and every triangle
//! has three non-collinear corners (its corners lie strictly inside three distinct edges
//! of a non-degenerate tetrahedron, not all in one face), hence positive area. No
//! triangle is ever dropped. The clamp moves a vertex by at most `CLAMP` × its grid
//! edge's length.
//!
//! # Orientation rule
//!
//! Tetrahedra are listed with positive orientation (checked exactly on the integer
//! lattice, two vertices swapped otherwise). For an even permutation `(i, j, k, l)` of
//! the tetrahedron's corners: one inside corner `i` gives the triangle
//! `(e_ij, e_ik, e_il)`; one outside corner `i` gives `(e_ij, e_il, e_ik)`; inside
//! `{i, j}` and outside `{k, l}` give the quad `(e_ik, e_il, e_jl, e_jk)`, split along
//! its shorter diagonal (ties: `e_ik–e_jl`). Each is the orientation whose normal points
//! to the outside corners (a direct computation on the standard simplex, preserved by
//! orientation-preserving affine maps).
//!
//! # Complexity, memory, determinism
//!
//! O(cells) time (f evaluated once per sample point), O(cells per slab + output)
//! memory: the box is swept in slabs of constant `z`, keeping three planes of samples.
//! Vertices are numbered in order of first use along that sweep and faces in sweep
//! order, so the same parameters give the same mesh, bit for bit.

use std::collections::HashMap;

use crate::core::{MAX_FACES, MAX_VERTICES};
use crate::mesh::TriMesh;

/// Interpolation parameters are clamped to `[CLAMP, 1 − CLAMP]` (see the module doc).
pub const CLAMP: f64 = 1e-3;

/// An implicit surface `f(p) = level` (`level` is 0 for the presets). Every variant
/// documents `f`, which side is inside (`f <= level`) and its default box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Implicit {
    /// `f = x² + y² + z² − radius²`; inside is the ball. Box: `±1.25·radius`.
    Sphere {
        /// Radius (> 0).
        radius: f64,
    },
    /// `f = (√(x² + y²) − major)² + z² − minor²`, the torus around the `z` axis; inside
    /// is the solid torus. Box: `±1.2·(major + minor)` in `x, y`, `±1.5·minor` in `z`.
    Torus {
        /// Distance from the axis to the tube's centre (`major > minor > 0`).
        major: f64,
        /// Tube radius.
        minor: f64,
    },
    /// A flat rounded slab pierced by `g` round holes in a row: genus `g` (a sphere for
    /// `g = 0`). With hole centres `c_i = (2i, 0, 0)` (`i < g`), `s` the segment from
    /// `c_0` to `c_{g−1}` (`(0,0,0)` alone when `g <= 1`) and `d` the distance in the
    /// `xy` plane from `(x, y)` to `s`:
    /// `f = max(√(d² + (z/0.5)²) − 1, max_i (0.45 − |(x, y) − c_i|))`. Inside is the
    /// slab minus the holes. Adjacent holes are 1.1 apart, and 0.55 from the rim. Box:
    /// `x ∈ [−1.25, 2(g−1) + 1.25]`, `y ∈ ±1.25`, `z ∈ ±0.625`.
    GenusG {
        /// The genus (number of holes), at most [`MAX_GENUS`].
        g: u32,
    },
    /// `f = x² + y² − z² + c`, the two-sheeted hyperboloid `z = ±√(x² + y² + c)`;
    /// inside (`f <= 0`) is the two convex caps `|z| >= √(x² + y² + c)`. Box:
    /// `x, y ∈ ±half_width`, `z ∈ ±half_height` (`half_height > √c`), which cuts both
    /// sheets: two discs with boundary on the box.
    TwoSheetHyperboloid {
        /// The constant `c > 0` (the sheets' apexes are at `z = ±√c`).
        c: f64,
        /// Half the box's extent in `x` and `y`.
        half_width: f64,
        /// Half the box's extent in `z`.
        half_height: f64,
    },
}

/// The largest genus [`Implicit::GenusG`] accepts (it only bounds the box's size).
pub const MAX_GENUS: u32 = 1 << 16;

/// How the cells are split into tetrahedra. Both are conforming (face-to-face) over
/// the whole box.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub enum Tessellation {
    /// Every cube into 6 tetrahedra around its main diagonal (Kuhn/Freudenthal): the
    /// paths `p, p + e_a, p + e_a + e_b, p + (1,1,1)` over the 6 orders `(a, b, c)` of
    /// the axes. Samples: the grid corners.
    SixTetrahedra,
    /// Chan–Purisima body-centred tessellation: samples at the grid corners and the cube
    /// centres; for every face shared by two cubes, 4 tetrahedra (the two centres and an
    /// edge of the face), 12 per cube. A cube face on the box surface uses its centre
    /// (also a sample) in place of the missing neighbour's centre, so the tessellation
    /// fills the box exactly.
    BodyCentred,
}

/// What [`isosurface`] samples, on which grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IsoParams {
    /// The function.
    pub implicit: Implicit,
    /// The split into tetrahedra.
    pub tessellation: Tessellation,
    /// Cells along `x`, `y`, `z` (each >= 1).
    pub cells: [u32; 3],
    /// The box's lower corner.
    pub min: [f64; 3],
    /// The box's upper corner (> `min` on every axis).
    pub max: [f64; 3],
    /// The iso-level.
    pub level: f64,
}

/// Why [`isosurface`] cannot build a mesh from the given parameters.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum IsoError {
    /// A parameter of the implicit function is out of its documented range.
    #[error("{surface}: {what} (got {value})")]
    BadSurface {
        /// The variant.
        surface: &'static str,
        /// The violated requirement.
        what: &'static str,
        /// The offending value.
        value: f64,
    },
    /// An axis has zero cells.
    #[error("axis {axis}: the grid needs at least one cell")]
    NoCells {
        /// 0, 1 or 2 for x, y, z.
        axis: usize,
    },
    /// The box is empty, inverted or not finite on an axis.
    #[error("axis {axis}: box [{min}, {max}] must be finite with min < max")]
    BadBox {
        /// 0, 1 or 2 for x, y, z.
        axis: usize,
        /// Lower bound given.
        min: f64,
        /// Upper bound given.
        max: f64,
    },
    /// The iso-level is NaN or infinite.
    #[error("the iso-level must be finite (got {0})")]
    BadLevel(f64),
    /// The grid has more than 2²⁰ cells on an axis, or more than 2²² cells in a layer
    /// of constant `z` (the memory of a slab's samples).
    #[error("grid of {cells:?} cells is too large (at most 2^20 per axis, 2^22 per z layer)")]
    GridTooLarge {
        /// The cells given.
        cells: [u32; 3],
    },
    /// The output would exceed the triangulation's index range.
    #[error("more than {max} {what}: reduce the resolution")]
    TooLarge {
        /// `"vertices"` or `"faces"`.
        what: &'static str,
        /// The limit.
        max: usize,
    },
    /// No grid edge crosses the level: the level set misses the box's samples.
    #[error("the level set does not cross the sampling grid (no triangles)")]
    Empty,
}

impl Implicit {
    /// `f(p)` as documented on each variant.
    pub fn eval(&self, p: [f64; 3]) -> f64 {
        let [x, y, z] = p;
        match *self {
            Implicit::Sphere { radius } => x * x + y * y + z * z - radius * radius,
            Implicit::Torus { major, minor } => {
                let q = (x * x + y * y).sqrt() - major;
                q * q + z * z - minor * minor
            }
            Implicit::GenusG { g } => {
                let last = f64::from(g.max(1) - 1) * GENUS_PITCH;
                // Distance in the xy plane to the segment [0, last] on the x axis.
                let dx = x - x.clamp(0.0, last);
                let slab = (dx * dx + y * y + (z / GENUS_THICKNESS).powi(2)).sqrt() - 1.0;
                let mut f = slab;
                if g > 0 {
                    // Only the nearest hole matters for the max: the holes are disjoint.
                    let i = (x / GENUS_PITCH).round().clamp(0.0, f64::from(g - 1));
                    let hx = x - i * GENUS_PITCH;
                    f = f.max(GENUS_HOLE - (hx * hx + y * y).sqrt());
                }
                f
            }
            Implicit::TwoSheetHyperboloid { c, .. } => x * x + y * y - z * z + c,
        }
    }

    /// Checks the documented parameter ranges.
    pub fn validate(&self) -> Result<(), IsoError> {
        let bad = |surface, what, value| {
            Err(IsoError::BadSurface {
                surface,
                what,
                value,
            })
        };
        match *self {
            Implicit::Sphere { radius } => {
                if !(radius.is_finite() && radius > 0.0) {
                    return bad("sphere", "radius must be finite and > 0", radius);
                }
            }
            Implicit::Torus { major, minor } => {
                if !(minor.is_finite() && minor > 0.0) {
                    return bad("torus", "minor radius must be finite and > 0", minor);
                }
                if !(major.is_finite() && major > minor) {
                    return bad("torus", "major radius must be finite and > minor", major);
                }
            }
            Implicit::GenusG { g } => {
                if g > MAX_GENUS {
                    return bad("genus", "g must be at most 65536", f64::from(g));
                }
            }
            Implicit::TwoSheetHyperboloid {
                c,
                half_width,
                half_height,
            } => {
                if !(c.is_finite() && c > 0.0) {
                    return bad("hyperboloid", "c must be finite and > 0", c);
                }
                if !(half_width.is_finite() && half_width > 0.0) {
                    return bad(
                        "hyperboloid",
                        "half_width must be finite and > 0",
                        half_width,
                    );
                }
                if !(half_height.is_finite() && half_height * half_height > c) {
                    return bad("hyperboloid", "half_height must exceed √c", half_height);
                }
            }
        }
        Ok(())
    }

    /// The default sampling box `(min, max)` documented on each variant.
    pub fn default_box(&self) -> ([f64; 3], [f64; 3]) {
        match *self {
            Implicit::Sphere { radius } => {
                let a = 1.25 * radius;
                ([-a; 3], [a; 3])
            }
            Implicit::Torus { major, minor } => {
                let a = 1.2 * (major + minor);
                let h = 1.5 * minor;
                ([-a, -a, -h], [a, a, h])
            }
            Implicit::GenusG { g } => {
                let last = f64::from(g.max(1) - 1) * GENUS_PITCH;
                let h = 1.25 * GENUS_THICKNESS;
                ([-1.25, -1.25, -h], [last + 1.25, 1.25, h])
            }
            Implicit::TwoSheetHyperboloid {
                half_width,
                half_height,
                ..
            } => (
                [-half_width, -half_width, -half_height],
                [half_width, half_width, half_height],
            ),
        }
    }
}

/// Distance between adjacent hole centres of [`Implicit::GenusG`].
const GENUS_PITCH: f64 = 2.0;
/// Hole radius of [`Implicit::GenusG`].
const GENUS_HOLE: f64 = 0.45;
/// Half-thickness of [`Implicit::GenusG`]'s slab.
const GENUS_THICKNESS: f64 = 0.5;

impl IsoParams {
    /// The implicit's default box at level 0, with `resolution` cells along its longest
    /// axis and on the other axes the count that keeps the cells closest to cubes
    /// (rounded, at least 1).
    pub fn new(implicit: Implicit, tessellation: Tessellation, resolution: u32) -> Self {
        let (min, max) = implicit.default_box();
        let ext = [max[0] - min[0], max[1] - min[1], max[2] - min[2]];
        let longest = ext[0].max(ext[1]).max(ext[2]);
        let cells = ext.map(|e| {
            let n = (f64::from(resolution) * e / longest).round();
            // `as` saturates; the ratio is <= 1, so n <= resolution.
            (n as u32).max(1)
        });
        IsoParams {
            implicit,
            tessellation,
            cells,
            min,
            max,
            level: 0.0,
        }
    }
}

/// `params` with its box moved by `(1/3, 2/3, 3/3)·fraction` of a cell along `x, y, z`:
/// breaks the mirror symmetries of a centred surface, so that vertex counts are not
/// all multiples of 8 (used by the presets to reach exact target sizes).
fn shifted(mut p: IsoParams, fraction: f64) -> IsoParams {
    for k in 0..3 {
        let cell = (p.max[k] - p.min[k]) / f64::from(p.cells[k]);
        let d = fraction * cell * (k as f64 + 1.0) / 3.0;
        p.min[k] += d;
        p.max[k] += d;
    }
    p
}

/// The torus of the paper's Table 1 (Pepko–Borisenko: 16,772 vertices, 33,544 faces)
/// as a closed genus-1 surface, with `resolution` cells across (the paper's size at
/// the preset's own resolution, see [`paper_torus`]).
fn torus_preset(tessellation: Tessellation, resolution: u32) -> IsoParams {
    // The grid is that of the default box of the torus (1, 0.5); the minor radius was
    // tuned (on that grid) to give the paper's vertex count exactly.
    let grid = IsoParams::new(
        Implicit::Torus {
            major: 1.0,
            minor: 0.5,
        },
        tessellation,
        resolution,
    );
    match tessellation {
        Tessellation::SixTetrahedra => IsoParams {
            implicit: Implicit::Torus {
                major: 1.0,
                minor: 0.48896,
            },
            ..grid
        },
        Tessellation::BodyCentred => shifted(
            IsoParams {
                implicit: Implicit::Torus {
                    major: 1.0,
                    minor: 0.50938,
                },
                ..grid
            },
            0.1,
        ),
    }
}

/// The two-sheeted hyperboloid of the paper's Table 1, open where the box's top and
/// bottom faces cut it, with `resolution` cells along `x` and `y`.
fn hyperboloid_preset(tessellation: Tessellation, resolution: u32) -> IsoParams {
    // `c` and the radius `rho` of the boundary circles (the box's half-height is
    // √(rho² + c)) were tuned to give the paper's vertex and face counts; a large `c`
    // makes the sheets flat caps, which is what the paper's ratio of vertices to
    // boundary edges needs with these tessellations.
    let (c, rho): (f64, f64) = match tessellation {
        Tessellation::SixTetrahedra => (20.0, 0.90935),
        Tessellation::BodyCentred => (19.75, 0.9296),
    };
    let half_height = (rho * rho + c).sqrt();
    let implicit = Implicit::TwoSheetHyperboloid {
        c,
        half_width: 1.0,
        half_height,
    };
    let mut p = IsoParams::new(implicit, tessellation, resolution);
    let n = f64::from(resolution);
    // Square cells in the xy plane, about square in z (saturating `as`: n·h is small).
    p.cells = [resolution, resolution, (n * half_height).round() as u32];
    shifted(p, 0.1)
}

/// The torus of the paper's Table 1 (Pepko–Borisenko): a closed torus of exactly
/// 16,772 vertices and 33,544 faces with either tessellation.
///
/// Six tetrahedra: torus (1, 0.48896), box `±1.8 × ±1.8 × ±0.75`, 50 × 50 × 21 cells.
/// Body-centred: torus (1, 0.50938), the same box moved by (1/30, 2/30, 3/30) of a
/// cell, 41 × 41 × 17 cells. (The paper gives no grid or function; these were found by
/// a search over the radius and the resolution.)
pub fn paper_torus(tessellation: Tessellation) -> IsoParams {
    let n = match tessellation {
        Tessellation::SixTetrahedra => 50,
        Tessellation::BodyCentred => 41,
    };
    torus_preset(tessellation, n)
}

/// The two-sheeted hyperboloid of the paper's Table 1 (56,288 vertices, 111,140
/// faces): two discs with boundary on the box.
///
/// Body-centred (exact: 56,288 vertices, 111,140 faces, 1,432 boundary edges):
/// `x² + y² − z² + 19.75`, box `±1 × ±1 × ±√(0.9296² + 19.75)` moved by
/// (1/30, 2/30, 3/30) of a cell, 80 × 80 × 363 cells. Six tetrahedra (56,288 vertices,
/// 111,332 faces: the six-tetrahedra split puts fewer edges on a boundary circle, so
/// both counts cannot match at once): `c = 20`, `rho = 0.90935`, 100 × 100 × 456 cells.
pub fn paper_hyperboloid(tessellation: Tessellation) -> IsoParams {
    let n = match tessellation {
        Tessellation::SixTetrahedra => 100,
        Tessellation::BodyCentred => 80,
    };
    hyperboloid_preset(tessellation, n)
}

/// The paper's torus at a finer grid, over 1,000,000 triangles (for benchmarks).
pub fn large_torus(tessellation: Tessellation) -> IsoParams {
    let n = match tessellation {
        Tessellation::SixTetrahedra => LARGE_TORUS_SIX,
        Tessellation::BodyCentred => LARGE_TORUS_BCC,
    };
    torus_preset(tessellation, n)
}

/// The paper's hyperboloid at a finer grid, over 1,000,000 triangles (for benchmarks).
pub fn large_hyperboloid(tessellation: Tessellation) -> IsoParams {
    let n = match tessellation {
        Tessellation::SixTetrahedra => LARGE_HYPERBOLOID_SIX,
        Tessellation::BodyCentred => LARGE_HYPERBOLOID_BCC,
    };
    hyperboloid_preset(tessellation, n)
}

const LARGE_TORUS_SIX: u32 = 280;
const LARGE_TORUS_BCC: u32 = 230;
const LARGE_HYPERBOLOID_SIX: u32 = 310;
const LARGE_HYPERBOLOID_BCC: u32 = 250;

/// A sample point in doubled lattice coordinates: corners are all even, cube centres
/// all odd, centres of cube faces on the box surface have one coordinate `0` or `2n`
/// and two odd ones.
type Lattice = [u32; 3];

/// The 6 Kuhn tetrahedra of the cube at doubled origin `(0,0,0)` (side 2).
const SIX: [[Lattice; 4]; 6] = {
    const fn path(a: usize, b: usize) -> [Lattice; 4] {
        let mut p1 = [0u32; 3];
        p1[a] = 2;
        let mut p2 = p1;
        p2[b] = 2;
        [[0, 0, 0], p1, p2, [2, 2, 2]]
    }
    [
        path(0, 1),
        path(0, 2),
        path(1, 0),
        path(1, 2),
        path(2, 0),
        path(2, 1),
    ]
};

/// The grid and the samples of the current slab.
struct Grid {
    implicit: Implicit,
    level: f64,
    /// Doubled extents `2·cells`.
    ext: [u32; 3],
    min: [f64; 3],
    /// Half the cell size per axis (the step of one doubled unit).
    half: [f64; 3],
    body_centred: bool,
    /// Samples of the doubled planes `z = 2k − 1 ..= 2k + 2` of the current slab `k`
    /// (the centres of the cubes below and in the slab, and the slab's corner planes).
    planes: [Vec<f64>; 4],
    /// The current slab.
    slab: u32,
}

impl Grid {
    fn position(&self, p: Lattice) -> [f64; 3] {
        [0, 1, 2].map(|a| self.min[a] + f64::from(p[a]) * self.half[a])
    }

    /// Whether `p` is a sample point of the tessellation (see [`Lattice`]).
    fn is_sample(&self, p: Lattice) -> bool {
        let odd = p.iter().filter(|&&c| c % 2 == 1).count();
        match odd {
            0 => true,
            3 => self.body_centred,
            2 => {
                self.body_centred
                    && (0..3).any(|a| p[a] % 2 == 0 && (p[a] == 0 || p[a] == self.ext[a]))
            }
            _ => false,
        }
    }

    fn fill_plane(&mut self, slot: usize, z: u32) {
        let w = self.ext[0] as usize + 1;
        let mut plane = std::mem::take(&mut self.planes[slot]);
        for y in 0..=self.ext[1] {
            for x in 0..=self.ext[0] {
                let p = [x, y, z];
                if self.is_sample(p) {
                    plane[y as usize * w + x as usize] = self.implicit.eval(self.position(p));
                }
            }
        }
        self.planes[slot] = plane;
    }

    /// Loads slab `k` (doubled `z` from `2k − 1` to `2k + 2`), reusing the previous
    /// slab's top two planes.
    fn load_slab(&mut self, k: u32) {
        if k == 0 {
            self.fill_plane(1, 0);
        } else {
            self.planes.swap(0, 2);
            self.planes.swap(1, 3);
        }
        self.slab = k;
        self.fill_plane(2, 2 * k + 1);
        self.fill_plane(3, 2 * k + 2);
    }

    /// The sample at `p`, which must lie in the current slab's window.
    fn value(&self, p: Lattice) -> f64 {
        let w = self.ext[0] as usize + 1;
        let slot = (p[2] + 1 - 2 * self.slab) as usize;
        self.planes[slot][p[1] as usize * w + p[0] as usize]
    }

    /// A key unique to the sample point.
    fn key(&self, p: Lattice) -> u64 {
        let w = u64::from(self.ext[0]) + 1;
        let h = u64::from(self.ext[1]) + 1;
        u64::from(p[0]) + w * (u64::from(p[1]) + h * u64::from(p[2]))
    }
}

/// Sign of the orientation determinant of a lattice tetrahedron (exact).
fn orientation(t: &[Lattice; 4]) -> i64 {
    let d = |i: usize| [0, 1, 2].map(|a| i64::from(t[i][a]) - i64::from(t[0][a]));
    let (u, v, w) = (d(1), d(2), d(3));
    u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0])
}

/// The even permutation of `0..4` starting with `i` (the Klein four-group).
const EVEN_FROM: [[usize; 4]; 4] = [[0, 1, 2, 3], [1, 0, 3, 2], [2, 3, 0, 1], [3, 2, 1, 0]];

struct Builder {
    positions: Vec<[f64; 3]>,
    faces: Vec<[u32; 3]>,
    /// Surface vertex of each crossed grid edge, keyed by its (inside, outside) samples.
    vertex_of: HashMap<(u64, u64), u32>,
}

impl Builder {
    /// The surface vertex on the grid edge from inside sample `a` to outside sample `b`.
    fn vertex(&mut self, grid: &Grid, a: Lattice, b: Lattice) -> Result<u32, IsoError> {
        let key = (grid.key(a), grid.key(b));
        if let Some(&v) = self.vertex_of.get(&key) {
            return Ok(v);
        }
        let (fa, fb) = (grid.value(a), grid.value(b));
        // fa <= level < fb, so the denominator is positive and t is in [0, 1).
        let t = ((grid.level - fa) / (fb - fa)).clamp(CLAMP, 1.0 - CLAMP);
        let (pa, pb) = (grid.position(a), grid.position(b));
        let p = [0, 1, 2].map(|i| pa[i] + t * (pb[i] - pa[i]));
        if self.positions.len() >= MAX_VERTICES {
            return Err(IsoError::TooLarge {
                what: "vertices",
                max: MAX_VERTICES,
            });
        }
        let v = self.positions.len() as u32;
        self.positions.push(p);
        self.vertex_of.insert(key, v);
        Ok(v)
    }

    fn face(&mut self, f: [u32; 3]) -> Result<(), IsoError> {
        if self.faces.len() >= MAX_FACES {
            return Err(IsoError::TooLarge {
                what: "faces",
                max: MAX_FACES,
            });
        }
        self.faces.push(f);
        Ok(())
    }

    fn dist2(&self, a: u32, b: u32) -> f64 {
        let (p, q) = (self.positions[a as usize], self.positions[b as usize]);
        (0..3).map(|i| (p[i] - q[i]).powi(2)).sum()
    }

    /// Emits the level set of one positively oriented tetrahedron.
    fn tetrahedron(&mut self, grid: &Grid, t: &[Lattice; 4]) -> Result<(), IsoError> {
        let inside = t.map(|p| grid.value(p) <= grid.level);
        let n_in = inside.iter().filter(|&&b| b).count();
        match n_in {
            1 | 3 => {
                // The lone corner i and the even permutation (i, j, k, l).
                let i = (0..4).find(|&i| inside[i] == (n_in == 1)).unwrap_or(0);
                let [_, j, k, l] = EVEN_FROM[i];
                let e = |b: &mut Self, o: usize| {
                    if n_in == 1 {
                        b.vertex(grid, t[i], t[o])
                    } else {
                        b.vertex(grid, t[o], t[i])
                    }
                };
                let (ej, ek, el) = (e(self, j)?, e(self, k)?, e(self, l)?);
                if n_in == 1 {
                    self.face([ej, ek, el])
                } else {
                    self.face([ej, el, ek])
                }
            }
            2 => {
                let ins: Vec<usize> = (0..4).filter(|&v| inside[v]).collect();
                let outs: Vec<usize> = (0..4).filter(|&v| !inside[v]).collect();
                let (i, j) = (ins[0], ins[1]);
                let (mut k, mut l) = (outs[0], outs[1]);
                if !is_even([i, j, k, l]) {
                    std::mem::swap(&mut k, &mut l);
                }
                let eik = self.vertex(grid, t[i], t[k])?;
                let eil = self.vertex(grid, t[i], t[l])?;
                let ejl = self.vertex(grid, t[j], t[l])?;
                let ejk = self.vertex(grid, t[j], t[k])?;
                // Quad (eik, eil, ejl, ejk): split along the shorter diagonal.
                if self.dist2(eil, ejk) < self.dist2(eik, ejl) {
                    self.face([eik, eil, ejk])?;
                    self.face([eil, ejl, ejk])
                } else {
                    self.face([eik, eil, ejl])?;
                    self.face([eik, ejl, ejk])
                }
            }
            _ => Ok(()),
        }
    }
}

fn is_even(p: [usize; 4]) -> bool {
    let mut inversions = 0;
    for a in 0..4 {
        for b in a + 1..4 {
            if p[a] > p[b] {
                inversions += 1;
            }
        }
    }
    inversions % 2 == 0
}

/// Pushes `t`, positively oriented (two corners swapped if needed), to `out`.
fn push_oriented(mut t: [Lattice; 4], out: &mut Vec<[Lattice; 4]>) {
    if orientation(&t) < 0 {
        t.swap(2, 3);
    }
    out.push(t);
}

/// The tetrahedra of cube `(i, j, k)` (see [`Tessellation`]), positively oriented, or
/// none when every sample they use is on the same side of the level (they could not
/// contribute a triangle; skipping them only saves time).
fn cube_tetrahedra(grid: &Grid, cube: [u32; 3], out: &mut Vec<[Lattice; 4]>) {
    out.clear();
    let base = cube.map(|c| 2 * c);
    let side = |p: Lattice| grid.value(p) <= grid.level;
    let corner_side = side(base);
    let mut uniform = (0..8).all(|m: u32| {
        let p = [0, 1, 2].map(|a| base[a] + 2 * ((m >> a) & 1));
        side(p) == corner_side
    });
    if !grid.body_centred {
        if !uniform {
            for t in &SIX {
                push_oriented(t.map(|p| [0, 1, 2].map(|a| base[a] + p[a])), out);
            }
        }
        return;
    }
    let centre = base.map(|c| c + 1);
    uniform &= side(centre) == corner_side;
    // The (axis, face coordinate, apex) of every square pyramid pair this cube owns.
    // Each interior cube face belongs to one of its two cubes: along x and y the lower
    // cube owns it (its +a face), along z the upper one (its −z face), so that a slab's
    // tetrahedra only reach the centres of the cubes below it. Faces on the box surface
    // use their own centre as apex.
    let mut faces = [(0usize, 0u32, [0u32; 3]); 6];
    let mut nfaces = 0;
    for a in 0..3 {
        let box_face = |fa: u32| {
            let mut apex = centre;
            apex[a] = fa;
            (a, fa, apex)
        };
        let mut push = |f: (usize, u32, Lattice)| {
            faces[nfaces] = f;
            nfaces += 1;
        };
        if a < 2 {
            let fa = base[a] + 2;
            if fa < grid.ext[a] {
                let mut apex = centre;
                apex[a] += 2;
                push((a, fa, apex));
            } else {
                push(box_face(fa));
            }
            if cube[a] == 0 {
                push(box_face(0));
            }
        } else {
            let fa = base[a];
            if fa > 0 {
                let mut apex = centre;
                apex[a] -= 2;
                push((a, fa, apex));
            } else {
                push(box_face(0));
            }
            if base[a] + 2 == grid.ext[a] {
                push(box_face(grid.ext[a]));
            }
        }
    }
    let faces = &faces[..nfaces];
    if uniform && faces.iter().all(|&(_, _, apex)| side(apex) == corner_side) {
        return;
    }
    for &(a, fa, apex) in faces {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        let corner = |db: u32, dc: u32| {
            let mut p = base;
            p[a] = fa;
            p[b] += db;
            p[c] += dc;
            p
        };
        let ring = [corner(0, 0), corner(2, 0), corner(2, 2), corner(0, 2)];
        for e in 0..4 {
            push_oriented([centre, apex, ring[e], ring[(e + 1) % 4]], out);
        }
    }
}

/// The marching-tetrahedra surface of `params` (see the module doc for the guarantees,
/// the inside/outside convention and the orientation). Errors name the offending
/// parameter.
pub fn isosurface(params: &IsoParams) -> Result<TriMesh, IsoError> {
    params.implicit.validate()?;
    for a in 0..3 {
        if params.cells[a] == 0 {
            return Err(IsoError::NoCells { axis: a });
        }
        let (lo, hi) = (params.min[a], params.max[a]);
        if !(lo.is_finite() && hi.is_finite() && lo < hi) {
            return Err(IsoError::BadBox {
                axis: a,
                min: lo,
                max: hi,
            });
        }
    }
    if !params.level.is_finite() {
        return Err(IsoError::BadLevel(params.level));
    }
    // Sample keys (2n + 1)³ must fit u64, and the four sample planes of a slab (about
    // 4·4·cells_x·cells_y values) must stay within a few hundred MB.
    let too_large = params.cells.iter().any(|&n| n > (1 << 20))
        || (u64::from(params.cells[0]) * u64::from(params.cells[1])) > (1 << 22);
    if too_large {
        return Err(IsoError::GridTooLarge {
            cells: params.cells,
        });
    }
    let ext = params.cells.map(|n| 2 * n);
    let plane_len = (ext[0] as usize + 1) * (ext[1] as usize + 1);
    let mut grid = Grid {
        implicit: params.implicit,
        level: params.level,
        ext,
        min: params.min,
        half: [0, 1, 2].map(|a| (params.max[a] - params.min[a]) / f64::from(ext[a])),
        body_centred: params.tessellation == Tessellation::BodyCentred,
        planes: [
            vec![0.0; plane_len],
            vec![0.0; plane_len],
            vec![0.0; plane_len],
            vec![0.0; plane_len],
        ],
        slab: 0,
    };
    let mut b = Builder {
        positions: Vec::new(),
        faces: Vec::new(),
        vertex_of: HashMap::new(),
    };
    let mut tets = Vec::with_capacity(24);
    for k in 0..params.cells[2] {
        grid.load_slab(k);
        for j in 0..params.cells[1] {
            for i in 0..params.cells[0] {
                cube_tetrahedra(&grid, [i, j, k], &mut tets);
                for t in &tets {
                    b.tetrahedron(&grid, t)?;
                }
            }
        }
        // The next slab's tetrahedra have samples at doubled z >= 2k + 1 only; forget
        // the grid edges reaching below, to bound memory.
        let w = u64::from(ext[0]) + 1;
        let h = u64::from(ext[1]) + 1;
        let keep_from = w * h * u64::from(2 * k + 1);
        b.vertex_of
            .retain(|&(p, q), _| p >= keep_from && q >= keep_from);
    }
    if b.faces.is_empty() {
        return Err(IsoError::Empty);
    }
    Ok(TriMesh::with_positions(b.positions, b.faces))
}
