"""The verification wing: independent checks of the product (nothing in the product imports it).

``reference`` (arbitrary precision), ``collocation`` (a second direct method),
``verification.incremental`` (the oracle of the memory rules), ``convergence`` (N-studies),
``quadrature`` (arbitrary-precision Gauss-Legendre grids) and ``errata`` (the checks of the
paper's equations and statements).
"""
