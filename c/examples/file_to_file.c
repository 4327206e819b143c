/* file_to_file IN OUT: the irreducible triangulation of every component of IN, to OUT.
 * Build: cc -std=c11 -Wall -Wextra -Werror file_to_file.c -Iinclude \
 *        target/release/libcontractible_c.a -lm -lpthread -ldl -o file_to_file */
#include <stdio.h>
#include "contractible.h"

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: %s IN OUT\n", argv[0]);
        return 2;
    }
    ctr_error err;
    ctr_error_init(&err);
    ctr_mesh *mesh = ctr_mesh_read(argv[1], &err);
    ctr_reduce_result *result = mesh ? ctr_reduce(mesh, NULL, &err) : NULL;
    const ctr_mesh *out = ctr_reduce_result_mesh(result);
    if (result && ctr_mesh_write(out, argv[2], &err) == 0) {
        printf("%s: %zu vertices, %zu faces -> %s: %zu vertices, %zu faces\n", argv[1],
               ctr_mesh_vertex_count(mesh), ctr_mesh_face_count(mesh), argv[2],
               ctr_mesh_vertex_count(out), ctr_mesh_face_count(out));
    }
    ctr_reduce_result_free(result);
    ctr_mesh_free(mesh);
    if (err.code != CTR_OK) {
        fprintf(stderr, "error (%s): %s\n", err.kind, err.message);
        return err.code;
    }
    return 0;
}
