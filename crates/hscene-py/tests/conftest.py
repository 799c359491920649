"""Shared fixtures: the repository root and the `hscene` binary the
Python pictures are compared with."""

import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def hscene_bin():
    """$HSCENE_BIN, else the newer of target/release/hscene and
    target/debug/hscene (build one with `cargo build --release`)."""
    given = os.environ.get("HSCENE_BIN")
    if given:
        return os.path.abspath(given)
    built = [ROOT / "target" / p / "hscene" for p in ("release", "debug")]
    built = [b for b in built if b.exists()]
    if not built:
        pytest.fail("no hscene binary: run `cargo build --release` or set HSCENE_BIN")
    return str(max(built, key=lambda b: b.stat().st_mtime))
