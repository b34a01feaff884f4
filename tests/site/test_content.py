"""The built book carries all of the notes' content.

Expected strings are copied from the notes (../shared/notes/000_e3ec34309135aedb.txt);
the numbers come from physics_figures.answers (checked against the notes in
test_answers.py). Maths is compared in its TeX form: $...$ in the notes becomes
\\(...\\), read from the data-tex attribute the site keeps beside each rendered formula.
"""

# ruff: noqa: RUF001  (expected text keeps the notes' typography: en dashes, times signs)

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest

from physics_figures import answers

pytestmark = [pytest.mark.site]

ROOT = Path(__file__).resolve().parents[2]


class _ArticleText(HTMLParser):
    """Text of the page's <article>, without header-link "#" anchors, scripts or styles."""

    SKIPPED = frozenset({"script", "style"})
    BLOCKS = frozenset({"p", "li", "div", "section", "td", "th", "tr", "table", "caption", "br",
                        "h1", "h2", "h3", "h4", "ul", "ol", "dl", "dt", "dd", "details", "summary"})

    def __init__(self):
        super().__init__()
        self.parts: list[str] = []
        self._article_depth = 0
        self._skip_depth = 0

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "article":
            self._article_depth += 1
        if self._skip_depth or tag in self.SKIPPED or "headerlink" in (attrs.get("class") or ""):
            self._skip_depth += 1
        elif "data-tex" in attrs:  # maths rendered to SVG: read its TeX source instead
            if self._article_depth:
                inline = tag == "span"
                self.parts.append(rf"\({attrs['data-tex']}\)" if inline else rf" \[{attrs['data-tex']}\] ")
            self._skip_depth += 1

    def handle_endtag(self, tag):
        if self._skip_depth:
            self._skip_depth -= 1
        if tag == "article":
            self._article_depth -= 1
        if tag in self.BLOCKS:  # words in inline tags (strong, a, span) run on
            self.parts.append(" ")

    def handle_data(self, data):
        if self._article_depth and not self._skip_depth:
            self.parts.append(data)


def normalise(text: str) -> str:
    """One space between words; straight quotes (Sphinx curls them); $x$ maths as \\(x\\)."""
    text = re.sub(r"\$([^$]+)\$", r"\\(\1\\)", text)
    text = text.replace("\u2019", "'").replace("\u201c", '"').replace("\u201d", '"')
    return re.sub(r"\s+", " ", text).strip()


def page_html(site_dir: Path, page: str) -> str:
    return (site_dir / f"{page}.html").read_text(encoding="utf-8")


def page_text(site_dir: Path, page: str) -> str:
    parser = _ArticleText()
    parser.feed(page_html(site_dir, page))
    return normalise("".join(parser.parts))


def fragment_text(html: str) -> str:
    """Text of an HTML fragment (a list item, a table cell), maths as TeX."""
    parser = _ArticleText()
    parser._article_depth = 1  # a fragment is read whole
    parser.feed(html)
    return normalise("".join(parser.parts))


def assert_on_page(site_dir, page, expected):
    text = page_text(site_dir, page)
    missing = [phrase for phrase in expected if normalise(phrase) not in text]
    assert not missing, f"{page} is missing {missing}"


# --- Intro: What you need to know ----------------------------------------------------

LEARNING_OUTCOMES = [
    "Understand mass as the property of an object that resists a change in its motion.",
    ("Recall and use $F = ma$, knowing that the acceleration is always in the same direction "
    "as the resultant force."),
    "Define and use linear momentum: momentum = mass $\\times$ velocity.",
    "Define and use force as the rate of change of momentum.",
    "State and apply Newton's three laws of motion.",
    ("Describe and use weight as the effect of a gravitational field on a mass, and recall "
    "that weight = mass $\\times$ acceleration of free fall ($W = mg$)."),
    ("Explain friction and drag (air resistance) qualitatively: they oppose motion, and drag "
    "grows as the speed grows. No formulas or coefficients are needed."),
    ("Describe and explain how an object moves in a uniform gravitational field when there is "
    "air resistance."),
    ("Understand terminal velocity: an object moving against a resistive force can reach a "
    "constant velocity."),
    "State the principle of conservation of momentum.",
    ("Apply conservation of momentum to elastic and inelastic collisions and explosions, in "
    "one and in two dimensions."),
    ("Recall that in an elastic collision the total kinetic energy is conserved, and the "
    "relative speed of approach equals the relative speed of separation."),
    ("Understand that momentum is always conserved in an interaction, while kinetic energy "
    "may change."),
]


def test_intro_lists_the_thirteen_learning_outcomes_in_order(site_dir):
    html = page_html(site_dir, "book/intro")
    items = re.search(r"<ol[^>]*>(.*?)</ol>", html, re.DOTALL).group(1)
    found = re.findall(r"<li>(.*?)</li>", items, re.DOTALL)
    shown = [fragment_text(item) for item in found]
    assert len(shown) == len(LEARNING_OUTCOMES)
    # The notes' words, then the pages that teach the outcome (issue "reading", item 5).
    for item, text, outcome in zip(found, shown, LEARNING_OUTCOMES, strict=True):
        assert text.startswith(normalise(outcome)), text
        assert re.fullmatch(r" Taught in: .+\.", text[len(normalise(outcome)):]), text
        assert re.search(r'<a class="reference internal" href="understand/[a-z-]+\.html', item), item


def test_intro_says_what_is_not_needed_and_points_to_the_recap(site_dir):
    assert_on_page(site_dir, "book/intro", [
        "Kinematics describes motion; this topic explains it with forces.",
        ("The coefficient of restitution and coefficients of friction and viscosity are not "
        "needed."),
    ])
    assert 'href="recap.html' in page_html(site_dir, "book/intro")


def test_recap_replaces_the_read_first_links(site_dir):
    assert_on_page(site_dir, "book/recap", [
        "Kinematics", "Physical quantities and units", "Forces, density and pressure",
        "v^2 &= u^2 + 2as", "s &= ut + \\tfrac{1}{2}at^2",
        "gradient of a velocity–time graph is the acceleration",
        "area under a velocity–time graph is the displacement",
        "1\\ \\text{N} = 1\\ \\text{kg m s}^{-2}", "F = \\rho g V",
        "12 ms = 0.012 s",
    ])
    key_facts = page_html(site_dir, "book/exam/key-facts")
    assert 'href="../recap.html#recap-kinematics"' in key_facts
    assert 'href="../recap.html#recap-upthrust"' in key_facts


# --- Understand it -------------------------------------------------------------------

UNDERSTAND_PAGES = {
    "mass-and-first-law": ("Mass and Newton's first law", [
        "property of an object that resists a change in its motion",
        "A full shopping trolley is harder to get moving",
        "Mass is a scalar, measured in kg, and it is the same wherever the object is",
        ("An object stays at rest, or keeps moving at a constant velocity, unless a resultant "
        "force acts on it."),
        "A car cruising at a steady 25 m s",
    ]),
    "momentum-and-second-law": ("Momentum and Newton's second law", [
        "Linear momentum is the product of mass and velocity.",
        "which is the same as N s",
        ("The resultant force on an object is proportional to its rate of change of momentum, "
        "and acts in the direction of that change."),
        "With SI units the constant of proportionality is 1",
        "Force is the rate of change of momentum.",
        "The acceleration is always in the direction of the resultant force.",
        ("A car braking while it moves forwards has a resultant force, and an acceleration, "
        "backwards."),
        "Force × time = change in momentum:",
        "That is why a crumple zone",
        "a rocket burning fuel",
    ]),
    "momentum-time-graph": ("Reading a momentum–time graph", [
        "gradient of a momentum–time graph is the resultant force",
        "area under a force–time graph is the change in momentum",
        "A straight line means a constant force.",
        "the object stops and then moves the other way, with the same force still acting",
    ]),
    "third-law": ("Newton's third law", [
        ("If body A exerts a force on body B, then B exerts a force on A that is equal in size "
        "and opposite in direction."),
        "act on different bodies (so they never cancel each other out)",
        "are the same type of force (both gravitational, both contact, both electric)",
        "act for the same time",
        "the pair of that force is the book pulling the Earth up",
        ("It equals \\(W\\) only because the book is in equilibrium, which is Newton's first law, "
        "not the third."),
    ]),
    "weight": ("Weight", [
        "Weight is the force on a mass caused by a gravitational field.",
        "Mass stays the same; weight depends on where you are.",
        "and you feel heavier", "and you feel lighter",
        "Your weight, \\(mg\\), doesn't change in any of these; only the contact force does.",
    ]),
    "friction-drag-terminal-velocity": ("Friction, drag and terminal velocity", [
        "Friction acts where two surfaces slide, or try to slide, over each other",
        "increases as the speed increases",
        "That one idea explains every falling-object question.",
        "A (just after jumping):", "A to B:", "C (terminal velocity):",
        "D (parachute opens):", "D to E:", "E:",
        "slows down but is still moving down",
        "at a lower terminal velocity of 5.0 m s",
        "At both terminal velocities the drag is the same size: the weight.",
        "What affects terminal velocity",
        "a snowflake, sitting upright on a bike",
        "The height it is dropped from doesn't matter.",
        "Upthrust in a liquid",
        "Thrown upwards with air resistance",
        ("the ball reaches a lower height, takes less time to get there, and comes back slower "
        "than it was thrown"),
        "The resultant force is largest at the start",
    ]),
    "conservation-of-momentum": ("Conservation of momentum", [
        ("The total momentum of a system of objects stays constant, provided no resultant "
        "external force acts on the system (an isolated system)."),
        "So B gains exactly the momentum that A loses",
        "Explosions start with zero total momentum, so they end with zero total.",
        "The lighter part always moves faster.",
        "why a nucleus recoils when it emits an α-particle",
    ]),
    "elastic-and-inelastic": ("Elastic and inelastic collisions", [
        "Momentum is conserved in every collision and explosion in an isolated system.",
        "relative speed of approach equals the relative speed of separation",
        "(thermal energy, sound, permanent deformation)",
        "Objects that stick together always have an inelastic collision.",
        "In an explosion the kinetic energy goes up",
        "Relative speed is how fast the gap between the objects closes or opens.",
        "much easier to use than the kinetic-energy one",
    ]),
    "momentum-in-two-dimensions": ("Momentum in two dimensions", [
        "it is conserved in each direction separately",
        "Puck P has momentum 1.00 N s and hits puck Q, which is at rest.",
        "Afterwards P has 0.60 N s at 50° to its old line",
        "must end where the arrow before the collision ends",
        # The physics issue: a collision's triangle is a resultant, not a closed triangle.
        "So the arrow before is the resultant of the two arrows after, drawn tip to tail",
        "that picture is for an explosion from rest",
    ]),
}


@pytest.mark.parametrize("page", sorted(UNDERSTAND_PAGES))
def test_understand_page_has_its_title_and_ideas(site_dir, page):
    title, phrases = UNDERSTAND_PAGES[page]
    text = page_text(site_dir, f"book/understand/{page}")
    assert re.match(rf"\d+\. {re.escape(normalise(title))} ", text)  # numbered chapter
    assert_on_page(site_dir, f"book/understand/{page}", phrases)


# Each page that prints computed numbers, and the answers function that computes them.
GLUED_PAGES = {
    "book/understand/momentum-and-second-law": "momentum_and_second_law",
    "book/understand/momentum-time-graph": "momentum_time_graph",
    "book/understand/weight": "weight_and_lift",
    "book/understand/friction-drag-terminal-velocity": "terminal_velocity",
    "book/understand/conservation-of-momentum": "conservation_of_momentum",
    "book/understand/elastic-and-inelastic": "elastic_and_inelastic",
    "book/understand/momentum-in-two-dimensions": "momentum_in_two_dimensions",
    "book/exam/method-newtons-laws": "method_newtons_laws",
    "book/exam/method-drag": "method_drag",
    "book/exam/method-force-momentum": "method_force_momentum",
    "book/exam/method-definitions": "method_definitions",
    "book/exam/example-1": "example_1",
    "book/exam/example-2": "example_2",
    "book/exam/example-3": "example_3",
    "book/exam/example-4": "example_4",
    "book/exam/example-5": "example_5",
    "book/exam/common-mistakes": "common_mistakes",
}


@pytest.mark.parametrize("page", sorted(GLUED_PAGES))
def test_every_glued_number_is_printed_as_computed(site_dir, page):
    source = (ROOT / f"{page}.md").read_text(encoding="utf-8")
    function = GLUED_PAGES[page]
    assert f"glue_all({function}())" in source
    names = re.findall(r"\{glue:text\}`([a-z0-9_]+)`", source)
    computed = answers.ALL[function]()
    expected = [computed[name].text for name in names]
    shown = re.findall(r'<span class="pasted-text">([^<]*)</span>', page_html(site_dir, page))
    assert shown == expected


def test_every_page_with_numbers_uses_its_answers():
    glued = {path.relative_to(ROOT).with_suffix("").as_posix()
             for path in (ROOT / "book").rglob("*.md") if "{glue:text}" in path.read_text()}
    assert glued == set(GLUED_PAGES)


# --- Exam skills: key facts ----------------------------------------------------------

# (a distinctive part of the formula row, its status), in the notes' order.
KEY_FACTS = [
    ("Momentum \\(p = mv\\) (a vector; units", "Learn it"),
    ("Force = rate of change of momentum", "Learn it"),
    ("(resultant force, constant mass;", "Learn it"),
    ("= area under a force–time graph", "Learn it"),
    ("Gradient of a momentum–time graph = resultant force", "Learn it"),
    ("Force from a steady stream (jet, rocket, hose):", "Learn it"),
    ("Weight \\(W = mg\\)", "Learn it"),
    ("\\(g = 9.81\\ \\text{m s}^{-2}\\)", "Given"),
    ("Conservation of momentum: \\(m_1 u_1 + m_2 u_2 = m_1 v_1 + m_2 v_2\\) (isolated system)",
     "Learn it"),
    ("Kinetic energy \\(E_k = \\frac{1}{2}mv^2\\); also", "Learn it"),
    ("conserved; relative speed of approach = relative speed of separation", "Learn it"),
    ("At terminal velocity: resultant force = 0 (weight = drag, plus upthrust in a fluid)",
     "Learn it"),
    ("Upthrust \\(F = \\rho g V\\) (from Forces, density and pressure)", "Given"),
    ("\\(v^2 = u^2 + 2as\\), \\(s = ut + \\frac{1}{2}at^2\\) (from Kinematics)", "Given"),
]


def table_rows(html: str, table_id: str) -> list[list[str]]:
    table = re.search(rf'<table[^>]*id="{table_id}".*?</table>', html, re.DOTALL).group(0)
    body = table.split("<tbody>", 1)[1]
    return [[fragment_text(cell) for cell in
             re.findall(r"<td>(.*?)</td>", row, re.DOTALL)]
            for row in re.findall(r"<tr[^>]*>(.*?)</tr>", body, re.DOTALL)]


def test_key_facts_table_has_every_row_with_its_status(site_dir):
    html = page_html(site_dir, "book/exam/key-facts")
    rows = table_rows(html, "table-key-facts")
    assert len(rows) == len(KEY_FACTS)
    for (formula, status), row in zip(KEY_FACTS, rows, strict=True):
        assert normalise(formula) in row[0] and row[1] == status
    assert_on_page(site_dir, "book/exam/key-facts", [
        ('"Given" means it is on the data sheet in the exam. "Learn it" means you must '
        "remember it."),
    ])


# --- Exam skills: how to do it -------------------------------------------------------

QUESTION_TYPES = {  # page: (type, count, method phrases, variation leads), from the notes
    "method-newtons-laws": ("Newton's laws, F = ma and third-law pairs", 49, [
        "Draw the object and every force on it:", "Choose a positive direction",
        "Write resultant force", "then check the sign",
    ], [
        "Rockets and lifts:", "Connected objects", "A new force suddenly acts:",
        '"Which pair is a Newton\'s third law pair?"', "Balanced forces:",
        "From a velocity–time graph:", "Constant force, mass falling",
        "Stopping distance with a constant force:",
    ]),
    "method-drag": ("Drag, air resistance and terminal velocity", 48, [
        "List the forces:", "Resultant force = the forces in the direction of motion minus",
        "Explain with a chain:", "At terminal velocity:",
    ], [
        "Describe and explain the motion", "Forces at a point on the graph:", "Graph shapes:",
        "Calculations at terminal velocity:", "Acceleration at a given instant:",
        "Thrown upwards in air:", "Comparing objects:", "Why a force can't be drag:",
    ]),
    "method-force-momentum": ("Force as rate of change of momentum", 44, [
        "Choose a positive direction.", "Change in momentum", "Average force",
        "Direction:",
    ], [
        "Momentum–time graph:", "Force–time graph:", "A steady stream",
        "Change in momentum at an angle:", "Constant force, find the time:",
        "Momentum and kinetic energy together:", "Sketching from a momentum–time graph:",
    ]),
    "method-definitions": ("Mass, weight and the definitions", 36, [
        "Learn these word for word in meaning",
        "Mass: the property of an object that resists a change in its motion.",
        "Weight: the force on a mass due to a gravitational field;",
        "Momentum: the product of mass and velocity.",
        "Force: the rate of change of momentum.",
        ("Newton's second law: the resultant force is proportional to the rate of change of "
        "momentum (and in its direction)."),
        ("Principle of conservation of momentum: the total momentum of a system is constant, "
        "provided no resultant external force acts on it."),
    ], [
        "Mass and weight on another planet:", "Finding \\(g\\) from a weight and a mass:",
        '"Which statement is correct?":', "Weight in a moving spacecraft:",
    ]),
    "method-momentum-line": ("Conservation of momentum in a straight line", 23, [
        "Draw before and after", "Write total momentum before = total momentum after",
        "The sign of the answer gives its direction.", "If asked about energy",
    ], [
        "Objects stick together:", "Explosions and recoil", "Kinetic energy from an explosion:",
        "Something dropped into a moving cart:", "Two stages:",
        "Percentage of kinetic energy lost", "Contact force during the collision:",
    ]),
    "method-collisions": ("Elastic and inelastic collisions", 23, [
        "What is conserved?", "To decide elastic or inelastic",
        "To find two unknown velocities after an elastic collision", "Solve simultaneously:",
    ], [
        "Equal masses, one at rest, elastic:", "Light object hits a heavy one at rest, elastic:",
        '"Which row / which diagram is possible?"', "Bouncing ball:", "A statement that is wrong:",
    ]),
    "method-two-dimensions": ("Conservation of momentum in two dimensions", 12, [
        "Choose two directions", "Resolve every momentum", "Conserve each direction separately.",
        "Combine",
    ], [
        "Given both angles, find the speeds:", "Explosion into three pieces from rest:",
        "Two objects meeting at angles and sticking together:", "Vector-diagram options:",
        '"Which diagram is impossible?":',
    ]),
}


def test_how_to_table_counts_each_question_type(site_dir):
    html = page_html(site_dir, "book/exam/how-to")
    rows = table_rows(html, "table-question-types")
    assert rows == [[normalise(kind), str(count)] for kind, count, *_ in QUESTION_TYPES.values()]
    assert_on_page(site_dir, "book/exam/how-to", [
        ("In the Paper 1 and Paper 2 questions we have tagged for this topic (195 different "
        "questions, 2021–2025; 6 more appear on two papers), the types came up this often."),
        "27 of the 195 questions mix two or more types, so the counts add up to more than 195.",
    ])


@pytest.mark.parametrize("page", sorted(QUESTION_TYPES))
def test_each_question_type_has_its_method_and_every_variation(site_dir, page):
    kind, count, method, variations = QUESTION_TYPES[page]
    text = page_text(site_dir, f"book/exam/{page}")
    assert text.startswith(normalise(kind).replace("F = ma", "\\(F = ma\\)"))
    assert_on_page(site_dir, f"book/exam/{page}",
                   [f"came up in {count} of the 195 tagged questions",
                    "Variations you will meet", *method, *variations])
    if page != "method-definitions":  # that one is a list of definitions, not steps
        # The method is a numbered list of four steps, as in the notes.
        html = page_html(site_dir, f"book/exam/{page}")
        steps = re.search(r"<ol[^>]*>(.*?)</ol>", html, re.DOTALL).group(1)
        assert len(re.findall(r"<li>", steps)) >= 4


# --- Exam skills: worked examples ----------------------------------------------------

# The physics issue corrects the notes' table (M1 for calculation steps, "A1 needs the M
# mark"): 9702 marks calculation steps C1, and keeps M1/A1 for show that, explanations
# and stated principles.
MARK_CODES = [
    ["C1", ("compensatory mark: for a step of a calculation. A right final answer earns it "
            'without the working, because a bare correct answer gets full marks (except in "show '
            'that" questions).')],
    ["M1", ('method mark: for the method in a "show that", an explanation or a stated principle. '
            "The A1 after it depends on it.")],
    ["A1", ("accuracy mark: for the answer (to 2 or more significant figures) or the conclusion. "
            "After an M1 it is given only if the M1 is.")],
    ["B1", ("independent mark: for a single point on its own, such as a recalled fact, a "
            "direction, or a one-mark result.")],
]

EXAMPLES = {  # page: question phrases with their marks, and solution phrases
    "example-1": [
        "A car of mass 1200 kg tows a trailer of mass 400 kg along a straight, level road.",
        "Calculate the acceleration of the car and trailer. [2]",
        "Calculate the tension in the tow bar. [2]",
        ("State the size and direction of the force that the trailer exerts on the car, and name "
        "the law you used. [2]"),
        "Treat the car and trailer as one object.", "For the trailer alone:",
        "Check with the car alone:", "backwards (opposite to the motion), by Newton's third law",
    ],
    "example-2": [
        "A tennis ball of mass 0.058 kg hits a vertical wall at 24 m s",
        "Calculate the change in momentum of the ball. [2]",
        "Calculate the average force exerted on the ball by the wall. [1]",
        "State and explain whether the collision is elastic. [2]",
        "State the average force exerted on the wall by the ball. [1]",
        "Take the direction the ball bounces back as positive",
        "so the collision is inelastic. A1", "towards the wall (Newton's third law). B1",
    ],
    "example-3": [
        "A trolley A of mass 0.60 kg moves at 2.5 m s",
        "State the principle of conservation of momentum. [2]",
        "Calculate the velocity of B after the collision. [2]",
        "Show that the collision is elastic, using relative speeds. [2]",
        "The trolleys are in contact for 0.050 s. Calculate the average force on B. [2]",
        ("The total momentum of a system stays constant M1, provided no resultant external force "
        "acts (an isolated system). A1"),
        "They are equal, so the collision is elastic. A1", "in A's original direction. A1",
    ],
    "example-4": [
        "On a frictionless air table, a puck X of mass 0.20 kg moving at",
        ("Calculate the components of the momentum of Y after the collision, along and at right "
        "angles to X's original direction. [3]"),
        "Calculate the speed of Y and its direction. [2]",
        "Determine whether the collision is elastic. [2]",
        "on the other side of the line from X. A1", "to X's original direction. B1",
        "Less than before, so it is inelastic",
        # The physics issue: the notes square 1.74 and print 0.456, but 1.74^2 gives 0.454;
        # the working keeps 1.744 so that it gives the printed value.
        "\\frac{1}{2} \\times 0.30 \\times\\) 1.744\\(^2 =\\) 0.324 \\(+\\) 0.456",
        "shows the momentum before as the resultant of X's and Y's momenta after, drawn tip to tail",
    ],
    "example-5": [
        "A small metal sphere of mass 0.012 kg and volume 1.5",
        ("Describe and explain the motion of the sphere from the moment it is released until it "
         "reaches terminal velocity. [4]"),
        "Calculate the upthrust on the sphere. [2]",
        "weight = drag + upthrust", "the density of the oil",
    ],
}

# Parts of the worked examples that earn M1: they ask to show that, to explain, or to state
# a principle. Any other part is a calculation or a single point, marked C1/A1 or B1.
METHOD_MARKED_PARTS = {("example-2", "c"), ("example-3", "a"), ("example-3", "c"), ("example-5", "a")}
METHOD_WORDS = re.compile(r"\b(Show that|explain|State the principle)", re.IGNORECASE)


def _example_parts(source: str, fence: str) -> dict[str, str]:
    """{part letter: text} of the exercise or solution block of an example page."""
    block = re.search(rf"(`{{3,}})\{{{fence}\}}.*?\n(.*?)\n\1(?!`)", source, re.DOTALL).group(2)
    pieces = re.split(r"(?:^|\n)\**\(([a-z])\)\**", block)
    return dict(zip(pieces[1::2], pieces[2::2], strict=True))


@pytest.mark.parametrize("page", [f"example-{n}" for n in range(1, 6)])
def test_worked_example_marks_follow_9702_codes(page):
    """No M1 on a calculation step; every A1 after a C1 or M1 of its own part; the codes of
    each part add up to the [n] its question prints."""
    source = (ROOT / "book" / "exam" / f"{page}.md").read_text(encoding="utf-8")
    questions, solutions = _example_parts(source, "exercise"), _example_parts(source, "solution")
    assert questions.keys() == solutions.keys()
    for part, question in questions.items():
        codes = re.findall(r"\*\*([CMAB]1)\*\*", solutions[part])
        flagged = (page, part) in METHOD_MARKED_PARTS
        assert flagged == bool(METHOD_WORDS.search(question)), (page, part)
        if not flagged:
            assert "M1" not in codes, f"{page} ({part}): M1 on a calculation step"
        for index, code in enumerate(codes):
            if code == "A1":
                assert {"C1", "M1"} & set(codes[:index]), f"{page} ({part}): an A1 with no mark before it"
        assert len(codes) == int(re.search(r"\*\*\[(\d)\]\*\*", question).group(1)), (page, part)


def test_worked_examples_explain_the_mark_codes(site_dir):
    rows = table_rows(page_html(site_dir, "book/exam/worked-examples"), "table-mark-codes")
    assert rows == MARK_CODES


@pytest.mark.parametrize("page", sorted(EXAMPLES))
def test_worked_example_shows_the_question_and_hides_the_solution(site_dir, page):
    assert_on_page(site_dir, f"book/exam/{page}", EXAMPLES[page])
    html = page_html(site_dir, f"book/exam/{page}")
    assert html.index('class="exercise') < html.index('class="solution dropdown')
    assert "<strong>A1</strong>" in html  # the marks are shown in bold, as in a mark scheme


# --- Exam skills: mistakes, marks, past papers ----------------------------------------

COMMON_MISTAKES = [
    'Defining force as "mass × acceleration".',
    "Leaving out the condition in the conservation principle.",
    "Wrong signs.", "Examiners see at least one wrong sign in many answers.",
    "Using the wrong momentum for a force.",
    "Change in momentum vs change in the size of momentum.",
    "Mixing up the resultant force with one of the forces.",
    "Wrong third-law pairs.", "Explaining terminal velocity only halfway.",
    "Thinking the skydiver moves upwards when the parachute opens.",
    "Forgetting upthrust in a liquid", "Using kinetic energy instead of momentum",
    "Treating mass as changing with \\(g\\).",
]

GETTING_THE_MARKS = [
    '"Define" and "state":', "Show the equation with numbers.",
    "Physics mark schemes give a C1 mark", "Vectors need directions.",
    '"Describe and explain"', "Force diagrams:", "Elastic or inelastic:",
    'A number without "so it is inelastic" loses the mark.', "Sketches:", "Units:",
    "Multiple choice:",
    # The physics issue: what C1, M1, A1, B1 and ecf each mean.
    "A right final answer earns the C1 marks too", '"Show that": the method is marked M1 and the result A1',
    "the reason is the M1 and the conclusion the A1", "is a B1 on its own", "(ecf)",
]

PAST_QUESTIONS = [
    ("9702/21/M/J/23 Q3: resultant force and applied force from a momentum–time graph, with "
    "friction."),
    ("9702/22/M/J/24 Q2: a skydiver's velocity–time graph, the acceleration when the parachute "
    "opens and the change in momentum."),
    ("9702/23/O/N/24 Q2: a collision where one ball stops, the kinetic energy change, and the "
    "forces each ball exerts on the other."),
    "9702/21/M/J/24 Q3: conservation of momentum in two dimensions, then a stopping force.",
]


@pytest.mark.parametrize(("page", "phrases"), [
    ("common-mistakes", COMMON_MISTAKES),
    ("getting-the-marks", GETTING_THE_MARKS),
    ("past-questions", PAST_QUESTIONS),
])
def test_exam_advice_pages_carry_every_point(site_dir, page, phrases):
    assert_on_page(site_dir, f"book/exam/{page}", phrases)


def test_the_book_has_every_section_of_the_notes(site_dir):
    titles = {
        "book/intro": "What you need to know",
        "book/exam/key-facts": "Key facts and formulas",
        "book/exam/how-to": "How to do it",
        "book/exam/worked-examples": "Worked examples",
        "book/exam/example-1": "Example 1",
        "book/exam/example-2": "Example 2",
        "book/exam/example-3": "Example 3",
        "book/exam/example-4": "Example 4",
        "book/exam/example-5": "Example 5",
        "book/exam/common-mistakes": "Common mistakes",
        "book/exam/getting-the-marks": "How to get the marks",
        "book/exam/past-questions": "Past questions to try",
    }
    for page, title in titles.items():
        assert f">{title}" in page_html(site_dir, page), page


# --- The physics issue: what a 9702 examiner expects the book to say ------------------

PHYSICS_ISSUE_PHRASES = {
    # 6: which angle theta is in 2p sin theta.
    "book/exam/method-force-momentum": [
        "with \\(\\theta\\) measured from the surface",
        "it is \\(\\Delta p = 2p\\cos\\theta\\)",
    ],
    # 7: the cut string, with its two masses; 16: lifts slowing.
    "book/exam/method-newtons-laws": [
        "Two masses hang from a spring, \\(m_1\\) above and \\(m_2\\) below, joined by a string.",
        "accelerates upwards at \\(\\dfrac{m_2 g}{m_1}\\)", "falls freely",
        "going up faster or going down and slowing", "going down faster or going up and slowing",
    ],
    "book/understand/weight": [
        "A lift moving down and slowing accelerates upwards, so \\(R = m(g + a)\\)",
        "A lift moving up and slowing accelerates downwards, so \\(R = m(g - a)\\)",
    ],
    # 13: the first and third laws, word for word.
    "book/exam/method-definitions": [
        ("Newton's first law: an object stays at rest, or keeps moving at a constant velocity, unless "
         "a resultant force acts on it."),
        ("Newton's third law: if body A exerts a force on body B, then B exerts a force on A that is "
         "equal in magnitude and opposite in direction. The two forces act on different bodies and are "
         "of the same type."),
    ],
    # 14: the syllabus's phrase, and the word in multiple-choice options.
    "book/understand/elastic-and-inelastic": ["The syllabus calls this a perfectly elastic collision"],
    "book/understand/momentum-and-second-law": ["is called the impulse of the force",
                                                "impulse = change in momentum, in N s"],
}


@pytest.mark.parametrize("page", sorted(PHYSICS_ISSUE_PHRASES))
def test_pages_say_what_a_9702_examiner_expects(site_dir, page):
    assert_on_page(site_dir, page, PHYSICS_ISSUE_PHRASES[page])


def test_worked_examples_list_all_five_examples(site_dir):
    html = page_html(site_dir, "book/exam/worked-examples")
    for n in range(1, 6):
        assert f'href="example-{n}.html' in html
    assert "drag, upthrust and terminal velocity in a liquid" in page_text(site_dir, "book/exam/worked-examples")


# Issue "reading", item 14: each past question as a student searches for it. The notes give
# the code (9702/21/M/J/23 Q3); the page spells it out and names the paper's file, nothing more.
PAST_QUESTION_REFERENCES = [
    ("9702/21/M/J/23 Q3", "May/June 2023, Paper 2, variant 1 (paper 21), question 3", "9702_s23_qp_21"),
    ("9702/22/M/J/24 Q2", "May/June 2024, Paper 2, variant 2 (paper 22), question 2", "9702_s24_qp_22"),
    ("9702/23/O/N/24 Q2", "October/November 2024, Paper 2, variant 3 (paper 23), question 2", "9702_w24_qp_23"),
    ("9702/21/M/J/24 Q3", "May/June 2024, Paper 2, variant 1 (paper 21), question 3", "9702_s24_qp_21"),
]


@pytest.mark.parametrize(("code", "spelled", "file"), PAST_QUESTION_REFERENCES)
def test_past_questions_give_series_paper_variant_and_question(site_dir, code, spelled, file):
    # The spelled-out form follows from the notes' code alone: nothing is invented.
    paper, series, year, question = re.fullmatch(r"9702/(\d\d)/(M/J|O/N)/(\d\d) Q(\d+)", code).groups()
    assert spelled == (f"{'May/June' if series == 'M/J' else 'October/November'} 20{year}, Paper "
                       f"{paper[0]}, variant {paper[1]} (paper {paper}), question {question}")
    assert file == f"9702_{'s' if series == 'M/J' else 'w'}{year}_qp_{paper}"
    assert_on_page(site_dir, "book/exam/past-questions", [code, spelled + ": search for " + file])
    codes = re.findall(r"9702/\d\d/[MO]/[JN]/\d\d Q\d+", page_html(site_dir, "book/exam/past-questions"))
    assert sorted(set(codes)) == sorted(c for c, _, _ in PAST_QUESTION_REFERENCES)
