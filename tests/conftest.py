"""Shared fixtures: mpmath precision is restored after every test (mpmath's own practice)."""

import mpmath
import pytest


@pytest.fixture(autouse=True)
def _restore_mpmath_precision():
    saved = mpmath.mp.prec
    yield
    mpmath.mp.prec = saved


#: Module fixtures that are expensive to compute, (test module, fixture) -> group: the tests that use one share a
#: pytest-xdist group, so that ``--dist loadgroup`` (workflow/test.sh, workflow/checks) computes each once instead
#: of once per worker.
SHARED_FIXTURES = {("test_reference_abel_fredholm", "references"): "abel-fredholm-references",
                   ("test_errata", "table"): "errata-table",
                   ("test_finite_element", "coarse"): "finite-element-coarse"}


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """The tests that need the whole errata table (about a minute to compute) belong to the slow tier; the tests
    of an expensive shared fixture to one xdist group."""
    for item in items:
        names = getattr(item, "fixturenames", ())
        if item.module.__name__.endswith("test_errata") and "table" in names:
            item.add_marker(pytest.mark.slow)
        for (module, fixture), group in SHARED_FIXTURES.items():
            if item.module.__name__.endswith(module) and fixture in names:
                item.add_marker(pytest.mark.xdist_group(group))


def pytest_sessionfinish(session, exitstatus):
    """Write the headroom records of this process (only with TORSIONAL_HEADROOM set; tests/tolerances.py)."""
    from tolerances import write_records

    write_records()
