"""The diagram a question prints (issue 37): its bodies before and after, each with its mass and
its velocities as arrows labelled as the text states them, drawn from one variant's
:class:`physics_figures.pictures.Diagram`. The arrows are vectors.py's; the bodies are the
collision diagram's (collisions.py) outlined shapes, round in a plane. Nothing is computed
here: every number is the question's, as the bank wrote it."""

from __future__ import annotations

import math

from matplotlib.figure import Figure
from matplotlib.patches import Arc, Circle, Rectangle

from ..notation import format_number
from ..pictures import Body, Diagram
from ._text import plain
from .book_figure import BookFigure
from .style import GUIDE, INK, MAIN, PAPER, SECOND, SMALL_TEXT, book_style, styled
from .vectors import _arrow

#: Inches per unit of the panels (a body's radius is 0.3 units, an arrow 1.6).
_SCALE = 0.36
_LENGTH = 1.6
_SPACING = 5.2  # between bodies in a panel: an arrow and its label fit between
_LEFT, _RIGHT, _HEIGHT = 2.6, 3.6, 2.2  # a panel's reach beyond its first and last bodies, and up and down
#: At most this wide: a phone shows it about 315 px wide, so its 12 pt text stays at 11 px or more.
_MAX_INCHES = 4.2
_MIN_WIDTH = 9.0  # a lone body's panel: room for an arrow's label either side
_HEADROOM = 0.5  # above an arrow's label: a line of text
_COLOURS = (MAIN, SECOND, INK)


def _direction_words(degrees: float, compass: bool) -> str:
    """Where an arrow points, in words, for the alt text."""
    names = (("east", "north", "west", "south") if compass else ("right", "up", "left", "down"))
    quarter = round((degrees % 360) / 90) % 4
    if math.isclose((degrees % 360) % 90, 0, abs_tol=1e-9):
        return names[quarter]
    return f"at {format_number(degrees % 360, decimals=0)} degrees anticlockwise from {names[0]}"


def _body(ax, x: float, body: Body, colour: str, *, plane: bool) -> None:
    shape = (Circle((x, 0), 0.3, facecolor=PAPER, edgecolor=colour, linewidth=2) if plane
             else Rectangle((x - 0.35, -0.3), 0.7, 0.6, facecolor=PAPER, edgecolor=colour, linewidth=2))
    ax.add_patch(shape)
    inside = len(body.name) <= 3  # a longer name goes under the body, with its mass
    if inside:
        ax.text(x, 0, body.name, ha="center", va="center", fontsize=SMALL_TEXT, color=INK, zorder=5)
    under = "\n".join(t for t in ("" if inside else body.name, body.mass, body.note) if t)
    if under:  # under the body, or over it when an arrow points down
        down = any(math.sin(math.radians(a.direction)) < -0.3 for a in body.arrows)
        ax.text(x, 0.45 if down else -0.45, under, ha="center", va="bottom" if down else "top",
                fontsize=SMALL_TEXT, color=INK)
    for arrow in body.arrows:
        angle = math.radians(arrow.direction)
        tail = (x + 0.3 * math.cos(angle), 0.3 * math.sin(angle))
        tip = (x + _LENGTH * math.cos(angle), _LENGTH * math.sin(angle))
        _arrow(ax, tail, tip, colour=colour)
        if abs(math.sin(angle)) < 0.2:  # along the line: over the arrow, clear of a body it points at
            ax.text((tail[0] + tip[0]) / 2, 0.2, arrow.label, ha="center", va="bottom", fontsize=SMALL_TEXT,
                    color=INK)
        else:
            ax.text(tip[0] + 0.15 * math.cos(angle), tip[1] + 0.15 * math.sin(angle), arrow.label,
                    ha="left" if math.cos(angle) > 0.2 else "right" if math.cos(angle) < -0.2 else "center",
                    va="bottom" if math.sin(angle) > 0 else "top", fontsize=SMALL_TEXT, color=INK)
        if arrow.angle_from is not None:
            start, end = sorted((arrow.angle_from, arrow.direction))
            ax.add_patch(Arc((x, 0), 1.6, 1.6, theta1=start, theta2=end, color=GUIDE, linewidth=1.3))
            ref = math.radians(arrow.angle_from)
            ax.plot([x, x + 1.2 * math.cos(ref)], [0, 1.2 * math.sin(ref)], color=GUIDE, linestyle="--", linewidth=1.2)
            # the label beside the arc, on the far side of the line it is measured from
            away = math.radians(arrow.angle_from + (-18 if arrow.direction > arrow.angle_from else 18))
            ax.text(x + 1.0 * math.cos(away), 1.0 * math.sin(away), arrow.angle_label, ha="center",
                    va="center", fontsize=SMALL_TEXT, color=INK)


def _panel(ax, title: str, bodies: tuple[Body, ...], diagram: Diagram, *, plane: bool, compass: bool) -> None:
    for index, body in enumerate(bodies):
        _body(ax, index * _SPACING, body, _COLOURS[index % len(_COLOURS)], plane=plane)
    right = (len(bodies) - 1) * _SPACING
    if diagram.wall:
        ax.plot([right + 4.4, right + 4.4], [-_HEIGHT, _HEIGHT], color=INK, linewidth=4)
    if compass:
        for tip, name, where in (((-2.2, 1.9), "N", {"ha": "center", "va": "bottom"}),
                                 ((-1.5, 1.2), "E", {"ha": "left", "va": "center"})):
            ax.annotate("", xy=tip, xytext=(-2.2, 1.2), arrowprops={"arrowstyle": "-|>", "color": GUIDE})
            ax.text(tip[0] + (0.1 if name == "E" else 0), tip[1] + (0.05 if name == "N" else 0), name,
                    fontsize=SMALL_TEXT, color=GUIDE, **where)
    ax.set_title(title, fontsize=SMALL_TEXT, color=INK)
    ax.set_xlim(-_LEFT, right + _RIGHT)
    ax.set_ylim(-_HEIGHT, _HEIGHT + _HEADROOM)  # an upward arrow's label stays under the title
    ax.set_aspect("equal")
    ax.set_axis_off()
    # Hidden too, not only left undrawn: else constrained layout and the title's placement lay
    # out ticks and tick labels nobody sees, half of a diagram's drawing time.
    ax.xaxis.set_visible(False)
    ax.yaxis.set_visible(False)


@styled
def plot_question_diagram(diagram: Diagram) -> Figure:
    panels = [(title, bodies) for title, bodies in (("Before", diagram.before), ("After", diagram.after)) if bodies]
    # Before above After, not side by side: narrow enough that a phone shows its text at 11 px or
    # more (tests/browser/test_reading_browser.py), the panels sharing one scale.
    width = max(_MIN_WIDTH, *(_LEFT + _RIGHT + (len(bodies) - 1) * _SPACING for _, bodies in panels))
    scale = min(_SCALE, _MAX_INCHES / width)  # three bodies abreast: the same inches, text relatively larger
    figure = Figure(figsize=(width * scale, len(panels) * ((2 * _HEIGHT + _HEADROOM) * scale + 0.3)), layout="constrained")
    plane = diagram.compass or diagram.wall or any(
        a.direction % 180 for b in (*diagram.before, *diagram.after) for a in b.arrows)
    axes = figure.subplots(len(panels), 1, squeeze=False)[:, 0]
    for index, (ax, (title, bodies)) in enumerate(zip(axes, panels, strict=True)):
        _panel(ax, title, bodies, diagram, plane=plane, compass=diagram.compass and index == 0)
        # one width, so one scale for both panels, each panel's bodies centred in it
        pad = (width - (_LEFT + _RIGHT + (len(bodies) - 1) * _SPACING)) / 2
        ax.set_xlim(-_LEFT - pad, (len(bodies) - 1) * _SPACING + _RIGHT + pad)
    return figure


def _arrow_words(arrow, diagram: Diagram) -> str:
    """"moving right at 2.5 m/s", "moving at 1.5 m/s at 40° above the x-direction"."""
    if arrow.angle_from is None:
        return f"moving {_direction_words(arrow.direction, diagram.compass)} at {arrow.label}"
    angle = math.radians(arrow.direction)
    if diagram.wall:
        side = "towards the wall" if math.cos(angle) > 0 else "away from the wall"
        return f"moving {side} at {arrow.label}, at {arrow.angle_label} to the wall"
    up = arrow.direction % 360 < 180
    if diagram.compass:
        return f"moving at {arrow.label}, {arrow.angle_label} {'north' if up else 'south'} of east"
    return f"moving at {arrow.label}, {arrow.angle_label} {'above' if up else 'below'} the x-direction"


def diagram_alt(diagram: Diagram) -> str:
    """The diagram in words, with every number it prints."""
    def said(body: Body) -> str:
        mass = f" of mass {body.mass}" if body.mass else ""
        moves = "; ".join(_arrow_words(a, diagram) for a in body.arrows)
        name = f"piece {body.name}" if body.name.isdigit() else body.name or "a body"
        return f"{name}{mass}, " + (moves or body.note)

    parts = [f"{title}: " + "; ".join(said(b) for b in bodies) + "."
             for title, bodies in (("Before", diagram.before), ("After", diagram.after)) if bodies]
    wall = " A wall stands on the right." if diagram.wall else ""
    return plain("Diagram. " + " ".join(parts) + wall)


def question_diagram(diagram: Diagram) -> BookFigure:
    """A question's diagram as the site, the book and the sheets print it."""
    with book_style():
        figure = plot_question_diagram(diagram)
    return BookFigure("question-diagram", figure, "", diagram_alt(diagram))
