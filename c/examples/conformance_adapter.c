/* conformance_adapter: the conformance protocol (spec/conformance.md) answered through
 * the C interface, for the task it covers, reduce: one JSON case on stdin, one JSON
 * answer on stdout (the faces in the input's vertex ids and the contractions), or
 * {"error": {"kind", "message"}} and exit code 2 for an input the library refuses (other
 * tasks are refused as "unsupported"). Run by the harness:
 *   contractible conformance --impl PATH/TO/conformance_adapter --task reduce
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

/* `n` rows of `width` numbers, each a whole number in [0, 2^32), into `out`. */
static int rows(const jvalue *a, size_t width, uint32_t *out) {
    for (size_t i = 0; i < a->len; i++) {
        const jvalue *r = &a->kids[i];
        if (r->type != J_ARR || r->len != width) return 0;
        for (size_t k = 0; k < width; k++) {
            double x = r->kids[k].num;
            if (r->kids[k].type != J_NUM || x < 0 || x > 4294967295.0 || x != (double)(uint32_t)x)
                return 0;
            out[i * width + k] = (uint32_t)x;
        }
    }
    return 1;
}

static int answer(const jvalue *c) {
    const jvalue *task = member(c, "task"), *faces = member(c, "faces");
    const jvalue *count = member(c, "vertex_count"), *positions = member(c, "positions");
    const jvalue *options = member(c, "options");
    if (!task || task->type != J_STR || !faces || faces->type != J_ARR || !count ||
        count->type != J_NUM || count->num < 0)
        return refuse("protocol", "the case lacks its task, faces or vertex_count");
    if (strcmp(task->str, "reduce") != 0)
        return refuse("unsupported", "this adapter answers reduce only");
    size_t n = (size_t)count->num, m = faces->len;
    ctr_reduce_options o = ctr_reduce_options_default();
    o.keep_history = true;
    const jvalue *algorithm = member(options, "algorithm"), *seed = member(options, "seed");
    if (algorithm && algorithm->type == J_STR) {
        if (!strcmp(algorithm->str, "schipper")) o.algorithm = CTR_REDUCE_SCHIPPER;
        else if (!strcmp(algorithm->str, "brute")) o.algorithm = CTR_REDUCE_BRUTE;
        else if (strcmp(algorithm->str, "rs") != 0)
            return refuse("unknown_name", "the algorithm is none of rs, schipper, brute");
    }
    if (seed && seed->type == J_NUM) o.seed = (uint64_t)seed->num;
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
    ctr_reduce_result *r = mesh ? ctr_reduce(mesh, &o, &err) : NULL;
    if (!r) {
        status = refuse(err.kind, err.message);
    } else {
        const ctr_mesh *out = ctr_reduce_result_mesh(r);
        const uint32_t *of = ctr_mesh_faces(out), *map = ctr_reduce_result_vertex_map(r);
        size_t steps = 0;
        const uint32_t *h = ctr_reduce_result_contractions(r, &steps);
        printf("{\"positions\": null, \"faces\": [");
        for (size_t i = 0; i < ctr_mesh_face_count(out); i++)
            printf("%s[%u, %u, %u]", i ? ", " : "", map[of[3 * i]], map[of[3 * i + 1]],
                   map[of[3 * i + 2]]);
        printf("], \"history\": [");
        for (size_t i = 0; i < steps; i++) printf("%s[%u, %u]", i ? ", " : "", h[2 * i], h[2 * i + 1]);
        printf("]}\n");
    }
    ctr_reduce_result_free(r);
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
