"""The tests' house (issue 39), measured on the built site: a template's question data keeps within
its budget. The checks of the sources are tests/no_site/test_house.py."""

from __future__ import annotations

import re

import pytest


@pytest.mark.site
def test_question_data_keeps_within_40_kb_gzip_a_template(site_dir):
    """A template's question data (issue 39, "Lighter first visits"): its inline data on the page
    that asks it and the file of variants New numbers (or the mock test) loads, gzip as a host
    sends them, at most QUESTION_DATA_BYTES. The forms in the files are the mock test's, so only
    a template it can ask carries one (an explanation's form never did any work there)."""
    import gzip

    from browser import QUESTION_DATA_BYTES

    inline: dict[str, bytes] = {}
    for page in sorted(site_dir.rglob("*.html")):
        text = page.read_text(encoding="utf-8")
        for data in re.findall(r'<script type="application/json" class="q-data">(.*?)</script>', text, re.DOTALL):
            key = re.search(r'"id": "([^"]+)"', data)[1]
            inline.setdefault(key, data.encode())
    files = {path.stem: path.read_bytes() for path in (site_dir / "_static" / "questions").glob("*.js")}
    assert files, "no question data file"
    sizes = {key: len(gzip.compress(inline.get(key, b""), mtime=0)) + len(gzip.compress(data, mtime=0))
             for key, data in files.items()}
    over = {key: size for key, size in sizes.items() if size > QUESTION_DATA_BYTES}
    assert not over, f"question data over {QUESTION_DATA_BYTES:,} B gzip: {over}"
    explained = [key for key, data in files.items() if b"q-explain" in data and b"QuestionForms" in data]
    assert not explained, f"an explanation's form in its data file, which the mock test never draws: {explained}"
