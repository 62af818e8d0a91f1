r"""A(x) = sinh(x) - x in arbitrary precision (python-flint), alone and as the matrices A(xi_k t_i) of the Abel-Fredholm
kernels (``nystrom_mp``, ``kernels_mp``).

Everything is computed with ``arb`` numbers at flint's working precision.  ``sinh_excess``: Taylor series below
1/2 (no cancellation).  ``sinh_excess_matrix`` / ``sinh_excess_values``: the same numbers for a whole matrix,
by three methods (the series, the independent check; "sharp", rigorous balls with the cancelled bits added to the
working precision; "cancel", the same at the products' midpoints), with the exponentials of a block of nodes
c_p + d_j factored into outer products.
"""

from __future__ import annotations

import math

import flint
import numpy as np

__all__ = ["sinh_excess", "sinh_excess_matrix", "sinh_excess_values"]


def sinh_excess(x):
    """A(x) = sinh(x) - x for arb x >= 0 (Taylor series below 1/2: no cancellation)."""
    xf = float(x)
    if xf >= 0.5:
        return x.sinh() - x
    if xf == 0.0:
        return flint.arb(0)
    x2 = x * x
    term = x * x2 / 6
    total = term
    k = 1
    limit = 2.0 ** (-flint.ctx.prec)
    ratio = xf * xf
    size = 1.0
    while size > limit:
        k += 1
        term = term * x2 / ((2 * k) * (2 * k + 1))
        total += term
        size *= ratio / ((2 * k) * (2 * k + 1))
    return total


def sinh_excess_matrix(points, xi, method: str = "series", lengths=None, blocks=()) -> flint.arb_mat:
    """The matrix A(xi_k t_i) (len(points) x len(xi)) as an ``arb_mat``.

    ``method="series"``: the same values as ``sinh_excess`` element by element, bit for bit (the
    branch is chosen from float copies and the product xi t is formed once): Taylor series in
    Python below 1/2 (the slow path; kept as the independent check of the others).
    ``method="sharp"``: Arb's sinh(x) - x, below 1/2 with the bits the difference cancels
    (log2(6/x^2), in steps of 32) added to the working precision, the products xi t formed
    exactly (at twice the working precision: nodes and points with zero radius, as the Nystrom
    solve's are, give exact products).  A rigorous ball for any input (a point with a radius
    keeps it, at the price of a wider ball below 1/2), as tight as the series' for exact input
    and several times faster where most products are small (small b).  The Nystrom solve uses it.
    ``method="cancel"``: the same at the midpoints of the products (a point's radius is dropped:
    for the profiles, whose error estimate compares two solves); equal to the series to within
    rounding.
    ``lengths``: row i holds A(xi_k t_i) for k < lengths[i] only and exact zeros beyond (for
    sums whose rest the caller bounds; default: every row full).
    ``blocks`` (``sharp`` and ``cancel``): runs of nodes xi = c_p + d_j (``kernels_mp.XiQuadrature.blocks``,
    the nodes in that order).  Where a block's products are all >= 1/2, exp(xi t) = exp(c_p t) exp(d_j t)
    is formed as an outer product in C from P + m exponentials instead of P m (and the same for
    exp(-xi t)), then A = (exp(xi t) - exp(-xi t))/2 - xi t, at 8 bits more than the working
    precision (the products of two rounded exponentials), rounded once: rigorous balls,
    as tight as the direct sinh's.
    """
    points = list(points)
    return flint.arb_mat(len(points), len(xi), sinh_excess_values(points, xi, method, lengths, blocks))


def sinh_excess_values(points, xi, method: str = "series", lengths=None, blocks=()) -> list:
    """The entries of ``sinh_excess_matrix`` (the same arguments) as a row-major list: A(xi_k t_i) at i len(xi) + k."""
    if method not in ("series", "sharp", "cancel"):
        raise ValueError(f"method must be 'series', 'sharp' or 'cancel', got {method!r}")
    points = list(points)
    n_xi = len(xi)
    if lengths is None:
        lengths = [n_xi] * len(points)
    elif len(lengths) != len(points) or any(not 0 <= k <= n_xi for k in lengths):
        raise ValueError(f"lengths must give one count in [0, {n_xi}] per point")
    if method == "series":
        return _sinh_excess_series_values(points, xi, lengths)
    n_points = len(points)
    xi_float = np.array([float(x) for x in xi])
    t_float = [float(t) for t in points]
    if method == "cancel":
        points = [t.mid() for t in points]
    zero = flint.arb(0)
    prec = flint.ctx.prec
    values = np.full(n_points * n_xi, zero, dtype=object)  # row-major; exact zeros beyond each row's length
    pending = np.arange(n_xi)[None, :] < np.array(lengths, dtype=np.int64)[:, None]  # entries still to compute
    xi_blocks = {}  # (block, panels) -> the nodes of its first panels as an arb_mat
    try:
        for i, (t, t_f, length) in enumerate(zip(points, t_float, lengths, strict=True)):
            for index, (start, mids, offsets) in enumerate(blocks):
                if start >= length or float(xi_float[start]) * t_f < 0.5:
                    continue
                # only the panels the row reaches (every entry of the outer products is formed on its own)
                panels = min(len(mids), -(-(length - start) // len(offsets)))
                mids = mids[:panels]
                if (index, panels) not in xi_blocks:
                    xi_blocks[index, panels] = flint.arb_mat(panels, len(offsets),
                                                             list(xi[start:start + panels * len(offsets)]))
                flint.ctx.prec = 2 * prec + 80  # exact products c_p t, d_j t
                mid_products, offset_products = [c * t for c in mids], [d * t for d in offsets]
                flint.ctx.prec = prec + 8
                up_mid, up_offset = [v.exp() for v in mid_products], [v.exp() for v in offset_products]
                down_mid, down_offset = [1 / v for v in up_mid], [1 / v for v in up_offset]
                growth = flint.arb_mat(panels, 1, up_mid) * flint.arb_mat(1, len(offsets), up_offset)
                decay = flint.arb_mat(panels, 1, down_mid) * flint.arb_mat(1, len(offsets), down_offset)
                half_difference, linear = (growth - decay) / 2, xi_blocks[index, panels] * t
                flint.ctx.prec = prec
                block = (half_difference - linear).entries()  # rounded once, to the working precision
                stop = min(length - start, len(block))
                values[i * n_xi + start:i * n_xi + start + stop] = block[:stop]
                pending[i, start:start + stop] = False
        rows, columns = np.nonzero(pending)
        sizes = np.array(t_float)[rows] * xi_float[columns]
        xi_objects, point_objects = np.empty(n_xi, dtype=object), np.empty(n_points, dtype=object)
        xi_objects[:], point_objects[:] = list(xi), points  # the arb themselves: numpy applies their operators
        # the products >= 1/2 at the working precision, the others by their cancelled bits (whole matrix at once)
        for extra, members in _cancelled_bits_groups(sizes):
            if extra < 0:
                continue  # A(0) = 0 exactly (values holds exact zeros)
            flint.ctx.prec = 2 * prec + 80  # exact products of two midpoints (nodes have up to prec + 64 bits)
            products = xi_objects[columns[members]] * point_objects[rows[members]]
            flint.ctx.prec = prec + extra
            excess = _SINH(products) - products
            flint.ctx.prec = prec
            if extra > 0:  # rounded to the working precision (the others are at it)
                excess = +excess
            values[rows[members] * n_xi + columns[members]] = excess
    finally:
        flint.ctx.prec = prec
    return values.tolist()


#: Arb's sinh elementwise over numpy arrays of arb (``sinh_excess_values``).
_SINH = np.frompyfunc(flint.arb.sinh, 1, 1)


def _cancelled_bits_groups(sizes):
    """[(extra bits, indices)] of the products x t (floats ``sizes``): 0 where x t >= 1/2, -1 where it is 0, else
    the bits sinh(x) - x cancels, 6/x^2 < (2.5/x)^2, rounded up to a multiple of 32:
    32 ceil((2 log2(2.5/x) + 8)/32) (``_cancelled_bits``).  Vectorised; where numpy's log2 could round the
    argument of the ceiling across an integer, the entry is recomputed by the scalar formula."""
    extra = np.zeros(sizes.size, dtype=np.int64)
    small = (sizes < 0.5) & (sizes != 0.0)
    extra[sizes == 0.0] = -1
    with np.errstate(over="ignore"):
        ratio = 2.5 / sizes[small]
    overflow = ~np.isfinite(ratio)  # x below 2.5 / DBL_MAX (subnormal): log2(2.5) - log2(x)
    ratio[overflow] = 1.0
    logarithm = np.log2(ratio)
    logarithm[overflow] = math.log2(2.5) - np.log2(sizes[small][overflow])
    steps = (2.0 * logarithm + 8.0) / 32.0
    extra[small] = 32 * np.ceil(steps).astype(np.int64)
    near = np.abs(steps - np.rint(steps)) < 1e-9
    for index in np.flatnonzero(small)[near]:
        extra[index] = _cancelled_bits(float(sizes[index]))
    return [(int(e), np.flatnonzero(extra == e).tolist()) for e in np.unique(extra)]


def _cancelled_bits(size: float) -> int:
    """32 ceil((2 log2(2.5/x) + 8)/32) for 0 < x < 1/2 (log2(2.5) - log2(x) where 2.5/x overflows)."""
    ratio = 2.5 / size
    logarithm = math.log2(ratio) if math.isfinite(ratio) else math.log2(2.5) - math.log2(size)
    return 32 * math.ceil((2.0 * logarithm + 8) / 32)


def _sinh_excess_series_values(points, xi, lengths) -> list:
    xi_float = [float(x) for x in xi]
    entries = []
    zero = flint.arb(0)
    for t, length in zip(points, lengths, strict=True):
        t_float = float(t)
        for x, x_float in zip(xi[:length], xi_float[:length], strict=True):
            product = x * t
            if x_float * t_float >= 0.5:
                entries.append(product.sinh() - product)
            else:
                entries.append(sinh_excess(product))
        entries.extend([zero] * (len(xi) - length))
    return entries
