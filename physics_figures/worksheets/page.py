"""What the "For teachers" page (book/teachers.md) lists: every sheet `make worksheets`
writes, its versions and keys, and the Moodle file `make moodle` writes, as links.

The page shows ``teachers_files()`` in one cell. On the site it is an HTML table of links
to ``../teachers/<file>`` (raw links, which Sphinx leaves alone: the files are made after
the HTML build); in the PDF book, where those links cannot work, a list of the file names.
"""

from __future__ import annotations

import html
from dataclasses import dataclass

from ..topics import Topic
from . import SITE_SEED, Sheet, bank_templates, site_sheets, topic_of

#: Where `make worksheets` and `make moodle` write, relative to the site's root, and from
#: the page (book/teachers.html).
FOLDER = "teachers"
FROM_PAGE = f"../{FOLDER}/"


def moodle_file(topic: Topic | None = None) -> str:
    """The Moodle XML's name, by topic: dynamics-moodle.xml."""
    return f"{topic_of(topic).key}-moodle.xml"


def sheet_files(sheet: Sheet) -> list[tuple[str, str]]:
    """(question sheet, key) file names of every version of a sheet."""
    return [(f"{sheet.name}-{v.letter}.pdf", f"{sheet.name}-key-{v.letter}.pdf") for v in sheet.versions]


def site_files(topic: Topic | None = None) -> list[str]:
    """Every file the page links (what `make worksheets` and `make moodle` must write)."""
    files = [name for sheet in site_sheets(topic=topic) for pair in sheet_files(sheet) for name in pair]
    return [*files, moodle_file(topic)]


@dataclass(frozen=True)
class TeachersFiles:
    sheets: tuple[Sheet, ...]
    topic: Topic

    def _html(self) -> str:
        # One row per sheet and one column per version, each cell the sheet and its key:
        # four narrow columns, so the table fits a 390 px phone.
        letters = [v.letter for v in self.sheets[0].versions]
        rows = []
        for sheet in self.sheets:
            title = html.escape(sheet.title)
            short = html.escape(sheet.title.removeprefix("Worksheet: "))  # the column says "Sheet"
            cells = "".join(
                f'<td><a href="{FROM_PAGE}{paper}" download aria-label="Sheet {v.letter}: {title}">Sheet</a>'
                f'<br><a href="{FROM_PAGE}{key}" download aria-label="Key {v.letter}: {title}">Key</a></td>'
                for v, (paper, key) in zip(sheet.versions, sheet_files(sheet), strict=True))
            rows.append(f'<tr><th scope="row">{short}<br><small>{len(sheet.templates)} questions, '
                        f"{sheet.marks} marks</small></th>{cells}</tr>")
        templates = bank_templates(self.topic)
        variants = sum(len(t.reserve_variants) for t in templates)
        versions = "".join(f'<th scope="col">Version {letter}</th>' for letter in letters)
        return (
            '<table class="table teachers-sheets">'
            "<caption>Worksheets (PDF, A4): each version with its own answer key</caption>"
            f'<thead><tr><th scope="col">Sheet</th>{versions}'
            "</tr></thead><tbody>" + "".join(rows) + "</tbody></table>\n"
            f'<p><a href="{FROM_PAGE}{moodle_file(self.topic)}" download>The question bank for Moodle '
            f"(Moodle XML)</a>: {len(templates)} templates, {variants} variants in all.</p>\n"
            f"<p>{html.escape(self._shared())}</p>")

    def _shared(self) -> str:
        shared = [t.title for t in bank_templates(self.topic) if t.shares_variants]
        return (f"These {len(shared)} questions have too few situations to keep some back, so the sheets "
                f"and the site share them: {'; '.join(shared)}.")

    def _markdown(self) -> str:
        lines = [(f"The worksheets are files of the website's `{FOLDER}/` folder "
                 f"(seed {SITE_SEED}):"), ""]
        for sheet in self.sheets:
            names = ", ".join(f"`{paper}` with `{key}`" for paper, key in sheet_files(sheet))
            lines.append(f"- {sheet.title} ({len(sheet.templates)} questions, {sheet.marks} marks): {names}")
        lines += ["", f"The question bank for Moodle: `{FOLDER}/{moodle_file(self.topic)}`.", "", self._shared()]
        return "\n".join(lines) + "\n"

    def _repr_mimebundle_(self, include=None, exclude=None) -> dict[str, str]:
        return {"text/html": self._html(), "text/markdown": self._markdown(),
                "text/plain": self._markdown()}


def teachers_files(topic: Topic | None = None) -> TeachersFiles:
    """The page's list of sheets, keys and the Moodle file."""
    topic = topic_of(topic)
    return TeachersFiles(tuple(site_sheets(topic=topic)), topic)
