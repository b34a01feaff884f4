"""Time `make test` on fresh clones of two commits, one after the other, in one run.

    python scripts/bench_make_test.py BASE [COMMIT]     (COMMIT: HEAD when left out)

Each commit is cloned from this repository into a temporary folder and `make test` runs
there as CI runs it (the new commit first, so a cache the first run warms favours the base): a new venv, `npm ci`, the book built from nothing, the whole suite.
The wall time, the tests that passed and failed, the ratio of the second commit's time to
the first's, and how long each phase of the run took (from the second each line of its
output arrived, which the log under _build/ carries) go into BENCHMARKS.md, under "`make
test`, side by side" (the rest of the file is `make bench`'s, which keeps this section when
it rewrites the file).
"""

from __future__ import annotations

import argparse
import datetime
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HEADING = "## `make test`, side by side"


def make_test(commit: str, folder: Path) -> dict:
    """Clone `commit` into `folder`, run `make test` there; its time and test counts."""
    subprocess.run(["git", "clone", "--quiet", str(ROOT), str(folder)], check=True)
    subprocess.run(["git", "-C", str(folder), "checkout", "--quiet", commit], check=True)
    sha = subprocess.run(["git", "-C", str(folder), "rev-parse", "--short", "HEAD"], check=True,
                         capture_output=True, text=True).stdout.strip()
    log = ROOT / "_build" / f"make-test-{sha}.log"
    log.parent.mkdir(exist_ok=True)
    print(f">>> make test at {sha} (log: {log})", flush=True)
    start = time.monotonic()
    with log.open("w") as out, subprocess.Popen(["make", "test"], cwd=folder, stdout=subprocess.PIPE,
                                                stderr=subprocess.STDOUT, text=True, errors="replace") as make:
        for line in make.stdout:  # each line stamped with the second it arrived
            out.write(f"[{time.monotonic() - start:7.1f}] {line}")
        status = make.wait()
    seconds = time.monotonic() - start
    text = log.read_text(errors="replace")
    # one pytest summary line per run ("=== 3 failed, 590 passed, 2 deselected in 552.21s ===")
    summaries = re.findall(rf"^{STAMP}=+ (.*\d+ passed.*) in [\d.]+s.* =+$", text, re.MULTILINE)
    counted = {word: sum(int(n) for line in summaries for n in re.findall(rf"(\d+) {word}", line))
               for word in ("passed", "failed", "error")}
    print(f">>> {sha}: {seconds:.0f} s, exit {status}, {counted}", flush=True)
    if status:
        print(text[-3000:], file=sys.stderr)
    return {"commit": sha, "seconds": seconds, "status": status, "phases": phases(text, seconds), **counted}


#: A line of the log as make_test writes it: "[  123.4] " and the line make printed.
STAMP = r"\[\s*[\d.]+\] "
#: The phases of `make test`, each ending where the line that begins the next arrives (the
#: Makefile's own ">>>" lines, the same since c4f87a4; the site's run ends at its pytest summary).
PHASES = (
    ("install and lint", ">>> building the book"),
    ("the book (the runs that need no site beside it)", ">>> the tests of the built site"),
    ("the site's tests", "=+ .* in [\\d.]+s"),
    ("waiting for the runs that need no site", ">>> the tests that need no site:"),
    ("the tests that measure speed, alone", None),
)


def phases(log: str, seconds: float) -> dict[str, float]:
    """How long each phase of PHASES took in a stamped log of `make test` that took `seconds`
    (a phase whose line never came, as in a run that failed early, is left out)."""
    took, begun, at = {}, 0.0, 0
    lines = [(float(m[1]), m[2]) for m in re.finditer(r"^\[\s*([\d.]+)\] (.*)$", log, re.MULTILINE)]
    for name, ends in PHASES:
        found = next((n for n in range(at, len(lines)) if ends and re.match(ends, lines[n][1])), None)
        if ends is not None and found is None:
            break
        end = seconds if ends is None else lines[found][0]
        took[name], begun, at = end - begun, end, (found or 0) + 1
    return took


def section(runs: list[dict], command: str, goal: float) -> str:
    base, new = runs
    ratio = new["seconds"] / base["seconds"]
    rows = "\n".join(
        f"| {r['commit']} | {r['seconds']:.0f} ({r['seconds'] / 60:.1f} min) | {r['passed']:,} | "
        f"{r['failed'] + r['error']} | {r['status']} |" for r in runs)
    when = datetime.datetime.now(datetime.UTC).strftime("%Y-%m-%d %H:%M UTC")
    return (f"{HEADING}\n\nMeasured {when} by `{command}`: each commit cloned afresh and `make test` run "
            "in it, one after the other, on this machine.\n\n"
            "| commit | wall seconds | tests passed | failed | exit status |\n|---|---:|---:|---:|---:|\n"
            f"{rows}\n\n`make test` at {new['commit']} takes **{ratio:.2f}** of the time at {base['commit']} "
            f"(goal: at most {goal:.2f}).\n\n"
            f"Its phases, in seconds (from the stamped logs, _build/make-test-COMMIT.log):\n\n"
            f"| phase | {base['commit']} | {new['commit']} | difference |\n|---|---:|---:|---:|\n"
            + "".join(f"| {name} | {base['phases'].get(name, 0):.0f} | {new['phases'].get(name, 0):.0f} | "
                      f"{new['phases'].get(name, 0) - base['phases'].get(name, 0):+.0f} |\n" for name, _ in PHASES))


def replace_section(document: str, text: str, heading: str = HEADING) -> str:
    """`document` with its section under `heading` replaced by (or ended with) `text`."""
    found = re.search(rf"^{re.escape(heading)}\n.*?(?=^## |\Z)", document, re.MULTILINE | re.DOTALL)
    if found:
        return document[:found.start()] + text + ("\n" if document[found.end():] else "") + document[found.end():]
    return document.rstrip("\n") + "\n\n" + text


def carry_over(old_document: str, new_document: str) -> str:
    """`new_document` (make bench's report) with the side-by-side section of the old one."""
    found = re.search(rf"^{re.escape(HEADING)}\n.*?(?=^## |\Z)", old_document, re.MULTILINE | re.DOTALL)
    return replace_section(new_document, found[0].rstrip("\n") + "\n") if found else new_document


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("base", help="the commit to compare against")
    parser.add_argument("commit", nargs="?", default="HEAD")
    parser.add_argument("--goal", type=float, default=1.10,
                        help="the most the commit may take, as a share of the base's time (issue 39: 1.10 of c4f87a4's)")
    parser.add_argument("--output", default=str(ROOT / "BENCHMARKS.md"))
    args = parser.parse_args()
    command = f"python scripts/bench_make_test.py {args.base} {args.commit} --goal {args.goal}"
    with tempfile.TemporaryDirectory(prefix="bench-make-test-") as tmp:
        # the new commit first: any cache the first run warms (uv's, npm's) serves the base
        new = make_test(args.commit, Path(tmp) / "clone-new")
        runs = [make_test(args.base, Path(tmp) / "clone-base"), new]
    output = Path(args.output)
    text = section(runs, command, args.goal)
    output.write_text(replace_section(output.read_text() if output.exists() else "# Benchmarks\n", text))
    print(text)


if __name__ == "__main__":
    main()
