"""The response to the referee is filled from the build's macros (workflow/scripts/build_response.py).

Every number of paper/response_to_referee.md is a ``{{name}}`` placeholder of a generated macro: the filler
writes the macro values as plain text and refuses a placeholder that the build does not define; and the
template quotes no macro that none of the three LaTeX documents loads.
"""

import importlib.util
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
_spec = importlib.util.spec_from_file_location("build_response", ROOT / "workflow" / "scripts" / "build_response.py")
build_response = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(build_response)


def test_macro_values_are_written_as_plain_text():
    assert build_response.plain(r"2.4\times10^{-3}") == "2.4×10^-3"
    assert build_response.plain(r"10^{-12}") == "10^-12"
    assert build_response.plain(r"$0.053$") == "0.053"
    assert build_response.plain(r"Abel--Fredholm method") == "Abel–Fredholm method"


def test_placeholders_are_filled_from_the_macro_files(tmp_path):
    macros = tmp_path / "m.tex"
    macros.write_text("% generated\n\\expandafter\\def\\csname res@limit-c2-last\\endcsname{0.12}\n"
                      "\\expandafter\\def\\csname res@fem-error-torque\\endcsname{3\\times10^{-12}}\n")
    values = build_response.macros([macros])
    text = build_response.fill("C2 within {{limit-c2-last}}; FEM {{fem-error-torque}}.", values)
    assert text == "C2 within 0.12; FEM 3×10^-12."


def test_a_number_the_build_does_not_define_stops_the_response():
    with pytest.raises(ValueError, match="not-a-macro"):
        build_response.fill("{{not-a-macro}}", {})


def test_the_response_template_quotes_numbers_only_through_placeholders():
    """No digit-dot-digit number is typed in the response outside a placeholder, a code span, a reference to a
    numbered part of the papers (e.g. 'Table 3', 'section 4.2', 'eq. (38)') or a list of the configuration's
    inputs in brackets or braces (the loop [0.2, 1.3], the radii {0.05, 0.1})."""
    text = (ROOT / "paper" / "response_to_referee.md").read_text()
    text = re.sub(r"\{\{[\w.:-]+\}\}|`[^`]*`", "", text)
    numbered = r"(?i)(section|sections|table|tables|fig\.|figs\.|figure|eq\.|eqs\.|point|appendix|S)\s*\(?\d+(\.\d+)*"
    text = re.sub(numbered, "", text)
    text = re.sub(r"\[[\d., −-]+\]|\{[\d., ]+\}", "", text)
    assert not re.findall(r"\d\.\d", text), [text[m.start() - 30:m.end() + 10] for m in re.finditer(r"\d\.\d", text)]


def test_section_and_table_numbers_come_from_the_aux_files(tmp_path):
    aux = tmp_path / "ms.aux"
    aux.write_text("\\relax\n\\newlabel{tab:limit}{{3}{5}{The limit problem}{table.3}{}}\n"
                   "\\newlabel{sec:series}{{3}{3}{The series}{section.3}{}}\n")
    values = build_response.labels([aux])
    text = build_response.fill("Table {{ref:ms:tab:limit}}, section {{ref:ms:sec:series}} (p. {{page:ms:tab:limit}})",
                               values)
    assert text == "Table 3, section 3 (p. 5)"
    with pytest.raises(ValueError, match="ref:ms:tab:missing"):
        build_response.fill("{{ref:ms:tab:missing}}", values)
