"""The verification report's inputs section reads as a person types values (auxbearing.report.verify_html)."""

import re

from auxbearing.machine.files import read_machine
from auxbearing.machine.judging import read_criteria
from auxbearing.report.verify_html import readable_inputs


def test_inputs_carry_units_and_no_float_noise():
    machine = read_machine("blower")
    criteria = {k: v for k, v in read_criteria(None).items() if k != "given"}
    shown = readable_inputs({"machine": machine.describe(), "criteria": criteria})
    assert shown["criteria"]["max_temperature"] == "120 degC"
    assert shown["machine"]["coastdown"]["ambient_temperature"].endswith("degC")
    assert shown["machine"]["drop"]["duration"].endswith(" s")
    text = repr(shown)
    assert not re.search(r"\d\.\d{9,}", text), "a float printed past its precision"
