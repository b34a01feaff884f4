"""The minified scripts' cache (book/_ext/site_assets/stylesheets.py, MinifiedCache): a cold
build takes a script terser minified before from node_modules/.cache, and never one made from
another source, another minify-js.js or another terser."""

from __future__ import annotations

import json
from pathlib import Path

from site_assets.stylesheets import MinifiedCache


def _node_modules(folder: Path, terser_version: str) -> Path:
    (folder / "terser").mkdir(parents=True)
    (folder / "terser" / "package.json").write_text(json.dumps({"name": "terser", "version": terser_version}))
    return folder


def test_a_kept_script_comes_back_whole_for_the_same_source(tmp_path):
    cache = MinifiedCache(_node_modules(tmp_path / "node_modules", "5.0.0"))
    minified = tmp_path / "made.js"
    minified.write_text("var a=1;\n")
    key = cache.key(b"var a = 1; // the source\n")
    cache.keep(key, minified)

    target = tmp_path / "site.js"
    target.write_text("var a = 1; // the source\n")
    assert cache.fetch(key, target)
    assert target.read_text() == "var a=1;\n"
    assert [p.name for p in cache.folder.iterdir()] == [f"{key}.js"], "a partial file was left behind"


def test_another_source_or_terser_is_another_key_and_misses(tmp_path):
    cache = MinifiedCache(_node_modules(tmp_path / "one", "5.0.0"))
    other_terser = MinifiedCache(_node_modules(tmp_path / "two", "5.0.1"))
    source = b"var a = 1;\n"
    assert cache.key(source) == cache.key(source)
    assert cache.key(source) != cache.key(b"var a = 2;\n")
    assert cache.key(source) != other_terser.key(source)

    minified = tmp_path / "made.js"
    minified.write_text("var a=1;\n")
    cache.keep(cache.key(source), minified)
    target = tmp_path / "site.js"
    target.write_text("var a = 2;\n")
    assert not cache.fetch(cache.key(b"var a = 2;\n"), target)
    assert target.read_text() == "var a = 2;\n", "a miss must leave the site's copy for terser"
