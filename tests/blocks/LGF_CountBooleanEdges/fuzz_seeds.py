"""LGF_CountBooleanEdges's own fuzz seeds (docs/behaviour.md §12), beside those every block gets
from its interface (tests/fuzz/make_seeds.py): a single, a double and a long pulse in their
monitoring times, and 300 edges in one (past noOfEdges' 255)."""

SCENARIOS = {
    "single_double_long": "trigger=1 monitorTime=0.5; trigger=0; 6; get noOfEdges; "
    + "trigger=1; 1; trigger=0; 1; " * 2
    + "4; trigger=1; 8; get single double long severalEdges; monitorTime=0 trigger=0; 2x3",
    "many_edges": "cycleTime=0.001 monitorTime=1; "
    + "trigger=1; 1; trigger=0; 1; " * 300
    + "500x4",
}
