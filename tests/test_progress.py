"""Long work reports its progress to a listener (the command line's progress bar)."""

from __future__ import annotations

import ballscrew
from ballscrew.progress import advance, listening
from quick_cases import QUICK, write_case


def test_advance_without_a_listener_does_nothing_and_a_listener_hears_it():
    advance("nothing listens", 1, 2)
    heard = []
    with listening(lambda *report: heard.append(report)):
        advance("work", 1, 4)
    advance("after", 1, 1)
    assert heard == [("work", 1.0, 4.0)]


def test_the_thermal_transient_reports_every_step(tmp_path):
    case = ballscrew.load_case(
        write_case(tmp_path, "gao2019_tcr.toml", QUICK | {"thermal.model": "network"})
    )
    heard = []
    with listening(lambda *report: heard.append(report)):
        ballscrew.thermal_field(case)
    steps = [done for task, done, _ in heard if task == "thermal transient"]
    total = {total for task, _, total in heard if task == "thermal transient"}
    assert len(total) == 1 and steps == list(range(1, int(total.pop()) + 1))
    assert ("thermal steady state", 1.0, 1.0) in heard
