"""LGF_SimpleSmoothingFB (docs/behaviour.md §16): its model, spec, cross script, tests and
references; its scenarios are the build's, src/blocks/LGF_SimpleSmoothingFB/scenarios.py."""
