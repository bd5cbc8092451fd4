"""LGF_SawToothCI (docs/behaviour.md §6): its model, spec, cross script, tests and references;
its scenarios are the build's, src/blocks/LGF_SawToothCI/scenarios.py."""
