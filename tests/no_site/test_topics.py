"""A topic is declared once (physics_figures.topics): its types with their titles, exam weights
and method pages, its pages, templates and sections. The Dynamics topic is the bank's."""

from __future__ import annotations

import dataclasses

import pytest

from physics_figures import bank, topics
from physics_figures.topics import QuestionType, Topic

DRAG = bank.by_type("drag")[0]


def _topic(**changes) -> Topic:
    fields = {"key": "t", "name": "T", "pages": ("p/method",),
              "types": (QuestionType("drag", "Drag", "p/method", 1),), "templates": (DRAG,)}
    return Topic(**(fields | changes))


def test_the_dynamics_topic_is_the_banks():
    topic = topics.load("physics_figures.bank")
    assert topic is bank.TOPIC and topic.name == "Dynamics"
    assert [t.key for t in topic.types] == ["newton", "drag", "force-momentum", "definitions", "momentum-line",
                                            "elastic", "two-d"]
    assert set(topic.by_key) == set(bank.TEMPLATES)
    assert topic.practice_templates() == [t for k in topic.type_keys for t in bank.by_type(k)]


@pytest.mark.parametrize(("changes", "message"), [
    ({"types": ()}, "types must be one or more"),
    ({"types": (QuestionType("drag", "Drag", "p/other", 1),)}, "must name method pages among the topic's pages"),
    ({"types": (QuestionType("newton", "N", "p/method", 1),)}, "templates must be of the topic's types"),
    ({"templates": (DRAG, DRAG)}, "must each have their own key"),
    ({"sections": {"s": ("p/elsewhere", "")}}, "sections must point at the topic's pages"),
])
def test_a_topic_that_does_not_hold_together_is_refused(changes, message):
    with pytest.raises(ValueError, match=message):
        _topic(**changes)


def test_a_question_type_is_checked():
    with pytest.raises(ValueError, match="key must be a lower-case id"):
        QuestionType("Two D", "x", "p", 1)
    with pytest.raises(ValueError, match="exam_count must be a whole number"):
        QuestionType("two-d", "x", "p", -1)


def test_a_topic_looks_up_types_and_templates():
    topic = _topic()
    assert topic.type("drag").title == "Drag" and topic.by_type("drag") == [DRAG]
    with pytest.raises(ValueError, match=r"question_type must be one of \('drag',\)"):
        topic.by_type("newton")
    assert dataclasses.replace(topic, name="U").name == "U"


def test_loading_a_module_without_a_topic_says_so():
    with pytest.raises(ValueError, match="cannot be imported"):
        topics.load("no_such_topic_module")
    with pytest.raises(ValueError, match=r"TOPIC is a physics_figures\.topics\.Topic"):
        topics.load("physics_figures.notation")
