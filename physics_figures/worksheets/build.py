"""Typeset sheets with xelatex: each version's question sheet and answer key, in parallel.

For each version the .tex files and the graphs' vector PDFs go into ``<work>/<name>-<letter>/``
(``work`` is ``<out>/.tex`` unless given)
and xelatex typesets them there (one pass: nothing refers to a later page). The PDFs are
copied to ``<out>/<name>-A.pdf`` and ``<out>/<name>-key-A.pdf``. No clock reaches the
files: SOURCE_DATE_EPOCH and FORCE_SOURCE_DATE fix the PDFs' dates and ids, so the same
seed gives the same bytes.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

from ..cores import on_every_core
from ..reproducible import source_date_epoch
from . import Sheet
from .latex import answer_key, graphs, question_sheet

XELATEX = ("xelatex", "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape")


@dataclass(frozen=True)
class Job:
    folder: Path
    jobname: str
    target: Path


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["SOURCE_DATE_EPOCH"] = str(source_date_epoch())  # when the caller sets none, the book's date
    env["FORCE_SOURCE_DATE"] = "1"
    return env


def write_sources(sheets: list[Sheet], out: Path, work: Path | None = None) -> list[Job]:
    """Write every version's .tex files and graphs; return the typesetting jobs."""
    jobs = []
    work = out / ".tex" if work is None else work
    versions = [(sheet, version) for sheet in sheets for version in sheet.versions]
    for _, version in versions:  # each question worked out here, once: the sheets print them too
        for item in version.items:
            item.question  # noqa: B018 (a cached property)
    # the graphs on every core: matplotlib's PDFs (their fonts' subsetting) are most of the time
    drawn = on_every_core(lambda n: graphs(versions[n][1]), range(len(versions)))
    for (sheet, version), figures in zip(versions, drawn, strict=True):
        folder = work / f"{sheet.name}-{version.letter}"
        if folder.exists():
            shutil.rmtree(folder)
        folder.mkdir(parents=True)
        for name, data in figures.items():
            (folder / name).write_bytes(data)
        for jobname, text in ((f"{sheet.name}-{version.letter}", question_sheet(sheet, version)),
                              (f"{sheet.name}-key-{version.letter}", answer_key(sheet, version))):
            (folder / f"{jobname}.tex").write_text(text, encoding="utf-8")
            jobs.append(Job(folder, jobname, out / f"{jobname}.pdf"))
    return jobs


def _typeset(job: Job) -> Path:
    result = subprocess.run([*XELATEX, f"{job.jobname}.tex"], cwd=job.folder, env=_env(), check=False,
                            capture_output=True, text=True, errors="replace")
    pdf = job.folder / f"{job.jobname}.pdf"
    if result.returncode != 0 or not pdf.exists():
        log = job.folder / f"{job.jobname}.log"
        errors = [line for line in result.stdout.splitlines() if line.startswith("!")]
        raise RuntimeError(f"xelatex failed on {job.folder / job.jobname}.tex: "
                           f"{'; '.join(errors[:3]) or 'see the log'} (log: {log})")
    shutil.copyfile(pdf, job.target)
    return job.target


def typeset(jobs: list[Job], *, parallel: int | None = None) -> list[Path]:
    """Run xelatex on every job, ``parallel`` at a time (default: one per core)."""
    if shutil.which(XELATEX[0]) is None:
        raise RuntimeError("xelatex is not installed: run `make pdf` once (scripts/ensure-debian-packages "
                           "pdf installs TeX Live)")
    workers = parallel or os.cpu_count() or 1
    with ThreadPoolExecutor(max_workers=workers) as pool:
        return list(pool.map(_typeset, jobs))


def build(sheets: list[Sheet], out: Path, *, parallel: int | None = None,
          work: Path | None = None) -> list[Path]:
    """Write and typeset every sheet's versions into ``out`` (the LaTeX in ``work``); return
    the PDFs."""
    out.mkdir(parents=True, exist_ok=True)
    return typeset(write_sources(sheets, out, work), parallel=parallel)
