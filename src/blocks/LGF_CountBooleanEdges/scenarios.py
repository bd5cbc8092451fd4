"""The demo scenarios of LGF_CountBooleanEdges (docs/behaviour.md §12), as
tools/blocks.py describes them."""

from tools.scenario import Scenario


def _pulses(*times: float) -> list[tuple[float, dict]]:
    """trigger TRUE at the first time, FALSE at the second, TRUE at the third, ..."""
    return [(t, {"trigger": k % 2 == 0}) for k, t in enumerate(times)]


SCENARIOS = [
    Scenario(
        name="count_boolean_edges",
        title="LGF_CountBooleanEdges, 1 s windows: single, double, long, several, double held, "
        "an edge right after a single",
        stop_time=14.0,
        inputs=[
            (0.0, {"trigger": False, "monitorTime": 1.0}),
            *_pulses(0.5, 0.7),  # one edge: single for one call at 1.6 s
            *_pulses(2.5, 2.7, 2.9, 3.1),  # two edges: double at 3.6 s
            *_pulses(4.5, 6.5),  # one edge, held: long from 5.6 s while trigger is TRUE
            *_pulses(7.5, 7.6, 7.7, 7.8, 7.9, 8.0, 8.1, 8.3),  # four edges: severalEdges
            *_pulses(9.5, 9.7, 9.9, 11.5),  # two edges, held: double from 10.6 s while TRUE
            # one edge again: single at 13.1 s; an edge in the next call, before a call with
            # trigger FALSE has cleared the result, counts into that window: double from 13.2 s
            # while held, cleared at 13.6 s
            *_pulses(12.0, 12.1, 13.1, 13.5),
        ],
    ),
]
