"""Running a campaign on Dask: batches of samples as tasks, results streamed into the store as they finish.

By default a local cluster of one single-threaded worker process per core is started and stopped
here; ``scheduler`` uses a running cluster instead (its workers must import the same auxbearing and
see the same files). Each worker loads the compiled kernels once (:func:`warm_up`) before the first
batch (unless the caller's cluster has done so: a verification's). Only this process writes the store, one
batch at a time, so a batch is on disk whole or not flagged complete; running the same campaign again skips
every complete batch.
"""

from __future__ import annotations

import logging
import os
import time
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import numpy as np

from auxbearing.campaign.config import Campaign
from auxbearing.campaign.evaluate import evaluate_batch, warm_up
from auxbearing.campaign.sampling import design
from auxbearing.campaign.store import pending_batches, prepare_store, store_lock, write_batch
from auxbearing.common import interrupt
from auxbearing.common.errors import InputError

#: How long a campaign waits for a scheduler to have its first worker [s].
WORKER_WAIT = 60.0
#: Batches of a campaign with a stopping rule out on the cluster at a time, per worker: enough to keep every
#: worker busy while this process stores and judges the last one, few enough that a campaign which stops
#: leaves little computed past its stop (all at once, the blower's recommended geometry ran 128 drops of
#: which 88 were used). They are counted from the first batch not yet in: a batch that waits (behind another
#: case's long task) holds the rest back instead of letting the batches after it run on past the stop.
IN_FLIGHT = 2
#: Tasks a local worker holds at a time (Dask's ``distributed.scheduler.worker-saturation`` times its one
#: thread): the one it runs. At Dask's default of 1.1 a single-threaded worker also takes the next task in
#: while it runs one, and in a verification a campaign batch handed to a worker busy with a 15-20 s
#: coast-down waited there while the other worker ran the batches after it: the blower's 7208 DB campaign,
#: settled after 64 drops, ran 72 to 120 in five verifications. At 1.0 the tasks wait on the scheduler, in
#: priority order, for the first worker free (64 in six verifications since).
WORKER_SATURATION = 1.0


class CampaignInterrupted(KeyboardInterrupt):
    """Ctrl-C (or SIGTERM) during a campaign: what was stored stays; ``done`` samples are in the store."""

    def __init__(self, done: int, runs: int) -> None:
        super().__init__(f"{done} of {runs} samples stored")
        self.done = done
        self.runs = runs


class Progress(NamedTuple):
    """What a progress callback receives after each batch."""

    done: int  #: samples in the store
    runs: int  #: samples of the design
    new: int  #: samples run by this call
    rate: float  #: samples per second in this call
    remaining_s: float | None  #: estimate of the time left


def cores() -> int:
    """Cores this process may use."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def _client(scheduler: str | None, workers: int | None):
    """A Dask client and the local cluster it owns (None with a scheduler address)."""
    from distributed import Client, LocalCluster

    if scheduler is not None:
        try:
            return Client(scheduler, timeout="10s"), None
        except (OSError, TimeoutError, ValueError) as err:
            raise InputError.for_field("--scheduler", scheduler, f"no Dask scheduler answers there ({err})") from None
    n = workers or cores()
    # no dashboard; the scheduler's small HTTP server on a free local port, so that two campaigns (or a
    # running Dask) never fight over port 8787
    import dask

    with dask.config.set({"distributed.scheduler.worker-saturation": WORKER_SATURATION}):  # read at the start
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                               scheduler_kwargs={"dashboard": False, "dashboard_address": "127.0.0.1:0"},
                               silence_logs=logging.CRITICAL)
    return Client(cluster), cluster


def on_every_worker(client, fn, *args) -> dict:
    """``fn(*args)`` once on each worker, as tasks pinned to it; {worker address: result}.

    Not ``Client.run``: that is a message with the connection's time limit, and a worker compiling the kernels
    after a fresh install on a busy machine outlasts it (seen: a legal campaign refused with a timeout). The
    restriction is loose: a task whose worker died (and came back under a new address) runs on another.
    """
    workers = list(client.scheduler_info(n_workers=-1)["workers"])
    futures = {w: client.submit(fn, *args, workers=[w], allow_other_workers=True, pure=False) for w in workers}
    return {w: f.result() for w, f in futures.items()}


def run_campaign(campaign: Campaign | str | Path, store: str | Path, scheduler: str | None = None,
                 workers: int | None = None,
                 progress: Callable[[Progress], None] | None = None,
                 decided: Callable[[Path, int], bool] | None = None, priority: int = 0, client=None,
                 warm: bool = True) -> dict:
    """Run every sample of ``campaign`` not yet in ``store``; returns counts and timing.

    Parameters
    ----------
    campaign : Campaign, str or Path
        A campaign, or the path of its TOML file (:func:`auxbearing.campaign.config.read_campaign`).
    store : path
        Zarr store; made when absent, resumed when it holds this campaign, refused otherwise.
    scheduler : str, optional
        Address of a running Dask scheduler (``tcp://host:8786``); default a local cluster.
    workers : int, optional
        Worker processes of the local cluster; default one per core.
    progress : callable, optional
        Called with a :class:`Progress` after every stored batch.
    decided : callable, optional
        ``decided(store, n)``: True when the first ``n`` samples (in design order) already settle what the
        campaign is run for. It is asked at every batch end n, in design order, once every sample before n is
        complete: never of a set that depends on which batches a busy cluster finished first. When it says True
        the rest is cancelled and ``decided_at`` is n; batches past n already stored stay in the store.
    priority : int
        Dask priority of its batches on a shared cluster (higher runs first; ``Client.submit``).
    client : distributed.Client, optional
        A client of the caller's to run on (``scheduler`` then only names it in messages), left open: the
        campaigns of a verification, run side by side in threads, share the verification's client (seen
        with a client each to the same scheduler: one campaign waited forever on batches the scheduler
        already held in memory).
    warm : bool
        Run a short drop of the campaign's machine on every worker first (kernels loaded, the machine buildable
        there) and say in one line if it cannot run. False on a cluster whose workers the caller has already
        loaded and ran this machine on: a verification's, where each of its five campaigns' warm-up tasks,
        pinned to a worker, waited behind that worker's coast-down before the campaign could start.

    Returns
    -------
    dict
        ``runs``, ``completed``, ``new`` (this call), ``lost`` (samples of batches whose worker died;
        run again to retry), ``workers``, ``warm_up_s`` (largest per worker), ``startup_s``,
        ``run_s`` (first task to last record), ``wall_time_s`` and ``drops_per_second`` (new / run_s);
        ``lost_reason`` is the first error of a lost batch; ``decided_at`` (None unless ``decided`` ended it).
    """
    start = time.perf_counter()
    if isinstance(campaign, (str, Path)):  # a campaign file, as the command line takes it
        from auxbearing.campaign.config import read_campaign

        campaign = read_campaign(campaign)
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= 1024):
        # checked before the store is made (the command line's --workers rule, under the argument's name)
        raise InputError.for_field("workers", workers, "must be a whole number from 1 to 1024")
    points = design(campaign)
    # a scheduler address is tried before the store is touched, so a wrong address writes nothing
    own_client = client is None and scheduler is not None
    if own_client:
        client = _client(scheduler, None)[0]
    try:
        # one writer per store: the lock is held from before the store is made until its last batch is in
        with store_lock(store):
            prepare_store(store, campaign, points)
            todo = pending_batches(store, campaign.runs, campaign.batch_size)
            return _run(campaign, store, points, todo, client, scheduler, workers, progress, start, decided,
                        priority, warm)
    finally:
        if own_client:
            client.close()


def _complete_run(have: np.ndarray) -> int:
    """Samples complete from the first one on, without a gap."""
    missing = np.flatnonzero(~have)
    return int(missing[0]) if missing.size else int(have.size)


def _within_reach(start: int, settled: np.ndarray, reach: int) -> bool:
    """Whether a batch starting at sample ``start`` may go out: within ``reach`` samples of the first one not settled.

    Counted from the first sample neither in nor given up (``settled``), not from the last batch sent: a batch
    that waits behind another task holds back the ones after it, so a campaign that stops there has little run
    past its stop.
    """
    return start < _complete_run(settled) + reach


def _first_settled(decided, store: Path, ends: list, before: int, now: int) -> int | None:
    """The first batch end in (before, now] at which ``decided`` says the campaign is settled, or None.

    Every batch end is asked in design order, also when several batches complete the run at once: where the
    campaign stops does not depend on the order in which a cluster happened to finish them.
    """
    if decided is None:
        return None
    for n in ends:
        if before < n <= now and decided(store, n):
            return n
    return None


def _run(campaign: Campaign, store: Path, points, todo: list, client, scheduler: str | None, workers: int | None,
         progress, start: float, decided=None, priority: int = 0, warm: bool = True) -> dict:
    """The batches still to do, on the cluster (started here unless ``client`` is given), into the store."""
    from distributed import as_completed

    runs = campaign.runs
    done = runs - sum(b - a for a, b in todo)
    out = {"runs": runs, "completed": done, "new": 0, "lost": 0, "lost_reason": None, "workers": 0, "warm_up_s": 0.0,
           "startup_s": 0.0, "run_s": 0.0, "wall_time_s": 0.0, "drops_per_second": None, "decided_at": None}
    have = np.ones(runs, dtype=bool)
    for a, b in todo:
        have[a:b] = False
    ends = [min(a + campaign.batch_size, runs) for a in range(0, runs, campaign.batch_size)]
    prefix = _complete_run(have)
    settled = _first_settled(decided, store, ends, 0, prefix)  # a resumed store may settle it already
    if settled is not None:
        todo, out["decided_at"] = [], settled
    if not todo:
        out["wall_time_s"] = time.perf_counter() - start
        return out
    own = client is None
    cluster = None
    if own:
        client, cluster = _client(None, workers)
    try:
        try:
            client.wait_for_workers(1, timeout=WORKER_WAIT)
        except TimeoutError:
            raise InputError.for_field("--scheduler", scheduler, f"the scheduler has had no worker for {WORKER_WAIT:g} "
                                       "s; start some (dask worker ADDRESS)") from None
        out["workers"] = len(client.scheduler_info(n_workers=-1)["workers"])
        if warm:
            try:
                spent = on_every_worker(client, warm_up, campaign)
            except InputError:
                raise
            except Exception as err:  # nothing can run there: say so in one line instead of failing every sample
                where = f"the workers of {scheduler}" if scheduler else "the local workers"
                raise InputError(f"{where} cannot run a drop of this campaign ({type(err).__name__}: {err})") from None
            out["warm_up_s"] = max(spent.values(), default=0.0)
        out["startup_s"] = time.perf_counter() - start
        first = time.perf_counter()
        tag = campaign.fingerprint()
        pending = {}
        queue = list(todo)

        def submit_next(stream=None) -> None:
            a, b = queue.pop(0)
            # the campaign (4 kB) goes with each batch: a scattered copy would make every batch depend on it,
            # and Dask holds only tasks without such dependencies on the scheduler (WORKER_SATURATION)
            future = client.submit(evaluate_batch, campaign, points.values[a:b], key=f"campaign-{tag}-{a}", pure=False,
                                   priority=priority)
            pending[future.key] = (future, a, b)
            if stream is not None:
                stream.add(future)

        # with a stopping rule, only a few batches past the first one not yet in go out (in design order):
        # those past the stop would be computed for nothing; without one, all go at once
        reach = IN_FLIGHT * max(out["workers"], 1) * campaign.batch_size
        gone = np.zeros(runs, dtype=bool)  # samples of lost batches: not waited for

        def top_up(stream=None) -> None:
            while queue and (decided is None or _within_reach(queue[0][0], have | gone, reach)):
                submit_next(stream)

        top_up()
        new = lost = 0
        try:
            completed = as_completed([f for f, _, _ in pending.values()])
            for future in completed:
                _, a, b = pending.pop(future.key)
                try:
                    arrays = future.result()
                except Exception as err:  # a worker died or the batch broke: its samples stay pending
                    lost += b - a
                    gone[a:b] = True
                    out["lost_reason"] = out["lost_reason"] or f"{type(err).__name__}: {err}"[:200]
                    top_up(completed)
                    continue
                finally:
                    future.release()
                write_batch(store, a, arrays)
                interrupt.check()  # a Ctrl-C that a Dask callback swallowed
                new += b - a
                done += b - a
                have[a:b] = True
                grown = _complete_run(have)
                settled = _first_settled(decided, store, ends, prefix, grown)
                prefix = grown
                if settled is not None:
                    out["decided_at"] = settled
                    for rest, _, _ in pending.values():
                        rest.cancel()
                    break
                top_up(completed)  # only now: a batch sent before the stopping rule is asked may be one too many
                if progress is not None:
                    elapsed = time.perf_counter() - first
                    rate = new / elapsed if elapsed > 0 else 0.0
                    left = (runs - done - lost) / rate if rate > 0 else None
                    progress(Progress(done, runs, new, rate, left))
        except KeyboardInterrupt:
            for future, _, _ in pending.values():
                future.cancel()
            raise CampaignInterrupted(done, runs) from None
        out["run_s"] = time.perf_counter() - first
        out.update(completed=done, new=new, lost=lost,
                   drops_per_second=new / out["run_s"] if out["run_s"] > 0 else None)
    finally:
        if own:
            client.close()
            if cluster is not None:
                cluster.close()
    out["wall_time_s"] = time.perf_counter() - start
    return out
