// Render TeX to SVG at build time with MathJax 3 (npm `mathjax`), so the site ships
// no maths JavaScript and no maths fonts. Called by site_assets/__init__.py with the
// path of the mathjax package. Protocol: one JSON request per line on stdin,
// {"tex": "...", "display": true}; one JSON reply per line on stdout,
// {"svg": "<svg ...>", "mathml": "<math ...>", "error": null | "message"}.
"use strict";
const readline = require("readline");

require(process.argv[2])
  .init({
    loader: { load: ["input/tex", "output/svg", "[tex]/ams", "[tex]/boldsymbol"] },
    tex: {
      // No 'noundefined': an unknown command is an error (the build fails), not red text.
      packages: { "[+]": ["ams", "boldsymbol"], "[-]": ["noundefined"] },
      formatError: (jax, err) => {
        throw err;
      },
    },
    // Each formula carries its own glyph definitions, so it stands alone anywhere
    // (body text, page titles in the navigation, captions).
    svg: { fontCache: "local" },
  })
  .then((MathJax) => {
    const adaptor = MathJax.startup.adaptor;
    readline.createInterface({ input: process.stdin }).on("line", (line) => {
      const { tex, display } = JSON.parse(line);
      let reply;
      try {
        const container = MathJax.tex2svg(tex, { display });
        reply = {
          svg: adaptor.outerHTML(adaptor.firstChild(container)),
          mathml: MathJax.tex2mml(tex, { display }),
          error: null,
        };
      } catch (err) {
        reply = { svg: "", mathml: "", error: String((err && err.message) || err) };
      }
      process.stdout.write(JSON.stringify(reply) + "\n");
    });
  })
  .catch((err) => {
    process.stderr.write("MathJax failed to start: " + err + "\n");
    process.exit(1);
  });
