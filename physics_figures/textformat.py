# ruff: noqa: RUF002  (typeset text: true minus, times sign)
"""The one small text format of question text, keys and mark schemes.

Variant text needs no TeX: it is plain Unicode (units as m s⁻¹, a true minus, ×) with
a few inline tags, written once and rendered to HTML (the site and Moodle), to LaTeX
(xelatex) and, by the questions extension, to docutils nodes::

    A <em>resultant</em> force of 5.0 N acts for 3.0 s. v<sub>1</sub> = 2.0 m s<sup>−1</sup>

Tags: ``<sup>``, ``<sub>``, ``<em>``, ``<strong>``; a blank line starts a new paragraph.
Any other lower-case tag is refused, so a typo cannot leak into a page; a < or > that is
not a tag ("v > 0") is text, escaped in every output.
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass

from .notation import join_units

TAGS = ("sup", "sub", "em", "strong")
_TOKEN = re.compile(r"<(/?)([a-z]+)>")


@dataclass(frozen=True)
class Span:
    """A run of text with the tags around it, outermost first (e.g. ("em", "sup"))."""

    text: str
    tags: tuple[str, ...] = ()


def parse(source: str) -> list[list[Span]]:
    """Paragraphs of spans; ValueError names the unknown or unbalanced tag."""
    paragraphs = []
    for block in re.split(r"\n\s*\n", source.strip()):
        spans, open_tags, at = [], [], 0
        block = " ".join(block.split())  # one paragraph: line breaks are spaces
        for match in _TOKEN.finditer(block):
            if match.start() > at:
                spans.append(Span(block[at:match.start()], tuple(open_tags)))
            closing, tag = match[1] == "/", match[2]
            if tag not in TAGS:
                raise ValueError(f"text has the tag <{match[1]}{tag}>, which is not one of {TAGS} "
                                 f"(got text={source!r})")
            if closing:
                if not open_tags or open_tags[-1] != tag:
                    raise ValueError(f"text closes <{tag}> that is not open (got text={source!r})")
                open_tags.pop()
            else:
                open_tags.append(tag)
            at = match.end()
        if open_tags:
            raise ValueError(f"text leaves <{open_tags[-1]}> open (got text={source!r})")
        if at < len(block):
            spans.append(Span(block[at:], tuple(open_tags)))
        paragraphs.append(spans)
    return paragraphs


def _joined(spans: list[Span]) -> list[Span]:
    """Each number joined to its unit by no-break spaces (notation.join_units), also when
    the unit's text is the next span's: "2.0 m s<sup>−1</sup>" never breaks on a screen."""
    out, previous = [], ""
    for span in spans:
        text = join_units(span.text, after_number=previous[-1:].isdigit())
        out.append(Span(text, span.tags))
        previous = text
    return out


def to_html(source: str, *, paragraphs: bool = True) -> str:
    """HTML for the site and for Moodle; one paragraph without <p> if paragraphs=False.
    Numbers are joined to their units with no-break spaces (U+00A0)."""
    out = []
    for spans in parse(source):
        body = "".join(_wrap_html(span) for span in _joined(spans))
        out.append(f"<p>{body}</p>" if paragraphs else body)
    return "\n".join(out) if paragraphs else " ".join(out)


def _wrap_html(span: Span) -> str:
    text = html.escape(span.text, quote=False)
    for tag in reversed(span.tags):
        text = f"<{tag}>{text}</{tag}>"
    return text


_LATEX_SPECIAL = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                  "#": r"\#", "_": r"\_", "%": r"\%", "~": r"\textasciitilde{}",
                  "^": r"\textasciicircum{}", "\u00a0": "~"}  # a no-break space is TeX's tie
_LATEX_TAG = {"sup": r"\textsuperscript{%s}", "sub": r"\textsubscript{%s}", "em": r"\emph{%s}",
              "strong": r"\textbf{%s}"}


#: A slash inside a word ("9702/22/M/J/21", "kg/m"): a line may break after it, so a paper's
#: code at a line's end does not run into the margin.
_SLASH_IN_WORD = re.compile(r"(?<=\S)/(?=\S)")


def latex_escape(text: str) -> str:
    """Plain text for LaTeX: its special characters escaped, no-break spaces as ties, and a
    break allowed after a slash inside a word."""
    escaped = "".join(_LATEX_SPECIAL.get(char, char) for char in text)
    return _SLASH_IN_WORD.sub(r"/\\allowbreak{}", escaped)


def to_latex(source: str) -> str:
    """LaTeX for xelatex (Unicode text stays Unicode); paragraphs separated by blank lines.
    Numbers are tied to their units, as on the site, so a line never breaks between them."""
    out = []
    for spans in parse(source):
        body = ""
        for span in _joined(spans):
            text = latex_escape(span.text)
            for tag in reversed(span.tags):
                text = _LATEX_TAG[tag] % text
            body += text
        out.append(body)
    return "\n\n".join(out)


def to_plain(source: str, *, joined: bool = False) -> str:
    """The words alone (for search, names and tests). joined: numbers tied to their units by
    no-break spaces, as to_html does, for words a page shows as text."""
    return "\n\n".join("".join(span.text for span in (_joined(spans) if joined else spans))
                       for spans in parse(source))
