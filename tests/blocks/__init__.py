"""One folder per block, named by its modelIdentifier; tests/lgf_blocks.py lists them and says what
each one holds."""
