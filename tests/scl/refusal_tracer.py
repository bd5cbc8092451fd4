"""A pytest plugin for tests/scl/test_refusals.py: traces the lines the compiler (lgf_fmus.scl)
runs during the session and writes them, as JSON [[file name, line], ...], to the file named by
the environment variable LGF_REFUSAL_TRACE."""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from lgf_fmus import scl

ROOT = str(Path(scl.__file__).parent)
_reached: set[tuple[str, int]] = set()


def _local(frame, event, arg):
    if event == "line":
        _reached.add((Path(frame.f_code.co_filename).name, frame.f_lineno))
    return _local


def _calls(frame, event, arg):
    return _local if frame.f_code.co_filename.startswith(ROOT) else None


def pytest_sessionstart(session):
    sys.settrace(_calls)


def pytest_sessionfinish(session, exitstatus):
    sys.settrace(None)
    Path(os.environ["LGF_REFUSAL_TRACE"]).write_text(json.dumps(sorted(_reached)))
