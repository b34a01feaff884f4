/* "The class at a glance" (book/teachers-class.md): a teacher loads the students' exported
 * progress files (Your practice, "Export progress") and sees marks and attempts per student
 * and per question type, the class's most frequent named mistakes and each question's share
 * of full marks; Download CSV gives the table. The files are read in this browser only:
 * nothing is sent anywhere. Plain JavaScript, offline, no physics.
 *
 * A file is refused, with its name and why, when it is not JSON, has no format version, is
 * from another book or its records do not match their checksum (progress-file.js), or an
 * attempt in it is not one Your practice would keep (progress-store.js, read: formats 1 and 2,
 * format 1 upgraded; the checksum is of the attempts as the file holds them). The others
 * still load. A student is the file's name without its extension: "amira-khan.json" is
 * amira-khan; a file of a name loaded before replaces it (a later export holds all of an
 * earlier one's attempts). Marks count as Your practice counts them (summarise: the best
 * attempt at each question tried); attempts are every checked answer.
 * The pure part (top) runs under Node for the tests; the page code (bottom) in a browser. */
(function (root) {
  "use strict";

  var Notation = root.Notation || require("../../notation/static/notation.js");
  var Progress = root.PracticeProgress || require("./progress.js");
  var Store = root.ProgressStore || require("./progress-store.js");
  var ProgressFile = root.ProgressFile || require("./progress-file.js");

  function count(n) {
    return Notation.formatNumber(n, null, { decimals: 0 });
  }
  function plural(n, one, many) {
    return count(n) + " " + (n === 1 ? one : many);
  }

  /* The student a file is: its name without the extension. */
  function studentName(fileName) {
    return fileName.replace(/\.[^.]*$/, "") || fileName;
  }

  /* A promise of {ok: true, name, student, attempts} or {ok: false, name, message}: the
   * message says why the file is refused (the end of "NAME was refused: …"). */
  function readFile(name, text, book) {
    function refused(message) {
      return { ok: false, name: name, message: message };
    }
    if (!text.trim()) return Promise.resolve(refused("it is empty."));
    var file = null;
    try {
      file = JSON.parse(text);
    } catch {
      /* Store.read says it is not JSON */
    }
    // Another book's file: said as the export's format says it (which book, and this one).
    if (file && typeof file.book === "string" && file.book !== book) {
      return ProgressFile.exportProblem(file, book).then(refused);
    }
    var read = Store.read(text);
    if (!read.ok) return Promise.resolve(refused(read.message));
    // The checksum is of the records as exported (a format 1 file's, before its upgrade).
    return ProgressFile.exportProblem(file, book).then(function (problem) {
      if (problem) return refused(problem);
      return { ok: true, name: name, student: studentName(name), attempts: read.progress.attempts };
    });
  }

  function sum(cells) {
    var total = { earned: 0, available: 0, attempts: 0 };
    cells.forEach(function (cell) {
      total.earned += cell.earned;
      total.available += cell.available;
      total.attempts += cell.attempts;
    });
    return total;
  }

  /* The table: types (the build's list) across, students ([{student, attempts}]) down. Each
   * cell: {earned, available, attempts, tried, mistakes}, where earned/available are the
   * student's best attempts at the type's questions tried (summarise) and attempts count
   * every attempt at them. Totals per student (row.total), per type (typeTotals) and all. */
  function classTable(types, students) {
    var rows = students.map(function (s) {
      var cells = types.map(function (kind) {
        var summary = Progress.summarise(kind, s.attempts);
        var attempts = 0;
        kind.templates.forEach(function (t) {
          attempts += summary.templates[t.key].attempts;
        });
        return {
          earned: summary.earned,
          available: summary.available,
          attempts: attempts,
          tried: summary.tried,
          mistakes: summary.mistakes,
        };
      });
      return { student: s.student, cells: cells, total: sum(cells) };
    });
    var typeTotals = types.map(function (kind, i) {
      return sum(
        rows.map(function (row) {
          return row.cells[i];
        }),
      );
    });
    return { rows: rows, typeTotals: typeTotals, total: sum(typeTotals) };
  }

  /* Every named mistake the class made, most often first: {name, count, students}. */
  function classMistakes(table) {
    var byName = {},
      order = [];
    table.rows.forEach(function (row) {
      var mine = {};
      row.cells.forEach(function (cell) {
        cell.mistakes.forEach(function (m) {
          if (!byName[m.name]) {
            byName[m.name] = { name: m.name, count: 0, students: 0 };
            order.push(byName[m.name]);
          }
          byName[m.name].count += m.count;
          if (!mine[m.name]) byName[m.name].students += 1;
          mine[m.name] = true;
        });
      });
    });
    return order.slice().sort(function (a, b) {
      return b.count - a.count || b.students - a.students;
    }); // stable: first met first on a tie
  }

  /* Each question tried by anyone: {kind, template, students (who tried it), studentsFull
   * (whose best attempt earned every mark), attempts, full (attempts that earned every mark)},
   * lowest share of full marks (full / attempts) first, then bank order. */
  function questionShares(types, students) {
    var byKey = {},
      order = [];
    types.forEach(function (kind) {
      kind.templates.forEach(function (t) {
        byKey[t.key] = { kind: kind, template: t, students: 0, studentsFull: 0, attempts: 0, full: 0 };
        order.push(byKey[t.key]);
      });
    });
    students.forEach(function (s) {
      var best = {};
      s.attempts.forEach(function (a) {
        var entry = byKey[a.question];
        if (!entry) return; // a question the bank no longer has: Your practice skips it too
        entry.attempts += 1;
        if (a.earned === a.available) entry.full += 1;
        best[a.question] = best[a.question] || a.earned === a.available;
      });
      Object.keys(best).forEach(function (key) {
        byKey[key].students += 1;
        if (best[key]) byKey[key].studentsFull += 1;
      });
    });
    return order
      .filter(function (entry) {
        return entry.attempts > 0;
      })
      .sort(function (a, b) {
        return a.full / a.attempts - b.full / b.attempts;
      });
  }

  function percent(part, whole) {
    return count(Math.round((100 * part) / whole)) + "%";
  }

  /* One CSV field (RFC 4180): quoted when it holds a comma, quote or line break. A text that a
   * spreadsheet would run as a formula (= + - @ first) gets a leading apostrophe. */
  function csvField(value) {
    if (typeof value === "number") return String(value);
    var text = /^[=+\-@\t\r]/.test(value) ? "'" + value : value;
    return /[",\r\n]/.test(text) ? '"' + text.replace(/"/g, '""') + '"' : text;
  }

  /* The table as CSV (UTF-8 with a byte-order mark, so spreadsheets read names in any
   * script; a header row; CRLF lines): per type and in total, marks earned, marks available
   * and attempts; a last row for the class. */
  function csvText(types, table) {
    var header = ["Student"];
    types.concat([{ name: "Total" }]).forEach(function (kind) {
      header.push(kind.name + ": marks earned", kind.name + ": marks available", kind.name + ": attempts");
    });
    function line(label, cells, total) {
      var out = [label];
      cells.concat([total]).forEach(function (cell) {
        out.push(cell.earned, cell.available, cell.attempts);
      });
      return out.map(csvField).join(",");
    }
    var lines = [header.map(csvField).join(",")];
    table.rows.forEach(function (row) {
      lines.push(line(row.student, row.cells, row.total));
    });
    lines.push(line("Class", table.typeTotals, table.total));
    return "\ufeff" + lines.join("\r\n") + "\r\n";
  }

  var api = {
    studentName: studentName,
    readFile: readFile,
    classTable: classTable,
    classMistakes: classMistakes,
    questionShares: questionShares,
    csvText: csvText,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ClassProgress = api;

  // ------------------------------------------------------------------ page

  if (typeof document === "undefined") return;

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
    var students = {}; // student -> {student, attempts}
    var loads = 0;
    document.documentElement.classList.add("cp-js");
    box.querySelector(".cp-load").hidden = false;

    function sorted() {
      return Object.keys(students)
        .sort(function (a, b) {
          return a.localeCompare(b);
        })
        .map(function (name) {
          return students[name];
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
      function row(label, cells, total, body) {
        var tr = element("tr");
        var th = element("th", null, label);
        th.scope = "row";
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
        row(r.student, r.cells, r.total, body).setAttribute("data-student", r.student);
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
        li.appendChild(element("span", "cp-by", ", by " + plural(m.students, "student", "students")));
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

    function render() {
      var list = sorted();
      results.hidden = !list.length;
      if (list.length) {
        var table = classTable(data.types, list);
        renderTable(table);
        renderMistakes(table);
        renderQuestions(questionShares(data.types, list));
      }
      loads += 1;
      box.setAttribute("data-loads", loads); // tests and the benchmark wait on it
    }

    function loadFiles(files) {
      files = Array.prototype.slice.call(files || []);
      if (!files.length) return Promise.resolve();
      status.textContent = "Reading " + plural(files.length, "file", "files") + "…";
      return Promise.all(
        files.map(function (file) {
          return file.text().then(
            function (text) {
              return readFile(file.name, text, data.book);
            },
            function () {
              return { ok: false, name: file.name, message: "it could not be read." };
            },
          );
        }),
      ).then(function (read) {
        var loaded = 0,
          replaced = 0;
        refusedList.textContent = "";
        read.forEach(function (file) {
          if (!file.ok) {
            var li = element("li", null, file.name + " was refused: " + file.message);
            li.setAttribute("data-file", file.name);
            refusedList.appendChild(li);
            return;
          }
          if (students[file.student]) replaced += 1;
          students[file.student] = { student: file.student, attempts: file.attempts };
          loaded += 1;
        });
        var refused = read.length - loaded;
        refusedList.hidden = !refused;
        render();
        status.textContent =
          "Loaded " +
          plural(loaded, "file", "files") +
          (replaced ? " (" + count(replaced) + " in place of an earlier file of the same name)" : "") +
          (refused ? "; refused " + count(refused) + " (below, with why)" : "") +
          ". The class: " +
          plural(Object.keys(students).length, "student", "students") +
          ".";
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
      var text = csvText(data.types, classTable(data.types, sorted()));
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
