"""docs/python.md as a notebook user runs it: every ```python block, in order, in one session, in
an empty folder. A block that starts with "# Not run" is only compiled (it needs a cluster)."""
import os
import pathlib
import re

import pytest

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "python.md"


def blocks():
    return re.findall(r"```python\n(.*?)```", DOC.read_text(), flags=re.S)


def test_the_page_has_its_worked_example():
    found = blocks()
    assert len(found) >= 8
    assert any("fogdrift.train(" in b for b in found)
    assert any("savefig" in b for b in found)


def test_every_example_on_the_page_runs(tmp_path, monkeypatch, capsys):
    pytest.importorskip("matplotlib")
    pytest.importorskip("distributed")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    session = {"__name__": "__docs__"}
    for number, code in enumerate(blocks(), start=1):
        compiled = compile(code, f"docs/python.md block {number}", "exec")
        if code.lstrip().startswith("# Not run"):
            continue
        exec(compiled, session)
    # What the example says it makes.
    assert (tmp_path / "model.json").is_file() and (tmp_path / "startup.png").stat().st_size > 0
    assert sorted(os.listdir(tmp_path / "line" / "models")) == [
        "unit101.json", "unit102.json", "unit103.json"]
    table2 = session["table2"]["overall"]
    assert table2["std_compensated_dph"] < table2["std_denoised_dph"]
    assert session["table3"]["table3"]["removable_error_removed"] > 0.5
    assert session["table3"]["table3"]["drift_error_removed"] > 0.5
    assert all(e is None for e in session["summary"]["error"])
    printed = capsys.readouterr().out
    assert "STD" in printed and "removed" in printed
    # The figures step 6's prose quotes are the ones its example prints.
    assert "causal, guard off: STD compensated 0.0037 °/h (centred 0.0036)" in printed
    assert "STD 0.0037 against\n0.0036 °/h here" in DOC.read_text()
    assert "centred model streamed: 0.011 °/h RMS from predict's, drift STD 0.018" in printed
    assert "by 0.011 °/h RMS on this recording, against a\ndrift STD of 0.018 °/h" in DOC.read_text()
