"""The three faces of the options described once (train, simulate, the streaming fault policy,
denoise) agree: the command line's flags, the Python keywords and docs/options.md all come from
one description of each option (docs/options.md), and this checks that what each shows a user is
that description."""
import inspect
import json
import os
import pathlib
import re
import subprocess

import numpy as np
import pytest

import fogdrift

DOCS = pathlib.Path(__file__).resolve().parents[2] / "docs" / "options.md"


@pytest.fixture(scope="module")
def described(cli):
    return json.loads(cli("options", "--json"))


def assert_help_shows(help_text, described, where=""):
    """--help shows each option's flag with its type name and default (CLI11 writes
    "--c-max NUMBER=1000"; an on/off flag stands alone) and its help text, other options named
    by flag."""
    help_text = re.sub(r"\s+", " ", help_text)
    for o in described:
        if o["type"] == "on/off":
            assert f" {o['flag']} " in help_text, (where, o["flag"])
        else:  # an empty default (a list that defaults to another option's) shows no "="
            default = "=" + re.escape(o["default"]) if o["default"] else ""
            assert re.search(re.escape(o["flag"]) + r" \S+" + default + " ", help_text), \
                (where, o["flag"])
        assert re.sub(r"\s+", " ", o["help"]) in help_text, (where, o["flag"])


def test_the_command_line_has_every_option_with_its_default(cli, described):
    assert_help_shows(cli("train", "--help"), described)


def test_python_has_every_option_with_its_default(described):
    signature = inspect.signature(fogdrift.train).parameters
    options = {o["keyword"]: o for o in fogdrift.train_options()}
    for o in described:
        assert o["keyword"] in signature, o["keyword"]
        assert options[o["keyword"]]["default"] == o["default"]
        assert options[o["keyword"]]["flag"] == o["flag"]
        default = signature[o["keyword"]].default
        assert str(default).lower() == o["default"] or default == float(o["default"]), o
        assert o["doc"][:40] in fogdrift.train.__doc__, o["keyword"]
    # Python's own keywords come after the command's options and have no flag.
    extra = [o["keyword"] for o in fogdrift.train_options() if not o["flag"]]
    assert extra == ["threads", "target", "progress", "validate_only"]
    assert list(signature) == ["campaign"] + [o["keyword"] for o in fogdrift.train_options()]


def rows_of(command):
    """The docs table of `command`'s options, between its marker lines."""
    text = DOCS.read_text()
    table = text.split(f"<!-- {command} options: begin")[1].split(f"<!-- {command} options: end")[0]
    return [line for line in table.splitlines() if line.startswith("| `")]


def test_the_docs_table_is_the_description(described):
    rows = rows_of("train")
    assert [re.match(r"\| `(\w+)`", r).group(1) for r in rows] == [o["keyword"] for o in described]
    for row, o in zip(rows, described):
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", row)[1:-1]]
        assert cells[1] == f"`{o['flag']}`" and cells[2] == o["type"]
        assert cells[4] == f"`{o['default']}`"


def test_an_error_names_the_option_in_each_front_ends_words(tmp_path):
    cli = os.environ.get("FOGDRIFT_CLI", "build/apps/fogdrift/fogdrift")
    fogdrift.simulate("calibration", seed=1, temps_degc=[0, 20, 40], repetitions=1,
                      test_repetitions=0, out=tmp_path / "cal")
    # The library checks the window as window_s, the degree as degree; each front end names the
    # option that sets it, in its own words.
    for keyword, value, extra, rule in [
            ("rate_window_s", 1.0, {}, "a window of 1"),
            ("max_degree", 9, dict(method="poly"), "9 must be between 1 and 6"),
            ("epsilon_min", 0.0, dict(search_epsilon=True), "0 must be > 0"),
            ("search", "pso", dict(method="ssa-svr"), "'pso' contradicts ")]:
        with pytest.raises(ValueError, match=f"option {keyword}: .*{rule}"):
            fogdrift.train(tmp_path / "cal", **{keyword: value}, **extra)
        flag = "--" + keyword.replace("_", "-")
        args = [cli, "train", str(tmp_path / "cal"), "-o", str(tmp_path / "m.json"), flag,
                str(value)]
        for k, v in extra.items():
            args += ["--" + k.replace("_", "-")] + ([] if v is True else [str(v)])
        done = subprocess.run(args, capture_output=True, text=True)
        assert done.returncode == 1 and f"option {flag}: " in done.stderr, done.stderr
        assert rule in done.stderr, done.stderr
        assert not (tmp_path / "m.json").exists()
    # A message that names other options names them in each front end's words.
    with pytest.raises(ValueError, match="give method svr with search pso"):
        fogdrift.train(tmp_path / "cal", method="ssa-svr", search="pso")
    done = subprocess.run([cli, "train", str(tmp_path / "cal"), "-o", str(tmp_path / "m.json"),
                           "--method", "ssa-svr", "--search", "pso"], capture_output=True, text=True)
    assert "give --method svr with --search pso" in done.stderr, done.stderr


@pytest.mark.parametrize("scenario", ["calibration", "northfind", "stable"])
def test_simulate_has_one_description_in_every_face(cli, scenario):
    described = json.loads(cli("options", f"simulate-{scenario}", "--json"))
    # Python's description is the command line's.
    python = fogdrift.simulate_options(scenario)
    assert [(o["keyword"], o["flag"], o["default"]) for o in python] == \
        [(o["keyword"], o["flag"], o["default"]) for o in described]
    # --help shows each flag with its default and its help text.
    assert_help_shows(cli("simulate", scenario, "--help"), described)
    for o in described:
        assert o["doc"][:40] in fogdrift.simulate.__doc__, o["keyword"]
    # docs/options.md's table.
    rows = rows_of(f"simulate-{scenario}")
    assert [re.match(r"\| `(\w+)`", r).group(1) for r in rows] == [o["keyword"] for o in described]
    for row, o in zip(rows, described):
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", row)[1:-1]]
        assert cells[1] == f"`{o['flag']}`" and cells[4] == f"`{o['default']}`"


def test_simulate_names_an_error_in_each_front_ends_words(tmp_path):
    cli = os.environ.get("FOGDRIFT_CLI", "build/apps/fogdrift/fogdrift")
    for scenario, keyword, flag, value, rule in [
            ("calibration", "temps_degc", "--temps", [-20, 120], "120 °C must be between -70 and 100"),
            ("calibration", "test_repetitions", "--test-repetitions", 7, "7 is outside"),
            ("northfind", "position_s", "--position-s", 5.0, "5 s must be between 20 and 36000"),
            ("stable", "output_rate_hz", "--rate-hz", 0, "0 Hz must be > 0, ≤ 2000")]:
        with pytest.raises(ValueError, match=f"option {keyword}: {rule}"):
            fogdrift.simulate(scenario, **{keyword: value})
        text = ",".join(map(str, value)) if isinstance(value, list) else str(value)
        done = subprocess.run([cli, "simulate", scenario, "--out", str(tmp_path / "x"), flag,
                               text], capture_output=True, text=True)
        assert done.returncode == 1 and f"option {flag}: {rule}" in done.stderr, done.stderr
        assert not (tmp_path / "x").exists()
    # The same options give the same campaign from either front end.
    subprocess.run([cli, "simulate", "northfind", "--out", str(tmp_path / "cli"), "--temps",
                    "-5,30", "--findings", "1", "--approach", "warm", "--seed", "4"], check=True,
                   capture_output=True)
    fogdrift.simulate("northfind", out=tmp_path / "py", temps_degc=[-5, 30], findings=1,
                      approach="warm", seed=4)
    for f in sorted((tmp_path / "cli").iterdir()):
        assert f.read_bytes() == (tmp_path / "py" / f.name).read_bytes(), f.name


def test_the_fault_policy_has_one_description_in_every_face(cli):
    described = json.loads(cli("options", "stream", "--json"))
    # How the command reads its CSV, then the compensator's own options, which Python's
    # StreamingCompensator takes: it is given each sample's interval and raises on a fault.
    assert [o["keyword"] for o in described[:2]] == ["rate_hz", "strict"]
    compensator = described[2:]
    assert [(o["keyword"], o["flag"], o["default"]) for o in fogdrift.stream_options()] == \
        [(o["keyword"], o["flag"], o["default"]) for o in compensator]
    assert compensator[0]["keyword"] == "guarded"  # the guard's switch, then the fault policy
    signature = inspect.signature(fogdrift.StreamingCompensator.__init__).parameters
    assert list(signature) == ["self", "model", "dt_s"] + [o["keyword"] for o in compensator]
    assert_help_shows(cli("stream", "--help"), described, "stream")
    # export-c runs the fault policy alone: the header's guard is the model's.
    assert_help_shows(cli("export-c", "--help"), compensator[1:], "export-c")
    rows = rows_of("stream")
    assert [re.match(r"\| `(\w+)`", r).group(1) for r in rows] == [o["keyword"] for o in described]


def test_a_model_is_loaded_with_the_options_of_every_command_that_reads_one(cli):
    described = fogdrift.model_load_options()
    assert [(o["keyword"], o["flag"], o["default"]) for o in described] == \
        [("allow_edited", "--allow-edited", "false"),
         ("allow_old_format", "--allow-old-format", "false")]
    for function, first in ((fogdrift.Model.load, ["path", "target"]),
                            (fogdrift.Model.from_json, ["text"])):
        assert list(inspect.signature(function).parameters) == \
            first + [o["keyword"] for o in described]
        for o in described:
            assert o["doc"][:40] in function.__doc__, o["keyword"]
    for command in ("compensate", "stream", "export-c", "evaluate"):
        help_text = re.sub(r"\s+", " ", cli(command, "--help"))
        for o in described:
            assert f" {o['flag']} " in help_text, (command, o["flag"])


def test_denoise_has_one_description_in_every_face(cli, tmp_path):
    described = json.loads(cli("options", "denoise", "--json"))
    assert [(o["keyword"], o["flag"], o["default"]) for o in fogdrift.denoise_options()] == \
        [(o["keyword"], o["flag"], o["default"]) for o in described]
    signature = inspect.signature(fogdrift.denoise).parameters
    assert list(signature) == ["data", "summary"] + [o["keyword"] for o in described]
    assert_help_shows(cli("denoise", "--help"), described)
    for o in described:
        assert o["doc"][:40] in fogdrift.denoise.__doc__, o["keyword"]
    rows = rows_of("denoise")
    assert [re.match(r"\| `(\w+)`", r).group(1) for r in rows] == [o["keyword"] for o in described]
    # The same options give the same signal from either front end; level None, "auto" and the
    # command line's "max" are one level.
    t = np.arange(2048) * 1.0
    x = np.sin(t / 50.0) + 0.1 * np.random.default_rng(3).standard_normal(t.size)
    (tmp_path / "x.csv").write_text("time_s,gyro_dph\n" + "".join(
        f"{a!r},{b!r}\n" for a, b in zip(t, x)))
    for flags, keywords in [([], {}), (["--level", "max"], dict(level=None)),
                            (["--level", "auto", "--threshold", "sure", "--mode", "hard"],
                             dict(level="auto", threshold="sure", mode="hard")),
                            (["--wavelet", "db4", "--level", "5", "--extension", "periodization"],
                             dict(wavelet="db4", level=5, extension="periodization"))]:
        cli("denoise", tmp_path / "x.csv", "-o", tmp_path / "y.csv", "-q", *flags)
        got = np.loadtxt(tmp_path / "y.csv", delimiter=",", skiprows=1)[:, 1]
        np.testing.assert_array_equal(got, fogdrift.denoise(x, **keywords))
    # An error names the option in each front end's words.
    with pytest.raises(ValueError, match="option level: 12 is too high for 2048 samples"):
        fogdrift.denoise(x, level=12)
    done = subprocess.run([os.environ.get("FOGDRIFT_CLI", "build/apps/fogdrift/fogdrift"),
                           "denoise", str(tmp_path / "x.csv"), "-o", str(tmp_path / "z.csv"),
                           "--level", "12"], capture_output=True, text=True)
    assert done.returncode == 1 and "option --level: 12 is too high for 2048" in done.stderr
    with pytest.raises(ValueError, match="option threshold: 'median' is not a threshold rule"):
        fogdrift.denoise(x, threshold="median")
    with pytest.raises(TypeError, match=r"denoise\(\) got an unexpected keyword argument 'levels'; "
                                        r"its keywords are data, summary, wavelet, level"):
        fogdrift.denoise(x, levels=3)


@pytest.mark.parametrize("command, functions", [
    ("evaluate", {"evaluate": ["model", "data", "input_rate_dph", "references"]}),
    ("northfind", {"northfind": ["campaign", "model"],
                   "find_north": ["recording", "latitude_deg", "model"]})])
def test_the_evaluations_have_one_description_in_every_face(cli, command, functions):
    described = json.loads(cli("options", command, "--json"))
    python = getattr(fogdrift, f"{command}_options")()
    assert [(o["keyword"], o["flag"], o["default"]) for o in python] == \
        [(o["keyword"], o["flag"], o["default"]) for o in described]
    for name, own in functions.items():
        function = getattr(fogdrift, name)
        assert list(inspect.signature(function).parameters) == own + [o["keyword"] for o in
                                                                      described]
        for o in described:
            assert o["doc"][:40] in function.__doc__, (name, o["keyword"])
    assert_help_shows(cli(command, "--help"), described)
    rows = rows_of(command)
    assert [re.match(r"\| `(\w+)`", r).group(1) for r in rows] == [o["keyword"] for o in described]


def test_northfind_names_an_error_in_each_front_ends_words(tmp_path):
    cli = os.environ.get("FOGDRIFT_CLI", "build/apps/fogdrift/fogdrift")
    held = fogdrift.simulate("northfind", temps_degc=[20], findings=1, out=tmp_path / "nf")
    with pytest.raises(ValueError, match=r"option tolerance_deg: 50 ° must be > 0, < 45"):
        fogdrift.northfind(held, tolerance_deg=50)
    with pytest.raises(ValueError, match="option settle_s: -1 s must be ≥ 0"):
        fogdrift.find_north(tmp_path / "nf" / held["recordings"][0]["file"], 30.0, settle_s=-1)
    done = subprocess.run([cli, "northfind", str(tmp_path / "nf"), "--tolerance-deg", "50"],
                          capture_output=True, text=True)
    assert done.returncode == 1 and "option --tolerance-deg: 50 ° must be > 0, < 45" in \
        done.stderr, done.stderr
    # The same options, the same findings from either front end.
    got = fogdrift.northfind(tmp_path / "nf", tolerance_deg=0.5, settle_s=4.0)
    expected = json.loads(subprocess.run([cli, "northfind", str(tmp_path / "nf"), "--json",
                                          "--tolerance-deg", "0.5", "--settle-s", "4"],
                                         capture_output=True, text=True, check=True).stdout)
    assert got["table3"] == expected["table3"]
    with pytest.raises(TypeError, match=r"northfind\(\) got an unexpected keyword argument "
                                        r"'tolerance'; its keywords are campaign, model, guarded"):
        fogdrift.northfind(held, tolerance=0.5)
