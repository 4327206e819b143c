//! Mesh file I/O (OFF, OBJ, PLY ascii/binary, optionally gzip-compressed).
