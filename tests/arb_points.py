"""Evaluate a function of one variable in Arb balls (python-flint) at an mpmath point, to the working digits.

mpmath's Bessel K and I are slow at 25-30 digits (their large-argument path sums a 2F0 term by term); Arb's are
ten to a hundred times faster and carry a rigorous error ball.  The quadratures of the tests keep mpmath's
``quad`` (and its error estimate) and take their integrands from here: the point is converted exactly enough
(ten digits beyond the working precision), the function is evaluated at twice the working precision, doubled
until the ball is relatively as small as the working digits ask (cancellation inside the function costs
precision, not accuracy), and the ball's midpoint is returned as an mpf.
"""

import flint
import mpmath

#: Precision doublings before giving up (a function with no finite ball at the point, e.g. Arb's 1F2 at a
#: large argument, raises instead of returning a wrong number).
DOUBLINGS = 6

#: Bits below which Arb's Bessel K of integer order is slow (python-flint 0.9: K_2 at six arguments in [3, 79]
#: took 100-140 ms at 200-400 bits, 5-10 ms at 480-1000 bits): a starting precision for integrands with K, a speed
#: choice (the ball decides the accuracy).  Other functions are faster at fewer bits (J_1: 0.04 ms at 280 bits,
#: 0.07 ms at 512).
BESSEL_K_BITS = 512


def at_mpf(function, x, absolute=False, bits=0):
    """``function`` (arb -> arb) at the mpf ``x``, as an mpf with the working digits of mpmath (relative, or with
    ``absolute`` absolute: for a function of size one that may cancel to nearly zero, such as a residual), starting
    at a working precision of at least ``bits``."""
    digits = mpmath.mp.dps + 5
    precision = max(8 * digits, bits)  # bits: a little over twice the digits
    saved = flint.ctx.prec
    try:
        for _ in range(DOUBLINGS):
            flint.ctx.prec = precision
            value = function(flint.arb(mpmath.nstr(x, digits + 10, strip_zeros=False)))
            scale = 1 if absolute else abs(value.mid())
            if value.is_finite() and value.rad() <= scale * flint.arb(10) ** -digits:
                return mpmath.mpf(value.mid().str(digits + 5, radius=False))
            precision *= 2
    finally:
        flint.ctx.prec = saved
    raise ArithmeticError(f"no {digits}-digit Arb ball at x = {x}")
