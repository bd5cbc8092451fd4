"""LGF_PulseRelay's own fuzz seeds (docs/behaviour.md §11), beside those every block gets from its
interface (tests/fuzz/make_seeds.py): the output toggled by six trigger edges, then set and reset
against each other and the trigger."""

SCENARIOS = {
    "toggle_set_reset": "trigger=1; "
    + "trigger=0; 1; trigger=1; 1; " * 6
    + "get out; set=1 trigger=0; 2; reset=1 set=0; 2; trigger=1 set=1 reset=0; 1;"
    " trigger=0 set=0 reset=1; 3x2",
}
