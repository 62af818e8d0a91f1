"""Solvers of the partial-slip problem for a given stick radius.

``weak_form``: the paper's eq. (38) as printed and completed by the rigid-rotation mode;
``abel_fredholm``: the Abel-Fredholm (Nystrom) method, with the cylinder's kernels in
``solvers.kernels``; ``equilibration``: the scaled dense solve and its condition number.
"""
