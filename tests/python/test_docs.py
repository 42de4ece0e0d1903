"""docs/python.md says what a user can check: its speed figures come with the command that
measures them, not with a note only the project's tracker has (issue 57, item 6)."""

import os
import re

from conftest import SOURCE


def section(text, title):
    start = text.index(f"\n## {title}\n")
    end = text.find("\n## ", start + 1)
    return text[start:end if end >= 0 else len(text)]


def test_the_speed_figures_come_with_the_command_that_measures_them():
    with open(os.path.join(SOURCE, "docs", "python.md")) as f:
        speed = section(f.read(), "Speed")
    assert "/usr/bin/python3 scripts/bench-python.py build" in speed
    assert os.path.exists(os.path.join(SOURCE, "scripts", "bench-python.py"))
    assert re.search(r"\d+\.\d+ evaluations/s", speed) and re.search(r"\d+\.\d+ %", speed), speed
    assert not re.search(r"issue \d+|closing note", speed), speed
