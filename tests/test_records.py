"""Result records: every key declares its quantity, and the SI form converts exactly the declared ones."""

from __future__ import annotations

import dataclasses
import math

import pytest

from torsional_contact import records, solve
from torsional_contact.histories import analyse_signal, history
from torsional_contact.records import ABSENT, QUANTITIES, Record, measured, record
from torsional_contact.specimen import Specimen, physical_record

SPECIMEN = Specimen(radius="5 mm", normal_force="1 kN", friction=0.6, shear_modulus="80 GPa", gauge_length="20 mm")


def _record_classes():
    return [getattr(records, name) for name in records.__all__
            if isinstance(getattr(records, name), type) and issubclass(getattr(records, name), Record)
            and getattr(records, name) is not Record]


def test_a_field_without_a_quantity_is_refused():
    class Loose(Record):
        torque: float = measured("torque")
        stray: float = 0.0

    with pytest.raises(TypeError, match="Loose.stray does not declare its quantity"):
        record(Loose)
    with pytest.raises(ValueError, match="quantity must be one of"):
        measured("furlongs")


@pytest.mark.parametrize("cls", _record_classes(), ids=lambda c: c.__name__)
def test_every_package_record_declares_every_field(cls):
    for f in dataclasses.fields(cls):
        assert f.metadata["quantity"] in {*QUANTITIES, "plain", "nested", "extra"}, (cls.__name__, f.name)


def _manufactured(cls):
    """An instance whose numbers are distinct powers of two (exact under scaling checks)."""
    values = {}
    for i, f in enumerate(dataclasses.fields(cls)):
        quantity = f.metadata["quantity"]
        if quantity in QUANTITIES:
            values[f.name] = [2.0 ** i, 2.0 ** (i + 1)] if f.type in ("list", list) else 2.0 ** i
        elif quantity == "extra":
            values[f.name] = {"rcond": 0.5}
        elif quantity == "nested":
            values[f.name] = ABSENT
        else:
            values[f.name] = f"plain-{i}"
    return cls(**values)


@pytest.mark.parametrize("cls", _record_classes(), ids=lambda c: c.__name__)
def test_si_form_scales_exactly_the_measured_fields(cls):
    instance = _manufactured(cls)
    scales = {q: 3.0 + k for k, q in enumerate(QUANTITIES)}
    units: dict = {}
    si = instance.si_dict(scales, units)
    plain_dict = instance.as_dict()
    for f in dataclasses.fields(cls):
        quantity, value = f.metadata["quantity"], getattr(instance, f.name)
        if value is ABSENT:
            assert f.name not in si and f.name not in units
        elif quantity in QUANTITIES:
            expected = [v * scales[quantity] for v in value] if isinstance(value, list) else value * scales[quantity]
            assert si[f.name] == expected and units[f.name] == QUANTITIES[quantity]
        elif quantity == "extra":
            assert si["rcond"] == plain_dict["rcond"] == 0.5
        else:
            assert si[f.name] == plain_dict[f.name] and f.name not in units
    for alias, key in cls.si_aliases.items():
        assert si[alias] == si[key] and units[alias] == units[key]


def test_non_finite_numbers_become_null():
    state = history([0.0, 4.0 / 3.0])[-1]  # spinning: unbounded rotation and energy
    as_dict = state.as_dict()
    assert as_dict["rigid_rotation"] is None and as_dict["dissipated_energy"] is None
    si = physical_record(state.record(), SPECIMEN)
    assert si["rigid_rotation"] is None and si["twist"] is None and si["torque"] == pytest.approx(
        4.0 / 3.0 * SPECIMEN.torque_scale, rel=1e-15)


def test_si_conversion_of_real_results_against_the_scales():
    """Each SI value equals its normalised value times the scale of the quantity the record declares."""
    solution = solve(torque=1.23)
    si = physical_record(solution.record(), SPECIMEN)
    assert si["stick_radius"] == solution.stick_radius * SPECIMEN.radius
    assert si["rigid_rotation"] == solution.rigid_rotation * SPECIMEN.rotation_scale
    expected_twist = SPECIMEN.rotation_scale * (1.23 * 0.02 / 0.005 + 2 * solution.rigid_rotation)
    assert math.isclose(si["twist"], expected_twist, rel_tol=4e-16 * 8)  # a few roundings of the same sum
    result = analyse_signal([0.0, 1.2, -1.2, 1.2, -1.2, 0.3])
    summary = records.SignalSummary(samples=6, turning_points=6, dropped_turning_points=0, gate=0.0,
                                    dissipated_energy=result.total_dissipated_energy, closed_loops=result.closed_loops,
                                    half_loops=result.half_loops, loop_energy=result.loop_energy, method="fast",
                                    n_terms=None, model="cylinder", states_file=None, output_file=None,
                                    bin_width=None, cycles=result.cycle_records(), states=result.state_records())
    si = physical_record(summary, SPECIMEN)
    assert si["turning_points"] == 6  # a count, not a torque: nothing converts it
    for cycle, normalized in zip(si["cycles"], summary.cycles, strict=True):
        assert cycle["energy"] == cycle["dissipated_energy"] == normalized.dissipated_energy * SPECIMEN.energy_scale
        assert cycle["range"] == normalized.range * SPECIMEN.torque_scale
    for state, normalized in zip(si["states"], summary.states, strict=True):
        assert state["turning_points"] == [t * SPECIMEN.torque_scale for t in normalized.turning_points]
        assert state["slip_fronts"] == [b * SPECIMEN.radius for b in normalized.slip_fronts]
    assert si["units"]["turning_points"] == "N m" and si["units"]["energy"] == "J"
