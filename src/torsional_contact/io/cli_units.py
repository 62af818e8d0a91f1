"""The command line in physical units: the specimen options, SI results, lab files and ``fit``.

``solve`` and ``history`` take the specimen options ``--radius --normal-force --friction
--shear-modulus`` (all four, or none) and optionally ``--gauge-length``; values are numbers in SI
units or quantities ("5 mm", "1 kN", "80 GPa").  With them, torques (``--torque``,
``--turning-points``, the ``torque`` column of a ``--signal`` file) are in N m and the result is
in SI units (``specimen.physical_record``: the keys converted, a ``units`` object, the
normalised result under ``normalized``); ``--stick-radius`` is then a length.  Without them
nothing changes: every number is normalised.

``history --signal FILE`` with the specimen options reads a lab CSV (``io.lab_files``:
``time [s],torque [N m]``, time optional) and runs the same analysis as without them
(``io.history_command.analyse_file`` on the T* samples), then converts the result: every closed
cycle gains its ``energy`` (J), ``dissipated_energy`` is in J.

``fit --loop FILE --radius R --normal-force F`` reads ``torque [N m],twist [rad]`` and prints
``fitting.fit_loop``'s result (profile-likelihood intervals; ``--bootstrap N [--seed S]`` adds
bias-corrected percentile intervals from N parametric-bootstrap refits).
"""

from __future__ import annotations

import argparse
import math
import os

import numpy as np

from .. import models

__all__ = ["SPECIMEN_OPTIONS", "add_specimen_options", "add_fit_parser", "specimen_from", "number_or_quantity",
           "plain_number", "solve_si", "history_si", "fit_command", "profiles"]

#: The specimen options that go together (dest, flag).
SPECIMEN_OPTIONS = (("radius", "--radius"), ("normal_force", "--normal-force"), ("friction", "--friction"),
                    ("shear_modulus", "--shear-modulus"))


def number_or_quantity(text: str):
    """argparse ``type``: a finite number (float) or a quantity with a unit (kept as text, read later)."""
    try:
        value = float(text)
    except ValueError:
        if any(c.isalpha() for c in text):  # a unit: read (and checked) with the specimen
            return text.strip()
        raise argparse.ArgumentTypeError(f"expected a number or a quantity such as '1.8 N m', got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return value


def plain_number(option: str, value):
    """A normalised value: a float, or ValueError when it carries a unit (the specimen options are missing)."""
    if isinstance(value, str):
        raise ValueError(f"{option} {value!r} is not a plain number: values with units need the specimen options "
                         "--radius, --normal-force, --friction and --shear-modulus")
    return value


def add_specimen_options(parser) -> None:
    """--radius --normal-force --friction --shear-modulus [--gauge-length] (all four or none)."""
    group = parser.add_argument_group("specimen (physical units: all four, or none for normalised units)")
    group.add_argument("--radius", help="cylinder radius a, e.g. '5 mm' (a number: m)")
    group.add_argument("--normal-force", help="normal force F, e.g. '1 kN' (a number: N)")
    group.add_argument("--friction", help="Coulomb friction coefficient f, e.g. 0.6")
    group.add_argument("--shear-modulus", help="shear modulus G of both cylinders, e.g. '80 GPa' (a number: Pa)")
    group.add_argument("--gauge-length", help="distance L between the two cross-sections of the twist, e.g. "
                       "'20 mm' (a number: m); adds 'twist' (rad)")


def specimen_from(args):
    """The ``Specimen`` of the options, None without any; ValueError for a partial set or a bad value."""
    from ..specimen import Specimen

    given = [(dest, flag) for dest, flag in SPECIMEN_OPTIONS if getattr(args, dest, None) is not None]
    if not given:
        if getattr(args, "gauge_length", None) is not None:
            raise ValueError("--gauge-length needs the specimen options --radius, --normal-force, --friction and "
                             "--shear-modulus")
        return None
    missing = [flag for dest, flag in SPECIMEN_OPTIONS if getattr(args, dest, None) is None]
    if missing:
        raise ValueError(f"{missing[0]} is missing: the specimen options --radius, --normal-force, --friction and "
                         "--shear-modulus go together")
    values = {dest: getattr(args, dest) for dest, _ in SPECIMEN_OPTIONS}
    try:
        return Specimen(**values, gauge_length=args.gauge_length, model=getattr(args, "model", None))
    except ValueError as exc:  # name the option, not the keyword
        raise ValueError(option_named(str(exc), dict((*SPECIMEN_OPTIONS, ("gauge_length", "--gauge-length"))))) \
            from None


def option_named(text: str, names: dict) -> str:
    """A message of the API (starting with a keyword, "radius must ..." or "radius: ...") with the keyword replaced
    by its command-line option."""
    for key, flag in names.items():
        if text.startswith((key + " ", key + ":")):
            return flag + text[len(key):]
    return text


def solve_si(args, specimen) -> dict:
    """``solve`` with the specimen options: the state in SI units (``--radii`` in m)."""
    if args.stick_radius is not None:
        state = specimen.solve(stick_radius=args.stick_radius, method=args.method, n_terms=args.n_terms,
                               model=args.model)
    else:
        state = specimen.solve(torque=_torque_text("--torque", args.torque), method=args.method, n_terms=args.n_terms,
                               model=args.model)
    from ..specimen import physical_record

    radii = None
    if args.radii is not None:
        radii = np.array([_length("--radii", r) for r in args.radii]) / specimen.radius
        if np.any(radii < 0) or np.any(radii > 1):
            raise ValueError(f"--radii must lie in [0, {specimen.radius:g}] m (0 to the radius)")
    return physical_record([state.normalized.record(), profiles(state.normalized, radii)], specimen, state.contact)


def profiles(state, radii, residual: bool = False):
    """The interface profiles of ``state`` at ``radii`` (``records.ProfileRecord``; the residual traction with
    ``residual``), or None without radii."""
    from ..records import ABSENT, ProfileRecord

    if radii is None:
        return None
    radii = np.asarray(radii, dtype=float)
    values = {name: [float(v) for v in getattr(state, name)(radii)] for name in ("traction", "slip")}
    residual_traction = [float(v) for v in state.residual_traction(radii)] if residual else ABSENT
    return ProfileRecord(radii.tolist(), values["traction"], values["slip"], residual_traction)


def _torque_text(option: str, value):
    from .. import units

    return units.si_value(option, value, "torque")


def _length(option: str, value) -> float:
    from .. import units

    return units.si_value(option, value, "length")


def history_si(args, specimen):
    """``history`` with the specimen options: turning points in N m, or a lab CSV for ``--signal``."""
    from ..specimen import physical_record

    if args.signal is None:
        if args.radii is not None:
            raise ValueError("--radii is not available with the specimen options for history (use solve)")
        torques = [_torque_text(f"--turning-points[{i}]", v) for i, v in enumerate(args.turning_points)]
        return [physical_record(state.normalized.record(), specimen, state.contact) for state in
                specimen.history(torques, method=args.method, n_terms=args.n_terms, model=args.model)]
    for option, value in (("--output", args.output), ("--states", args.states), ("--column", args.column)):
        if value is not None:
            raise ValueError(f"{option} is not available with the specimen options (the tables are normalised; "
                             "the lab file names its columns by their units); leave out the specimen options for it")
    from .history_command import analyse_values
    from .lab_files import read_lab_columns

    label = f"--signal {args.signal}"
    columns = read_lab_columns(args.signal, ["torque"], ["time"], label=label, encoding=args.encoding,
                               columns=named_columns(args, ("torque", "time")))
    contact = specimen.contact if args.model is None else models.get(args.model)
    gross = contact.gross_slip_torque
    torque_star = columns["torque"] / specimen.torque_scale
    bad = np.abs(torque_star) > gross * (1 + 4 * np.finfo(float).eps)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{label}: sample {i} (data row {i + 1}): torque {columns['torque'][i]:.6g} N m exceeds the "
                         f"gross-slip torque {gross * specimen.torque_scale:.6g} N m (T* = {contact.gross_slip_text}): "
                         f"{contact.bodies} spin, there is no static solution")
    gate = 0.0 if args.gate is None else _torque_text("--gate", args.gate) / specimen.torque_scale
    bin_width = None if args.bin_width is None else _torque_text("--bin-width", args.bin_width) / specimen.torque_scale
    result = analyse_values(np.clip(torque_star, -gross, gross), source=args.signal, method=args.method,
                            n_terms=args.n_terms, model=args.model, gate=gate, bin_width=bin_width,
                            progress=not args.no_progress, full=args.json)
    record = physical_record(result, specimen, contact)
    record["columns"] = {"torque": columns["units"]["torque"], **({"time": columns["units"]["time"]}
                                                                  if "time" in columns["units"] else {})}
    if "time" in columns:
        record["duration"] = float(columns["time"][-1] - columns["time"][0])
        record["units"]["duration"] = "s"
    return record


def add_fit_parser(sub, parser_class) -> None:
    """The ``fit`` subcommand: f, G and the compliance from a measured loop."""
    p = sub.add_parser("fit", help="friction coefficient and shear modulus from a measured torque-twist loop")
    p.add_argument("--loop", required=True, help="CSV with a header 'torque [N m],twist [rad]' (units as written), "
                   "samples in time order from the virgin state")
    p.add_argument("--radius", required=True, help="cylinder radius a, e.g. '5 mm' (a number: m)")
    p.add_argument("--normal-force", required=True, help="normal force F, e.g. '1 kN' (a number: N)")
    p.add_argument("--torque-noise", help="standard deviation of the torque noise, e.g. '0.01 N m' (default: "
                   "estimated, floored at the channel's resolution); state it for a commanded (exact) channel")
    p.add_argument("--twist-noise", help="standard deviation of the twist noise, e.g. '1e-5 rad' (default: estimated, "
                   "floored at the channel's resolution)")
    p.add_argument("--bootstrap", type=int, default=0, metavar="N",
                   help="add bias-corrected percentile intervals from N parametric-bootstrap refits (20 to 100000; "
                        "costs about N fits; default 0: profile-likelihood intervals only)")
    p.add_argument("--seed", type=int, default=None, help="seed of the bootstrap's random numbers")
    p.add_argument("--model", choices=models.names(), default=None,
                   help="the contact model whose loop is fitted (default: cylinder; see 'models')")
    p.add_argument("--shear-modulus", help="G, e.g. '80 GPa': fixed, so that f and the compliance are fitted "
                   "(without it the fitted G is an effective modulus of the contact, absorbing asperity compliance)")
    p.add_argument("--gauge-length", help="L between the twist's cross-sections, e.g. '20 mm' (with --shear-modulus, "
                   "for shafts): the shafts' L/(G J) is taken out and rig_compliance reported")
    p.add_argument("--per-cycle", action="store_true",
                   help="also fit every whole cycle on its own (friction per cycle: running-in, wear)")
    add_fit_input_options(p)
    add_fit_output_options(p)
    p.add_argument("--json", action="store_true", help="print one JSON object (default: a text report)")
    p.set_defaults(handler=fit_command)


def add_fit_input_options(p, roles=("torque", "twist", "time"), condition: str = "") -> None:
    """How ``fit`` (and ``history --signal`` with the specimen options: ``roles`` torque and time, ``condition``
    saying so) reads the lab export: the columns by name and the encoding (``io.lab_files``)."""
    group = p.add_argument_group("reading the export (separator, decimal mark and metadata lines are found)"
                                 + condition)
    examples = {"torque": "'Drehmoment'", "twist": "'Winkel'", "time": "'Zeit'"}
    for role in roles:
        example = examples[role]
        group.add_argument(f"--{role}-column", metavar="NAME",
                           help=f"the header name of the {role} column (e.g. {example}), when it is not "
                           f"'{role}' or a synonym of it")
    group.add_argument("--encoding", help="the file's text encoding (default: UTF-8, else Windows-1252)")


def add_fit_output_options(p) -> None:
    """What ``fit`` writes beside its report: the plot and the residual table (``io.fit_report``)."""
    group = p.add_argument_group("outputs")
    group.add_argument("--confidence", type=float, default=0.95,
                       help="level of the intervals, in (0, 1) (default 0.95); the slip test's level is 1 - it")
    group.add_argument("--plot", metavar="FILE", help="the loop with the fitted model and the normalised residuals; "
                       "with --per-cycle also each cycle's loop and f against the cycle number (.png, .pdf or .svg; "
                       "needs matplotlib, the plots extra)")
    group.add_argument("--residuals", metavar="FILE", help="every sample with the fitted torque, its residual and the "
                       "normalised residual (CSV; .npz or .npy: binary)")
    group.add_argument("--parents", action="store_true", help="create the missing directories of --plot and "
                       "--residuals")


def named_columns(args, roles=("torque", "twist", "time")) -> dict:
    """role -> header name given with --ROLE-column (``read_lab_columns``'s ``columns``)."""
    return {role: getattr(args, f"{role}_column") for role in roles if getattr(args, f"{role}_column", None)
            is not None}


def fit_outputs_checked(args) -> None:
    """--confidence, --plot and --residuals checked before the fit: a bad one costs no fit."""
    import os

    from .. import extras
    from ..output import distinct_outputs
    from .fit_report import PLOT_FORMATS

    if not (math.isfinite(args.confidence) and 0 < args.confidence < 1):
        raise ValueError(f"--confidence must lie in (0, 1) (e.g. 0.95), got {args.confidence!r}")
    if args.plot is not None:
        if os.path.splitext(args.plot)[1].lower() not in PLOT_FORMATS:
            raise ValueError(f"--plot {args.plot}: name a {', '.join(PLOT_FORMATS)} file (the format is the "
                             "extension)")
        extras.require("plots", "fit --plot")
    if args.parents and args.plot is None and args.residuals is None:
        raise ValueError("--parents needs --plot or --residuals (it creates their missing directories)")
    distinct_outputs((("--plot", args.plot), ("--residuals", args.residuals)), inputs=(("--loop", args.loop),),
                     parents=args.parents)


def fit_outputs(args, result, columns) -> dict:
    """The fit's record with the input's provenance, after writing --residuals and --plot."""
    from .. import units
    from .fit_report import FitRecord, fit_provenance, plot_fit, residual_columns, write_residuals

    record = FitRecord(result.as_dict())
    record["input"] = columns["report"]
    record["provenance"] = fit_provenance(columns["report"])
    outputs = {}
    if args.residuals is not None or args.plot is not None:
        noise = [None if value is None else units.positive_si(key, value, kind) for key, value, kind in
                 (("torque_noise", args.torque_noise, "torque"), ("twist_noise", args.twist_noise, "angle"))]
        table = residual_columns(result, columns, *noise)
        if args.residuals is not None:
            write_residuals(args.residuals, table, inputs=(("--loop", args.loop),), parents=args.parents)
            outputs["--residuals"] = args.residuals
        if args.plot is not None:
            plot_fit(args.plot, table, record, title=f"{os.path.basename(args.loop)}: f = "
                     f"{_shown_value(record['friction'].get('value'))}, regime {record['regime']}",
                     inputs=(("--loop", args.loop),), parents=args.parents)
            outputs["--plot"] = args.plot
    if outputs:
        record["outputs"] = outputs
    return record


def _shown_value(value) -> str:
    return "not identified" if value is None else f"{value:.4g}"


def fit_command(args) -> dict:
    from ..fitting import MIN_SAMPLES, fit_loop
    from .lab_files import read_lab_columns

    fit_outputs_checked(args)
    columns = read_lab_columns(args.loop, ["torque", "twist"], ["time"], label=f"--loop {args.loop}",
                               min_rows=MIN_SAMPLES, encoding=args.encoding, columns=named_columns(args))
    constant_columns_refused(f"--loop {args.loop}", columns)
    names = {"radius": "--radius", "normal_force": "--normal-force", "torque_noise": "--torque-noise",
             "twist_noise": "--twist-noise", "bootstrap": "--bootstrap", "shear_modulus": "--shear-modulus",
             "gauge_length": "--gauge-length"}
    try:
        result = fit_loop(columns["torque"], columns["twist"], radius=args.radius, normal_force=args.normal_force,
                          torque_noise=args.torque_noise, twist_noise=args.twist_noise, bootstrap=args.bootstrap,
                          seed=args.seed, time=columns.get("time"), confidence=args.confidence, model=args.model,
                          shear_modulus=args.shear_modulus, gauge_length=args.gauge_length,
                          per_cycle=args.per_cycle)
    except ValueError as exc:
        raise ValueError(option_named(str(exc), names)) from None
    return fit_outputs(args, result, columns)


def constant_columns_refused(label: str, columns: dict) -> None:
    """A torque or twist column that never changes is no loop: ValueError naming the file, the column and its value."""
    from .. import units

    for role, kind in (("torque", "torque"), ("twist", "angle")):
        values = columns[role]
        if values.size and np.ptp(values) == 0:
            header = columns["report"]["columns"][role]["header"]
            raise ValueError(f"{label}: the {role} column {units.shown_text(header, 40)} is constant "
                             f"({units.shown(float(values[0]), kind)} in every row): a loop needs a varying {role}")
