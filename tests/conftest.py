"""Shared fixtures: mpmath precision is restored after every test (mpmath's own practice)."""

import mpmath
import pytest


@pytest.fixture(autouse=True)
def _restore_mpmath_precision():
    saved = mpmath.mp.prec
    yield
    mpmath.mp.prec = saved
