r"""Special functions of the Abel-Fredholm kernels in arbitrary precision (python-flint).

Everything is computed with ``arb`` numbers at flint's working precision (set it with
``arbitrary_precision.working_digits``); the same code runs at any precision.

* ``bessel_k2_i2``, ``bessel_ratio``: K2, I2 and rho = K2/I2 (power series with extra bits
  below (prec ln 2)/2 + 12, the ratio of Hankel expansions above).
* ``i2_excess``: I2(x) - x^2/8 without cancellation.
* ``sinh_excess``, ``sinh_excess_matrix``: A(x) = sinh(x) - x without cancellation, alone and as the matrices of
  the kernels (module ``sinh_excess_mp``, re-exported here).
* ``integral_x_i1``: F(x) = int_0^x y I1(y) dy = x^3/6 1F2(3/2; 2, 5/2; x^2/4) (eq. A3 of
  ``kernels``): power series (positive terms) below ``asymptotic_threshold()``, above it
  F = x I0(x) - int_0^x I0 from the expansions of I0 (DLMF 10.40.1) and of int_0^x I0
  (term by term, beta_k = alpha_k + (k - 1/2) beta_(k-1)).  The latter has terms
  ~ Gamma(k) x^-k, smallest near k = x, of relative size exp(-x): hence the threshold
  prec ln 2 + 12.
* ``tail_coefficients``, ``tail_integrals``: the large-xi expansion of the E_1 integrand and
  the integrals J_k(eps) = int_X^inf exp(-eps xi) xi^(-k-3/2) d xi used by
  ``kernels_mp.spinning_tail`` (eq. M4 there).

All expansion coefficients are exact rationals (python-flint ``fmpq``).
"""

from __future__ import annotations

import functools
import math

import flint

from .arbitrary_precision import to_full_accuracy
from .sinh_excess_mp import sinh_excess, sinh_excess_matrix, sinh_excess_values

__all__ = [
    "EXTRA_DECAYS",
    "asymptotic_threshold",
    "expansion_terms",
    "bessel_k2_i2",
    "bessel_ratio",
    "i2_excess",
    "sinh_excess",
    "sinh_excess_matrix",
    "sinh_excess_values",
    "integral_x_i1",
    "integral_x_i1_excess",
    "integral_x_i1_pair",
    "tail_coefficients",
    "tail_integrals",
]

#: Extra e-folds beyond the working precision in thresholds and truncations.
EXTRA_DECAYS = 12.0


def asymptotic_threshold(prec: int | None = None) -> float:
    """Smallest xi at which the large-xi expansions are used: exp(-xi) < 2^-prec e^-12.

    The expansion of int_0^x I0 (inside F) has terms ~ Gamma(k) x^-k, smallest near
    k = x, of relative size exp(-x) (its algebraic companion).
    """
    prec = flint.ctx.prec if prec is None else prec
    return prec * math.log(2.0) + EXTRA_DECAYS


def expansion_terms(x: float, scale: float = 1.0) -> int:
    """Terms of an expansion with coefficients ~ Gamma(k + 1) / scale^k at x, for 2^-prec.

    Capped at the smallest term (k ~ scale x).
    """
    prec = flint.ctx.prec
    count = 8
    if count < scale * x:
        log_size, target = math.log(scale * x), -(prec + 20) * math.log(2.0)
        while count < scale * x:
            if math.lgamma(count + 1) - count * log_size < target:
                break
            count += 8
    return count


def bessel_k2_i2(x):
    """(K2(x), I2(x)) for exact arb x > 0 from their power series (DLMF 10.25.2, 10.31.1).

    K2 = 2/x^2 - 1/2 - ln(x/2) I2 + (1/2) sum_k (psi(k+1) + psi(k+3)) tau_k,
    I2 = sum_k tau_k,  tau_k = (x/2)^(2k+2) / (k! (k+2)!).
    The terms reach exp(x) while K2 ~ exp(-x): the sums run with 2.9 x + 24 extra bits
    (the cancellation costs 2 x / ln 2 bits), so both are returned to the working
    precision.  Meant for x up to ~ the working precision in nats (above that,
    ``bessel_ratio`` uses the Hankel expansions).  The weights psi(k+1) + psi(k+3) (harmonic
    numbers and Euler's gamma at that raised precision) do not depend on x: ``_digamma_weights``.
    """
    prec = flint.ctx.prec
    xf = float(x)
    flint.ctx.prec = prec + math.ceil(2.9 * xf) + 24
    try:
        weights = _digamma_weights(flint.ctx.prec)
        size = len(weights)
        quarter = x * x / 4
        tau = quarter / 2  # k = 0: (x/2)^2 / (0! 2!)
        i2 = tau
        psi_sum = weights[0] * tau
        limit = flint.arb(2) ** (-flint.ctx.prec)  # an arb: 2.0**-prec underflows above 1074 bits
        k = 0
        while True:
            k += 1
            if k == size:
                weights = _digamma_weights(flint.ctx.prec, 2 * k)
                size = len(weights)
            tau = tau * quarter / (k * (k + 2))
            i2 += tau
            psi_sum += weights[k] * tau
            if k > xf and tau * (1 + math.log(k + 3)) < limit * i2:
                break
        k2 = 2 / (x * x) - flint.arb(1) / 2 - (x / 2).log() * i2 + psi_sum / 2
    finally:
        flint.ctx.prec = prec
    return +k2, +i2


#: psi(k+1) + psi(k+3) of ``bessel_k2_i2`` per precision: [weights, H_k, H_(k+2)] (``_digamma_weights``).
_DIGAMMA_WEIGHTS: dict = {}
_DIGAMMA_WEIGHTS_LIMIT = 4096


def _digamma_weights(prec: int, count: int = 64) -> list:
    """[H_k + H_(k+2) - 2 gamma for k < count] (at least) at ``prec`` bits, H the harmonic numbers (H_2 = 3/2):
    psi(k+1) + psi(k+3) as ``bessel_k2_i2`` sums them, each H_k the running sum of 1/k at ``prec`` bits (so the
    same bits for every x with that raised precision); cached per precision, extended on demand."""
    entry = _DIGAMMA_WEIGHTS.get(prec)
    if entry is None:
        if len(_DIGAMMA_WEIGHTS) > _DIGAMMA_WEIGHTS_LIMIT:
            _DIGAMMA_WEIGHTS.clear()
        saved = flint.ctx.prec
        flint.ctx.prec = prec
        try:
            harmonic_k, harmonic_k2 = flint.arb(0), flint.arb(3) / 2  # H_0, H_2
            entry = [[harmonic_k + harmonic_k2 - 2 * flint.arb.const_euler()], harmonic_k, harmonic_k2]
        finally:
            flint.ctx.prec = saved
        _DIGAMMA_WEIGHTS[prec] = entry
    weights = entry[0]
    if len(weights) < count:
        saved = flint.ctx.prec
        flint.ctx.prec = prec
        try:
            gamma = flint.arb.const_euler()
            harmonic_k, harmonic_k2 = entry[1], entry[2]
            for k in range(len(weights), count):
                harmonic_k += flint.arb(1) / k
                harmonic_k2 += flint.arb(1) / (k + 2)
                weights.append(harmonic_k + harmonic_k2 - 2 * gamma)
            entry[1], entry[2] = harmonic_k, harmonic_k2
        finally:
            flint.ctx.prec = saved
    return weights


def bessel_ratio(xi):
    """rho(xi) = K2(xi) / I2(xi) for a sequence of exact xi > 0, at full working precision.

    Below (prec ln 2 + 24)/2: ``bessel_k2_i2`` (power series with extra bits); above: the
    ratio of the Hankel expansions, pi exp(-2 xi) sum kappa_k xi^-k / sum (-1)^k kappa_k
    xi^-k (relative error exp(-2 xi) < 2^-prec e^-24), both sums by Horner's rule, in C for
    all the nodes with the same number of terms at once (``_bessel_ratio_asymptotic``).
    """
    switch = (flint.ctx.prec * math.log(2.0) + 24.0) / 2.0
    out = [None] * len(xi)
    far = {}  # number of expansion terms -> indices of the nodes above the switch
    for index, x in enumerate(xi):
        xf = float(x)
        if xf >= switch:
            far.setdefault(expansion_terms(xf, 2.0), []).append(index)
        else:
            k2, i2 = bessel_k2_i2(x)
            out[index] = k2 / i2
    for count, indices in far.items():
        for index, value in zip(indices, _bessel_ratio_asymptotic([xi[i] for i in indices], count), strict=True):
            out[index] = value
    return out


def _bessel_ratio_asymptotic(points, count: int) -> list:
    """pi exp(-2 x) sum_k kappa_k x^-k / sum_k (-1)^k kappa_k x^-k, k < count, at the exact ``points``.

    Horner's rule in 1/x from the highest term (``arb_poly.evaluate``, term by term the same
    operations as the loop it replaced: Arb evaluates by Horner's rule below 1024 bits; above, the
    loop in Python)."""
    kappa = _hankel_arb(2, count, flint.ctx.prec)
    inverses = [1 / x for x in points]
    if flint.ctx.prec < 1024 and count > 2:
        numerators = flint.arb_poly(list(kappa)).evaluate(inverses, algorithm="iter")
        denominators = flint.arb_poly([c if k % 2 == 0 else -c for k, c in enumerate(kappa)]).evaluate(
            inverses, algorithm="iter")
    else:
        numerators, denominators = [], []
        for inverse in inverses:
            numerator, denominator = flint.arb(0), flint.arb(0)
            for k in range(count - 1, -1, -1):
                c = kappa[k]
                numerator = numerator * inverse + c
                denominator = denominator * inverse + (c if k % 2 == 0 else -c)
            numerators.append(numerator)
            denominators.append(denominator)
    pi = flint.arb.pi()
    return [pi * (-2 * x).exp() * numerator / denominator
            for x, numerator, denominator in zip(points, numerators, denominators, strict=True)]


def i2_excess(x):
    """I2(x) - x^2/8 = sum_{k>=1} (x/2)^(2k+2) / (k! (k+2)!) (series below x = 2)."""
    if float(x) >= 2.0:  # no cancellation left: python-flint's I2 at full accuracy
        return to_full_accuracy(lambda y: y.bessel_i(2), x) - x * x / 8
    eps = flint.arb(2) ** (-flint.ctx.prec)
    quarter = x * x / 4
    term = quarter * quarter / 6  # k = 1: (x/2)^4 / (1! 3!)
    total = term
    k = 1
    while abs(float(term)) > float(eps) * abs(float(total)):
        k += 1
        term = term * quarter / (k * (k + 2))
        total += term
    return total


def integral_x_i1(x):
    """F(x) = int_0^x y I1(y) dy = x^3/6 1F2(3/2; 2, 5/2; x^2/4) (eq. A3), arb x >= 0.

    Power series (positive terms) below ``asymptotic_threshold()``, Hankel expansion above
    (F = x I0(x) - int_0^x I0 with both expansions; relative error below 2^-prec).
    """
    if float(x) >= asymptotic_threshold():
        return _integral_x_i1_asymptotic(x)
    return _integral_x_i1_series(x, first=True)


def integral_x_i1_excess(x):
    """F(x) - x^3/6 (the first term of the power series removed), arb x >= 0."""
    if float(x) >= asymptotic_threshold():
        return _integral_x_i1_asymptotic(x) - x**3 / 6
    return _integral_x_i1_series(x, first=False)


def integral_x_i1_pair(x):
    """(F(x), F(x) - x^3/6) for arb x >= 0 (the xi-layer's load profiles), one evaluation for both.

    Below ``asymptotic_threshold()``: F - x^3/6 = (x^5/80) 2F3(1, 5/2; 2, 3, 7/2; x^2/4) (the series
    of ``integral_x_i1`` from its second term: positive terms, no cancellation) by Arb's
    hypergeometric series in C (a rigorous ball, 2-3 times faster than the series in Python), and
    F = that + x^3/6; above it the Hankel expansion of ``integral_x_i1`` (the same as there).
    """
    if float(x) >= asymptotic_threshold():
        full = _integral_x_i1_asymptotic(x)
        return full, full - x**3 / 6
    if float(x) == 0.0:
        return flint.arb(0), flint.arb(0)
    x2 = x * x
    half = flint.arb(1) / 2
    excess = x2 * x2 * x / 80 * flint.arb.hypgeom(x2 / 4, [1, 5 * half], [2, 3, 7 * half])
    return excess + x2 * x / 6, excess


def _integral_x_i1_series(x, first: bool):
    """sum_k x^(2k+3) / ((2k+3) 2^(2k+1) k! (k+1)!), from k = 0 or k = 1."""
    if float(x) == 0.0:
        return flint.arb(0)
    x2 = x * x
    term = x * x2 / 2  # x^3 / (2^1 0! 1!)
    total = term / 3 if first else flint.arb(0)
    limit = 2.0 ** (-flint.ctx.prec - 4)
    k = 0
    while True:
        k += 1
        term = term * x2 / (4 * k * (k + 1))
        piece = term / (2 * k + 3)
        total += piece
        if 2 * k > float(x) and float(piece) <= limit * float(total):
            return total


def _integral_x_i1_asymptotic(x):
    """F(x) = exp(x) (2 pi x)^(-1/2) x sum_k phi_k x^-k (large x)."""
    coefficients = _f_coefficients_arb(expansion_terms(float(x)), flint.ctx.prec)
    inverse = 1 / x
    total = flint.arb(0)
    for c in reversed(coefficients):
        total = total * inverse + c
    return x.exp() * x * total / (2 * flint.arb.pi() * x).sqrt()


# --------------------------------------------------------------------------- Hankel-type expansions


@functools.lru_cache(maxsize=64)
def _hankel(nu: int, count: int) -> tuple:
    """a_k(nu) = prod_{j=1..k} (4 nu^2 - (2j - 1)^2) / (k! 8^k), k < count (DLMF 10.40), exact (cached)."""
    out = [flint.fmpq(1)]
    for k in range(1, count):
        out.append(out[-1] * flint.fmpq(4 * nu * nu - (2 * k - 1) ** 2, 8 * k))
    return tuple(out)


@functools.lru_cache(maxsize=256)
def _hankel_arb(nu: int, count: int, prec: int) -> tuple:
    """``_hankel(nu, count)`` rounded to arb at ``prec`` bits (the working precision of the caller; cached)."""
    saved = flint.ctx.prec
    flint.ctx.prec = prec
    try:
        return tuple(flint.arb(a) for a in _hankel(nu, count))
    finally:
        flint.ctx.prec = saved


@functools.lru_cache(maxsize=8)
def _f_coefficients_cached(count: int):
    """phi_k of exp(-x) F(x) = (2 pi x)^(-1/2) x sum_k phi_k x^-k, exact rationals.

    F = x I0(x) - int_0^x I0 with I0 ~ e^x (2 pi x)^(-1/2) sum alpha_k x^-k and
    int_0^x I0 ~ e^x (2 pi x)^(-1/2) sum beta_k x^-k, beta_k = alpha_k + (k - 1/2) beta_(k-1).
    """
    alpha = [a * (-1) ** k for k, a in enumerate(_hankel(0, count))]
    beta = [alpha[0]]
    for k in range(1, count):
        beta.append(alpha[k] + flint.fmpq(2 * k - 1, 2) * beta[-1])
    return tuple([alpha[0]] + [alpha[k] - beta[k - 1] for k in range(1, count)])


def _f_coefficients(count: int):
    return _f_coefficients_cached(8 * math.ceil(count / 8))[:count]


@functools.lru_cache(maxsize=256)
def _f_coefficients_arb(count: int, prec: int) -> tuple:
    """``_f_coefficients(count)`` rounded to arb at ``prec`` bits (the caller's working precision; cached: the
    same roundings for every x, which ``_integral_x_i1_asymptotic`` otherwise repeats at each of its nodes)."""
    saved = flint.ctx.prec
    flint.ctx.prec = prec
    try:
        return tuple(flint.arb(c) for c in _f_coefficients(count))
    finally:
        flint.ctx.prec = saved


@functools.lru_cache(maxsize=8)
def _tail_coefficients_cached(count: int):
    """c_k of exp(2 xi) rho(xi) exp(-xi) F(xi) (2 pi xi)^(1/2) / xi = pi sum_k c_k xi^-k."""
    phi = _f_coefficients(count)
    kappa = _hankel(2, count)  # K2 ~ sqrt(pi/(2 xi)) e^-xi sum kappa_k xi^-k
    sigma = [a * (-1) ** k for k, a in enumerate(kappa)]  # I2 ~ e^xi / sqrt(2 pi xi) sum sigma_k xi^-k
    ratio = []
    for k in range(count):  # kappa / sigma as a power series in 1/xi
        value = kappa[k]
        for j in range(1, k + 1):
            value -= sigma[j] * ratio[k - j]
        ratio.append(value)
    return tuple(sum((phi[j] * ratio[k - j] for j in range(k + 1)), flint.fmpq(0)) for k in range(count))


def tail_coefficients(count: int):
    """c_k, k < count, of the large-xi expansion of the E_1 integrand (see ``_tail_coefficients_cached``)."""
    return _tail_coefficients_cached(8 * math.ceil(count / 8))[:count]


@functools.lru_cache(maxsize=64)
def _tail_constants(start: float, count: int, prec: int) -> tuple:
    """(X, X^(-1/2), 1/X, (k + 1/2 for k < count)) at ``prec`` bits for ``tail_integrals`` (the same for every eps)."""
    saved = flint.ctx.prec
    flint.ctx.prec = prec
    try:
        x = flint.arb(start)
        half = flint.arb(1) / 2
        return x, x ** (-half), 1 / x, tuple(k + half for k in range(count))
    finally:
        flint.ctx.prec = saved


def tail_integrals(eps, start, count: int):
    """J_k(eps) = int_X^inf exp(-eps xi) xi^(-k-3/2) d xi, k < count, eq. (M4); X = ``start``.

    Midpoint arithmetic (eps is replaced by its exact midpoint) with 20 extra bits: ball
    radii would otherwise grow through the recurrences and Arb would drop midpoint
    precision.  Gamma(-k-1/2, eps X) comes from python-flint at full accuracy
    (``to_full_accuracy``: arb's incomplete gamma loses up to ~45 bits near eps X ~ 10).
    """
    prec = flint.ctx.prec
    eps = eps.mid()
    flint.ctx.prec = prec + 20
    try:
        x, root, inverse, shifted = _tail_constants(start, count, flint.ctx.prec)  # X, X^(-1/2), 1/X, k + 1/2
        if eps.is_zero():
            return [+(x ** -s / s) for s in shifted]
        decay = (-eps * x).exp()
        power = decay * root
        powers = [power]  # exp(-eps X) X^(-k-1/2)
        for _ in range(1, count):
            power = (power * inverse).mid()
            powers.append(power)
        pivot = min(count - 1, int(float(eps) * start))
        j = [None] * count
        gamma = to_full_accuracy(lambda z, a: z.gamma_upper(a), (eps * x).mid(), -shifted[pivot])
        value = (eps ** shifted[pivot] * gamma).mid()
        j[pivot] = value
        for k in range(pivot + 1, count):  # stable for k > eps X
            value = ((powers[k] - eps * value) / shifted[k]).mid()
            j[k] = value
        value = j[pivot]
        for k in range(pivot, 0, -1):  # stable for k < eps X
            value = ((powers[k] - shifted[k] * value) / eps).mid()
            j[k - 1] = value
    finally:
        flint.ctx.prec = prec
    return [+v for v in j]
