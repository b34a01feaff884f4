"""The worksheet draw, run where it lives: the teachers' sheet builder's question-draw.js (book/_ext/
questions/static), under Node. It is the one implementation of which templates a sheet asks and
which variant each version prints, so the command line, `make worksheets` and the builder in the
browser give the same sheets for the same choices and seed. This module sends it the topic's index
(types with exam counts; templates with marks, one-wording flag and reserve variants) and a kit's
requests as JSON, and reads back the draw, or the draw's refusal as a ValueError naming the field,
the value and the rule.
"""

from __future__ import annotations

import functools
import json
import shutil
import subprocess
from collections.abc import Sequence
from pathlib import Path

from ..topics import Topic
from ..variants import Template

#: The draw, as the browser runs it.
DRAW = Path(__file__).resolve().parents[2] / "book" / "_ext" / "questions" / "static" / "question-draw.js"
#: Reads {data, kit} on stdin; writes the draw, or the refusal's message and field.
_RUNNER = """
const draw = require(process.argv[1]); let text = '';
process.stdin.on('data', c => text += c).on('end', () => {
  const request = JSON.parse(text);
  try {
    process.stdout.write(JSON.stringify(draw.drawKit(request.data, request.kit)));
  } catch (error) {
    if (!(error instanceof draw.DrawError)) throw error;
    process.stdout.write(JSON.stringify({refused: error.message, field: error.field}));
  }
});
"""


def index(topic: Topic, templates: Sequence[Template]) -> dict:
    """What the draw reads: the topic's types and its bank's templates in the bank's order (the
    order a sheet prints them in), then any other template asked for."""
    bank = topic.practice_templates()
    every = {t.key: t for t in [*bank, *templates]}  # the bank's order first
    return {
        "types": [{"key": kind.key, "examCount": kind.exam_count} for kind in topic.types],
        "templates": [{"key": t.key, "type": t.type, "marks": t.variant(0).marks, "oneWording": bool(t.one_wording),
                       "reserve": list(t.reserve_variants)}
                      for t in every.values()],
    }


def draw_kit(topic: Topic, templates: Sequence[Template], kit: dict) -> dict:
    """question-draw.js's drawKit on the topic's index: ``kit`` is {seed, versions, avoid, sheets:
    [{templates: [key], marks, fitting, marksAtMost}]}. ValueError when the draw refuses."""
    answer = json.loads(_run(json.dumps({"data": index(topic, templates), "kit": kit}, sort_keys=True, default=repr)))
    if "refused" in answer:
        raise ValueError(answer["refused"])
    return answer


@functools.lru_cache(maxsize=64)
def _run(request: str) -> str:
    """The draw's answer to a request (the same request, the same answer: kept)."""
    node = shutil.which("node")
    if node is None:
        raise RuntimeError("node is missing, and the worksheet draw (question-draw.js) runs in it: "
                           "install Node 20 (apt-get install nodejs)")
    done = subprocess.run([node, "-e", _RUNNER, str(DRAW)], input=request, capture_output=True, text=True,
                          check=False)
    if done.returncode:
        raise RuntimeError(f"the worksheet draw ({DRAW}) failed under Node: {done.stderr[-2000:]}")
    return done.stdout
