"""The signatures and docstrings of fogdrift's functions (train, denoise, evaluate, northfind,
find_north, StreamingCompensator) and fogdrift.simulate's docstring, from the one description of
each option.

The compiled ``train`` takes its options as keywords and checks each against the description
fogdrift's library keeps of it (docs/options.md), the same one ``fogdrift train``'s flags come
from. ``with_options`` gives the Python function the signature and docstring those descriptions
make, so that ``help(fogdrift.train)``, ``inspect.signature`` and editors show every keyword with
its default.
"""
import functools
import inspect


def _value(option):
    """The Python value of an option's default, written as text in the description."""
    text, kind = option["default"], option["type"]
    if text == "None":
        return None
    if kind == "on/off":
        return text == "true"
    if kind in ("whole", "whole or auto") and text != "auto":
        return int(text)
    if kind in ("number", "seconds or auto") and text != "auto":
        return float(text)
    if kind == "numbers":  # "" is an empty list (simulate's start_up_temps_degc: the temps)
        return [float(v) for v in text.split(",")] if text else []
    if kind == "number or none":
        return None if text == "none" else float(text)
    if kind in ("mapping", "assignments"):
        return {}
    return text


def with_options(function, options, first="campaign", command="fogdrift train"):
    """`function` with a signature (`first`, then every option, keyword-only) and a docstring
    listing each option as the descriptions give it, with the flag of `command` that sets it."""
    @functools.wraps(function)
    def call(*args, **kwargs):
        return function(*args, **kwargs)

    parameters = [inspect.Parameter(first, inspect.Parameter.POSITIONAL_OR_KEYWORD)]
    parameters += [inspect.Parameter(o["keyword"], inspect.Parameter.KEYWORD_ONLY,
                                     default=_value(o)) for o in options]
    call.__signature__ = inspect.Signature(parameters)
    lines = [function.__doc__.strip().split("\n")[-1], "", "Keywords:"]
    call.__doc__ = "\n".join(lines + keyword_lines(options, command))
    return call


def with_keywords(function, positional, options, command):
    """`function` with a signature (`positional`, then every option, keyword-only) and its
    docstring followed by a line per option: for a function whose compiled form takes
    ``**kwargs`` and checks each against the descriptions. A positional argument is a name, or
    (name, default) for one that may be left out. A Python function (a wrapper of _keywords.py)
    is given them itself, so that no frame comes between the caller and a warning it raises."""
    if inspect.isfunction(function):
        call = function
    else:
        @functools.wraps(function)
        def call(*args, **kwargs):
            return function(*args, **kwargs)

    parameters = [inspect.Parameter(p[0], inspect.Parameter.POSITIONAL_OR_KEYWORD, default=p[1])
                  if isinstance(p, tuple) else
                  inspect.Parameter(p, inspect.Parameter.POSITIONAL_OR_KEYWORD)
                  for p in positional]
    parameters += [inspect.Parameter(o["keyword"], inspect.Parameter.KEYWORD_ONLY,
                                     default=_value(o)) for o in options]
    call.__signature__ = inspect.Signature(parameters)
    doc = (function.__doc__ or "").strip().split("\n")[-1]
    call.__doc__ = "\n".join([doc, "", "Keywords:"] + keyword_lines(options, command))
    return call


def keyword_lines(options, command):
    """One docstring line per option: its keyword, default, the flag of `command` and its doc."""
    lines = []
    for o in options:
        flag = f" ({command} {o['flag']})" if o["flag"] else ""
        lines.append(f"    {o['keyword']} = {_value(o)!r}{flag}: {o['doc']}")
    return lines
