"""Shared fixtures of the Python API's tests: where the sources and the `tribo` command are
(CTest passes them in the environment: TRIBO_SOURCE_DIR, TRIBO_CLI)."""
import os
import pathlib

import pytest


@pytest.fixture(scope="session")
def source_dir():
    return pathlib.Path(os.environ.get("TRIBO_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("TRIBO_CLI")
    if not path:
        pytest.skip("TRIBO_CLI (the tribo command) is not set")
    return path


@pytest.fixture(scope="session")
def belt(source_dir):
    return str(source_dir / "scenes" / "belt.yaml")
