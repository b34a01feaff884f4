/* The mock test's page (book/exam/mock-test.md): choose a paper and a length, then a test drawn
 * fresh (mock-draw.js) with each question's form as form.py writes it and its variant's words
 * and numbers (from the template's data file, _static/questions/KEY.js, loaded by a <script>
 * element, so file:// works too). No feedback until the end: no Check, no marks, no worked
 * answer. The test (paper, seed, questions and variants, start, minutes allowed, answers as
 * typed) is kept in this browser, so a reload resumes it with the time that is left, or ends it
 * when time ran out meanwhile. At the end the engine (marking.js) marks every answer; the score,
 * a line per type and each question's marks and worked answer show, and the result is kept
 * (progress-store.js: the mock, and each question answered as an attempt). */
(function (root) {
  "use strict";

  var Mock = root.MockDraw,
    Questions = root.MockQuestions,
    engine = root.QuestionMarking;
  var STATE = root.ProgressStore.KEYS.mock;

  function loadState() {
    try {
      var state = JSON.parse(localStorage.getItem(STATE));
      return state && state.version === 1 ? state : null;
    } catch {
      return null;
    }
  }

  function saveState(state) {
    try {
      localStorage.setItem(STATE, JSON.stringify(state));
    } catch {
      /* private mode: the test runs, but a reload cannot resume it */
    }
  }

  function dropState() {
    try {
      localStorage.removeItem(STATE);
    } catch {
      /* nothing kept */
    }
  }

  function contentRoot() {
    return document.documentElement.getAttribute("data-content_root") || "";
  }

  /* Each template's data file, once: its variants and its form. done() when all have come. */
  function loadTemplates(keys, done) {
    var wanted = keys.filter(function (key, i) {
      return keys.indexOf(key) === i && !((root.QuestionVariants || {})[key] && (root.QuestionForms || {})[key]);
    });
    var left = wanted.length;
    if (!left) return done();
    wanted.forEach(function (key) {
      var script = document.createElement("script");
      script.src = contentRoot() + "_static/questions/" + key + ".js";
      script.onload = script.onerror = function () {
        if (--left === 0) done();
      };
      document.head.appendChild(script);
    });
  }

  function variantOf(question) {
    var all = (root.QuestionVariants || {})[question.question];
    return (all && all[question.variant]) || null;
  }

  /* "18¾ minutes": the paces give quarters of a minute. */
  function minutesText(minutes) {
    var whole = Math.floor(minutes),
      quarter = Math.round((minutes - whole) * 4);
    return (whole || "") + ["", "¼", "½", "¾"][quarter] + (minutes === 1 ? " minute" : " minutes");
  }

  function sizeText(paper, size) {
    var unit = Mock.PAPERS[paper].unit;
    return size + " " + unit[size === 1 ? 0 : 1] + " in " + minutesText(Mock.minutesFor(paper, size));
  }

  /* The result's "What next": the weakest type of this test (MockDraw.weakestType) with a link
   * to its practice page and its method (the build's links: index.next), or, with every mark,
   * a longer test; and Your practice. A paragraph, built of text and links. */
  function whatNext(index, mock) {
    var weakest = Mock.weakestType(index.types, mock.questions);
    var next = index.next || { types: {} };
    var p = document.createElement("p");
    p.className = "mock-next";
    var strong = document.createElement("strong");
    strong.textContent = "What next:";
    p.appendChild(strong);
    function add(part) {
      p.appendChild(typeof part === "string" ? document.createTextNode(part) : part);
    }
    function link(href, text) {
      var a = document.createElement("a");
      a.href = href;
      a.textContent = text;
      return a;
    }
    if (weakest) {
      var links = next.types[weakest.type.key] || {};
      p.setAttribute("data-type", weakest.type.key);
      add(" practise your weakest type in this test, ");
      add(links.practise ? link(links.practise, weakest.type.title) : weakest.type.title);
      add(" (" + engine.marksText(weakest.earned, weakest.available) + ")");
      if (links.method) {
        add(", after reading ");
        add(link(links.method, "how to do it"));
      }
      add(".");
    } else {
      add(" every mark in this test. Try a longer one.");
    }
    if (next.practice) {
      add(" ");
      add(link(next.practice, "Your practice"));
      add(" brings this test's questions back when they are due.");
    }
    return p;
  }

  // The page's parts, and the test under way: its state, its clock's timer, its forms.
  function mockPage(box) {
    var setup = box.querySelector(".mock-setup"),
      test = box.querySelector(".mock-test");
    return {
      box: box,
      index: JSON.parse(box.querySelector("script.mock-index").textContent),
      setup: setup,
      sizeBox: setup.querySelector("#mock-size"),
      status: setup.querySelector(".mock-status"),
      startButton: setup.querySelector(".mock-start"),
      test: test,
      list: test.querySelector(".mock-questions"),
      clock: test.querySelector(".mock-time"),
      warning: test.querySelector(".mock-warning"),
      confirmBox: test.querySelector(".mock-confirm"),
      result: box.querySelector(".mock-result"),
      state: null,
      timer: null,
      forms: [],
    };
  }

  function paperChosen(page) {
    return page.setup.querySelector('input[name="mock-paper"]:checked').value;
  }

  function offerSizes(page) {
    var paper = paperChosen(page);
    page.sizeBox.innerHTML = "";
    Mock.PAPERS[paper].sizes.forEach(function (size) {
      var option = document.createElement("option");
      option.value = String(size);
      option.textContent = sizeText(paper, size);
      page.sizeBox.appendChild(option);
    });
  }

  // ------------------------------------------------------------------ the questions

  function keepAnswers(page, event) {
    var state = page.state;
    var section = event.target.closest(".mock-q");
    if (!section || !state || state.ended) return;
    var i = Number(section.getAttribute("data-index"));
    state.answers[i] = Questions.answersOf(page.forms[i], variantOf(state.questions[i]));
    saveState(state);
  }

  function showQuestions(page) {
    var state = page.state;
    page.list.innerHTML = "";
    if (state.paper === "2") {
      var hint = document.createElement("p");
      hint.className = "q-unit-hint mock-unit-hint";
      hint.textContent = page.box.getAttribute("data-unit-hint");
      page.list.appendChild(hint);
    }
    page.forms = state.questions.map(function (question, i) {
      var section = Questions.questionSection(
        question,
        variantOf(question),
        root.QuestionForms[question.question],
        i,
        state.answers[i] || {},
        page.box.getAttribute("data-enlarge"),
      );
      page.list.appendChild(section);
      return section.querySelector("form.q-form");
    });
    page.setup.hidden = true;
    page.test.hidden = false;
  }

  // ------------------------------------------------------------------ the clock

  function tick(page) {
    var state = page.state;
    var left = Mock.timeLeft(state, Date.now());
    page.clock.textContent = Mock.clockText(left);
    var due = Mock.warningDue(left, state.warned);
    if (due) {
      page.warning.textContent = due.text;
      Mock.WARNINGS.forEach(function (w) {
        if (w.at >= left && state.warned.indexOf(w.at) < 0) state.warned.push(w.at);
      });
      saveState(state);
    }
    if (left <= 0) return finish(page, "time");
    page.timer = setTimeout(tick, left % 1000 || 1000, page); // on the next whole second
  }

  // ------------------------------------------------------------------ the end

  function markAll(state) {
    return state.questions.map(function (question, i) {
      var variant = variantOf(question);
      var answers = (state.answers || {})[i] || {};
      return {
        question: question,
        variant: variant,
        answers: answers,
        marked: engine.markQuestion(variant, answers),
      };
    });
  }

  function mockOf(state, marked) {
    var earned = 0,
      available = 0;
    var questions = marked.map(function (m) {
      earned += m.marked.marks.earned;
      available += m.marked.marks.available;
      return {
        question: m.question.question,
        type: m.question.type,
        variant: m.question.variant,
        earned: m.marked.marks.earned,
        available: m.marked.marks.available,
      };
    });
    return {
      id: "mock-" + state.at + "-" + state.seed,
      paper: state.paper,
      at: state.at,
      minutes: state.minutes,
      ended: state.ended,
      earned: earned,
      available: available,
      questions: questions,
    };
  }

  /* The result, kept once: the mock, and each question answered as an attempt of its card. */
  function keepResult(mock, marked) {
    var store = root.ProgressStore;
    if (!store) return;
    var now = Date.now();
    marked.forEach(function (m) {
      if (!Questions.answered(m.variant, m.answers)) return; // as on a question's page, nothing written is no attempt
      store.recordAttempt({
        question: m.question.question,
        type: m.question.type,
        variant: m.question.variant,
        earned: m.marked.marks.earned,
        available: m.marked.marks.available,
        at: now,
        // each part's named mistake, and the sign, unit and 1 s.f. slips the engine names, as a
        // question's page records them (questions.js): the plan counts them
        mistakes: m.variant.parts
          .map(function (p) {
            var result = m.marked.results[p.id];
            return result.mistake || engine.slipName(result.code);
          })
          .filter(Boolean),
        mock: mock.id,
      });
    });
    store.recordMock(mock);
  }

  function finish(page, ended) {
    var state = page.state;
    clearTimeout(page.timer);
    page.warning.textContent = ""; // "1 minute left." is over once the test is
    if (!state.ended) {
      state.ended = ended;
      state.endedAt = Date.now();
      saveState(state);
    }
    var marked = markAll(state);
    var mock = mockOf(state, marked);
    if (!state.kept) {
      keepResult(mock, marked);
      state.kept = true;
      saveState(state);
    }
    showResult(page, mock, marked);
  }

  /* The result's line per type: each type in this test, with its marks. */
  function typeLinesHtml(index, mock) {
    var byType = {};
    mock.questions.forEach(function (q) {
      var line = (byType[q.type] = byType[q.type] || [0, 0]);
      line[0] += q.earned;
      line[1] += q.available;
    });
    return index.types
      .filter(function (t) {
        return byType[t.key];
      })
      .map(function (t) {
        return (
          '<li data-type="' +
          t.key +
          '"><span class="mock-type">' +
          t.title +
          '</span> <span class="mock-type-marks">' +
          engine.marksText(byType[t.key][0], byType[t.key][1]) +
          "</span></li>"
        );
      })
      .join("");
  }

  // The test's bar and Finish buttons: hidden once it has ended, shown again for another.
  function showTestControls(page, shown) {
    Array.prototype.forEach.call(page.test.querySelectorAll(".mock-bar, .mock-end"), function (el) {
      el.hidden = !shown;
    });
  }

  function showResult(page, mock, marked) {
    var result = page.result;
    page.confirmBox.hidden = true;
    page.test.classList.add("mock-ended");
    showTestControls(page, false);
    result.innerHTML =
      '<h2 class="mock-result-title">Your result</h2><p class="mock-score">' +
      Mock.PAPERS[mock.paper].name +
      " style: " +
      engine.marksText(mock.earned, mock.available) +
      '</p><p class="mock-how">' +
      (mock.ended === "time" ? "Time ran out: " : "You finished: ") +
      "each question is marked below, with its worked answer.</p>" +
      '<ul class="mock-types">' +
      typeLinesHtml(page.index, mock) +
      '</ul><p><button type="button" class="mock-again">Take another test</button></p>';
    result.insertBefore(whatNext(page.index, mock), result.querySelector(".mock-again").parentNode);
    result.hidden = false;
    marked.forEach(function (m, i) {
      Questions.showMarks(page.forms[i], m);
    });
    result.querySelector(".mock-again").addEventListener("click", takeAnother.bind(null, page));
    result.focus();
  }

  function takeAnother(page) {
    dropState();
    page.state = null;
    page.result.hidden = true;
    page.result.innerHTML = "";
    page.list.innerHTML = "";
    page.test.hidden = true;
    page.test.classList.remove("mock-ended");
    showTestControls(page, true);
    page.warning.textContent = "";
    page.setup.hidden = false;
    page.startButton.disabled = false;
    page.startButton.focus();
  }

  // ------------------------------------------------------------------ starting, resuming

  // Questions that did not come: a fresh test can be started again; a kept one is dropped.
  function giveUpLoading(page, fresh) {
    page.status.textContent = fresh
      ? "The questions could not be loaded. Check your connection, then press Start the test again."
      : "Your last test could not be loaded (its questions are not in this version of the book). Start a new one.";
    if (!fresh) dropState();
    page.state = null;
    page.setup.hidden = false;
    page.startButton.disabled = false;
  }

  /* Show a kept test: its result when it ended (or its time ran out meanwhile), else the
   * questions and the clock. */
  function run(page, fresh) {
    var keys = page.state.questions.map(function (q) {
      return q.question;
    });
    loadTemplates(keys, function () {
      var state = page.state;
      var missing = state.questions.filter(function (q) {
        return !variantOf(q) || !(root.QuestionForms || {})[q.question];
      });
      if (missing.length) return giveUpLoading(page, fresh);
      if (fresh) {
        state.at = Date.now(); // the clock starts when the questions are there
        saveState(state);
        page.status.textContent = "";
      }
      showQuestions(page);
      if (state.ended || Mock.timeLeft(state, Date.now()) <= 0) return finish(page, state.ended || "time");
      tick(page);
      if (fresh) page.list.querySelector(".mock-q-title").focus();
    });
  }

  // Start the test: draw one of the paper and length chosen, from a fresh seed.
  function startNewTest(page) {
    var paper = paperChosen(page),
      size = Number(page.sizeBox.value);
    var seed = root.crypto.getRandomValues(new Uint32Array(1))[0];
    var drawn;
    try {
      drawn = Mock.draw(page.index, paper, size, seed);
    } catch (error) {
      if (!(error instanceof Mock.DrawError)) throw error;
      page.status.textContent = "This test cannot be drawn from the book's questions: " + error.message + ".";
      return;
    }
    page.status.textContent = "Loading the questions…";
    page.startButton.disabled = true; // one test at a time: a second tap would draw another
    page.state = Object.assign(drawn, { version: 1, at: Date.now(), answers: {}, warned: [] });
    run(page, true);
  }

  // The setup's form offers each paper's lengths and starts a test; the questions' forms keep
  // the answers as they are typed.
  function wireForms(page) {
    var keep = keepAnswers.bind(null, page);
    page.setup.addEventListener("change", function (event) {
      if (event.target.name === "mock-paper") offerSizes(page);
    });
    page.setup.addEventListener("submit", function (event) {
      event.preventDefault();
      startNewTest(page);
    });
    // Enter in an answer box would submit its form: answers are kept as typed, marked at the end
    page.list.addEventListener("submit", function (event) {
      event.preventDefault();
    });
    page.list.addEventListener("input", keep);
    page.list.addEventListener("change", keep);
  }

  // Finish asks first ("Finish now?"); No goes back to the test, Yes ends it.
  function wireFinish(page) {
    var confirmBox = page.confirmBox;
    Array.prototype.forEach.call(page.test.querySelectorAll(".mock-finish"), function (button) {
      button.addEventListener("click", function () {
        confirmBox.hidden = false;
        confirmBox.querySelector(".mock-finish-no").focus();
      });
    });
    confirmBox.querySelector(".mock-finish-no").addEventListener("click", function () {
      confirmBox.hidden = true;
      page.test.querySelector(".mock-finish").focus();
    });
    confirmBox.querySelector(".mock-finish-yes").addEventListener("click", function () {
      finish(page, "submitted");
    });
  }

  function start() {
    var box = document.querySelector(".mock");
    if (!box) return;
    if (!Mock || !Questions || !engine || !root.QuestionRelabel) {
      // a script the test needs did not come: Start the test stays disabled
      box.querySelector(".mock-status").textContent =
        "The test could not be loaded. Check your connection, then reload the page.";
      return;
    }
    var page = mockPage(box);
    wireForms(page);
    wireFinish(page);
    offerSizes(page);
    // Ready: the page could not start a test before this (mock_test.py writes the button
    // disabled, with "Getting the test ready…"), so a tap never sent the form.
    page.status.textContent = "";
    page.state = loadState();
    if (page.state) {
      page.setup.hidden = true;
      run(page, false);
    } else {
      page.startButton.disabled = false;
    }
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
