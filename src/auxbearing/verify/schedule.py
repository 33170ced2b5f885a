"""One Dask cluster for a whole verification: the cases of every design side by side.

A verification is many independent runs: each design's drops and coast-down, its campaign, the geometry
search's drops, the recommended design's cases and the convergence run. They go to one cluster (a local
one of single-threaded worker processes, one per core, or the user's by address), started once, its
workers loading the compiled kernels once; every campaign, run side by side with the others in a thread of
this process, submits through the verification's one client.
"""

from __future__ import annotations

from contextlib import contextmanager


class DaskExecutor:
    """``submit(fn, *args)`` onto a Dask client; the futures answer ``result()``.

    ``priority``: Dask's task priority (higher first among the tasks ready to run). The verification's chain
    of steps that wait on each other (the geometry search's rounds, then the recommended geometry's runs)
    goes ahead of the campaigns' batches, which only fill the workers; queued first-come first-served the
    search's last round waited two minutes behind the candidates' campaigns.
    """

    def __init__(self, client, priority: int = 0) -> None:
        self.client = client
        self.priority = priority

    def submit(self, fn, *args, **kwargs):
        """A future of ``fn(*args, **kwargs)`` on the cluster (never taken from a cache: runs are not pure)."""
        return self.client.submit(fn, *args, pure=False, priority=self.priority, **kwargs)

    def ahead(self) -> DaskExecutor:
        """The same cluster, its tasks run before this executor's and the campaigns' (which run at 0)."""
        return DaskExecutor(self.client, self.priority + 1)


def _load_kernels() -> float:
    """Load (or compile) the machine kernels in a worker with two short drops, full and lean; seconds spent."""
    import time

    from auxbearing.analysis.drop import run_machine
    from auxbearing.machine.files import read_machine

    start = time.perf_counter()
    machine = read_machine("paper_rig").for_batch()
    run_machine(machine, duration=1e-4)
    run_machine(machine, duration=1e-4, lean=True)  # a campaign's runs build their outputs with kernels of their own
    return time.perf_counter() - start


@contextmanager
def verification_cluster(scheduler: str | None, workers: int | None):
    """(executor, scheduler address) for the verification, the local cluster closed at the end."""
    from auxbearing.campaign.run import _client, on_every_worker

    client, local = _client(scheduler, workers)
    try:
        on_every_worker(client, _load_kernels)  # once per worker, before the first case
        yield DaskExecutor(client), client.scheduler.address
    finally:
        client.close()
        if local is not None:
            local.close()
