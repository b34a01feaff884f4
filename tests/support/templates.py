# ruff: noqa: RUF001  (the printed keys are typeset text: true minus)
"""The bank's templates as the tests take them, and answers written as a student writes them."""

from __future__ import annotations

from physics_figures import bank
from physics_figures import questions as q
from physics_figures.notation import DIGIT_GROUP_SEPARATOR, format_number, plain_number


def printed(key: str) -> q.Question:
    """A template's printed version (variant 0): what a first visit and the PDFs show."""
    return bank.TEMPLATES[key].variant(0)


def numbered_variants(key: str) -> list[tuple[int, dict]]:
    """A template's variants with their indices."""
    return list(enumerate(bank.TEMPLATES[key].variants))


def typed(value: float, sig_figs: int = 3) -> str:
    """A value as a student types it: ASCII digits, no grouping, to `sig_figs` figures."""
    return plain_number(format_number(value, sig_figs))


def sig3(x: float) -> str:
    """An answer written to 3 s.f., trailing zeros kept ("8.00", "133")."""
    return f"{x:#.3g}".rstrip(".")


#: Every template of the two-dimensional type, and the collisions and explosions along a line,
#: elastic or not, that have no graph to read (a graph template prints its graph) and give numbers
#: (collision-energy-explained describes four situations in words, with no numbers to draw).
DIAGRAMMED = sorted(key for key, template in bank.TEMPLATES.items()
                    if template.build.__module__.endswith((".two_d", ".momentum_line", ".elastic"))
                    and template.variant(0).graph is None and template.variant(0).givens)


def diagram_numbers(question: q.Question) -> list[str]:
    """The numbers a question's diagram must carry: each mass, speed and angle the text gives (not a time)."""
    return [given.text.replace(DIGIT_GROUP_SEPARATOR, "") for given in question.givens
            if given.unit not in ("s", "ms")]


#: Every question as the book printed it before it became a template: its givens (name,
#: value, unit, s.f.) and its key. The quick check's are the notes' (Notes, "Quick check"
#: and its "Answers", items 1-5); the practice questions' are the book's own. A first visit
#: (variant 0) and the PDFs must still show exactly these.
PRINTED = {
    "quick-check-1": ((("force", 5.0, "N", 2), ("mass", 2.0, "kg", 2), ("duration", 3.0, "s", 2)),
                      ("15 N s", "7.5 m s⁻¹")),
    "quick-check-2": ((("rifle mass", 4.0, "kg", 2), ("bullet mass", 0.010, "kg", 2),
                       ("bullet speed", 400.0, "m s^-1", 3)),
                      ("1.0 m s⁻¹",)),
    "quick-check-3": ((("mass", 70.0, "kg", 2), ("drag with the parachute open", 1500.0, "N", 2)),
                      ("687 N", "11.6 m s⁻² upwards")),
    "quick-check-4": ((("m1", 1.0, "kg", 2), ("u1", 6.0, "m s^-1", 2), ("m2", 2.0, "kg", 2)),
                      ("−2.0 m s⁻¹ (positive: the direction the 1.0 kg ball moves at first)",
                       "4.0 m s⁻¹ (positive: the direction the 1.0 kg ball moves at first)")),
    "quick-check-5": ((("mass", 12.0, "kg", 2), ("g on the Moon", 1.62, "m s^-2", 3)),
                      ("12 kg", "19.4 N")),
    "practice-tennis-ball": ((("mass", 57.0, "g", 2), ("speed", 50.0, "m s^-1", 2)), ("2.9 N s",)),
    "practice-wall-bounce": ((("mass", 0.16, "kg", 2), ("speed in", 15.0, "m s^-1", 2),
                              ("speed out", 10.0, "m s^-1", 2), ("contact time", 20.0, "ms", 2)),
                             ("4.0 N s away from the wall", "200 N away from the wall")),
    "practice-car-slowing": ((("mass", 800.0, "kg", 2), ("driving force", 1500.0, "N", 2),
                              ("resistive force", 2300.0, "N", 2)),
                             ("−1.0 m s⁻² (positive: forwards)",)),
    "practice-lift": ((("mass", 58.0, "kg", 2), ("acceleration", 1.5, "m s^-2", 2)), ("482 N",)),
    "practice-mars-rock": ((("weight on Mars", 5.4, "N", 2), ("g on Mars", 3.7, "m s^-2", 2)),
                           ("1.5 kg", "14.3 N")),
    "practice-hose": ((("mass per second", 4.0, "kg s^-1", 2), ("speed", 15.0, "m s^-1", 2)), ("60 N",)),
    "practice-trolleys-stick": ((("m1", 2.0, "kg", 2), ("u1", 3.0, "m s^-1", 2), ("m2", 1.0, "kg", 2),
                                 ("speed 2", 1.5, "m s^-1", 2)),
                                ("1.5 m s⁻¹ (positive: the direction the 2.0 kg trolley moves at first)",
                                 "6.75 J")),
    "practice-stopping-time": ((("mass", 900.0, "kg", 2), ("speed", 12.0, "m s^-1", 2),
                                ("force", 3600.0, "N", 2)),
                               ("3.0 s",)),
    "practice-towing": ((("car mass", 1000.0, "kg", 2), ("trailer mass", 500.0, "kg", 2),
                         ("driving force", 2400.0, "N", 2), ("car resistance", 300.0, "N", 2),
                         ("trailer resistance", 150.0, "N", 2)),
                        ("1.3 m s⁻²", "800 N")),
    "practice-pucks": ((("mass", 0.40, "kg", 2), ("speed before", 2.5, "m s^-1", 2),
                        ("speed after", 1.5, "m s^-1", 2), ("angle", 40.0, "°", 2)),
                       ("0.66 N s", "35.5°")),
}
