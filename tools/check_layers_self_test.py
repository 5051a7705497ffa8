"""The self-test of tools/check_layers.py (`check_layers.py --self-test`): the checker CAN fail.

It copies the tree's CMakeLists.txt files and library sources to a temporary folder, removes the
includes the checker reports there (so that the copy passes: the checker can also pass), then
adds one bad include or changes one link at a time (undone after each) and requires exactly the
violations that change makes, no more and no fewer; a harmless change must add none. One case
runs the script itself, for its exit codes and its output line.
"""
import pathlib
import shutil
import subprocess
import sys
import tempfile

import check_layers as layers


def copy_tree(root, destination):
    """The CMake files, the README and the library folders' C++ files of `root`, copied under
    `destination`, and the other folders of the README's layout table, empty."""
    files = list(layers.cmake_files(root)) + [root / "README.md"]
    for folder in layers.LIBRARY_FOLDERS:
        files += layers.folder_sources(root, folder)
    for path in files:
        target = destination / path.relative_to(root)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(path, target)
    for folder in layers.layout_rows(root / "README.md"):  # the folders the README lists
        (destination / folder).mkdir(parents=True, exist_ok=True)


def strip_includes(root, violations):
    """Removes from the files at `root` the include lines the violations name."""
    for violation in violations:
        if violation.header == "-":
            continue
        path = root / violation.file
        lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
        kept = [l for l in lines if not (layers.INCLUDE.match(l) and f'"{violation.header}"' in l)]
        path.write_text("".join(kept), encoding="utf-8")


class Copy:
    """The clean copy, changed one case at a time: undo() puts back every file changed."""

    def __init__(self, root):
        self.root, self.originals = root, {}

    def text(self, file):
        text = (self.root / file).read_text(encoding="utf-8")
        self.originals.setdefault(file, text)
        return text

    def write(self, file, text):
        (self.root / file).write_text(text, encoding="utf-8")

    def append_line(self, file, line):
        self.write(file, self.text(file) + line + "\n")

    def add_include(self, file, header):
        self.append_line(file, f'#include "{header}"')

    def edit(self, file, old, new):
        text = self.text(file)
        if old not in text:
            raise AssertionError(f"{file} has no {old!r} to change (the self-test needs updating)")
        self.write(file, text.replace(old, new, 1))

    def undo(self):
        for file, text in self.originals.items():
            self.write(file, text)
        self.originals = {}


def first_source(root, folder):
    return layers.folder_sources(root, folder)[0].relative_to(root).as_posix()


def bad_include_cases(clean):
    """(name, change of a copy, expected new violations as (file, header, words of the why))."""
    fluid, synthesis = first_source(clean, "sim/fluid"), first_source(clean, "acoustics/synthesis")
    return [
        ("an upstream folder includes a downstream one (sim/fluid -> sim/bubbles)",
         lambda c: c.add_include(fluid, "sim/bubbles/bubble_model.h"),
         [(fluid, "sim/bubbles/bubble_model.h", "does not link sim/bubbles")]),
        ("acoustics includes the solver, which it does not link",
         lambda c: c.add_include(synthesis, "sim/fluid/grid.h"),
         [(synthesis, "sim/fluid/grid.h", "does not link sim/fluid")]),
        ("io includes a solver header that is not a record",
         lambda c: c.add_include("io/scene_file.h", "sim/fluid/pressure_solver.h"),
         [("io/scene_file.h", "sim/fluid/pressure_solver.h", "record headers")]),
        ("an include of a header that does not exist",
         lambda c: c.add_include(fluid, "sim/fluid/no_such_header.h"),
         [(fluid, "sim/fluid/no_such_header.h", "no such header")]),
        ("io includes a record header (allowed)",
         lambda c: c.add_include("io/audio_file.h", "sim/scene.h"), []),
        ("an include through PUBLIC links (acoustics/analysis -> acoustics/bubble, allowed)",
         lambda c: c.add_include(first_source(c.root, "acoustics/analysis"),
                               "acoustics/bubble/minnaert.h"),
         []),
    ]


def link_cases(clean):
    """Changes of the CMake files: the table is read from them, not written in the checker."""
    bubbles_fluid = {(s.relative_to(clean).as_posix(), h) for s in
                     layers.folder_sources(clean, "sim/bubbles")
                     for h in layers.project_includes(clean, s) if h.startswith("sim/fluid/")}
    solver_users = sorted(
        (s.relative_to(clean).as_posix(), h, "does not link " + h.rsplit("/", 1)[0])
        for folder in ("io", "tools") for s in layers.folder_sources(clean, folder)
        for h in layers.project_includes(clean, s) if h.startswith(("sim/fluid/", "sim/bubbles/", "sim/bodies/")))
    return [
        ("sim links its parts PRIVATE: io's and tools' includes of them are reported",
         lambda c: c.edit("sim/CMakeLists.txt", "fluidsound_sim PUBLIC", "fluidsound_sim PRIVATE"),
         solver_users),
        ("sim/bubbles no longer links sim_fluid: each of its sim/fluid includes is reported",
         lambda c: c.edit("sim/bubbles/CMakeLists.txt",
                        "PUBLIC fluidsound::sim_fluid", "PUBLIC fluidsound::core"),
         [(f, h, "does not link sim/fluid") for f, h in sorted(bubbles_fluid)]),
        ("the README's layout table names another target for sim/fluid",
         lambda c: c.edit("README.md", "`fluidsound::sim_fluid`", "`fluidsound::sim`"),
         [("README.md", "-", "target of sim/fluid/")]),
        ("a link from core back to acoustics makes a cycle",
         lambda c: c.append_line("sim/core/CMakeLists.txt",
                               "target_link_libraries(fluidsound_core INTERFACE "
                               "fluidsound::acoustics_bubble)"),
         [("sim/core/CMakeLists.txt", "-", "cycle"),
          ("acoustics/bubble/CMakeLists.txt", "-", "cycle")]),
    ]


def expect(name, found, baseline, expected):
    """Compares the new violations with the expected ones; prints the outcome; True if equal."""
    new = [v for v in found if v not in baseline]
    expected = sorted(expected)
    matched = len(new) == len(expected) and all(
        v.file == f and v.header == h and words in v.why for v, (f, h, words) in zip(new, expected))
    print(("ok:   " if matched else "FAIL: ") + name)
    if not matched:
        print("  expected: " + "; ".join(f"{f}: includes {h}: ...{w}..." for f, h, w in expected))
        print("  found:    " + "; ".join(v.line() for v in new))
    return matched


def exit_codes(script, clean):
    """The script run as a program: 0 on the clean copy; 1 and the line on one bad include."""
    runs = []
    for bad in (False, True):
        if bad:
            clean.add_include("io/scene_file.h", "sim/fluid/pressure_solver.h")
        runs.append(subprocess.run([sys.executable, str(script), "--root", str(clean.root)],
                                   capture_output=True, text=True))
    clean.undo()
    line = ("io/scene_file.h: includes sim/fluid/pressure_solver.h: io/ may include of sim/ and "
            "acoustics/ only record headers (tools/check_layers.py --records): this is not one")
    matched = runs[0].returncode == 0 and runs[1].returncode == 1 and \
        runs[1].stdout.splitlines()[0] == line
    outcome = "ok:   " if matched else "FAIL: "
    print(outcome + "exit 0 on the clean copy; 1 and the line on a bad one")
    if not matched:
        print(f"  exit codes {runs[0].returncode}, {runs[1].returncode}; output:\n{runs[1].stdout}")
    return matched


def run(root):
    """0 if the checker finds every planted violation and nothing else, else 1."""
    with tempfile.TemporaryDirectory(prefix="check_layers_") as scratch:
        scratch = pathlib.Path(scratch)
        clean = scratch / "clean"
        copy_tree(root, clean)
        faithful = layers.check(clean) == layers.check(root)
        print(("ok:   " if faithful else "FAIL: ") + "the copy has the tree's violations")
        strip_includes(clean, layers.check(clean))
        baseline = layers.check(clean)
        passes = expect("the copy without the reported includes passes", baseline, [], [])
        results = [faithful, passes]
        copy = Copy(clean)
        for name, change, expected in bad_include_cases(clean) + link_cases(clean):
            change(copy)
            results.append(expect(name, layers.check(clean), baseline, expected))
            copy.undo()
        results.append(exit_codes(pathlib.Path(layers.__file__).resolve(), copy))
    failed = results.count(False)
    print(f"{len(results) - failed} of {len(results)} self-test cases pass")
    return 1 if failed else 0
