"""The libFuzzer target of the FMUs and its seeds (tests/fuzz/README.md): make_seeds writes the
committed corpus from each block's interface and tests/blocks/<Block>/fuzz_seeds.py."""
