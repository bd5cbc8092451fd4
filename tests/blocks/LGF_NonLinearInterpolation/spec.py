"""LGF_NonLinearInterpolation's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them."""

from hypothesis import strategies as st

from src.blocks.LGF_NonLinearInterpolation.table import setpoints
from tests.block_spec import BlockSpec, rarely_true

from .model import NonLinearInterpolation

# Quarter units: the table's inputValues and many values fall on the same grid, so values on a
# point (where the search steps down, docs/behaviour.md §20.3, §20.4) are frequent; a gap of at
# least 0.25 between points and moderate outputValues keep every slope finite (no NaN to
# compare).
quarters = st.integers(-1200, 1200).map(lambda i: i / 4)
values = st.one_of(quarters, st.floats(-1e4, 1e4, allow_nan=False), st.sampled_from([0.0, -0.0]))
outputs = st.one_of(
    st.integers(-100, 100).map(float), st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)
)


def _table():
    """numberOfSetpoints 2 ... 6 with distinct inputValues, ascending or in any order: the FMU
    computes a table out of order by the original's search (docs/behaviour.md §20.5), where the
    segment depends on the one the search starts from."""
    distinct = st.lists(st.integers(-1000, 1000), min_size=2, max_size=6, unique=True)
    xs = distinct.flatmap(lambda x: st.one_of(st.just(sorted(x)), st.permutations(x)))
    return xs.flatmap(
        lambda x: st.fixed_dictionaries(
            {
                "numberOfSetpoints": st.just(len(x)),
                **setpoints([(st.just(i / 4), outputs) for i in x]),
            }
        )
    )


SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: NonLinearInterpolation(cycle_us, **parameters),
    cycles_us=st.sampled_from([1000, 10000, 100000, 3300, 7]),
    parameters=_table,
    inputs={
        "value": values,
        "defaultOutValue": outputs,
        "enDefaultOutValue": rarely_true,
        "track": rarely_true,
        "reset": rarely_true,
    },
    # the outputValues may change at run time (a table in a data block); the inputValues stay,
    # so that no two points come to share one
    tunables=lambda parameters: {
        f"setpoints[{i}].outputValue": outputs for i in range(parameters["numberOfSetpoints"])
    },
)

ACTIVE = {"value": 30.0}

# Names of the original V3.0.1 block (docs/behaviour.md §1.5, §20.1).
ORIGINAL_NAMES = ["LGF_typeNonLinSetpoints"]
