"""Benchmarks that reproduce the paper's tables on a hoard with known truth (synthetic or real)."""
