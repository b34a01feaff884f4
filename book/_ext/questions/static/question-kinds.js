/* The part kinds' registry: QuestionKinds. Each part kind is one script in question-kinds/ (the
 * browser twin of its Python class in physics_figures/parts/, whose `browser_script` names it)
 * that registers itself here; nothing outside a kind's two modules and the two registries
 * branches on a kind's name (tests/no_site/test_kind_plugins.py checks). The page loads this file first,
 * then each kind's script (book/_ext/questions/form.py, kind_scripts), then the engine. Under
 * Node, the first look-up loads every script in question-kinds/ (a test may register its own).
 *
 * A kind's script ends with
 *     if (typeof module === "object" && module.exports) module.exports = kind;
 *     else kind.kinds.forEach(function (name) { root.QuestionKinds.register(name, kind); });
 * (a script may export a list of such objects: numeric.js, the numeric and graph kinds), and
 * `kind` has:
 *   kinds: [names]                  the names it registers under (its Python classes' `kind`)
 *   mark(part, answer, figures)     the outcome {code, message, ...} of an answer (marking.js
 *                                   calls it; `figures` is the rule table's {min, check} s.f.)
 *   read(box, part)                 the answer in the part's fieldset (box), as `mark` takes it
 *   fill(box, part, answer)         put an answer (a saved one, or {} to clear) into the fieldset
 *   answered(answer)                the answer has something in it (a Check of a blank is no attempt)
 *   relabel(box, part, data)        rewrite the fieldset's words for another variant's data (the
 *                                   legend and a signed part's note are the page's own)
 * and, where it differs from the default (false / ""):
 *   selfMarked                      its lines count when ticked (result.ticked: line indices)
 *   readsGraph                      its value is read off the question's graph
 *   helpSteps                       it offers help by steps of the working (help-steps.js)
 *   mockPaper                       "1" or "2": the mock test's paper that asks templates made of it
 *   missedNote(part)                what the end of a mock test adds to a part not right ("The
 *                                   answer is B.")
 *   outcome(code, message, extra)   (a kind with ecf) how its marker builds an outcome
 *   show(box, result)               after Check, show in the fieldset what the marker found (text)
 *   preTick(box, result)            on a Check, tick the points the marker found for the student
 *                                   to confirm (explain with rules); true when it ticked any
 */
(function (root) {
  "use strict";

  var kinds = {},
    loaded = false;

  /* Add a kind's module under a name; a name is taken once. */
  function register(name, kind) {
    if (typeof name !== "string" || !name)
      throw new Error("a part kind needs a name (got " + JSON.stringify(name) + ")");
    if (!kind || typeof kind.mark !== "function") throw new Error("the part kind " + name + " has no mark function");
    if (kinds[name] && kinds[name] !== kind) throw new Error("the part kind " + name + " is registered twice");
    kinds[name] = kind;
    return kind;
  }

  /* Under Node: every script of question-kinds/, each registering its names. */
  function loadAll() {
    if (loaded || typeof require !== "function" || typeof document !== "undefined") return;
    loaded = true;
    var fs = require("fs"),
      path = require("path"),
      folder = path.join(path.dirname(module.filename), "question-kinds");
    fs.readdirSync(folder)
      .filter(function (file) {
        return /\.js$/.test(file);
      })
      .sort()
      .forEach(function (file) {
        [].concat(require(path.join(folder, file))).forEach(function (kind) {
          kind.kinds.forEach(function (name) {
            register(name, kind);
          });
        });
      });
  }

  /* The module of a part's kind (a part without one is a number to calculate, as the bank's
   * oldest data write it). An unknown kind is an error, never a guess. */
  function of(part) {
    var name = (part && part.kind) || DEFAULT;
    if (!kinds[name]) loadAll();
    var kind = kinds[name];
    if (!kind) throw new Error("no part kind " + JSON.stringify(name));
    return kind;
  }

  function get(name) {
    return of({ kind: name });
  }

  function names() {
    loadAll();
    return Object.keys(kinds);
  }

  //: The kind of a part whose data name none.
  var DEFAULT = "numeric";

  var QuestionKinds = { register: register, of: of, get: get, names: names };
  if (typeof module === "object" && module.exports) module.exports = QuestionKinds;
  else root.QuestionKinds = QuestionKinds;
})(this);
