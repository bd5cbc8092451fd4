"""LGF_IecTimerOnOff (docs/behaviour.md §8): its model, spec, cross script, tests and references;
its scenarios are the build's, src/blocks/LGF_IecTimerOnOff/scenarios.py."""
