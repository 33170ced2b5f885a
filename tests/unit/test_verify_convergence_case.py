"""Which drop the convergence evidence runs again: the one the governing criterion's evidence names."""

from types import SimpleNamespace

from auxbearing.verify.convergence import convergence_started
from auxbearing.verify.criteria import upper_bound


class _Recorder:
    """An executor that records what it is asked to run and runs nothing."""

    def __init__(self):
        self.runs = []

    def submit(self, fn, *args):
        self.runs.append(args)
        return SimpleNamespace(result=lambda: None)


def _cases():
    machines = {case: SimpleNamespace(name=case, simulation=SimpleNamespace(rtol=1e-6, atol=1e-9))
                for case in ("drop at the maximum speed", "scenario: surge")}
    drops = {case: SimpleNamespace(summary={"largest_excursion_m": 1e-4, "planes": []}) for case in machines}
    return SimpleNamespace(drops=drops, machines=machines, coastdown=None)


def _seal(evidence: str):
    return upper_bound("journal excursion against the seal clearance", 0.4, 0.35, "mm", "user input", evidence)


def test_the_drop_the_seal_evidence_names_is_run_again(monkeypatch):
    import auxbearing.verify.convergence as convergence

    monkeypatch.setattr(convergence, "_tightened", lambda machine, coastdown: machine)
    executor = _Recorder()
    convergence_started(_cases(), [_seal("largest journal excursion from its bearing centre in the drops: "
                                         "scenario: surge")], executor)
    (args,) = executor.runs
    assert args[0].name == "scenario: surge"  # not the first drop, whose excursion was smaller


def test_a_seal_a_campaign_drop_governs_has_no_case_to_run_again():
    executor = _Recorder()
    finish = convergence_started(_cases(), [_seal("largest journal excursion from its bearing centre in the "
                                                  "campaign's 120 drops that ended ok")], executor)
    assert executor.runs == [] and finish() is None
