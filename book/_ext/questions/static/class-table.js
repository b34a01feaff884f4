/* "The class at a glance" (book/teachers-class.md), the pure part: reading the students'
 * exported progress files and working out the class's table, mistakes, questions and CSV.
 * class.js is the page that shows them. Plain JavaScript, offline, no physics; runs under
 * Node for the tests (tests/js/class.test.js, through class.js).
 *
 * A file is refused, with its name and why, when it is not JSON, has no format version, is
 * from another book or its records do not match their checksum (progress-file.js), or an
 * attempt in it is not one Your practice would keep (progress-store.js, read: formats 1 and 2,
 * format 1 upgraded; the checksum is of the attempts as the file holds them). A file with no
 * book id or no checksum is an export from before they existed: it loads, with every attempt,
 * labelled "older export, not checked" (on the page and in the CSV). The others still load.
 * A student is the name the file carries (Export asks for it); an older file's is its file's
 * name without the extension ("amira-khan.json" is amira-khan). Each file is a row: two files
 * that give one name are two rows, each with its file's name, and a note says so (never
 * merged); the same file loaded again is read again, not added twice. Marks count as Your
 * practice counts them (summarise: the best attempt at each question tried); attempts are
 * every checked answer. The CSV holds the table, the mistakes and the questions (csvText). */
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

  /* The student an older file is (one that carries no name): its name without the extension. */
  function studentName(fileName) {
    return fileName.replace(/\.[^.]*$/, "") || fileName;
  }

  /* The name a file gives: the student's name it carries (Export asks for it), else the
   * file's name (an export from before exports carried a name). */
  function fileStudent(file, fileName) {
    var given = file && typeof file.student === "string" ? file.student.trim() : "";
    return given ? given.slice(0, 80) : studentName(fileName);
  }

  /* A promise of {ok: true, name, student, attempts, checked} or {ok: false, name, message}:
   * the message says why the file is refused (the end of "NAME was refused: …"). checked is
   * false for an older export (no book id or no checksum): read, but "older export, not
   * checked" (progress-file.js, exportCheck). */
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
    var read = Store.read(text);
    // Another book's file: said as the export's format says it (which book, and this one).
    if (!read.ok && !(file && typeof file.book === "string" && file.book !== book)) {
      return Promise.resolve(refused(read.message));
    }
    // The checksum is of the records as exported (a format 1 file's, before its upgrade).
    return ProgressFile.exportCheck(file, book).then(function (check) {
      if (!check.ok) return refused(check.message);
      if (!read.ok) return refused(read.message);
      return {
        ok: true,
        name: name,
        student: fileStudent(file, name),
        attempts: read.progress.attempts,
        checked: check.checked,
      };
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

  /* The names given by more than one of students ([{student, file}]): {name: [file, ...]}. */
  function sharedNames(students) {
    var files = {},
      shared = {};
    students.forEach(function (s) {
      (files[s.student] = files[s.student] || []).push(s.file || "");
    });
    Object.keys(files).forEach(function (name) {
      if (files[name].length > 1) shared[name] = files[name];
    });
    return shared;
  }

  /* The table: types (the build's list) across, students ([{student, file, checked,
   * attempts}], one a file) down. Each cell: {earned, available, attempts, tried, mistakes},
   * where earned/available are the student's best attempts at the type's questions tried
   * (summarise) and attempts count every attempt at them. Totals per student (row.total), per
   * type (typeTotals) and all. A row's label is its name, with its file's name when another
   * file gives the same name (two rows, never merged). */
  function classTable(types, students) {
    var shared = sharedNames(students);
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
      return {
        student: s.student,
        file: s.file || "",
        checked: s.checked !== false,
        label: shared[s.student] ? s.student + " (" + s.file + ")" : s.student,
        cells: cells,
        total: sum(cells),
      };
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

  /* Every named mistake the class made, most often first: {name, count, students, who} (who:
   * the rows' labels of the students who made it, in the table's order). */
  function classMistakes(table) {
    var byName = {},
      order = [];
    table.rows.forEach(function (row) {
      var mine = {};
      row.cells.forEach(function (cell) {
        cell.mistakes.forEach(function (m) {
          if (!byName[m.name]) {
            byName[m.name] = { name: m.name, count: 0, students: 0, who: [] };
            order.push(byName[m.name]);
          }
          byName[m.name].count += m.count;
          if (!mine[m.name]) {
            byName[m.name].students += 1;
            byName[m.name].who.push(row.label);
          }
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

  function csvLine(fields) {
    return fields.map(csvField).join(",");
  }

  /* The marks table's lines: a header row, a row a file (the student, the file, per type and
   * in total: marks earned, marks available and attempts; a type not tried has its marks
   * empty and "not tried"; whether the file was checked), a last row for the class. */
  function csvTable(types, table) {
    var header = ["Student", "File"];
    types.concat([{ name: "Total" }]).forEach(function (kind) {
      header.push(kind.name + ": marks earned", kind.name + ": marks available", kind.name + ": attempts");
    });
    header.push("Checksum");
    function line(first, cells, total, checked) {
      var out = first.slice();
      cells.concat([total]).forEach(function (cell) {
        if (cell.attempts) out.push(cell.earned, cell.available, cell.attempts);
        else out.push("not tried", "", 0);
      });
      out.push(checked);
      return csvLine(out);
    }
    var lines = [csvLine(header)];
    table.rows.forEach(function (row) {
      lines.push(line([row.student, row.file], row.cells, row.total, row.checked ? "checked" : ProgressFile.OLDER));
    });
    lines.push(line(["Class", ""], table.typeTotals, table.total, ""));
    return lines;
  }

  /* The CSV of the page (UTF-8 with a byte-order mark, so spreadsheets read names in any
   * script; CRLF lines): three sections, one after another, each with its header row and an
   * empty line between them (book/teachers-class.md says the layout):
   *   the marks table (csvTable);
   *   the mistakes: Mistake, Times, Students, Who (the students' names, "; " between them);
   *   the questions tried, lowest share of full marks first: Question, Key, Type, Students
   *   who tried it, Students with full marks, Attempts, Attempts with full marks, Share of
   *   full marks (%). */
  function csvText(types, students) {
    var table = classTable(types, students);
    var lines = csvTable(types, table);
    lines.push("", csvLine(["Mistake", "Times", "Students", "Who"]));
    classMistakes(table).forEach(function (m) {
      lines.push(csvLine([m.name, m.count, m.students, m.who.join("; ")]));
    });
    lines.push(
      "",
      csvLine([
        "Question",
        "Key",
        "Type",
        "Students who tried it",
        "Students with full marks",
        "Attempts",
        "Attempts with full marks",
        "Share of full marks (%)",
      ]),
    );
    questionShares(types, students).forEach(function (q) {
      var share = Math.round((100 * q.full) / q.attempts);
      lines.push(
        csvLine([q.template.title, q.template.key, q.kind.name, q.students, q.studentsFull, q.attempts, q.full, share]),
      );
    });
    return "\ufeff" + lines.join("\r\n") + "\r\n";
  }

  var api = {
    count: count,
    plural: plural,
    percent: percent,
    studentName: studentName,
    fileStudent: fileStudent,
    sharedNames: sharedNames,
    readFile: readFile,
    classTable: classTable,
    classMistakes: classMistakes,
    questionShares: questionShares,
    csvText: csvText,
  };
  if (typeof module === "object" && module.exports) module.exports = api;
  else root.ClassTable = api;
})(this);
