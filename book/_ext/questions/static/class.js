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

  function start() {
    var box = document.querySelector(".cp");
    if (!box) return;
    var data = JSON.parse(box.querySelector("script.cp-data").textContent);
    var status = box.querySelector(".cp-status");
    var refusedList = box.querySelector(".cp-refused");
    var results = box.querySelector(".cp-results");
    var input = box.querySelector(".cp-choose");
    var drop = box.querySelector(".cp-drop");
    var students = {}; // a file (its name and text) -> {student, file, checked, attempts}
    var loads = 0;
    document.documentElement.classList.add("cp-js");
    box.querySelector(".cp-load").hidden = false;

    // The files' students by name, then by file name (two files of one name stay two rows).
    function sorted() {
      return Object.keys(students)
        .map(function (key) {
          return students[key];
        })
        .sort(function (a, b) {
          return a.student.localeCompare(b.student) || a.file.localeCompare(b.file);
        });
    }

    function renderTable(table) {
      var node = box.querySelector(".cp-table");
      node.textContent = "";
      node.appendChild(
        element("caption", null, "Marks (best attempt at each question tried) and attempts, by question type"),
      );
      var head = element("thead");
      head.appendChild(
        headerRow(
          ["Student"].concat(
            data.types.map(function (kind) {
              return kind.name;
            }),
            ["Total"],
          ),
        ),
      );
      node.appendChild(head);
      function row(label, cells, total, body, older) {
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
          td.setAttribute("data-type", data.types[i].type);
          tr.appendChild(td);
        });
        var td = marksCell("td", total);
        td.setAttribute("data-type", "total");
        td.className = "cp-total";
        tr.appendChild(td);
        body.appendChild(tr);
        return tr;
      }
      var body = element("tbody");
      table.rows.forEach(function (r) {
        var tr = row(r.label, r.cells, r.total, body, !r.checked);
        tr.setAttribute("data-student", r.student);
        tr.setAttribute("data-file", r.file);
        tr.setAttribute("data-checked", r.checked ? "yes" : "no");
      });
      node.appendChild(body);
      var foot = element("tfoot");
      row("Class", table.typeTotals, table.total, foot).setAttribute("data-student", "");
      node.appendChild(foot);
    }

    function renderMistakes(table) {
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

    function renderQuestions(list) {
      var node = box.querySelector(".cp-questions");
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
        body.appendChild(tr);
      });
      node.appendChild(body);
      var inBank = data.types.reduce(function (n, kind) {
        return n + kind.templates.length;
      }, 0);
      box.querySelector(".cp-untried").textContent =
        plural(inBank - list.length, "question", "questions") + " of the bank's " + count(inBank) + " tried by no one.";
    }

    // Two files that give one name: two rows (each with its file's name), and a note.
    function renderNotes(list) {
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

    function render() {
      var list = sorted();
      results.hidden = !list.length;
      if (list.length) {
        var table = classTable(data.types, list);
        renderNotes(list);
        renderTable(table);
        renderMistakes(table);
        renderQuestions(questionShares(data.types, list));
      }
      loads += 1;
      box.setAttribute("data-loads", loads); // tests and the benchmark wait on it
    }

    function loadedText(loaded, older, again, refused) {
      var names = sharedNames(sorted());
      var shared = Object.keys(names).length;
      return (
        "Loaded " +
        plural(loaded, "file", "files") +
        (older ? " (" + plural(older, "older export", "older exports") + ", not checked)" : "") +
        (again ? " (" + plural(again, "file", "files") + " loaded before: read again, not added twice)" : "") +
        (refused ? "; refused " + count(refused) + " (below, with why)" : "") +
        ". The class: " +
        plural(Object.keys(students).length, "student", "students") +
        (shared ? " (" + plural(shared, "name is", "names are") + " given by two files or more: see the note)" : "") +
        "."
      );
    }

    function loadFiles(files) {
      files = Array.prototype.slice.call(files || []);
      if (!files.length) return Promise.resolve();
      status.textContent = "Reading " + plural(files.length, "file", "files") + "…";
      return Promise.all(
        files.map(function (file) {
          return file.text().then(
            function (text) {
              return readFile(file.name, text, data.book).then(function (read) {
                read.key = file.name + "\n" + text; // the same file loaded again is one file
                return read;
              });
            },
            function () {
              return { ok: false, name: file.name, message: "it could not be read." };
            },
          );
        }),
      ).then(function (read) {
        var loaded = 0,
          older = 0,
          again = 0;
        refusedList.textContent = "";
        read.forEach(function (file) {
          if (!file.ok) {
            var li = element("li", null, file.name + " was refused: " + file.message);
            li.setAttribute("data-file", file.name);
            refusedList.appendChild(li);
            return;
          }
          if (students[file.key]) again += 1;
          students[file.key] = {
            student: file.student,
            file: file.name,
            checked: file.checked,
            attempts: file.attempts,
          };
          loaded += 1;
          if (!file.checked) older += 1;
        });
        refusedList.hidden = loaded === read.length;
        render();
        status.textContent = loadedText(loaded, older, again, read.length - loaded);
      });
    }

    input.addEventListener("change", function () {
      loadFiles(input.files).then(function () {
        input.value = ""; // the same files can be chosen again
      });
    });

    // Files dropped anywhere on the page load (a drop that misses the box must not open the
    // file in the tab, which would lose the class loaded so far).
    function carriesFiles(event) {
      return event.dataTransfer && Array.prototype.indexOf.call(event.dataTransfer.types, "Files") >= 0;
    }
    document.addEventListener("dragover", function (event) {
      if (!carriesFiles(event)) return;
      event.preventDefault();
      event.dataTransfer.dropEffect = "copy";
      drop.classList.add("cp-dragging");
    });
    document.addEventListener("dragleave", function (event) {
      if (!event.relatedTarget) drop.classList.remove("cp-dragging");
    });
    document.addEventListener("drop", function (event) {
      if (!carriesFiles(event)) return;
      event.preventDefault();
      drop.classList.remove("cp-dragging");
      loadFiles(event.dataTransfer.files);
    });

    box.querySelector(".cp-csv").addEventListener("click", function () {
      var text = csvText(data.types, sorted());
      var a = element("a");
      a.href = URL.createObjectURL(new Blob([text], { type: "text/csv;charset=utf-8" }));
      a.download = "class-progress-" + new Date().toISOString().slice(0, 10) + ".csv";
      document.body.appendChild(a);
      a.click();
      a.remove();
      setTimeout(function () {
        URL.revokeObjectURL(a.href);
      }, 1000);
      status.textContent = "Downloaded the table as " + a.download + ".";
    });

    box.querySelector(".cp-clear").addEventListener("click", function () {
      students = {};
      refusedList.textContent = "";
      refusedList.hidden = true;
      render();
      input.focus();
      status.textContent = "Cleared: no files are loaded.";
    });
    render();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(this);
