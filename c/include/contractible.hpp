// contractible.hpp: a C++17 layer over contractible.h (the C ABI of contractible):
// std::vector in, values out, failures as contractible::Error exceptions, every handle
// freed by its owner (RAII). Header-only; link as for the C interface (docs/c.md).
#ifndef CONTRACTIBLE_HPP
#define CONTRACTIBLE_HPP

#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "contractible.h"

namespace contractible {

// A failed call: the C error's code (CTR_INPUT, CTR_FAILURE, ...), kind and location.
class Error : public std::runtime_error {
  public:
    explicit Error(const ctr_error &e)
        : std::runtime_error(e.message), code(e.code), kind(e.kind), face(e.face),
          vertex(e.vertex), line(e.line) {}
    int code;
    std::string kind;
    int64_t face, vertex, line;  // -1 where they do not apply
};

namespace detail {
// Calls f(&err) and throws the error it reports.
template <class F> auto call(F f) {
    ctr_error err;
    ctr_error_init(&err);
    auto value = f(&err);
    if (err.code != CTR_OK) throw Error(err);
    return value;
}
struct MeshFree {
    void operator()(ctr_mesh *m) const { ctr_mesh_free(m); }
};
struct ReduceFree {
    void operator()(ctr_reduce_result *r) const { ctr_reduce_result_free(r); }
};
struct QuadFree {
    void operator()(ctr_quad_result *r) const { ctr_quad_result_free(r); }
};
struct SimplifyFree {
    void operator()(ctr_simplify_result *r) const { ctr_simplify_result_free(r); }
};
struct DecimateFree {
    void operator()(ctr_decimate_result *r) const { ctr_decimate_result_free(r); }
};
struct VerdictFree {
    void operator()(ctr_verdict *v) const { ctr_verdict_free(v); }
};
template <class T> std::vector<T> copy(const T *p, size_t n) {
    return p ? std::vector<T>(p, p + n) : std::vector<T>();
}
}  // namespace detail

// A triangle mesh owned by this object: positions (3 per vertex, or none) and faces (3
// vertex indices each).
class Mesh {
  public:
    // From flat arrays (copied); no positions when `positions` is empty.
    static Mesh from_arrays(const std::vector<double> &positions, size_t vertex_count,
                            const std::vector<uint32_t> &faces) {
        if (!positions.empty() && positions.size() != 3 * vertex_count)
            throw std::invalid_argument("positions must hold 3 coordinates per vertex");
        if (faces.size() % 3 != 0)
            throw std::invalid_argument("faces must hold 3 indices per face");
        const double *p = positions.empty() ? nullptr : positions.data();
        return Mesh(detail::call([&](ctr_error *e) {
            return ctr_mesh_new(p, vertex_count, faces.data(), faces.size() / 3, e);
        }));
    }
    // From an OFF, OBJ, PLY or STL file (optionally .gz).
    static Mesh read(const std::string &path) {
        return Mesh(detail::call([&](ctr_error *e) { return ctr_mesh_read(path.c_str(), e); }));
    }
    // Writes the mesh by the file's extension.
    void write(const std::string &path) const {
        detail::call([&](ctr_error *e) { return ctr_mesh_write(handle_.get(), path.c_str(), e); });
    }
    size_t vertex_count() const { return ctr_mesh_vertex_count(handle_.get()); }
    size_t face_count() const { return ctr_mesh_face_count(handle_.get()); }
    bool has_positions() const { return ctr_mesh_positions(handle_.get()) != nullptr; }
    // 3 coordinates per vertex (empty without positions).
    std::vector<double> positions() const {
        const double *p = ctr_mesh_positions(handle_.get());
        return p ? std::vector<double>(p, p + 3 * vertex_count()) : std::vector<double>();
    }
    // 3 vertex indices per face.
    std::vector<uint32_t> faces() const {
        const uint32_t *f = ctr_mesh_faces(handle_.get());
        return std::vector<uint32_t>(f, f + 3 * face_count());
    }
    // A copy of a mesh the library owns (a result's output).
    static Mesh copy_of(const ctr_mesh *m) {
        size_t n = ctr_mesh_vertex_count(m), k = ctr_mesh_face_count(m);
        return from_arrays(detail::copy(ctr_mesh_positions(m), 3 * n), n,
                           detail::copy(ctr_mesh_faces(m), 3 * k));
    }
    const ctr_mesh *get() const { return handle_.get(); }

  private:
    explicit Mesh(ctr_mesh *m) : handle_(m) {}
    std::unique_ptr<ctr_mesh, detail::MeshFree> handle_;
};

// What describe() finds (summed over the components).
inline ctr_description describe(const Mesh &mesh) {
    ctr_description d = ctr_description_default();
    detail::call([&](ctr_error *e) { return ctr_describe(mesh.get(), &d, e); });
    return d;
}

// The options of reduce(): ctr_reduce_options with their defaults.
struct ReduceOptions : ctr_reduce_options {
    ReduceOptions() : ctr_reduce_options(ctr_reduce_options_default()) {}
};

// The irreducible triangulation of every component, the input vertex of each output
// vertex, and the contractions (kept, removed) when the options keep them.
struct Reduced {
    Mesh mesh;
    std::vector<uint32_t> vertex_map;
    std::vector<std::array<uint32_t, 2>> contractions;
    size_t components;
};

inline Reduced reduce(const Mesh &mesh, const ReduceOptions &options = ReduceOptions()) {
    std::unique_ptr<ctr_reduce_result, detail::ReduceFree> r(detail::call(
        [&](ctr_error *e) { return ctr_reduce(mesh.get(), &options, e); }));
    const ctr_mesh *out = ctr_reduce_result_mesh(r.get());
    size_t n = ctr_mesh_vertex_count(out), k = 0;
    const uint32_t *steps = ctr_reduce_result_contractions(r.get(), &k);
    std::vector<std::array<uint32_t, 2>> contractions(k);
    for (size_t i = 0; i < k; i++) contractions[i] = {steps[2 * i], steps[2 * i + 1]};
    return Reduced{Mesh::copy_of(out), detail::copy(ctr_reduce_result_vertex_map(r.get()), n),
                   std::move(contractions), ctr_reduce_result_component_count(r.get())};
}

// The options of quadrangulate(): ctr_quad_options with their defaults.
struct QuadOptions : ctr_quad_options {
    QuadOptions() : ctr_quad_options(ctr_quad_options_default()) {}
};

// The quads (input vertex ids), the paired triangulation K (one row per input face), the
// pairs (two rows of K per quad) and the totals.
struct Quads {
    std::vector<std::array<uint32_t, 4>> quads;
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<std::array<uint32_t, 2>> pairs;
    ctr_quad_stats stats;
};

namespace detail {
template <size_t N> std::vector<std::array<uint32_t, N>> rows(const uint32_t *p, size_t n) {
    std::vector<std::array<uint32_t, N>> out(n);
    for (size_t i = 0; i < n; i++)
        for (size_t k = 0; k < N; k++) out[i][k] = p[N * i + k];
    return out;
}
}  // namespace detail

inline Quads quadrangulate(const Mesh &mesh, const QuadOptions &options = QuadOptions()) {
    std::unique_ptr<ctr_quad_result, detail::QuadFree> r(detail::call(
        [&](ctr_error *e) { return ctr_quadrangulate(mesh.get(), &options, e); }));
    size_t q = 0, t = 0, p = 0;
    const uint32_t *quads = ctr_quad_result_quads(r.get(), &q);
    const uint32_t *triangles = ctr_quad_result_triangles(r.get(), &t);
    const uint32_t *pairs = ctr_quad_result_pairs(r.get(), &p);
    Quads out{detail::rows<4>(quads, q), detail::rows<3>(triangles, t), detail::rows<2>(pairs, p),
              ctr_quad_stats_default()};
    detail::call([&](ctr_error *e) { return ctr_quad_result_stats(r.get(), &out.stats, e); });
    return out;
}

// The options of simplify(): ctr_simplify_options with their defaults (ε 1 % of the
// bounding-box diagonal).
struct SimplifyOptions : ctr_simplify_options {
    SimplifyOptions() : ctr_simplify_options(ctr_simplify_options_default()) {}
};

// The simplified mesh and what was done.
struct Simplified {
    Mesh mesh;
    ctr_simplify_stats stats;
};

inline Simplified simplify(const Mesh &mesh, const SimplifyOptions &options = SimplifyOptions()) {
    std::unique_ptr<ctr_simplify_result, detail::SimplifyFree> r(detail::call(
        [&](ctr_error *e) { return ctr_simplify(mesh.get(), &options, e); }));
    Simplified out{Mesh::copy_of(ctr_simplify_result_mesh(r.get())), ctr_simplify_stats_default()};
    detail::call([&](ctr_error *e) { return ctr_simplify_result_stats(r.get(), &out.stats, e); });
    return out;
}

// The options of decimate(): ctr_decimate_options with their defaults (no target: as
// coarse as the guards allow) and the locked vertices as a vector.
struct DecimateOptions : ctr_decimate_options {
    DecimateOptions() : ctr_decimate_options(ctr_decimate_options_default()) {}
    std::vector<uint32_t> locked_vertices;
};

// The decimated mesh, the provenance maps (per output vertex its surviving input vertex;
// per input vertex its output vertex, CTR_NO_VERTEX for an unused one; per output face
// its input face) and why the run stopped.
struct Decimated {
    Mesh mesh;
    std::vector<uint32_t> vertex_map, collapse_map, face_origin;
    ctr_decimate_stats stats;
};

inline Decimated decimate(const Mesh &mesh, const DecimateOptions &options = DecimateOptions()) {
    ctr_decimate_options o = options;
    o.locked = options.locked_vertices.data();
    o.locked_count = options.locked_vertices.size();
    std::unique_ptr<ctr_decimate_result, detail::DecimateFree> r(
        detail::call([&](ctr_error *e) { return ctr_decimate(mesh.get(), &o, e); }));
    const ctr_mesh *out = ctr_decimate_result_mesh(r.get());
    Decimated d{Mesh::copy_of(out),
                detail::copy(ctr_decimate_result_vertex_map(r.get()), ctr_mesh_vertex_count(out)),
                detail::copy(ctr_decimate_result_collapse_map(r.get()), mesh.vertex_count()),
                detail::copy(ctr_decimate_result_face_origin(r.get()), ctr_mesh_face_count(out)),
                ctr_decimate_stats_default()};
    detail::call([&](ctr_error *e) { return ctr_decimate_result_stats(r.get(), &d.stats, e); });
    return d;
}

// One reason an output fails, located (-1 where a location does not apply).
struct Reason {
    std::string kind, message;
    int64_t face, edge_from, edge_to, vertex, component;
};

// The checker's verdict on an output: passed, or the reasons it fails.
struct Verdict {
    bool passed;
    std::vector<Reason> reasons;
};

namespace detail {
// The verdict a ctr_check_* call made (thrown as Error when the input is refused).
template <class F> Verdict verdict(F f) {
    std::unique_ptr<ctr_verdict, VerdictFree> v(call(f));
    Verdict out{ctr_verdict_passed(v.get()), {}};
    for (size_t i = 0; i < ctr_verdict_failure_count(v.get()); i++) {
        ctr_check_failure r = ctr_check_failure_default();
        call([&](ctr_error *e) { return ctr_verdict_failure(v.get(), i, &r, e); });
        out.reasons.push_back(
            {r.kind, r.message, r.face, r.edge_from, r.edge_to, r.vertex, r.component});
    }
    return out;
}
}  // namespace detail

// Judges `output` as an irreducible triangulation of `input`; with a history (kept,
// removed per contraction), also replays it.
inline Verdict check_reduce(const Mesh &input, const Mesh &output,
                            const std::vector<std::array<uint32_t, 2>> *history = nullptr) {
    static_assert(sizeof(std::array<uint32_t, 2>) == 2 * sizeof(uint32_t), "pairs are packed");
    static const uint32_t no_steps[2] = {0, 0};
    const uint32_t *steps =
        !history ? nullptr : history->empty() ? no_steps : history->front().data();
    return detail::verdict([&](ctr_error *e) {
        return ctr_check_reduce(input.get(), output.get(), steps, history ? history->size() : 0,
                                e);
    });
}

// Judges `output` as a simplification of `input` by a run with `options`.
inline Verdict check_simplify(const Mesh &input, const Mesh &output,
                              const SimplifyOptions &options = SimplifyOptions()) {
    return detail::verdict([&](ctr_error *e) {
        return ctr_check_simplify(input.get(), output.get(), &options, e);
    });
}

// Judges quads (input vertex ids) as a tri-quad conversion of `input`, with the paired
// triangulation and the pairs they state.
inline Verdict check_quad(const Mesh &input, const Quads &q) {
    return detail::verdict([&](ctr_error *e) {
        return ctr_check_quad(input.get(), q.quads.empty() ? nullptr : q.quads.front().data(),
                              q.quads.size(),
                              q.triangles.empty() ? nullptr : q.triangles.front().data(),
                              q.triangles.size(),
                              q.pairs.empty() ? nullptr : q.pairs.front().data(), e);
    });
}

// Judges `d` as a decimation of `input` by a run with `options`, its maps included.
inline Verdict check_decimate(const Mesh &input, const Decimated &d,
                              const DecimateOptions &options = DecimateOptions()) {
    ctr_decimate_options o = options;
    o.locked = options.locked_vertices.data();
    o.locked_count = options.locked_vertices.size();
    return detail::verdict([&](ctr_error *e) {
        return ctr_check_decimate(input.get(), d.mesh.get(), &o, d.vertex_map.data(),
                                  d.collapse_map.data(), d.face_origin.data(), e);
    });
}

}  // namespace contractible

#endif  // CONTRACTIBLE_HPP
