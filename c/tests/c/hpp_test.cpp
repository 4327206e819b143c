// The C++ layer (contractible.hpp): every function on the octahedron, its values against
// what the C calls give, and each kind of failure as an exception. Prints one line per
// failed check; exit 0 when all pass. Run by c/tests/c_programs.rs, also under valgrind.
#include <cstdio>
#include <cstring>
#include <vector>

#include "contractible.hpp"

static int failures = 0, checks = 0;
#define CHECK(cond)                                                              \
    do {                                                                         \
        checks++;                                                                \
        if (!(cond)) {                                                           \
            failures++;                                                          \
            std::fprintf(stderr, "hpp_test.cpp:%d: failed: %s\n", __LINE__, #cond); \
        }                                                                        \
    } while (0)

namespace c = contractible;

static const std::vector<double> positions = {1, 0, 0, -1, 0, 0, 0, 1, 0,
                                              0, -1, 0, 0, 0, 1, 0, 0, -1};
static const std::vector<uint32_t> faces = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                            2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

int main() {
    auto m = c::Mesh::from_arrays(positions, 6, faces);
    CHECK(m.positions() == positions && m.faces() == faces && m.has_positions());

    // reduce, with its history, judged with and without it.
    c::ReduceOptions ro;
    ro.keep_history = true;
    auto r = c::reduce(m, ro);
    CHECK(r.mesh.face_count() == 4 && r.contractions.size() == 2 && r.components == 1);
    std::vector<uint32_t> in_ids;
    for (uint32_t v : r.mesh.faces()) in_ids.push_back(r.vertex_map[v]);
    auto answer = c::Mesh::from_arrays(positions, 6, in_ids);
    CHECK(c::check_reduce(m, answer).passed);
    CHECK(c::check_reduce(m, answer, &r.contractions).passed);
    std::vector<std::array<uint32_t, 2>> none;
    auto v = c::check_reduce(m, answer, &none);
    CHECK(!v.passed && v.reasons[0].kind == "history_mismatch");
    v = c::check_reduce(m, m);
    CHECK(!v.passed && v.reasons[0].kind == "contractible_edge" && v.reasons[0].edge_from == 0 &&
          v.reasons[0].edge_to == 2 && !v.reasons[0].message.empty());

    // quadrangulate, every algorithm, judged.
    for (uint32_t a = CTR_QUAD_LRS; a <= CTR_QUAD_DS_NAIVE; a++) {
        c::QuadOptions qo;
        qo.algorithm = a;
        auto q = c::quadrangulate(m, qo);
        CHECK(q.quads.size() == 4 && q.triangles.size() == 8 && q.pairs.size() == 4);
        CHECK(q.stats.quads == 4 && q.stats.euler_characteristic == 2);
        CHECK(c::check_quad(m, q).passed);
        q.pairs[0].swap(q.pairs[1]);
        auto w = c::check_quad(m, q);
        CHECK(!w.passed);
    }

    // simplify, judged; the input is no answer.
    c::SimplifyOptions so;
    so.eps = 2;
    so.eps_relative = false;
    so.allow_foldover = true;
    auto s = c::simplify(m, so);
    CHECK(s.mesh.face_count() == 4 && s.stats.edges_contracted == 2 && s.stats.eps == 2);
    CHECK(c::check_simplify(m, s.mesh, so).passed);
    v = c::check_simplify(m, m, so);
    CHECK(!v.passed && v.reasons[0].kind == "short_contractible_edge");

    // decimate with a locked vertex, judged with its maps; a map that lies is named.
    c::DecimateOptions dop;
    dop.faces = 4;
    dop.allow_foldover = true;
    dop.locked_vertices = {5};
    auto d = c::decimate(m, dop);
    CHECK(d.mesh.face_count() == 4 && d.stats.stopped == CTR_STOPPED_TARGET);
    CHECK(d.vertex_map.size() == 4 && d.collapse_map.size() == 6 && d.face_origin.size() == 4);
    CHECK(d.collapse_map[5] != CTR_NO_VERTEX && d.vertex_map[d.collapse_map[5]] == 5);
    CHECK(c::check_decimate(m, d, dop).passed);
    d.vertex_map[0] = d.vertex_map[1];
    v = c::check_decimate(m, d, dop);
    CHECK(!v.passed && v.reasons[0].kind == "inconsistent_map");

    // Failures are exceptions with the C error's code and kind.
    try {
        c::SimplifyOptions bad;
        bad.eps = 0;
        c::simplify(m, bad);
        CHECK(false);
    } catch (const c::Error &e) {
        CHECK(e.code == CTR_INPUT && e.kind == "bad_option");
    }
    try {
        c::QuadOptions bad;
        bad.algorithm = 99;
        c::quadrangulate(m, bad);
        CHECK(false);
    } catch (const c::Error &e) {
        CHECK(e.code == CTR_INVALID_ARGUMENT);
    }
    try {
        std::vector<uint32_t> open(faces.begin(), faces.end() - 3);
        c::check_reduce(c::Mesh::from_arrays(positions, 6, open), m);
        CHECK(false);
    } catch (const c::Error &e) {
        CHECK(e.code == CTR_INPUT && e.kind == "boundary_edge" && e.face >= 0);
    }
    try {
        c::decimate(c::Mesh::from_arrays({}, 6, faces));
        CHECK(false);
    } catch (const c::Error &e) {
        CHECK(e.kind == "missing_positions");
    }
    std::printf("%d of %d checks passed\n", checks - failures, checks);
    return failures == 0 ? 0 : 1;
}
