#!/usr/bin/python3
"""Searches for inputs that make `fluidsound` exit 5 (internal error), hang or die by a signal.

Every numeric, string and array leaf of a small valid scene and a small valid bubble-track file
is replaced in turn by each of a list of awkward values (zero, negatives, the largest and the
smallest doubles, non-integers where integers belong, huge integers, wrong types); every key is
also removed once and an unknown key added once. Each variant is run through the command that
reads it (`run` for scenes, `synth` for bubble files), and a list of bad command-line values is
run through every subcommand's options. A finding is an exit code of 5, a death by a signal, a
run over the time limit, or an error message of more than one line. Exit status: 1 if anything
was found, else 0; the last line counts the runs ("N passed, M failed").

--quick (the ctest `Probe.BadInputsFindNothing`, label `probe`, a budget of 3 min on a loaded
2-core machine) runs fewer awkward values, a fixed sample of the document variants (every
QUICK_SCENE_STEP-th scene variant and QUICK_BUBBLES_STEP-th bubble variant, always the same ones)
and fewer option values, plus every input a past full run found (QUICK_REGRESSIONS), so each
finding fixed stays in the quick set.

usage: probe_bad_inputs.py FLUIDSOUND [--quick] [--verbose]
Standard library only (the brief: Debian's /usr/bin/python3).
"""
import copy
import json
import os
import subprocess
import sys
import tempfile

AWKWARD_NUMBERS = [0, -1, 0.5, 1e308, -1e308, 5e-324, 1e-300, 44100.5, 18446744073709551615,
                   18446744073709551616, 1e19, 7.0]
AWKWARD_OTHERS = ["x", "", None, True, [], {}, [1, 2], [0, 0, 0, 0]]
QUICK_NUMBERS = [0, -1, 0.5, 1e308, 5e-324, 18446744073709551616]
QUICK_OTHERS = ["x", None, []]
QUICK_SCENE_STEP = 2
QUICK_BUBBLES_STEP = 2
# Every (document, JSON path, value) a full run has found (exit 5, a signal or over the time
# limit), run in every quick run whether or not the sample above holds it.
QUICK_REGRESSIONS = [
    ("scene", "time.fps", 44100.5),                      # 4410 frames of 0.1 s: over 60 s
    ("scene", "emitters[0].disk.center[1]", 1e308),      # particles at y = inf: SIGSEGV
    ("scene", "emitters[0].disk.radius", 44100.5),       # 10^15 particles drawn: over 60 s
    ("scene", "emitters[0].disk.radius", 7.0),           # 3·10^7 particles: over 60 s
]

# A scene small enough that an accepted variant simulates in well under a second.
BASE_SCENE = {
    "format": "fluidsound.scene/1",
    "domain": {"min": [0, 0, 0], "max": [0.04, 0.04, 0.04], "cell": 0.01, "open": ["+y"]},
    "gravity": [0, -9.81, 0],
    "time": {"duration": 0.1, "fps": 30, "cfl": 1.0},
    "seed": 1,
    "liquid": [{"box": {"min": [0, 0, 0], "max": [0.04, 0.02, 0.04]}, "velocity": [0, 0, 0]}],
    "emitters": [{"disk": {"center": [0.02, 0.035, 0.02], "normal": [0, -1, 0], "radius": 0.005},
                  "speed": 0.5, "start": 0.0, "end": 0.05}],
    "solids": [{"sphere": {"center": [0.02, 0.01, 0.02], "radius": 0.005}},
               {"box": {"min": [0, 0, 0], "max": [0.01, 0.01, 0.01]},
                "path": [{"t": 0.0, "translate": [0, 0, 0]}, {"t": 0.1, "translate": [0.01, 0, 0]}]}],
    "listeners": [{"name": "left", "position": [0.0, 0.3, 0.02]},
                  {"name": "right", "position": [0.04, 0.3, 0.02]}],
    "audio": {"sample_rate": 48000},
}

BASE_BUBBLES = {
    "format": "fluidsound.bubbles/1",
    "sample_rate": 48000,
    "duration": 0.2,
    "listeners": ["left", "right"],
    "bubbles": [
        {"radius": 0.001, "birth": 0.01,
         "track": [{"t": 0.01, "depth": 0.03, "transfer": [1.0, 0.8], "position": [0, 0, 0]},
                   {"t": 0.05, "depth": 0.02, "transfer": [0.9, 0.7], "position": [0, 0.01, 0]}]},
        {"radius": 0.002, "birth": 0.02, "amplitude": 0.01},
    ],
}

# (subcommand, option, values) for every numeric or enumerated option documented in docs/cli.md.
OPTION_VALUES = ["0", "-1", "0.5", "1e308", "5e-324", "nan", "inf", "x", "", "18446744073709551616"]
# nan was the value of every option finding (synth --normalize, spectrogram --range, validate --rate).
QUICK_OPTION_VALUES = ["-1", "1e308", "nan", "inf", "x"]
SYNTH_OPTIONS = ["--rate", "--bits", "--normalize", "--loudness", "--duration", "--format", "--threads",
                 "--chirp-rise", "--displacement", "--damping", "--excitation"]
SPECTROGRAM_OPTIONS = ["--window", "--hop", "--range", "--width", "--height", "--channel",
                       "--min-frequency", "--threads"]
VALIDATE_OPTIONS = ["--rate", "--chirp-rise", "--displacement", "--damping", "--excitation"]
SIMULATE_OPTIONS = ["--frames", "--cell", "--threads"]


class Probe:
    def __init__(self, executable, work, verbose, timeout):
        self.executable = executable
        self.work = work
        self.verbose = verbose
        self.timeout = timeout
        self.runs = 0
        self.findings = []

    def run(self, label, arguments):
        self.runs += 1
        try:
            done = subprocess.run([self.executable] + arguments, stdin=subprocess.DEVNULL,
                                  stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                  timeout=self.timeout, cwd=self.work)
        except subprocess.TimeoutExpired:
            self.findings.append(f"{label}: still running after {self.timeout} s")
            return
        err = done.stderr.decode("utf-8", "replace")
        error_lines = [line for line in err.splitlines() if "error" in line]
        if done.returncode < 0:
            self.findings.append(f"{label}: killed by signal {-done.returncode}: {err.strip()[-300:]}")
        elif done.returncode == 5:
            self.findings.append(f"{label}: exit 5: {err.strip()[-300:]}")
        elif len(error_lines) > 1:
            self.findings.append(f"{label}: {len(error_lines)} error lines: {err.strip()[-300:]}")
        elif self.verbose:
            print(f"{label}: exit {done.returncode}: {err.strip()[-160:]}")


def leaves(value, path=""):
    """Every (json_path, value) pair below `value`, containers included."""
    yield path, value
    if isinstance(value, dict):
        for key, item in value.items():
            yield from leaves(item, f"{path}.{key}" if path else key)
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from leaves(item, f"{path}[{index}]")


def replaced(document, path, new_value, remove=False):
    """A copy of `document` with the value at `path` replaced (or its key removed)."""
    copy_ = copy.deepcopy(document)
    parts = []
    for piece in path.replace("]", "").replace("[", ".").split("."):
        parts.append(int(piece) if piece.isdigit() else piece)
    parent = copy_
    for part in parts[:-1]:
        parent = parent[part]
    if remove:
        del parent[parts[-1]]
    else:
        parent[parts[-1]] = new_value
    return copy_


def variants(document, numbers, others):
    for path, value in leaves(document):
        if not path:
            continue
        if isinstance(value, dict):
            yield f"{path}: unknown key", replaced(document, path, dict(value, unknown_key=1))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            for awkward in numbers + others:
                yield f"{path} = {json.dumps(awkward)}", replaced(document, path, awkward)
        else:
            for awkward in numbers[:2] + others:
                yield f"{path} = {json.dumps(awkward)}", replaced(document, path, awkward)
        if not path.endswith("]"):
            yield f"{path}: removed", replaced(document, path, None, remove=True)


def run_scene(probe, label, scene):
    path = os.path.join(probe.work, "probe.scene.json")
    with open(path, "w") as out:
        json.dump(scene, out)
    probe.run("scene " + label, ["run", path, "-o", os.path.join(probe.work, "out"), "--quiet",
                                 "--threads", "1"])


def run_bubbles(probe, label, bubbles):
    path = os.path.join(probe.work, "probe.bubbles.json")
    with open(path, "w") as out:
        json.dump(bubbles, out)
    probe.run("bubbles " + label, ["synth", path, "-o", os.path.join(probe.work, "probe.wav"), "--quiet"])


def probe_documents(probe, numbers, others, quick):
    """Every variant of both documents (with --quick: a fixed sample, and the regressions)."""
    scene_step, bubbles_step = (QUICK_SCENE_STEP, QUICK_BUBBLES_STEP) if quick else (1, 1)
    for index, (label, scene) in enumerate(variants(BASE_SCENE, numbers, others)):
        if index % scene_step == 0:
            run_scene(probe, label, scene)
    for index, (label, bubbles) in enumerate(variants(BASE_BUBBLES, numbers, others)):
        if index % bubbles_step == 0:
            run_bubbles(probe, label, bubbles)
    if not quick:
        return
    for document, path, value in QUICK_REGRESSIONS:
        label = f"{path} = {json.dumps(value)}"
        if document == "scene":
            run_scene(probe, label, replaced(BASE_SCENE, path, value))
        else:
            run_bubbles(probe, label, replaced(BASE_BUBBLES, path, value))


def probe_options(probe, values):
    bubbles = os.path.join(probe.work, "base.bubbles.json")
    with open(bubbles, "w") as out:
        json.dump(BASE_BUBBLES, out)
    scene = os.path.join(probe.work, "base.scene.json")
    with open(scene, "w") as out:
        json.dump(BASE_SCENE, out)
    wav = os.path.join(probe.work, "base.wav")
    probe.run("synth base", ["synth", bubbles, "-o", wav, "--quiet"])
    for option in SYNTH_OPTIONS:
        for value in values:
            probe.run(f"synth {option} {value!r}",
                      ["synth", bubbles, "-o", os.path.join(probe.work, "o.wav"), "--quiet", option, value])
    for value in values:  # --true-peak needs --loudness
        probe.run(f"synth --loudness -23 --true-peak {value!r}",
                  ["synth", bubbles, "-o", os.path.join(probe.work, "o.wav"), "--quiet", "--loudness", "-23",
                   "--true-peak", value])
    for option in SPECTROGRAM_OPTIONS:
        for value in values:
            probe.run(f"spectrogram {option} {value!r}",
                      ["spectrogram", wav, "-o", os.path.join(probe.work, "o.png"), "--quiet", option, value])
    for option in VALIDATE_OPTIONS:
        for value in [v for v in values if v in OPTION_VALUES[:6]]:
            probe.run(f"validate {option} {value!r}", ["validate", "--quiet", option, value])
    for option in SIMULATE_OPTIONS:
        for value in values + ["3:1", "0:999", "-1:2", "1:"]:
            probe.run(f"simulate {option} {value!r}",
                      ["simulate", scene, "-o", os.path.join(probe.work, "sim"), "--quiet", option, value])
    for name in ["synth", "spectrogram", "simulate", "transfer", "run"]:
        probe.run(f"{name} missing input", [name, os.path.join(probe.work, "missing.json"), "-o",
                                            os.path.join(probe.work, "m.out")])
        probe.run(f"{name} folder as input", [name, probe.work, "-o", os.path.join(probe.work, "m.out")])


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    executable = os.path.abspath(sys.argv[1])
    quick = "--quick" in sys.argv
    verbose = "--verbose" in sys.argv
    with tempfile.TemporaryDirectory(prefix="fluidsound-probe-") as work:
        probe = Probe(executable, work, verbose, timeout=60)
        numbers, others = (QUICK_NUMBERS, QUICK_OTHERS) if quick else (AWKWARD_NUMBERS, AWKWARD_OTHERS)
        probe_documents(probe, numbers, others, quick)
        probe_options(probe, QUICK_OPTION_VALUES if quick else OPTION_VALUES)
    for finding in probe.findings:
        print("FINDING " + finding)
    print(f"probe: {probe.runs} runs of {executable}")
    print(f"{probe.runs - len(probe.findings)} passed, {len(probe.findings)} failed")
    return 1 if probe.findings else 0


if __name__ == "__main__":
    sys.exit(main())
