"""The tests of the SCL compiler (lgf_fmus.scl, docs/scl.md): the twins of the hand-written
blocks (tests/scl/twins/), each construct and rule against values computed by hand, and the
error messages."""
