// decimate_file: decimation from C++ with the result judged by the conformance checker.
// Reads IN, decimates it to FACES faces (every collapse keeping the surface), checks the
// output and its provenance maps independently, writes OUT. Build: c++ -std=c++17 -Wall
//   -Wextra -Werror decimate_file.cpp -Iinclude target/release/libcontractible_c.a -lm
//   -lpthread -ldl -o decimate_file
#include <cstdio>
#include <cstdlib>

#include "contractible.hpp"

int main(int argc, char **argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s IN OUT FACES\n", argv[0]);
        return 2;
    }
    try {
        auto mesh = contractible::Mesh::read(argv[1]);
        contractible::DecimateOptions options;
        options.faces = std::strtoull(argv[3], nullptr, 10);
        auto d = contractible::decimate(mesh, options);
        auto verdict = contractible::check_decimate(mesh, d, options);
        if (!verdict.passed) {
            std::fprintf(stderr, "rejected (%s): %s\n", verdict.reasons[0].kind.c_str(),
                         verdict.reasons[0].message.c_str());
            return 1;
        }
        d.mesh.write(argv[2]);
        const char *why[] = {"target reached", "error cap reached", "blocked"};
        std::printf("%s: %zu faces -> %s: %zu faces (%s), largest error %.6g, checked\n",
                    argv[1], mesh.face_count(), argv[2], d.mesh.face_count(),
                    why[d.stats.stopped], d.stats.max_error);
    } catch (const contractible::Error &e) {
        std::fprintf(stderr, "error (%s): %s\n", e.kind.c_str(), e.what());
        return e.code;
    }
    return 0;
}
