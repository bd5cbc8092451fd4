"""The scripts for tests/cross/scenario_runner.c: the shared machinery (scripts.py); each block's
script is its tests/blocks/<Block>/cross.py."""
