"""Motor tests: each test's motor specs are forgotten afterwards, as its registered parts are."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from assembler.models.motor_table import MOTORS


@pytest.fixture(autouse=True)
def isolated_motors() -> Iterator[None]:
    """Whatever motor specs a test registers are removed afterwards (the shipped ones stay)."""
    before = MOTORS.state()
    yield
    MOTORS.restore(before)
