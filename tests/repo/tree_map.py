#!/usr/bin/env python3
"""The README's map of the tree is the tree.

The map is the first fenced block of README.md's "## Architecture" section: one folder a line, a
line indented by two spaces naming a folder inside the last unindented one above it; deeper
indented lines continue a description. NN-name stands for each chapter's folder (01-free-fall).
Checks:
  - every folder the map names exists;
  - every folder that holds a tracked file is in the map (a layer folder of common/include/kit/
    counts as named by its common/src/ twin);
  - common/include/kit/ and common/src/ have the same layer folders;
  - no folder holds more than MAX_FILES tracked files (the kit's root aside);
  - each layer of common/ includes (#include <kit/LAYER/...>) only the layers MAY_INCLUDE gives it,
    as README.md's "Layers inside common/" says.

Usage: tree_map.py [KIT_ROOT]   exit 0 when all hold, 1 with each problem otherwise.
"""
import collections
import pathlib
import re
import subprocess
import sys

MAX_FILES = 35
# What each layer of common/ may include besides itself: the layers below it, and what those may.
BELOW = {"base": [], "app": ["base"], "ode": ["app"], "problems": ["ode"], "render": ["app"],
         "sprites": ["render"], "cloth": ["render"], "rigid": ["ode", "render"], "fem": ["cloth"]}


def may_include(layer):
    allowed = set()
    for lower in BELOW.get(layer, []):
        allowed |= {lower} | may_include(lower)
    return allowed


def map_folders(readme):
    section = readme.split("\n## Architecture\n", 1)
    if len(section) < 2 or "```\n" not in section[1]:
        return None
    block = section[1].split("```\n", 2)[1]
    folders, parent = [], ""
    for line in block.splitlines():
        indent = len(line) - len(line.lstrip(" "))
        name = line.split()[0] if line.strip() else ""
        if indent == 0 and name:
            parent = name if name.endswith("/") else ""
            if name.endswith("/"):
                folders.append(name.rstrip("/"))
        elif indent == 2 and name.endswith("/"):
            folders.append((parent + name).rstrip("/"))
    return folders


def tracked_folders(root):
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=root, capture_output=True, check=True).stdout.decode()
    counts = collections.Counter(str(pathlib.PurePosixPath(f).parent) for f in listed.split("\0") if f)
    return counts


def main(argv):
    root = pathlib.Path(argv[1] if len(argv) > 1 else pathlib.Path(__file__).resolve().parents[2])
    problems = []
    folders = map_folders((root / "README.md").read_text(encoding="utf-8"))
    if not folders:
        print("FAILED: README.md has no map of the tree (a fenced block under ## Architecture)")
        return 1
    counts = tracked_folders(root)
    patterns = [re.compile(re.escape(f).replace("NN\\-name", r"\d\d-[a-z0-9-]+") + "$") for f in folders]
    existing = {str(p.relative_to(root)) for p in root.rglob("*") if p.is_dir() and ".git" not in p.parts}
    problems += [f"the map names {f}/, which does not exist" for f, pattern in zip(folders, patterns)
                 if not any(pattern.match(e) for e in existing)]
    include, src = root / "common/include/kit", root / "common/src"
    layers = {p.name for p in include.iterdir() if p.is_dir()} if include.is_dir() else set()
    sources = {p.name for p in src.iterdir() if p.is_dir()} if src.is_dir() else set()
    problems += [f"common/include/kit/{n}/ has no twin common/src/{n}/" for n in sorted(layers - sources)]
    problems += [f"common/src/{n}/ has no twin common/include/kit/{n}/" for n in sorted(sources - layers)]
    for folder, count in sorted(counts.items()):
        if folder == ".":
            continue
        twin = re.sub(r"^common/include/kit/(\w+)$", r"common/src/\1", folder)
        if not any(pattern.match(folder) or pattern.match(twin) for pattern in patterns):
            problems.append(f"{folder}/ holds tracked files and is not in the map")
        if count > MAX_FILES:
            problems.append(f"{folder}/ holds {count} files, more than {MAX_FILES}")
    for layer in sorted(layers | sources):
        if layer not in BELOW:
            problems.append(f"common's layer {layer}/ has no place in tree_map.py's BELOW")
            continue
        for folder in (include / layer, src / layer):
            for path in sorted(folder.glob("*.?pp")):
                for other in re.findall(r"^\s*#\s*include\s*<kit/(\w+)/", path.read_text(encoding="utf-8"), re.M):
                    if other != layer and other not in may_include(layer):
                        problems.append(f"{path.relative_to(root)} ({layer}/) includes the layer {other}/, above it")
    for problem in sorted(set(problems)):
        print("FAILED:", problem)
    if not problems:
        print(f"the map names {len(folders)} folders; every tracked folder is there, none over {MAX_FILES} files")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
