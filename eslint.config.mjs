// ESLint for the site's JavaScript (flat config; `make check` and pre-commit run it).
// Prettier owns the layout (.prettierrc.json), so only js.configs.recommended's rules are on.
import js from "@eslint/js";
import globals from "globals";

export default [
  {
    ignores: ["node_modules/", "_build/", ".venv/"],
  },
  js.configs.recommended,
  {
    // The reader's browser: plain scripts loaded by <script> (no modules), sharing a few
    // globals (Explorables, ExplorableModels, Notation). models.js, notation.js and the
    // marking engine's scripts also load under Node's tests: their `typeof module === "object"
    // && module.exports` guard reads `module`, and under Node they `require` what a page
    // loads before them; the browser has neither.
    files: ["book/_ext/**/static/**/*.js"],
    languageOptions: {
      sourceType: "script",
      globals: { ...globals.browser, module: "readonly", require: "readonly" },
    },
  },
  {
    // The service worker's template: book/_ext/offline writes __PRECACHE__ (the file list)
    // into it when the site is built.
    files: ["book/_ext/offline/sw_template.js"],
    languageOptions: {
      sourceType: "script",
      globals: { ...globals.serviceworker, __PRECACHE__: "readonly" },
    },
  },
  {
    // Node: the build's helpers (MathJax, PurgeCSS, terser) and the tests' runners, CommonJS.
    files: ["book/_ext/site_assets/*.js", "tests/js/**/*.js", "tests/js_explorables/**/*.js"],
    languageOptions: {
      sourceType: "commonjs",
      globals: globals.node,
    },
  },
  {
    // Functions a reader can hold (issue 39): at most 80 lines (a file's own wrapper, an
    // immediately called function, is not counted) and at most 15 paths through one.
    // tests/test_function_size.py checks these limits stay here.
    files: ["**/*.js", "**/*.mjs"],
    rules: {
      "max-lines-per-function": ["error", { max: 80 }],
      complexity: ["error", 15],
    },
  },
  {
    // Node modules: this file, and scripts/lighthouse_runs.mjs (Lighthouse's node API)
    files: ["eslint.config.mjs", "scripts/*.mjs"],
    languageOptions: { sourceType: "module", globals: globals.node },
  },
];
