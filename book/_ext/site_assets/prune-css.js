// Ship only the CSS rules the site uses, minified: PurgeCSS keeps a rule of a bundle when its
// selectors' class names, ids and tags appear in the pages that link the bundle or in the
// scripts they load, which add classes at run time (the theme's, dark mode's, the
// explorables', the questions'). Called by book/_ext/site_assets when the HTML build finishes:
//   node prune-css.js SITE_DIR BUNDLE.css [BUNDLE.css ...]   (paths relative to SITE_DIR)
"use strict";
const fs = require("node:fs");
const path = require("node:path");
const { PurgeCSS } = require(path.join(process.cwd(), "node_modules", "purgecss"));
const csso = require(path.join(process.cwd(), "node_modules", "csso"));

// Classes a script builds from pieces, or a state the theme sets on <html>/<body>, that no
// page or script names whole: kept by pattern.
const SAFELIST = {
  standard: [/^q-/, /^pp-/, /^ex-/, /^offline-/, /^sb-/], // sb-: the sheet builder's data file
  // a selector of pseudo-classes alone (the theme's :focus-visible ring) names nothing to find
  greedy: [/data-theme/, /data-mode/, /prefers-color-scheme/, /focus/],
};

function pages(folder, out) {
  for (const entry of fs.readdirSync(folder, { withFileTypes: true })) {
    const full = path.join(folder, entry.name);
    if (entry.isDirectory() && !["_static", "_sources", "_images"].includes(entry.name)) pages(full, out);
    else if (entry.isFile() && entry.name.endsWith(".html")) out.push(full);
  }
  return out;
}

// Files a page's scripts load by name: Sphinx's search highlighter (on a page opened from a
// search result) and the questions' data files (New numbers' forms, the mock test's).
function onDemand(site) {
  const found = ["doctools.js", "sphinx_highlight.js"].map((name) => path.join(site, "_static", name));
  const questions = path.join(site, "_static", "questions");
  if (fs.existsSync(questions)) {
    for (const name of fs.readdirSync(questions)) if (name.endsWith(".js")) found.push(path.join(questions, name));
  }
  return found.filter((file) => fs.existsSync(file));
}

// The pages that link `bundle`, the scripts they load (their script bundle), and what those
// load on demand: each bundle keeps the rules of its own pages (not every file in _static:
// fontawesome.js names every icon there is, and no page loads it).
function contentOf(site, html, bundle) {
  const linking = html.filter((page) => fs.readFileSync(page, "utf8").includes(path.basename(bundle)));
  const scripts = new Set(onDemand(site));
  for (const page of linking) {
    for (const [, src] of fs.readFileSync(page, "utf8").matchAll(/<script[^>]*\ssrc="([^"?#]+)/g)) {
      if (src.includes("://")) continue;
      const file = path.resolve(path.dirname(page), src);
      if (fs.existsSync(file)) scripts.add(file);
    }
  }
  return [...linking, ...scripts];
}

async function main() {
  const [site, ...bundles] = process.argv.slice(2);
  if (!site || !bundles.length) throw new Error("usage: node prune-css.js SITE_DIR BUNDLE.css ...");
  const html = pages(site, []);
  // Every colour of tokens.css (book/_ext/design_tokens.py) stays, read by a rule or not.
  const tokens = path.join(site, "_static", "tokens.css");
  const variables = fs.existsSync(tokens)
    ? [...fs.readFileSync(tokens, "utf8").matchAll(/(--[\w-]+):/g)].map((m) => m[1])
    : [];
  for (const bundle of bundles) {
    const file = path.join(site, bundle);
    const [result] = await new PurgeCSS().purge({
      content: contentOf(site, html, bundle),
      css: [file],
      safelist: { ...SAFELIST, variables },
      fontFace: false,
      keyframes: false,
      // custom properties no kept rule reads (var()): most of the theme's and Bootstrap's
      variables: true,
    });
    // then minified (comments and spaces out; no rule merged or moved, so the cascade stands)
    fs.writeFileSync(file, csso.minify(result.css, { restructure: false }).css);
  }
}

main().catch((error) => {
  console.error(String((error && error.stack) || error));
  process.exit(1);
});
