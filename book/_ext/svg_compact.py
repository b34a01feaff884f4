"""A matplotlib SVG in fewer bytes, drawn the same: for a graph inline in the teachers' data
file (questions/sheet_builder.py, inline_svg), and for a figure a page loads as an image
(svg_file): a question's (questions/directive.py) and a page's own (site_assets, when the build
finishes)."""

from __future__ import annotations

import re

XML_HEAD = re.compile(r"<\?xml[^>]*>|<!DOCTYPE[^>]*>|<metadata>.*?</metadata>|<!--.*?-->", re.DOTALL)
ID_ATTRIBUTE = re.compile(r'\sid="([^"]+)"')
#: matplotlib's tick mark, drawn once in <defs> and placed at each tick by a <use>
_MARK = re.compile(r'<path id="([^"]+)" d="M 0 0 L (-?[\d.]+) (-?[\d.]+) " style="([^"]*)"/>')
_MARKS_PLACED = re.compile(r'(?:<use xlink:href="#[^"]+" x="[^"]+" y="[^"]+" style="[^"]*"/>)+')
_PLACED = re.compile(r'<use xlink:href="#([^"]+)" x="([^"]+)" y="([^"]+)" style="[^"]*"/>')
_LONG_NUMBER = re.compile(r"-?\d+\.\d{3,}")
_FAMILY = re.compile(r" font-family: ([^;\"]+);")


def _number(match: re.Match) -> str:
    """A coordinate to 0.01 px (a hundredth of a point: far below what a screen or a printer
    shows), without trailing zeros."""
    text = f"{float(match[0]):.2f}".rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


def _marks_as_one_path(svg: str) -> str:
    """Each axis's tick marks as one path (a move and a short line a tick) in place of a <use>
    of the mark a tick: the same strokes, a sixth of the bytes."""
    marks = {m[1]: (float(m[2]), float(m[3]), m[4]) for m in _MARK.finditer(svg)}

    def one_path(run: re.Match) -> str:
        placed = _PLACED.findall(run[0])
        if len({mark for mark, _, _ in placed}) != 1 or placed[0][0] not in marks:
            return run[0]
        dx, dy, style = marks[placed[0][0]]
        moves = "".join(f"M{x} {y}l{dx:g} {dy:g}" for _, x, y in placed)
        return f'<path d="{moves}" style="{style}"/>'

    svg = _MARKS_PLACED.sub(one_path, svg)
    used = set(re.findall(r'href="#([^"]+)"', svg))
    return _MARK.sub(lambda m: m[0] if m[1] in used else "", svg).replace("<defs></defs>", "")


def _path_data(d: str) -> str:
    """matplotlib's path data (absolute M, L, C, Q, z, each number spaced) without the spaces a
    reader of SVG does not need, a line along an axis as H or V: the same path."""
    tokens = re.findall(r"[A-Za-z]|-?[\d.]+(?:e-?\d+)?", d)
    if any(t.isalpha() and t not in "MLCQz" for t in tokens):
        return d
    out, x, y, i = [], None, None, 0
    while i < len(tokens):
        command = tokens[i]
        count = {"M": 2, "L": 2, "C": 6, "Q": 4, "z": 0}[command]
        numbers = tokens[i + 1:i + 1 + count]
        i += 1 + count
        if command == "L" and numbers[1] == y:
            out.append(f"H{numbers[0]}")
        elif command == "L" and numbers[0] == x:
            out.append(f"V{numbers[1]}")
        else:
            out.append(command + " ".join(numbers).replace(" -", "-"))
        if count:
            x, y = numbers[-2], numbers[-1]
    return "".join(out)


def compact_svg(svg: str) -> str:
    """A graph's SVG in fewer bytes, drawn the same: tick marks as one path an axis, coordinates
    to 0.01 px, path data without needless spaces, no rotation by 0, and the one font family of
    its texts said once, on the <svg>."""
    svg = _marks_as_one_path(svg)
    svg = re.sub(r'(\s(?!aria-label)[\w:-]+=")([^"]*)"', lambda m: m[1] + _LONG_NUMBER.sub(_number, m[2]) + '"', svg)
    svg = re.sub(r' transform="rotate\(-?0 [^")]*\)"', "", svg)
    svg = re.sub(r'(<path\b[^>]*?\sd=")([^"]*)"', lambda m: m[1] + _path_data(m[2]) + '"', svg)
    families = set(_FAMILY.findall(svg))
    if len(families) == 1:
        svg = _FAMILY.sub("", svg)
        svg = svg.replace("<svg ", f'<svg style="font-family: {families.pop()}" ', 1)
    return svg



def is_compact(svg: str) -> bool:
    """Written by svg_file: matplotlib begins its files with an XML prologue."""
    return not svg.startswith("<?xml")


def svg_file(svg: str) -> str:
    """A figure's SVG as the site ships it to an <img>: no XML prologue, doctype or metadata
    (an image needs none), no line breaks inside its paths, compact (compact_svg)."""
    svg = XML_HEAD.sub("", svg)
    svg = re.sub(r"\s*\n\s*", " ", svg).replace("> <", "><").strip()
    return compact_svg(svg) + "\n"
