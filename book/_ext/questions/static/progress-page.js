/* "Your practice", the page: each type's line, summary, named mistakes and questions' marks,
 * the mock tests, and the buttons that move the record (Export, Import, Clear, Undo clear).
 * What it shows is worked out by progress.js (the record's pure part, which the tests run
 * under Node); what the store and the exported file hold is described there. Browser only. */
(function (root) {
  "use strict";

  if (typeof document === "undefined" || !root.ProgressStore) return;
  var Store = root.ProgressStore;
  var Schedule = root.Schedule;
  var ProgressFile = root.ProgressFile;
  var Progress = root.PracticeProgress;
  var count = Progress.count,
    marksText = Progress.marksText,
    times = Progress.times,
    dueText = Progress.dueText,
    summarise = Progress.summarise,
    nextTemplate = Progress.nextTemplate,
    practiseUrl = Progress.practiseUrl,
    typeLine = Progress.typeLine,
    mockText = Progress.mockText;

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

  // The page's parts, and what it remembers between presses: the store as it was before
  // Clear (for Undo) and whether Export has asked for a name yet.
  function practicePage(box) {
    return {
      box: box,
      data: JSON.parse(box.querySelector("script.pp-data").textContent),
      status: box.querySelector(".pp-status"),
      importInput: box.querySelector(".pp-import"),
      undoButton: box.querySelector(".pp-undo"),
      clearButton: box.querySelector(".pp-clear"),
      nameInput: box.querySelector(".pp-student"),
      cleared: null, // the store as it was before Clear, for Undo
      asked: false,
    };
  }

  function say(page, message) {
    page.status.textContent = message;
  }

  // Each card's schedule: {id: {due, today}} (schedule.js replays the attempts).
  function dueByCard(progress, now) {
    var out = {};
    Schedule.cardsByDue(progress, now).forEach(function (c) {
      out[c.id] = c;
    });
    return out;
  }

  // The record kept in this browser (an empty one when it cannot be read). The store keeps
  // the schedule as last worked out (the export carries it too).
  function readRecord() {
    var read = Store.load();
    var progress = read.ok ? read.progress : Store.empty();
    var schedule = Schedule.replay(progress);
    if (read.ok && JSON.stringify(schedule) !== JSON.stringify(progress.schedule)) {
      progress.schedule = schedule;
      Store.save(progress);
    }
    return { read: read, progress: progress };
  }

  function typeSummaryText(s) {
    var bank = count(s.inBank) + " question" + (s.inBank === 1 ? "" : "s") + " in the bank";
    return s.tried
      ? "Tried " +
          count(s.tried) +
          " of " +
          bank +
          ". Marks: " +
          marksText(s.earned, s.available) +
          " (your best attempt at each question tried)."
      : bank.charAt(0).toUpperCase() + bank.slice(1) + "; none tried yet.";
  }

  function mistakesText(s) {
    return s.mistakes.length
      ? "Mistakes made most often: " +
          s.mistakes
            .slice(0, 3)
            .map(function (m) {
              return m.name + " (" + times(m.count) + ")";
            })
            .join("; ") +
          "."
      : "No named mistakes so far.";
  }

  // A question's marks in its type's list: its best attempt, how often tried (and with help),
  // and when its card is due; or its marks, not tried.
  function questionMarksText(t, entry, card, now, dayEnds) {
    if (!entry.best) return "(" + count(t.marks) + " mark" + (t.marks === 1 ? "" : "s") + ", not tried)";
    return (
      "(best " +
      marksText(entry.best.earned, entry.best.available) +
      ", tried " +
      times(entry.attempts) +
      (entry.withHelp ? ", " + times(entry.withHelp) + " with help" : "") +
      (card ? ", " + (card.soon ? "back " + Schedule.backText(card.due, now) : dueText(card.due, now, dayEnds)) : "") +
      ")"
    );
  }

  // "Practise this type" links to the question it serves next, with new numbers.
  function pointPractiseLink(section, kind, s) {
    var link = section.querySelector(".pp-practise");
    var next = nextTemplate(kind, s);
    if (!link || !next) return;
    link.href = practiseUrl(next);
    link.setAttribute("data-next", next.key);
    link.title = "Next: " + next.title + (s.templates[next.key].last ? "" : " (not tried yet)") + ", with new numbers";
  }

  // One type's section: its line, its summary and mistakes, each question's marks, its link.
  function renderType(section, kind, progress, clock) {
    if (!kind.templates.length) {
      section.querySelector(".pp-line").textContent = typeLine({ inBank: 0 }, 0);
      return; // the static "not in the bank yet" stands
    }
    var due = clock.due;
    var s = summarise(kind, progress.attempts);
    var dueToday = kind.templates.filter(function (t) {
      return due[t.key] && due[t.key].today;
    }).length;
    section.querySelector(".pp-line").textContent = typeLine(s, dueToday);
    section.querySelector(".pp-summary").textContent = typeSummaryText(s);
    var mistakes = section.querySelector(".pp-mistakes");
    mistakes.hidden = !s.tried;
    mistakes.textContent = mistakesText(s);
    kind.templates.forEach(function (t) {
      var marks = section.querySelector('li[data-key="' + t.key + '"] .pp-marks');
      marks.textContent = questionMarksText(t, s.templates[t.key], due[t.key], clock.now, clock.dayEnds);
    });
    pointPractiseLink(section, kind, s);
  }

  // The mock tests: the latest in a line; the earlier ones folded, newest first, so the page
  // stays short.
  function renderMocks(box, kept) {
    var mocks = box.querySelector(".pp-mocks");
    mocks.hidden = !kept.length;
    var newest = kept.slice().reverse();
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
  }

  function render(page) {
    var record = readRecord();
    var read = record.read,
      progress = record.progress;
    var now = Date.now();
    var clock = { now: now, dayEnds: Schedule.endOfDay(now), due: dueByCard(progress, now) };
    page.data.types.forEach(function (kind) {
      renderType(page.box.querySelector('.pp-type[data-type="' + kind.type + '"]'), kind, progress, clock);
    });
    renderMocks(page.box, progress.mocks);
    if (document.activeElement !== page.nameInput) page.nameInput.value = progress.student || "";
    page.clearButton.disabled = !read.ok ? false : progress.attempts.length + progress.mocks.length === 0;
    if (!read.ok) {
      say(
        page,
        "The progress kept in this browser cannot be read here: " +
          read.message +
          " It is kept as it is; Export copies it out.",
      );
    }
    // The plan (progress-plan.js) follows the same record.
    page.box.dispatchEvent(new CustomEvent("pp-changed"));
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
  function nameToExport(page, progress) {
    var typed = page.nameInput.value.trim().slice(0, Store.NAME_LENGTH);
    if (typed && typed !== progress.student) {
      progress.student = typed;
      Store.update(function (kept) {
        kept.student = typed;
      });
    }
    if (progress.student || page.asked) return true;
    page.asked = true;
    page.nameInput.focus();
    say(
      page,
      "Type your name in the box first: it goes in the file and its name, so your teacher can tell " +
        "whose it is. (Or press Export progress again to export without a name.)",
    );
    return false;
  }

  // The file carries the name, the schedule, the book's id and its records' checksum
  // (progress-file.js), and is named after the student.
  function exportProgress(page) {
    var read = Store.load();
    var today = new Date().toISOString().slice(0, 10);
    if (!read.ok) {
      // a format this page cannot read: copied out whole
      var name = ProgressFile.exportFileName(page.nameInput.value.trim(), today, Store.KEYS.exports);
      download(getStored(Store.STORE) || getStored(Store.OLD_STORE), name);
      say(page, "Exported your progress to " + name + ".");
      return;
    }
    var progress = read.progress;
    if (!nameToExport(page, progress)) return;
    progress.schedule = Schedule.replay(progress);
    ProgressFile.exportFile(progress, page.data.book).then(function (out) {
      var name = ProgressFile.exportFileName(out.student, today, Store.KEYS.exports);
      download(JSON.stringify(out, null, 1), name);
      say(
        page,
        "Exported " +
          plural(out.attempts.length, "attempt") +
          " to " +
          name +
          ". Import that file on another device to carry on there" +
          (out.sha256 ? ", or give it to your teacher." : "."),
      );
    });
  }

  // An import the file's check let through: its attempts join the record here, each once.
  function addImported(page, incoming, check, name) {
    var here = Store.load();
    if (!here.ok) {
      say(
        page,
        "Nothing was imported: the progress kept in this browser is in a format this page " +
          "cannot read, and importing would replace it. It is unchanged.",
      );
      return;
    }
    var merged = Store.merge(here.progress, incoming.progress);
    merged.progress.schedule = Schedule.replay(merged.progress);
    if (!Store.save(merged.progress)) {
      say(page, "Nothing was imported: this browser does not let the page keep data (private mode?).");
      return;
    }
    render(page);
    say(
      page,
      "Imported " +
        plural(merged.added, "attempt") +
        " from " +
        name +
        (check.checked ? "" : " (an " + check.label + ")") +
        (merged.already ? " (" + count(merged.already) + " were here already)" : "") +
        ".",
    );
  }

  /* Import adds each attempt once. The file is taken as the class page takes it (exportCheck):
   * refused when another book's or edited; an older export is imported, "not checked". */
  function importText(page, text, name) {
    var incoming = Store.read(text);
    if (!incoming.ok) {
      say(page, "Nothing was imported from " + name + ": " + incoming.message + " Your progress here is unchanged.");
      return Promise.resolve();
    }
    return ProgressFile.exportCheck(text ? JSON.parse(text) : {}, page.data.book).then(function (check) {
      if (!check.ok) {
        say(page, "Nothing was imported from " + name + ": " + check.message + " Your progress here is unchanged.");
        return;
      }
      addImported(page, incoming, check, name);
    });
  }

  function wireNameAndExport(page) {
    page.nameInput.addEventListener("change", function () {
      if (page.nameInput.value.trim()) nameToExport(page, Store.load().progress || Store.empty());
    });
    page.box.querySelector(".pp-export").addEventListener("click", function () {
      exportProgress(page);
    });
  }

  function wireImport(page) {
    var importInput = page.importInput;
    importInput.addEventListener("change", function () {
      var chosen = importInput.files && importInput.files[0];
      if (!chosen) return;
      var reader = new FileReader();
      reader.onload = function () {
        importInput.value = ""; // the same file can be chosen again
        importText(page, String(reader.result), chosen.name);
      };
      reader.onerror = function () {
        importInput.value = "";
        say(page, "Nothing was imported: the file could not be read. Your progress here is unchanged.");
      };
      reader.readAsText(chosen);
    });
  }

  /* Clear keeps an empty format 2 store (the format 1 one, never deleted, would otherwise
   * be read again); Undo puts back what was there, with any attempt made since. */
  function wireClearAndUndo(page) {
    var clearButton = page.clearButton,
      undoButton = page.undoButton;
    clearButton.addEventListener("click", function () {
      page.cleared = getStored(Store.STORE);
      Store.save(Store.empty());
      render(page);
      undoButton.hidden = false;
      undoButton.focus();
      say(page, "Progress cleared. Press Undo clear to bring it back (until you leave this page).");
    });
    undoButton.addEventListener("click", function () {
      var since = Store.load();
      setStored(Store.STORE, page.cleared);
      var before = Store.load();
      if (since.ok && before.ok && since.progress.attempts.length + since.progress.mocks.length) {
        Store.save(Store.merge(before.progress, since.progress).progress); // attempts made since: keep both
      }
      page.cleared = null;
      undoButton.hidden = true;
      render(page);
      clearButton.focus();
      say(page, "Progress restored.");
    });
  }

  function wireOtherTabsAndPrint(page) {
    // Another tab checking an answer updates this page.
    window.addEventListener("storage", function (event) {
      if (event.key === Store.STORE || event.key === Store.OLD_STORE || event.key === null) render(page);
    });
    // Printed, every type's questions show.
    window.addEventListener("beforeprint", function () {
      Array.prototype.forEach.call(page.box.querySelectorAll("details.pp-type"), function (d) {
        d.open = true;
      });
    });
  }

  function start() {
    var box = document.querySelector(".pp");
    if (!box) return;
    var page = practicePage(box);
    document.documentElement.classList.add("pp-js");
    box.querySelector(".pp-file").hidden = false;
    wireNameAndExport(page);
    wireImport(page);
    wireClearAndUndo(page);
    wireOtherTabsAndPrint(page);
    render(page);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
