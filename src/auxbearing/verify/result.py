"""A verification's result as a Python object: the verdict, its criteria as a table, the report and files.

:func:`auxbearing.verify.run.verify` returns a :class:`Verification`, a dict (what ``verify.json`` holds,
plus the design's cases) with the views an engineer at a prompt or in a notebook wants: the criteria as a
pandas DataFrame, ``to_html(path)`` for the report, ``save(folder)`` for everything the command line writes,
and a rich display in Jupyter.
"""

from __future__ import annotations

from pathlib import Path

#: The keys of ``verify.json`` (the rest are objects for the report: runs, datasets, rows).
PUBLIC_KEYS_LEFT_OUT = ("design", "candidate_rows", "recommendation_rows", "figures")


class Verification(dict):
    """The result of a verification (a dict, as before), with views.

    In use (a full verification takes minutes, so this is not run as a doctest; the README's example is)::

        from auxbearing.verify import verify
        result = verify("blower", "out/blower")
        result.verdict, result.criteria[["name", "margin", "pass"]]
        result.to_html("out/blower/report.html")
    """

    @property
    def verdict(self) -> str:
        """``pass``, ``fail`` or ``incomplete``."""
        return self["verdict"]

    @property
    def criteria(self):
        """The design's criteria as a pandas DataFrame: name, required, found, margin, pass, unit, origin, evidence."""
        import pandas as pd

        return pd.DataFrame(self["criteria"])

    def to_html(self, path: str | Path) -> Path:
        """Write the verification report (verdicts first, figures, inputs) to ``path``; returns it."""
        from auxbearing.report.verify_figures import build_figures
        from auxbearing.report.verify_html import render

        path = Path(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(render(self, build_figures(self)), encoding="utf-8")
        return path

    def save(self, folder: str | Path) -> Path:
        """Write report.html, verify.json and the design's drop and coast-down datasets into ``folder``."""
        from auxbearing.common.io import save_dataset, write_json

        folder = Path(folder)
        folder.mkdir(parents=True, exist_ok=True)
        cases = self["design"]["cases"]
        for i, run in enumerate(cases.drops.values()):
            save_dataset(run.dataset, folder / f"drop_{i}.nc", {"machine": cases.machine.describe()})
        if cases.coastdown is not None:
            save_dataset(cases.coastdown.history, folder / "coastdown.nc", {"machine": cases.machine.describe()})
        self.to_html(folder / "report.html")
        write_json(self.public(), folder / "verify.json", self.typed_inputs())
        return folder

    def typed_inputs(self) -> dict:
        """The inputs with the criteria as a user types them, with units (SI in this object, for the figures)."""
        from auxbearing.machine.judging import CRITERIA_TABLE, typed_values

        inputs = self["inputs"]
        if "criteria" not in inputs:
            return inputs
        return {**inputs, "criteria": typed_values(inputs["criteria"], CRITERIA_TABLE)}

    def public(self) -> dict:
        """What ``verify.json`` holds: criteria and settings with their units (a bare 393.15 reads as no unit)."""
        from auxbearing.machine.judging import VERIFY_TABLE, typed_values

        out = {k: v for k, v in self.items() if k not in PUBLIC_KEYS_LEFT_OUT}
        if "inputs" in out:
            out["inputs"] = self.typed_inputs()
        if isinstance(out.get("settings"), dict):
            out["settings"] = typed_values(out["settings"], VERIFY_TABLE)
        return out

    def __repr__(self) -> str:
        n = len(self["criteria"])
        return (f"<Verification of {self['machine']}: {self['verdict'].upper()}, {n} criteria; "
                f"{self['reason']}>")

    def _repr_html_(self) -> str:
        from auxbearing.report.html import _e, _table
        from auxbearing.report.verify_html import verdict_rows

        rows, _ = verdict_rows(self["design"]["criteria"])
        return (f"<p><b>Verification of {_e(self['machine'])}: {self['verdict'].upper()}</b>: {_e(self['reason'])}"
                f"</p>{_table(['criterion', 'required', 'found', 'margin', 'pass/fail'], rows)}")
