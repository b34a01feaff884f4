"""The sheet builder's data without its repetitions (questions/sheet_builder.py writes it).

A variant's sheet and key are HTML that physics_figures writes whole. Much of it repeats: the
key restates the question's text that the sheet prints; the variants of a graph template draw
the same axes, grid, ticks and labels, and only the plotted line differs; a template's answer
spaces, the "Common wrong answers" heading and many of the feedback lines are the same in every
variant. So the data file holds each sheet and key as a list of pieces, in order: a piece is
HTML, or the number of a piece the file holds once, in ``pieces``, for every sheet and key that
uses it. The builder (static/sheet-builder.js, ``page``) joins the pieces again: the same HTML,
byte for byte.

Pieces are whole elements or text: a long element that holds others (a ``<div>``, a list, an
SVG and its groups) is cut into its opening tag, its children and its closing tag; any other (a
paragraph, a list item, a path, a short group) is one piece. A graph's ids are its own on a page (several
graphs share one): in the pieces they are written ``ID_MARK``, and the variant says its own
prefix (``ids``)."""

from __future__ import annotations

import re
from collections import Counter
from itertools import pairwise

#: What a graph's own id prefix is written as in the pieces (the builder puts the variant's back).
ID_MARK = "{ids}"
#: The elements cut into their tags and children; any other element is one piece.
CONTAINERS = frozenset({"div", "ul", "ol", "figure", "svg", "g", "defs", "clipPath"})
#: Elements with no closing tag in HTML.
VOID = frozenset({"br", "hr", "img", "input", "wbr", "col"})
#: A container as long as this or shorter is one piece (an axis's tick with its label, an answer's
#: space); a longer one is cut, so that what it shares with another is found.
LONGEST_WHOLE = 200
#: Shorter pieces stay where they are: their number and the cut cost about as much as they save.
SHORTEST_SHARED = 16
_TOKEN = re.compile(r"<(/?)([A-Za-z][\w:-]*)[^>]*?(/?)>|[^<]+|<")


def cut(html: str) -> list[str]:
    """The HTML's pieces, in order: joined, they are the HTML again."""
    tokens = [(m[0], m[1], m[2], bool(m[3]) or tag_is_void(m[2])) for m in _TOKEN.finditer(html)]
    ends, open_at = {}, []  # where each element that has a closing tag ends (its closing token)
    for i, (_, closing, tag, self_closing) in enumerate(tokens):
        if tag and not self_closing and not closing:
            open_at.append((tag, i))
        elif tag and closing:
            if not open_at or open_at[-1][0] != tag:
                raise ValueError(f"html: </{tag}> closes no element, so it cannot be cut into pieces: {html[:200]!r}")
            ends[open_at.pop()[1]] = i
    if open_at:
        raise ValueError(f"html: <{open_at[-1][0]}> is not closed, so it cannot be cut into pieces: {html[:200]!r}")
    pieces: list[str] = []
    _cut(tokens, ends, 0, len(tokens), pieces)
    return pieces


def _cut(tokens: list, ends: dict[int, int], start: int, stop: int, pieces: list[str]) -> None:
    """Tokens start to stop as pieces: a container longer than LONGEST_WHOLE as its tags
    around its children's pieces, any other element or text whole."""
    i = start
    while i < stop:
        end = ends.get(i, i)
        whole = "".join(token[0] for token in tokens[i:end + 1])
        if tokens[i][2] in CONTAINERS and end > i and len(whole) > LONGEST_WHOLE:
            pieces.append(tokens[i][0])
            _cut(tokens, ends, i + 1, end, pieces)
            pieces.append(tokens[end][0])
        else:
            pieces.append(whole)
        i = end + 1


def tag_is_void(tag: str | None) -> bool:
    return bool(tag) and tag.lower() in VOID


def _runs(lists: list[list[str]], shared: set[str]) -> list[list[str]]:
    """Each list with a run of shared pieces that always come together made one piece."""
    while True:
        uses = Counter(piece for pieces in lists for piece in pieces if piece in shared)
        pairs = Counter((a, b) for pieces in lists for a, b in pairwise(pieces)
                        if a in shared and b in shared)
        together = {pair for pair, count in pairs.items() if uses[pair[0]] == uses[pair[1]] == count
                    and pair[0] != pair[1]}
        if not together:
            return lists
        lists = [_join_pairs(pieces, together) for pieces in lists]
        shared |= {a + b for a, b in together}


def _join_pairs(pieces: list[str], together: set[tuple[str, str]]) -> list[str]:
    out: list[str] = []
    for piece in pieces:
        if out and (out[-1], piece) in together:
            out[-1] += piece
        else:
            out.append(piece)
    return out


def share(lists: list[list[str]]) -> tuple[list[str], list[list[str | int]]]:
    """The pieces used more than once (each once, in the order first used), and each list with
    those pieces as their numbers, the others joined where they meet."""
    repeated = Counter(piece for pieces in lists for piece in pieces)
    lists = _runs(lists, {piece for piece, count in repeated.items() if count > 1})
    uses = Counter(piece for pieces in lists for piece in pieces)
    shared = {piece for piece, count in uses.items() if count > 1 and len(piece) >= SHORTEST_SHARED}
    numbers: dict[str, int] = {}
    out = []
    for pieces in lists:
        items: list[str | int] = []
        for piece in pieces:
            if piece in shared:
                items.append(numbers.setdefault(piece, len(numbers)))
            elif items and isinstance(items[-1], str):
                items[-1] += piece
            else:
                items.append(piece)
        out.append(items)
    return list(numbers), out
