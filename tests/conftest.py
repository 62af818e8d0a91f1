"""Shared fixtures: mpmath precision is restored after every test (mpmath's own practice)."""

import mpmath
import pytest


@pytest.fixture(autouse=True)
def _restore_mpmath_precision():
    saved = mpmath.mp.prec
    yield
    mpmath.mp.prec = saved


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """The tests that need the whole errata table (about a minute to compute) belong to the slow tier."""
    for item in items:
        if item.module.__name__.endswith("test_errata") and "table" in getattr(item, "fixturenames", ()):
            item.add_marker(pytest.mark.slow)


def pytest_sessionfinish(session, exitstatus):
    """Write the headroom records of this process (only with TORSIONAL_HEADROOM set; tests/tolerances.py)."""
    from tolerances import write_records

    write_records()
