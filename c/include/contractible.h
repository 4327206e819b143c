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

// Ramaswami–Siqueira's algorithm (the default).
#define CTR_REDUCE_RS 0

// Schipper's algorithm.
#define CTR_REDUCE_SCHIPPER 1

// The randomised brute force (its order from `seed`).
#define CTR_REDUCE_BRUTE 2

// A triangle mesh: `vertex_count` vertices (with a position each, or none) and faces of
// three vertex indices (0-based). Opaque: made by `ctr_mesh_new` or `ctr_mesh_read`
// (or returned by a result's accessor, then owned by that result), freed by
// `ctr_mesh_free`.
typedef struct ctr_mesh ctr_mesh;

// The result of `ctr_reduce`: the irreducible triangulations (one mesh), the input
// vertex of each output vertex, the contractions when kept. Opaque; freed by
// `ctr_reduce_result_free`.
typedef struct ctr_reduce_result ctr_reduce_result;

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

#ifdef __cplusplus
extern "C" {
#endif // __cplusplus

// `CTR_ABI_VERSION` as the library was built, to compare with the header's at run
// time.
uint32_t ctr_abi_version(void);

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

// Frees a mesh made by `ctr_mesh_new` or `ctr_mesh_read` (NULL is ignored). A mesh
// a result owns is freed with its result, not here.
//
// # Safety
// `mesh` is NULL or a mesh from `ctr_mesh_new`/`ctr_mesh_read` not freed yet.
void ctr_mesh_free(struct ctr_mesh *mesh);

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

#ifdef __cplusplus
}  // extern "C"
#endif  // __cplusplus

#endif  /* CONTRACTIBLE_H */
