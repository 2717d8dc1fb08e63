"""A fleet of units: one compensation model per campaign folder, trained and evaluated in
parallel on a Dask cluster (docs/python.md, "A production line").

Each campaign is an independent task, ``fogdrift.train`` then ``fogdrift.evaluate`` on it, run
by Dask's distributed scheduler: on this machine with a ``LocalCluster`` of processes, on a
production line's cluster by giving its scheduler's address. The results do not depend on where
a task ran: every model is byte for byte the one a serial run (``client=None``) trains.

The workers must see the campaign folders under the same paths (a shared file system) and
import the same fogdrift; models come back to the caller, which writes them.
"""
import os

from ._fogdrift import evaluate as _evaluate, train as _train


def _train_one(campaign, options, evaluate):
    """One unit: its model, the training summary and Table 2 on its test recordings. A campaign
    fogdrift refuses (bad data, impossible options) is reported, not raised, so that one unit
    does not stop the line."""
    result = {"campaign": str(campaign), "model": None, "summary": None, "evaluation": None,
              "error": None}
    try:
        trained = _train(campaign, **options)
        result["model"], result["summary"] = trained["model"], trained["summary"]
        if evaluate:
            result["evaluation"] = _evaluate(trained["model"], campaign)
    except (ValueError, MemoryError) as e:
        # A unit that failed, in training or in its evaluation, gives no model: the docstring's
        # promise, and what out= writes.
        result.update(model=None, summary=None, evaluation=None, error=str(e))
    return result


def train_fleet(campaigns, *, client=None, out=None, evaluate=True, progress=None,
                threads=1, **options):
    """Trains and evaluates one model per campaign folder.

    campaigns: campaign folders (or their campaign.json), one per unit.
    client: a ``distributed.Client``; None runs the units one after another in this process.
        ``Client(LocalCluster(n_workers=4, threads_per_worker=1))`` uses this machine's cores,
        ``Client("tcp://scheduler:8786")`` a cluster's.
    out: a folder to write each unit's model to, as ``<campaign folder name>.json``.
    evaluate: also evaluate each model on its campaign's recordings with role "test".
    progress: called as ``progress(done, total, result)`` as each unit finishes.
    threads: threads each unit's training uses (1: Dask's workers are the parallelism).
    options: ``fogdrift.train``'s keywords (method, population, seed, ...), the same for every
        unit.

    Options fogdrift refuses (a method it does not have, a population too small, a box upside
    down) raise ValueError once, before any unit runs.

    Returns one dict per campaign, in the order given: ``campaign``, ``model`` (a Model),
    ``summary`` and ``evaluation`` (as fogdrift.train and fogdrift.evaluate return them) and
    ``error`` (the message, when fogdrift refused the unit; the other fields are then None).
    """
    campaigns = [os.fspath(c) for c in campaigns]
    options = dict(options, threads=threads)
    # Options wrong for every unit are one error, raised before any unit runs.
    _train(None, validate_only=True, **options)
    names = [os.path.basename(os.path.normpath(c[:-len("campaign.json")]
                                               if c.endswith("campaign.json") else c))
             for c in campaigns]
    if out is not None and len(set(names)) != len(names):
        raise ValueError("option out: two campaigns have the same folder name; their models "
                         "would overwrite each other")
    results = [None] * len(campaigns)
    if client is None:
        for i, c in enumerate(campaigns):
            results[i] = _train_one(c, options, evaluate)
            if progress is not None:
                progress(i + 1, len(campaigns), results[i])
    else:
        from distributed import as_completed
        # pure=False: a unit is trained again when asked again, not taken from a cache.
        futures = client.map(_train_one, campaigns, options=options, evaluate=evaluate,
                             pure=False)
        index = {f.key: i for i, f in enumerate(futures)}
        for done, future in enumerate(as_completed(futures), start=1):
            i = index[future.key]
            results[i] = future.result()
            if progress is not None:
                progress(done, len(campaigns), results[i])
    if out is not None:
        os.makedirs(out, exist_ok=True)
        for name, r in zip(names, results):
            if r["model"] is not None:
                r["model"].save(os.path.join(out, name + ".json"))
    return results


__all__ = ["train_fleet"]
