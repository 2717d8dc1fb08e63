#!/usr/bin/env python3
"""Prints a JSON document with times removed and numbers rounded to 6 significant digits, so a
committed copy changes only when fogdrift's results do (the change indicator of cli_test.sh)."""
import json
import sys

TIME_KEYS = {"elapsed_s", "train_s", "seconds"}


def clean(value):
    if isinstance(value, dict):
        return {k: clean(v) for k, v in value.items() if k not in TIME_KEYS}
    if isinstance(value, list):
        return [clean(v) for v in value]
    if isinstance(value, float):
        return float(f"{value:.6g}")
    return value


print(json.dumps(clean(json.load(sys.stdin)), indent=1, sort_keys=False))
