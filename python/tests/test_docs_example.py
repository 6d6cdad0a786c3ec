"""docs/python.md's worked example runs, its assertions hold, and it prints what the page shows."""
import os
import pathlib
import subprocess
import sys

import disklab

MARKER = "<!-- example: run by python/tests/test_docs_example.py -->\n```python\n"


def blocks(page):
    start = page.index(MARKER) + len(MARKER)
    code = page[start:page.index("```", start)]
    rest = page[page.index("```", start) + 3:]
    shown = rest[rest.index("```\n") + 4:]
    return code, shown[:shown.index("```")]


def test_the_worked_example_runs_and_prints_what_the_page_shows(tmp_path):
    page = (pathlib.Path(os.environ["DISKLAB_SOURCE_DIR"]) / "docs" / "python.md").read_text()
    code, shown = blocks(page)
    env = {**os.environ, "PYTHONPATH": str(pathlib.Path(disklab.__file__).parents[1])}
    run = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, env=env,
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout == shown
    assert (tmp_path / "python_example.png").stat().st_size > 10_000
