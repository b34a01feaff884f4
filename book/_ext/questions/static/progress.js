/* "Your practice": what a student has done with the bank, by question type, from the
 * attempts questions.js keeps in this browser. Plain JavaScript, offline, no physics.
 * The pure part (top) runs under Node for the tests; the page code (bottom) in a browser.
 *
 * Storage: localStorage "dynamics-progress-v1" holds
 *   {version: 1, attempts: [{question, type, variant, earned, available, at, mistakes: [names]}]}.
 * Versioning: this page reads format 1 only. A later build that changes the format must bump
 * the version and keep its data under a new key (upgrading a v1 store it finds, never
 * deleting it). If this page meets any other version, in the store or in an imported file,
 * it reads nothing from it and writes nothing over it: the store is left exactly as it is
 * (export still copies it out whole), and such a file is refused with the reason.
 * Export adds the book's id and a checksum of the attempts (progress-file.js, for the
 * teacher's class page); import reads files with or without them. */
(function (root) {
  "use strict";

  var Notation = root.Notation || require("../../notation/static/notation.js");
  var ProgressFile = root.ProgressFile || require("./progress-file.js");

  var STORE = "dynamics-progress-v1";
  var VERSION = 1;

  function count(n) {
    return Notation.formatNumber(n, null, { decimals: 0 });
  }
  function marksText(earned, available) {
    return count(earned) + "/" + count(available) + " mark" + (available === 1 ? "" : "s");
  }
  function times(n) {
    return n === 1 ? "once" : n === 2 ? "twice" : count(n) + " times";
  }

  // What is wrong with one attempt, or null.
  function attemptProblem(a) {
    if (!a || typeof a !== "object" || Array.isArray(a)) return "is not an attempt";
    if (typeof a.question !== "string" || !a.question) return "names no question";
    if (typeof a.type !== "string") return "has no question type";
    if (!Number.isInteger(a.variant) || a.variant < 0) return "has no variant number";
    if (!Number.isInteger(a.available) || a.available < 1) return "has no marks available";
    if (!Number.isInteger(a.earned) || a.earned < 0 || a.earned > a.available) {
      return "has marks earned that are not between 0 and the marks available";
    }
    if (typeof a.at !== "number" || !isFinite(a.at)) return "has no time";
    if (
      !Array.isArray(a.mistakes) ||
      a.mistakes.some(function (m) {
        return typeof m !== "string";
      })
    ) {
      return "has no list of mistakes";
    }
    return null;
  }

  /* Read stored or exported progress (text). {ok: true, progress} or {ok: false, message},
   * the message saying what is wrong. Nothing stored reads as empty progress. */
  function readProgress(text) {
    if (text === null || text === undefined || text === "") {
      return { ok: true, progress: { version: VERSION, attempts: [] } };
    }
    var data;
    try {
      data = JSON.parse(text);
    } catch {
      return { ok: false, message: "it is not a progress file from this book (it is not JSON)." };
    }
    if (!data || typeof data !== "object" || Array.isArray(data) || !("version" in data)) {
      return { ok: false, message: "it is not a progress file from this book (it has no format version)." };
    }
    if (data.version !== VERSION) {
      return {
        ok: false,
        message:
          typeof data.version === "number" && data.version > VERSION
            ? "it was saved by a newer version of the book (format " +
              count(data.version) +
              "); this page reads format " +
              count(VERSION) +
              ". Open it in the newer book."
            : "its format version (" + String(data.version).slice(0, 20) + ") is not one this book wrote.",
      };
    }
    if (!Array.isArray(data.attempts)) {
      return { ok: false, message: "it has no list of attempts." };
    }
    for (var i = 0; i < data.attempts.length; i++) {
      var problem = attemptProblem(data.attempts[i]);
      if (problem) {
        return {
          ok: false,
          message: "attempt " + count(i + 1) + " of " + count(data.attempts.length) + " " + problem + ".",
        };
      }
    }
    return { ok: true, progress: data };
  }

  function identity(a) {
    return JSON.stringify([a.question, a.variant, a.at, a.earned, a.available, a.mistakes]);
  }

  /* Attempts of both, each once, oldest first: importing the same file twice adds nothing.
   * Returns {attempts, added, already}. */
  function mergeAttempts(kept, incoming) {
    var seen = {},
      out = kept.slice(),
      added = 0;
    kept.forEach(function (a) {
      seen[identity(a)] = true;
    });
    incoming.forEach(function (a) {
      var id = identity(a);
      if (seen[id]) return;
      seen[id] = true;
      out.push(a);
      added += 1;
    });
    out.sort(function (a, b) {
      return a.at - b.at;
    });
    return { attempts: out, added: added, already: incoming.length - added };
  }

  /* One type's progress. kind: {type, name, templates: [{key, title, marks, page}]} (the
   * build's list). Attempts count by their question's key, so a template the bank no longer
   * has is kept in the store but not shown. Marks: the best attempt at each template tried. */
  function summarise(kind, attempts) {
    var byKey = {},
      mistakes = {},
      order = [];
    kind.templates.forEach(function (t) {
      byKey[t.key] = { template: t, attempts: [] };
    });
    attempts.forEach(function (a) {
      var entry = byKey[a.question];
      if (!entry) return;
      entry.attempts.push(a);
      a.mistakes.forEach(function (name) {
        if (!mistakes[name]) {
          mistakes[name] = 0;
          order.push(name);
        }
        mistakes[name] += 1;
      });
    });
    var tried = 0,
      earned = 0,
      available = 0,
      templates = {};
    kind.templates.forEach(function (t) {
      var entry = byKey[t.key],
        best = null,
        last = null;
      entry.attempts.forEach(function (a) {
        if (!best || a.earned / a.available > best.earned / best.available) best = a;
        if (!last || a.at >= last.at) last = a;
      });
      templates[t.key] = { attempts: entry.attempts.length, best: best, last: last };
      if (best) {
        tried += 1;
        earned += best.earned;
        available += best.available;
      }
    });
    var often = order
      .map(function (name) {
        return { name: name, count: mistakes[name] };
      })
      .sort(function (a, b) {
        return b.count - a.count;
      }); // stable: first made first on a tie
    return {
      tried: tried,
      inBank: kind.templates.length,
      earned: earned,
      available: available,
      mistakes: often,
      templates: templates,
    };
  }

  /* The template "Practise this type" serves: the first untried one (bank order); else one
   * whose last attempt lost marks, the longest ago first; else the longest ago. Only
   * templates a page places can be served; null if none is. */
  function nextTemplate(kind, summary) {
    var placed = kind.templates.filter(function (t) {
      return t.page;
    });
    var untried = placed.filter(function (t) {
      return !summary.templates[t.key].last;
    });
    if (untried.length) return untried[0];
    function lastAt(t) {
      return summary.templates[t.key].last.at;
    }
    function oldestFirst(list) {
      return list.slice().sort(function (a, b) {
        return lastAt(a) - lastAt(b);
      })[0];
    }
    var wrong = placed.filter(function (t) {
      var last = summary.templates[t.key].last;
      return last.earned < last.available;
    });
    return (wrong.length ? oldestFirst(wrong) : oldestFirst(placed)) || null;
  }

  function practiseUrl(template) {
    var key = encodeURIComponent(template.key);
    return template.page + "?new=" + key + "#question-" + key;
  }

  var api = {
    STORE: STORE,
    VERSION: VERSION,
    readProgress: readProgress,
    mergeAttempts: mergeAttempts,
    summarise: summarise,
    nextTemplate: nextTemplate,
    practiseUrl: practiseUrl,
    marksText: marksText,
    times: times,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.PracticeProgress = api;

  // ------------------------------------------------------------------ page

  if (typeof document === "undefined") return;

  function getStored() {
    try {
      return localStorage.getItem(STORE);
    } catch {
      return null;
    }
  }

  function setStored(text) {
    try {
      if (text === null) localStorage.removeItem(STORE);
      else localStorage.setItem(STORE, text);
      return true;
    } catch {
      return false;
    }
  }

  function start() {
    var box = document.querySelector(".pp");
    if (!box) return;
    var data = JSON.parse(box.querySelector("script.pp-data").textContent);
    var file = box.querySelector(".pp-file");
    var status = box.querySelector(".pp-status");
    var importInput = box.querySelector(".pp-import");
    var undoButton = box.querySelector(".pp-undo");
    var clearButton = box.querySelector(".pp-clear");
    var cleared = null; // the store as it was before Clear, for Undo
    document.documentElement.classList.add("pp-js");
    file.hidden = false;

    function say(message) {
      status.textContent = message;
    }

    function current() {
      return readProgress(getStored());
    }

    function render() {
      var read = current();
      var attempts = read.ok ? read.progress.attempts : [];
      data.types.forEach(function (kind) {
        var section = box.querySelector('.pp-type[data-type="' + kind.type + '"]');
        if (!kind.templates.length) return; // the static "not in the bank yet" stands
        var s = summarise(kind, attempts);
        var bank = count(s.inBank) + " question" + (s.inBank === 1 ? "" : "s") + " in the bank";
        section.querySelector(".pp-summary").textContent = s.tried
          ? "Tried " +
            count(s.tried) +
            " of " +
            bank +
            ". Marks: " +
            marksText(s.earned, s.available) +
            " (your best attempt at each question tried)."
          : bank.charAt(0).toUpperCase() + bank.slice(1) + "; none tried yet.";
        var mistakes = section.querySelector(".pp-mistakes");
        mistakes.hidden = !s.tried;
        mistakes.textContent = s.mistakes.length
          ? "Mistakes made most often: " +
            s.mistakes
              .slice(0, 3)
              .map(function (m) {
                return m.name + " (" + times(m.count) + ")";
              })
              .join("; ") +
            "."
          : "No named mistakes so far.";
        kind.templates.forEach(function (t) {
          var entry = s.templates[t.key];
          var marks = section.querySelector('li[data-key="' + t.key + '"] .pp-marks');
          marks.textContent = entry.best
            ? "(best " + marksText(entry.best.earned, entry.best.available) + ", tried " + times(entry.attempts) + ")"
            : "(" + count(t.marks) + " mark" + (t.marks === 1 ? "" : "s") + ", not tried)";
        });
        var link = section.querySelector(".pp-practise");
        var next = nextTemplate(kind, s);
        if (link && next) {
          link.href = practiseUrl(next);
          link.setAttribute("data-next", next.key);
          link.title =
            "Next: " + next.title + (s.templates[next.key].last ? "" : " (not tried yet)") + ", with new numbers";
        }
      });
      clearButton.disabled = !read.ok ? false : attempts.length === 0;
      if (!read.ok) {
        say(
          "The progress kept in this browser cannot be read here: " +
            read.message +
            " It is kept as it is; Export copies it out.",
        );
      }
    }

    function download(text, name) {
      var blob = new Blob([text], { type: "application/json" });
      var a = document.createElement("a");
      a.href = URL.createObjectURL(blob);
      a.download = name;
      document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(function () {
        URL.revokeObjectURL(a.href);
      }, 1000);
    }

    // The file carries the book's id and its records' checksum (progress-file.js).
    box.querySelector(".pp-export").addEventListener("click", function () {
      var stored = getStored();
      var read = readProgress(stored);
      var name = "dynamics-progress-" + new Date().toISOString().slice(0, 10) + ".json";
      if (!read.ok) {
        download(stored, name); // a format this page cannot read: copied out whole
        say("Exported your progress to " + name + ".");
        return;
      }
      ProgressFile.exportFile(read.progress, data.book).then(function (file) {
        download(JSON.stringify(file, null, 1), name);
        var n = file.attempts.length;
        say(
          "Exported " +
            count(n) +
            " attempt" +
            (n === 1 ? "" : "s") +
            " to " +
            name +
            ". Import that file on another device to carry on there" +
            (file.sha256 ? ", or give it to your teacher." : "."),
        );
      });
    });

    importInput.addEventListener("change", function () {
      var chosen = importInput.files && importInput.files[0];
      if (!chosen) return;
      var reader = new FileReader();
      reader.onload = function () {
        importInput.value = ""; // the same file can be chosen again
        var incoming = readProgress(String(reader.result));
        var name = chosen.name;
        if (!incoming.ok) {
          say("Nothing was imported from " + name + ": " + incoming.message + " Your progress here is unchanged.");
          return;
        }
        var here = current();
        if (!here.ok) {
          say(
            "Nothing was imported: the progress kept in this browser is in a format this page " +
              "cannot read, and importing would replace it. It is unchanged.",
          );
          return;
        }
        var merged = mergeAttempts(here.progress.attempts, incoming.progress.attempts);
        var progress = here.progress;
        progress.attempts = merged.attempts;
        if (!setStored(JSON.stringify(progress))) {
          say("Nothing was imported: this browser does not let the page keep data (private mode?).");
          return;
        }
        render();
        say(
          "Imported " +
            count(merged.added) +
            " attempt" +
            (merged.added === 1 ? "" : "s") +
            " from " +
            name +
            (merged.already ? " (" + count(merged.already) + " were here already)" : "") +
            ".",
        );
      };
      reader.onerror = function () {
        importInput.value = "";
        say("Nothing was imported: the file could not be read. Your progress here is unchanged.");
      };
      reader.readAsText(chosen);
    });

    clearButton.addEventListener("click", function () {
      cleared = getStored();
      setStored(null);
      render();
      undoButton.hidden = false;
      undoButton.focus();
      say("Progress cleared. Press Undo clear to bring it back (until you leave this page).");
    });

    undoButton.addEventListener("click", function () {
      var now = current();
      var before = readProgress(cleared);
      if (now.ok && now.progress.attempts.length && before.ok) {
        // attempts made since: keep both
        now.progress.attempts = mergeAttempts(before.progress.attempts, now.progress.attempts).attempts;
        setStored(JSON.stringify(now.progress));
      } else {
        setStored(cleared);
      }
      cleared = null;
      undoButton.hidden = true;
      render();
      clearButton.focus();
      say("Progress restored.");
    });

    // Another tab checking an answer updates this page.
    window.addEventListener("storage", function (event) {
      if (event.key === STORE || event.key === null) render();
    });
    render();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
