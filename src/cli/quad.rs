//! `contractible quad IN [-o OUT] [--pairs FILE]`: tri-quad conversion per component.

use std::path::Path;
use std::time::Instant;

use contractible::quad::{self, Algorithm, Options, Quadrangulation};
use contractible::{QuadMesh, SurfaceType, Surfaces, TriMesh};
use serde::Serialize;

use super::args::QuadArgs;
use super::progress::{bar, StageBar};
use super::reduce::component_prefix;
use super::{meshio, print_json, CliError, Ui};

use contractible::quad::DS_NAIVE_MAX_FACES;

/// Counters of one conversion (one component, or the totals): the paper's Table 4.3
/// columns (a)–(e) plus the work of each step.
#[derive(Serialize, Debug, Clone)]
pub struct QuadStats {
    pub algo: &'static str,
    pub faces: usize,
    pub quads: usize,
    pub euler_characteristic: i64,
    pub orientable: bool,
    /// (a) seconds of the initial pairing.
    pub initial_seconds: f64,
    /// (b) % of the triangles paired by the initial step.
    pub initial_paired_percent: f64,
    /// (c) triangles left unpaired by the initial step.
    pub initial_unpaired: usize,
    /// (d) seconds of the completion.
    pub completion_seconds: f64,
    /// (e) total seconds.
    pub total_seconds: f64,
    pub flips: usize,
    pub augmenting_paths: usize,
    pub phases: usize,
    /// Whether the independent check passed (perfect, pairs share an edge of K, K a valid
    /// triangulation of the input's surface with the input's counts).
    pub verified: bool,
}

impl QuadStats {
    pub fn of(q: &Quadrangulation, input: SurfaceType, verified: bool) -> Self {
        let s = &q.stats;
        QuadStats {
            algo: q.algorithm.name(),
            faces: s.faces,
            quads: q.pairing.len(),
            euler_characteristic: input.euler_characteristic(),
            orientable: input.is_orientable(),
            initial_seconds: s.initial_seconds,
            initial_paired_percent: s.initial_paired_percent,
            initial_unpaired: s.initial_unpaired,
            completion_seconds: s.completion_seconds,
            total_seconds: s.total_seconds,
            flips: s.flips,
            augmenting_paths: s.augmenting_paths,
            phases: s.phases,
            verified,
        }
    }

    pub fn total(algo: Algorithm, parts: &[QuadStats]) -> Self {
        let sum = |f: fn(&QuadStats) -> usize| parts.iter().map(f).sum::<usize>();
        let sumf = |f: fn(&QuadStats) -> f64| parts.iter().map(f).sum::<f64>();
        let faces = sum(|p| p.faces);
        let unpaired = sum(|p| p.initial_unpaired);
        QuadStats {
            algo: algo.name(),
            faces,
            quads: sum(|p| p.quads),
            euler_characteristic: parts.iter().map(|p| p.euler_characteristic).sum(),
            orientable: parts.iter().all(|p| p.orientable),
            initial_seconds: sumf(|p| p.initial_seconds),
            initial_paired_percent: if faces == 0 {
                100.0
            } else {
                100.0 * (faces - unpaired) as f64 / faces as f64
            },
            initial_unpaired: unpaired,
            completion_seconds: sumf(|p| p.completion_seconds),
            total_seconds: sumf(|p| p.total_seconds),
            flips: sum(|p| p.flips),
            augmenting_paths: sum(|p| p.augmenting_paths),
            phases: parts.iter().map(|p| p.phases).max().unwrap_or(0),
            verified: parts.iter().all(|p| p.verified),
        }
    }
}

/// The JSON result of `quad`: totals at the top level plus one entry per component.
#[derive(Serialize, Debug)]
pub struct QuadReport {
    pub file: String,
    pub output: Option<String>,
    pub pairs: Option<String>,
    pub seed: u64,
    pub components: usize,
    pub dropped_vertices: usize,
    /// Vertices merged by `--weld` (present only with `--weld`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub welded_vertices: Option<usize>,
    #[serde(flatten)]
    pub totals: QuadStats,
    pub component_list: Vec<QuadStats>,
    pub seconds_read: f64,
    pub seconds_build: f64,
    /// The independent check of every pairing (its own step, after the conversions).
    pub seconds_verify: f64,
    /// Writing the quad mesh (absent without `-o`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write: Option<f64>,
    /// Writing the pairs file (absent without `--pairs`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub seconds_write_pairs: Option<f64>,
}

/// The independent check of a conversion of `input`: `K` validates from scratch, has the
/// input's vertex set and counts and surface type, and the pairing is perfect with every
/// pair sharing an edge of `K` (checked on `K`'s face lists, not by the pairing's own
/// bookkeeping).
pub fn verify(input: &contractible::Triangulation, q: &Quadrangulation) -> bool {
    let k = &q.tri;
    if k.validate().is_err()
        || k.vertex_count() != input.vertex_count()
        || k.face_count() != input.face_count()
        || !k.vertices().eq(input.vertices())
        || SurfaceType::of(k) != SurfaceType::of(input)
        || 2 * q.pairing.len() != k.face_count()
    {
        return false;
    }
    let mut seen = vec![false; k.face_capacity()];
    for (f, g) in q.pairing.pairs() {
        if !k.is_face(f) || !k.is_face(g) || seen[f.index()] || seen[g.index()] {
            return false;
        }
        seen[f.index()] = true;
        seen[g.index()] = true;
        let (a, b) = (k.face_vertices(f), k.face_vertices(g));
        if a.iter().filter(|v| b.contains(v)).count() != 2 {
            return false;
        }
    }
    true
}

/// Converts (a copy of) every component of `surfaces` with `algo` (a bar follows the
/// algorithm inside each component), then checks each by [`verify`] as a step of its
/// own; returns the per-component counters.
pub fn quad_all(surfaces: &Surfaces, algo: Algorithm, seed: u64, ui: Ui) -> Vec<QuadStats> {
    let done = convert_all(surfaces, algo, seed, ui);
    let inputs: Vec<&contractible::Triangulation> =
        surfaces.components.iter().map(|c| &c.tri).collect();
    let (verdicts, _) = verify_all(&inputs, &done, ui);
    done.iter()
        .zip(&inputs)
        .zip(verdicts)
        .map(|((q, t), ok)| QuadStats::of(q, SurfaceType::of(t), ok))
        .collect()
}

/// Converts (a copy of) every component, a bar following the algorithm inside each.
fn convert_all(surfaces: &Surfaces, algo: Algorithm, seed: u64, ui: Ui) -> Vec<Quadrangulation> {
    let options = Options { seed };
    let n = surfaces.components.len();
    let mut bar = StageBar::new(ui, component_prefix(VERB, algo.name(), 0, n));
    let mut done = Vec::with_capacity(n);
    for (i, c) in surfaces.components.iter().enumerate() {
        bar.set_prefix(component_prefix(VERB, algo.name(), i, n));
        done.push(quad::convert_observed(
            c.tri.clone(),
            algo,
            &options,
            &mut |p| bar.observe(p),
        ));
    }
    bar.finish();
    done
}

/// What the bar of the conversions says.
const VERB: &str = "pairing";

/// The verification step: [`verify`] on every conversion (a bar over the components,
/// announced as its own step). Returns the verdicts and the seconds taken.
fn verify_all(
    inputs: &[&contractible::Triangulation],
    done: &[Quadrangulation],
    ui: Ui,
) -> (Vec<bool>, f64) {
    let t = Instant::now();
    let pb = bar(
        ui,
        done.len() as u64,
        "verifying: perfect pairings of adjacent faces",
    );
    let verdicts = inputs
        .iter()
        .zip(done)
        .map(|(input, q)| {
            let ok = verify(input, q);
            pb.inc(1);
            ok
        })
        .collect();
    pb.finish_and_clear();
    (verdicts, t.elapsed().as_secs_f64())
}

/// Runs the command without printing its report (warnings and bars follow `ui`).
pub fn compute(a: &QuadArgs, ui: Ui) -> Result<QuadReport, CliError> {
    let output = match &a.output {
        Some(out) => {
            let o = meshio::check_output(out, a.output_format.map(Into::into), &[&a.input])?;
            if o.format == contractible::io::Format::Stl {
                return Err(CliError::Input(format!(
                    "{}: STL holds triangles only; write the quad mesh as .off, .obj or .ply",
                    o.display()
                )));
            }
            Some(o)
        }
        None => None,
    };
    if let Some(p) = &a.pairs {
        if p.as_os_str() == "-" {
            if output.as_ref().is_some_and(|o| o.path.is_none()) {
                return Err(CliError::Input(
                    "-o - and --pairs - would both write to stdout: send one to a file".into(),
                ));
            }
            super::report_to_stderr();
        } else {
            meshio::check_side_file(p, &[&a.input])?;
        }
    }
    let (mesh, seconds_read, welded_vertices, names) =
        meshio::read_input(&a.input, &a.input_opts, ui)?;
    let (surfaces, seconds_build) = meshio::build_closed(&mesh, &names, ui, "quad")?;
    let TriMesh {
        vertex_count,
        positions,
        faces,
    } = mesh;
    drop(faces);
    let dropped_vertices = surfaces.dropped_vertices.len();
    let algo: Algorithm = a.algo.into();
    if algo == Algorithm::DsNaive {
        // O(F²): about F²/4 node visits, minutes beyond this size.
        if let Some(c) = surfaces
            .components
            .iter()
            .find(|c| c.tri.face_count() > DS_NAIVE_MAX_FACES)
        {
            return Err(CliError::Input(format!(
                "{}: --algo ds-naive is quadratic and refuses components above {DS_NAIVE_MAX_FACES} faces (this one has {}); use --algo ds or --algo frink-lct",
                a.input.display(),
                c.tri.face_count()
            )));
        }
    }
    let n = surfaces.components.len();
    let done = convert_all(&surfaces, algo, a.seed, ui);
    let inputs: Vec<&contractible::Triangulation> =
        surfaces.components.iter().map(|c| &c.tri).collect();
    let (verdicts, seconds_verify) = verify_all(&inputs, &done, ui);
    let mut stats = Vec::with_capacity(n);
    let mut quads: Vec<[u32; 4]> = Vec::new();
    let mut pair_lines: Vec<(usize, usize)> = Vec::new();
    for ((c, q), ok) in surfaces.components.iter().zip(&done).zip(verdicts) {
        stats.push(QuadStats::of(q, SurfaceType::of(&c.tri), ok));
        if ok {
            for (f, g) in q.pairing.pairs() {
                let quad = quad::quad_of(&q.tri, f, g).ok_or_else(|| {
                    CliError::Failure(format!(
                        "internal error: {}: verified pair {f}, {g} shares no edge",
                        a.input.display()
                    ))
                })?;
                quads.push(quad.map(|v| c.vertex_origin[v as usize]));
                pair_lines.push((
                    c.face_origin[f.index()] as usize,
                    c.face_origin[g.index()] as usize,
                ));
            }
        }
    }
    drop(done);
    drop(surfaces);
    let totals = QuadStats::total(algo, &stats);
    if !totals.verified {
        let bad: Vec<String> = stats
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.verified)
            .map(|(i, _)| i.to_string())
            .collect();
        return Err(CliError::Failure(format!(
            "{}: the pairing of component(s) {} failed the independent check; nothing written",
            a.input.display(),
            bad.join(", ")
        )));
    }
    let mut seconds_write = None;
    if let Some(out) = &output {
        let m = QuadMesh {
            vertex_count,
            positions,
            faces: quads,
        };
        seconds_write = Some(meshio::write(out, &m, ui)?);
    }
    let mut seconds_write_pairs = None;
    if let Some(path) = &a.pairs {
        let t = Instant::now();
        write_pairs(path, &pair_lines)?;
        seconds_write_pairs = Some(t.elapsed().as_secs_f64());
    }
    let report = QuadReport {
        file: a.input.display().to_string(),
        output: output.as_ref().map(meshio::Output::display),
        pairs: a.pairs.as_deref().map(|p: &Path| p.display().to_string()),
        seed: a.seed,
        components: stats.len(),
        dropped_vertices,
        welded_vertices,
        totals,
        component_list: stats,
        seconds_read,
        seconds_build,
        seconds_verify,
        seconds_write,
        seconds_write_pairs,
    };
    Ok(report)
}

pub fn run(a: &QuadArgs, ui: Ui) -> Result<(), CliError> {
    let report = compute(a, ui)?;
    if ui.json {
        print_json(&report)?;
    } else if !ui.quiet {
        let t = &report.totals;
        outln!(
            "{} ({}): {} triangles -> {} quads; initial {:.4} s, {:.3} % paired ({} unpaired); \
             completion {:.4} s ({} augmenting paths, {} phases); total {:.4} s; {} flips",
            report.file,
            t.algo,
            t.faces,
            t.quads,
            t.initial_seconds,
            t.initial_paired_percent,
            t.initial_unpaired,
            t.completion_seconds,
            t.augmenting_paths,
            t.phases,
            t.total_seconds,
            t.flips
        );
        let mut steps = vec![
            format!("read {:.3} s", report.seconds_read),
            format!("check input {:.3} s", report.seconds_build),
            format!("{} {:.3} s", t.algo, t.total_seconds),
            format!("verify {:.3} s", report.seconds_verify),
        ];
        if let Some(w) = report.seconds_write {
            steps.push(format!("write {w:.3} s"));
        }
        if let Some(w) = report.seconds_write_pairs {
            steps.push(format!("write pairs {w:.3} s"));
        }
        outln!("time: {}", steps.join(", "));
        for o in [&report.output, &report.pairs].into_iter().flatten() {
            outln!("wrote {o}");
        }
    }
    Ok(())
}

/// Writes the pairs file atomically (temporary file renamed into place), or to stdout
/// for `-`.
fn write_pairs(path: &Path, lines: &[(usize, usize)]) -> Result<(), CliError> {
    if path.as_os_str() == "-" {
        use std::io::Write;
        let mut w = std::io::BufWriter::new(std::io::stdout().lock());
        let r = lines
            .iter()
            .try_for_each(|(f, g)| writeln!(w, "{f} {g}"))
            .and_then(|()| w.flush());
        return match r {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                super::signals::die_of_broken_pipe()
            }
            Err(e) => Err(CliError::Failure(format!("-: cannot write to stdout: {e}"))),
        };
    }
    meshio::write_side_file(path, |w| {
        for (f, g) in lines {
            writeln!(w, "{f} {g}")?;
        }
        Ok(())
    })
}
