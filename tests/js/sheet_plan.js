// Runs the sheet builder's plan (sheet-builder.js, over the one draw, question-draw.js) on cases
// read as JSON from stdin: {data, cases: [{types, marks, versions, seed}]}. Prints, per case, the
// plan's template keys and variants per version, or the error's message, as JSON for
// tests/no_site/test_sheet_builder.py to compare with the command line's.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const S = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "sheet-builder.js"));

jsonFilter((request) => ({
  plans: (request.cases || []).map((c) => {
    try {
      const sheet = S.plan(request.data, c);
      return {
        title: sheet.title,
        versions: sheet.versions.map((v) => v.items.map((item) => [item.template.key, item.variant])),
        repeats: S.readyMadeRepeats(sheet).map((r) => `Version ${r.letter}, question ${r.number}: as in ${r.where}`),
      };
    } catch (error) {
      if (!(error instanceof S.SheetError)) throw error;
      return { error: error.message };
    }
  }),
}));
