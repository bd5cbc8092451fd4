"""Releases: the release zip (release/dist.py, `make dist`) of the FMUs with their
compatibility information (tools/compat.py, which the build writes into each FMU)."""
