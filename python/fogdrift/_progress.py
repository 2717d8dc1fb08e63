"""Progress of fogdrift.train's search (docs/python.md, "Progress").

``progress=`` takes a callable (called after each iteration with a dict: iteration, iterations,
evaluations, best_rmse, best_point; returning False stops the search), or says how to show it:

* ``'auto'`` (the default): a tqdm bar when tqdm is installed (``tqdm.auto``: a widget in a
  notebook, a bar in a terminal), else a line on standard error every 5 s when standard error
  is a terminal, else nothing;
* ``True``: a tqdm bar, or the lines when tqdm is missing, wherever standard error goes;
* ``'lines'``: the lines, even with tqdm installed;
* ``False`` or ``None``: nothing.
"""
import sys
import time

_EVERY_S = 5.0


class _Lines:
    """A line every 5 s of the search, and one at its end."""

    def __init__(self, label, stream):
        self.label, self.stream = label, stream
        self.start = time.monotonic()
        self.last = self.start

    def __call__(self, r):
        now = time.monotonic()
        if now - self.last >= _EVERY_S or r["iteration"] == r["iterations"]:
            self.last = now
            print(f"{self.label}: iteration {r['iteration']}/{r['iterations']}, best RMSE "
                  f"{r['best_rmse']:.5f}, {r['evaluations']} evaluations, "
                  f"{now - self.start:.0f} s", file=self.stream, flush=True)
        return True

    def close(self):
        pass


class _Bar:
    """A tqdm bar over the search's iterations."""

    def __init__(self, label):
        from tqdm.auto import tqdm
        self.tqdm, self.label, self.bar = tqdm, label, None

    def __call__(self, r):
        if self.bar is None:
            self.bar = self.tqdm(total=r["iterations"], desc=self.label, unit="iteration")
        self.bar.update(r["iteration"] - self.bar.n)
        self.bar.set_postfix(best_rmse=f"{r['best_rmse']:.5f}", evaluations=r["evaluations"],
                             refresh=False)
        return True

    def close(self):
        if self.bar is not None:
            self.bar.close()


class _Callback:
    """A caller's own callable, as given."""

    def __init__(self, function):
        self.function = function

    def __call__(self, r):
        return self.function(r)

    def close(self):
        pass


def _has_tqdm():
    try:
        import tqdm.auto  # noqa: F401
    except ImportError:
        return False
    return True


def reporter(progress, label):
    """What to pass to the compiled call for `progress` (None: nothing), with close() to end a
    bar. A value of another kind is a TypeError naming the keyword."""
    if progress is None or progress is False:
        return None
    if callable(progress):
        return _Callback(progress)
    if progress is True:
        return _Bar(label) if _has_tqdm() else _Lines(label, sys.stderr)
    if progress == "lines":
        return _Lines(label, sys.stderr)
    if progress == "auto":
        if _has_tqdm():
            return _Bar(label)
        return _Lines(label, sys.stderr) if sys.stderr.isatty() else None
    raise TypeError(f"train(): progress must be 'auto', True, False, 'lines', None or a "
                    f"callable, not {type(progress).__name__} ({progress!r})")


def with_progress(train):
    """The compiled train with ``progress`` read as above (default 'auto')."""
    def call(campaign, progress="auto", **kwargs):
        shown = reporter(progress, "fogdrift.train")
        try:
            return train(campaign, progress=shown, **kwargs)
        finally:
            if shown is not None:
                shown.close()

    call.__name__, call.__doc__ = train.__name__, train.__doc__
    return call
