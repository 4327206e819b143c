//! The command-line grammar (clap derive).

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::choice;
// The choices are the library's own enums (one list of names, parsed and printed by
// them, adapted to clap by `choice`); under these names for the arguments below.
use contractible::decimate::{Placement, Schedule};
use contractible::irreducible::Algorithm as Algo;
use contractible::quad::Algorithm as QuadAlgo;
use contractible::simplify::{
    Mode as SimplifyMode, Position as SimplifyPosition, Side as SimplifySide,
};

/// Topology-preserving edge contraction on closed triangulated surfaces.
///
/// Reads OFF, OBJ, PLY (ascii or binary) and STL (binary or ascii), optionally
/// gzip-compressed (`.gz`).
/// Exit codes: 0 success, 2 invalid input, 1 other failures.
#[derive(Parser, Debug)]
#[command(name = "contractible", version, about, long_about = None, after_help = CLI_AFTER_HELP)]
pub struct Cli {
    /// Print a machine-readable JSON result on stdout (and nothing else there).
    #[arg(long, global = true)]
    pub json: bool,
    /// No progress bars and no human-readable text (errors still go to stderr).
    #[arg(long, short, global = true)]
    pub quiet: bool,
    #[command(subcommand)]
    pub command: Command,
}

/// Formats, outputs, exit codes: what every command shares.
const CLI_AFTER_HELP: &str = "Files: OFF, OBJ, PLY (ascii or binary) and STL (binary or \
ascii), optionally gzip-compressed (.gz); the format follows the extension. An output \
may be `-` (stdout, with --output-format); outputs are checked before any work and \
written through a temporary file, which SIGINT and SIGTERM remove. Exit codes: 0 \
success, 2 invalid input or an output that cannot be written, 1 other failures; a \
closed stdout ends the program as SIGPIPE does.";

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Validate a mesh and print its topology per connected component.
    Info(InfoArgs),
    /// Generate a triangulated surface (closed, except the hyperboloid isosurface).
    Gen(GenArgs),
    /// Convert between mesh formats (by extension), validating the input as surfaces
    /// (closed or with boundary).
    Convert(ConvertArgs),
    /// Contract edges until every component is irreducible.
    #[command(after_help = REDUCE_AFTER_HELP)]
    Reduce(ReduceArgs),
    /// Pair the triangles of every component into quads on the same vertices (tri-quad
    /// conversion): always a perfect pairing, checked before writing.
    Quad(QuadArgs),
    /// Contract every edge shorter than ε where the surface allows it (Pepko–Borisenko
    /// short-edge simplification), keeping every component's topology (χ,
    /// orientability, boundary loops): checked before writing. Needs vertex positions;
    /// accepts surfaces with boundary.
    #[command(
        after_help = "ε (--eps, or --eps-rel times the bounding-box diagonal) is a \
length: every edge strictly shorter than ε is a candidate for contraction; the one \
contracted is replaced by one vertex (--position). It is unrelated to the ε column of \
`reduce`."
    )]
    Simplify(SimplifyArgs),
    /// Collapse edges, cheapest quadric error first (Garland–Heckbert), down to a face
    /// budget or an error cap, every collapse passing the link condition: every
    /// component keeps its topology (χ, orientability, boundary loops), checked before
    /// writing. Needs vertex positions; accepts surfaces with boundary.
    #[command(after_help = DECIMATE_AFTER_HELP)]
    Decimate(DecimateArgs),
    /// Judge an output of any implementation of a task by its properties (not its
    /// bytes): exit 0 when it is a correct answer for the input, 1 with every reason
    /// (located) when it is not, 2 when a file cannot be read or the input is not one
    /// the task accepts.
    #[command(after_help = CHECK_AFTER_HELP)]
    Check(CheckArgs),
    /// Run an implementation of the conformance protocol (any program: a port, another
    /// library's wrapper) over the suite, one process per case, and judge every answer
    /// by its properties (with --exact, also against the stored output): exit 0 when
    /// every selected case passes, 1 when any fails or times out, 2 for a usage error.
    #[command(after_help = CONFORMANCE_AFTER_HELP)]
    Conformance(ConformanceArgs),
    /// Answer one conformance case with this library: read the case (a JSON object) on
    /// stdin, print the answer on stdout (exit 0), or the refusal
    /// `{"error": {"kind", "message"}}` (exit 2). The adapter `conformance --impl
    /// 'contractible answer'` runs.
    Answer,
    /// Run the main job on built-in inputs: generate, describe, reduce with RS, Schipper
    /// and the brute force, pair into quads, simplify marching-tetrahedra isosurfaces
    /// (naive and nested, ε = 1 % of the bounding-box diagonal), verify.
    #[command(after_help = REDUCE_AFTER_HELP)]
    Demo(DemoArgs),
    /// Run one task (info, reduce, quad, simplify or decimate) over many files in parallel: one
    /// JSON line per file, in input order; a failing file never stops the batch.
    #[command(after_help = BATCH_AFTER_HELP)]
    Batch(BatchArgs),
    /// Print a shell completion script on stdout (e.g. `contractible completions bash >
    /// /etc/bash_completion.d/contractible`).
    Completions(CompletionsArgs),
    /// Print the man page contractible(1) (roff) on stdout (e.g. `contractible man | man
    /// -l -`).
    Man,
}

/// How `batch` reports.
const BATCH_AFTER_HELP: &str = "Each file runs as `contractible TASK FILE [-o \
OUTDIR/NAME.TASK.EXT] [TASK OPTIONS]` would (the options after `--` go to the task's own \
parser), quietly, one file per thread. Each line is {\"file\", \"task\", \"ok\", \
\"result\": the task's --json report, \"error\": {\"kind\", \"exit_code\", \
\"message\"}}; `info` on a broken mesh gives both (the problems and the error). Exit \
code 0 when every file succeeded, 1 when any failed.";

/// The targets, the error and the stop rule of `decimate`.
const DECIMATE_AFTER_HELP: &str = "Targets: the run stops at the first one reached \
(--faces and --keep: the larger face count; --max-error: no collapse whose error exceeds \
the cap). With no target at all it collapses as far as the guards allow: until every edge \
left fails the link condition or is refused by the fold-over guard or a lock. The report \
says why it stopped (target, error cap, blocked) and, short of the target, how many edges \
each guard refuses. The error of a vertex is the root mean square distance of its \
position from the planes of the input faces merged into it, in the mesh's units. Vertex \
ids (--lock, the --maps file) count from 0 in every format, OBJ included (the OBJ vertex \
`1` is id 0), as the vertices' order in the file.";

/// What the columns of `reduce` and `demo` mean.
const REDUCE_AFTER_HELP: &str = "Columns (the RS paper's counters): ℓ is the number of \
link-condition tests carried out; ε is the number of edges tested more than once (an edge \
keeps its identity when a contraction renames an endpoint). In `simplify`, ε is instead \
the edge length below which edges are contracted. The output is checked independently of \
the algorithm (no edge passes the link condition: by its definition on small outputs, by \
the marked-neighbour test on every edge of large ones); the check is its own step, with its \
own time (seconds_verify).";

#[derive(Args, Debug)]
pub struct CompletionsArgs {
    /// The shell to complete for.
    #[arg(value_enum)]
    pub shell: clap_complete::Shell,
}

/// A mesh format, for `--format` (input) and `--output-format`.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FormatArg {
    /// Object File Format (ASCII).
    Off,
    /// Wavefront OBJ.
    Obj,
    /// Stanford PLY (read ascii or binary; written binary little-endian).
    Ply,
    /// STL (read binary or ASCII; written binary; triangles only).
    Stl,
}

impl From<FormatArg> for contractible::io::Format {
    fn from(f: FormatArg) -> Self {
        use contractible::io::Format;
        match f {
            FormatArg::Off => Format::Off,
            FormatArg::Obj => Format::Obj,
            FormatArg::Ply => Format::Ply,
            FormatArg::Stl => Format::Stl,
        }
    }
}

#[derive(Args, Debug)]
pub struct InfoArgs {
    /// Mesh file (.off/.obj/.ply/.stl, optionally .gz; `-` for standard input).
    pub file: PathBuf,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

/// How an input mesh is read: shared by every command that reads one.
#[derive(Args, Debug, Clone)]
pub struct InputOpts {
    /// Merge vertices before validation, for triangle soups: `--weld` merges vertices at
    /// bitwise-equal positions (STL files are welded so on reading already);
    /// `--weld=EPS` merges vertices within distance EPS, transitively (a chain of close
    /// vertices becomes one), each group becoming its lowest-numbered vertex. The count
    /// is reported on stderr; a face whose corners merge is an error naming it, never
    /// dropped silently.
    #[arg(
        long,
        value_name = "EPS",
        num_args = 0..=1,
        require_equals = true,
        default_missing_value = "0",
        value_parser = parse_tolerance
    )]
    pub weld: Option<f64>,
    /// Split faces with more than 3 corners into triangles: a quad along its shorter
    /// diagonal, any other polygon as a fan from its first corner. Without it, such
    /// faces are refused (`info` describes polygon meshes as they are).
    #[arg(long)]
    pub triangulate: bool,
    /// The input's format, when neither its content nor its name tells (as for `-`,
    /// standard input). By default the content decides, else the extension; a name that
    /// disagrees with the content gets a warning.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<FormatArg>,
}

/// A weld tolerance: a finite number >= 0.
fn parse_tolerance(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x >= 0.0 => Ok(x),
        _ => Err(format!("{s:?} is not a distance (a finite number >= 0)")),
    }
}

#[derive(Args, Debug)]
pub struct GenArgs {
    #[command(subcommand)]
    pub kind: GenKind,
}

/// The output file of a generator.
#[derive(Args, Debug)]
pub struct OutArg {
    /// Output file; the format follows the extension (.off/.obj/.ply/.stl, optionally .gz);
    /// `-` writes to stdout (with --output-format).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Format of the output: required with `-o -` (stdout); with a file name it must
    /// agree with the extension.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub output_format: Option<FormatArg>,
}

#[derive(Subcommand, Debug)]
pub enum GenKind {
    /// A random triangulation grown from a minimal one by random vertex splits (no
    /// coordinates: every vertex is written as 0 0 0).
    Random(RandomArgs),
    /// A brick with cavities and through-holes (the RS paper's benchmark surfaces).
    Brick(BrickArgs),
    /// 1-to-4 subdivision of an input surface (positions kept, midpoints averaged).
    Subdivide(SubdivideArgs),
    /// Marching tetrahedra on an implicit surface sampled on a grid (with positions). The
    /// hyperboloid is open where the box cuts it (two discs); the others are closed.
    Isosurface(IsoArgs),
    /// The boundary of the tetrahedron (4 vertices).
    Tetrahedron(OutArg),
    /// The boundary of the octahedron (6 vertices).
    Octahedron(OutArg),
    /// The boundary of the icosahedron (12 vertices).
    Icosahedron(OutArg),
    /// The 7-vertex torus.
    Torus7(OutArg),
    /// The 6-vertex projective plane.
    Rp2(OutArg),
    /// A 9-vertex Klein bottle.
    Klein(OutArg),
}

#[derive(Args, Debug)]
pub struct RandomArgs {
    /// Orientable genus g (default 0 unless --crosscaps is given).
    #[arg(long, conflicts_with = "crosscaps")]
    pub genus: Option<u32>,
    /// Non-orientable surface with this Euler genus h >= 1 (1: projective plane, 2: Klein
    /// bottle).
    #[arg(long)]
    pub crosscaps: Option<u32>,
    /// Grow until at least this many faces.
    #[arg(long, default_value_t = 1000)]
    pub faces: usize,
    /// Percentage of splits followed by a random edge flip.
    #[arg(long, default_value_t = 0)]
    pub flips: u32,
    /// Seed of the documented random stream.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    #[command(flatten)]
    pub out: OutArg,
}

#[derive(Args, Debug)]
pub struct BrickArgs {
    /// Number of sites (cavities, of which --holes are through-holes).
    #[arg(long, required_unless_present = "paper")]
    pub cavities: Option<u32>,
    /// How many of the sites are through-holes: the genus.
    #[arg(long, default_value_t = 0, conflicts_with = "paper")]
    pub holes: u32,
    /// Uniform grid resolution (cells per site side).
    #[arg(long, conflicts_with_all = ["faces", "paper"])]
    pub resolution: Option<u32>,
    /// Choose the shape whose triangle count is closest to this target.
    #[arg(long, conflicts_with = "paper")]
    pub faces: Option<u64>,
    /// A member of the paper's benchmark groups: B0..B9, C0..C7, D0..D9.
    #[arg(long, conflicts_with = "cavities")]
    pub paper: Option<String>,
    #[command(flatten)]
    pub out: OutArg,
}

/// How `gen isosurface` splits the grid's cubes into tetrahedra.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum TessellationArg {
    /// 6 tetrahedra per cube around its main diagonal.
    Six,
    /// Chan–Purisima body-centred tessellation (12 tetrahedra per cube).
    Bcc,
}

/// Named `gen isosurface` workloads.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum IsoPreset {
    /// Table 1's torus: 16,772 vertices, 33,544 faces (both tessellations).
    PaperTorus,
    /// Table 1's two-sheeted hyperboloid: 56,288 vertices, 111,140 faces with bcc
    /// (111,332 faces with six).
    PaperHyperboloid,
    /// The paper's torus over 1,000,000 triangles.
    LargeTorus,
    /// The paper's hyperboloid over 1,000,000 triangles.
    LargeHyperboloid,
}

#[derive(Args, Debug)]
pub struct IsoArgs {
    /// sphere (radius 1), torus (radii 1 and 0.4), genus:G (a slab with G holes), or
    /// hyperboloid (x² + y² − z² + 0.3 in the box ±1.2 × ±1.2 × ±1.5).
    #[arg(long, required_unless_present = "preset", conflicts_with = "preset")]
    pub surface: Option<String>,
    /// How cubes are split into tetrahedra.
    #[arg(long, value_enum, default_value_t = TessellationArg::Six)]
    pub tessellation: TessellationArg,
    /// Cells along the box's longest axis (the others keep cells about cubic).
    #[arg(long, default_value_t = 32, conflicts_with = "preset")]
    pub resolution: u32,
    /// A named workload (grid and function fixed).
    #[arg(long, value_enum)]
    pub preset: Option<IsoPreset>,
    #[command(flatten)]
    pub out: OutArg,
}

#[derive(Args, Debug)]
pub struct SubdivideArgs {
    /// Input surface (`-` for standard input).
    #[arg(long)]
    pub input: PathBuf,
    #[command(flatten)]
    pub input_opts: InputOpts,
    /// Number of 1-to-4 subdivision rounds.
    #[arg(long, default_value_t = 1)]
    pub levels: u32,
    #[command(flatten)]
    pub out: OutArg,
}

#[derive(Args, Debug)]
pub struct ConvertArgs {
    /// Input mesh (`-` for standard input).
    pub input: PathBuf,
    /// Output mesh (.off/.obj/.ply/.stl, optionally .gz; PLY and STL are written binary);
    /// `-` writes to stdout (with --output-format).
    pub output: PathBuf,
    /// Format of the output: required with `-o -` (stdout); with a file name it must
    /// agree with the extension.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub output_format: Option<FormatArg>,
    /// Convert even if the input is not a union of surfaces (closed or with boundary).
    #[arg(long)]
    pub no_validate: bool,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

#[derive(Args, Debug)]
pub struct ReduceArgs {
    /// Input mesh (`-` for standard input).
    pub input: PathBuf,
    /// Write the irreducible components here (original coordinates of the survivors);
    /// `-` writes to stdout (with --output-format).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Format of the output: required with `-o -` (stdout); with a file name it must
    /// agree with the extension.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub output_format: Option<FormatArg>,
    /// Algorithm.
    #[arg(long, value_parser = choice::parser::<Algo>(), default_value_t = Algo::Rs)]
    pub algo: Algo,
    /// Seed (used by the brute force's shuffle).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Skip the independent check that every output component is irreducible.
    #[arg(long)]
    pub no_verify: bool,
    /// Write every contraction here, one line `KEPT REMOVED` per contraction (0-based
    /// input vertex ids: REMOVED was contracted into KEPT), oldest first, component by
    /// component: replayed on the input, they give the output (`check reduce --history`
    /// checks it). `-` writes them to stdout. Keeping them costs about 44 bytes per
    /// input triangle.
    #[arg(long, value_name = "FILE")]
    pub history: Option<PathBuf>,
    /// Components of the mesh processed at once (default: one per CPU; 1 processes
    /// them one after another). The output is the same for every value.
    #[arg(long, short = 'j')]
    pub jobs: Option<usize>,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

#[derive(Args, Debug)]
pub struct QuadArgs {
    /// Input mesh (closed triangulated surfaces).
    pub input: PathBuf,
    /// Write the quad mesh here (the input's vertices and positions, one quad per pair;
    /// .off, .obj or .ply); `-` writes to stdout (with --output-format).
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Format of the output: required with `-o -` (stdout); with a file name it must
    /// agree with the extension.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub output_format: Option<FormatArg>,
    /// Algorithm.
    #[arg(long, value_parser = choice::parser::<QuadAlgo>(), default_value_t = QuadAlgo::Lrs)]
    pub algo: QuadAlgo,
    /// Seed of the randomised orders of SG and PS.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Write one line per quad with the two input face indices it joins (0-based, in the
    /// order of the quads in the output). For LRS the faces are those of the flipped
    /// triangulation K, which keeps the input's face indices. `-` writes them to stdout.
    #[arg(long)]
    pub pairs: Option<PathBuf>,
    /// Write the paired triangulation K here as a triangle mesh (.off/.obj/.ply/.stl,
    /// optionally .gz; the input's vertices and positions, one face per input face, in the
    /// input's order): the input's faces, except those LRS's flips changed. With the
    /// quads and `--pairs`, what `check quad` needs to judge a conversion that flips.
    #[arg(long, value_name = "FILE")]
    pub triangles: Option<PathBuf>,
    /// Components of the mesh processed at once (default: one per CPU; 1 processes
    /// them one after another). The output is the same for every value.
    #[arg(long, short = 'j')]
    pub jobs: Option<usize>,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

#[derive(Args, Debug)]
#[command(group(clap::ArgGroup::new("epsilon").required(true).args(["eps", "eps_rel"])))]
pub struct SimplifyArgs {
    /// Input mesh with vertex positions (closed surfaces or surfaces with boundary, any
    /// number of components).
    pub input: PathBuf,
    /// Output mesh (.off/.obj/.ply/.stl, optionally .gz); written only after the result has
    /// passed the topology check; `-` writes to stdout (with --output-format).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Format of the output: required with `-o -` (stdout); with a file name it must
    /// agree with the extension.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub output_format: Option<FormatArg>,
    /// Contract edges strictly shorter than this length (finite, > 0).
    #[arg(long, allow_negative_numbers = true)]
    pub eps: Option<f64>,
    /// ε as a fraction of the diagonal of the bounding box of the vertices the faces use
    /// (finite, > 0; 0.01 is 1 %).
    #[arg(long, allow_negative_numbers = true)]
    pub eps_rel: Option<f64>,
    /// What to do with short edges that fail the link condition.
    #[arg(long, value_parser = choice::parser::<SimplifyMode>(), default_value_t = SimplifyMode::Nested)]
    pub mode: SimplifyMode,
    /// The nested mode's side heuristic.
    #[arg(long, value_parser = choice::parser::<SimplifySide>(), default_value_t = SimplifySide::Count)]
    pub side: SimplifySide,
    /// Where the new vertex of a contraction goes.
    #[arg(long, value_parser = choice::parser::<SimplifyPosition>(), default_value_t = SimplifyPosition::Midpoint)]
    pub position: SimplifyPosition,
    /// Turn off the geometry guard (which skips a contraction that would flip a
    /// triangle's normal by 90° or more or leave a zero-area triangle). The topology is
    /// kept either way.
    #[arg(long)]
    pub allow_foldover: bool,
    /// Components of the mesh simplified at once (default: one per CPU; 1 processes
    /// them one after another). The output is the same for every value.
    #[arg(long, short = 'j')]
    pub jobs: Option<usize>,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

/// The protocol and the verdicts of `conformance`.
const CONFORMANCE_AFTER_HELP: &str = "Each case is written to the implementation's \
standard input as one JSON object {\"protocol\": 1, \"id\", \"task\", \"options\", \
\"vertex_count\", \"faces\", \"positions\"}; it answers with one JSON object on its \
standard output: {\"faces\", \"positions\"} (for quad also \"triangles\" and \"pairs\") \
and exit code 0, or {\"error\": {\"kind\", \"message\"}} and a nonzero exit code for \
an input it refuses (spec/conformance.md). A valid case passes when the answer passes \
`check` (and, with --exact, equals the stored output); an invalid case passes when the \
input is refused. Before the run, the checker must reject every wrong answer of the \
suite with its stated reason. --script prints the --skip arguments of the failures, to \
commit as known failures.";

/// What `check` verifies.
const CHECK_AFTER_HELP: &str = "reduce: OUTPUT is a closed 2-manifold on INPUT's \
vertices (by id when OUTPUT keeps INPUT's vertex list, else by exact position) with \
INPUT's positions, one component per input component with the same χ and \
orientability, and irreducible: every edge fails the link condition (the tetrahedron \
aside); with --history, each recorded contraction passes the link condition on the \
surface the earlier ones left and their replay gives OUTPUT. quad (OUTPUT a quad mesh; with --triangles K and --pairs P when the run flipped \
edges): every quad is two triangles of K (of INPUT's faces without --triangles) split \
along one of its diagonals (the pair P states for it, if given), every triangle in \
exactly one quad, and K a closed surface on INPUT's vertices of INPUT's surface per \
component. decimate (with the run's target and options as `decimate` takes them, and \
its --maps file if any): OUTPUT is a surface of INPUT's type per component with finite \
positions, the maps consistent with each other and the faces, locked vertices kept, \
every position an input position with --placement endpoint, and a face count the \
target explains (at most one collapse below it; above it, for a run with \
--allow-foldover and no cap, no unlocked edge passing the link condition). simplify \
(with the run's --eps or --eps-rel, and its --position and \
--allow-foldover): OUTPUT is a 2-manifold, boundary allowed, with finite positions, of \
INPUT's surface per component (χ, orientability, boundary loops; by id when OUTPUT keeps \
INPUT's vertex list, else as multisets of surface types), and no edge strictly shorter \
than ε passes the link condition of the surface with boundary unless the geometry guard \
refuses it (recomputed for midpoints; with --position quadric and the guard on, no short \
edge is judged). The checks share no code with the algorithms. At most 20 reasons of a \
kind are listed, with the count of all.";

/// A task whose outputs `check` judges.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheckTask {
    /// An irreducible triangulation of every component.
    Reduce,
    /// A perfect pairing of edge-adjacent triangles, as quads.
    Quad,
    /// A decimation to a budget that kept every component's surface.
    Decimate,
    /// Every edge shorter than ε contracted that the link condition and the guard allow.
    Simplify,
}

#[derive(Args, Debug)]
pub struct CheckArgs {
    /// The task the output answers.
    #[arg(value_enum)]
    pub task: CheckTask,
    /// The task's input mesh (.off/.obj/.ply/.stl, optionally .gz).
    pub input: PathBuf,
    /// The output to judge, from any implementation.
    pub output: PathBuf,
    /// simplify: the run's ε, an absolute length (finite, > 0).
    #[arg(long, allow_negative_numbers = true, conflicts_with = "eps_rel")]
    pub eps: Option<f64>,
    /// simplify: the run's ε as a fraction of the diagonal of the bounding box of the
    /// vertices INPUT's faces use (finite, > 0).
    #[arg(long, allow_negative_numbers = true)]
    pub eps_rel: Option<f64>,
    /// simplify: where the run put the vertex of a contracted edge.
    #[arg(long, value_parser = choice::parser::<SimplifyPosition>())]
    pub position: Option<SimplifyPosition>,
    /// simplify: the run had the geometry guard off (every short edge that passes the
    /// link condition must then be gone).
    #[arg(long)]
    pub allow_foldover: bool,
    /// quad: the triangulation K the quads pair, a triangle mesh in OUTPUT's vertex ids
    /// (as `quad --triangles` writes it); without it, the quads must pair INPUT's faces.
    #[arg(long, value_name = "FILE")]
    pub triangles: Option<PathBuf>,
    /// quad: the pairs, one line per quad of two 0-based face indices of K (of INPUT
    /// without --triangles), as `quad --pairs` writes them.
    #[arg(long, value_name = "FILE")]
    pub pairs: Option<PathBuf>,
    /// decimate: the run's face target.
    #[arg(long, value_name = "N")]
    pub faces: Option<usize>,
    /// decimate: the run's fraction of the faces kept.
    #[arg(long, value_name = "F", allow_negative_numbers = true)]
    pub keep: Option<f64>,
    /// decimate: the run's error cap (then a run may stop above its target anywhere).
    #[arg(long, value_name = "E", allow_negative_numbers = true)]
    pub max_error: Option<f64>,
    /// decimate: the run's error cap as a fraction of the bounding-box diagonal.
    #[arg(
        long,
        value_name = "R",
        allow_negative_numbers = true,
        conflicts_with = "max_error"
    )]
    pub max_error_rel: Option<f64>,
    /// decimate: the run's placement (with `endpoint`, every output position must be
    /// an input position).
    #[arg(long, value_parser = choice::parser::<Placement>())]
    pub placement: Option<Placement>,
    /// decimate: the run locked the boundary vertices.
    #[arg(long)]
    pub lock_boundary: bool,
    /// decimate: the run's locked input vertices (ids from 0, comma-separated or
    /// repeated).
    #[arg(long, value_name = "V", value_delimiter = ',')]
    pub lock: Vec<u32>,
    /// decimate: the provenance maps, as `decimate --maps` writes them (vertex_map,
    /// collapse_map, face_origin).
    #[arg(long, value_name = "FILE")]
    pub maps: Option<PathBuf>,
    /// reduce: the run's contractions, as `reduce --history` writes them (one line
    /// `KEPT REMOVED` each, input vertex ids, oldest first): each must pass the link
    /// condition on the surface the earlier ones left, and their replay give OUTPUT.
    #[arg(long, value_name = "FILE")]
    pub history: Option<PathBuf>,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

/// A task of the conformance protocol.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum ProtocolTask {
    Reduce,
    Quad,
    Simplify,
    Decimate,
}

impl ProtocolTask {
    pub fn name(self) -> &'static str {
        match self {
            ProtocolTask::Reduce => "reduce",
            ProtocolTask::Quad => "quad",
            ProtocolTask::Simplify => "simplify",
            ProtocolTask::Decimate => "decimate",
        }
    }
}

/// A class of conformance cases.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CaseClass {
    /// Inputs with a correct answer.
    Valid,
    /// Inputs the implementation must refuse.
    Invalid,
}

impl CaseClass {
    pub fn class(self) -> crate::conformance::suite::Class {
        match self {
            CaseClass::Valid => crate::conformance::suite::Class::Valid,
            CaseClass::Invalid => crate::conformance::suite::Class::Invalid,
        }
    }
}

#[derive(Args, Debug)]
pub struct ConformanceArgs {
    /// The implementation: a program and its arguments, quoted as a shell would (run
    /// once per case, without a shell).
    #[arg(long = "impl", value_name = "CMD ARGS")]
    pub implementation: String,
    /// The suite folder: its vectors/*.jsonl and suite/*.jsonl (default: spec, the
    /// repository's).
    #[arg(long, value_name = "DIR", default_value = "spec")]
    pub suite: PathBuf,
    /// Only the cases of this task (repeatable).
    #[arg(long, value_enum)]
    pub task: Vec<ProtocolTask>,
    /// Only the cases of this class.
    #[arg(long, value_enum)]
    pub class: Option<CaseClass>,
    /// Also demand the stored output where a case has one (for faithful ports).
    #[arg(long)]
    pub exact: bool,
    /// Only the cases whose id matches this glob (repeatable: any of them).
    #[arg(long, value_name = "GLOB")]
    pub run: Vec<String>,
    /// Skip the cases whose id matches this glob (repeatable): known failures.
    #[arg(long, value_name = "GLOB")]
    pub skip: Vec<String>,
    /// Skip the invalid cases (an implementation that does not validate its input).
    #[arg(long)]
    pub skip_must_fail: bool,
    /// Seconds a case may take before it is stopped and counted as timed out.
    #[arg(long, value_name = "S", default_value_t = 10.0)]
    pub timeout: f64,
    /// Cases run at once (default: one per CPU). The report is the same for every value.
    #[arg(long, short = 'j')]
    pub jobs: Option<usize>,
    /// Print only the --skip arguments of the failed and timed-out cases.
    #[arg(long)]
    pub script: bool,
}

#[derive(Args, Debug)]
pub struct DecimateArgs {
    /// Input mesh with vertex positions (closed surfaces or surfaces with boundary, any
    /// number of components).
    pub input: PathBuf,
    /// Output mesh (.off/.obj/.ply/.stl, optionally .gz); written only after the result has
    /// passed its independent check; `-` writes to stdout (with --output-format).
    #[arg(short, long)]
    pub output: PathBuf,
    /// Format of the output: required with `-o -` (stdout); with a file name it must
    /// agree with the extension.
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub output_format: Option<FormatArg>,
    /// Stop at this many faces or fewer.
    #[arg(long, value_name = "N")]
    pub faces: Option<usize>,
    /// Stop at this fraction of the input's faces kept or fewer (in [0, 1]; 0.1 keeps
    /// a tenth, ceil(F × 0.1) faces). With --faces too, the larger face count wins.
    #[arg(long, value_name = "F", allow_negative_numbers = true)]
    pub keep: Option<f64>,
    /// Make no collapse whose error exceeds this distance (finite, >= 0).
    #[arg(long, value_name = "E", allow_negative_numbers = true)]
    pub max_error: Option<f64>,
    /// The error cap as a fraction of the diagonal of the bounding box of the vertices
    /// the faces use (finite, >= 0; 0.001 is 0.1 %).
    #[arg(
        long,
        value_name = "R",
        allow_negative_numbers = true,
        conflicts_with = "max_error"
    )]
    pub max_error_rel: Option<f64>,
    /// Where the vertex that replaces a collapsed edge goes (a locked endpoint
    /// overrides it: the edge collapses onto that endpoint).
    #[arg(long, value_parser = choice::parser::<Placement>(), default_value_t = Placement::Optimal)]
    pub placement: Placement,
    /// The order of the collapses: `exact` (always the cheapest edge the guards allow)
    /// or `passes` (the fast option: passes of independent collapses, somewhat larger
    /// error). The topology, guards and targets are kept either way.
    #[arg(long, value_parser = choice::parser::<Schedule>(), default_value_t = Schedule::Exact)]
    pub schedule: Schedule,
    /// Turn off the geometry guard (which refuses a collapse that would turn a face by
    /// 90° or more or leave it with zero area). The topology is kept either way.
    #[arg(long)]
    pub allow_foldover: bool,
    /// Keep every boundary vertex where it is: a boundary edge never collapses, an
    /// interior edge at the boundary only onto its boundary end.
    #[arg(long)]
    pub lock_boundary: bool,
    /// Input vertices that must survive at their input positions: ids counted from 0
    /// in every format (the OBJ vertex `1` is id 0), comma-separated or repeated.
    #[arg(long, value_name = "V", value_delimiter = ',')]
    pub lock: Vec<u32>,
    /// Skip the independent check of the output (topology per component, the maps,
    /// the locks).
    #[arg(long)]
    pub no_verify: bool,
    /// Write where every output vertex and face comes from as JSON (vertex_map,
    /// collapse_map, face_origin; ids of the input file counted from 0), to carry
    /// attributes over; `-` writes it to stdout.
    #[arg(long, value_name = "FILE")]
    pub maps: Option<PathBuf>,
    /// Threads for checking the input and the output (their surfaces are built on the
    /// pool from 262,144 faces) and for costing edges and sorting keys (default: one
    /// per CPU); the collapses themselves are sequential, and the output is the same
    /// for every value.
    #[arg(long, short = 'j')]
    pub jobs: Option<usize>,
    #[command(flatten)]
    pub input_opts: InputOpts,
}

#[derive(Args, Debug)]
pub struct DemoArgs {
    /// Seed for the random surface and the brute force.
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Algorithms to compare (comma-separated).
    #[arg(long, value_parser = choice::parser::<Algo>(), value_delimiter = ',', default_values_t = [Algo::Rs, Algo::Schipper, Algo::Brute])]
    pub algos: Vec<Algo>,
}

/// The tasks `batch` runs.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum BatchTask {
    /// `contractible info`.
    Info,
    /// `contractible reduce`.
    Reduce,
    /// `contractible quad`.
    Quad,
    /// `contractible simplify` (give --eps or --eps-rel after `--`).
    Simplify,
    /// `contractible decimate` (targets such as --faces or --keep after `--`).
    Decimate,
}

#[derive(Args, Debug)]
pub struct BatchArgs {
    /// Directories (every .off/.obj/.ply/.stl file below them, optionally .gz), glob
    /// patterns (quoted: `'meshes/**/*.stl'`) or files; sorted, duplicates removed.
    #[arg(required = true, num_args = 1..)]
    pub inputs: Vec<String>,
    /// The task to run on every file.
    #[arg(long, value_enum)]
    pub task: BatchTask,
    /// Write each output mesh under this directory (the input's path relative to the
    /// inputs' common directory, the task before the extension: `x.reduce.off.gz`).
    /// Without it, no mesh is written (`simplify` and `decimate` need it).
    #[arg(short, long, value_name = "OUTDIR")]
    pub output: Option<PathBuf>,
    /// Files processed at once (default: the number of CPUs).
    #[arg(long, short = 'j')]
    pub jobs: Option<usize>,
    /// Write the JSON lines to this file instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub jsonl: Option<PathBuf>,
    /// Skip the files that already have a line in the --jsonl file and append the others.
    #[arg(long)]
    pub resume: bool,
    /// Options of the task, after `--` (e.g. `-- --algo brute --seed 3`,
    /// `-- --eps-rel 0.01`, `-- --keep 0.1`).
    #[arg(last = true, allow_hyphen_values = true)]
    pub options: Vec<String>,
}
