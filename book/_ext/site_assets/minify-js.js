// The site's own scripts (the explorables', the questions', notation's, ...) are written to
// be read, with comments; students download them minified. Called by book/_ext/site_assets
// when the HTML build finishes, on the copies in the site (the sources stay as they are):
//   node minify-js.js SITE_DIR SCRIPT.js [SCRIPT.js ...]   (paths relative to SITE_DIR)
// Top-level names are kept: the scripts share globals (Explorables, Notation, ...).
"use strict";
const fs = require("node:fs");
const path = require("node:path");
const { minify } = require(path.join(process.cwd(), "node_modules", "terser"));

async function main() {
  const [site, ...scripts] = process.argv.slice(2);
  if (!site || !scripts.length) throw new Error("usage: node minify-js.js SITE_DIR SCRIPT.js ...");
  for (const script of scripts) {
    const file = path.join(site, script);
    const result = await minify(fs.readFileSync(file, "utf8"), {
      ecma: 2020,
      compress: { passes: 2 },
      mangle: true,
      format: { comments: false },
    });
    fs.writeFileSync(file, result.code + "\n");
  }
}

main().catch((error) => {
  console.error(String((error && error.stack) || error));
  process.exit(1);
});
