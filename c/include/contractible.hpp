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
    const double *p = ctr_mesh_positions(out);
    const uint32_t *f = ctr_mesh_faces(out);
    size_t n = ctr_mesh_vertex_count(out), m = ctr_mesh_face_count(out);
    std::vector<double> positions = p ? std::vector<double>(p, p + 3 * n) : std::vector<double>();
    const uint32_t *map = ctr_reduce_result_vertex_map(r.get());
    size_t k = 0;
    const uint32_t *steps = ctr_reduce_result_contractions(r.get(), &k);
    std::vector<std::array<uint32_t, 2>> contractions(k);
    for (size_t i = 0; i < k; i++) contractions[i] = {steps[2 * i], steps[2 * i + 1]};
    return Reduced{Mesh::from_arrays(positions, n, std::vector<uint32_t>(f, f + 3 * m)),
                   std::vector<uint32_t>(map, map + n), std::move(contractions),
                   ctr_reduce_result_component_count(r.get())};
}

}  // namespace contractible

#endif  // CONTRACTIBLE_HPP
