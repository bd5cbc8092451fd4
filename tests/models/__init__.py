"""What the independent Python models of the blocks (tests/blocks/<Block>/model.py, written from
docs/behaviour.md only, never from the C) share: the IEC 61131-3 data types (iec.py)."""
