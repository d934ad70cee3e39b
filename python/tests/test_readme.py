# SPDX-License-Identifier: MIT
"""The README's Python snippet runs, and prints the clipped area `roiclip run` reports."""

import csv
import json
import os
import re
import shutil
import subprocess
import sys

import pytest


def _readme_snippet(source_dir):
    text = (source_dir / "README.md").read_text()
    section = text.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert len(blocks) == 1, "expected one ```python block in the README's Python section"
    return blocks[0]


def test_readme_snippet_matches_roiclip_run(source_dir, tmp_path):
    run = subprocess.run([sys.executable, "-c", _readme_snippet(source_dir)], cwd=source_dir,
                         capture_output=True, text=True, check=True)
    printed = run.stdout.strip().splitlines()[-1]

    cli = os.environ.get("ROICLIP_CLI")
    if not cli:
        pytest.skip("ROICLIP_CLI not set (the roiclip app is not built)")
    images = tmp_path / "images"
    images.mkdir()
    shutil.copy(source_dir / "images" / "scene_01.png", images)
    subprocess.run([cli, "run", str(images), "-o", str(tmp_path / "out")], check=True,
                   capture_output=True)
    with open(tmp_path / "out" / "summary.csv", newline="") as f:
        row = next(r for r in csv.DictReader(f) if r["image"] == "scene_01.png")
    assert row["status"] == "ok"
    assert printed == row["clipped_area"]  # both %.3f of the same double
    record = json.loads((tmp_path / "out" / "scene_01.json").read_text())
    assert float(printed) == pytest.approx(record["clipped_area"], abs=5e-4)
