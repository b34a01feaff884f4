// The pure parts of the export's format (progress-file.js) and the class page (class-table.js, through class.js),
// run with `node --test tests/js`.
"use strict";
const test = require("node:test");
const assert = require("node:assert/strict");
const crypto = require("node:crypto");
const path = require("node:path");
const STATIC = path.join(__dirname, "..", "..", "book", "_ext", "questions", "static");
require("./book_storage.js"); // the storage keys a page of the book names
const F = require(path.join(STATIC, "progress-file.js"));
const C = require(path.join(STATIC, "class.js"));
const fs = require("node:fs");
const V1_FILE = path.join(__dirname, "..", "fixtures", "progress_v1", "progress-v1.json");

const BOOK = "dynamics";
const EXPORTS = "dynamics-progress"; // the book's storage_keys()["exports"] (physics_figures/topics.py)
function attempt(question, type, earned, available, at, mistakes) {
  return { question, type, variant: 0, earned, available, at, mistakes: mistakes || [] };
}
const types = [
  {
    type: "drag",
    name: "Drag, terminal velocity",
    templates: [
      { key: "d1", title: "Drag 1", marks: 4 },
      { key: "d2", title: "Drag 2", marks: 2 },
    ],
  },
  { type: "two-d", name: "Two dimensions", templates: [{ key: "t1", title: "Two-d 1", marks: 3 }] },
  { type: "empty", name: "Not in the bank yet", templates: [] },
];

async function exported(attempts, book) {
  return JSON.stringify(await F.exportFile({ version: 1, attempts }, book || BOOK), null, 1);
}

test("the checksum is the SHA-256 of JSON.stringify(attempts), as the page documents", async () => {
  const attempts = [attempt("d1", "drag", 3, 4, 1700000000000, ["g = 10"])];
  const expected = crypto.createHash("sha256").update(JSON.stringify(attempts), "utf8").digest("hex");
  assert.equal(await F.recordsChecksum(attempts), expected);
  assert.equal(await F.recordsChecksum([]), crypto.createHash("sha256").update("[]").digest("hex"));
});

test("an export keeps version 1, names the book and carries the checksum, every stored field kept", async () => {
  const attempts = [attempt("d1", "drag", 3, 4, 10)];
  const file = await F.exportFile({ version: 1, attempts, definitions: { version: 1, cards: {} } }, BOOK);
  assert.deepEqual(Object.keys(file), ["version", "book", "sha256", "attempts", "definitions"]);
  assert.equal(file.version, 1);
  assert.equal(file.book, BOOK);
  assert.match(file.sha256, /^[0-9a-f]{64}$/);
  assert.deepEqual(file.definitions, { version: 1, cards: {} });
});

test("a class file is read: the student is its name without the extension", async () => {
  const read = await C.readFile("amira-khan.json", await exported([attempt("d1", "drag", 3, 4, 1)]), BOOK);
  assert.equal(read.ok, true);
  assert.equal(read.student, "amira-khan");
  assert.equal(read.attempts.length, 1);
  // spacing in the file does not count: the records do
  const spaced = JSON.stringify(JSON.parse(await exported([attempt("d1", "drag", 3, 4, 1)])), null, 4);
  assert.equal((await C.readFile("b.json", spaced, BOOK)).ok, true);
  assert.equal(C.studentName("x.y.json"), "x.y");
  assert.equal(C.studentName("noextension"), "noextension");
});

test("a format 2 export is read, and so is a real format 1 export of the site before it", async () => {
  const v2 = await F.exportFile(
    { version: 2, attempts: [attempt("d1", "drag", 3, 4, 1)], definitions: { version: 1, cards: {} }, mocks: [] },
    BOOK,
  );
  const read = await C.readFile("v2.json", JSON.stringify(v2), BOOK);
  assert.equal(read.ok, true, read.message);
  assert.equal(read.attempts.length, 1);
  // tests/fixtures/progress_v1: three answers and two self-test marks, exported on the site
  const v1 = JSON.parse(fs.readFileSync(V1_FILE, "utf8"));
  const old = await C.readFile("v1.json", JSON.stringify(v1), BOOK);
  assert.equal(old.ok, true, old.message);
  for (const a of v1.attempts) assert.ok(old.attempts.some((b) => b.question === a.question && b.at === a.at));
});

test("a file that is not this book's unedited export is refused, saying why", async () => {
  const good = JSON.parse(await exported([attempt("d1", "drag", 3, 4, 1), attempt("t1", "two-d", 1, 3, 2)]));
  const edited = structuredClone(good);
  edited.attempts[1].earned = 3; // still a valid attempt: only the checksum tells
  const noBook = structuredClone(good);
  delete noBook.book;
  const noSum = structuredClone(good);
  delete noSum.sha256;
  const cases = [
    ["", /it is empty/],
    ["{not json", /not JSON/],
    ['{"attempts": []}', /no format version/],
    [JSON.stringify({ ...good, version: 3 }), /newer version/],
    [
      await exported([attempt("d1", "drag", 3, 4, 1)], "waves"),
      /another book \("waves"\), not this one \("dynamics"\)/,
    ],
    [JSON.stringify(edited), /do not match their checksum: it was changed after it was exported/],
    [JSON.stringify({ ...good, attempts: [{ question: "d1" }] }), /attempt 1 of 1 has no question type/],
  ];
  for (const [text, reason] of cases) {
    const read = await C.readFile("f.json", text, BOOK);
    assert.equal(read.ok, false, text);
    assert.equal(read.name, "f.json");
    assert.match(read.message, reason, text);
  }
  assert.equal((await C.readFile("g.json", JSON.stringify(good), BOOK)).ok, true);
  // another book's file without a checksum is still another book's
  const otherOld = structuredClone(noSum);
  otherOld.book = "waves";
  assert.match((await C.readFile("w.json", JSON.stringify(otherOld), BOOK)).message, /another book \("waves"\)/);
});

test("an export from before the book id or the checksum loads with every attempt, not checked", async () => {
  const good = JSON.parse(await exported([attempt("d1", "drag", 3, 4, 1), attempt("t1", "two-d", 1, 3, 2)]));
  const noBook = structuredClone(good);
  delete noBook.book;
  const noSum = structuredClone(good);
  delete noSum.sha256;
  const plain = { version: 1, attempts: good.attempts }; // as the site wrote before 8be9d57
  for (const file of [noBook, noSum, plain]) {
    const read = await C.readFile("old.json", JSON.stringify(file), BOOK);
    assert.equal(read.ok, true, read.message);
    assert.equal(read.checked, false);
    assert.deepEqual(
      read.attempts.map((a) => [a.question, a.earned, a.at]),
      [
        ["d1", 3, 1],
        ["t1", 1, 2],
      ],
    );
  }
  assert.equal((await C.readFile("new.json", JSON.stringify(good), BOOK)).checked, true);
  assert.deepEqual(await F.exportCheck(plain, BOOK), { ok: true, checked: false, label: "older export, not checked" });
});

test("a student is the name the file carries; an older file's is its file's name", async () => {
  const named = await F.exportFile({ version: 2, student: "Amira Khan", attempts: [], mocks: [] }, BOOK);
  assert.deepEqual(Object.keys(named).slice(0, 4), ["version", "book", "student", "sha256"]);
  const read = await C.readFile("dynamics-progress-2026-11-28.json", JSON.stringify(named), BOOK);
  assert.equal(read.student, "Amira Khan");
  assert.equal((await C.readFile("ben.json", JSON.stringify({ version: 1, attempts: [] }), BOOK)).student, "ben");
  assert.equal(F.exportFileName("Amira Khan", "2026-11-28", EXPORTS), "dynamics-progress-Amira-Khan-2026-11-28.json");
  assert.equal(
    F.exportFileName(" Zoë O'Brien / 12B ", "2026-11-28", EXPORTS),
    "dynamics-progress-Zoë-O-Brien-12B-2026-11-28.json",
  );
  assert.equal(F.exportFileName("../..", "2026-11-28", EXPORTS), "dynamics-progress-2026-11-28.json");
  assert.equal(F.exportFileName("", "2026-11-28", EXPORTS), "dynamics-progress-2026-11-28.json");
});

test("two files that give one name are two rows, each labelled with its file, never merged", () => {
  const two = [
    { student: "Sam", file: "a.json", attempts: [attempt("d1", "drag", 4, 4, 1)] },
    { student: "Sam", file: "b.json", attempts: [attempt("d1", "drag", 1, 4, 2, ["g = 10"])] },
    { student: "Tia", file: "c.json", attempts: [] },
  ];
  const table = C.classTable(types, two);
  assert.deepEqual(
    table.rows.map((r) => [r.label, r.total.earned, r.total.attempts]),
    [
      ["Sam (a.json)", 4, 1],
      ["Sam (b.json)", 1, 1],
      ["Tia", 0, 0],
    ],
  );
  assert.deepEqual(C.sharedNames(two), { Sam: ["a.json", "b.json"] });
  assert.deepEqual(C.classMistakes(table)[0].who, ["Sam (b.json)"]);
});

const students = [
  {
    student: "amira",
    attempts: [
      attempt("d1", "drag", 1, 4, 1, ["g = 10"]),
      attempt("d1", "drag", 4, 4, 2),
      attempt("d2", "drag", 0, 2, 3, ["drag as resultant", "g = 10"]),
      attempt("gone", "drag", 1, 1, 4, ["not counted"]), // no longer in the bank
    ],
  },
  {
    student: "ben", // the same mistake in two types: one student
    attempts: [attempt("t1", "two-d", 2, 3, 1, ["g = 10"]), attempt("d1", "drag", 3, 4, 2, ["g = 10"])],
  },
  { student: "cy", attempts: [] },
];

test("the table: best marks per question tried and every attempt, per student and type, with totals", () => {
  const table = C.classTable(types, students);
  const cell = (row, i) => {
    const c = table.rows[row].cells[i];
    return [c.earned, c.available, c.attempts];
  };
  assert.deepEqual(cell(0, 0), [4 + 0, 4 + 2, 3]); // d1 best 4/4, d2 0/2; three attempts
  assert.deepEqual(cell(0, 1), [0, 0, 0]);
  assert.deepEqual(cell(1, 0), [3, 4, 1]);
  assert.deepEqual(cell(1, 1), [2, 3, 1]);
  assert.deepEqual(cell(2, 0), [0, 0, 0]);
  assert.deepEqual(table.rows[0].total, { earned: 4, available: 6, attempts: 3 });
  assert.deepEqual(table.rows[1].total, { earned: 5, available: 7, attempts: 2 });
  assert.deepEqual(table.typeTotals[0], { earned: 7, available: 10, attempts: 4 });
  assert.deepEqual(table.typeTotals[2], { earned: 0, available: 0, attempts: 0 });
  assert.deepEqual(table.total, { earned: 9, available: 13, attempts: 5 });
});

test("the class's mistakes: most often first, with how many students made each", () => {
  const mistakes = C.classMistakes(C.classTable(types, students));
  assert.deepEqual(mistakes, [
    { name: "g = 10", count: 4, students: 2, who: ["amira", "ben"] },
    { name: "drag as resultant", count: 1, students: 1, who: ["amira"] },
  ]);
});

test("each question's share of full marks: full-mark attempts over attempts, lowest first", () => {
  const shares = C.questionShares(types, students);
  const row = (q) => [q.template.key, q.students, q.studentsFull, q.attempts, q.full];
  assert.deepEqual(shares.map(row), [
    ["d2", 1, 0, 1, 0],
    ["t1", 1, 0, 1, 0],
    ["d1", 2, 1, 3, 1],
  ]);
});

test("the CSV: the table (not tried left empty), then the mistakes with who, then the questions", () => {
  const text = C.csvText(
    types,
    students.map((s, i) => ({ ...s, file: s.student + ".json", checked: i !== 1 })),
  );
  assert.ok(text.startsWith("\ufeff"));
  const lines = text.slice(1).split("\r\n");
  assert.equal(lines.pop(), "");
  assert.equal(
    lines[0],
    'Student,File,"Drag, terminal velocity: marks earned","Drag, terminal velocity: marks available",' +
      '"Drag, terminal velocity: attempts",Two dimensions: marks earned,Two dimensions: marks available,' +
      "Two dimensions: attempts,Not in the bank yet: marks earned,Not in the bank yet: marks available," +
      "Not in the bank yet: attempts,Total: marks earned,Total: marks available,Total: attempts,Checksum",
  );
  assert.deepEqual(lines.slice(1), [
    "amira,amira.json,4,6,3,not tried,,0,not tried,,0,4,6,3,checked",
    'ben,ben.json,3,4,1,2,3,1,not tried,,0,5,7,2,"older export, not checked"',
    "cy,cy.json,not tried,,0,not tried,,0,not tried,,0,not tried,,0,checked",
    "Class,,7,10,4,2,3,1,not tried,,0,9,13,5,",
    "",
    "Mistake,Times,Students,Who",
    "g = 10,4,2,amira; ben",
    "drag as resultant,1,1,amira",
    "",
    "Question,Key,Type,Students who tried it,Students with full marks,Attempts,Attempts with full marks," +
      "Share of full marks (%)",
    'Drag 2,d2,"Drag, terminal velocity",1,0,1,0,0',
    "Two-d 1,t1,Two dimensions,1,0,1,0,0",
    'Drag 1,d1,"Drag, terminal velocity",2,1,3,1,33',
  ]);
});

test("a CSV field is quoted when it must be, and a name is never a spreadsheet formula", () => {
  const row = C.csvText(types, [{ student: '=HYPERLINK("x")', file: "x.json", attempts: [] }]).split("\r\n")[1];
  assert.ok(row.startsWith('"\'=HYPERLINK(""x"")",x.json,'), row);
});
