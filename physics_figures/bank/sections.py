"""The sections of the book a feedback sends a student back to, by id.

A part names the section its idea is taught in (``Part(see=...)``), and a named mistake or
a wrong option may name its own; the build turns each id into a link from the page the
question is on ("Revisit: Explosions (Conservation of momentum)"). An id is never guessed
from the feedback's words.
"""

from __future__ import annotations

#: id -> (page, section title; "" for the top of the page)
SECTIONS = {
    "first-law": ("book/understand/mass-and-first-law", ""),
    "momentum": ("book/understand/momentum-and-second-law", "Linear momentum"),
    "second-law": ("book/understand/momentum-and-second-law", "Newton's second law"),
    "momentum-time-graph": ("book/understand/momentum-time-graph", ""),
    "third-law": ("book/understand/third-law", ""),
    "weight": ("book/understand/weight", ""),
    "lift": ("book/understand/weight", "In a lift"),
    "friction": ("book/understand/friction-drag-terminal-velocity", "Friction and drag"),
    "skydiver": ("book/understand/friction-drag-terminal-velocity", "The skydiver"),
    "conservation": ("book/understand/conservation-of-momentum", "Using it in a straight line"),
    "explosions": ("book/understand/conservation-of-momentum", "Explosions"),
    "kinetic-energy": ("book/understand/elastic-and-inelastic", "Kinetic energy in the sticking trolleys"),
    "relative-speed": ("book/understand/elastic-and-inelastic", "Relative speed"),
    "two-d": ("book/understand/momentum-in-two-dimensions", "The vector picture"),
    "marks": ("book/exam/getting-the-marks", ""),
}

