"""What a submission may provide: exactly the exercise files named in points.json.

The grader copies those files, and nothing else, into the submission's own grade tree before
anything is compiled. Everything else in the folder (a catch2/ folder, a kit/ header, a test
file, a symbolic link) is ignored and listed in the report, so a student can shadow nothing of
the kit's, and the original folder is never touched again."""
import pathlib
import shutil

MAX_FILE_BYTES = 1 << 20


def exercise_files(points):
    """The file names a student edits, in points.json order, without repeats."""
    return list(dict.fromkeys(e["file"] for e in points["exercises"]))


def snapshot(folder, allowed, destination):
    """Makes `destination` hold exactly the allowed files of `folder`.
    Returns (copied names, missing names, ignored relative paths with the reason)."""
    folder, destination = pathlib.Path(folder), pathlib.Path(destination)
    destination.mkdir(parents=True, exist_ok=True)
    copied, missing, ignored = [], [], []
    for name in allowed:
        source, target = folder / name, destination / name
        if source.is_symlink():
            ignored.append((name, "a symbolic link: only regular files are graded"))
            missing.append(name)
        elif not source.is_file():
            missing.append(name)
        elif source.stat().st_size > MAX_FILE_BYTES:
            ignored.append((name, f"larger than {MAX_FILE_BYTES} bytes"))
            missing.append(name)
        else:
            content = source.read_bytes()
            # Rewritten only when it changed: a regrade then recompiles only what changed.
            if not target.is_file() or target.read_bytes() != content:
                target.write_bytes(content)
            copied.append(name)
    for stale in destination.iterdir():  # what the folder no longer provides
        if stale.name not in copied:
            if stale.is_dir() and not stale.is_symlink():
                shutil.rmtree(stale)
            else:
                stale.unlink()
    allowed_set = set(allowed)
    for path in sorted(folder.rglob("*")):
        rel = path.relative_to(folder).as_posix()
        if rel in allowed_set or path.is_dir() and not path.is_symlink():
            continue
        if rel.endswith(("README.md", ".gitignore")) or "/." in "/" + rel:
            continue  # the skeleton's own readme and hidden files: nothing to report
        ignored.append((rel, "not an exercise file of points.json"))
    return copied, missing, ignored
