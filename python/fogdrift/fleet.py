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
import warnings

from ._fogdrift import evaluate as _evaluate, train as _train, train_options as _train_options

_OWN = ("client", "out", "evaluate", "progress", "threads")


def _train_one(campaign, label, options, evaluate):
    """One unit: its model, the training summary and Table 2 on its test recordings. A campaign
    fogdrift refuses (bad data, impossible options) is reported, not raised, so that one unit
    does not stop the line. The warnings it raised are kept, to be raised again in the caller
    (a worker's own are printed where nobody reads them)."""
    result = {"campaign": label if isinstance(campaign, dict) else os.fspath(campaign),
              "unit": label, "model": None, "summary": None, "evaluation": None,
              "error": None, "warnings": []}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            trained = _train(campaign, **options)
            result["model"], result["summary"] = trained["model"], trained["summary"]
            if evaluate:
                result["evaluation"] = _evaluate(trained["model"], campaign)
        except (ValueError, MemoryError) as e:
            # A unit that failed, in training or in its evaluation, gives no model: the
            # docstring's promise, and what out= writes.
            result.update(model=None, summary=None, evaluation=None, error=str(e))
    result["warnings"] = [(w.category, str(w.message)) for w in caught]
    return result


def _label(campaign, i):
    """A unit's name: its folder's, or for a campaign in memory its "name" or "unit N"."""
    if isinstance(campaign, dict):
        return str(campaign.get("name") or f"unit {i + 1}")
    path = os.fspath(campaign)
    return os.path.basename(os.path.normpath(path[:-len("campaign.json")]
                                             if path.endswith("campaign.json") else path))


def _finished(result):
    """Raises a unit's warnings in the caller, each naming the unit."""
    for category, message in result["warnings"]:
        warnings.warn(f"{result['unit']}: {message}", category, stacklevel=3)


def train_fleet(campaigns, *, client=None, out=None, evaluate=True, progress=None,
                threads=1, **options):
    """Trains and evaluates one model per campaign folder.

    campaigns: campaign folders (or their campaign.json), or campaigns in memory (the dicts
        fogdrift.simulate returns; named by their "name", else "unit N"), one per unit.
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

    Returns one dict per campaign, in the order given: ``campaign`` (the path as given, or the
    name of a campaign in memory), ``unit`` (its name: the folder's), ``model`` (a Model),
    ``summary`` and ``evaluation`` (as fogdrift.train and fogdrift.evaluate return them),
    ``error`` (the message, when fogdrift refused the unit; the other fields are
    then None) and ``warnings`` ((category, message) of each warning the unit raised). Each
    warning is also raised here, in the caller, as "UNIT: message", so that
    ``warnings.catch_warnings`` and ``-W error`` see it wherever the unit ran.
    """
    campaigns = list(campaigns)
    for i, c in enumerate(campaigns):
        if not isinstance(c, (dict, str, os.PathLike)):
            raise TypeError(f"train_fleet(): campaigns[{i}] must be a folder (str or "
                            f"os.PathLike) or a campaign in memory (the dict fogdrift.simulate "
                            f"returns), not {type(c).__name__}")
    known = [o["keyword"] for o in _train_options() if o["keyword"] not in
             ("progress", "validate_only", "threads")]
    for key in options:
        if key not in known:
            raise TypeError(f"train_fleet() got an unexpected keyword argument '{key}'; its "
                            f"keywords are {', '.join(_OWN)}, and fogdrift.train's: "
                            f"{', '.join(known)}")
    options = dict(options, threads=threads)
    # Options wrong for every unit are one error, raised before any unit runs.
    _train(None, validate_only=True, **options)
    names = [_label(c, i) for i, c in enumerate(campaigns)]
    if out is not None and len(set(names)) != len(names):
        raise ValueError("option out: two campaigns have the same folder name; their models "
                         "would overwrite each other")
    results = [None] * len(campaigns)
    if client is None:
        for i, c in enumerate(campaigns):
            results[i] = _train_one(c, names[i], options, evaluate)
            _finished(results[i])
            if progress is not None:
                progress(i + 1, len(campaigns), results[i])
    else:
        from distributed import as_completed
        # pure=False: a unit is trained again when asked again, not taken from a cache.
        futures = client.map(_train_one, campaigns, names, options=options, evaluate=evaluate,
                             pure=False)
        index = {f.key: i for i, f in enumerate(futures)}
        for done, future in enumerate(as_completed(futures), start=1):
            i = index[future.key]
            results[i] = future.result()
            _finished(results[i])
            if progress is not None:
                progress(done, len(campaigns), results[i])
    if out is not None:
        os.makedirs(out, exist_ok=True)
        for name, r in zip(names, results):
            if r["model"] is not None:
                r["model"].save(os.path.join(out, name + ".json"))
    return results


__all__ = ["train_fleet"]
