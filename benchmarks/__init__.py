"""The benchmark table of the FMUs (python -m benchmarks.bench)."""
