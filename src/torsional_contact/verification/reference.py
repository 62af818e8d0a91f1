r"""High-precision reference solution of eq. (38) (``published``) and its completion.

Units: lengths in a (a = 1), tractions in f p0, displacements in f p0 a / mu,
omega in f p0 / mu, amplitudes c_n = lam_n A~_n (see ``solvers.weak_form``).

Everything here is computed with mpmath at a chosen number of significant digits
(default 50) and runs unchanged at any precision: every function takes ``digits``
or works in the caller's ``mpmath.workdps`` context, and never leaves ``mp.dps``
changed.  The functions mirror the mathematical objects of the paper one by one:

* ``bessel_j2_zeros``                lam_n, J2(lam_n) = 0 (eq. 19-20), Newton-refined
  from the double-precision zeros of ``zeros.bessel_j2_zeros``;
* ``dini_norm``                      h (eq. 35, a = 1), printed form;
* ``integral_t_j1_hyp1f2``           x^3/6 1F2(3/2; 2, 5/2; -x^2/4), the form printed in
  eq. (51) (mpmath.hyp1f2 picks its own extra precision / asymptotic expansion);
* ``integral_t_j1_struve``           the same integral as int_0^x J0 - x J0(x)
  = (pi x / 2) [J1(x) H0(x) - J0(x) H1(x)] (Struve functions), independent of 1F2;
* ``load_vector``                    B_m (eq. 51);
* ``lommel_offdiagonal``, ``lommel_diagonal``, ``lommel_matrix``
                                     the integrals of eq. (52), (53) (without the
                                     factor lam_n (lam_n - 1)), printed forms including
                                     the r = 1 terms;
* ``coupling_matrix``                C_mn (eq. 52, 53);
* ``assemble``                       the matrix of (iii)-(iv) of ``solvers.weak_form``,
                                     with exactly the layout of ``solvers.weak_form.assemble``;
* ``solve_reference``                T*, omega, c_n with the regularity condition (v).

The dense solve is the only O(N^3) step.  It uses python-flint's ``arb_mat.solve``
(ball arithmetic, so the result carries a rigorous bound for the rounding of the
solve) when python-flint is importable, otherwise mpmath's LU.  Measured on the
2-core development machine (N = 145, 50 digits, 70 working digits), per radius:
assembly about 1 s, dominated by the ~10^4 pure-Python mpf products of the Lommel
matrix (0.9 s; mpmath runs on its Python backend, no gmpy2), then 1450 Bessel
evaluations (0.3 s) and 290 1F2 evaluations (0.15 s); flint solve 0.2-0.3 s, mostly
the exact mpf -> arb conversion of the matrix; mpmath's LU instead takes about 6 s.
Six radii x two formulations: about 13 s alone, 21 s with other jobs on the cores.

``rounding_error`` and ``condition_numbers`` compare the double-precision solver
``solvers.weak_form.solve_series`` with this reference.
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field

import mpmath

from .. import validation
from ..criteria import GROSS_SLIP_TORQUE
from ..diagnostics import IllConditioningWarning, ResolutionWarning, UnphysicalResultWarning
from ..provenance import write_json
from ..solvers.weak_form import WEAK_FORMS, resolution_limit, terms_to_resolve
from . import weak_form_arb
from .arbitrary_precision import (
    FLINT,
    arb_radius,
    arb_to_mp,
    mp_to_arb,
    parse_decimal,
    require_flint,
    solve_linear,
    working_digits,
)
from .arbitrary_precision import backend as default_backend
from .weak_form_mp import assemble, bessel_j2_zeros

__all__ = [
    "DEFAULT_DIGITS",
    "GUARD_DIGITS",
    "AFFORDABLE_TERMS",
    "resolution_advice",
    "ReferenceSolution",
    "solve_reference",
    "reference_set",
    "write_reference_json",
    "load_reference_json",
]

#: Default number of significant decimal digits of the reference.
DEFAULT_DIGITS = 50
#: Extra working digits: the system loses about log10(cond) ~ 4 digits at N = 145;
#: 20 guard digits leave a wide margin, which ``solve_reference`` verifies.
GUARD_DIGITS = 20
#: The most terms the reference is advised (and the command line allowed) to use: the assembly is
#: O(N^2) multiple-precision products, the solve O(N^3), about a minute at N = 1000.
AFFORDABLE_TERMS = 1000


def resolution_advice(width) -> str:
    """What to do when a stick disc or slip annulus of ``width`` (b or 1 - b) is not resolved.

    The terms that resolve it (``terms_to_resolve``) when the reference can afford them
    (``AFFORDABLE_TERMS``); otherwise the default method, which needs no resolution rule (its
    small-stick-disc and small-slip expansions take over at the ends) -- never a count such as
    n_terms >= 3e300 that no computer could use.
    """
    needed = terms_to_resolve(float(width))
    if needed <= AFFORDABLE_TERMS:
        return f"use n_terms >= {needed}"
    return (f"no affordable n_terms resolves it (it needs more than {AFFORDABLE_TERMS}): use the default method "
            "(solve(stick_radius=...), or `reference --method fast` for the converged solution in arbitrary "
            "precision)")


# --------------------------------------------------------------------------- solution


@dataclass(frozen=True)
class ReferenceSolution:
    """High-precision solution for one stick radius (units of ``solvers.weak_form``).

    Attributes
    ----------
    method : str
    stick_radius : mpf
        b/a.
    torque : mpf
        T*(b) from the regularity condition (v).
    rigid_rotation : mpf or None
        omega (f p0 / mu); None for ``published``.
    eigenvalues, amplitudes : tuple of mpf
        lam_n and c_n = lam_n A~_n (f p0 a / mu).
    digits : int
        Significant digits requested (the working precision is digits + GUARD_DIGITS).
    solve_bound : mpf or None
        Rigorous relative bound on the rounding of the dense solve (flint backend).
    seconds : dict
        Wall-clock time of zeros, assembly and solve.
    """

    method: str
    stick_radius: object
    torque: object
    rigid_rotation: object
    eigenvalues: tuple
    amplitudes: tuple
    digits: int
    backend: str
    solve_bound: object = None
    seconds: dict = field(default_factory=dict)

    @property
    def n_terms(self) -> int:
        return len(self.eigenvalues)

    def as_dict(self, digits: int | None = None) -> dict:
        """JSON-ready dict with decimal strings of ``digits`` significant digits."""
        d = self.digits if digits is None else digits

        def s(x):
            return None if x is None else mpmath.nstr(x, d, strip_zeros=False)

        return {
            "stick_radius": s(self.stick_radius),
            "torque": s(self.torque),
            "rigid_rotation": s(self.rigid_rotation),
            "amplitudes": [s(c) for c in self.amplitudes],
            "eigenvalues": [s(x) for x in self.eigenvalues],
            "method": self.method,
            "n_terms": self.n_terms,
            "digits": d,
            "backend": self.backend,
            "solve_bound": None if self.solve_bound is None else float(self.solve_bound),
        }


def solve_reference(
    stick_radius,
    method: str = "complete",
    n_terms: int = 145,
    digits: int = DEFAULT_DIGITS,
    *,
    backend: str | None = None,
    form: str = "hyp1f2",
    progress: bool = False,
    assembly: str | None = None,
) -> ReferenceSolution:
    """High-precision analogue of ``solvers.weak_form.solve_series`` (0 < b < 1).

    Assembles (iii)-(iv) at ``digits + GUARD_DIGITS`` working digits, solves for the
    two right-hand sides (torque part, constant part) and fixes T* with the
    regularity condition (v): T* b - sum_n c_n lam_n J1(lam_n b) = 1.

    Parameters
    ----------
    stick_radius : float or str
        b/a in (0, 1), read as an exact decimal (a float as its shortest repr; ``arbitrary_precision.parse_decimal``).
    method : {"published", "complete"}
    n_terms : int
    digits : int
        Significant digits wanted in T*, omega, c_n (rounding only; the truncation at
        N terms is the formulation's and is not reduced by precision).
    backend, form
        See ``solve_linear`` and ``load_integral_constant``.
    progress : bool
        Show a tqdm progress bar over the rows of the Lommel matrix (mpmath assembly).
    assembly : {"arb", "mpmath"}, optional
        ``arb``: the system assembled and solved in Arb balls (``weak_form_arb``: the same printed
        formulas in C, the bound covering the assembly's rounding too); ``mpmath``: assembled by
        ``weak_form_mp`` and solved by ``backend``.  Default: arb when python-flint is importable,
        the backend is flint and the form is hyp1f2; otherwise mpmath.

    Warns
    -----
    ResolutionWarning
        If the stick disc or the slip annulus is narrower than 10 wavelengths of the
        highest term (the rule of ``solvers.weak_form``): precision does not help there.
    UnphysicalResultWarning
        If T* falls outside [1, 4/3].
    IllConditioningWarning
        If the rigorous bound of the flint solve leaves fewer than ``digits`` digits.
    """
    method = validation.choice("method", method, WEAK_FORMS)
    n_terms = validation.positive_int("n_terms", n_terms)
    digits = validation.positive_int("digits", digits)
    b_in = stick_radius
    work = digits + GUARD_DIGITS
    seconds = {}
    with mpmath.workdps(work):
        b = parse_decimal("stick_radius", b_in, 0, 1, closed=False)  # partial slip only
        b_min, b_max = resolution_limit(n_terms)
        narrow = min(b, 1 - b)
        if not b_min <= b <= b_max:
            warnings.warn(
                f"stick_radius={b_in!r} is not resolved by n_terms={n_terms}: the "
                f"{'stick disc' if b < 0.5 else 'slip annulus'} is narrower than 10 wavelengths of the highest "
                f"term; T* and omega are the truncated system's to {digits} digits, far from the "
                f"problem's; {resolution_advice(narrow)}",
                ResolutionWarning,
                stacklevel=2,
            )
        t0 = time.perf_counter()
        lam = bessel_j2_zeros(n_terms, work)
        seconds["zeros"] = time.perf_counter() - t0
        if _assembly(assembly, backend, form) == "arb":
            (x_torque, x_constant), bound, weight = _solve_arb(method, lam, b, work, seconds)
        else:
            t0 = time.perf_counter()
            matrix, rhs_torque, rhs_constant = assemble(method, lam, b, form=form, progress=progress)
            seconds["assembly"] = time.perf_counter() - t0
            t0 = time.perf_counter()
            (x_torque, x_constant), bound = solve_linear(matrix, [rhs_torque, rhs_constant], backend)
            seconds["solve"] = time.perf_counter() - t0
            weight = [x * mpmath.besselj(1, x * b) for x in lam]
        wk = mpmath.fsum(w * c for w, c in zip(weight, x_constant, strict=False))
        wl = mpmath.fsum(w * c for w, c in zip(weight, x_torque, strict=False))
        torque = (1 + wk) / (b - wl)
        coeffs = [k + torque * t for k, t in zip(x_constant, x_torque, strict=False)]
    if not 1 <= torque <= GROSS_SLIP_TORQUE or not mpmath.isfinite(torque):
        warnings.warn(
            f"the {method} system at n_terms={n_terms} gives T* = {mpmath.nstr(torque, 8)} at stick_radius={b_in!r}, "
            "outside [1, 4/3] (partial slip): physically impossible",
            UnphysicalResultWarning,
            stacklevel=2,
        )
    if bound is not None and bound > 0 and -mpmath.log10(bound) < digits:
        warnings.warn(
            f"the reference solve for stick_radius={b_in!r}, n_terms={n_terms} keeps only "
            f"{float(-mpmath.log10(bound)):.1f} of {digits} requested digits (rigorous bound of the solve): only "
            "those are significant (the command line prints only those)",
            IllConditioningWarning,
            stacklevel=2,
        )
    with mpmath.workdps(digits):
        return ReferenceSolution(
            method=method,
            stick_radius=+b,
            torque=+torque,
            rigid_rotation=+coeffs[n_terms] if method == "complete" else None,
            eigenvalues=tuple(+x for x in lam),
            amplitudes=tuple(+c for c in coeffs[:n_terms]),
            digits=digits,
            backend=backend or default_backend(),
            solve_bound=bound,
            seconds=seconds,
        )


def _assembly(assembly, backend, form) -> str:
    """The assembly path of ``solve_reference`` (see its ``assembly`` parameter)."""
    if assembly is None:
        return "arb" if FLINT and (backend or default_backend()) == "flint" and form == "hyp1f2" else "mpmath"
    name = validation.choice("assembly", assembly, ("arb", "mpmath"))
    if name == "arb":
        require_flint("assembly='arb'")
        if form != "hyp1f2" or (backend or default_backend()) != "flint":
            raise ValueError(f"assembly='arb' needs form='hyp1f2' and backend='flint', got {form!r}, {backend!r}")
    return name


def _solve_arb(method, lam, b, work: int, seconds: dict):
    """(columns x_torque, x_constant as mpf), the solve's relative bound, lam_n J1(lam_n b) (mpf).

    Computed at ``work`` digits in Arb, converted to mpf at the caller's mpmath precision.
    """
    with working_digits(work):
        lam_arb, b_arb = [mp_to_arb(x) for x in lam], mp_to_arb(b)
        t0 = time.perf_counter()
        matrix, rhs = weak_form_arb.assemble(method, lam_arb, b_arb)
        seconds["assembly"] = time.perf_counter() - t0
        t0 = time.perf_counter()
        solution = matrix.solve(rhs)
        seconds["solve"] = time.perf_counter() - t0
        weight_arb = weak_form_arb.traction_weights(lam_arb, b_arb)
    columns, bound = [], mpmath.mpf(0)
    for j in range(2):
        column = []
        for i in range(solution.nrows()):
            mid, rad = arb_to_mp(solution[i, j]), arb_radius(solution[i, j])
            column.append(mid)
            if mid != 0:
                bound = max(bound, rad / abs(mid))
        columns.append(column)
    return columns, bound, [arb_to_mp(w) for w in weight_arb]


def reference_set(stick_radii, methods=WEAK_FORMS, n_terms=145, digits=DEFAULT_DIGITS, progress=True, **kwargs):
    """``solve_reference`` for every (method, b); returns (list of solutions, total seconds)."""
    jobs = [(m, b) for m in methods for b in stick_radii]
    if progress:
        from tqdm import tqdm

        jobs = tqdm(jobs, desc=f"reference N={n_terms}, {digits} digits")
    t0 = time.perf_counter()
    out = [solve_reference(b, m, n_terms, digits, **kwargs) for m, b in jobs]
    return out, time.perf_counter() - t0




def write_reference_json(path, solutions) -> None:
    """Write reference solutions (full-precision decimal strings) with provenance metadata, atomically.

    No timings: the file is the same from one build to the next (the times are in ``seconds``
    of each solution, for a separate timing record).
    """
    payload = {
        "description": "High-precision reference of the torsional contact series (a = 1); "
        "T* = 2T/(f F a), omega in f p0/mu, amplitudes c_n = lam_n A~_n in f p0 a/mu.",
        "solutions": [s.as_dict() for s in solutions],
    }
    digits = sorted({s.digits for s in solutions})
    write_json(
        path,
        payload,
        method="weak forms (iii)-(iv) in arbitrary precision (mpmath; python-flint dense solve if importable)",
        resolution={"n_terms": sorted({s.n_terms for s in solutions})},
        precision={"digits": digits, "guard_digits": GUARD_DIGITS},
    )


def load_reference_json(path) -> list[ReferenceSolution]:
    """The solutions ``write_reference_json`` wrote, as ReferenceSolution objects (mpf at their digits)."""
    import json

    with open(path, encoding="utf-8") as handle:
        records = json.load(handle)["solutions"]
    out = []
    for record in records:
        digits = int(record["digits"])
        with mpmath.workdps(digits + GUARD_DIGITS):
            omega = record["rigid_rotation"]
            out.append(ReferenceSolution(
                method=record["method"],
                stick_radius=mpmath.mpf(record["stick_radius"]),
                torque=mpmath.mpf(record["torque"]),
                rigid_rotation=None if omega is None else mpmath.mpf(omega),
                eigenvalues=tuple(mpmath.mpf(x) for x in record["eigenvalues"]),
                amplitudes=tuple(mpmath.mpf(c) for c in record["amplitudes"]),
                digits=digits,
                backend=record["backend"],
                solve_bound=None if record["solve_bound"] is None else mpmath.mpf(record["solve_bound"]),
            ))
    return out
