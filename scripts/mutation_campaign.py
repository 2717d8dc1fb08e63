#!/usr/bin/env python3
"""A mutation campaign against every reader of the fogdrift command (docs/reliability.md).

Good inputs are made first: a small simulated calibration campaign, a model trained on it, a
chamber sheet and a three-axis IMU log (scripts/make_chamber_fixture.py), an instrument file.
Each of N rounds mutates one of them (bytes flipped, inserted or cut; lines duplicated, dropped
or swapped; numbers replaced by extreme or non-finite text; brackets nested deep; line ends, a
byte-order mark or a NUL byte added; a cell made megabytes long) and runs the commands that read
it, each with a time limit. A run must end in one of two ways:
  - exit 0, with every output file whole and every number fogdrift reads or computes in it
    finite (a column fogdrift does not know is kept as the user wrote it, and not checked);
  - exit 1 with a message 'fogdrift: error: ...' on standard error, and no output file left
    behind (nor a temporary one).
Anything else is a finding: a signal (a crash), a run over the time limit (a hang), another exit
status, an exit 0 whose output holds inf or nan, a partial or temporary file, or a message
that is not fogdrift's. A sample of the runs that exit 0 is repeated with standard output on
/dev/full, which must fail. Findings are copied to OUT/findings/ with the command line.

A further kind of input, "model_text", edits the strings a model file gives a C header (its
method, version, feature names and spec, target column) to text that tries to leave a comment or
a string literal and declare `fogdrift_injected`. export-c (with --allow-edited) must then
refuse the file, or write a header that compiles with -Wall -Wextra -Werror -pedantic and
declares no `fogdrift_injected` (docs/reliability.md, "Generated code").

Deterministic: the same seed mutates the same way.
Usage: python3 scripts/mutation_campaign.py FOGDRIFT N SEED [OUT]
FOGDRIFT_MUTATION_KINDS=model_text,recording,... runs those kinds only.
"""
import csv
import io
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

TIME_LIMIT_S = 20
csv.field_size_limit(1 << 30)  # a mutated cell may be megabytes long
EXTREMES = ["1e308", "-1e308", "1e309", "nan", "NaN", "inf", "-inf", "1e-320", "0", "-0",
            "9" * 400, "1.5.5", "0x10", "", " ", "1,5", "+", "-", "1e", "3e2e2", "\u00b5",
            "12345678901234567890123"]


def mutate(data: bytes, rng: random.Random) -> bytes:
    """One random mutation of a file's bytes."""
    kind = rng.randrange(14)
    text = data.decode("utf-8", errors="surrogateescape")
    lines = text.split("\n")
    if kind == 0 and data:  # flip bits
        b = bytearray(data)
        for _ in range(rng.randint(1, 8)):
            i = rng.randrange(len(b))
            b[i] ^= 1 << rng.randrange(8)
        return bytes(b)
    if kind == 1:  # insert random bytes
        i = rng.randrange(len(data) + 1)
        return data[:i] + bytes(rng.randrange(256) for _ in range(rng.randint(1, 16))) + data[i:]
    if kind == 2 and data:  # cut a chunk
        i = rng.randrange(len(data))
        return data[:i] + data[i + rng.randint(1, 400):]
    if kind == 3:  # truncate
        return data[:rng.randrange(len(data) + 1)]
    if kind == 4 and len(lines) > 2:  # duplicate, drop or swap lines
        i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
        op = rng.randrange(3)
        if op == 0:
            lines.insert(j, lines[i])
        elif op == 1:
            del lines[i]
        else:
            lines[i], lines[j] = lines[j], lines[i]
        return "\n".join(lines).encode("utf-8", errors="surrogateescape")
    if kind in (5, 6, 7):  # a number replaced by an extreme or non-number
        tokens = [k for k, c in enumerate(text) if c.isdigit() and (k == 0 or not text[k - 1].isdigit()
                                                                     and text[k - 1] not in ".eE")]
        if tokens:
            k = rng.choice(tokens)
            end = k
            while end < len(text) and (text[end].isdigit() or text[end] in ".eE+-"):
                end += 1
            text = text[:k] + rng.choice(EXTREMES) + text[end:]
            return text.encode("utf-8", errors="surrogateescape")
    if kind == 8:  # deep nesting where a value may stand
        depth = rng.choice([70, 1000, 100000])
        i = text.find(": ")
        i = i + 2 if i >= 0 else rng.randrange(len(text) + 1)
        return (text[:i] + "[" * depth + "]" * depth + text[i:]).encode(
            "utf-8", errors="surrogateescape")
    if kind == 9:  # line ends
        return data.replace(b"\n", rng.choice([b"\r\n", b"\r", b"\n\n"]))
    if kind == 10:  # a byte-order mark, or a NUL
        return rng.choice([b"\xef\xbb\xbf" + data, data[:len(data) // 2] + b"\x00" + data[len(data) // 2:]])
    if kind == 11:  # a cell megabytes long
        i = rng.randrange(len(data) + 1)
        return data[:i] + b"7" * rng.choice([10**5, 10**7]) + data[i:]
    if kind == 12 and len(lines) > 1:  # a header name changed
        header = lines[0].split(",")
        header[rng.randrange(len(header))] = rng.choice(["", "time_s", "gyro_dph", "x" * 300, "\"a"])
        lines[0] = ",".join(header)
        return "\n".join(lines).encode("utf-8", errors="surrogateescape")
    # one row's field count changed
    if len(lines) > 2:
        i = rng.randrange(1, len(lines))
        lines[i] = lines[i] + rng.choice([",", ",1", ",,,"]) if rng.random() < 0.5 else \
            lines[i].rsplit(",", 1)[0]
    return "\n".join(lines).encode("utf-8", errors="surrogateescape")


# A non-finite number as printed: nan, inf, -inf, infinity, in any case, as a word of its own.
NON_FINITE = re.compile(r"(?<![A-Za-z0-9_])[-+]?(nan|inf|infinity)(?![A-Za-z0-9_])", re.I)


# In a C header, NAN is the macro the fault policy uses; a number fogdrift printed is lower case.
NON_FINITE_C = re.compile(r"(?<![A-Za-z0-9_])[-+]?(nan|inf)(?![A-Za-z0-9_])")


# Text that tries to leave a C comment or string literal and declare fogdrift_injected.
INJECTIONS = ["*/ int fogdrift_injected; /*", "\"; int fogdrift_injected; static const char* x = \"",
              "\\\nint fogdrift_injected;", "??/\nint fogdrift_injected;", "*/\n#define A\n/*",
              "\nint fogdrift_injected;\n", "\rint fogdrift_injected;", "\x00int fogdrift_injected;",
              "' int fogdrift_injected; '", "/* int fogdrift_injected; */", "// int fogdrift_injected;",
              "@REAL@ fogdrift_injected;", "\u00b0C */ int fogdrift_injected;", "%s%n", "\\",
              "*", "/", "?", "\"", "T_fog_degc", "", "x" * 3000]


def inject_text(model: dict, rng: random.Random) -> dict:
    """The model with one to three of its strings replaced by injection attempts."""
    def nasty():
        parts = [rng.choice(INJECTIONS) for _ in range(rng.randint(1, 3))]
        if rng.random() < 0.3:
            parts.insert(rng.randrange(len(parts) + 1),
                         "".join(chr(rng.randrange(1, 0x250)) for _ in range(rng.randint(1, 6))))
        return "".join(parts)
    places = ["method", "version", "name", "spec", "target"]
    for _ in range(rng.randint(1, 3)):
        where = rng.choice(places)
        if where == "method":
            model["provenance"]["method"] = nasty()
        elif where == "version":
            model["provenance"]["fogdrift_version"] = nasty()
        elif where == "name":
            names = model["features"]["names"]
            names[rng.randrange(len(names))] = nasty()
        elif where == "spec":
            model["features"]["spec"] = nasty()
        else:
            model["target"]["column"] = nasty()
    return model


def header_is_safe(header_path):
    """Whether a header compiles strictly and declares nothing a model's text injected."""
    cc = os.environ.get("CC", "cc")
    folder = os.path.dirname(header_path)
    strict = subprocess.run([cc, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic",
                             "-fsyntax-only", "-x", "c", header_path], capture_output=True)
    if strict.returncode != 0:
        return False, "the header does not compile: " + strict.stderr.decode(errors="replace")[:300]
    probe = os.path.join(folder, "probe.c")
    with open(probe, "w") as f:
        f.write(f'#include "{os.path.basename(header_path)}"\n'
                "int main(void) { return fogdrift_injected; }\n")
    used = subprocess.run([cc, "-std=c99", "-fsyntax-only", "-I", folder, probe],
                          capture_output=True)
    if used.returncode == 0:
        return False, "the header declares fogdrift_injected"
    return True, ""


def finite_text(text, c_source=False):
    """Whether a command's output holds no non-finite number."""
    return (NON_FINITE_C if c_source else NON_FINITE).search(text) is None


# The columns of a CSV that fogdrift reads as numbers or computes. A column it does not know is
# kept as the user wrote it (docs/formats.md), text and all, and is not checked.
FOGDRIFT_COLUMN = re.compile(
    r"^(time_s|gyro(_[a-z0-9_]+)?_dph|temp_[a-z0-9_]+_degc|accel_[a-z0-9_]+_g|table_deg|"
    r"chamber_degc|drift(_[a-z0-9_]+)?_dph|gyro(_[a-z0-9_]+)?_comp_dph|novelty(_[a-z0-9_]+)?|"
    r"guard_weight(_[a-z0-9_]+)?|fault_flags(_[a-z0-9_]+)?)$")


# The columns compensate and stream compute. stream echoes each input line as it came, a faulty
# reading included (its fault policy handles it), and appends these.
COMPUTED_COLUMN = re.compile(
    r"^(drift(_[a-z0-9_]+)?_dph|gyro(_[a-z0-9_]+)?_comp_dph|novelty(_[a-z0-9_]+)?|"
    r"guard_weight(_[a-z0-9_]+)?|fault_flags(_[a-z0-9_]+)?)$")


def finite_csv(text, computed_only=False):
    """Whether every column of a CSV that fogdrift reads or computes is finite."""
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return True
    pattern = COMPUTED_COLUMN if computed_only else FOGDRIFT_COLUMN
    owned = [k for k, h in enumerate(rows[0]) if pattern.match(h) and h != "drift_true_dph"]
    return all(finite_text(row[k]) for row in rows[1:] for k in owned if k < len(row))


def finite_outputs(path):
    """Whether every number in an output file (or every file of an output folder) is finite."""
    paths = [os.path.join(d, f) for d, _, fs in os.walk(path) for f in fs] \
        if os.path.isdir(path) else [path]
    for p in paths:
        with open(p, "rb") as f:
            text = f.read().decode("utf-8", errors="replace")
        ok = finite_csv(text) if p.endswith(".csv") else finite_text(text, p.endswith(".h"))
        if not ok:
            return False
    return True


class Campaign:
    def __init__(self, fd, out, seed):
        self.fd, self.out = fd, out
        self.rng = random.Random(seed)
        self.runs = self.findings = self.exit0 = self.exit1 = self.full_checks = 0
        self.inputs = 0
        os.makedirs(os.path.join(out, "findings"), exist_ok=True)

    def finding(self, why, argv, files):
        self.findings += 1
        where = os.path.join(self.out, "findings", f"{self.findings:03d}")
        os.makedirs(where, exist_ok=True)
        for f in files:
            if os.path.isdir(f):
                shutil.copytree(f, os.path.join(where, os.path.basename(f)), dirs_exist_ok=True)
            elif os.path.exists(f):
                shutil.copy(f, where)
        with open(os.path.join(where, "WHY.txt"), "w") as w:
            w.write(why + "\n" + " ".join(map(str, argv)) + "\n")
        print(f"FINDING {self.findings}: {why}: {' '.join(map(str, argv))}", file=sys.stderr)

    def run(self, argv, outputs, files, stdin=None):
        """Runs fogdrift with argv; `outputs` are the files it may write."""
        for o in outputs:
            if os.path.isdir(o):
                shutil.rmtree(o)
            elif os.path.exists(o):
                os.remove(o)
        self.runs += 1
        try:
            p = subprocess.run([self.fd] + argv, stdin=stdin, capture_output=True,
                               timeout=TIME_LIMIT_S)
        except subprocess.TimeoutExpired:
            self.finding(f"hang (over {TIME_LIMIT_S} s)", argv, files)
            return None
        err = p.stderr.decode("utf-8", errors="replace")
        leftovers = [n for o in outputs for n in os.listdir(os.path.dirname(o) or ".")
                     if n.startswith(".tmp-") or ".tmp-" in n]
        if leftovers:
            self.finding(f"temporary files left: {leftovers}", argv, files)
        if p.returncode < 0:
            self.finding(f"killed by signal {-p.returncode}", argv, files)
        elif p.returncode == 0:
            self.exit0 += 1
            for o in outputs:
                if os.path.exists(o) and not finite_outputs(o):
                    self.finding(f"exit 0 with a non-finite number in {o}", argv, files)
            stdout = p.stdout.decode("utf-8", errors="replace")
            if not (finite_csv(stdout, True) if argv[0] == "stream" else finite_text(stdout)):
                self.finding("exit 0 with a non-finite number on standard output", argv, files)
        elif p.returncode == 1:
            self.exit1 += 1
            if "fogdrift: error:" not in err:
                self.finding(f"exit 1 without fogdrift's message: {err[:200]!r}", argv, files)
            for o in outputs:
                if os.path.exists(o):
                    self.finding(f"exit 1 left an output: {o}", argv, files)
        else:
            self.finding(f"exit status {p.returncode}: {err[:200]!r}", argv, files)
        return p

    def full_disk(self, argv, files):
        """A run that exits 0 must fail when standard output cannot be written."""
        self.full_checks += 1
        with open("/dev/full", "wb") as full:
            p = subprocess.run([self.fd] + argv, stdout=full, stderr=subprocess.PIPE,
                               timeout=TIME_LIMIT_S)
        if p.returncode == 0:
            self.finding("exit 0 with standard output on a full device", argv, files)


def main():
    fd, n, seed = os.path.abspath(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
    scratch = len(sys.argv) <= 4  # a folder of its own, removed unless there are findings
    out = sys.argv[4] if not scratch else tempfile.mkdtemp(prefix="fogdrift_mutation_")
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    good = os.path.join(out, "good")
    shutil.rmtree(good, ignore_errors=True)
    os.makedirs(good)

    def fogdrift(*args):
        subprocess.run([fd] + list(map(str, args)), check=True, capture_output=True)

    fogdrift("simulate", "calibration", "--out", f"{good}/cal", "--temps", "-10,30",
             "--repetitions", "3", "--seed", str(seed))
    fogdrift("train", f"{good}/cal", "--method", "poly", "-o", f"{good}/model.json", "-q")
    subprocess.run([sys.executable, f"{root}/scripts/make_chamber_fixture.py", good], check=True)
    with open(f"{good}/imu3.csv") as f:  # an hour of the IMU is enough
        head = [next(f) for _ in range(3001)]
    with open(f"{good}/imu3.csv", "w") as f:
        f.writelines(head)
    fogdrift("import", f"{good}/imu3.csv", "-o", f"{good}/imu.csv", "--step-s", "60",
             "--map", "time_s=millis", "--unit", "time_s=ms", "--map", "gyro_dph=gx_dps",
             "--unit", "gyro_dph=deg/s", "--map", "temp_fog_degc=temp_raw",
             "--unit", "temp_fog_degc=int16:0.00390625:25", "-q")
    with open(f"{good}/instrument.json", "w") as f:
        f.write(subprocess.run([fd, "simulate", "--print-instrument"], check=True,
                               capture_output=True, text=True).stdout)
    recordings = sorted(r for r in os.listdir(f"{good}/cal") if r.endswith(".csv"))

    c = Campaign(fd, out, seed)
    work = os.path.join(out, "work")
    sheet_map = ["--partial", "--map", "time_s=Time", "--unit", "time_s=clock", "--time-zero",
                 "09:12:40", "--map", "chamber_degc=Air (C)", "--map",
                 "temp_acc1_degc=TC2 far side (F)", "--unit", "temp_acc1_degc=degF"]
    imu_map = ["--map", "time_s=millis", "--unit", "time_s=ms", "--map", "gyro_dph=gx_dps",
               "--unit", "gyro_dph=deg/s", "--map", "gyro_y_dph=gy_dps", "--unit",
               "gyro_y_dph=deg/s", "--map", "temp_fog_degc=temp_raw", "--unit",
               "temp_fog_degc=int16:0.00390625:25"]
    kinds = ["recording", "manifest", "model", "sheet", "imu", "instrument", "joined",
             "model_text"]
    if os.environ.get("FOGDRIFT_MUTATION_KINDS"):
        kinds = os.environ["FOGDRIFT_MUTATION_KINDS"].split(",")
    for i in range(n):
        shutil.rmtree(work, ignore_errors=True)
        shutil.copytree(good, work)
        kind = kinds[i % len(kinds)]
        c.inputs += 1
        w = lambda name: os.path.join(work, name)  # noqa: E731
        if kind == "model_text":
            target = w("model.json")
            with open(target) as f:
                model = json.load(f)
            with open(target, "w") as f:
                json.dump(inject_text(model, c.rng), f, indent=2)
            header = w("m.h")
            for extra in ([], ["--stream-rate-hz", "1"],
                          ["--stream-rate-hz", "1", "--precision", "float", "--force-float"]):
                argv = ["export-c", target, "--allow-edited", "-o", header] + extra
                p = c.run(argv, [header], [target])
                if p is not None and p.returncode == 0:
                    ok, why = header_is_safe(header)
                    if not ok:
                        c.finding(why, argv, [target, header])
            continue
        if kind == "recording":
            target = w(f"cal/{c.rng.choice(recordings)}")
        else:
            target = w({"manifest": "cal/campaign.json", "model": "model.json",
                        "sheet": "sheet.csv", "imu": "imu3.csv", "instrument": "instrument.json",
                        "joined": "imu.csv"}[kind])
        with open(target, "rb") as f:
            data = f.read()
        for _ in range(c.rng.choice([1, 1, 2, 3])):
            data = mutate(data, c.rng)
        with open(target, "wb") as f:
            f.write(data)
        files = [target]
        o = w("out.csv")
        plans = []
        if kind == "recording":
            plans = [(["inspect", target], []),
                     (["compensate", w("model.json"), target, "-o", o], [o]),
                     (["evaluate", w("model.json"), target, "--input-rate-dph", "0"], []),
                     (["stream", w("model.json"), target, "--rate-hz", "1"], [])]
        elif kind == "manifest":
            plans = [(["inspect", w("cal")], []),
                     (["train", w("cal"), "--method", "poly", "-o", w("m2.json"), "-q"],
                      [w("m2.json")]),
                     (["evaluate", w("model.json"), w("cal")], [])]
        elif kind == "model":
            rec = w(f"cal/{recordings[-1]}")
            plans = [(["compensate", target, rec, "-o", o], [o]),
                     (["export-c", target, "-o", w("m.h"), "--stream-rate-hz", "1"], [w("m.h")]),
                     (["stream", target, rec, "--rate-hz", "1"], [])]
        elif kind == "sheet":
            plans = [(["import", target, "-o", w("sheet_fd.csv")] + sheet_map,
                      [w("sheet_fd.csv")])]
        elif kind == "imu":
            plans = [(["import", target, "-o", w("imu2.csv"), "--step-s", "60", "--hampel"]
                      + imu_map, [w("imu2.csv")]),
                     (["inspect", target], [])]
        elif kind == "instrument":
            plans = [(["simulate", "calibration", "--out", w("sim"), "--instrument", target,
                       "--temps", "20", "--repetitions", "1"], [w("sim")])]
        else:  # a recording joined with a good sheet
            fogdrift("import", w("sheet.csv"), "-o", w("sheet_fd.csv"), *sheet_map, "-q")
            plans = [(["join", target, w("sheet_fd.csv"), "-o", o, "--offset-from",
                       "temp_fog_degc=temp_acc1_degc"], [o]),
                     (["join", w("sheet_fd.csv"), target, "-o", w("o2.csv"),
                       "--method", "nearest"], [w("o2.csv")])]
        for argv, outputs in plans:
            p = c.run(argv, outputs, files)
            # Standard output on a full device must fail too (a sample of the runs that print).
            if p is not None and p.returncode == 0 and p.stdout and c.rng.random() < 0.2:
                c.full_disk(argv, files)
        if (i + 1) % 50 == 0:
            print(f"{i + 1}/{n} inputs, {c.runs} runs, {c.findings} findings", file=sys.stderr)
    shutil.rmtree(work, ignore_errors=True)
    print(json.dumps({"inputs": c.inputs, "runs": c.runs, "exit_0": c.exit0, "exit_1": c.exit1,
                      "full_device_checks": c.full_checks, "findings": c.findings,
                      "out": out}))
    if scratch and not c.findings:
        shutil.rmtree(out, ignore_errors=True)
    return 1 if c.findings else 0


if __name__ == "__main__":
    sys.exit(main())
