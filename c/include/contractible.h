/* contractible.h: the C ABI of contractible (topology-preserving edge contraction on
 * triangulated surfaces). Generated from c/src by cbindgen (c/cbindgen.toml); do not
 * edit. Guide: docs/c.md. License: MIT OR Apache-2.0. */

#ifndef CONTRACTIBLE_H
#define CONTRACTIBLE_H



#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

// The version of this ABI: incremented when a function's meaning or a struct's existing
// fields change (new functions and new trailing fields do not change it).
#define CTR_ABI_VERSION 1

// Placement: the minimiser of the summed quadric (the default; the best of the
// endpoints and the midpoint where its system is ill-conditioned).
#define CTR_PLACEMENT_OPTIMAL 0

// Placement: the edge's midpoint.
#define CTR_PLACEMENT_MIDPOINT 1

// Placement: the endpoint with the smaller error (every output position is an input
// position).
#define CTR_PLACEMENT_ENDPOINT 2

// Schedule: one priority queue, always the cheapest edge that passes every guard (the
// default).
#define CTR_SCHEDULE_EXACT 0

// Schedule: passes over a sorted edge list, several times faster, a somewhat larger
// error.
#define CTR_SCHEDULE_PASSES 1

// Why a decimation stopped: a face target was reached.
#define CTR_STOPPED_TARGET 0

// Why a decimation stopped: every edge left is over the error cap or refused by a
// guard, at least one over the cap.
#define CTR_STOPPED_ERROR 1

// Why a decimation stopped: every edge left is refused by a guard (`remaining_*` of
// the statistics say which).
#define CTR_STOPPED_BLOCKED 2

// The entry of a collapse map for an input vertex no face uses.
#define CTR_NO_VERTEX UINT32_MAX

// No error.
#define CTR_OK 0

// A failure that is not the input's fault: a file could not be written, an output
// failed its independent check, the call was cancelled (the command line's exit code 1).
#define CTR_FAILURE 1

// The input is at fault: a file that cannot be read or parsed, a mesh that is not what
// the task accepts, an option out of range (the command line's exit code 2).
#define CTR_INPUT 2

// The call itself is wrong: a NULL or misaligned pointer, a count whose array cannot
// exist, an unknown enumeration value, an options struct of an unknown size, a path that
// is not UTF-8.
#define CTR_INVALID_ARGUMENT 3

// A bug in the library, caught before it crossed the boundary (please report it).
#define CTR_INTERNAL 4

// Bytes of the `kind` of `ctr_error`, its NUL included.
#define CTR_KIND_LEN 32

// Bytes of the `message` of `ctr_error`, its NUL included.
#define CTR_MESSAGE_LEN 1024

// Lemos–Ramaswami–Siqueira: contraction, expansion with flips, completion (the
// default).
#define CTR_QUAD_LRS 0

// Pulli–Segal greedy, then completion by augmenting paths.
#define CTR_QUAD_PULLI_SEGAL 1

// Simple greedy, then completion.
#define CTR_QUAD_SIMPLE_GREEDY 2

// Edmonds' matching on the whole dual graph.
#define CTR_QUAD_MATCHING 3

// Frink's reduction, Diks–Stańczyk strategy.
#define CTR_QUAD_DIKS_STANCZYK 4

// Frink's reduction, Biedl–Bose–Demaine–Lubiw strategy.
#define CTR_QUAD_BBDL 5

// Frink's reduction, link–cut cover-count strategy.
#define CTR_QUAD_FRINK_LCT 6

// Frink's reduction, naive DFS strategy (quadratic: refused above 100,000 faces per
// component).
#define CTR_QUAD_DS_NAIVE 7

// Ramaswami–Siqueira's algorithm (the default).
#define CTR_REDUCE_RS 0

// Schipper's algorithm.
#define CTR_REDUCE_SCHIPPER 1

// The randomised brute force (its order from `seed`).
#define CTR_REDUCE_BRUTE 2

// Mode: remove the discs inside the outermost 3-cycles through an edge the link
// condition blocks, then contract it (the paper's processEdge; the default).
#define CTR_SIMPLIFY_NESTED 0

// Mode: skip every edge that fails the link condition.
#define CTR_SIMPLIFY_NAIVE 1

// Side of a 3-cycle's disc (nested mode): grow both sides face by face, a 3-cycle goes
// to the side that closes it first (the default).
#define CTR_SIDE_COUNT 0

// Side: the side whose opposite vertex is nearer in edge hops.
#define CTR_SIDE_PATH 1

// Side: the side whose opposite vertex is nearer in space.
#define CTR_SIDE_EUCLIDEAN 2

// Position of a contracted edge's vertex: the midpoint, or the boundary endpoint of an
// edge with one endpoint on the boundary (the default).
#define CTR_POSITION_MIDPOINT 0

// Position: the minimiser of the summed Garland–Heckbert quadrics of both endpoints.
#define CTR_POSITION_QUADRIC 1

// The result of [`ctr_decimate`]: the output mesh, the provenance maps and the
// statistics. Opaque; freed by [`ctr_decimate_result_free`].
typedef struct ctr_decimate_result ctr_decimate_result;

// A triangle mesh: `vertex_count` vertices (with a position each, or none) and faces of
// three vertex indices (0-based). Opaque: made by `ctr_mesh_new`, `ctr_mesh_borrow` or
// `ctr_mesh_read` (or returned by a result's accessor, then owned by that result),
// freed by `ctr_mesh_free`.
typedef struct ctr_mesh ctr_mesh;

// The result of [`ctr_quadrangulate`]: the quads, the paired triangulation, the pairs
// and the statistics. Opaque; freed by [`ctr_quad_result_free`].
typedef struct ctr_quad_result ctr_quad_result;

// The result of `ctr_reduce`: the irreducible triangulations (one mesh), the input
// vertex of each output vertex, the contractions when kept. Opaque; freed by
// `ctr_reduce_result_free`.
typedef struct ctr_reduce_result ctr_reduce_result;

// The result of [`ctr_simplify`]: the output mesh and the statistics. Opaque; freed by
// [`ctr_simplify_result_free`].
typedef struct ctr_simplify_result ctr_simplify_result;

// A verdict: passed, or the reasons the output fails (at most 20 of a kind, in the
// order found). Opaque; freed by [`ctr_verdict_free`].
typedef struct ctr_verdict ctr_verdict;

// One reason an output fails: what, a sentence saying what and where, and the output
// face, edge, vertex or input component involved (-1 where none is).
typedef struct ctr_check_failure {
  // `sizeof(ctr_check_failure)` as the caller was compiled (set by
  // [`ctr_check_failure_default`]).
  uint32_t size;
  // The kind, a NUL-terminated name (`contractible_edge`, `surface_changed`, … as
  // `contractible check --json` prints them); owned by the verdict.
  const char *kind;
  // The sentence, NUL-terminated; owned by the verdict.
  const char *message;
  // An output face, or -1.
  int64_t face;
  // The smaller end of an output edge, or -1.
  int64_t edge_from;
  // The larger end of that edge, or -1.
  int64_t edge_to;
  // An output vertex, or -1.
  int64_t vertex;
  // An input component (numbered in the order of their smallest face), or -1.
  int64_t component;
} ctr_check_failure;

// Why a call failed: what (`code`, `kind`, `message`) and where (`face`, `vertex`,
// `line`, each -1 when it does not apply).
typedef struct ctr_error {
  // `sizeof(ctr_error)` as the caller was compiled: set by `ctr_error_init`. The
  // library writes no byte past it.
  uint32_t size;
  // `CTR_OK`, `CTR_FAILURE`, `CTR_INPUT`, `CTR_INVALID_ARGUMENT` or
  // `CTR_INTERNAL`.
  int32_t code;
  // A stable snake-case name (`boundary_edge`, `non_manifold_edge`, `read`, `io`,
  // `bad_option`, `invalid_argument`, `internal`...; the library's error kinds),
  // NUL-terminated; empty when `code` is `CTR_OK`.
  char kind[CTR_KIND_LEN];
  // A sentence saying what and where, NUL-terminated UTF-8 (cut at a character
  // boundary if longer than the array).
  char message[CTR_MESSAGE_LEN];
  // The input face involved (0-based), or -1.
  int64_t face;
  // The input vertex involved (0-based), or -1.
  int64_t vertex;
  // The line of the file involved (1-based), or -1.
  int64_t line;
} ctr_error;

// Options of [`ctr_simplify`]; start from [`ctr_simplify_options_default`].
typedef struct ctr_simplify_options {
  // `sizeof(ctr_simplify_options)` as the caller was compiled.
  uint32_t size;
  // Edges strictly shorter than ε are contracted: `eps` is ε, or with `eps_relative`
  // its fraction of the diagonal of the bounding box of the vertices the faces use.
  double eps;
  // `eps` is a fraction of the bounding-box diagonal (on by default).
  bool eps_relative;
  // `CTR_SIMPLIFY_NESTED` or `CTR_SIMPLIFY_NAIVE`.
  uint32_t mode;
  // `CTR_SIDE_COUNT`, `CTR_SIDE_PATH` or `CTR_SIDE_EUCLIDEAN`.
  uint32_t side;
  // `CTR_POSITION_MIDPOINT` or `CTR_POSITION_QUADRIC`.
  uint32_t position;
  // Allow contractions that turn a remaining triangle by 90° or more (the fold-over
  // guard off; the topology is kept either way).
  bool allow_foldover;
  // Check the output independently before returning it (on by default).
  bool verify;
} ctr_simplify_options;

// Options of [`ctr_decimate`]; start from [`ctr_decimate_options_default`]. Targets
// combine (the first reached stops the run); with none, the run goes as far as the
// guards allow.
typedef struct ctr_decimate_options {
  // `sizeof(ctr_decimate_options)` as the caller was compiled.
  uint32_t size;
  // `CTR_PLACEMENT_OPTIMAL`, `CTR_PLACEMENT_MIDPOINT` or `CTR_PLACEMENT_ENDPOINT`.
  uint32_t placement;
  // Stop at this many faces (0: no face-count target).
  uint64_t faces;
  // Stop at this fraction of the faces kept, in (0, 1] (0: no such target).
  double keep;
  // Stop before a collapse whose error would exceed this (negative: no cap).
  double max_error;
  // `max_error` is a fraction of the bounding-box diagonal, not a distance.
  bool max_error_relative;
  // Allow collapses that turn a face by 90° or more (the fold-over guard off).
  bool allow_foldover;
  // Keep every boundary vertex where it is.
  bool lock_boundary;
  // Check the output independently before returning it (on by default).
  bool verify;
  // `CTR_SCHEDULE_EXACT` or `CTR_SCHEDULE_PASSES`.
  uint32_t schedule;
  // Input vertices kept where they are: `locked_count` ids (NULL when 0).
  const uint32_t *locked;
  // The number of ids at `locked`.
  size_t locked_count;
} ctr_decimate_options;

// What a decimation did and why it stopped.
typedef struct ctr_decimate_stats {
  // `sizeof(ctr_decimate_stats)` as the caller was compiled (set by
  // [`ctr_decimate_stats_default`]).
  uint32_t size;
  // `CTR_STOPPED_TARGET`, `CTR_STOPPED_ERROR` or `CTR_STOPPED_BLOCKED`.
  uint32_t stopped;
  // Faces of the input.
  uint64_t faces_in;
  // Faces of the output.
  uint64_t faces_out;
  // Vertices of the input that faces use.
  uint64_t vertices_in;
  // Vertices of the output.
  uint64_t vertices_out;
  // Connected components.
  uint64_t components;
  // Edges collapsed.
  uint64_t collapses;
  // The largest error of a collapse (0 without collapses).
  double max_error;
  // Edges left at the end refused by a lock (all `remaining_*` are 0 when the run
  // stopped at its target).
  uint64_t remaining_lock;
  // Edges left on the boundary with the boundary locked.
  uint64_t remaining_boundary;
  // Edges left whose collapse would exceed the error cap.
  uint64_t remaining_error;
  // Edges left that fail the link condition: collapsing them would change the
  // surface.
  uint64_t remaining_link_condition;
  // Edges left that the fold-over guard refuses.
  uint64_t remaining_foldover;
} ctr_decimate_stats;

// What `ctr_describe` finds: counts and topology summed over the components.
typedef struct ctr_description {
  // `sizeof(ctr_description)` as the caller was compiled (set by
  // `ctr_description_default`); no byte past it is written.
  uint32_t size;
  // Connected components.
  uint32_t components;
  // Whether every component is closed (no boundary loop).
  bool closed;
  // Whether every component is orientable.
  bool orientable;
  // Vertices the faces use.
  uint64_t vertices;
  // Edges.
  uint64_t edges;
  // Faces.
  uint64_t faces;
  // Vertices no face uses.
  uint64_t dropped_vertices;
  // χ, summed over the components.
  int64_t euler_characteristic;
  // Boundary loops, summed over the components.
  uint64_t boundary_loops;
} ctr_description;

// Options of [`ctr_quadrangulate`]; start from [`ctr_quad_options_default`].
typedef struct ctr_quad_options {
  // `sizeof(ctr_quad_options)` as the caller was compiled.
  uint32_t size;
  // One of `CTR_QUAD_*`.
  uint32_t algorithm;
  // Seed of the randomised orders of the greedy algorithms (the library's documented
  // random stream).
  uint64_t seed;
  // Check every pairing independently (on by default); a failure is `CTR_FAILURE`
  // with kind `unverified`.
  bool verify;
} ctr_quad_options;

// What a conversion did (the totals over the components).
typedef struct ctr_quad_stats {
  // `sizeof(ctr_quad_stats)` as the caller was compiled (set by
  // [`ctr_quad_stats_default`]).
  uint32_t size;
  // Triangles of the input.
  uint64_t faces;
  // Quads of the output (half the triangles).
  uint64_t quads;
  // Connected components.
  uint64_t components;
  // χ of the input, summed over the components.
  int64_t euler_characteristic;
  // Whether every component is orientable.
  bool orientable;
  // Triangles the initial step left unpaired.
  uint64_t initial_unpaired;
  // Edge flips (LRS only).
  uint64_t flips;
  // Augmenting paths applied by the completion.
  uint64_t augmenting_paths;
} ctr_quad_stats;

// Options of `ctr_reduce`; start from `ctr_reduce_options_default`.
typedef struct ctr_reduce_options {
  // `sizeof(ctr_reduce_options)` as the caller was compiled.
  uint32_t size;
  // `CTR_REDUCE_RS`, `CTR_REDUCE_SCHIPPER` or `CTR_REDUCE_BRUTE`.
  uint32_t algorithm;
  // Seed of the brute force's shuffle (the library's documented random stream).
  uint64_t seed;
  // Check every output independently (on by default); a failure is
  // `CTR_FAILURE` with kind `unverified`.
  bool verify;
  // Keep the contractions (`ctr_reduce_result_contractions`); off, they cost no
  // memory (about 44 bytes per input triangle).
  bool keep_history;
} ctr_reduce_options;

// What a simplification did.
typedef struct ctr_simplify_stats {
  // `sizeof(ctr_simplify_stats)` as the caller was compiled (set by
  // [`ctr_simplify_stats_default`]).
  uint32_t size;
  // The absolute ε used.
  double eps;
  // Faces of the input.
  uint64_t faces_in;
  // Faces of the output.
  uint64_t faces_out;
  // Vertices of the input that faces use.
  uint64_t vertices_in;
  // Vertices of the output.
  uint64_t vertices_out;
  // Connected components.
  uint64_t components;
  // Boundary loops (the same before and after).
  uint64_t boundary_loops;
  // Edges contracted.
  uint64_t edges_contracted;
  // Discs inside 3-cycles replaced by one triangle (nested mode).
  uint64_t discs_removed;
  // Edges shorter than ε left at the end (each one fails the link condition, or its
  // contraction would fold a face over).
  uint64_t short_edges_remaining;
  // The shortest edge of the output (-1 for an output without edges).
  double shortest_remaining_edge;
} ctr_simplify_stats;

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

// `CTR_ABI_VERSION` as the library was built, to compare with the header's at run
// time.
uint32_t ctr_abi_version(void);

// A `ctr_check_failure` with its `size` set, NULL strings and no location.
struct ctr_check_failure ctr_check_failure_default(void);

// Judges `output` as an irreducible triangulation of `input` (the task `reduce`), as
// `contractible::check::reduce`: a closed 2-manifold of the input's surface per
// component, on the input's vertices at their positions, no edge passing the link
// condition. With `history` (not NULL), `2 * history_count` input vertex ids (`kept,
// removed` per contraction, as `ctr_reduce_result_contractions` gives them), each
// contraction must also be valid in turn and replaying them must give the output
// (`check::reduce_history`). The verdict, or NULL on failure: `CTR_INPUT` when `input`
// is no closed surface (which `reduce` must refuse).
//
// # Safety
// `input` and `output` are live meshes; `history` is NULL or points to `2 *
// history_count` ids; `err` is NULL or set up by `ctr_error_init`.
struct ctr_verdict *ctr_check_reduce(const struct ctr_mesh *input, const struct ctr_mesh *output, const uint32_t *history, size_t history_count, struct ctr_error *err);

// Judges `output` as a simplification of `input` by a run with `options` (the options
// given to `ctr_simplify`: ε, the position and the fold-over guard are read; NULL: the
// defaults), as `contractible::check::simplify`: the input's surface per component
// (boundary loops included), a 2-manifold, and no edge shorter than ε left that the
// run could have contracted. The verdict, or NULL on failure: `CTR_INPUT` when `input`
// is no surface or ε is no positive length, `CTR_INVALID_ARGUMENT` for an unknown
// position.
//
// # Safety
// `input` and `output` are live meshes; `options` is NULL or from
// `ctr_simplify_options_default`; `err` is NULL or set up by `ctr_error_init`.
struct ctr_verdict *ctr_check_simplify(const struct ctr_mesh *input, const struct ctr_mesh *output, const struct ctr_simplify_options *options, struct ctr_error *err);

// Judges `quads` (`4 * quad_count` vertex ids of the input) as a tri-quad conversion of
// `input` (the task `quad`), as `contractible::check::quad`: every quad two triangles of
// the paired triangulation K split along a diagonal, every triangle of K in exactly one
// quad, the quad mesh a closed polygon surface of the input's χ per component. K is
// `triangles` (`3 * triangle_count` ids: an algorithm that flips edges must state it),
// or the input's faces when NULL; `pairs` (NULL: inferred) gives per quad the two rows
// of K it joins (`2 * quad_count` ids). The verdict, or NULL on failure: `CTR_INPUT`
// when `input` is no closed surface.
//
// # Safety
// `input` is a live mesh; `quads` points to `4 * quad_count` ids; `triangles` is NULL
// or points to `3 * triangle_count` ids; `pairs` is NULL or points to `2 * quad_count`
// ids; `err` is NULL or set up by `ctr_error_init`.
struct ctr_verdict *ctr_check_quad(const struct ctr_mesh *input, const uint32_t *quads, size_t quad_count, const uint32_t *triangles, size_t triangle_count, const uint32_t *pairs, struct ctr_error *err);

// Judges `output` as a decimation of `input` by a run with `options` (the options given
// to `ctr_decimate`: its targets, cap, placement, guard and locks; NULL: the defaults),
// as `contractible::check::decimate`: the input's surface per component, a face count
// the target explains, locked vertices in place, and the provenance maps where given
// (NULL: not stated) consistent with each other and with the faces: `vertex_map` (per
// output vertex, the input vertex that survives as it), `collapse_map` (per input
// vertex, the output vertex it went into), `face_origin` (per output face, the input
// face it descends from). The verdict, or NULL on failure: `CTR_INPUT` when `input` is
// no surface, has no positions or an option is out of range.
//
// # Safety
// `input` and `output` are live meshes; `options` is NULL or from
// `ctr_decimate_options_default` (its `locked` pointing to `locked_count` ids); each
// map is NULL or holds the count stated; `err` is NULL or set up by `ctr_error_init`.
struct ctr_verdict *ctr_check_decimate(const struct ctr_mesh *input, const struct ctr_mesh *output, const struct ctr_decimate_options *options, const uint32_t *vertex_map, const uint32_t *collapse_map, const uint32_t *face_origin, struct ctr_error *err);

// Whether the output passed (false for NULL).
//
// # Safety
// `verdict` is NULL or a live verdict.
bool ctr_verdict_passed(const struct ctr_verdict *verdict);

// The number of reasons listed (0 when the output passed, or for NULL).
//
// # Safety
// `verdict` is NULL or a live verdict.
size_t ctr_verdict_failure_count(const struct ctr_verdict *verdict);

// Copies reason `index` (0-based, in the order found) into `*out` (made by
// `ctr_check_failure_default`; its strings stay valid until the verdict is freed):
// `CTR_OK`, or `CTR_INVALID_ARGUMENT` for a NULL verdict, an index past the count or an
// `out` of another size.
//
// # Safety
// `verdict` is NULL or a live verdict; `out` points to a `ctr_check_failure` from
// `ctr_check_failure_default`; `err` is NULL or set up by `ctr_error_init`.
int32_t ctr_verdict_failure(const struct ctr_verdict *verdict, size_t index, struct ctr_check_failure *out, struct ctr_error *err);

// Frees a verdict and its strings (NULL is ignored).
//
// # Safety
// `verdict` is NULL or a verdict of a `ctr_check_*` function not freed yet.
void ctr_verdict_free(struct ctr_verdict *verdict);

// The default options: no target (as coarse as the guards allow), optimal placement,
// the exact schedule, the fold-over guard on, nothing locked, the output verified.
struct ctr_decimate_options ctr_decimate_options_default(void);

// A `ctr_decimate_stats` of zeros with its `size` set.
struct ctr_decimate_stats ctr_decimate_stats_default(void);

// Decimates `mesh` (closed or with boundary, orientable or not, several components;
// positions needed): every component keeps its surface (χ, orientability, boundary
// loops), checked before returning. NULL on failure: `CTR_INPUT` for a mesh that is no
// surface (located), no positions, or an option out of range (kind `bad_option`),
// `CTR_INVALID_ARGUMENT` for an unknown placement or schedule.
//
// # Safety
// `mesh` is a live mesh; `options` is NULL (the defaults) or from
// `ctr_decimate_options_default`, its `locked` pointing to `locked_count` ids; `err` is
// NULL or set up by `ctr_error_init`.
struct ctr_decimate_result *ctr_decimate(const struct ctr_mesh *mesh, const struct ctr_decimate_options *options, struct ctr_error *err);

// The output mesh (owned by the result: valid until it is freed, not to be passed to
// `ctr_mesh_free`). NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const struct ctr_mesh *ctr_decimate_result_mesh(const struct ctr_decimate_result *result);

// Per output vertex, the input vertex that survives as it (the output's vertex count
// entries). NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const uint32_t *ctr_decimate_result_vertex_map(const struct ctr_decimate_result *result);

// Per input vertex, the output vertex it went into (`CTR_NO_VERTEX` for a vertex no
// face uses): the input's vertex count entries, to carry any per-vertex attribute
// across. NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const uint32_t *ctr_decimate_result_collapse_map(const struct ctr_decimate_result *result);

// Per output face, the input face it descends from (the output's face count entries).
// NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const uint32_t *ctr_decimate_result_face_origin(const struct ctr_decimate_result *result);

// Copies the statistics into `*out` (made by `ctr_decimate_stats_default`): `CTR_OK`,
// or `CTR_INVALID_ARGUMENT` for a NULL result or an `out` of another size.
//
// # Safety
// `result` is NULL or a live result; `out` points to a `ctr_decimate_stats` from
// `ctr_decimate_stats_default`; `err` is NULL or set up by `ctr_error_init`.
int32_t ctr_decimate_result_stats(const struct ctr_decimate_result *result, struct ctr_decimate_stats *out, struct ctr_error *err);

// Frees a result and the mesh it owns (NULL is ignored).
//
// # Safety
// `result` is NULL or a result of `ctr_decimate` not freed yet.
void ctr_decimate_result_free(struct ctr_decimate_result *result);

// A `ctr_description` of zeros with its `size` set: pass it to `ctr_describe`.
struct ctr_description ctr_description_default(void);

// Describes `mesh` into `*out`: `CTR_OK` (0) when its faces form a union of surfaces
// (closed or with boundary, orientable or not); otherwise `CTR_INPUT` with the first
// problem the validation meets in `err` (its kind, such as `non_manifold_edge`, and its
// face or vertex) and `*out` untouched.
//
// # Safety
// `mesh` is a live mesh; `out` points to a `ctr_description` from
// `ctr_description_default`; `err` is NULL or set up by `ctr_error_init`.
int32_t ctr_describe(const struct ctr_mesh *mesh, struct ctr_description *out, struct ctr_error *err);

// Sets `*err` to "no error" with `size = sizeof(ctr_error)`; call it once before
// passing `err` to the library. NULL is ignored.
//
// # Safety
// `err` is NULL or points to a writable `ctr_error`.
void ctr_error_init(struct ctr_error *err);

// A mesh from flat arrays, copied: `positions` holds `3 * vertex_count` coordinates
// (x, y, z per vertex; NULL for a mesh without positions), `faces` holds `3 *
// face_count` vertex indices. The faces are not checked here: each task checks them
// and reports the first defect with its face or vertex. NULL on failure
// (`CTR_INVALID_ARGUMENT` for a NULL or misaligned array with a nonzero count).
//
// # Safety
// `positions` (when not NULL) and `faces` point to arrays of the stated lengths; `err`
// is NULL or a `ctr_error` set up by `ctr_error_init`.
struct ctr_mesh *ctr_mesh_new(const double *positions, size_t vertex_count, const uint32_t *faces, size_t face_count, struct ctr_error *err);

// A mesh over the caller's flat arrays, read in place: as `ctr_mesh_new` but without
// the copy, for large meshes (the copy costs about a tenth of a `ctr_reduce` on 4 million
// triangles). `ctr_reduce` and `ctr_quadrangulate` read the arrays where they are;
// the other functions copy them for the call. The arrays must stay valid and
// unchanged until the mesh is freed. NULL on failure (`CTR_INVALID_ARGUMENT` for a
// NULL or misaligned array with a nonzero count).
//
// # Safety
// `positions` (when not NULL) and `faces` point to arrays of the stated lengths that
// stay valid and unchanged until `ctr_mesh_free`; `err` is NULL or set up by
// `ctr_error_init`.
struct ctr_mesh *ctr_mesh_borrow(const double *positions, size_t vertex_count, const uint32_t *faces, size_t face_count, struct ctr_error *err);

// The mesh of a file (`.off`, `.obj`, `.ply`, `.stl`, optionally gzip-compressed as
// `.gz`; by the extension, else by the content): triangles only, as written. NULL on
// failure: `CTR_INPUT` for a file that cannot be opened or parsed (kind `io` or
// `read`, with its line when known).
//
// # Safety
// `path` is a NUL-terminated UTF-8 string; `err` is NULL or set up by `ctr_error_init`.
struct ctr_mesh *ctr_mesh_read(const char *path, struct ctr_error *err);

// Writes `mesh` to a file in the format of its extension (`.off`, `.obj`, `.ply`,
// `.stl`, optionally `.gz`), atomically: on failure nothing is left at `path`. Returns
// `CTR_OK` (0) or the error's code (`CTR_FAILURE` when the file cannot be written).
//
// # Safety
// `mesh` is a live mesh; `path` a NUL-terminated UTF-8 string; `err` NULL or set up by
// `ctr_error_init`.
int32_t ctr_mesh_write(const struct ctr_mesh *mesh, const char *path, struct ctr_error *err);

// The number of vertices (0 for NULL).
//
// # Safety
// `mesh` is NULL or a live mesh.
size_t ctr_mesh_vertex_count(const struct ctr_mesh *mesh);

// The number of faces (0 for NULL).
//
// # Safety
// `mesh` is NULL or a live mesh.
size_t ctr_mesh_face_count(const struct ctr_mesh *mesh);

// The positions, `3 * vertex_count` coordinates, or NULL when the mesh has none (or is
// NULL). Valid until the mesh (or the result that owns it) is freed.
//
// # Safety
// `mesh` is NULL or a live mesh.
const double *ctr_mesh_positions(const struct ctr_mesh *mesh);

// The faces, `3 * face_count` vertex indices (NULL for a NULL mesh; a valid pointer to
// nothing when there are no faces). Valid until the mesh (or the result that owns it)
// is freed.
//
// # Safety
// `mesh` is NULL or a live mesh.
const uint32_t *ctr_mesh_faces(const struct ctr_mesh *mesh);

// Frees a mesh made by `ctr_mesh_new`, `ctr_mesh_borrow` or `ctr_mesh_read` (NULL is
// ignored; the arrays a borrowing mesh reads stay the caller's). A mesh a result owns is
// freed with its result, not here.
//
// # Safety
// `mesh` is NULL or a mesh from `ctr_mesh_new`/`ctr_mesh_borrow`/`ctr_mesh_read` not
// freed yet.
void ctr_mesh_free(struct ctr_mesh *mesh);

// The default options: LRS, seed 0, outputs verified.
struct ctr_quad_options ctr_quad_options_default(void);

// A `ctr_quad_stats` of zeros with its `size` set.
struct ctr_quad_stats ctr_quad_stats_default(void);

// Pairs the triangles of every component of the closed surface `mesh` into quads, as
// `contractible::quadrangulate`: every triangle of the paired triangulation K (the
// input's faces, except where LRS flipped an edge) in exactly one quad. NULL on
// failure: `CTR_INPUT` for a mesh that is no closed surface (the first defect,
// located) or an odd face count (kind `odd_faces`), `CTR_INVALID_ARGUMENT` for an
// unknown algorithm.
//
// # Safety
// `mesh` is a live mesh; `options` is NULL (the defaults) or from
// `ctr_quad_options_default`; `err` is NULL or set up by `ctr_error_init`.
struct ctr_quad_result *ctr_quadrangulate(const struct ctr_mesh *mesh, const struct ctr_quad_options *options, struct ctr_error *err);

// The quads, `4 * *count` vertex ids of the input (each quad the cycle around its two
// triangles, so consistently oriented triangles give consistently oriented quads), per
// component one quad per pair in increasing order of the pair's smaller face. NULL
// (and `*count` 0) for a NULL result.
//
// # Safety
// `result` is NULL or a live result; `count` is NULL or writable.
const uint32_t *ctr_quad_result_quads(const struct ctr_quad_result *result, size_t *count);

// The paired triangulation K, `3 * *count` vertex ids, one row per input face: the
// input's faces, except those LRS's flips changed. NULL (and `*count` 0) for a NULL
// result.
//
// # Safety
// `result` is NULL or a live result; `count` is NULL or writable.
const uint32_t *ctr_quad_result_triangles(const struct ctr_quad_result *result, size_t *count);

// The pairs, `2 * *count` rows of the triangulation K, in the order of the quads. NULL
// (and `*count` 0) for a NULL result.
//
// # Safety
// `result` is NULL or a live result; `count` is NULL or writable.
const uint32_t *ctr_quad_result_pairs(const struct ctr_quad_result *result, size_t *count);

// Copies the statistics into `*out` (made by `ctr_quad_stats_default`): `CTR_OK`, or
// `CTR_INVALID_ARGUMENT` for a NULL result or an `out` of another size.
//
// # Safety
// `result` is NULL or a live result; `out` points to a `ctr_quad_stats` from
// `ctr_quad_stats_default`; `err` is NULL or set up by `ctr_error_init`.
int32_t ctr_quad_result_stats(const struct ctr_quad_result *result, struct ctr_quad_stats *out, struct ctr_error *err);

// Writes the quad mesh (the input's vertices and positions, the quads) to a file in the
// format of its extension (`.off`, `.obj`, `.ply`, optionally `.gz`; STL holds
// triangles only and is refused), atomically. `CTR_OK` or the error's code.
//
// # Safety
// `result` is a live result; `path` a NUL-terminated UTF-8 string; `err` NULL or set up
// by `ctr_error_init`.
int32_t ctr_quad_result_write(const struct ctr_quad_result *result, const char *path, struct ctr_error *err);

// Frees a result (NULL is ignored).
//
// # Safety
// `result` is NULL or a result of `ctr_quadrangulate` not freed yet.
void ctr_quad_result_free(struct ctr_quad_result *result);

// The default options: RS, seed 0, outputs verified, no history.
struct ctr_reduce_options ctr_reduce_options_default(void);

// Reduces every component of the closed surface `mesh` to an irreducible triangulation
// (no edge passes the link condition), as `contractible::reduce`. NULL on failure:
// `CTR_INPUT` for a mesh that is no closed surface (the first defect, located)
// or a bad option, `CTR_INVALID_ARGUMENT` for an unknown algorithm.
//
// # Safety
// `mesh` is a live mesh; `options` is NULL (the defaults) or from
// `ctr_reduce_options_default`; `err` is NULL or set up by `ctr_error_init`.
struct ctr_reduce_result *ctr_reduce(const struct ctr_mesh *mesh, const struct ctr_reduce_options *options, struct ctr_error *err);

// The output mesh: the survivors (renumbered in increasing input order, with their
// input positions) and the faces, component by component. Owned by the result: valid
// until it is freed, not to be passed to `ctr_mesh_free`. NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const struct ctr_mesh *ctr_reduce_result_mesh(const struct ctr_reduce_result *result);

// The input vertex of each output vertex (`ctr_mesh_vertex_count` of the output
// entries). NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const uint32_t *ctr_reduce_result_vertex_map(const struct ctr_reduce_result *result);

// The contractions, `2 * *count` input vertex ids (`kept, removed` each, oldest first,
// component by component), as `contractible check reduce --history` replays them; `*count`
// is 0 unless the options kept the history. NULL (and `*count` 0) for a NULL result.
//
// # Safety
// `result` is NULL or a live result; `count` is NULL or writable.
const uint32_t *ctr_reduce_result_contractions(const struct ctr_reduce_result *result, size_t *count);

// The number of connected components reduced (0 for a NULL result).
//
// # Safety
// `result` is NULL or a live result.
size_t ctr_reduce_result_component_count(const struct ctr_reduce_result *result);

// Frees a result and the mesh it owns (NULL is ignored).
//
// # Safety
// `result` is NULL or a result of `ctr_reduce` not freed yet.
void ctr_reduce_result_free(struct ctr_reduce_result *result);

// The default options, those of `contractible::simplify`: ε 1 % of the bounding-box
// diagonal, the nested mode, the count heuristic, midpoints, the fold-over guard on,
// the output verified.
struct ctr_simplify_options ctr_simplify_options_default(void);

// A `ctr_simplify_stats` of zeros with its `size` set.
struct ctr_simplify_stats ctr_simplify_stats_default(void);

// Contracts every edge of `mesh` shorter than ε whose contraction keeps the surface
// (closed or with boundary, orientable or not, several components; positions needed),
// as `contractible::simplify`; the output keeps every component's surface (χ,
// orientability, boundary loops), checked before returning. NULL on failure:
// `CTR_INPUT` for a mesh that is no surface (located), no positions, or an ε that is
// not a finite positive length (kind `bad_option`), `CTR_INVALID_ARGUMENT` for an
// unknown mode, side or position.
//
// # Safety
// `mesh` is a live mesh; `options` is NULL (the defaults) or from
// `ctr_simplify_options_default`; `err` is NULL or set up by `ctr_error_init`.
struct ctr_simplify_result *ctr_simplify(const struct ctr_mesh *mesh, const struct ctr_simplify_options *options, struct ctr_error *err);

// The output mesh: the vertices left of every component with their positions,
// component by component (in the order of their smallest input face), each in input
// vertex order. Owned by the result: valid until it is freed, not to be passed to
// `ctr_mesh_free`. NULL for a NULL result.
//
// # Safety
// `result` is NULL or a live result.
const struct ctr_mesh *ctr_simplify_result_mesh(const struct ctr_simplify_result *result);

// Copies the statistics into `*out` (made by `ctr_simplify_stats_default`): `CTR_OK`,
// or `CTR_INVALID_ARGUMENT` for a NULL result or an `out` of another size.
//
// # Safety
// `result` is NULL or a live result; `out` points to a `ctr_simplify_stats` from
// `ctr_simplify_stats_default`; `err` is NULL or set up by `ctr_error_init`.
int32_t ctr_simplify_result_stats(const struct ctr_simplify_result *result, struct ctr_simplify_stats *out, struct ctr_error *err);

// Frees a result and the mesh it owns (NULL is ignored).
//
// # Safety
// `result` is NULL or a result of `ctr_simplify` not freed yet.
void ctr_simplify_result_free(struct ctr_simplify_result *result);

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* CONTRACTIBLE_H */
