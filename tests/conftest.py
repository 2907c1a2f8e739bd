"""Shared test set-up: tests/ on the import path, for the data modules kept beside the tests;
``--update-goldens`` to rewrite the golden files under tests/goldens/ instead of comparing with them."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))

GOLDENS = Path(__file__).parent / "goldens"


def pytest_addoption(parser):
    parser.addoption(
        "--update-goldens",
        action="store_true",
        default=False,
        help="rewrite the golden files under tests/goldens/ from what the code produces now",
    )


@pytest.fixture
def update_goldens(request) -> bool:
    """True when pytest runs with --update-goldens."""
    return request.config.getoption("--update-goldens")


@pytest.fixture
def golden(update_goldens):
    """``golden(name, text)``: assert ``text`` equals tests/goldens/<name>, or rewrite it with --update-goldens."""

    def check(name: str, text: str) -> None:
        path = GOLDENS / name
        if update_goldens:
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
            return
        assert path.exists(), f"no golden file {path}; run pytest with --update-goldens to write it"
        assert text == path.read_text(encoding="utf-8"), f"{name} differs; if the change is intended, --update-goldens"

    return check
