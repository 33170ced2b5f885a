"""Verification of a machine's touchdown bearings: cases, criteria, candidates, a recommendation.

``from auxbearing.verify import verify``: the command line's ``auxbearing verify`` as a function
(:func:`auxbearing.verify.run.verify`), returning a :class:`~auxbearing.verify.result.Verification`: the
verdict, the criteria with their margins (``.criteria``, a DataFrame), the candidates and the recommendation
as a dict, with ``.to_html(path)``, ``.save(folder)`` (what the command line writes) and a Jupyter display.
"""

__all__ = ["verify"]


def __getattr__(name: str):
    # the verification pulls in Dask and the kernels: imported when asked for, not with the package
    if name == "verify":
        from auxbearing.verify.run import verify

        return verify
    raise AttributeError(f"module 'auxbearing.verify' has no attribute {name!r}")
