"""`make bench`: how fast the book builds and how light its pages are, in one run.

1. Copies the repository to a temporary folder (edits never touch the work tree) and
   times, with the Makefile's strict build command:
   a cold full build, a no-op rebuild, a rebuild after editing the text of one page,
   and a rebuild after editing one figure module, physics_figures/figures/collisions.py,
   which only the collision pages draw from (reported as ratios to the cold build, with
   the pages each rebuild executed).
2. Builds a default one-page Jupyter Book 1 project in another temporary folder and
   measures, in headless Chromium with gzip as a static host serves it, the bytes
   its page transfers and the bytes of every page of our site (as ratios to it).
   It times marking one answer, and the class page loading 30 students' progress files.
3. Runs Lighthouse (mobile, offline against localhost) on every page of our site.
4. Writes BENCHMARKS.md with the machine and the date.

Usage: .venv/bin/python scripts/bench.py [--no-lighthouse] [--builds-only]
"""

from __future__ import annotations

import argparse
import ast
import asyncio
import datetime
import gzip
import json
import os
import platform
import random
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
from bench_make_test import carry_over, replace_section
from browser import (
    FIRST_VISIT_REQUESTS,
    FIRST_VISIT_SHARE,
    LIGHTHOUSE_RUNS,
    QUESTION_DATA_BYTES,
    PageVisitor,
    chromium_path,
    lighthouse_runs,
    median_scores,
    node_module,
    open_browser_async,
    progress_checksum,
    serve_site,
    site_pages,
)

from physics_figures.reproducible import source_date_epoch

VENV_BIN = ROOT / ".venv" / "bin"
ENV = {
    **os.environ,
    "SOURCE_DATE_EPOCH": str(source_date_epoch()),
    "FORCE_SOURCE_DATE": "1",
    "PYTHONHASHSEED": "0",
}
SKIP = {".venv", "_build", ".git", "node_modules", ".pytest_cache", ".hypothesis", ".ruff_cache", "__pycache__"}


def build(project: Path, *, env: dict[str, str]) -> tuple[float, str]:
    """Run the strict build in `project`; (seconds, log). Fails loudly on a build error."""
    command = [str(VENV_BIN / "jupyter-book"), "build", ".", "-n", "-W", "--keep-going"]
    start = time.perf_counter()
    result = subprocess.run(command, cwd=project, env=env, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    if result.returncode != 0:
        raise SystemExit(f"build failed in {project}:\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}")
    return seconds, result.stdout + result.stderr


def executed_pages(log: str, project: Path) -> list[str]:
    """The pages (paths relative to `project`) that the build's log says it executed."""
    found = re.findall(r"(\S+?\.(?:md|ipynb)): Executing notebook", log)
    return sorted({Path(path).resolve().relative_to(project.resolve()).as_posix() for path in found})


def copy_project(target: Path) -> Path:
    def ignore(folder, names):
        return [name for name in names if name in SKIP]

    shutil.copytree(ROOT, target, ignore=ignore, symlinks=True)
    (target / "node_modules").symlink_to(ROOT / "node_modules")
    return target


def edit_text_of_a_page(project: Path) -> str:
    """Add a sentence to an executed page (one with code cells), as an author would."""
    pages = sorted(p for p in (project / "book").rglob("*.md") if "kernelspec:" in p.read_text())
    page = pages[0]
    page.write_text(page.read_text() + "\nThis sentence was added by the benchmark.\n")
    return page.relative_to(project).as_posix()


#: The one figure module the benchmark edits: only the collision pages draw from it.
EDITED_FIGURE_MODULE = "physics_figures/figures/collisions.py"


def edit_a_figure_function(project: Path) -> str:
    """Change the docstring of a function of EDITED_FIGURE_MODULE, as a maintainer would."""
    source = project / EDITED_FIGURE_MODULE
    tree = ast.parse(source.read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef) and ast.get_docstring(node):
            lines = source.read_text().splitlines(keepends=True)
            first = node.body[0].lineno - 1  # the docstring's first line
            lines[first] = lines[first].replace('"""', '"""(benchmark edit) ', 1)
            source.write_text("".join(lines))
            return f"{EDITED_FIGURE_MODULE} ({node.name})"
    raise SystemExit(f"no documented function in {EDITED_FIGURE_MODULE} to edit")


DEFAULT_PAGE = """\
# A default page

Jupyter Book's defaults: this page has a paragraph, a formula $E = mc^2$ and a list.

- one
- two
"""


def default_book(folder: Path) -> Path:
    """A default one-page Jupyter Book 1 project, built with Jupyter Book's defaults."""
    folder.mkdir(parents=True)
    (folder / "_config.yml").write_text("title: Default\nauthor: Benchmark\n")
    (folder / "_toc.yml").write_text("format: jb-book\nroot: intro\n")
    (folder / "intro.md").write_text(DEFAULT_PAGE)
    result = subprocess.run(
        [str(VENV_BIN / "jupyter-book"), "build", "."], cwd=folder, env=ENV, capture_output=True, text=True,
        check=False,
    )
    if result.returncode != 0:
        raise SystemExit(f"the default book failed to build:\n{result.stdout[-2000:]}")
    return folder / "_build" / "html"


async def page_bytes(site: Path, pages: list[str]) -> dict[str, dict]:
    """Bytes (gzip) each page transfers on a first visit in Chromium: a fresh browser context per
    page (nothing cached from another page), service workers blocked, other hosts blocked. Also
    the question data each page carries (inline, and the variant files New numbers may load)."""
    results = {}
    with serve_site(site) as base:
        async with open_browser_async() as browser:
            for path in pages:
                context = await browser.new_context(viewport={"width": 390, "height": 844},
                                                    service_workers="block")
                await context.route(re.compile(r"^(?!http://127\.0\.0\.1:)"), lambda route: route.abort())
                visitor = PageVisitor(await context.new_page())
                load = await visitor.visit(f"{base}/{path}", scroll=True)
                inline = await visitor.page.evaluate(
                    "[...document.querySelectorAll('script.q-data')].map(s => s.textContent).join('')")
                keys = await visitor.page.evaluate(
                    "[...document.querySelectorAll('form.q-form[data-question]')].map(f => f.dataset.question)")
                variants = b"".join((site / "_static" / "questions" / f"{key}.js").read_bytes()
                                    for key in keys if (site / "_static" / "questions" / f"{key}.js").exists())
                results[path] = {
                    "bytes": load.total_bytes,
                    "requests": len(load.requests),
                    "foreign": sorted(set(load.foreign)),
                    "question_data": len(gzip.compress(inline.encode(), mtime=0)) if inline else 0,
                    "variant_data": len(gzip.compress(variants, mtime=0)) if variants else 0,
                }
                await context.close()
    return results


async def marking_time(site: Path, page: str = "book/exam/quick-check.html", runs: int = 2000) -> float:
    """Milliseconds Chromium takes to mark one answer (every part of a question, ecf included),
    averaged over many runs of the page's own marking engine."""
    with serve_site(site) as base:
        async with open_browser_async() as browser:
            context = await browser.new_context()
            tab = await context.new_page()
            await tab.goto(f"{base}/{page}", wait_until="load")
            ms = await tab.evaluate("""(runs) => {
                const data = JSON.parse(document.querySelector('script.q-data').textContent);
                const answers = {};
                data.parts.forEach(p => { answers[p.id] = {value: '1.7', unit: 'N s'}; });
                const start = performance.now();
                for (let i = 0; i < runs; i++) QuestionMarking.markQuestion(data, answers);
                return (performance.now() - start) / runs;
            }""", runs)
            await context.close()
    return ms


TEXT_ANSWERS = Path(__file__).resolve().parents[1] / "tests" / "fixtures" / "text_answers.json"
TEXT_RUNS = 25


async def text_marking_times(site: Path) -> dict:
    """Text marking in Chromium: each typed answer of tests/fixtures/text_answers.json marked
    (the whole question, as Check marks it) by its page's own engine, TEXT_RUNS times; an
    answer's time is the median of its runs (a run the busy machine interrupts is not the
    marker's), and the budget's figure is the 95th percentile over the answers, at full speed
    and with the CPU slowed 4x (CDP Emulation.setCPUThrottlingRate)."""
    answers = json.loads(TEXT_ANSWERS.read_text())["answers"]
    by_key: dict[str, list[str]] = {}
    for row in answers:
        by_key.setdefault(row["template"], []).append(row["answer"])
    pages = {key: next(p for p in site_pages(site) if f'data-question="{key}"' in (site / p).read_text())
             for key in by_key}
    out = {"answers": len(answers)}
    with serve_site(site) as base:
        async with open_browser_async() as browser:
            for label, rate in (("p95_ms", 1), ("p95_ms_cpu_4x", 4)):
                times = []
                for key, texts in by_key.items():
                    context = await browser.new_context()
                    tab = await context.new_page()
                    await tab.goto(f"{base}/{pages[key]}", wait_until="load")
                    cdp = await context.new_cdp_session(tab)
                    await cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
                    times += await tab.evaluate("""([key, texts, runs]) => {
                        const form = document.querySelector(`form[data-question="${key}"]`);
                        const data = JSON.parse(form.closest('section').querySelector('script.q-data').textContent);
                        return texts.map(text => {
                            const each = [];
                            for (let i = 0; i < runs; i++) {
                                const start = performance.now();
                                QuestionMarking.markQuestion(data, {[data.parts[0].id]: {text: text, ticked: []}});
                                each.push(performance.now() - start);
                            }
                            each.sort((a, b) => a - b);
                            return each[Math.floor(runs / 2)];
                        });
                    }""", [key, texts, TEXT_RUNS])
                    await context.close()
                times.sort()
                out[label] = times[min(len(times) - 1, int(0.95 * len(times)))]
    return out


async def question_marking_times(site: Path, runs: int = 25) -> dict:
    """Marking in Chromium over every question the site's pages ask: each question marked
    whole (every part, ecf included; a wrong number typed in each numeric part, so the marker
    tries every named mistake, alternative and slip before it gives up) by its page's own
    engine, ``runs`` times; a question's time is the median of its runs, and the budget's
    figure the 95th percentile over the questions, at full speed and with the CPU slowed 4x."""
    pages = [page for page in site_pages(site) if "q-data" in (site / page).read_text(encoding="utf-8")]
    out = {"pages": len(pages)}
    with serve_site(site) as base:
        async with open_browser_async() as browser:
            for label, rate in (("p95_ms", 1), ("p95_ms_cpu_4x", 4)):
                times = []
                for page in pages:
                    context = await browser.new_context()
                    tab = await context.new_page()
                    await tab.goto(f"{base}/{page}", wait_until="load")
                    cdp = await context.new_cdp_session(tab)
                    await cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
                    times += await tab.evaluate("""(runs) => [...document.querySelectorAll('script.q-data')]
                        .map(script => JSON.parse(script.textContent)).map(data => {
                            const answers = {};
                            data.parts.forEach(p => { answers[p.id] = {value: '1.7', unit: 'N', text: 'x'}; });
                            const each = [];
                            for (let i = 0; i < runs; i++) {
                                const start = performance.now();
                                QuestionMarking.markQuestion(data, answers);
                                each.push(performance.now() - start);
                            }
                            each.sort((a, b) => a - b);
                            return each[Math.floor(runs / 2)];
                        })""", runs)
                    await context.close()
                times.sort()
                out["questions"] = len(times)
                out[label] = times[min(len(times) - 1, int(0.95 * len(times)))]
    return out


CLASS_PAGE = "book/teachers-class.html"
CLASS_FILES, TERM_ATTEMPTS, CLASS_RUNS = 30, 300, 3
CLASS_LOAD_GOAL_MS = 2000


def term_of_practice(data: dict, student: int) -> str:
    """One student's export after a term: TERM_ATTEMPTS attempts at the bank's questions (of the
    page's data), a day apart in fours, with the bank's named mistakes on most wrong answers."""
    from physics_figures import bank

    names = sorted({m.name for t in bank.TEMPLATES.values() for p in t.variant(0).parts
                    for m in getattr(p, "mistakes", ())})
    templates = [(kind["type"], t) for kind in data["types"] for t in kind["templates"]]
    pick = random.Random(student)
    attempts = []
    for n in range(TERM_ATTEMPTS):
        kind, template = pick.choice(templates)
        earned = pick.randint(0, template["marks"])
        mistakes = [pick.choice(names)] if earned < template["marks"] and pick.random() < 0.7 else []
        attempts.append({"question": template["key"], "type": kind, "variant": pick.randrange(10), "earned": earned,
                         "available": template["marks"], "at": 1767225600000 + n * 21_600_000, "mistakes": mistakes})
    export = {"version": 1, "book": data["book"], "sha256": progress_checksum(attempts), "attempts": attempts}
    return json.dumps(export, indent=1, ensure_ascii=False)


async def class_page_load_time(site: Path) -> float:
    """Milliseconds from dropping CLASS_FILES students' exports on the class page to its tables
    laid out (every file read, checked against its checksum, summed and shown): the median of
    CLASS_RUNS, each on a freshly loaded page (never the best: a slow run counts as often as it
    happens)."""
    times = []
    with serve_site(site) as base:
        async with open_browser_async() as browser:
            context = await browser.new_context()
            tab = await context.new_page()
            for _ in range(CLASS_RUNS):
                await tab.goto(f"{base}/{CLASS_PAGE}", wait_until="load")
                data = json.loads(await tab.locator("script.cp-data").text_content())
                files = [[f"student-{n + 1:02d}.json", term_of_practice(data, n)] for n in range(CLASS_FILES)]
                ms = await tab.evaluate("""async (files) => {
                    const box = document.querySelector('.cp');
                    const before = Number(box.getAttribute('data-loads'));
                    const shown = new Promise((resolve) => new MutationObserver((_, watch) => {
                        if (Number(box.getAttribute('data-loads')) > before) { watch.disconnect(); resolve(); }
                    }).observe(box, {attributes: true, attributeFilter: ['data-loads']}));
                    const dropped = new DataTransfer();
                    files.forEach(([name, text]) => dropped.items.add(new File([text], name, {type: 'application/json'})));
                    const start = performance.now();
                    box.querySelector('.cp-drop').dispatchEvent(
                        new DragEvent('drop', {dataTransfer: dropped, bubbles: true, cancelable: true}));
                    await shown;
                    document.body.getBoundingClientRect();  // laid out, not just written
                    return performance.now() - start;
                }""", files)
                shown = await tab.locator(".cp-table tbody tr").count()
                if shown != CLASS_FILES:
                    raise SystemExit(f"the class page showed {shown} students of {CLASS_FILES} files")
                times.append(ms)
            await context.close()
    return statistics.median(times)


LIGHTHOUSE_GOAL = {"performance": 0.97, "accessibility": 1.0, "best-practices": 1.0, "seo": 1.0}


def _lighthouse_run(site: Path, pages: list[str]) -> dict[str, dict]:
    """One Lighthouse run over `pages` (one Chrome, one page after another)."""
    with serve_site(site) as base:
        return dict(zip(pages, lighthouse_runs([f"{base}/{page}" for page in pages]), strict=True))


def lighthouse_scores(site: Path, pages: list[str]) -> dict[str, dict]:
    """Each page's median of LIGHTHOUSE_RUNS runs, category by category (CLARIFICATIONS, House:
    as Lighthouse CI aggregates them): every page runs every time, whatever it scored."""
    runs = [_lighthouse_run(site, pages) for _ in range(LIGHTHOUSE_RUNS)]
    return {page: median_scores([run[page] for run in runs]) for page in pages}


def machine() -> str:
    cpu = "unknown CPU"
    cpuinfo = Path("/proc/cpuinfo")
    if cpuinfo.exists():
        found = re.search(r"model name\s*:\s*(.+)", cpuinfo.read_text())
        cpu = found[1].strip() if found else cpu
    memory = ""
    meminfo = Path("/proc/meminfo")
    if meminfo.exists():
        kb = int(re.search(r"MemTotal:\s+(\d+)", meminfo.read_text())[1])
        memory = f", {kb / 1024**2:.0f} GiB RAM"
    chromium = subprocess.run(
        [chromium_path(whole_browser=True), "--version"], capture_output=True, text=True, check=False
    ).stdout.strip()
    return f"{platform.platform()}, {os.cpu_count()} cores ({cpu}){memory}; Python {platform.python_version()}; {chromium}"


def parse_args() -> argparse.Namespace:
    """The command line: skip Lighthouse, or time the builds only, and where the report goes."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-lighthouse", action="store_true", help="skip Lighthouse (faster)")
    parser.add_argument("--builds-only", action="store_true",
                        help="time the builds and rewrite only BENCHMARKS.md's build times")
    parser.add_argument("--output", default=str(ROOT / "BENCHMARKS.md"))
    return parser.parse_args()


def noop_after_latex(project: Path, env: dict) -> tuple[float, str]:
    """`make html` right after `make latex`, as after `make test` (whose `make pdf` runs the same
    LaTeX build first): the LaTeX build has its own doctrees, so this HTML build has nothing to
    read again. Both go through the Makefile, with this repository's venv and node tools, which
    make must not install again (-o: taken as up to date), least of all into this repository's venv."""
    venv = ROOT / ".venv"
    make = ["make", "--no-print-directory", f"VENV={venv}", "-o", f"{venv}/.installed",
            "-o", "node_modules/.package-lock.json"]
    print(">>> the LaTeX build (make latex), then make html", flush=True)
    latex = subprocess.run([*make, "latex"], cwd=project, env=env, capture_output=True, text=True, check=False)
    if latex.returncode != 0:
        raise SystemExit(f"make latex failed in {project}:\n{latex.stdout[-3000:]}\n{latex.stderr[-3000:]}")
    start = time.perf_counter()
    html = subprocess.run([*make, "html"], cwd=project, env=env, capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    if html.returncode != 0:
        raise SystemExit(f"make html failed in {project}:\n{html.stdout[-3000:]}\n{html.stderr[-3000:]}")
    return seconds, html.stdout + html.stderr


def time_builds(project: Path, env: dict) -> tuple[dict, dict, str, str]:
    """The builds of the copy (cold, no-op, `make html` after the LaTeX build, after a page's text
    edit, after a figure function's edit): their seconds, the pages each executed, and what was edited."""
    timings = {}
    print(">>> cold build (empty cache)", flush=True)
    timings["cold"], log = build(project, env=env)
    cold_executed = executed_pages(log, project)
    print(">>> no-op rebuild", flush=True)
    timings["noop"], log = build(project, env=env)
    noop_executed = executed_pages(log, project)
    timings["after_latex"], log = noop_after_latex(project, env)
    after_latex_executed = executed_pages(log, project)
    edited_page = edit_text_of_a_page(project)
    print(f">>> rebuild after editing {edited_page}", flush=True)
    timings["page"], log = build(project, env=env)
    page_executed = executed_pages(log, project)
    edited_function = edit_a_figure_function(project)
    print(f">>> rebuild after editing {edited_function}", flush=True)
    timings["figure"], log = build(project, env=env)
    figure_executed = executed_pages(log, project)
    print(">>> seconds: " + ", ".join(f"{k} {v:.1f}" for k, v in timings.items()), flush=True)
    print(f">>> pages executed: cold {len(cold_executed)}, no-op {len(noop_executed)}, "
          f"page edit {len(page_executed)}, figure-module edit {len(figure_executed)}: "
          f"{', '.join(figure_executed) or 'none'}", flush=True)
    executed = {"cold": cold_executed, "noop": noop_executed, "after_latex": after_latex_executed,
                "page": page_executed, "figure": figure_executed}
    return timings, executed, edited_page, edited_function


def write_build_times(output: Path, timings: dict, executed: dict, edited_page: str, edited_function: str) -> None:
    """--builds-only: print the ratios to the cold build and rewrite only the report's build times."""
    print(f">>> ratio to cold: no-op {timings['noop'] / timings['cold']:.3f}, "
          f"html after the LaTeX build {timings['after_latex'] / timings['cold']:.3f}, "
          f"page {timings['page'] / timings['cold']:.3f}, "
          f"figure module {timings['figure'] / timings['cold']:.3f}", flush=True)
    when = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    section = render_builds(timings, executed, edited_page, edited_function)
    section = section.replace("of a copy of the repository.",
                              f"of a copy of the repository (`scripts/bench.py --builds-only`, {when}).", 1)
    output.write_text(replace_section(output.read_text(), section, BUILDS_HEADING))


def measure_site(site: Path, tmp: Path, lighthouse: bool) -> dict:
    """The built site's measurements: page bytes beside a default Jupyter Book page, marking times in
    Chromium, the class page's load, the offline sizes and (unless skipped) Lighthouse's scores."""
    pages = site_pages(site)
    print(">>> default Jupyter Book page", flush=True)
    default_site = default_book(tmp / "default")
    default = asyncio.run(page_bytes(default_site, ["intro.html"]))["intro.html"]
    print(f">>> bytes of {len(pages)} pages", flush=True)
    ours = asyncio.run(page_bytes(site, pages))
    print(">>> marking time in Chromium", flush=True)
    marking = asyncio.run(marking_time(site))
    print(">>> text marking time in Chromium", flush=True)
    text_marking = asyncio.run(text_marking_times(site))
    print(">>> marking every question in Chromium", flush=True)
    question_marking = asyncio.run(question_marking_times(site))
    print(f">>> the class page loading {CLASS_FILES} progress files", flush=True)
    class_load = asyncio.run(class_page_load_time(site))
    offline = offline_sizes(site)
    scores = {}
    if lighthouse:
        print(f">>> lighthouse on {len(pages)} pages (mobile)", flush=True)
        scores = lighthouse_scores(site, pages)
    return {"default": default, "ours": ours, "scores": scores, "marking": marking, "class_load": class_load,
            "offline": offline, "text_marking": text_marking, "question_marking": question_marking}


def main() -> None:
    args = parse_args()
    node_module("axe-core")

    with tempfile.TemporaryDirectory(prefix="bench-") as tmp:
        tmp = Path(tmp)
        project = copy_project(tmp / "book")
        # The copy's physics_figures is the one the build and the kernels import.
        env = {**ENV, "PYTHONPATH": str(project)}
        timings, executed, edited_page, edited_function = time_builds(project, env)
        if args.builds_only:
            write_build_times(Path(args.output), timings, executed, edited_page, edited_function)
            return
        measured = measure_site(project / "_build" / "html", tmp, not args.no_lighthouse)

    report = render(timings=timings, executed=executed, edited_page=edited_page, edited_function=edited_function,
                    **measured)
    output = Path(args.output)
    # the side-by-side `make test` times (scripts/bench_make_test.py) stay
    report = carry_over(output.read_text() if output.exists() else "", report)
    output.write_text(report)
    print(report)
    broken = broken_budgets(measured["default"], measured["ours"], measured["offline"]) + slow_builds(timings)
    if broken:
        raise SystemExit("budgets broken:\n  " + "\n  ".join(broken))


NOOP_SHARE = 0.10  # issue 39 and earlier: a build with nothing to do takes at most 0.10 of a cold build


def slow_builds(timings: dict[str, float]) -> list[str]:
    """The builds with nothing to do (a no-op, and make html after the LaTeX build) that took over
    NOOP_SHARE of the cold build."""
    return [f"{name} build: {timings[name]:.1f} s ({timings[name] / timings['cold']:.3f} of the cold build)"
            for name in ("noop", "after_latex") if timings[name] > NOOP_SHARE * timings["cold"]]


def offline_sizes(site: Path) -> dict[str, int]:
    """What the service worker keeps (gzip, as a server sends it) and the whole output folder."""
    sys.path.insert(0, str(ROOT / "book" / "_ext"))
    from offline import precache_list, precache_size

    sheet_data = site / "teachers" / "sheet-data.js"
    return {"precache": precache_size(site), "precache_files": len(precache_list(site)),
            "output": sum(p.stat().st_size for p in site.rglob("*") if p.is_file()),
            "template_data": max(template_data_sizes(site).values(), default=0),
            "sheet_data": sheet_data.stat().st_size if sheet_data.exists() else 0}


def template_data_sizes(site: Path) -> dict[str, int]:
    """Each template's question data, gzip: its inline data (on the first page that asks it) and its
    variants. file (tests/site/test_house_site.py checks the same budget)."""
    inline: dict[str, bytes] = {}
    for page in sorted(site.rglob("*.html")):
        for data in re.findall(r'<script type="application/json" class="q-data">(.*?)</script>',
                               page.read_text(encoding="utf-8"), re.DOTALL):
            inline.setdefault(re.search(r'"id": "([^"]+)"', data)[1], data.encode())
    return {path.stem: len(gzip.compress(inline.get(path.stem, b""), mtime=0))
            + len(gzip.compress(path.read_bytes(), mtime=0))
            for path in (site / "_static" / "questions").glob("*.js")}


PRECACHE_BYTES = 2_000_000  # CLARIFICATIONS (standing, Page weight): at most 2 MB gzip
SHEET_DATA_BYTES = 2_600_000  # issue 39: teachers/sheet-data.js at most half its size then


def broken_budgets(default: dict, ours: dict, offline: dict) -> list[str]:
    """The page-weight budgets this run broke, each with its figure: make bench fails on any."""
    limit = FIRST_VISIT_SHARE * default["bytes"]
    broken = [f"{page}: {data['bytes']:,} B ({data['bytes'] / default['bytes']:.3f} of the default page) "
              f"in {data['requests']} requests" for page, data in sorted(ours.items())
              if data["bytes"] > limit or data["requests"] > FIRST_VISIT_REQUESTS]
    if offline["precache"] > PRECACHE_BYTES:
        broken.append(f"precache: {offline['precache']:,} B gzip (at most {PRECACHE_BYTES:,})")
    if offline["template_data"] > QUESTION_DATA_BYTES:
        broken.append(f"question data of a template: {offline['template_data']:,} B gzip (at most {QUESTION_DATA_BYTES:,})")
    if offline["sheet_data"] > SHEET_DATA_BYTES:
        broken.append(f"teachers/sheet-data.js: {offline['sheet_data']:,} B (at most {SHEET_DATA_BYTES:,})")
    return broken


def marking_line(most: int, marking: float, text_marking: dict, question_marking: dict, offline: dict) -> str:
    """The question data's weight and the marking times, against their goals."""
    return (f"Largest question data on one page: {most:,} bytes gzip; of one template (inline and its variants' "
            f"file): {offline['template_data']:,} bytes gzip (goal: at most {QUESTION_DATA_BYTES:,}); "
            f"teachers/sheet-data.js: {offline['sheet_data']:,} bytes (goal: at most {SHEET_DATA_BYTES:,}). Marking one "
            f"answer (every part, ecf included) in Chromium takes {marking:.3f} ms (goal: at most 5 ms). "
            f"Text marking, over the {text_marking['answers']} typed answers of tests/fixtures/text_answers.json "
            f"(each the median of {TEXT_RUNS} runs): p95 {text_marking['p95_ms']:.3f} ms, "
            f"{text_marking['p95_ms_cpu_4x']:.3f} ms with the CPU slowed 4 times (goals: 5 ms and 16 ms). "
            f"Every question of the site's {question_marking['pages']} question pages marked whole "
            f"({question_marking['questions']} questions, each the median of 25 runs): p95 "
            f"{question_marking['p95_ms']:.3f} ms, {question_marking['p95_ms_cpu_4x']:.3f} ms with the CPU "
            "slowed 4 times (goals: 5 ms and 16 ms).")


def class_load_line(ms: float) -> str:
    return (f"Class page: {CLASS_FILES} progress files load (a term's practice each, {TERM_ATTEMPTS} attempts) in "
            f"{ms:.0f} ms in Chromium, dropped at once and laid out (median of {CLASS_RUNS}; goal: under "
            f"{CLASS_LOAD_GOAL_MS} ms).")


BUILDS_HEADING = "## Build times"


def render_builds(timings, executed, edited_page, edited_function) -> str:
    """The build-times section: each build's seconds and its ratio to the cold build."""
    cold = timings["cold"]
    rows = [
        ("cold full build (empty cache, every page executed)", "cold", ""),
        ("no-op rebuild (nothing changed)", "noop", "goal: < 0.10"),
        ("`make html` right after the LaTeX build (`make latex`, as `make test`'s `make pdf` runs it)",
         "after_latex", "goal: ≤ 0.10"),
        (f"after editing the text of one page ({edited_page})", "page", "goal: only that page executes"),
        (f"after editing one figure module ({edited_function})", "figure",
         "goal: ≤ 0.5; only the pages that draw from it execute"),
    ]
    lines = [
        BUILDS_HEADING,
        "",
        "Strict build (`jupyter-book build . -n -W --keep-going`) of a copy of the repository.",
        "",
        "| build | seconds | ratio to cold | pages executed | note |",
        "|---|---:|---:|---:|---|",
    ]
    for label, key, note in rows:
        lines.append(
            f"| {label} | {timings[key]:.1f} | {timings[key] / cold:.3f} | {len(executed[key])} | {note} |"
        )
    lines += [
        "",
        f"Pages executed after the one-page edit: {', '.join(executed['page']) or 'none'}.",
        "",
        f"Pages executed after the figure-module edit: {', '.join(executed['figure']) or 'none'}.",
        "",
    ]
    return "\n".join(lines)


def render(*, timings, executed, edited_page, edited_function, default, ours, scores, marking, class_load, text_marking,
           offline, question_marking) -> str:
    now = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    lines = [
        "# Benchmarks",
        "",
        f"Measured by `make bench` (scripts/bench.py) on {now}.",
        "",
        f"Machine: {machine()}.",
        "",
        render_builds(timings, executed, edited_page, edited_function),
        "## Page weight",
        "",
        "Bytes each page transfers in headless Chromium (390 px wide, scrolled to the bottom so",
        "every figure loads), served with gzip as a static host serves it; requests to other",
        "hosts blocked (offline). The reference is a default one-page Jupyter Book 1 project",
        "built in the same run (its CDN MathJax is blocked offline, so the reference is, if",
        "anything, lighter than what a student online would download).",
        "",
        (f"Default Jupyter Book page: **{default['bytes']:,} bytes** in {default['requests']} requests; "
         f"requests to other hosts: {', '.join(default['foreign']) or 'none'}."),
        "",
        ("| page | bytes (gzip) | ratio to default | requests | other hosts |"
         + (" perf | a11y | best practices | SEO |" if scores else "")),
        "|---|---:|---:|---:|---:|" + ("---:|---:|---:|---:|" if scores else ""),
    ]
    for page, data in sorted(ours.items(), key=lambda item: -item[1]["bytes"]):
        row = (
            f"| {page} | {data['bytes']:,} | {data['bytes'] / default['bytes']:.2f} | {data['requests']} | "
            f"{len(data['foreign'])} |"
        )
        if scores:
            s = scores.get(page, {})
            row += "".join(
                f" {round(100 * s[c]) if s.get(c) is not None else '?'} |"
                for c in ("performance", "accessibility", "best-practices", "seo")
            )
        lines.append(row)
    heaviest = max(data["bytes"] for data in ours.values())
    most_requests = max(data["requests"] for data in ours.values())
    lines += [
        "",
        (f"Heaviest page: {heaviest:,} bytes = {heaviest / default['bytes']:.3f} of the default page; "
         f"at most {most_requests} requests a page (goal: at most {FIRST_VISIT_SHARE} in at most "
         f"{FIRST_VISIT_REQUESTS} requests, bytes on the wire with headers; each page measured on a first "
         "visit, in a fresh browser context with service workers blocked)."),
        "",
        "## Offline",
        "",
        (f"The service worker keeps {offline['precache_files']} files, {offline['precache']:,} bytes gzip "
         f"(goal: at most 2 MB). The output folder (before make book adds the PDFs and the zip): "
         f"{offline['output']:,} bytes."),
        "",
        "## Practice",
        "",
        "| page | question data inline (gzip) | with every variant New numbers can load (gzip) |",
        "|---|---:|---:|",
    ]
    for page, data in sorted(ours.items(), key=lambda item: -item[1]["question_data"]):
        if data["question_data"]:
            lines.append(f"| {page} | {data['question_data']:,} | "
                         f"{data['question_data'] + data['variant_data']:,} |")
    most = max(d["question_data"] + d["variant_data"] for d in ours.values())
    lines += [
        "",
        marking_line(most, marking, text_marking, question_marking, offline),
        class_load_line(class_load),
    ]
    if scores:
        worst = {c: min(s[c] for s in scores.values()) for c in ("performance", "accessibility", "best-practices", "seo")}
        lines.append(
            "Lighthouse (mobile, simulated slow 4G, offline against localhost), lowest over all pages: "
            + ", ".join(f"{c} {round(100 * v)}" for c, v in worst.items())
            + f" (goal: performance >= {round(100 * LIGHTHOUSE_GOAL['performance'])}, the others 100;"
            + f" each page the median of {LIGHTHOUSE_RUNS} runs)."
        )
    lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    main()
