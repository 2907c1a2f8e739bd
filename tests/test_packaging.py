"""What an installed wheel carries: an install that is not editable must find its templates.

The templates live at the top of the repository (``templates/``) and the wheel maps them
into the package; a package or a template left out would only show when a department
installs the grader and its first report fails to render.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_the_wheel_carries_every_package_and_every_template(tmp_path):
    source = tmp_path / "source"  # a copy: building in the checkout would leave build/ and egg-info behind
    source.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, source / name)
    for folder in ("grader", "templates"):
        shutil.copytree(ROOT / folder, source / folder, ignore=shutil.ignore_patterns("__pycache__"))
    subprocess.run(
        [sys.executable, "-m", "pip", "wheel", "--no-deps", "-q", "-w", tmp_path, source],  # as pip installs it
        check=True,
        capture_output=True,
    )
    (wheel,) = tmp_path.glob("grader-*.whl")
    carried = set(zipfile.ZipFile(wheel).namelist())
    templates = sorted(path.name for path in (ROOT / "templates").iterdir() if path.suffix == ".j2")
    assert templates
    assert {f"grader/templates/{name}" for name in templates} <= carried
    modules = {path.relative_to(ROOT).as_posix() for path in (ROOT / "grader").rglob("*.py")}
    assert modules <= carried, f"left out of the wheel: {sorted(modules - carried)}"
