/* "Your practice", the record: what a student has done with the bank, by question type (a
 * line each: marks, tried, due; its questions folded beneath), the mock tests, and moving the
 * record to and from a file. Plain JavaScript, offline, no physics. The plan at the top of
 * the page is progress-plan.js's. The pure part (top) runs under Node for the tests; the page
 * code (bottom) in a browser.
 *
 * Storage: the progress store (progress-store.js, format 2, "dynamics-progress-v2"; a format 1
 * store is upgraded on reading and never deleted). A store of a format this page does not know
 * is left exactly as it is (Export still copies it out whole) and nothing is written over it.
 * Export writes format 2 with the student's name (asked once, kept in the store), the schedule
 * (schedule.js), the book's id and a checksum of the attempts (progress-file.js, for the
 * teacher's class page), to dynamics-progress-NAME-DATE.json; Import reads formats 1 and 2 as
 * the class page does (an older export is read, not checked; another book's, or an edited one,
 * is refused) and adds each attempt once. */
(function (root) {
  "use strict";

  var Notation = root.Notation || require("../../notation/static/notation.js");

  var MONTHS = ["Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"];

  function count(n) {
    return Notation.formatNumber(n, null, { decimals: 0 });
  }
  function marksText(earned, available) {
    return count(earned) + "/" + count(available) + " mark" + (available === 1 ? "" : "s");
  }
  function times(n) {
    return n === 1 ? "once" : n === 2 ? "twice" : count(n) + " times";
  }

  /* When a card is due, as a student reads it: "due today" up to the end of today (dayEnds,
   * local midnight), else "due 28 Nov" (with the year when it is not this one). */
  function dueText(due, now, dayEnds) {
    if (due < dayEnds) return "due today";
    var day = new Date(due);
    var year = day.getFullYear() === new Date(now).getFullYear() ? "" : " " + day.getFullYear();
    return "due " + day.getDate() + " " + MONTHS[day.getMonth()] + year;
  }

  /* One type's progress. kind: {type, name, templates: [{key, title, marks, page}]} (the
   * build's list). Attempts count by their question's key, so a template the bank no longer
   * has is kept in the store but not shown. Marks: the best attempt at each template tried.
   * withHelp: the attempts that used help before their Check. */
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
        last = null,
        withHelp = 0;
      entry.attempts.forEach(function (a) {
        if (!best || a.earned / a.available > best.earned / best.available) best = a;
        if (!last || a.at >= last.at) last = a;
        if (a.help > 0) withHelp += 1;
      });
      templates[t.key] = { attempts: entry.attempts.length, best: best, last: last, withHelp: withHelp };
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

  /* A type's line: "3/8 marks · 2 of 9 tried · 1 due" (due: its cards due today). */
  function typeLine(summary, dueToday) {
    if (!summary.inBank) return "not in the bank yet";
    var parts = [
      summary.tried ? marksText(summary.earned, summary.available) : "no marks yet",
      count(summary.tried) + " of " + count(summary.inBank) + " tried",
    ];
    if (dueToday) parts.push(count(dueToday) + " due");
    return parts.join(" · ");
  }

  /* A mock test as Your practice lists it: "Paper 1, 26 Nov 2026: 14/20 marks (70 %)". */
  function mockText(mock) {
    var day = new Date(mock.at);
    var share = mock.available ? Math.round((100 * mock.earned) / mock.available) : 0;
    return (
      "Paper " +
      mock.paper +
      ", " +
      day.getDate() +
      " " +
      MONTHS[day.getMonth()] +
      " " +
      day.getFullYear() +
      ": " +
      marksText(mock.earned, mock.available) +
      " (" +
      count(share) +
      "\u202f%)" +
      (mock.ended === "time" ? ", ended when time ran out" : "")
    );
  }

  var api = {
    summarise: summarise,
    nextTemplate: nextTemplate,
    practiseUrl: practiseUrl,
    marksText: marksText,
    times: times,
    dueText: dueText,
    typeLine: typeLine,
    mockText: mockText,
    count: count,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.PracticeProgress = api;

  // ------------------------------------------------------------------ page

  if (typeof document === "undefined" || !root.ProgressStore) return;
  var Store = root.ProgressStore;
  var Schedule = root.Schedule;
  var ProgressFile = root.ProgressFile;

  function getStored(key) {
    try {
      return localStorage.getItem(key);
    } catch {
      return null;
    }
  }

  function setStored(key, text) {
    try {
      if (text === null) localStorage.removeItem(key);
      else localStorage.setItem(key, text);
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
    var nameInput = box.querySelector(".pp-student");
    var cleared = null; // the store as it was before Clear, for Undo
    document.documentElement.classList.add("pp-js");
    file.hidden = false;

    function say(message) {
      status.textContent = message;
    }

    // Each card's schedule: {id: {due, today}} (schedule.js replays the attempts).
    function dueByCard(progress, now) {
      var out = {};
      Schedule.cardsByDue(progress, now).forEach(function (c) {
        out[c.id] = c;
      });
      return out;
    }

    function render() {
      var read = Store.load();
      var progress = read.ok ? read.progress : Store.empty();
      // The store keeps the schedule as last worked out (the export carries it too).
      var schedule = Schedule.replay(progress);
      if (read.ok && JSON.stringify(schedule) !== JSON.stringify(progress.schedule)) {
        progress.schedule = schedule;
        Store.save(progress);
      }
      var now = Date.now(),
        dayEnds = Schedule.endOfDay(now),
        due = dueByCard(progress, now);
      data.types.forEach(function (kind) {
        var section = box.querySelector('.pp-type[data-type="' + kind.type + '"]');
        if (!kind.templates.length) {
          section.querySelector(".pp-line").textContent = typeLine({ inBank: 0 }, 0);
          return; // the static "not in the bank yet" stands
        }
        var s = summarise(kind, progress.attempts);
        var dueToday = kind.templates.filter(function (t) {
          return due[t.key] && due[t.key].today;
        }).length;
        section.querySelector(".pp-line").textContent = typeLine(s, dueToday);
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
            ? "(best " +
              marksText(entry.best.earned, entry.best.available) +
              ", tried " +
              times(entry.attempts) +
              (entry.withHelp ? ", " + times(entry.withHelp) + " with help" : "") +
              (due[t.key]
                ? ", " +
                  (due[t.key].soon
                    ? "back " + Schedule.backText(due[t.key].due, now)
                    : dueText(due[t.key].due, now, dayEnds))
                : "") +
              ")"
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
      var mocks = box.querySelector(".pp-mocks");
      mocks.hidden = !progress.mocks.length;
      // The latest in a line; the earlier ones folded, newest first, so the page stays short.
      var newest = progress.mocks.slice().reverse();
      mocks.querySelector(".pp-mock-latest").textContent = newest.length ? mockText(newest[0]) : "";
      var earlier = mocks.querySelector(".pp-mock-earlier");
      earlier.hidden = newest.length < 2;
      earlier.querySelector("summary").textContent =
        count(newest.length - 1) + " earlier mock test" + (newest.length === 2 ? "" : "s");
      var list = earlier.querySelector(".pp-mock-list");
      list.textContent = "";
      newest.slice(1).forEach(function (mock) {
        var item = document.createElement("li");
        item.textContent = mockText(mock);
        list.appendChild(item);
      });
      if (document.activeElement !== nameInput) nameInput.value = progress.student || "";
      clearButton.disabled = !read.ok ? false : progress.attempts.length + progress.mocks.length === 0;
      if (!read.ok) {
        say(
          "The progress kept in this browser cannot be read here: " +
            read.message +
            " It is kept as it is; Export copies it out.",
        );
      }
      // The plan (progress-plan.js) follows the same record.
      box.dispatchEvent(new CustomEvent("pp-changed"));
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

    function plural(n, one) {
      return count(n) + " " + one + (n === 1 ? "" : "s");
    }

    /* The name Export puts in the file: the one typed (kept in the store), else the one kept.
     * With none, Export asks for it and exports nothing; pressed again, it exports without. */
    var asked = false;
    function nameToExport(progress) {
      var typed = nameInput.value.trim().slice(0, Store.NAME_LENGTH);
      if (typed && typed !== progress.student) {
        progress.student = typed;
        Store.update(function (kept) {
          kept.student = typed;
        });
      }
      if (progress.student || asked) return true;
      asked = true;
      nameInput.focus();
      say(
        "Type your name in the box first: it goes in the file and its name, so your teacher can tell " +
          "whose it is. (Or press Export progress again to export without a name.)",
      );
      return false;
    }

    nameInput.addEventListener("change", function () {
      if (nameInput.value.trim()) nameToExport(Store.load().progress || Store.empty());
    });

    // The file carries the name, the schedule, the book's id and its records' checksum
    // (progress-file.js), and is named after the student.
    box.querySelector(".pp-export").addEventListener("click", function () {
      var read = Store.load();
      var today = new Date().toISOString().slice(0, 10);
      if (!read.ok) {
        // a format this page cannot read: copied out whole
        var name = ProgressFile.exportFileName(nameInput.value.trim(), today, Store.KEYS.exports);
        download(getStored(Store.STORE) || getStored(Store.OLD_STORE), name);
        say("Exported your progress to " + name + ".");
        return;
      }
      var progress = read.progress;
      if (!nameToExport(progress)) return;
      progress.schedule = Schedule.replay(progress);
      ProgressFile.exportFile(progress, data.book).then(function (out) {
        var name = ProgressFile.exportFileName(out.student, today, Store.KEYS.exports);
        download(JSON.stringify(out, null, 1), name);
        say(
          "Exported " +
            plural(out.attempts.length, "attempt") +
            " to " +
            name +
            ". Import that file on another device to carry on there" +
            (out.sha256 ? ", or give it to your teacher." : "."),
        );
      });
    });

    /* Import adds each attempt once. The file is taken as the class page takes it (exportCheck):
     * refused when another book's or edited; an older export is imported, "not checked". */
    function importText(text, name) {
      var incoming = Store.read(text);
      if (!incoming.ok) {
        say("Nothing was imported from " + name + ": " + incoming.message + " Your progress here is unchanged.");
        return Promise.resolve();
      }
      return ProgressFile.exportCheck(text ? JSON.parse(text) : {}, data.book).then(function (check) {
        if (!check.ok) {
          say("Nothing was imported from " + name + ": " + check.message + " Your progress here is unchanged.");
          return;
        }
        var here = Store.load();
        if (!here.ok) {
          say(
            "Nothing was imported: the progress kept in this browser is in a format this page " +
              "cannot read, and importing would replace it. It is unchanged.",
          );
          return;
        }
        var merged = Store.merge(here.progress, incoming.progress);
        merged.progress.schedule = Schedule.replay(merged.progress);
        if (!Store.save(merged.progress)) {
          say("Nothing was imported: this browser does not let the page keep data (private mode?).");
          return;
        }
        render();
        say(
          "Imported " +
            plural(merged.added, "attempt") +
            " from " +
            name +
            (check.checked ? "" : " (an " + check.label + ")") +
            (merged.already ? " (" + count(merged.already) + " were here already)" : "") +
            ".",
        );
      });
    }

    importInput.addEventListener("change", function () {
      var chosen = importInput.files && importInput.files[0];
      if (!chosen) return;
      var reader = new FileReader();
      reader.onload = function () {
        importInput.value = ""; // the same file can be chosen again
        importText(String(reader.result), chosen.name);
      };
      reader.onerror = function () {
        importInput.value = "";
        say("Nothing was imported: the file could not be read. Your progress here is unchanged.");
      };
      reader.readAsText(chosen);
    });

    /* Clear keeps an empty format 2 store (the format 1 one, never deleted, would otherwise
     * be read again); Undo puts back what was there, with any attempt made since. */
    clearButton.addEventListener("click", function () {
      cleared = getStored(Store.STORE);
      Store.save(Store.empty());
      render();
      undoButton.hidden = false;
      undoButton.focus();
      say("Progress cleared. Press Undo clear to bring it back (until you leave this page).");
    });

    undoButton.addEventListener("click", function () {
      var since = Store.load();
      setStored(Store.STORE, cleared);
      var before = Store.load();
      if (since.ok && before.ok && since.progress.attempts.length + since.progress.mocks.length) {
        Store.save(Store.merge(before.progress, since.progress).progress); // attempts made since: keep both
      }
      cleared = null;
      undoButton.hidden = true;
      render();
      clearButton.focus();
      say("Progress restored.");
    });

    // Another tab checking an answer updates this page.
    window.addEventListener("storage", function (event) {
      if (event.key === Store.STORE || event.key === Store.OLD_STORE || event.key === null) render();
    });
    // Printed, every type's questions show.
    window.addEventListener("beforeprint", function () {
      Array.prototype.forEach.call(box.querySelectorAll("details.pp-type"), function (d) {
        d.open = true;
      });
    });
    render();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
