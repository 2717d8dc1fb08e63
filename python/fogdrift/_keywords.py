"""A wrong type given to one of the compiled functions is a TypeError naming the keyword.

The compiled module (pybind11) answers a wrong type with "incompatible function arguments"
and the whole signature. `naming_keywords(f)` wraps `f` so that the message says which keyword
has the wrong type, what it must be, and what was given, e.g.

    train(): folds must be an int, not str ('three')

reading the types from the signature the compiled function itself reports (docs/python.md).
"""
import functools
import numbers
import os
import re

import numpy as np

_WHAT = {
    "int": ("an int", lambda v: isinstance(v, (numbers.Integral, np.integer))
            and not isinstance(v, (bool, np.bool_))),
    "float": ("a number", lambda v: isinstance(v, (numbers.Real, np.floating, np.integer))
              and not isinstance(v, (bool, np.bool_))),
    "str": ("a str", lambda v: isinstance(v, str)),
    "bool": ("a bool", lambda v: isinstance(v, (bool, np.bool_))),
    "os.PathLike": ("a path", lambda v: isinstance(v, (str, os.PathLike))),
}


_INCOMPATIBLE = re.compile(r"incompatible (function|constructor) arguments")


def _split_top(text):
    """Splits a parameter list at the commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _parameters(signature):
    """[(name, type)] of a signature "(a: int, *, b: str = 'x') -> object"."""
    inner = signature[signature.index("(") + 1:signature.rindex(")")]
    out = []
    for part in _split_top(inner):
        if part in ("*", "/") or ":" not in part:
            continue
        name, rest = part.split(":", 1)
        out.append((name.strip(), rest.split("=", 1)[0].strip()))
    return out


def _accepts(kind, value):
    """Whether a value fits a pybind11 type name (None when the name is not one we judge)."""
    if kind == "object":
        return True
    optional = re.fullmatch(r"Optional\[(.*)\]", kind)
    if optional:
        return value is None or _accepts(optional.group(1), value) is not False
    if kind in _WHAT:
        return _WHAT[kind][1](value)
    if kind.startswith("List[") or kind.startswith("Sequence["):
        return isinstance(value, (list, tuple, np.ndarray))
    return None


def _describe(kind):
    optional = re.fullmatch(r"Optional\[(.*)\]", kind)
    if optional:
        return _describe(optional.group(1)) + " or None"
    if kind in _WHAT:
        return _WHAT[kind][0]
    if kind.startswith("List[") or kind.startswith("Sequence["):
        return "a list"
    return "a " + kind.rsplit(".", 1)[-1]


def _diagnosis(name, message, args, kwargs):
    """The keyword with the wrong type, from the signatures listed in `message`; None when no
    single one can be blamed (several overloads, or every value fits)."""
    # "1. (a: int, ...) -> object" for a function, "1. module.Class(a: int, ...)" for a class.
    signatures = re.findall(r"^\s+\d+\. [\w.]*(\(.*\))(?: -> .*)?$", message, flags=re.M)
    if len(signatures) != 1:
        return None
    params = _parameters(signatures[0])
    if params and params[0][0] == "self":
        params = params[1:]
    given = list(zip([p for p, _ in params], args)) + list(kwargs.items())
    kinds = dict(params)
    for key, value in given:
        if key not in kinds:
            return (f"{name}() got an unexpected keyword argument '{key}'; its keywords are "
                    f"{', '.join(kinds)}")
        if _accepts(kinds[key], value) is False:
            shown = repr(value)
            shown = shown if len(shown) <= 40 else shown[:37] + "..."
            return (f"{name}(): {key} must be {_describe(kinds[key])}, not "
                    f"{type(value).__name__} ({shown})")
    return None


def _better(label, error, args, kwargs):
    """The TypeError to raise for pybind11's `error`: one naming the keyword when a single one
    can be blamed, else `error` itself."""
    if not _INCOMPATIBLE.search(str(error)):
        return error
    better = _diagnosis(label, str(error), args, kwargs)
    return error if better is None else TypeError(better)


def naming_keywords(function, name=None):
    """`function`, raising a TypeError that names the keyword where pybind11 would list the
    signature."""
    label = name or function.__name__

    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as error:
            better = _better(label, error, args, kwargs)
            if better is error:
                raise
            raise better from None

    return call


def method_naming_keywords(cls, method):
    """Replaces cls.method by one that names the keyword (self is not counted as given)."""
    original = getattr(cls, method)
    label = cls.__name__ if method == "__init__" else f"{cls.__name__}.{method}"

    @functools.wraps(original)
    def call(self, *args, **kwargs):
        try:
            return original(self, *args, **kwargs)
        except TypeError as error:
            better = _better(label, error, args, kwargs)
            if better is error:
                raise
            raise better from None

    setattr(cls, method, call)
