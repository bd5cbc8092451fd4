"""The Python test suite (pytest tests): FMPy against the FMUs, the independent models, the
blocks' own folders (tests/blocks/<Block>/)."""
