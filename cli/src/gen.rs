//! `contractible gen KIND ... -o FILE`: generators.

use std::path::Path;

use contractible::core::MAX_FACES;
use contractible::gen::{self, BrickParams, RandomParams, SurfaceKind};
use contractible::{Surfaces, TriMesh};

use super::args::{
    BrickArgs, FormatArg, GenArgs, GenKind, IsoArgs, IsoPreset, RandomArgs, SubdivideArgs,
    TessellationArg,
};
use super::info::Report;
use super::progress::spinner;
use super::{meshio, print_json, CliError, Ui};

/// A generator's refusal, as an input error (its message names the generator, the
/// count and the limit).
fn gen_error(e: gen::GenError) -> CliError {
    CliError::Input(e.to_string())
}

fn too_large(what: &str, faces: u64) -> CliError {
    CliError::Input(format!(
        "{what}: {faces} faces requested, at most {MAX_FACES} are supported"
    ))
}

fn random_mesh(a: &RandomArgs, ui: Ui) -> Result<TriMesh, CliError> {
    let surface = match (a.genus, a.crosscaps) {
        (_, Some(0)) => {
            return Err(CliError::Input(
                "--crosscaps must be at least 1 (use --genus 0 for the sphere)".into(),
            ))
        }
        (_, Some(h)) => SurfaceKind::NonOrientable(h),
        (g, None) => SurfaceKind::Orientable(g.unwrap_or(0)),
    };
    if a.faces > MAX_FACES {
        return Err(too_large("random", a.faces as u64));
    }
    // The seed surface alone has about 14 faces per handle / 10 per cross-cap.
    let seed_faces = match surface {
        SurfaceKind::Orientable(g) => 14 * g as u64,
        SurfaceKind::NonOrientable(h) => 10 * h as u64,
    };
    if seed_faces > MAX_FACES as u64 {
        return Err(too_large("random", seed_faces));
    }
    if a.flips > 100 {
        return Err(CliError::Input("--flips is a percentage (0..=100)".into()));
    }
    let pb = spinner(ui, format!("growing a random surface to {} faces", a.faces));
    let t = gen::random(&RandomParams {
        surface,
        min_faces: a.faces,
        flip_percent: a.flips,
        seed: a.seed,
    })
    .map_err(gen_error)?;
    pb.finish_and_clear();
    Ok(t.to_mesh())
}

/// Parses `B7`, `c3`, `D0` into the paper's group and index.
fn parse_paper(s: &str) -> Result<(char, u32), CliError> {
    let bad = || {
        CliError::Input(format!(
            "--paper {s:?}: expected one of B0..B9, C0..C7, D0..D9"
        ))
    };
    let mut chars = s.chars();
    let group = chars.next().ok_or_else(bad)?.to_ascii_uppercase();
    let index: u32 = chars.as_str().parse().map_err(|_| bad())?;
    gen::paper_entry(group, index).ok_or_else(bad)?;
    Ok((group, index))
}

fn brick_mesh(a: &BrickArgs, ui: Ui) -> Result<TriMesh, CliError> {
    if let Some(p) = &a.paper {
        let (group, index) = parse_paper(p)?;
        let pb = spinner(ui, format!("building paper brick {group}{index}"));
        let m = gen::paper_family(group, index).map_err(gen_error)?;
        pb.finish_and_clear();
        return Ok(m);
    }
    let cavities = a.cavities.unwrap_or(0);
    if a.holes > cavities {
        return Err(CliError::Input(format!(
            "--holes {} exceeds --cavities {cavities}",
            a.holes
        )));
    }
    if let Some(target) = a.faces {
        if target > MAX_FACES as u64 {
            return Err(too_large("brick", target));
        }
        let shape = gen::brick_target_shape(cavities, a.holes, target).map_err(gen_error)?;
        let (_, _, f) = gen::brick_shape_counts(cavities, a.holes, &shape).map_err(gen_error)?;
        if f > MAX_FACES as u64 {
            return Err(too_large("brick", f));
        }
        let pb = spinner(ui, format!("building a brick with about {target} faces"));
        let m = gen::brick_shaped(cavities, a.holes, &shape).map_err(gen_error)?;
        pb.finish_and_clear();
        return Ok(m);
    }
    let resolution = a.resolution.unwrap_or(1);
    if resolution == 0 {
        return Err(CliError::Input("--resolution must be at least 1".into()));
    }
    let params = BrickParams {
        cavities,
        holes: a.holes,
        resolution,
    };
    let (_, _, f) = gen::brick_counts(&params).map_err(gen_error)?;
    if f > MAX_FACES as u64 {
        return Err(too_large("brick", f));
    }
    let pb = spinner(ui, format!("building a brick with {f} faces"));
    let m = gen::brick(&params).map_err(gen_error)?;
    pb.finish_and_clear();
    Ok(m)
}

fn subdivide_mesh(a: &SubdivideArgs, ui: Ui) -> Result<TriMesh, CliError> {
    let (mesh, _, _, names) = meshio::read_input(&a.input, &a.input_opts, ui)?;
    meshio::build(&mesh, &names, ui)?;
    // `build` accepted every face index, and the readers give one position per vertex.
    let (mesh, _) = mesh.compacted().ok_or_else(|| {
        CliError::Failure(format!(
            "{}: inconsistent mesh after validation",
            a.input.display()
        ))
    })?;
    let faces = (mesh.faces.len() as u128) << (2 * a.levels.min(32));
    if a.levels > 32 || faces > MAX_FACES as u128 {
        return Err(CliError::Input(format!(
            "subdivide: {} levels would give more than {MAX_FACES} faces",
            a.levels
        )));
    }
    let pb = spinner(ui, format!("subdividing {} levels", a.levels));
    let m = gen::subdivide(&mesh, a.levels).map_err(gen_error)?;
    pb.finish_and_clear();
    Ok(m)
}

/// The largest `--resolution` of `gen isosurface`: about 10⁸ cells, far beyond any
/// surface the triangulation can index anyway.
const MAX_ISO_RESOLUTION: u32 = 2048;

fn iso_params(a: &IsoArgs) -> Result<gen::IsoParams, CliError> {
    let tess = match a.tessellation {
        TessellationArg::Six => gen::Tessellation::SixTetrahedra,
        TessellationArg::Bcc => gen::Tessellation::BodyCentred,
    };
    if let Some(p) = a.preset {
        return Ok(match p {
            IsoPreset::PaperTorus => gen::paper_torus(tess),
            IsoPreset::PaperHyperboloid => gen::paper_hyperboloid(tess),
            IsoPreset::LargeTorus => gen::large_torus(tess),
            IsoPreset::LargeHyperboloid => gen::large_hyperboloid(tess),
        });
    }
    let name = a.surface.as_deref().unwrap_or_default();
    let implicit = match name {
        "sphere" => gen::Implicit::Sphere { radius: 1.0 },
        "torus" => gen::Implicit::Torus {
            major: 1.0,
            minor: 0.4,
        },
        "hyperboloid" => gen::Implicit::TwoSheetHyperboloid {
            c: 0.3,
            half_width: 1.2,
            half_height: 1.5,
        },
        _ => {
            let g = name
                .strip_prefix("genus:")
                .and_then(|g| g.parse::<u32>().ok())
                .filter(|&g| g <= gen::MAX_GENUS)
                .ok_or_else(|| {
                    CliError::Input(format!(
                        "--surface {name:?}: expected sphere, torus, genus:G (0 <= G <= {}) \
                         or hyperboloid",
                        gen::MAX_GENUS
                    ))
                })?;
            gen::Implicit::GenusG { g }
        }
    };
    if a.resolution == 0 || a.resolution > MAX_ISO_RESOLUTION {
        return Err(CliError::Input(format!(
            "--resolution {}: expected 1..={MAX_ISO_RESOLUTION}",
            a.resolution
        )));
    }
    Ok(gen::IsoParams::new(implicit, tess, a.resolution))
}

/// What `gen isosurface` reports for an open result (which [`Surfaces`] does not
/// accept): counts and the checks made before writing.
#[derive(serde::Serialize, Debug)]
struct OpenReport {
    file: String,
    vertices: usize,
    edges: usize,
    faces: usize,
    components: usize,
    euler_characteristic: i64,
    boundary_edges: usize,
    /// Every interior edge is traversed once in each direction.
    consistently_oriented: bool,
    /// Writing the file (set once written).
    #[serde(skip_serializing_if = "Option::is_none")]
    seconds_write: Option<f64>,
}

/// What `gen` reports for a closed result: `info`'s report of it and the write time.
#[derive(serde::Serialize, Debug)]
struct GenReport {
    #[serde(flatten)]
    info: Report,
    seconds_write: f64,
}

/// Checks an open marching-tetrahedra mesh independently of the generator: every edge
/// in one or two faces, every interior edge traversed once each way. O(F) expected.
fn check_open(out: &str, m: &TriMesh) -> Result<OpenReport, CliError> {
    use std::collections::HashMap;
    let mut edge: HashMap<(u32, u32), (usize, bool)> = HashMap::new();
    let mut oriented = true;
    let mut parent: Vec<usize> = (0..m.faces.len()).collect();
    fn root(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    for (fi, f) in m.faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            let e = edge.entry((a.min(b), a.max(b))).or_insert((fi, a < b));
            if e.0 != fi {
                // A second face on this edge: it must run the other way, and no third.
                if e.0 == usize::MAX {
                    return Err(CliError::Failure(format!(
                        "generated mesh is not a surface: edge [{a}, {b}] in more than two faces"
                    )));
                }
                if e.1 == (a < b) {
                    oriented = false;
                }
                let (ra, rb) = (root(&mut parent, e.0), root(&mut parent, fi));
                parent[ra.max(rb)] = ra.min(rb);
                e.0 = usize::MAX;
            }
        }
    }
    let boundary_edges = edge.values().filter(|e| e.0 != usize::MAX).count();
    let components = (0..m.faces.len())
        .filter(|&f| root(&mut parent, f) == f)
        .count();
    Ok(OpenReport {
        file: out.to_string(),
        vertices: m.vertex_count,
        edges: edge.len(),
        faces: m.faces.len(),
        components,
        euler_characteristic: m.vertex_count as i64 - edge.len() as i64 + m.faces.len() as i64,
        boundary_edges,
        consistently_oriented: oriented,
        seconds_write: None,
    })
}

fn isosurface_mesh(a: &IsoArgs, ui: Ui) -> Result<TriMesh, CliError> {
    let params = iso_params(a)?;
    let pb = spinner(
        ui,
        format!("marching tetrahedra on {:?} cells", params.cells),
    );
    let m = gen::isosurface(&params).map_err(|e| CliError::Input(format!("isosurface: {e}")));
    pb.finish_and_clear();
    m
}

fn output_of(kind: &GenKind) -> (&Path, Option<FormatArg>) {
    let o = match kind {
        GenKind::Random(r) => &r.out,
        GenKind::Brick(b) => &b.out,
        GenKind::Subdivide(s) => &s.out,
        GenKind::Isosurface(i) => &i.out,
        GenKind::Tetrahedron(o)
        | GenKind::Octahedron(o)
        | GenKind::Icosahedron(o)
        | GenKind::Torus7(o)
        | GenKind::Rp2(o)
        | GenKind::Klein(o) => o,
    };
    (&o.output, o.output_format)
}

/// Writes an open surface (the hyperboloid) after [`check_open`], and reports it.
fn write_open(out: &meshio::Output, mesh: &TriMesh, ui: Ui) -> Result<(), CliError> {
    let report = check_open(&out.display(), mesh)?;
    if !report.consistently_oriented {
        return Err(CliError::Failure(
            "generated mesh is not consistently oriented".into(),
        ));
    }
    let seconds_write = meshio::write(out, mesh, ui)?;
    let report = OpenReport {
        seconds_write: Some(seconds_write),
        ..report
    };
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!(
            "wrote {}: V={} E={} F={} χ={} components={} boundary edges={} (open)",
            out.display(),
            report.vertices,
            report.edges,
            report.faces,
            report.euler_characteristic,
            report.components,
            report.boundary_edges
        );
    }
    Ok(())
}

pub fn run(a: &GenArgs, ui: Ui) -> Result<(), CliError> {
    let (path, format) = output_of(&a.kind);
    let inputs: Vec<&Path> = match &a.kind {
        GenKind::Subdivide(s) => vec![s.input.as_path()],
        _ => Vec::new(),
    };
    let out = &meshio::check_output(path, format.map(Into::into), &inputs)?;
    let mesh = match &a.kind {
        GenKind::Random(r) => random_mesh(r, ui)?,
        GenKind::Brick(b) => brick_mesh(b, ui)?,
        GenKind::Subdivide(s) => subdivide_mesh(s, ui)?,
        GenKind::Isosurface(i) => {
            let mesh = isosurface_mesh(i, ui)?;
            let is_open = matches!(
                iso_params(i)?.implicit,
                gen::Implicit::TwoSheetHyperboloid { .. }
            );
            if is_open {
                return write_open(out, &mesh, ui);
            }
            mesh
        }
        GenKind::Tetrahedron(_) => gen::tetrahedron(),
        GenKind::Octahedron(_) => gen::octahedron(),
        GenKind::Icosahedron(_) => gen::icosahedron(),
        GenKind::Torus7(_) => gen::torus7(),
        GenKind::Rp2(_) => gen::projective_plane6(),
        GenKind::Klein(_) => gen::klein_bottle(),
    };
    let surfaces = Surfaces::from_mesh(&mesh)
        .map_err(|e| CliError::Failure(format!("generated mesh is not a surface: {e}")))?;
    let seconds_write = meshio::write(out, &mesh, ui)?;
    let report = GenReport {
        info: Report::of(Path::new(&out.display()), &surfaces, None, None),
        seconds_write,
    };
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        outln!(
            "wrote {}: V={} E={} F={} χ={} components={} {}",
            out.display(),
            report.info.vertices,
            report.info.edges,
            report.info.faces,
            report.info.euler_characteristic,
            report.info.components,
            report
                .info
                .component_list
                .first()
                .map(|c| c.surface.name())
                .unwrap_or_default()
        );
    }
    Ok(())
}
