/* conformance_adapter: the conformance protocol (spec/conformance.md) answered through
 * the C interface, for every task (reduce, quad, simplify, decimate): one JSON case on
 * stdin, one JSON answer on stdout (with the contractions, the paired triangulation and
 * pairs, the provenance maps), or {"error": {"kind", "message"}} and exit code 2 for an
 * input the library refuses. Run by the harness:
 *   contractible conformance --impl PATH/TO/conformance_adapter --exact
 * The JSON reader is a small recursive-descent parser of the whole grammar; numbers are
 * read by strtod, exact for the shortest decimal forms the suite is written in. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contractible.h"

typedef enum { J_NULL, J_BOOL, J_NUM, J_STR, J_ARR, J_OBJ } jtype;
typedef struct jvalue {
    jtype type;
    double num;          /* J_NUM; J_BOOL as 0 or 1 */
    char *str;           /* J_STR */
    char *key;           /* a member of an object: its key */
    struct jvalue *kids; /* J_ARR, J_OBJ: `len` elements or members */
    size_t len;
} jvalue;

static const char *at; /* the parser's position */

static void skip_space(void) {
    while (isspace((unsigned char)*at)) at++;
}

static void jfree(jvalue *v) {
    for (size_t i = 0; i < v->len; i++) jfree(&v->kids[i]);
    free(v->kids);
    free(v->str);
    free(v->key);
}

/* A string at `at` (its quotes included), or NULL. */
static char *parse_string(void) {
    size_t cap = 16, n = 0;
    char *s = malloc(cap);
    if (!s || *at != '"') goto fail;
    at++;
    while (*at != '"') {
        char c = *at++;
        if (c == '\0') goto fail;
        if (c == '\\') {
            c = *at++;
            if (c == 'n') c = '\n';
            else if (c == 't') c = '\t';
            else if (c == 'r') c = '\r';
            else if (c == 'b') c = '\b';
            else if (c == 'f') c = '\f';
            else if (c == 'u') { /* none in the suite's cases: kept as '?' */
                for (int k = 0; k < 4; k++)
                    if (!isxdigit((unsigned char)*at++)) goto fail;
                c = '?';
            } else if (c != '"' && c != '\\' && c != '/') goto fail;
        }
        if (n + 2 > cap) {
            char *t = realloc(s, cap *= 2);
            if (!t) goto fail;
            s = t;
        }
        s[n++] = c;
    }
    at++;
    s[n] = '\0';
    return s;
fail:
    free(s);
    return NULL;
}

/* One value at `at` into `v` (zeroed first); 0 on a syntax error (then jfree(v)). */
static int parse(jvalue *v, int depth) {
    memset(v, 0, sizeof *v);
    skip_space();
    if (depth > 64) return 0;
    if (*at == '{' || *at == '[') {
        int object = *at == '{';
        char close = object ? '}' : ']';
        size_t cap = 0;
        v->type = object ? J_OBJ : J_ARR;
        at++;
        skip_space();
        if (*at == close) return at++, 1;
        for (;;) {
            if (v->len == cap) {
                jvalue *t = realloc(v->kids, (cap = cap ? 2 * cap : 4) * sizeof *t);
                if (!t) return 0;
                v->kids = t;
            }
            char *key = NULL;
            if (object) {
                skip_space();
                if (!(key = parse_string())) return 0;
                skip_space();
                if (*at++ != ':') return free(key), 0;
            }
            jvalue *kid = &v->kids[v->len++];
            int ok = parse(kid, depth + 1);
            kid->key = key;
            if (!ok) return 0;
            skip_space();
            if (*at == ',') {
                at++;
                continue;
            }
            return *at++ == close;
        }
    }
    if (*at == '"') return v->type = J_STR, (v->str = parse_string()) != NULL;
    if (!strncmp(at, "null", 4)) return at += 4, v->type = J_NULL, 1;
    if (!strncmp(at, "true", 4)) return at += 4, v->type = J_BOOL, v->num = 1, 1;
    if (!strncmp(at, "false", 5)) return at += 5, v->type = J_BOOL, 1;
    char *end;
    v->type = J_NUM;
    v->num = strtod(at, &end);
    if (end == at) return 0;
    at = end;
    return 1;
}

static const jvalue *member(const jvalue *o, const char *key) {
    if (!o || o->type != J_OBJ) return NULL;
    for (size_t i = 0; i < o->len; i++)
        if (!strcmp(o->kids[i].key, key)) return &o->kids[i];
    return NULL;
}

/* A JSON string for `s` (quotes, backslashes and control characters escaped). */
static void put_string(const char *s) {
    putchar('"');
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') printf("\\%c", c);
        else if (c < 0x20) printf("\\u%04x", c);
        else putchar(c);
    }
    putchar('"');
}

static int refuse(const char *kind, const char *message) {
    printf("{\"error\": {\"kind\": ");
    put_string(kind);
    printf(", \"message\": ");
    put_string(message);
    printf("}}\n");
    return 2;
}

/* A whole number in [0, 2^32) into `*out`; 0 for anything else. */
static int id(const jvalue *x, uint32_t *out) {
    if (x->type != J_NUM || x->num < 0 || x->num > 4294967295.0 || x->num != (double)(uint32_t)x->num)
        return 0;
    *out = (uint32_t)x->num;
    return 1;
}

/* The rows of `a`, each `width` ids, into `out`. */
static int rows(const jvalue *a, size_t width, uint32_t *out) {
    for (size_t i = 0; i < a->len; i++) {
        const jvalue *r = &a->kids[i];
        if (r->type != J_ARR || r->len != width) return 0;
        for (size_t k = 0; k < width; k++)
            if (!id(&r->kids[k], &out[i * width + k])) return 0;
    }
    return 1;
}

/* The number at `key` of `o` into `*x`: 1 when present, 0 when absent, -1 when not a
 * number. */
static int number(const jvalue *o, const char *key, double *x) {
    const jvalue *v = member(o, key);
    if (!v || v->type == J_NULL) return 0;
    if (v->type != J_NUM) return -1;
    *x = v->num;
    return 1;
}

/* The boolean at `key` of `o` into `*b` when present; 0 when present and no boolean. */
static int boolean(const jvalue *o, const char *key, bool *b) {
    const jvalue *v = member(o, key);
    if (!v || v->type == J_NULL) return 1;
    if (v->type != J_BOOL) return 0;
    *b = v->num != 0;
    return 1;
}

/* The index of the string at `key` of `o` among `names` (NULL-terminated) into `*out`
 * when present; 0 when present and none of them. */
static int name(const jvalue *o, const char *key, const char *const *names, uint32_t *out) {
    const jvalue *v = member(o, key);
    if (!v || v->type == J_NULL) return 1;
    if (v->type != J_STR) return 0;
    for (uint32_t i = 0; names[i]; i++)
        if (!strcmp(v->str, names[i])) return *out = i, 1;
    return 0;
}

static void put_faces(const uint32_t *f, size_t n, size_t width, const uint32_t *map) {
    printf("\"faces\": [");
    for (size_t i = 0; i < n; i++) {
        printf("%s[", i ? ", " : "");
        for (size_t k = 0; k < width; k++) {
            uint32_t x = f[width * i + k];
            printf("%s%u", k ? ", " : "", map ? map[x] : x);
        }
        printf("]");
    }
    printf("]");
}

/* The positions of `m`, each coordinate with 17 significant digits (reads back to the
 * same binary64, which the harness compares bit for bit with --exact). */
static void put_positions(const ctr_mesh *m) {
    const double *p = ctr_mesh_positions(m);
    printf("\"positions\": [");
    for (size_t i = 0; i < ctr_mesh_vertex_count(m); i++)
        printf("%s[%.17g, %.17g, %.17g]", i ? ", " : "", p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    printf("]");
}

static void put_ids(const char *key, const uint32_t *x, size_t n) {
    printf(", \"%s\": [", key);
    for (size_t i = 0; i < n; i++) {
        if (x[i] == CTR_NO_VERTEX) printf("%snull", i ? ", " : "");
        else printf("%s%u", i ? ", " : "", x[i]);
    }
    printf("]");
}

static int reduce(const ctr_mesh *mesh, const jvalue *options, ctr_error *err) {
    static const char *const algorithms[] = {"rs", "schipper", "brute", NULL};
    ctr_reduce_options o = ctr_reduce_options_default();
    o.keep_history = true;
    double seed = 0;
    if (!name(options, "algorithm", algorithms, &o.algorithm))
        return refuse("unknown_name", "the algorithm is none of rs, schipper, brute");
    if (number(options, "seed", &seed) < 0) return refuse("protocol", "the seed is no number");
    o.seed = (uint64_t)seed;
    ctr_reduce_result *r = ctr_reduce(mesh, &o, err);
    if (!r) return refuse(err->kind, err->message);
    const ctr_mesh *out = ctr_reduce_result_mesh(r);
    size_t steps = 0;
    const uint32_t *h = ctr_reduce_result_contractions(r, &steps);
    printf("{\"positions\": null, ");
    put_faces(ctr_mesh_faces(out), ctr_mesh_face_count(out), 3, ctr_reduce_result_vertex_map(r));
    printf(", \"history\": [");
    for (size_t i = 0; i < steps; i++) printf("%s[%u, %u]", i ? ", " : "", h[2 * i], h[2 * i + 1]);
    printf("]}\n");
    ctr_reduce_result_free(r);
    return 0;
}

static int quad(const ctr_mesh *mesh, const jvalue *options, ctr_error *err) {
    /* In the order of the CTR_QUAD_* constants. */
    static const char *const algorithms[] = {"lrs", "ps", "sg", "matching", "ds", "bbdl",
                                             "frink-lct", "ds-naive", NULL};
    ctr_quad_options o = ctr_quad_options_default();
    double seed = 0;
    if (!name(options, "algorithm", algorithms, &o.algorithm))
        return refuse("unknown_name", "the algorithm is none of the eight quad algorithms");
    if (number(options, "seed", &seed) < 0) return refuse("protocol", "the seed is no number");
    o.seed = (uint64_t)seed;
    ctr_quad_result *r = ctr_quadrangulate(mesh, &o, err);
    if (!r) return refuse(err->kind, err->message);
    size_t quads = 0, triangles = 0, pairs = 0;
    const uint32_t *q = ctr_quad_result_quads(r, &quads);
    const uint32_t *t = ctr_quad_result_triangles(r, &triangles);
    const uint32_t *p = ctr_quad_result_pairs(r, &pairs);
    printf("{\"positions\": null, ");
    put_faces(q, quads, 4, NULL);
    printf(", \"triangles\": [");
    for (size_t i = 0; i < triangles; i++)
        printf("%s[%u, %u, %u]", i ? ", " : "", t[3 * i], t[3 * i + 1], t[3 * i + 2]);
    printf("], \"pairs\": [");
    for (size_t i = 0; i < pairs; i++) printf("%s[%u, %u]", i ? ", " : "", p[2 * i], p[2 * i + 1]);
    printf("]}\n");
    ctr_quad_result_free(r);
    return 0;
}

static int simplify(const ctr_mesh *mesh, const jvalue *options, ctr_error *err) {
    static const char *const modes[] = {"nested", "naive", NULL};
    static const char *const sides[] = {"count", "path", "euclidean", NULL};
    static const char *const positions[] = {"midpoint", "quadric", NULL};
    ctr_simplify_options o = ctr_simplify_options_default();
    double eps = 0, eps_rel = 0;
    int absolute = number(options, "eps", &eps), relative = number(options, "eps_rel", &eps_rel);
    bool guard = true;
    if (absolute < 0 || relative < 0 || absolute + relative > 1)
        return refuse("bad_option", "give one of eps and eps_rel, a number");
    if (absolute) o.eps = eps, o.eps_relative = false;
    if (relative) o.eps = eps_rel;
    if (!name(options, "mode", modes, &o.mode) || !name(options, "side", sides, &o.side) ||
        !name(options, "position", positions, &o.position))
        return refuse("unknown_name", "a mode, side or position this adapter does not know");
    if (!boolean(options, "guard", &guard)) return refuse("protocol", "guard is no boolean");
    o.allow_foldover = !guard;
    ctr_simplify_result *r = ctr_simplify(mesh, &o, err);
    if (!r) return refuse(err->kind, err->message);
    const ctr_mesh *out = ctr_simplify_result_mesh(r);
    printf("{");
    put_faces(ctr_mesh_faces(out), ctr_mesh_face_count(out), 3, NULL);
    printf(", ");
    put_positions(out);
    printf("}\n");
    ctr_simplify_result_free(r);
    return 0;
}

static int decimate(const ctr_mesh *mesh, const jvalue *options, ctr_error *err) {
    static const char *const placements[] = {"optimal", "midpoint", "endpoint", NULL};
    static const char *const schedules[] = {"exact", "passes", NULL};
    ctr_decimate_options o = ctr_decimate_options_default();
    double faces = 0, cap = 0, cap_rel = 0;
    bool guard = true;
    int capped = number(options, "max_error", &cap), relative = number(options, "max_error_rel", &cap_rel);
    if (number(options, "faces", &faces) < 0 || number(options, "keep", &o.keep) < 0 ||
        capped < 0 || relative < 0 || capped + relative > 1 || faces < 0)
        return refuse("bad_option", "faces, keep and one of max_error, max_error_rel are numbers");
    o.faces = (uint64_t)faces;
    if (capped) o.max_error = cap;
    if (relative) o.max_error = cap_rel, o.max_error_relative = true;
    if (!name(options, "placement", placements, &o.placement) ||
        !name(options, "schedule", schedules, &o.schedule))
        return refuse("unknown_name", "a placement or schedule this adapter does not know");
    if (!boolean(options, "guard", &guard) || !boolean(options, "lock_boundary", &o.lock_boundary))
        return refuse("protocol", "guard and lock_boundary are booleans");
    o.allow_foldover = !guard;
    const jvalue *locked = member(options, "locked");
    uint32_t *ids = NULL;
    if (locked && locked->type == J_ARR) {
        ids = malloc((locked->len + 1) * sizeof *ids);
        int ok = ids != NULL;
        for (size_t i = 0; ok && i < locked->len; i++) ok = id(&locked->kids[i], &ids[i]);
        if (!ok) {
            free(ids);
            return refuse("protocol", "locked must be a list of vertex ids");
        }
        o.locked = ids;
        o.locked_count = locked->len;
    }
    ctr_decimate_result *r = ctr_decimate(mesh, &o, err);
    free(ids);
    if (!r) return refuse(err->kind, err->message);
    const ctr_mesh *out = ctr_decimate_result_mesh(r);
    printf("{");
    put_faces(ctr_mesh_faces(out), ctr_mesh_face_count(out), 3, NULL);
    printf(", ");
    put_positions(out);
    put_ids("vertex_map", ctr_decimate_result_vertex_map(r), ctr_mesh_vertex_count(out));
    put_ids("collapse_map", ctr_decimate_result_collapse_map(r), ctr_mesh_vertex_count(mesh));
    put_ids("face_origin", ctr_decimate_result_face_origin(r), ctr_mesh_face_count(out));
    printf("}\n");
    ctr_decimate_result_free(r);
    return 0;
}

static int answer(const jvalue *c) {
    const jvalue *task = member(c, "task"), *faces = member(c, "faces");
    const jvalue *count = member(c, "vertex_count"), *positions = member(c, "positions");
    const jvalue *options = member(c, "options");
    if (!task || task->type != J_STR || !faces || faces->type != J_ARR || !count ||
        count->type != J_NUM || count->num < 0)
        return refuse("protocol", "the case lacks its task, faces or vertex_count");
    int (*run)(const ctr_mesh *, const jvalue *, ctr_error *) =
        !strcmp(task->str, "reduce")     ? reduce
        : !strcmp(task->str, "quad")     ? quad
        : !strcmp(task->str, "simplify") ? simplify
        : !strcmp(task->str, "decimate") ? decimate
                                         : NULL;
    if (!run) return refuse("unsupported", "the task is none of reduce, quad, simplify, decimate");
    size_t n = (size_t)count->num, m = faces->len;
    uint32_t *f = malloc((3 * m + 1) * sizeof *f);
    double *xyz = NULL;
    int status = 0;
    if (!f || !rows(faces, 3, f)) {
        status = refuse("protocol", "faces must be rows of 3 vertex ids");
        goto done;
    }
    if (positions && positions->type == J_ARR) {
        xyz = malloc((3 * positions->len + 1) * sizeof *xyz);
        if (!xyz || positions->len != n) {
            status = refuse("protocol", "positions must give one row of 3 per vertex");
            goto done;
        }
        for (size_t i = 0; i < n; i++) {
            const jvalue *r = &positions->kids[i];
            if (r->type != J_ARR || r->len != 3) {
                status = refuse("protocol", "positions must be rows of 3 numbers");
                goto done;
            }
            for (size_t k = 0; k < 3; k++) xyz[3 * i + k] = r->kids[k].num;
        }
    }
    ctr_error err;
    ctr_error_init(&err);
    ctr_mesh *mesh = ctr_mesh_new(xyz, n, f, m, &err);
    status = mesh ? run(mesh, options, &err) : refuse(err.kind, err.message);
    ctr_mesh_free(mesh);
done:
    free(f);
    free(xyz);
    return status;
}

int main(void) {
    size_t cap = 1 << 16, n = 0, got;
    char *text = malloc(cap);
    while (text && (got = fread(text + n, 1, cap - n - 1, stdin)) > 0) {
        n += got;
        if (n + 1 == cap) {
            char *t = realloc(text, cap *= 2);
            if (!t) free(text);
            text = t;
        }
    }
    if (!text) return refuse("internal", "out of memory");
    text[n] = '\0';
    at = text;
    jvalue c;
    int ok = parse(&c, 0);
    if (ok) skip_space(); /* after a failure `at` may be past the text's end */
    int status = ok && *at == '\0' ? answer(&c) : refuse("protocol", "the case is not one JSON value");
    jfree(&c);
    free(text);
    return status;
}
