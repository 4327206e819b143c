// reduce_vectors: contractible from C++ with std::vector in and exceptions out. Reduces an
// octahedron given as arrays, prints the result, then shows the error a mesh with a
// non-manifold edge gets. Build: c++ -std=c++17 -Wall -Wextra -Werror reduce_vectors.cpp
//   -Iinclude target/release/libcontractible_c.a -lm -lpthread -ldl -o reduce_vectors
#include <cstdio>
#include <vector>

#include "contractible.hpp"

int main() {
    std::vector<double> positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    std::vector<uint32_t> faces = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                   2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    try {
        auto octahedron = contractible::Mesh::from_arrays(positions, 6, faces);
        ctr_description d = contractible::describe(octahedron);
        contractible::ReduceOptions options;
        options.keep_history = true;
        auto r = contractible::reduce(octahedron, options);
        std::printf("octahedron: chi %lld, %zu vertices -> %zu vertices, %zu faces, %zu "
                    "contractions\n", (long long)d.euler_characteristic,
                    octahedron.vertex_count(), r.mesh.vertex_count(), r.mesh.face_count(),
                    r.contractions.size());
        for (auto [kept, removed] : r.contractions)
            std::printf("  contracted %u into %u\n", removed, kept);
        faces.insert(faces.end(), {0, 2, 1});  // a third face on the edge [0, 2]
        contractible::reduce(contractible::Mesh::from_arrays(positions, 6, faces));
    } catch (const contractible::Error &e) {
        std::printf("refused (%s, face %lld): %s\n", e.kind.c_str(), (long long)e.face, e.what());
        return e.kind == "non_manifold_edge" ? 0 : 1;
    }
    return 1;
}
