// Joins the sheet builder's variants from their pieces (sheet-builder.js, variantHtml), as the
// builder's page does, on a request read as JSON from stdin: {data, pages: [[key, variant]]}
// (no pages: every variant of the data). Prints [{key, variant, sheet, key_html}] as JSON for
// the Python tests to compare with physics_figures' HTML.
"use strict";
const jsonFilter = require("./json_filter.js");
const path = require("node:path");
const S = require(path.join(__dirname, "..", "..", "book", "_ext", "questions", "static", "sheet-builder.js"));

jsonFilter((request) => {
  const data = request.data;
  const pages =
    request.pages ||
    Object.keys(data.variants).flatMap((key) => Object.keys(data.variants[key]).map((variant) => [key, variant]));
  return pages.map(([key, variant]) => {
    const html = S.variantHtml(data, key, variant);
    return { key, variant: String(variant), sheet: html.sheet, key_html: html.key };
  });
});
