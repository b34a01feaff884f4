"""Pack the built site into one zip a student can unzip and open from disk (file://).

Usage: python scripts/zip_site.py [SITE] — writes SITE/download/dynamics.zip, holding the
site under a folder "dynamics/" (open dynamics/index.html). The same site gives the same
bytes: entries sorted, every date SOURCE_DATE_EPOCH, fixed permissions.
"""

from __future__ import annotations

import sys
import time
import zipfile
from pathlib import Path

from physics_figures.reproducible import source_date_epoch

ZIP = Path("download") / "dynamics.zip"
FOLDER = "dynamics"
#: Only a server uses these (a copy on disk has no service worker or web app manifest).
LEFT_OUT = {"sw.js", "manifest.webmanifest", ".buildinfo", "objects.inv"}


def zip_site(site: Path) -> Path:
    if not (site / "index.html").is_file():
        raise ValueError(f"site must be a built site with an index.html (got site={str(site)!r}): run make html")
    target = site / ZIP
    target.parent.mkdir(parents=True, exist_ok=True)
    stamp = time.gmtime(source_date_epoch())[:6]
    files = sorted(p for p in site.rglob("*") if p.is_file() and p != target
                   and p.relative_to(site).as_posix() not in LEFT_OUT)
    partial = target.with_suffix(".zip.partial")
    with zipfile.ZipFile(partial, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as archive:
        for path in files:
            entry = zipfile.ZipInfo(f"{FOLDER}/{path.relative_to(site).as_posix()}", date_time=stamp)
            entry.external_attr = 0o644 << 16
            entry.compress_type = zipfile.ZIP_DEFLATED
            archive.writestr(entry, path.read_bytes())
    partial.replace(target)
    return target


if __name__ == "__main__":
    site = Path(sys.argv[1] if len(sys.argv) > 1 else "_build/html")
    written = zip_site(site)
    print(f">>> {written}: {written.stat().st_size / 1e6:.1f} MB, open {FOLDER}/index.html after unzipping")
