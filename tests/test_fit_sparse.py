"""The loop fit's path for long records: sparse Jacobians with LSMR steps, and the covariance from the Gram matrix.

Both are checked against the dense path they stand in for (exact trust-region steps by the SVD, the covariance by
the SVD), on the same record, with the threshold ``profile.SPARSE_ENTRIES`` moved so that a record small enough for
the suite takes either path.

Tolerances.  The least-squares fits stop when S changes by less than ``profile.TOLERANCE`` (1e-6) of itself, i.e.
by up to 1e-6 N in residual variances for N samples; a parameter may then sit up to sqrt(1e-6 N) standard errors
from the exact minimum (the likelihood-ratio statistic is quadratic in it), 0.025 standard errors at N = 600: the
two paths' estimates and interval ends must agree to that.  The Gram route of the covariance loses accuracy like
m cond(J D)^2 eps (m rows summed into J^T J; D: unit column norms), the SVD route like cond(J) eps: the bound is ten
times their sum, with the condition numbers computed.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from torsional_contact import fit_loop
from torsional_contact.fitting import profile
from torsional_contact.fitting.synthetic import Rig, noisy, twist_controlled

EPS = np.finfo(float).eps
RIG = Rig(radius=0.005, normal_force=1000.0, friction=0.6, shear_modulus=80e9, compliance=4e-4, offset=1e-4)


def _record(seed: int, cycles: int = 10, samples_per_cycle: int = 200):
    torque, twist = twist_controlled(RIG, 2.5e-3, cycles=cycles, samples_per_cycle=samples_per_cycle)
    return noisy(torque, twist, 0.005 * np.ptp(torque), 1e-5, np.random.default_rng(seed))


@pytest.mark.parametrize("seed", [3, 17])
def test_sparse_steps_reach_the_dense_minimum(monkeypatch, seed):
    torque, twist = _record(seed, cycles=5, samples_per_cycle=120)
    dense = fit_loop(torque, twist, radius=RIG.radius, normal_force=RIG.normal_force)
    calls = []
    original = profile.optimize.least_squares

    def spy(*args, **kwargs):
        calls.append(kwargs.get("tr_solver"))
        return original(*args, **kwargs)

    monkeypatch.setattr(profile, "SPARSE_ENTRIES", 1)  # every Jacobian counts as large
    monkeypatch.setattr(profile.optimize, "least_squares", spy)
    sparse = fit_loop(torque, twist, radius=RIG.radius, normal_force=RIG.normal_force)
    # the sparse path was taken by every fit of the model (the straight line's own small fit passes no solver)
    assert "lsmr" in calls and "exact" not in calls
    bound = math.sqrt(profile.TOLERANCE * torque.size)  # standard errors (module docstring)
    for name in ("friction", "compliance", "shear_modulus"):
        a, b = getattr(dense, name), getattr(sparse, name)
        assert (a.value is None) == (b.value is None), name
        if a.value is None:
            continue
        assert abs(a.value - b.value) <= bound * a.stderr, name
        assert abs(a.stderr - b.stderr) <= bound * a.stderr, name
        for end_a, end_b in zip(a.interval, b.interval, strict=True):
            assert (end_a is None) == (end_b is None), name
            if end_a is not None:
                assert abs(end_a - end_b) <= bound * a.stderr, name
    assert dense.warnings == sparse.warnings or len(dense.warnings) == len(sparse.warnings)


def test_covariance_by_the_gram_matrix_is_the_svd_one(monkeypatch):
    rng = np.random.default_rng(5)
    rows, columns = 3000, 40
    # a loop-like Jacobian: four global columns of different scales, the rest each acting on its own block of rows
    jacobian = np.zeros((rows, columns))
    # (scales within the SVD's own threshold, which is relative to the largest singular value of the unscaled J)
    jacobian[:, :4] = rng.standard_normal((rows, 4)) * np.array([10.0, 1.0, 0.1, 5.0])
    block = rows // (columns - 4)
    for j in range(4, columns):
        jacobian[(j - 4) * block:(j - 3) * block, j] = rng.standard_normal(block) * 100.0
    jacobian[:, 7] = 0.0  # a parameter without influence: no variance, by either route
    expected = profile.covariance(jacobian, 2.0)
    monkeypatch.setattr(profile, "SPARSE_ENTRIES", 1)
    got = profile.covariance(jacobian, 2.0)
    def condition(matrix):
        singular = np.linalg.svd(matrix, compute_uv=False)
        return singular[0] / singular[singular > singular[0] * 1e-10][-1]

    acting = jacobian[:, np.linalg.norm(jacobian, axis=0) > 0]
    scaled = acting / np.linalg.norm(acting, axis=0)
    bound = 10 * (rows * condition(scaled) ** 2 + condition(acting)) * EPS  # module docstring
    assert bound < 1e-6  # the check means something
    assert np.all(got[7] == 0.0) and np.all(got[:, 7] == 0.0)
    keep = np.delete(np.arange(columns), 7)
    got, expected = got[np.ix_(keep, keep)], expected[np.ix_(keep, keep)]
    diagonal = np.sqrt(np.outer(np.diag(expected), np.diag(expected)))  # errors relative to the standard errors
    assert np.max(np.abs(got - expected) / diagonal) <= bound


def _model_at_fit(seed: int = 7):
    """A loop model of a ten-cycle record and its fitted parameters (for Jacobians at a realistic point)."""
    torque, twist = _record(seed)
    from torsional_contact.fitting.loop_model import LoopModel
    from torsional_contact.fitting.samples import turning_points

    reversals = turning_points(twist, 3e-5)  # three twist-noise levels
    model = LoopModel(torque, twist, reversals, 0.005 * np.ptp(torque), 1e-5)
    shaft = RIG.compliance
    slip_torque = RIG.friction * RIG.normal_force * RIG.radius / 2.0
    p = np.concatenate([[slip_torque, 0.3, shaft, RIG.offset], twist[reversals]])
    return model, p


def test_sparse_jacobian_is_the_dense_one():
    """Built without its dense form (per sample: its piece's origin gradient plus the local columns), the Jacobian
    holds the same numbers: the rows are scaled by a product with 1/scale instead of a division (1 ulp each)."""
    model, p = _model_at_fit()
    dense = np.asarray(model.distances(p, jacobian=True)[1])
    sparse_jacobian = model.distances(p, jacobian=True, sparse=True)[1]
    assert sparse_jacobian.nnz < 0.2 * dense.size  # it is sparse
    row_scale = np.max(np.abs(dense), axis=1, keepdims=True)
    assert np.all(np.abs(sparse_jacobian.toarray() - dense) <= 4 * EPS * np.where(row_scale > 0, row_scale, 1.0))


def test_complement_projection_sparse_is_the_dense_one():
    """The defects' score tests project a defect's column off the fit's Jacobian: by the SVD basis (dense) or by
    the scaled Gram matrix (sparse); the two agree to the Gram route's accuracy (m cond^2 eps, module docstring)."""
    from scipy import sparse

    from torsional_contact.fitting.defects import _Complement

    model, p = _model_at_fit()
    dense = np.asarray(model.distances(p, jacobian=True)[1])
    z = np.random.default_rng(1).standard_normal((dense.shape[0], 2))
    by_svd, by_gram = _Complement(dense), _Complement(sparse.csr_matrix(dense))
    acting = dense[:, np.linalg.norm(dense, axis=0) > 0]
    singular = np.linalg.svd(acting / np.linalg.norm(acting, axis=0), compute_uv=False)
    bound = 10 * dense.shape[0] * (singular[0] / singular[-1]) ** 2 * EPS * np.linalg.norm(z, axis=0)
    assert np.all(np.linalg.norm(by_svd(z) - by_gram(z), axis=0) <= bound)
    by_svd.add(by_svd(z[:, 0]))
    by_gram.add(by_gram(z[:, 0]))
    assert np.linalg.norm(by_svd(z[:, 1]) - by_gram(z[:, 1])) <= bound[1] * 10
