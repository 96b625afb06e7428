//! Benchmarks of the generated dynamics; see `bench/README.md`.
