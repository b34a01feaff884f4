"""The sheet builder's data file (teachers/sheet-data.js), read, and its variants joined from
their pieces by the builder's own code (sheet-builder.js's variantHtml, under Node)."""

from __future__ import annotations

import json
from pathlib import Path

from support.engine import ROOT, node_json

PAGES = ROOT / "tests" / "js" / "sheet_pages.js"


def read_sheet_data(site_dir: Path) -> dict:
    script = (site_dir / "teachers" / "sheet-data.js").read_text(encoding="utf-8")
    return json.loads(script[script.index("{"):script.rindex("}") + 1])


def joined_pages(data: dict, pages: list[tuple[str, int | str]] | None = None) -> dict[tuple[str, str], dict]:
    """Each variant's sheet and key, {(key, variant): {"sheet": html, "key": html}}, as the
    builder's page joins them (every variant of the data, or those of ``pages``)."""
    request = {"data": data} if pages is None else {"data": data, "pages": [[k, str(v)] for k, v in pages]}
    return {(page["key"], page["variant"]): {"sheet": page["sheet"], "key": page["key_html"]}
            for page in node_json(PAGES, request)}
