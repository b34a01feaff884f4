"""The diagrams of the two-dimensional and collision templates (issue 37): what each text
describes, labelled with the variant's givens as the text prints them (notation.format_number),
never with an answer. physics_figures.figures.question_diagram draws them."""

from __future__ import annotations

from ..notation import format_number as n
from ..questions import Arrow, Body, Diagram

VELOCITY = "m s⁻¹"


def speed(value: float, sig_figs: int = 2) -> str:
    """A given speed as a label: "2.5 m s⁻¹"."""
    return f"{n(value, sig_figs)} {VELOCITY}"


def kg(value: float, sig_figs: int = 2) -> str:
    return f"{n(value, sig_figs)} kg"


def glancing(mass_a: float, speed_before: float, speed_after: float, angle: float,
             mass_b: float | None = None) -> Diagram:
    """A moving along the x-direction hits B at rest; after, A moves at ``angle`` above the line
    and B's velocity is asked (its direction is not drawn: a part may ask which side)."""
    b_mass = "" if mass_b is None else kg(mass_b)
    return Diagram(
        before=(Body("A", kg(mass_a), (Arrow(speed(speed_before), 0.0),)), Body("B", b_mass, note="at rest")),
        after=(Body("A", "", (Arrow(speed(speed_after), angle, 0.0, f"{n(angle, 2)}°"),)),
               Body("B", "", note="velocity ?")))


def explosion_from_rest(pieces: tuple[tuple[float, float | None, float | None], ...]) -> Diagram:
    """A shell at rest explodes; each piece (mass, speed or None, direction in degrees or None)
    flies off as given, an unknown one marked "velocity ?"."""
    after = tuple(Body(str(i), kg(m), (Arrow(speed(v), d),) if v is not None else (), "" if v is not None
                       else "velocity ?") for i, (m, v, d) in enumerate(pieces, start=1))
    return Diagram(before=(Body("shell", "", note="at rest"),), after=after, compass=True)


def at_right_angles(mass_a: float, speed_a: float, mass_b: float, speed_b: float) -> Diagram:
    """A due east and B due north; after, together, at a velocity asked for."""
    return Diagram(before=(Body("A", kg(mass_a), (Arrow(speed(speed_a), 0.0),)),
                           Body("B", kg(mass_b), (Arrow(speed(speed_b), 90.0),))),
                   after=(Body("A+B", "", note="velocity ?"),), compass=True)


def wall_bounce(mass: float, speed_: float, angle: float) -> Diagram:
    """A ball hits a wall on its right at ``angle`` to the wall, and leaves at the same angle."""
    theta = f"{n(angle, 2)}°"
    return Diagram(before=(Body("ball", kg(mass), (Arrow(speed(speed_), 90.0 - angle, 90.0, theta),)),),
                   after=(Body("ball", "", (Arrow(speed(speed_), 90.0 + angle, 90.0, theta),)),), wall=True)


def explosion_moving(mass: float, speed_: float, piece: float, piece_speed: float, angle: float,
                     north: bool) -> Diagram:
    """A shell moving east splits; one piece flies at ``angle`` north or south of east, the other's
    velocity is asked."""
    direction = angle if north else -angle
    return Diagram(before=(Body("shell", kg(mass), (Arrow(speed(speed_), 0.0),)),),
                   after=(Body("1", kg(piece), (Arrow(speed(piece_speed), direction, 0.0, f"{n(angle, 2)}°"),)),
                          Body("2", "", note="velocity ?")), compass=True)


def line(before: tuple[tuple[str, float | None], ...], after: tuple[tuple[str, float | None], ...] = (), *, names: tuple[str, ...] = ("A", "B"),
         speed_figures: int = 2) -> Diagram:
    """Bodies along a line, before and after: (mass as printed or "", signed velocity (right
    positive) or None when asked, 0 at rest) each. A body's name is from ``names``; one body
    after for two before is the pair stuck together."""
    def body(name: str, mass: str, velocity: float | None) -> Body:
        if velocity is None:
            return Body(name, mass, note="velocity ?")
        if velocity == 0:
            return Body(name, mass, note="at rest")
        return Body(name, mass, (Arrow(speed(abs(velocity), speed_figures), 0.0 if velocity > 0 else 180.0),))

    together = len(after) == 1 and len(before) == 2
    pair = "+".join(name for name in names[:2] if name) or "both"
    return Diagram(before=tuple(body(names[i], *b) for i, b in enumerate(before)),
                   after=tuple(body(pair if together else names[i], *a) for i, a in enumerate(after)))
