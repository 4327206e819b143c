//! Reading needs memory for the mesh, not for the input: decompression bombs (gzip files
//! that expand to a gigabyte of blank lines, of one endless line, or behind a header count
//! of a billion records) are read or refused while the heap stays within a few tens of
//! megabytes. Had the readers kept the decompressed input, these would need over a
//! gigabyte each.
//!
//! Decimation needs memory in proportion to the faces: the heap's peak during a
//! `decimate` call, beyond the input mesh, is bounded per triangle.
//!
//! This target has its own binary because it replaces the global allocator with one that
//! records the peak of live heap bytes; its tests hold one lock, each running its cases
//! one after the other, so that no other test's allocations are counted.

use std::alloc::{GlobalAlloc, Layout, System};
use std::io::Write;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use contractible::decimate::Schedule;
use contractible::gen::{isosurface, Implicit, IsoParams, Tessellation};
use contractible::io::{self, Format, ReadErrorKind};
use contractible::{decimate, DecimateOptions};

/// The system allocator, counting live bytes and their peak.
struct Counting;

static LIVE: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: every call is forwarded unchanged to the system allocator; the counters are
// only statistics.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: the caller upholds `GlobalAlloc::alloc`'s contract, passed on as is.
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            let now = LIVE.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as for `alloc`.
        unsafe { System.dealloc(ptr, layout) };
        LIVE.fetch_sub(layout.size(), Ordering::Relaxed);
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: as for `alloc`.
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                let grow = new_size - layout.size();
                let now = LIVE.fetch_add(grow, Ordering::Relaxed) + grow;
                PEAK.fetch_max(now, Ordering::Relaxed);
            } else {
                LIVE.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
            }
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Held by every test for its whole run: the counters are global, so one test at a time.
static SERIAL: Mutex<()> = Mutex::new(());

const MIB: usize = 1 << 20;
/// The decompressed size of each bomb.
const EXPANDED: usize = 1 << 30;

/// `head`, then `EXPANDED` bytes repeating `filler`, then `tail`, gzip-compressed.
fn bomb(head: &[u8], filler: &[u8], tail: &[u8]) -> Vec<u8> {
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    gz.write_all(head).unwrap();
    let block: Vec<u8> = filler.iter().copied().cycle().take(MIB).collect();
    for _ in 0..EXPANDED / MIB {
        gz.write_all(&block).unwrap();
    }
    gz.write_all(tail).unwrap();
    gz.finish().unwrap()
}

/// Runs `read` and returns its result with the peak heap growth during the call.
fn peak_during<T>(read: impl FnOnce() -> T) -> (T, usize) {
    let base = LIVE.load(Ordering::Relaxed);
    PEAK.store(base, Ordering::Relaxed);
    let out = read();
    (out, PEAK.load(Ordering::Relaxed).saturating_sub(base))
}

const TET_VERTICES: &str = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const TET_FACES: &str = "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n";

#[test]
fn decompression_bombs_are_read_or_refused_in_bounded_memory() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let dir = std::env::temp_dir().join(format!("contractible-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();

    // 1. A gigabyte of blank and comment lines between the vertices and the faces: the
    //    tetrahedron is read, through every entry point, in a few megabytes.
    let head = format!("OFF\n4 4 0\n{TET_VERTICES}");
    let gz = bomb(head.as_bytes(), b"   \n# padding\n\n", TET_FACES.as_bytes());
    assert!(gz.len() < 8 * MIB, "the bomb is small: {} bytes", gz.len());
    let (mesh, peak) = peak_during(|| io::read_tri_mesh_bytes(&gz, None));
    let mesh = mesh.expect("a valid OFF file");
    assert_eq!((mesh.vertex_count, mesh.faces.len()), (4, 4));
    eprintln!(
        "blank lines, from memory: peak {:.1} MiB",
        peak as f64 / MIB as f64
    );
    assert!(peak < 4 * MIB + gz.len(), "peak {peak} bytes");

    let path = dir.join("padded.off.gz");
    std::fs::write(&path, &gz).unwrap();
    let (mesh, peak) = peak_during(|| io::read_tri_mesh(&path));
    assert_eq!(mesh.expect("a valid OFF file").faces.len(), 4);
    eprintln!(
        "blank lines, from a file: peak {:.1} MiB",
        peak as f64 / MIB as f64
    );
    assert!(peak < 4 * MIB, "peak {peak} bytes");

    let (decoded, peak) = peak_during(|| io::decode_reader(&gz[..], None));
    assert_eq!(decoded.expect("a valid OFF file").format, Format::Off);
    assert!(peak < 4 * MIB, "peak {peak} bytes");

    // 2. One endless line: refused at its start, after buffering at most the line limit.
    let gz = bomb(b"OFF\n4 4 0\n0 0 0", b" ", b"\n");
    let (r, peak) = peak_during(|| io::read_tri_mesh_bytes(&gz, Some(Format::Off)));
    let e = r.expect_err("a gigabyte-long line");
    assert!(matches!(e.kind, ReadErrorKind::LineTooLong { .. }), "{e}");
    assert_eq!(e.location, io::Location::Line(3));
    eprintln!("one endless line: peak {:.1} MiB", peak as f64 / MIB as f64);
    assert!(
        peak < io::MAX_LINE * 3 / 2 + 4 * MIB + gz.len(),
        "peak {peak} bytes"
    );

    // 3. A header declaring a billion vertices, then only whitespace: what is reserved
    //    ahead is bounded (the length is unknown until the end), then the count is refused.
    let gz = bomb(b"OFF\n1000000000 1000000000 0\n", b"\n", b"");
    let (r, peak) = peak_during(|| io::read_tri_mesh_bytes(&gz, None));
    let e = r.expect_err("no vertices at all");
    assert!(
        matches!(e.kind, ReadErrorKind::CountMismatch { found: 0, .. }),
        "{e}"
    );
    eprintln!(
        "a billion declared vertices: peak {:.1} MiB",
        peak as f64 / MIB as f64
    );
    assert!(peak < 8 * MIB, "peak {peak} bytes");

    // 4. Binary STL declaring four billion triangles after its 80-byte header, padded with
    //    a gigabyte of zeros (twenty million triangles at the origin would follow): the
    //    length, measured by a first decompression pass, refuses the count before any
    //    triangle is stored.
    let mut head = vec![b' '; 80];
    head.extend_from_slice(&u32::MAX.to_le_bytes());
    let gz = bomb(&head, &[0], b"");
    let (r, peak) = peak_during(|| io::read_tri_mesh_bytes(&gz, Some(Format::Stl)));
    let e = r.expect_err("fewer triangles than declared");
    assert!(
        matches!(
            e.kind,
            ReadErrorKind::CountMismatch { .. } | ReadErrorKind::Truncated { .. }
        ),
        "{e}"
    );
    eprintln!(
        "four billion declared triangles: peak {:.1} MiB",
        peak as f64 / MIB as f64
    );
    assert!(peak < 8 * MIB + gz.len(), "peak {peak} bytes");

    std::fs::remove_dir_all(&dir).ok();
}

/// `decimate` to 10 % of the faces of a marching-tetrahedra sphere, with the default
/// options and with the pass schedule: the heap's peak during the call, beyond the input
/// mesh (24 bytes per vertex, 12 per face), stays below 400 bytes per input triangle,
/// whatever the build (debug builds keep the specification checks' state too). The
/// sphere has 64 cells across (73,944 triangles), or `DECIMATE_MEMORY_RESOLUTION` (470:
/// 3,985,392 triangles, for the figure in docs/benchmarks.md, in a release build).
#[test]
fn decimation_needs_memory_in_proportion_to_the_faces() {
    let _serial = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let resolution = std::env::var("DECIMATE_MEMORY_RESOLUTION")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(64);
    let mesh = isosurface(&IsoParams::new(
        Implicit::Sphere { radius: 1.0 },
        Tessellation::SixTetrahedra,
        resolution,
    ))
    .expect("a sphere");
    let faces = mesh.faces.len();
    for schedule in Schedule::ALL {
        let options = DecimateOptions {
            schedule,
            ..DecimateOptions::keep(0.1)
        };
        let (r, peak) = peak_during(|| decimate(&mesh, &options));
        let r = r.expect("a sphere decimates");
        assert!(r.verified);
        assert!(r.mesh.faces.len() * 10 <= faces + 9);
        let per_triangle = peak as f64 / faces as f64;
        eprintln!(
            "decimate ({} schedule) to 10 % of {faces} triangles ({} vertices): heap peak \
             beyond the input {:.1} MiB, {per_triangle:.1} bytes per triangle",
            schedule.name(),
            mesh.vertex_count,
            peak as f64 / MIB as f64
        );
        assert!(per_triangle < 400.0, "{per_triangle} bytes per triangle");
    }
}
