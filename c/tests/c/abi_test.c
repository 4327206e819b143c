/* The C ABI from C: every function on a right call and on each kind of wrong one (NULL
 * and misaligned pointers, options of an unknown size, unknown algorithms, meshes the
 * task refuses, files that cannot be read or written), the error's kind and location,
 * and a shorter (older) error struct left intact past its size. Prints one line per
 * failed check; exit 0 when all pass. Run by c/tests/c_programs.rs, also under
 * valgrind. Argument: a scratch directory. */
#include <stddef.h>
#include <stdio.h>
#include <string.h>
#include "contractible.h"

static int failures = 0, checks = 0;
#define CHECK(cond)                                                      \
    do {                                                                 \
        checks++;                                                        \
        if (!(cond)) {                                                   \
            failures++;                                                  \
            fprintf(stderr, "abi_test.c:%d: failed: %s\n", __LINE__, #cond); \
        }                                                                \
    } while (0)

static const double octahedron_positions[18] = {1, 0, 0, -1, 0, 0, 0, 1, 0,
                                                0, -1, 0, 0, 0, 1, 0, 0, -1};
static const uint32_t octahedron_faces[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                              2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

static void on_arrays(void) {
    ctr_error err;
    ctr_error_init(&err);
    CHECK(err.size == sizeof(ctr_error) && err.code == CTR_OK && err.face == -1);
    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    CHECK(m != NULL && err.code == CTR_OK);
    CHECK(ctr_mesh_vertex_count(m) == 6 && ctr_mesh_face_count(m) == 8);
    CHECK(ctr_mesh_positions(m)[3] == -1.0 && ctr_mesh_faces(m)[23] == 5);

    ctr_description d = ctr_description_default();
    CHECK(ctr_describe(m, &d, &err) == 0 && err.code == CTR_OK);
    CHECK(d.components == 1 && d.closed && d.orientable && d.euler_characteristic == 2);
    CHECK(d.vertices == 6 && d.edges == 12 && d.faces == 8 && d.boundary_loops == 0);

    ctr_reduce_options o = ctr_reduce_options_default();
    CHECK(o.size == sizeof o && o.algorithm == CTR_REDUCE_RS && o.verify && !o.keep_history);
    o.keep_history = true;
    ctr_reduce_result *r = ctr_reduce(m, &o, &err);
    CHECK(r != NULL && err.code == CTR_OK);
    const ctr_mesh *out = ctr_reduce_result_mesh(r);
    CHECK(ctr_mesh_vertex_count(out) == 4 && ctr_mesh_face_count(out) == 4);
    CHECK(ctr_reduce_result_component_count(r) == 1);
    const uint32_t *map = ctr_reduce_result_vertex_map(r);
    for (size_t v = 0; v < 4; v++) {
        /* Each survivor keeps its input position. */
        CHECK(ctr_mesh_positions(out)[3 * v] == octahedron_positions[3 * map[v]]);
    }
    size_t n = 99;
    const uint32_t *steps = ctr_reduce_result_contractions(r, &n);
    CHECK(n == 2 && steps != NULL && steps[0] != steps[1]);
    ctr_reduce_result_free(r);

    /* Without the history: none. The brute force with a seed, NULL error. */
    o = ctr_reduce_options_default();
    o.algorithm = CTR_REDUCE_BRUTE;
    o.seed = 3;
    r = ctr_reduce(m, &o, NULL);
    CHECK(r != NULL);
    n = 99;
    CHECK(ctr_reduce_result_contractions(r, &n) != NULL && n == 0);
    ctr_reduce_result_free(r);
    r = ctr_reduce(m, NULL, &err);
    CHECK(r != NULL && err.code == CTR_OK);

    /* A mesh over the caller's arrays, read in place: the same answers. */
    ctr_mesh *b = ctr_mesh_borrow(octahedron_positions, 6, octahedron_faces, 8, &err);
    CHECK(b != NULL && err.code == CTR_OK);
    CHECK(ctr_mesh_positions(b) == octahedron_positions && ctr_mesh_faces(b) == octahedron_faces);
    CHECK(ctr_mesh_vertex_count(b) == 6 && ctr_mesh_face_count(b) == 8);
    ctr_reduce_result *rb = ctr_reduce(b, NULL, &err);
    CHECK(rb != NULL && err.code == CTR_OK);
    const ctr_mesh *x = ctr_reduce_result_mesh(r), *y = ctr_reduce_result_mesh(rb);
    CHECK(ctr_mesh_face_count(x) == ctr_mesh_face_count(y));
    CHECK(memcmp(ctr_mesh_faces(x), ctr_mesh_faces(y), 3 * sizeof(uint32_t) * ctr_mesh_face_count(x)) == 0);
    CHECK(memcmp(ctr_reduce_result_vertex_map(r), ctr_reduce_result_vertex_map(rb),
                 sizeof(uint32_t) * ctr_mesh_vertex_count(x)) == 0);
    ctr_reduce_result_free(rb);
    ctr_description db = ctr_description_default();
    CHECK(ctr_describe(b, &db, &err) == CTR_OK && db.euler_characteristic == 2 && db.faces == 8);
    ctr_quad_result *qb = ctr_quadrangulate(b, NULL, &err);
    CHECK(qb != NULL && err.code == CTR_OK);
    ctr_quad_result_free(qb);
    ctr_mesh_free(b);
    /* Without positions, and empty: fine; a NULL or misaligned array with a count: refused. */
    b = ctr_mesh_borrow(NULL, 6, octahedron_faces, 8, &err);
    CHECK(b != NULL && ctr_mesh_positions(b) == NULL);
    ctr_mesh_free(b);
    b = ctr_mesh_borrow(NULL, 0, NULL, 0, &err);
    CHECK(b != NULL && ctr_mesh_face_count(b) == 0 && ctr_mesh_faces(b) != NULL);
    CHECK(ctr_reduce(b, NULL, &err) == NULL && err.code == CTR_INPUT);
    ctr_mesh_free(b);
    CHECK(ctr_mesh_borrow(octahedron_positions, 6, NULL, 8, &err) == NULL);
    CHECK(err.code == CTR_INVALID_ARGUMENT && strstr(err.message, "faces is NULL") != NULL);
    CHECK(ctr_mesh_borrow((const double *)((const char *)octahedron_positions + 4), 6,
                          octahedron_faces, 8, &err) == NULL);
    CHECK(err.code == CTR_INVALID_ARGUMENT && strstr(err.message, "aligned") != NULL);
    ctr_reduce_result_free(r);
    ctr_mesh_free(m);
}

static void wrong_calls(void) {
    ctr_error err;
    ctr_error_init(&err);
    /* NULL arrays with counts, a misaligned one. */
    CHECK(ctr_mesh_new(NULL, 6, NULL, 8, &err) == NULL);
    CHECK(err.code == CTR_INVALID_ARGUMENT && strcmp(err.kind, "invalid_argument") == 0);
    CHECK(strstr(err.message, "faces is NULL") != NULL);
    CHECK(err.face == -1 && err.vertex == -1 && err.line == -1);
    uint32_t buffer[32];
    const uint32_t *odd = (const uint32_t *)((const char *)buffer + 1);
    CHECK(ctr_mesh_new(NULL, 6, odd, 8, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(strstr(err.message, "aligned") != NULL);
    CHECK(ctr_mesh_new(NULL, 0, NULL, (size_t)-1, &err) == NULL);
    CHECK(err.code == CTR_INVALID_ARGUMENT);
    /* An empty mesh is a mesh; reducing it is refused as the input's fault. */
    ctr_mesh *empty = ctr_mesh_new(NULL, 0, NULL, 0, &err);
    CHECK(empty != NULL && err.code == CTR_OK);
    CHECK(ctr_reduce(empty, NULL, &err) == NULL && err.code == CTR_INPUT);
    ctr_mesh_free(empty);
    /* NULL handles. */
    CHECK(ctr_reduce(NULL, NULL, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(ctr_mesh_vertex_count(NULL) == 0 && ctr_mesh_faces(NULL) == NULL);
    CHECK(ctr_reduce_result_mesh(NULL) == NULL && ctr_reduce_result_vertex_map(NULL) == NULL);
    size_t n = 5;
    CHECK(ctr_reduce_result_contractions(NULL, &n) == NULL && n == 0);
    ctr_mesh_free(NULL);
    ctr_reduce_result_free(NULL);
    ctr_error_init(NULL);

    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    /* Options of an unknown size, an unknown algorithm. */
    ctr_reduce_options o = ctr_reduce_options_default();
    o.size = sizeof o + 8;
    CHECK(ctr_reduce(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(strstr(err.message, "options.size") != NULL);
    o = ctr_reduce_options_default();
    o.algorithm = 7;
    CHECK(ctr_reduce(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(strstr(err.message, "algorithm is 7") != NULL);
    /* An older, shorter options struct: the fields it has, defaults for the rest. */
    o = ctr_reduce_options_default();
    o.size = offsetof(ctr_reduce_options, seed);
    o.algorithm = CTR_REDUCE_SCHIPPER;
    ctr_reduce_result *r = ctr_reduce(m, &o, &err);
    CHECK(r != NULL && err.code == CTR_OK);
    ctr_reduce_result_free(r);
    ctr_description d = ctr_description_default();
    d.size = 8;
    CHECK(ctr_describe(m, &d, &err) == CTR_INVALID_ARGUMENT && err.code == CTR_INVALID_ARGUMENT);
    ctr_mesh_free(m);

    /* An open surface: reduce refuses it with the boundary edge's face. */
    m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 7, &err);
    CHECK(ctr_reduce(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "boundary_edge") == 0 && err.face >= 0 && err.face < 7);
    d = ctr_description_default();
    CHECK(ctr_describe(m, &d, &err) == 0 && !d.closed && d.boundary_loops == 1);
    ctr_mesh_free(m);
    /* A non-manifold edge: three faces on [0, 2]. */
    uint32_t faces[27];
    memcpy(faces, octahedron_faces, sizeof octahedron_faces);
    faces[24] = 0, faces[25] = 2, faces[26] = 1;
    m = ctr_mesh_new(NULL, 6, faces, 9, &err);
    CHECK(ctr_reduce(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "non_manifold_edge") == 0 && err.face >= 0);
    CHECK(ctr_describe(m, &d, &err) == CTR_INPUT && err.code == CTR_INPUT);
    /* A face beyond the vertices: located by face and vertex. */
    faces[26] = 6;
    ctr_mesh_free(m);
    m = ctr_mesh_new(NULL, 6, faces, 9, &err);
    CHECK(ctr_reduce(m, NULL, &err) == NULL && strcmp(err.kind, "vertex_out_of_range") == 0);
    CHECK(err.face == 8 && err.vertex == 6);
    ctr_mesh_free(m);

    /* A pinched vertex (two tetrahedra sharing vertex 0): located by the vertex. */
    static const uint32_t pinched[24] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2,
                                         0, 4, 5, 0, 6, 4, 0, 5, 6, 4, 6, 5};
    m = ctr_mesh_new(NULL, 7, pinched, 8, &err);
    CHECK(ctr_reduce(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(err.vertex == 0 && err.face == -1 && err.line == -1);
    ctr_mesh_free(m);
    /* A coordinate that is not finite: located by its vertex. */
    double bad[18];
    memcpy(bad, octahedron_positions, sizeof bad);
    bad[3 * 4 + 1] = 1.0 / 0.0;
    m = ctr_mesh_new(bad, 6, octahedron_faces, 8, &err);
    CHECK(ctr_simplify(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "non_finite_coordinate") == 0 && err.vertex == 4 && err.face == -1);
    ctr_mesh_free(m);
    /* A message longer than the struct holds is cut at a UTF-8 character boundary: a path of
     * two-byte characters, at two offsets so that one of them ends mid-character. */
    for (int offset = 0; offset < 2; offset++) {
        char path[2000] = "/nonexistent/";
        size_t n = strlen(path);
        if (offset) path[n++] = 'a';
        for (int i = 0; i < 600; i++) {
            path[n++] = (char)0xc3;
            path[n++] = (char)0xa9; /* U+00E9 */
            if (i % 100 == 99) path[n++] = '/';
        }
        strcpy(path + n, "x.off");
        CHECK(ctr_mesh_read(path, &err) == NULL && err.code == CTR_INPUT);
        size_t len = strlen(err.message);
        CHECK(len >= CTR_MESSAGE_LEN - 2 && len <= CTR_MESSAGE_LEN - 1);
        CHECK((unsigned char)err.message[len - 1] != 0xc3);
    }

    /* A shorter, older error struct: nothing written past its size. */
    struct {
        ctr_error e;
        char canary[8];
    } older;
    memset(&older, 0x5a, sizeof older);
    older.e.size = offsetof(ctr_error, message);
    CHECK(ctr_reduce(NULL, NULL, &older.e) == NULL && older.e.code == CTR_INVALID_ARGUMENT);
    CHECK(strcmp(older.e.kind, "invalid_argument") == 0);
    CHECK((unsigned char)older.e.message[0] == 0x5a && older.e.face == 0x5a5a5a5a5a5a5a5aLL);
    /* Success clears an earlier error. */
    m = ctr_mesh_new(NULL, 0, NULL, 0, &err);
    CHECK(err.code == CTR_OK && err.kind[0] == 0 && err.face == -1);
    ctr_mesh_free(m);
}

static void files(const char *dir) {
    ctr_error err;
    ctr_error_init(&err);
    char path[4096];
    snprintf(path, sizeof path, "%s/missing.off", dir);
    CHECK(ctr_mesh_read(path, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "io") == 0);
    snprintf(path, sizeof path, "%s/broken.off", dir);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f) {
        fputs("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n", f);
        fclose(f);
    }
    CHECK(ctr_mesh_read(path, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "read") == 0 && err.line == 6);
    CHECK(ctr_mesh_read(NULL, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);

    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    snprintf(path, sizeof path, "%s/octahedron.ply", dir);
    CHECK(ctr_mesh_write(m, path, &err) == 0 && err.code == CTR_OK);
    ctr_mesh *back = ctr_mesh_read(path, &err);
    CHECK(back != NULL && ctr_mesh_face_count(back) == 8);
    CHECK(back && memcmp(ctr_mesh_faces(back), octahedron_faces, sizeof octahedron_faces) == 0);
    CHECK(back && memcmp(ctr_mesh_positions(back), octahedron_positions,
                         sizeof octahedron_positions) == 0);
    ctr_mesh_free(back);
    snprintf(path, sizeof path, "%s/no/such/dir/x.off", dir);
    CHECK(ctr_mesh_write(m, path, &err) == CTR_FAILURE && err.code == CTR_FAILURE);
    CHECK(strcmp(err.kind, "write") == 0 && strstr(err.message, "no/such/dir") != NULL);
    ctr_mesh_free(m);
}

static void decimation(void) {
    ctr_error err;
    ctr_error_init(&err);
    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    ctr_decimate_options o = ctr_decimate_options_default();
    CHECK(o.size == sizeof o && o.placement == CTR_PLACEMENT_OPTIMAL && o.max_error < 0);
    CHECK(o.verify && !o.allow_foldover && o.locked == NULL && o.locked_count == 0);
    o.faces = 4;
    o.allow_foldover = true;
    o.placement = CTR_PLACEMENT_ENDPOINT;
    ctr_decimate_result *r = ctr_decimate(m, &o, &err);
    CHECK(r != NULL && err.code == CTR_OK);
    ctr_decimate_stats s = ctr_decimate_stats_default();
    CHECK(ctr_decimate_result_stats(r, &s, &err) == CTR_OK);
    CHECK(s.faces_in == 8 && s.faces_out == 4 && s.stopped == CTR_STOPPED_TARGET);
    CHECK(s.vertices_in == 6 && s.vertices_out == 4 && s.collapses == 2 && s.components == 1);
    const ctr_mesh *out = ctr_decimate_result_mesh(r);
    CHECK(ctr_mesh_face_count(out) == 4 && ctr_mesh_vertex_count(out) == 4);
    const uint32_t *vm = ctr_decimate_result_vertex_map(r);
    const uint32_t *cm = ctr_decimate_result_collapse_map(r);
    const uint32_t *fo = ctr_decimate_result_face_origin(r);
    for (size_t v = 0; v < 4; v++) {
        /* A survivor goes into itself; endpoint placement keeps input positions. */
        CHECK(vm[v] < 6 && cm[vm[v]] == v);
        CHECK(memcmp(ctr_mesh_positions(out) + 3 * v, octahedron_positions + 3 * vm[v],
                     3 * sizeof(double)) == 0);
    }
    for (size_t v = 0; v < 6; v++) CHECK(cm[v] < 4);
    for (size_t f = 0; f < 4; f++) CHECK(fo[f] < 8);
    ctr_decimate_result_free(r);

    /* As coarse as the guards allow, a vertex locked: blocked, the reasons counted. */
    o = ctr_decimate_options_default();
    uint32_t locked[1] = {0};
    o.locked = locked;
    o.locked_count = 1;
    r = ctr_decimate(m, &o, &err);
    CHECK(r != NULL && ctr_decimate_result_stats(r, &s, &err) == CTR_OK);
    CHECK(s.stopped == CTR_STOPPED_BLOCKED && s.remaining_link_condition > 0);
    CHECK(ctr_decimate_result_collapse_map(r)[0] != CTR_NO_VERTEX);
    ctr_decimate_result_free(r);

    /* Wrong calls. */
    o = ctr_decimate_options_default();
    o.placement = 9;
    CHECK(ctr_decimate(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    o = ctr_decimate_options_default();
    o.schedule = 5;
    CHECK(ctr_decimate(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    o = ctr_decimate_options_default();
    o.locked_count = 3;
    CHECK(ctr_decimate(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    o = ctr_decimate_options_default();
    o.keep = 2.0;
    CHECK(ctr_decimate(m, &o, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "bad_option") == 0);
    CHECK(err.face == -1 && err.vertex == -1 && err.line == -1);
    s.size = 12;
    CHECK(ctr_decimate_result_stats(NULL, &s, &err) == CTR_INVALID_ARGUMENT);
    CHECK(ctr_decimate_result_mesh(NULL) == NULL && ctr_decimate_result_collapse_map(NULL) == NULL);
    ctr_decimate_result_free(NULL);
    ctr_mesh_free(m);
    /* No positions: the input's fault. */
    m = ctr_mesh_new(NULL, 6, octahedron_faces, 8, &err);
    CHECK(ctr_decimate(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "missing_positions") == 0);
    ctr_mesh_free(m);
}

static void quadrangulation(void) {
    ctr_error err;
    ctr_error_init(&err);
    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    ctr_quad_options o = ctr_quad_options_default();
    CHECK(o.size == sizeof o && o.algorithm == CTR_QUAD_LRS && o.seed == 0 && o.verify);
    for (uint32_t a = CTR_QUAD_LRS; a <= CTR_QUAD_DS_NAIVE; a++) {
        o.algorithm = a;
        ctr_quad_result *r = ctr_quadrangulate(m, &o, &err);
        CHECK(r != NULL && err.code == CTR_OK);
        size_t quads = 0, triangles = 0, pairs = 0;
        const uint32_t *q = ctr_quad_result_quads(r, &quads);
        const uint32_t *t = ctr_quad_result_triangles(r, &triangles);
        const uint32_t *p = ctr_quad_result_pairs(r, &pairs);
        CHECK(quads == 4 && triangles == 8 && pairs == 4 && q && t && p);
        /* Every row of K in exactly one pair; every quad on four distinct vertices. */
        int used[8] = {0};
        for (size_t i = 0; i < 8; i++) CHECK(p[i] < 8 && ++used[p[i]] == 1);
        for (size_t i = 0; i < 4; i++)
            CHECK(q[4 * i] != q[4 * i + 2] && q[4 * i + 1] != q[4 * i + 3] && q[4 * i] < 6);
        ctr_quad_stats s = ctr_quad_stats_default();
        CHECK(ctr_quad_result_stats(r, &s, &err) == CTR_OK);
        CHECK(s.faces == 8 && s.quads == 4 && s.components == 1);
        CHECK(s.euler_characteristic == 2 && s.orientable);
        /* The checker passes it, with and without the stated pairs. */
        ctr_verdict *v = ctr_check_quad(m, q, quads, t, triangles, p, &err);
        CHECK(v != NULL && ctr_verdict_passed(v) && ctr_verdict_failure_count(v) == 0);
        ctr_verdict_free(v);
        v = ctr_check_quad(m, q, quads, t, triangles, NULL, &err);
        CHECK(v != NULL && ctr_verdict_passed(v));
        ctr_verdict_free(v);
        ctr_quad_result_free(r);
    }
    ctr_quad_result *r = ctr_quadrangulate(m, NULL, &err);
    char path[4096];
    snprintf(path, sizeof path, "/nonexistent-dir-of-abi-test/q.obj");
    CHECK(ctr_quad_result_write(r, path, &err) == CTR_FAILURE && strcmp(err.kind, "write") == 0);
    /* A quad given twice pairs its triangles twice. */
    size_t quads = 0, triangles = 0;
    uint32_t q[16];
    memcpy(q, ctr_quad_result_quads(r, &quads), sizeof q);
    memcpy(q + 4, q, 4 * sizeof *q);
    const uint32_t *k = ctr_quad_result_triangles(r, &triangles);
    ctr_verdict *v = ctr_check_quad(m, q, 4, k, triangles, NULL, &err);
    CHECK(v != NULL && !ctr_verdict_passed(v) && ctr_verdict_failure_count(v) >= 1);
    ctr_check_failure f = ctr_check_failure_default();
    CHECK(f.size == sizeof f && f.kind == NULL && f.message == NULL && f.face == -1);
    CHECK(f.edge_from == -1 && f.edge_to == -1 && f.vertex == -1 && f.component == -1);
    CHECK(ctr_verdict_failure(v, 0, &f, &err) == CTR_OK);
    CHECK(strcmp(f.kind, "triangle_used_twice") == 0 && strlen(f.message) > 0);
    /* A stated triangle, not an output face, edge or vertex: no location. */
    CHECK(f.face == -1 && f.edge_from == -1 && f.edge_to == -1 && f.vertex == -1);
    CHECK(f.component == -1 && f.size == sizeof f);
    CHECK(ctr_verdict_failure(v, 99, &f, &err) == CTR_INVALID_ARGUMENT);
    f.size = 4;
    CHECK(ctr_verdict_failure(v, 0, &f, &err) == CTR_INVALID_ARGUMENT);
    ctr_verdict_free(v);
    ctr_quad_result_free(r);

    /* Wrong calls: an unknown algorithm, an odd face count, NULL handles. */
    o = ctr_quad_options_default();
    o.algorithm = 8;
    CHECK(ctr_quadrangulate(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(ctr_check_quad(m, NULL, 4, NULL, 0, NULL, &err) == NULL);
    CHECK(err.code == CTR_INVALID_ARGUMENT);
    size_t n = 7;
    CHECK(ctr_quad_result_quads(NULL, &n) == NULL && n == 0);
    CHECK(ctr_quad_result_pairs(NULL, NULL) == NULL);
    ctr_quad_result_free(NULL);
    ctr_mesh_free(m);
    uint32_t faces[27];
    memcpy(faces, octahedron_faces, sizeof octahedron_faces);
    m = ctr_mesh_new(NULL, 6, faces, 7, &err);
    CHECK(ctr_quadrangulate(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(ctr_check_quad(m, faces, 1, NULL, 0, NULL, &err) == NULL && err.code == CTR_INPUT);
    ctr_mesh_free(m);
}

static void simplification(void) {
    ctr_error err;
    ctr_error_init(&err);
    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    ctr_simplify_options o = ctr_simplify_options_default();
    CHECK(o.size == sizeof o && o.eps == 0.01 && o.eps_relative && o.verify);
    CHECK(o.mode == CTR_SIMPLIFY_NESTED && o.side == CTR_SIDE_COUNT && !o.allow_foldover);
    /* The defaults: every edge (1.41) is longer than 1 % of the diagonal (3.46). */
    ctr_simplify_result *r = ctr_simplify(m, NULL, &err);
    ctr_simplify_stats s = ctr_simplify_stats_default();
    CHECK(s.size == sizeof s && s.shortest_remaining_edge == -1 && s.faces_in == 0);
    CHECK(r != NULL && ctr_simplify_result_stats(r, &s, &err) == CTR_OK);
    CHECK(s.faces_in == 8 && s.faces_out == 8 && s.edges_contracted == 0);
    CHECK(s.shortest_remaining_edge > 1.41 && s.shortest_remaining_edge < 1.42);
    ctr_simplify_result_free(r);
    /* Every edge short, the guard off: down to the tetrahedron, which is irreducible. */
    o.eps = 2;
    o.eps_relative = false;
    o.allow_foldover = true;
    r = ctr_simplify(m, &o, &err);
    CHECK(r != NULL && ctr_simplify_result_stats(r, &s, &err) == CTR_OK);
    CHECK(s.eps == 2 && s.faces_out == 4 && s.vertices_out == 4 && s.edges_contracted == 2);
    CHECK(s.short_edges_remaining == 6 && s.components == 1 && s.boundary_loops == 0);
    const ctr_mesh *out = ctr_simplify_result_mesh(r);
    CHECK(ctr_mesh_face_count(out) == 4 && ctr_mesh_positions(out) != NULL);
    ctr_verdict *v = ctr_check_simplify(m, out, &o, &err);
    CHECK(v != NULL && ctr_verdict_passed(v));
    ctr_verdict_free(v);
    /* The input is no answer: its short edges pass the link condition. */
    v = ctr_check_simplify(m, m, &o, &err);
    CHECK(v != NULL && !ctr_verdict_passed(v));
    ctr_check_failure f = ctr_check_failure_default();
    CHECK(ctr_verdict_failure(v, 0, &f, &err) == CTR_OK);
    CHECK(strcmp(f.kind, "short_contractible_edge") == 0);
    CHECK(f.edge_from >= 0 && f.edge_from < f.edge_to && f.edge_to < 6);
    ctr_verdict_free(v);
    /* Quadric positions: the same contractions, other positions (the octahedron's
     * vertices pulled towards its faces' planes, not to edge midpoints). */
    ctr_simplify_options oq = o;
    oq.position = CTR_POSITION_QUADRIC;
    ctr_simplify_result *rq = ctr_simplify(m, &oq, &err);
    CHECK(rq != NULL && ctr_mesh_face_count(ctr_simplify_result_mesh(rq)) == 4);
    CHECK(rq && memcmp(ctr_mesh_positions(ctr_simplify_result_mesh(rq)), ctr_mesh_positions(out),
                       12 * sizeof(double)) != 0);
    v = ctr_check_simplify(m, ctr_simplify_result_mesh(rq), &oq, &err);
    CHECK(v != NULL && ctr_verdict_passed(v));
    ctr_verdict_free(v);
    ctr_simplify_result_free(rq);
    ctr_simplify_result_free(r);

    /* Wrong calls: unknown names, ε zero, no positions. */
    o = ctr_simplify_options_default();
    o.mode = 2;
    CHECK(ctr_simplify(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    o = ctr_simplify_options_default();
    o.side = 3;
    CHECK(ctr_simplify(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    o = ctr_simplify_options_default();
    o.position = 2;
    CHECK(ctr_simplify(m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(ctr_check_simplify(m, m, &o, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    o = ctr_simplify_options_default();
    o.eps = 0;
    CHECK(ctr_simplify(m, &o, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "bad_option") == 0);
    CHECK(ctr_simplify_result_stats(NULL, &s, &err) == CTR_INVALID_ARGUMENT);
    CHECK(ctr_simplify_result_mesh(NULL) == NULL);
    ctr_simplify_result_free(NULL);
    ctr_mesh_free(m);
    m = ctr_mesh_new(NULL, 6, octahedron_faces, 8, &err);
    CHECK(ctr_simplify(m, NULL, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "missing_positions") == 0);
    ctr_mesh_free(m);
}

static void checking(void) {
    ctr_error err;
    ctr_error_init(&err);
    ctr_mesh *m = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 8, &err);
    /* A reduction and its history pass; the history one step short does not. */
    ctr_reduce_options ro = ctr_reduce_options_default();
    ro.keep_history = true;
    ctr_reduce_result *rr = ctr_reduce(m, &ro, &err);
    const ctr_mesh *reduced = ctr_reduce_result_mesh(rr);
    /* The output in the input's vertex ids, as a port would give it. */
    const uint32_t *map = ctr_reduce_result_vertex_map(rr), *of = ctr_mesh_faces(reduced);
    uint32_t faces[12];
    for (size_t i = 0; i < 12; i++) faces[i] = map[of[i]];
    ctr_mesh *answer = ctr_mesh_new(octahedron_positions, 6, faces, 4, &err);
    size_t steps = 0;
    const uint32_t *h = ctr_reduce_result_contractions(rr, &steps);
    ctr_verdict *v = ctr_check_reduce(m, answer, NULL, 0, &err);
    CHECK(v != NULL && ctr_verdict_passed(v));
    ctr_verdict_free(v);
    v = ctr_check_reduce(m, answer, h, steps, &err);
    CHECK(v != NULL && ctr_verdict_passed(v));
    ctr_verdict_free(v);
    v = ctr_check_reduce(m, answer, h, steps - 1, &err);
    ctr_check_failure f = ctr_check_failure_default();
    CHECK(v != NULL && !ctr_verdict_passed(v) && ctr_verdict_failure(v, 0, &f, &err) == CTR_OK);
    CHECK(strcmp(f.kind, "history_mismatch") == 0);
    ctr_verdict_free(v);
    /* The input itself is reducible: an edge passes the link condition. */
    v = ctr_check_reduce(m, m, NULL, 0, &err);
    CHECK(v != NULL && ctr_verdict_failure(v, 0, &f, &err) == CTR_OK);
    /* The first in edge order, [0, 2], located by its ends and a face on it. */
    CHECK(strcmp(f.kind, "contractible_edge") == 0 && f.edge_from == 0 && f.edge_to == 2);
    CHECK(f.face == 0 && f.vertex == -1 && f.component == -1);
    ctr_verdict_free(v);
    ctr_mesh_free(answer);
    ctr_reduce_result_free(rr);

    /* A decimation and its maps pass; a map that lies does not. */
    ctr_decimate_options o = ctr_decimate_options_default();
    o.faces = 4;
    o.allow_foldover = true;
    ctr_decimate_result *r = ctr_decimate(m, &o, &err);
    const ctr_mesh *out = ctr_decimate_result_mesh(r);
    const uint32_t *vm = ctr_decimate_result_vertex_map(r);
    const uint32_t *cm = ctr_decimate_result_collapse_map(r);
    const uint32_t *fo = ctr_decimate_result_face_origin(r);
    v = ctr_check_decimate(m, out, &o, vm, cm, fo, &err);
    CHECK(v != NULL && ctr_verdict_passed(v));
    ctr_verdict_free(v);
    v = ctr_check_decimate(m, out, &o, NULL, NULL, NULL, &err);
    CHECK(v != NULL && ctr_verdict_passed(v));
    ctr_verdict_free(v);
    uint32_t lying[4];
    memcpy(lying, vm, sizeof lying);
    lying[0] = lying[1];
    v = ctr_check_decimate(m, out, &o, lying, cm, fo, &err);
    CHECK(v != NULL && ctr_verdict_failure(v, 0, &f, &err) == CTR_OK);
    CHECK(strcmp(f.kind, "inconsistent_map") == 0);
    ctr_verdict_free(v);
    /* The input is no answer to a run to 4 faces with the guard off. */
    v = ctr_check_decimate(m, m, &o, NULL, NULL, NULL, &err);
    CHECK(v != NULL && ctr_verdict_failure(v, 0, &f, &err) == CTR_OK);
    CHECK(strcmp(f.kind, "target_missed") == 0);
    ctr_verdict_free(v);
    o.keep = 3;
    CHECK(ctr_check_decimate(m, out, &o, NULL, NULL, NULL, &err) == NULL);
    CHECK(err.code == CTR_INPUT && strcmp(err.kind, "bad_option") == 0);
    ctr_decimate_result_free(r);

    /* Wrong calls: NULL meshes and verdicts, an input the task refuses. */
    CHECK(ctr_check_reduce(NULL, m, NULL, 0, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(ctr_check_simplify(m, NULL, NULL, &err) == NULL && err.code == CTR_INVALID_ARGUMENT);
    CHECK(ctr_check_decimate(m, NULL, NULL, NULL, NULL, NULL, &err) == NULL);
    CHECK(!ctr_verdict_passed(NULL) && ctr_verdict_failure_count(NULL) == 0);
    CHECK(ctr_verdict_failure(NULL, 0, &f, &err) == CTR_INVALID_ARGUMENT);
    ctr_verdict_free(NULL);
    ctr_mesh *open = ctr_mesh_new(octahedron_positions, 6, octahedron_faces, 7, &err);
    CHECK(ctr_check_reduce(open, m, NULL, 0, &err) == NULL && err.code == CTR_INPUT);
    CHECK(strcmp(err.kind, "boundary_edge") == 0);
    ctr_mesh_free(open);
    ctr_mesh_free(m);
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s SCRATCH_DIR\n", argv[0]);
        return 2;
    }
    CHECK(ctr_abi_version() == CTR_ABI_VERSION);
    on_arrays();
    wrong_calls();
    decimation();
    quadrangulation();
    simplification();
    checking();
    files(argv[1]);
    printf("%d of %d checks passed\n", checks - failures, checks);
    return failures == 0 ? 0 : 1;
}
