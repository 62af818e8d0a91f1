"""The limit problem of the printed series (omega = 0, no regularity at r = b), checked independently.

Its torque comes from the Abel-Fredholm Nystrom system; the printed weak form closed by (C3), a
different discretisation (Dini series) of the same limit, must approach it like 1/N, and (C2) more
slowly but also towards it, not towards the regular solution.
"""

import warnings

import numpy as np
import pytest
from tolerances import assert_beyond, assert_within

from torsional_contact.diagnostics import TorsionalContactWarning
from torsional_contact.solvers.abel_fredholm import solve_abel_fredholm, stick_system
from torsional_contact.solvers.limit_problem import solve_without_rotation
from torsional_contact.solvers.weak_form import solve_series

EPS = np.finfo(float).eps


def _printed(b, n, closure):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", TorsionalContactWarning)
        return solve_series(b, "published", n, closure=closure).torque


@pytest.mark.parametrize("b", [0.3, 0.6])
def test_the_torque_closure_converges_to_the_limit_problem_like_one_over_n(b):
    """(C3) at N and 2N: the distance from the limit halves (order 1 within 0.25, the observed orders approach 1
    from below like those of the complete weak form), and the extrapolation 2 T_2N - T_N, which removes a 1/N
    term, is at least twice as close to the limit as T_2N (a wrong limit would not be approached so)."""
    limit = solve_without_rotation(b).torque
    t_n, t_2n = _printed(b, 500, "torque"), _printed(b, 1000, "torque")
    order = np.log2(abs(t_n - limit) / abs(t_2n - limit))
    assert_within(abs(order - 1.0), 0.25, "observed order of (C3) towards the limit problem: 1/N")
    assert_within(abs(2 * t_2n - t_n - limit), 0.5 * abs(t_2n - limit), "Richardson extrapolation of a 1/N error")


def test_the_front_closure_approaches_the_limit_problem_not_the_regular_solution():
    """(C2) at b = 0.3: its distance from the limit falls with N, and at N = 2000 it is closer to the limit than
    the regular solution is (the limit problem is a different problem: their torques differ)."""
    b = 0.3
    limit, regular = solve_without_rotation(b).torque, solve_abel_fredholm(b).torque
    distances = [abs(_printed(b, n, "displacement") - limit) for n in (250, 500, 1000, 2000)]
    assert all(later < earlier for earlier, later in zip(distances, distances[1:], strict=False)), distances
    assert_beyond(regular - limit, 0.02, "the regular and the limit torques differ (0.028 at b = 0.3)")
    assert_beyond(abs(_printed(b, 2000, "displacement") - regular), distances[-1],
                  "(C2) at N = 2000 nearer the limit problem than the regular solution")


@pytest.mark.parametrize("b", [0.1, 0.6, 0.9])
def test_the_limit_problem_is_resolved_by_the_default_nodes_and_singular_at_the_front(b):
    """Twice the nodes change T*_0 by rounding only (geometric convergence: the Nystrom error at the default nodes
    is below 1e-14); the traction is singular at r = b (C_b not 0); Omega = BETA T*_0 (omega = 0)."""
    coarse = solve_without_rotation(b)
    fine = solve_without_rotation(b, n_nodes=2 * len(solve_abel_fredholm(b).nodes))
    assert_within(abs(fine.torque - coarse.torque), 1e3 * EPS, "Nystrom at the default nodes: converged")
    assert_beyond(abs(coarse.edge_coefficient), 1e-3, "the limit traction is singular at the stick front")


def test_the_shared_system_gives_the_regular_solution_when_g_of_b_vanishes():
    """stick_system closed by g(b) = 0 reproduces solve_abel_fredholm's T* and Omega to rounding."""
    b = 0.6
    regular = solve_abel_fredholm(b)
    system = stick_system(b, len(regular.nodes))
    omega_big = -system.edge_constant / system.edge_rotation
    assert_within(abs(omega_big - regular.rotation_constant), 10 * EPS, "the same arithmetic")
    assert_within(abs(system.torque(omega_big) - regular.torque), 10 * EPS, "the same arithmetic")


@pytest.mark.parametrize("bad", [0.0, 1.0, -0.1, float("nan")])
def test_a_stick_radius_outside_the_open_interval_is_refused(bad):
    with pytest.raises(ValueError, match="stick_radius"):
        solve_without_rotation(bad)


def test_a_bad_node_count_is_refused():
    with pytest.raises(ValueError, match="n_nodes"):
        solve_without_rotation(0.5, n_nodes=1)
