"""The chapter binaries of a build folder, one for every chapters/NN-name/main.cpp of the kit."""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def chapter_binaries(bin_dir):
    """The binaries in `bin_dir`, sorted. Unless they are exactly the kit's chapters the test fails
    here (exit 1), so that a test over every chapter cannot pass by finding none."""
    binaries = sorted(p for p in pathlib.Path(bin_dir).iterdir() if p.is_file() and p.name[:2].isdigit())
    chapters = sorted(d.name for d in (ROOT / "chapters").glob("[0-9][0-9]-*") if (d / "main.cpp").exists())
    if [b.name for b in binaries] != chapters:
        sys.exit(f"FAILED: {bin_dir} holds {[b.name for b in binaries]}, not every chapter: {chapters}")
    return binaries
