/* "The class at a glance" (book/teachers-class.md), the page: a teacher loads the students'
 * exported progress files (Your practice, "Export progress") and sees marks and attempts per
 * student and per question type, the class's most frequent named mistakes (with who made
 * them) and each question's share of full marks; Download CSV saves all three. The files are
 * read in this browser only: nothing is sent anywhere. What is read, and how, is
 * class-table.js's (which this page's api, ClassProgress, is, for the tests under Node). */
(function (root) {
  "use strict";

  var api = root.ClassTable || require("./class-table.js");
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ClassProgress = api;

  if (typeof document === "undefined") return;

  var Progress = root.PracticeProgress;
  var ProgressFile = root.ProgressFile;
  var count = api.count,
    plural = api.plural,
    percent = api.percent,
    readFile = api.readFile,
    sharedNames = api.sharedNames,
    classTable = api.classTable,
    classMistakes = api.classMistakes,
    questionShares = api.questionShares,
    csvText = api.csvText;

  function element(tag, className, text) {
    var node = document.createElement(tag);
    if (className) node.className = className;
    if (text !== undefined) node.textContent = text; // file names are never read as HTML
    return node;
  }

  function marksCell(tag, cell) {
    var td = element(tag);
    td.setAttribute("data-earned", cell.earned);
    td.setAttribute("data-available", cell.available);
    td.setAttribute("data-attempts", cell.attempts);
    if (!cell.attempts) {
      td.appendChild(element("span", "cp-none", "not tried"));
      return td;
    }
    td.appendChild(element("span", "cp-marks", count(cell.earned) + "/" + count(cell.available)));
    td.appendChild(document.createTextNode(" "));
    td.appendChild(element("span", "cp-attempts", plural(cell.attempts, "attempt", "attempts")));
    return td;
  }

  function headerRow(labels) {
    var tr = element("tr");
    labels.forEach(function (label) {
      var th = element("th", null, label);
      th.scope = "col";
      tr.appendChild(th);
    });
    return tr;
  }

  // The page's parts, and what it holds: the files loaded so far.
  function classPage(box) {
    return {
      box: box,
      data: JSON.parse(box.querySelector("script.cp-data").textContent),
      status: box.querySelector(".cp-status"),
      refusedList: box.querySelector(".cp-refused"),
      results: box.querySelector(".cp-results"),
      input: box.querySelector(".cp-choose"),
      drop: box.querySelector(".cp-drop"),
      students: {}, // a file (its name and text) -> {student, file, checked, attempts}
      loads: 0,
    };
  }

  // The files' students by name, then by file name (two files of one name stay two rows).
  function sortedStudents(page) {
    return Object.keys(page.students)
      .map(function (key) {
        return page.students[key];
      })
      .sort(function (a, b) {
        return a.student.localeCompare(b.student) || a.file.localeCompare(b.file);
      });
  }

  // One row of the marks table: a student's (or the class's) marks per type, then the total.
  function marksRow(types, label, cells, total, older) {
    var tr = element("tr");
    var th = element("th", null, label);
    th.scope = "row";
    if (older) {
      th.appendChild(document.createTextNode(" "));
      th.appendChild(element("span", "cp-older", ProgressFile.OLDER));
    }
    tr.appendChild(th);
    cells.forEach(function (cell, i) {
      var td = marksCell("td", cell);
      td.setAttribute("data-type", types[i].type);
      tr.appendChild(td);
    });
    var td = marksCell("td", total);
    td.setAttribute("data-type", "total");
    td.className = "cp-total";
    tr.appendChild(td);
    return tr;
  }

  function renderMarksTable(page, table) {
    var types = page.data.types;
    var node = page.box.querySelector(".cp-table");
    node.textContent = "";
    node.appendChild(
      element("caption", null, "Marks (best attempt at each question tried) and attempts, by question type"),
    );
    var head = element("thead");
    var typeNames = types.map(function (kind) {
      return kind.name;
    });
    head.appendChild(headerRow(["Student"].concat(typeNames, ["Total"])));
    node.appendChild(head);
    var body = element("tbody");
    table.rows.forEach(function (r) {
      var tr = marksRow(types, r.label, r.cells, r.total, !r.checked);
      tr.setAttribute("data-student", r.student);
      tr.setAttribute("data-file", r.file);
      tr.setAttribute("data-checked", r.checked ? "yes" : "no");
      body.appendChild(tr);
    });
    node.appendChild(body);
    var foot = element("tfoot");
    var classRow = marksRow(types, "Class", table.typeTotals, table.total);
    classRow.setAttribute("data-student", "");
    foot.appendChild(classRow);
    node.appendChild(foot);
  }

  function renderMistakes(box, table) {
    var list = box.querySelector(".cp-mistakes");
    var mistakes = classMistakes(table).slice(0, 10);
    list.textContent = "";
    mistakes.forEach(function (m) {
      var li = element("li", null, m.name + ": " + Progress.times(m.count));
      li.appendChild(
        element("span", "cp-by", ", by " + plural(m.students, "student", "students") + " (" + m.who.join(", ") + ")"),
      );
      li.setAttribute("data-count", m.count);
      li.setAttribute("data-students", m.students);
      list.appendChild(li);
    });
    list.hidden = !mistakes.length;
    box.querySelector(".cp-no-mistakes").hidden = !!mistakes.length;
  }

  function questionRow(q) {
    var tr = element("tr");
    tr.setAttribute("data-key", q.template.key);
    var th = element("th", null, q.template.title);
    th.scope = "row";
    tr.appendChild(th);
    [
      q.kind.name,
      count(q.students),
      count(q.studentsFull),
      count(q.attempts),
      percent(q.full, q.attempts) + " (" + count(q.full) + " of " + count(q.attempts) + ")",
    ].forEach(function (text) {
      tr.appendChild(element("td", null, text));
    });
    return tr;
  }

  function renderQuestionShares(page, list) {
    var node = page.box.querySelector(".cp-questions");
    node.textContent = "";
    node.appendChild(element("caption", null, "The questions tried, lowest share of full marks first"));
    var head = element("thead");
    head.appendChild(
      headerRow([
        "Question",
        "Type",
        "Students who tried it",
        "Students with full marks",
        "Attempts",
        "Share of full marks",
      ]),
    );
    node.appendChild(head);
    var body = element("tbody");
    list.forEach(function (q) {
      body.appendChild(questionRow(q));
    });
    node.appendChild(body);
    var inBank = page.data.types.reduce(function (n, kind) {
      return n + kind.templates.length;
    }, 0);
    page.box.querySelector(".cp-untried").textContent =
      plural(inBank - list.length, "question", "questions") + " of the bank's " + count(inBank) + " tried by no one.";
  }

  // Two files that give one name: two rows (each with its file's name), and a note.
  function renderSharedNameNotes(box, list) {
    var notes = box.querySelector(".cp-notes");
    var shared = sharedNames(list);
    notes.textContent = "";
    Object.keys(shared).forEach(function (name) {
      var li = element(
        "li",
        null,
        plural(shared[name].length, "file gives", "files give") +
          " the name " +
          name +
          " (" +
          shared[name].join(", ") +
          "): each is a row of its own, not added together. If they are one student's, load only the latest; " +
          "if they are different students', ask each to export with their full name.",
      );
      li.setAttribute("data-name", name);
      notes.appendChild(li);
    });
    notes.hidden = !notes.children.length;
  }

  function render(page) {
    var list = sortedStudents(page);
    var types = page.data.types;
    page.results.hidden = !list.length;
    if (list.length) {
      var table = classTable(types, list);
      renderSharedNameNotes(page.box, list);
      renderMarksTable(page, table);
      renderMistakes(page.box, table);
      renderQuestionShares(page, questionShares(types, list));
    }
    page.loads += 1;
    page.box.setAttribute("data-loads", page.loads); // tests and the benchmark wait on it
  }

  // What the status line says once files are read: how many, which were older or loaded
  // before, how many were refused, and the class they make.
  function loadedText(page, tally, refused) {
    var shared = Object.keys(sharedNames(sortedStudents(page))).length;
    return (
      "Loaded " +
      plural(tally.loaded, "file", "files") +
      (tally.older ? " (" + plural(tally.older, "older export", "older exports") + ", not checked)" : "") +
      (tally.again
        ? " (" + plural(tally.again, "file", "files") + " loaded before: read again, not added twice)"
        : "") +
      (refused ? "; refused " + count(refused) + " (below, with why)" : "") +
      ". The class: " +
      plural(Object.keys(page.students).length, "student", "students") +
      (shared ? " (" + plural(shared, "name is", "names are") + " given by two files or more: see the note)" : "") +
      "."
    );
  }

  // Each file read and checked against this book; one that cannot be read is refused.
  function readEachFile(files, book) {
    return Promise.all(
      files.map(function (file) {
        return file.text().then(
          function (text) {
            return readFile(file.name, text, book).then(function (read) {
              read.key = file.name + "\n" + text; // the same file loaded again is one file
              return read;
            });
          },
          function () {
            return { ok: false, name: file.name, message: "it could not be read." };
          },
        );
      }),
    );
  }

  // The files read join the class (a refused one is listed, with why); returns the tally.
  function keepReadFiles(page, read) {
    var tally = { loaded: 0, older: 0, again: 0 };
    page.refusedList.textContent = "";
    read.forEach(function (file) {
      if (!file.ok) {
        var li = element("li", null, file.name + " was refused: " + file.message);
        li.setAttribute("data-file", file.name);
        page.refusedList.appendChild(li);
        return;
      }
      if (page.students[file.key]) tally.again += 1;
      page.students[file.key] = {
        student: file.student,
        file: file.name,
        checked: file.checked,
        attempts: file.attempts,
      };
      tally.loaded += 1;
      if (!file.checked) tally.older += 1;
    });
    page.refusedList.hidden = tally.loaded === read.length;
    return tally;
  }

  function loadFiles(page, files) {
    files = Array.prototype.slice.call(files || []);
    if (!files.length) return Promise.resolve();
    page.status.textContent = "Reading " + plural(files.length, "file", "files") + "…";
    return readEachFile(files, page.data.book).then(function (read) {
      var tally = keepReadFiles(page, read);
      render(page);
      page.status.textContent = loadedText(page, tally, read.length - tally.loaded);
    });
  }

  function wireFileChooser(page) {
    page.input.addEventListener("change", function () {
      loadFiles(page, page.input.files).then(function () {
        page.input.value = ""; // the same files can be chosen again
      });
    });
  }

  // Files dropped anywhere on the page load (a drop that misses the box must not open the
  // file in the tab, which would lose the class loaded so far).
  function wireDropAnywhere(page) {
    function carriesFiles(event) {
      return event.dataTransfer && Array.prototype.indexOf.call(event.dataTransfer.types, "Files") >= 0;
    }
    document.addEventListener("dragover", function (event) {
      if (!carriesFiles(event)) return;
      event.preventDefault();
      event.dataTransfer.dropEffect = "copy";
      page.drop.classList.add("cp-dragging");
    });
    document.addEventListener("dragleave", function (event) {
      if (!event.relatedTarget) page.drop.classList.remove("cp-dragging");
    });
    document.addEventListener("drop", function (event) {
      if (!carriesFiles(event)) return;
      event.preventDefault();
      page.drop.classList.remove("cp-dragging");
      loadFiles(page, event.dataTransfer.files);
    });
  }

  function wireCsvDownload(page) {
    page.box.querySelector(".cp-csv").addEventListener("click", function () {
      var text = csvText(page.data.types, sortedStudents(page));
      var a = element("a");
      a.href = URL.createObjectURL(new Blob([text], { type: "text/csv;charset=utf-8" }));
      a.download = "class-progress-" + new Date().toISOString().slice(0, 10) + ".csv";
      document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(function () {
        URL.revokeObjectURL(a.href);
      }, 1000);
      page.status.textContent = "Downloaded the table as " + a.download + ".";
    });
  }

  function wireClear(page) {
    page.box.querySelector(".cp-clear").addEventListener("click", function () {
      page.students = {};
      page.refusedList.textContent = "";
      page.refusedList.hidden = true;
      render(page);
      page.input.focus();
      page.status.textContent = "Cleared: no files are loaded.";
    });
  }

  function start() {
    var box = document.querySelector(".cp");
    if (!box) return;
    var page = classPage(box);
    document.documentElement.classList.add("cp-js");
    box.querySelector(".cp-load").hidden = false;
    wireFileChooser(page);
    wireDropAnywhere(page);
    wireCsvDownload(page);
    wireClear(page);
    render(page);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
