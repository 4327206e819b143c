//! Seeded, deterministic generators of closed triangulated surfaces.
