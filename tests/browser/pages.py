#!/usr/bin/env python3
"""Every 3D page the chapters wrote, opened in headless Chromium (software WebGL): the page says
nothing on the console, draws every pane at the first and the last frame, its scene moves between
them, the scene's colours are in the view, and the frame and the readouts it shows agree with the
chapter's own data for that frame (its counts, its summary, its OBJ meshes).

The pages are those the suite's figures.NN runs wrote (FIGURES_DIR/NN-name/, listed in each
summary under "pages"); the screenshots are kept in WORK_DIR for a person to look at.

Usage: pages.py FIGURES_DIR WORK_DIR PNG_PROBE
"""
import concurrent.futures
import html.parser
import json
import os
import pathlib
import shutil
import subprocess
import sys

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--force-device-scale-factor=1", "--window-size=1280,800", "--virtual-time-budget=15000",
                  "--disable-gpu-sandbox", "--no-first-run", "--disable-extensions"]
# What each chapter's scene shows in the middle of its first pane (png_probe's classes: red, blue,
# green, bright), the least share of the view it takes, and at which frame: the cloth's colour, the
# bodies' blue, the sprites' light points on the dark sky, chapter 9's strain colours (at the last
# frame: at the first the plate is at rest, all at the colour map's dark end).
COLOURS = {"05-sprites": ("bright", 0.0002, "first"), "06-cloth-explicit": ("red", 0.02, "first"),
           "07-cloth-implicit": ("red", 0.02, "first"), "08-rigid-bodies": ("blue", 0.005, "first"),
           "09-continuum": ("green", 0.02, "last")}
# The least share of a pane that differs from its background: the first frame of a particle
# system is a few hundred pixels.
DRAWN = 0.0001
THREE_D_CHAPTERS = sorted(COLOURS)


SKIPPED = 77  # ctest's SKIP_RETURN_CODE for this test


def chromium():
    """Debian's chromium, or None (Ubuntu has it only as a snap, which a container cannot run)."""
    found = shutil.which("chromium")
    if found and "snap" not in pathlib.Path(found).resolve().parts:
        return found
    return None


class PageDom(html.parser.HTMLParser):
    """What a page shows: its ready mark, frame, time, readouts and where its canvases lie."""

    def __init__(self):
        super().__init__()
        self.ready, self.frame, self.time = None, None, None
        self.readouts, self.rects = {}, []
        self._into = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "body":
            self.ready = a.get("data-kit-ready")
        if tag == "canvas" and a.get("data-kit-rect"):
            self.rects.append([int(v) for v in a["data-kit-rect"].split(",")])
        if tag == "output":
            if a.get("id") in ("kit-frame", "kit-time"):
                self._into = a["id"]
            elif "kit-readout" in (a.get("class") or "").split():
                self._into = (int(a["data-pane"]), a["data-name"])

    def handle_data(self, data):
        if self._into == "kit-frame":
            self.frame = int(data)
        elif self._into == "kit-time":
            self.time = float(data)
        elif self._into is not None:
            self.readouts[self._into] = None if data in ("", "null") else float(data)
        self._into = None


def open_page(page, frame, screenshot, browser):
    """One Chromium run at `frame`: its DOM, its console lines, and its screenshot."""
    url = page.resolve().as_uri() + f"#frame={frame}"
    done = subprocess.run([browser, *CHROMIUM_FLAGS, "--enable-logging=stderr", "--v=0", f"--screenshot={screenshot}",
                           "--dump-dom", url], capture_output=True, text=True, timeout=180)
    if done.returncode != 0 or not screenshot.is_file():
        raise AssertionError(f"{page}: no screenshot at frame {frame}: {done.stderr.strip()[-300:]}")
    console = [line for line in done.stderr.splitlines() if "CONSOLE" in line]
    dom = PageDom()
    dom.feed(done.stdout)
    return dom, console


def probe(png_probe, png, rect, other=None):
    x, y, w, h = rect
    args = [str(png_probe), str(png), str(x), str(y), str(w), str(h)] + ([str(other)] if other else [])
    return json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)


def middle(rect):
    """The middle half of a rectangle, each way."""
    x, y, w, h = rect
    return [x + w // 4, y + h // 4, w // 2, h // 2]


def obj_mean_y(path):
    ys = [float(line.split()[2]) for line in path.read_text().splitlines() if line.startswith("v ")]
    return sum(ys) / len(ys)


def counts_series(dat, wanted):
    """The (x, y) rows of the series named `wanted` in a figure's .dat file."""
    rows, inside = {}, False
    for line in dat.read_text().splitlines():
        if line.startswith("# index"):
            inside = line.split(":", 1)[1].strip().startswith(wanted)
        elif inside and line and not line.startswith("#"):
            x, y = line.split()[:2]
            rows[int(float(x))] = float(y)
    return rows


def close(a, b, rel=1e-9):
    return a is not None and b is not None and abs(a - b) <= rel * max(1.0, abs(b))


def chapter_data_checks(chapter, name, folder, summary, first, last, frames):
    """The page against what the chapter itself wrote: a list of problems."""
    problems = []
    if chapter == "05-sprites":
        alive = counts_series(folder / "counts.dat", "alive")
        warmup = summary["scene"]["warmup_frames"]
        for k, dom in ((0, first), (frames - 1, last)):
            if not close(dom.readouts.get((0, "alive")), alive.get(warmup + k)):
                problems.append(f"frame {k}: alive {dom.readouts.get((0, 'alive'))} where counts.dat has {alive.get(warmup + k)}")
    elif chapter == "06-cloth-explicit" and name == "cloth-stability":
        if last.readouts.get((1, "energy E")) is None or frames <= 2:
            problems.append("the pane above the stable step shows no energy at its last frame")
    elif chapter == "06-cloth-explicit":
        chosen = summary["scene"]["integrator"]
        run = next(r for r in summary["integrators"] if r["integrator"] == chosen)
        if not close(last.readouts.get((0, "E − E(0)")), run["energy_change"]):
            problems.append(f"last frame: E − E(0) {last.readouts.get((0, 'E − E(0)'))}, the summary's {chosen} run {run['energy_change']}")
    elif chapter == "07-cloth-implicit":
        if not close(last.readouts.get((0, "E − E(0)")), summary["run"]["energy"]):
            problems.append(f"last frame: E − E(0) {last.readouts.get((0, 'E − E(0)'))}, the summary's run {summary['run']['energy']}")
    elif chapter == "08-rigid-bodies" and name == "drop":
        for k, dom in ((0, first), (frames - 1, last)):
            mesh = obj_mean_y(folder / "drop_meshes" / f"drop_{k:04d}.obj")
            if not close(dom.readouts.get((0, "centre height")), mesh, 1e-7):
                problems.append(f"frame {k}: centre height {dom.readouts.get((0, 'centre height'))}, drop_{k:04d}.obj's {mesh}")
    elif chapter == "08-rigid-bodies":
        meshes = len(list((folder / f"{name}_meshes").glob("*.obj")))
        if meshes != frames:
            problems.append(f"{frames} frames in the page, {meshes} OBJ meshes of the run")
    elif chapter == "09-continuum":
        meshes = len(list((folder / "plate_meshes").glob("plate-*.obj")))
        if meshes != frames:
            problems.append(f"{frames} frames in the page, {meshes} OBJ meshes of the plate")
    return problems


def check_page(chapter, name, entry, folder, summary, work, png_probe, browser):
    page = pathlib.Path(entry["path"])
    frames = entry["frames"]
    shots = {k: work / f"{chapter}-{name}-{k}.png" for k in (0, frames - 1)}
    first, console_first = open_page(page, 0, shots[0], browser)
    last, console_last = open_page(page, "last", shots[frames - 1], browser)
    problems = [f"console: {line.strip()[:200]}" for line in console_first + console_last]
    for k, dom in ((0, first), (frames - 1, last)):
        if dom.ready != str(k) or dom.frame != k:
            problems.append(f"frame {k}: ready {dom.ready!r}, shown frame {dom.frame}")
    if not first.rects:
        return problems + ["no canvas drawn"]
    moved = 0.0
    for pane, rect in enumerate(first.rects):
        a = probe(png_probe, shots[0], rect)
        b = probe(png_probe, shots[frames - 1], rect, shots[0])
        for k, p in ((0, a), (frames - 1, b)):
            if p["not_background"] < DRAWN:
                problems.append(f"pane {pane} blank at frame {k} ({p['not_background']:.4f} of it drawn)")
        moved = max(moved, b["differs"])
    if moved < 0.005:
        problems.append(f"the first and the last frame look the same ({moved:.4f} of the view differs)")
    colour, share, when = COLOURS[chapter]
    at = 0 if when == "first" else frames - 1
    seen = probe(png_probe, shots[at], middle(first.rects[0]))[colour]
    if seen < share:
        problems.append(f"frame {at}: {seen:.4f} of the view's middle is {colour}, expected at least {share}")
    problems += chapter_data_checks(chapter, name, folder, summary, first, last, frames)
    print(f"{chapter}/{page.name}: {entry['bytes'] / 1e6:.1f} MB, {frames} frames, {len(first.rects)} panes, "
          f"{colour} {seen:.3f}, moved {moved:.3f}: {'ok' if not problems else 'FAILED'}")
    return [f"{chapter}/{page.name}: {p}" for p in problems]


# The page sizes the chapter READMEs print, as they print them: (chapter, page) → the README's
# words. A page's size is checked to the digits printed, browser or not.
README_SIZES = {("05-sprites", "sprites"): "3.8 MB for the", ("06-cloth-explicit", "cloth"): "1.5 MB for the flag",
                ("07-cloth-implicit", "cloth"): "(1.4 MB)"}


def readme_size_problems(figures):
    problems = []
    root = pathlib.Path(__file__).resolve().parents[2]
    for (chapter, page), words in README_SIZES.items():
        readme = " ".join((root / "chapters" / chapter / "README.md").read_text().split())
        if words not in readme:
            problems.append(f"{chapter}/README.md no longer says {words!r}: update README_SIZES")
            continue
        printed = words.strip("(").split()[0]
        half_unit = 0.5 * 10 ** -(len(printed.split(".")[1]) if "." in printed else 0)
        summary = json.loads((figures / f"{chapter}.summary.json").read_text())
        megabytes = summary.get("pages", {}).get(page, {}).get("bytes", 0) / 1e6
        if abs(megabytes - float(printed)) > half_unit:
            problems.append(f"{chapter}: {page}.html is {megabytes:.3f} MB; its README says {printed} MB")
    return problems


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    figures, work, png_probe = pathlib.Path(argv[1]), pathlib.Path(argv[2]), pathlib.Path(argv[3])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    sizes = readme_size_problems(figures)
    browser = chromium()
    if browser is None and sizes:
        print("\n".join("FAILED: " + problem for problem in sizes))
        return 1
    if browser is None:
        print("SKIPPED: no chromium here (./kit deps --for test installs Debian's package chromium; "
              "Ubuntu has Chromium only as a snap)")
        return SKIPPED
    jobs, problems = [], list(sizes)
    for chapter in THREE_D_CHAPTERS:
        summary = json.loads((figures / f"{chapter}.summary.json").read_text())
        pages = summary.get("pages", {})
        if not pages:
            problems.append(f"{chapter}: its run wrote no 3D page")
        for name, entry in sorted(pages.items()):
            jobs.append((chapter, name, entry, figures / chapter, summary))
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, min(2, os.cpu_count() or 1))) as pool:
        for found in pool.map(lambda j: check_page(*j, work, png_probe, browser), jobs):
            problems += found
    for problem in problems:
        print("FAILED:", problem)
    print(f"{len(jobs)} pages; screenshots in {work}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
