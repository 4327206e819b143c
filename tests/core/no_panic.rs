//! No public entry point panics, whatever it is given: random face lists (out-of-range
//! and repeated indices, duplicate faces, non-manifold edges, nothing at all), damaged
//! closed surfaces, huge vertex counts and sizes, NaN and infinite positions, every
//! algorithm and option value (NaN, negative and huge ε included), cancelled monitors,
//! and random bytes to the readers. Each call must return (a value or an error); a
//! panic fails the property and proptest shrinks it to a minimal input.

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use contractible::gen::{self, RandomParams, SurfaceKind};
use contractible::io;
use contractible::simplify::{Mode, Position, Side};
use contractible::{
    describe, irreducible, quad, quadrangulate, reduce, simplify, ConedSurfaces, Eps, Monitor,
    QuadOptions, ReduceOptions, SimplifyOptions, Surfaces, TriMesh, Triangulation,
};
use proptest::prelude::*;

/// A face list on `0..n` with indices up to `n + 1` (so some are out of range).
fn face_soup() -> impl Strategy<Value = TriMesh> {
    (0usize..10).prop_flat_map(|n| {
        let index = 0u32..(n as u32 + 2);
        (
            Just(n),
            prop::collection::vec([index.clone(), index.clone(), index], 0..20),
            prop::option::of(prop::collection::vec(coordinate3(), n..=n)),
        )
            .prop_map(|(n, faces, positions)| TriMesh {
                vertex_count: n,
                positions,
                faces,
            })
    })
}

/// A coordinate, occasionally NaN or infinite.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -10.0f64..10.0,
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
    ]
}

fn coordinate3() -> impl Strategy<Value = [f64; 3]> {
    [coordinate(), coordinate(), coordinate()]
}

/// A closed surface (random, small), damaged or not: a face removed, duplicated or
/// with a corner replaced; positions from a hash of the vertex, some NaN.
fn damaged_surface() -> impl Strategy<Value = TriMesh> {
    (
        0u32..3,
        any::<bool>(),
        8usize..80,
        any::<u64>(),
        0u8..5,
        any::<u32>(),
        any::<bool>(),
    )
        .prop_map(|(g, orientable, faces, seed, damage, at, nan)| {
            let surface = if orientable {
                SurfaceKind::Orientable(g)
            } else {
                SurfaceKind::NonOrientable(g + 1)
            };
            let t = gen::random(&RandomParams {
                surface,
                min_faces: faces,
                flip_percent: 30,
                seed,
            })
            .expect("small sizes");
            let mut m = t.to_mesh();
            let k = at as usize % m.faces.len();
            match damage {
                1 => {
                    m.faces.remove(k);
                }
                2 => m.faces.push(m.faces[k]),
                3 => m.faces[k][0] = m.faces[k][1],
                4 => m.faces[k][2] = at % (m.vertex_count as u32 + 3),
                _ => {}
            }
            let mut p: Vec<[f64; 3]> = (0..m.vertex_count)
                .map(|v| {
                    let h = (v as u64 + 1).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ seed;
                    [
                        (h % 1000) as f64,
                        ((h >> 20) % 1000) as f64,
                        ((h >> 40) % 1000) as f64,
                    ]
                })
                .collect();
            if nan && !p.is_empty() {
                let k = at as usize % p.len();
                p[k][1] = f64::NAN;
            }
            m.positions = Some(p);
            m
        })
}

fn any_mesh() -> impl Strategy<Value = TriMesh> {
    prop_oneof![face_soup(), damaged_surface()]
}

fn eps() -> impl Strategy<Value = Eps> {
    prop_oneof![
        (0.0f64..2.0).prop_map(Eps::Relative),
        (0.0f64..500.0).prop_map(Eps::Absolute),
        Just(Eps::Relative(f64::NAN)),
        Just(Eps::Absolute(-1.0)),
        Just(Eps::Absolute(f64::INFINITY)),
        Just(Eps::Relative(1e300)),
    ]
}

/// A monitor that observes every event, cancelled from the start or not.
fn monitor(cancelled: bool) -> Monitor {
    Monitor::new()
        .observe(|e| {
            let _ = format!("{e:?}");
        })
        .cancel_on(Arc::new(AtomicBool::new(cancelled)))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 192, ..ProptestConfig::default() })]

    #[test]
    fn the_task_calls_never_panic(
        mesh in any_mesh(),
        r_algo in prop::sample::select(irreducible::Algorithm::ALL.to_vec()),
        q_algo in prop::sample::select(quad::Algorithm::ALL.to_vec()),
        mode in prop::sample::select(Mode::ALL.to_vec()),
        side in prop::sample::select(Side::ALL.to_vec()),
        position in prop::sample::select(Position::ALL.to_vec()),
        eps in eps(),
        seed in any::<u64>(),
        cancelled in prop::bool::weighted(0.1),
        flags in any::<[bool; 4]>(),
    ) {
        let _ = describe(&mesh);
        let _ = reduce(&mesh, &ReduceOptions {
            algorithm: r_algo,
            seed,
            count_retests: flags[0],
            keep_history: true,
            verify: flags[1],
            parallel: flags[3],
            monitor: monitor(cancelled),
        });
        let _ = quadrangulate(&mesh, &QuadOptions {
            algorithm: q_algo,
            seed,
            verify: flags[1],
            parallel: flags[3],
            monitor: monitor(cancelled),
        });
        let _ = simplify(&mesh, &SimplifyOptions {
            eps,
            mode,
            side,
            position,
            allow_foldover: flags[2],
            skip_verify: !flags[1],
            parallel: flags[3],
            monitor: monitor(cancelled),
        });
    }

    #[test]
    fn the_core_mesh_and_io_entry_points_never_panic(
        mesh in any_mesh(),
        levels in 0u32..3,
        tolerance in prop_oneof![0.0f64..5.0, Just(f64::NAN), Just(-1.0)],
    ) {
        let _ = Surfaces::from_mesh(&mesh);
        let _ = ConedSurfaces::from_mesh(&mesh);
        let _ = Triangulation::from_faces(mesh.vertex_count, &mesh.faces);
        let _ = contractible::diagnose::diagnose(&mesh, 3);
        let _ = mesh.compacted();
        let _ = mesh.welded_within(tolerance);
        let _ = gen::subdivide(&mesh, levels);
        for format in [io::Format::Off, io::Format::Obj, io::Format::Ply, io::Format::Stl] {
            let mut bytes = Vec::new();
            if io::write_mesh_to(&mut bytes, &mesh, format, true).is_ok() {
                // What was written reads back (or is refused with an error).
                let _ = io::read_poly_mesh_bytes(&bytes, Some(format));
            }
        }
    }

    #[test]
    fn the_readers_never_panic_on_random_bytes(
        bytes in prop::collection::vec(any::<u8>(), 0..400),
        prefix in prop::sample::select(vec![
            &b""[..], b"OFF\n", b"ply\nformat ascii 1.0\n", b"solid x\n", b"v 0 0 0\nf ",
            b"ply\nformat binary_little_endian 1.0\nelement vertex 3\n",
        ]),
    ) {
        let mut input = prefix.to_vec();
        input.extend_from_slice(&bytes);
        for format in [None, Some(io::Format::Off), Some(io::Format::Obj),
                       Some(io::Format::Ply), Some(io::Format::Stl)] {
            let _ = io::read_poly_mesh_bytes(&input, format);
            let _ = io::read_tri_mesh_bytes(&input, format);
        }
    }
}

/// Sizes no machine could build are refused with errors, before any allocation: vertex
/// counts beyond the 32-bit ids (the faces themselves are few), subdivision levels and
/// random surfaces beyond the core's limits.
#[test]
fn huge_sizes_are_errors_not_panics_or_allocations() {
    let tetra = gen::tetrahedron();
    for n in [u32::MAX as usize, usize::MAX] {
        let huge = TriMesh::combinatorial(n, tetra.faces.clone());
        assert!(Surfaces::from_mesh(&huge).is_err());
        assert!(describe(&huge).is_err(), "describe of {n} vertices");
        assert!(reduce(&huge, &ReduceOptions::default()).is_err());
        assert!(quadrangulate(&huge, &QuadOptions::default()).is_err());
        assert!(gen::subdivide(&huge, 1).is_err());
    }
    assert!(gen::subdivide(&tetra, 40).is_err());
    assert!(gen::subdivide(&tetra, u32::MAX).is_err());
    for surface in [
        SurfaceKind::Orientable(u32::MAX),
        SurfaceKind::NonOrientable(u32::MAX),
    ] {
        assert!(gen::seed_surface(surface).is_err());
        let p = RandomParams {
            surface,
            min_faces: 10,
            flip_percent: 0,
            seed: 0,
        };
        assert!(gen::random(&p).is_err());
    }
    let p = RandomParams {
        surface: SurfaceKind::Orientable(1),
        min_faces: usize::MAX,
        flip_percent: 0,
        seed: 0,
    };
    assert!(gen::random(&p).is_err());
}
