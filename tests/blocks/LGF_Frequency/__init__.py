"""LGF_Frequency (docs/behaviour.md §10): its model, spec, cross script, tests and references;
its scenarios are the build's, src/blocks/LGF_Frequency/scenarios.py."""
