#!/usr/bin/python3
"""Checks that the sources' includes follow the CMake link graph (issue 18; docs/architecture.md).

Every `#include "..."` of the C++ files of a library folder (LIBRARY_FOLDERS; a folder's own
files only, not its subfolders') must name a header of a folder whose library the folder's
target links, directly or through a dependency's PUBLIC/INTERFACE links. The table is not written
here a second time: it is read from every CMakeLists.txt (fluidsound_add_library, add_library,
add_executable, target_link_libraries). On top of that, io/ converts files <-> records and nothing
else, so of sim/ and acoustics/ it may include only the record headers of IO_RECORD_HEADERS.

It prints one line per violation, `FILE: includes HEADER: WHY`, and exits 1 if there is any
(0 if none). An include of a header that does not exist, or of a folder that is no library's,
is a violation too, and so is a cycle in the link graph, and a README "Layout" table that misses a
library folder or names another target for it than CMake builds from it.

usage: tools/check_layers.py [--root DIR] [--graph] [--records] [--self-test]
  --root DIR   the source tree (default: the one this script is in)
  --graph      first print per folder: its C++ files, the folders it includes, its CMake links
  --records    first print the record headers io/ may include, each with its reason
  --self-test  check the checker on temporary copies of the tree with one bad include (or
               link) added; exits 1 if it misses one or reports one that is not there
"""
import argparse
import dataclasses
import pathlib
import re
import sys

# The folders whose sources are checked, upstream first: each is one CMake target's sources.
LIBRARY_FOLDERS = ("sim/core", "sim/fluid", "sim/bubbles", "sim/bodies", "sim", "acoustics/bubble",
                   "acoustics/transfer", "acoustics/synthesis", "acoustics/analysis",
                   "acoustics/binaural", "acoustics/modal", "acoustics/playback", "io", "tools")
# The top-level folders a project include starts with (anything else is a system header).
PROJECT_TOP = ("sim", "acoustics", "io", "tools", "tests")
CXX_SUFFIXES = (".h", ".hpp", ".cpp", ".cc", ".inl")
# What io/ may include of sim/ and acoustics/: the records it reads from or writes to files.
IO_RECORD_HEADERS = {
    "sim/core/vec3.h": "a point in space [m], part of every record below",
    "sim/scene.h": "the scene record that fluidsound.scene/1 is parsed into",
    "sim/fluid/fluid_scene.h": "the solver's part of the scene record (domain, liquid, solids)",
    "sim/fluid/triangle_mesh.h": "the mesh record an OBJ or PLY file is read into",
    "sim/bubbles/bubble_settings.h": "the scene's `bubbles` block as a record",
    "sim/bubbles/bubble_history.h": "the bubble model's output, written as bubbles.json",
    "sim/fluid/grid.h": "the frames' grid (GridGeometry), written as the VDB transform",
    "sim/fluid/array3.h": "the dense grid array the frame velocity is made of",
    "sim/fluid/mac_velocity.h": "a frame's velocity, written as frames/NNNN.vdb's `velocity`",
    "sim/fluid/particles.h": "a frame's particles, written as frames/NNNN.ply",
    "acoustics/bubble/bubble_track.h": "the bubble tracks of fluidsound.bubbles/1",
    "sim/fluid/solid_rotation.h": "what a solid record's `rotate` means: io places mesh solids by it",
    "acoustics/transfer/level_set_frames.h": "the frames' level sets as the transfer stage reads them: io implements it for frames/NNNN.vdb",
    "acoustics/transfer/geometric_transfer.h": "the limit of the scene's transfer.max_bands (kMaxTransferBands), checked as the block is read",
    "acoustics/analysis/spectrogram_power.h": "the pooled spectrogram record that spectrogram.png draws",
    "acoustics/binaural/hrir_table.h": "a head's impulse responses as a SOFA file holds them",
    "sim/liquid_frame.h": "a liquid cache's frame as the bubble model reads it: io fills it from OpenVDB files",
    "sim/cache_bubbles.h": "the frames of a liquid cache as the bubble model reads them: io implements its LiquidFrameSource",
    "acoustics/modal/modal_analysis.h": "a body's modal model, cached on disk as KEY.modes",
    "acoustics/modal/voxel_solid.h": "the surface faces a modal model holds (part of the cached record)",
    "acoustics/modal/solid_material.h": "the named materials a scene body's `material` names, checked as `bodies` is read",
    "sim/core/solid_material.h": "a body's material constants, part of the scene record",
    "sim/core/contact_record.h": "the rigid-body stage's contact log, written and read as contacts.bin",
    "sim/core/quaternion.h": "a body's orientation, part of every contact record in contacts.bin",
}
INCLUDE = re.compile(r'^\s*#\s*include\s*(?:"([^"]+)"|<([^>]+)>)')
LINK_KEYWORDS = {"PUBLIC", "PRIVATE", "INTERFACE", "LINK_PUBLIC", "LINK_PRIVATE",
                 "LINK_INTERFACE_LIBRARIES"}
EXPORTED = ("PUBLIC", "INTERFACE", "LINK_PUBLIC", "LINK_INTERFACE_LIBRARIES")


@dataclasses.dataclass(frozen=True, order=True)
class Violation:
    file: str  # repository-relative, e.g. io/scene_file.cpp
    header: str  # as included; "-" for a link-graph fault
    why: str

    def line(self):
        if self.header == "-":
            return f"{self.file}: {self.why}"
        return f"{self.file}: includes {self.header}: {self.why}"


@dataclasses.dataclass
class Target:
    name: str
    folder: str  # the folder of the CMakeLists.txt that defines it
    kind: str  # STATIC, INTERFACE, EXECUTABLE, ...
    links: list = dataclasses.field(default_factory=list)  # [(keyword, item)] in file order


def cmake_commands(text):
    """[(command name lower-case, [arguments])] of a CMake file, comments and quotes removed."""
    commands, i = [], 0
    text = re.sub(r"#\[(=*)\[.*?\]\1\]", " ", text, flags=re.S)  # bracket comments
    text = re.sub(r'#[^\n]*|("(?:[^"\\]|\\.)*")', lambda m: m.group(1) or " ", text)
    for match in re.finditer(r"\b([A-Za-z_][A-Za-z0-9_]*)\s*\(", text):
        if match.start() < i:
            continue  # inside the previous command's arguments
        depth, j = 1, match.end()
        while j < len(text) and depth:
            depth += {"(": 1, ")": -1}.get(text[j], 0)
            j += 1
        args = [a.strip('"') for a in re.findall(r'"[^"]*"|[^\s()]+', text[match.end():j - 1])]
        commands.append((match.group(1).lower(), args))
        i = j
    return commands


def cmake_files(root):
    """Every CMakeLists.txt of the tree, outside build folders and hidden folders."""
    found = []
    for path in sorted(root.rglob("CMakeLists.txt")):
        parts = path.relative_to(root).parts[:-1]
        if any(p.startswith((".", "build")) for p in parts):
            continue
        if any((root.joinpath(*parts[:k]) / "CMakeCache.txt").exists()
               for k in range(1, len(parts) + 1)):
            continue  # a build folder of another name
        found.append(path)
    return found


def read_targets(root):
    """({target name: Target}, {alias: target name}) of the project's own fluidsound* targets."""
    targets, aliases, links = {}, {}, []
    for path in cmake_files(root):
        folder = path.parent.relative_to(root).as_posix()
        folder = "" if folder == "." else folder
        for command, args in cmake_commands(path.read_text(encoding="utf-8")):
            if command == "fluidsound_add_library" and args:
                targets[f"fluidsound_{args[0]}"] = Target(f"fluidsound_{args[0]}", folder, "STATIC")
                aliases[f"fluidsound::{args[0]}"] = f"fluidsound_{args[0]}"
            elif command == "add_library" and len(args) >= 3 and args[1] == "ALIAS":
                aliases[args[0]] = args[2]
            elif command in ("add_library", "add_executable") and args:
                kind = "EXECUTABLE" if command == "add_executable" else \
                    (args[1] if len(args) > 1 and args[1].isupper() else "STATIC")
                targets[args[0]] = Target(args[0], folder, kind)
            elif command == "target_link_libraries" and args:
                links.append(args)
    for args in links:  # after all definitions: a target may be linked before it is defined
        if args[0] in targets:
            keyword = "PUBLIC"  # the plain signature's links are transitive
            for item in args[1:]:
                if item in LINK_KEYWORDS:
                    keyword = item
                else:
                    targets[args[0]].links.append((keyword, item))
    own = {n: t for n, t in targets.items() if n.startswith("fluidsound") and "$" not in n}
    return own, aliases


class LinkGraph:
    """The folders each library folder may include, from the CMake targets."""

    def __init__(self, root):
        self.targets, self.aliases = read_targets(root)
        self.allowed_ = {}

    def resolve(self, item):
        name = self.aliases.get(item, item)
        return name if name in self.targets else None

    def folder_target(self, folder):
        """The target built from `folder`'s sources (an INTERFACE one if it has no other)."""
        here = [t for t in self.targets.values() if t.folder == folder]
        built = [t for t in here if t.kind != "INTERFACE"]
        return (built or here or [None])[0]

    def exported(self, name, seen=()):
        """Folders of `name` and of everything it passes on (PUBLIC/INTERFACE), recursively."""
        if name in seen:
            return set()
        target = self.targets[name]
        folders = {target.folder}
        for keyword, item in target.links:
            dependency = self.resolve(item)
            if dependency and (keyword in EXPORTED or target.kind == "INTERFACE"):
                folders |= self.exported(dependency, seen + (name,))
        return folders

    def allowed(self, folder):
        """Folders whose headers `folder`'s sources may include: its own and all it links."""
        if folder not in self.allowed_:
            self.allowed_[folder] = self.linked_folders(folder)
        return self.allowed_[folder]

    def linked_folders(self, folder):
        target = self.folder_target(folder)
        if target is None:
            return {folder}
        folders = {folder}
        for _, item in target.links:
            dependency = self.resolve(item)
            if dependency:
                folders |= self.exported(dependency)
        return folders

    def cycles(self):
        """Violations for every own target that reaches itself through its links."""
        found = []
        for name in sorted(self.targets):
            stack, seen = [name], set()
            while stack:
                for _, item in self.targets[stack.pop()].links:
                    dependency = self.resolve(item)
                    if dependency == name:
                        found.append(Violation(f"{self.targets[name].folder}/CMakeLists.txt", "-",
                                               f"{name} links itself through its links (a cycle)"))
                        stack = []
                        break
                    if dependency and dependency not in seen:
                        seen.add(dependency)
                        stack.append(dependency)
        return found


def header_folder(header):
    """The library folder that owns a repository-relative header path, or None."""
    folder = header.rsplit("/", 1)[0] if "/" in header else ""
    return folder if folder in LIBRARY_FOLDERS else None


def folder_sources(root, folder):
    """The C++ files directly in `folder` (not its subfolders), sorted."""
    return sorted(p for p in (root / folder).glob("*") if p.is_file() and p.suffix in CXX_SUFFIXES)


def project_includes(root, path):
    """The repository-relative paths of a file's project includes, in file order: a quoted
    include whose first folder is not a top-level one is relative to the including file."""
    found = []
    for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
        match = INCLUDE.match(line)
        if not match:
            continue
        text = match.group(1) or match.group(2)
        if text.split("/", 1)[0] in PROJECT_TOP:
            found.append(text)
        elif match.group(1):
            beside = (path.parent / text).resolve()
            try:
                found.append(beside.relative_to(root).as_posix())
            except ValueError:
                found.append(text)  # outside the tree: check_include says it does not exist
    return found


def check_include(root, graph, folder, source, header):
    """The violation of one include in `folder`, or None."""
    owner = header_folder(header)
    target = graph.folder_target(folder)
    if not (root / header).is_file():
        return Violation(source, header, "no such header in the tree")
    if owner is None:
        return Violation(source, header, "not a header of a library folder ("
                         + ", ".join(LIBRARY_FOLDERS) + ")")
    if owner not in graph.allowed(folder):
        theirs = graph.folder_target(owner)
        return Violation(source, header, f"{folder} ({target.name if target else 'no target'}) "
                         f"does not link {owner} ({theirs.name if theirs else 'no target'})")
    if folder == "io" and owner.split("/")[0] in ("sim", "acoustics") \
            and header not in IO_RECORD_HEADERS:
        return Violation(source, header, "io/ may include of sim/ and acoustics/ only record "
                         "headers (tools/check_layers.py --records): this is not one")
    return None


def layout_rows(readme):
    """{folder: target column} of the README's "Layout" table (folders without their "/")."""
    rows, inside = {}, False
    for line in readme.read_text(encoding="utf-8").splitlines():
        if line.startswith("## "):
            inside = line.strip() == "## Layout"
        cells = [c.strip() for c in line.strip().strip("|").split("|")] if inside else []
        if len(cells) >= 3 and re.fullmatch(r"`[^`]+`", cells[0]):
            rows[cells[0].strip("`").rstrip("/")] = cells[-1]
    return rows


def layout_violations(root, graph):
    """The README's layout table must list every library folder with the target CMake builds."""
    readme = root / "README.md"
    if not readme.is_file():
        return []
    rows, found = layout_rows(readme), []
    for folder in LIBRARY_FOLDERS:
        target = graph.folder_target(folder)
        names = [a for a, t in graph.aliases.items() if target and t == target.name]
        names = names or ([target.name] if target else [])
        if folder not in rows:
            found.append(Violation("README.md", "-", f"the Layout table has no row for {folder}/"))
        elif names and not any(f"`{n}`" in rows[folder] for n in names):
            found.append(Violation("README.md", "-", f"the Layout table's target of {folder}/ is "
                                   f"not `{names[0]}`, which CMake builds from it"))
    for folder in rows:
        if not (root / folder).is_dir():
            found.append(Violation("README.md", "-",
                                   f"the Layout table lists {folder}/, which is not in the tree"))
    return found


def check(root):
    """Every violation of the tree at `root`, sorted."""
    graph = LinkGraph(root)
    violations = graph.cycles() + layout_violations(root, graph)
    for folder in LIBRARY_FOLDERS:
        if graph.folder_target(folder) is None:
            violations.append(Violation(f"{folder}/", "-", "no CMake target is built from it"))
        for path in folder_sources(root, folder):
            source = path.relative_to(root).as_posix()
            for header in project_includes(root, path):
                violation = check_include(root, graph, folder, source, header)
                if violation:
                    violations.append(violation)
    return sorted(set(violations))


def graph_listing(root):
    """Per library folder: files, included folders (with include counts), direct CMake links."""
    graph = LinkGraph(root)
    lines = ["per folder: its C++ files, the target built from them, the other folders its files "
             "include (include lines), its direct CMake links"]
    for folder in LIBRARY_FOLDERS:
        files = folder_sources(root, folder)
        counts = {}
        for path in files:
            for header in project_includes(root, path):
                owner = header_folder(header) or header.rsplit("/", 1)[0]
                if owner != folder:
                    counts[owner] = counts.get(owner, 0) + 1
        target = graph.folder_target(folder)
        links = " ".join(item for _, item in target.links) if target and target.links else "-"
        lines.append(f"{folder}/  {len(files)} files  target {target.name if target else '-'}")
        lines.append("  includes: " + (", ".join(f"{f} ({n})" for f, n in sorted(counts.items()))
                                       or "only itself"))
        lines.append(f"  links:    {links}")
    return lines


def record_listing():
    lines = ["io/ may include of sim/ and acoustics/ only these record headers:"]
    width = max(len(h) for h in IO_RECORD_HEADERS)
    return lines + [f"  {h.ljust(width)}  {why}" for h, why in IO_RECORD_HEADERS.items()]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--root", type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parent.parent)
    parser.add_argument("--graph", action="store_true")
    parser.add_argument("--records", action="store_true")
    parser.add_argument("--self-test", action="store_true")
    args = parser.parse_args(argv)
    root = args.root.resolve()
    if args.self_test:
        sys.dont_write_bytecode = True  # no __pycache__ in the source tree
        import check_layers_self_test  # tools/check_layers_self_test.py, beside this file
        return check_layers_self_test.run(root)
    if args.graph:
        print("\n".join(graph_listing(root)) + "\n")
    if args.records or args.graph:
        print("\n".join(record_listing()) + "\n")
    violations = check(root)
    for violation in violations:
        print(violation.line())
    print(f"{len(violations)} violation(s) of the layers in {len(LIBRARY_FOLDERS)} folders")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
