"""The scenario runner's scripts and their checks (tests/cross/scenario_runner.c): the shared
machinery of the scripts and the demo scenarios as scripts (scripts.py), each block's fixed
script in its tests/blocks/<Block>/cross.py, and what tests/test_win64.py and
tests/test_aarch64.py share (replay.py)."""
