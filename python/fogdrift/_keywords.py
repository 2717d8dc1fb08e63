"""A wrong type given to one of the compiled functions is a TypeError naming the keyword.

The compiled module (pybind11) answers a wrong type with "incompatible function arguments"
and the whole signature. `naming_keywords(f)` wraps `f` so that the message says which keyword
has the wrong type, what it must be, and what was given, e.g.

    train(): folds must be an int, not str ('three')

reading the types from the signature the compiled function itself reports (docs/python.md).
"""
import ast
import functools
import inspect
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


class _Default:
    """A default as pybind11 wrote it, shown as that text where it is no Python literal."""

    def __init__(self, text):
        self.text = text

    def __repr__(self):
        return self.text


def signature_of(function, drop_self=False):
    """The inspect.Signature of a compiled function, from the first line of the docstring
    pybind11 writes ("name(a: int, *, b: str = 'x', **kwargs) -> dict"); None when there is
    none to read. Annotations are pybind11's type names, as text."""
    first = (getattr(function, "__doc__", None) or "").split("\n", 1)[0]
    found = re.fullmatch(r"[\w.]*\((.*)\)(?: -> (.+))?", first.strip())
    if not found:
        return None
    parameters, kind = [], inspect.Parameter.POSITIONAL_OR_KEYWORD
    for part in _split_top(found.group(1)):
        if part == "*":
            kind = inspect.Parameter.KEYWORD_ONLY
            continue
        if part.startswith("**"):
            parameters.append(inspect.Parameter(part[2:].split(":")[0].strip(),
                                                inspect.Parameter.VAR_KEYWORD))
            continue
        if part.startswith("*"):
            parameters.append(inspect.Parameter(part[1:].split(":")[0].strip(),
                                                inspect.Parameter.VAR_POSITIONAL))
            kind = inspect.Parameter.KEYWORD_ONLY
            continue
        name_type, _, default = part.partition("=")
        name, _, annotation = name_type.partition(":")
        extra = {}
        if annotation.strip():
            extra["annotation"] = annotation.strip()
        if default.strip():
            try:
                extra["default"] = ast.literal_eval(default.strip())
            except (ValueError, SyntaxError):
                extra["default"] = _Default(default.strip())
        parameters.append(inspect.Parameter(name.strip(), kind, **extra))
    if drop_self and parameters and parameters[0].name == "self":
        parameters = parameters[1:]
    returns = found.group(2).strip() if found.group(2) else inspect.Signature.empty
    try:
        return inspect.Signature(parameters, return_annotation=returns)
    except ValueError:  # an order inspect refuses; no signature rather than a wrong one
        return None


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

    signature = signature_of(function)
    if signature is not None:
        call.__signature__ = signature
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

    signature = signature_of(original)
    if signature is not None:
        call.__signature__ = signature
    setattr(cls, method, call)

