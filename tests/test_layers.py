"""Modules import only what lies upstream of them.

The flow is problem bank → parse → judge (checking answers) → grade → report / export, then ``run``
(grading a class end to end) and ``serve`` (the self-check page), and the CLI on top; ``grader.errors`` is below
everything, and ``grader/__init__.py`` is the flat public face that may gather
from all of them.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "grader"
LAYERS = {
    "errors": 0, "interrupt": 0, "bank": 1, "parse": 2, "judge": 3, "grade": 4,
    "report": 5, "export": 5, "run": 6, "serve": 6, "cli": 7, "__main__": 8,
}  # fmt: skip
MODULES = sorted(path for path in PACKAGE.rglob("*.py") if path != PACKAGE / "__init__.py")


def _layer(path: Path) -> str:
    return path.relative_to(PACKAGE).parts[0].removesuffix(".py")


def _grader_imports(path: Path) -> set[str]:
    found = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        names = [alias.name for alias in node.names] if isinstance(node, ast.Import) else []
        if isinstance(node, ast.ImportFrom) and node.module:
            names = [node.module]
        for name in names:
            parts = name.split(".")
            if parts[0] == "grader":
                found.add(parts[1] if len(parts) > 1 else "__init__")
    return found


def test_every_module_belongs_to_a_layer():
    assert {_layer(path) for path in MODULES} <= LAYERS.keys()


@pytest.mark.parametrize("path", MODULES, ids=[str(path.relative_to(PACKAGE)) for path in MODULES])
def test_imports_flow_downstream_only(path):
    layer = _layer(path)
    for imported in _grader_imports(path):
        if imported == "__init__":
            assert layer in ("cli", "__main__"), f"{path.name} imports the package façade; import the module instead"
            continue
        assert LAYERS[imported] <= LAYERS[layer], f"{path.relative_to(PACKAGE)} imports grader.{imported}, downstream"


def test_the_checker_finds_a_violation():
    # The scan itself must be able to fail: a module importing grader.cli is caught.
    source = "from grader.cli import main\n"
    tree = ast.parse(source)
    module = next(node for node in ast.walk(tree) if isinstance(node, ast.ImportFrom))
    assert module.module.split(".")[1] == "cli" and LAYERS["cli"] > LAYERS["parse"]


def test_no_student_text_reaches_eval():
    # sympify and parse_expr call eval; none of our modules may call them.
    forbidden = {"eval", "exec", "sympify", "parse_expr", "S"}
    for path in MODULES:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call):
                name = getattr(node.func, "id", None) or getattr(node.func, "attr", None)
                assert name not in forbidden, f"{path.name}:{node.lineno} calls {name}"
