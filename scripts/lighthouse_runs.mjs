// Lighthouse runs through one Chrome, one after another: node scripts/lighthouse_runs.mjs OUT URL...
// A URL given three times is run three times (Lighthouse clears the origin's storage and cache
// before each run, so every run is a first visit). OUT gets one entry per URL, in order:
// {performance, accessibility, best-practices, seo, fcp, lcp}. Chrome's flags come in LH_FLAGS
// (JSON) and its path in CHROME_PATH; scripts/browser.py's lighthouse_runs() calls this.
import fs from "fs";
import lighthouse from "lighthouse";
import * as chromeLauncher from "chrome-launcher";

const CATEGORIES = ["performance", "accessibility", "best-practices", "seo"];
const [out, ...urls] = process.argv.slice(2);
const chrome = await chromeLauncher.launch({ chromeFlags: JSON.parse(process.env.LH_FLAGS) });
const runs = [];
try {
  for (const url of urls) {
    // the full-page screenshot only illustrates the HTML report, which is not written
    const { lhr } = await lighthouse(url, {
      port: chrome.port,
      output: "json",
      logLevel: "error",
      onlyCategories: CATEGORIES,
      disableFullPageScreenshot: true,
    });
    const scores = Object.fromEntries(Object.entries(lhr.categories).map(([name, c]) => [name, c.score]));
    scores.fcp = lhr.audits["first-contentful-paint"].numericValue;
    scores.lcp = lhr.audits["largest-contentful-paint"].numericValue;
    runs.push(scores);
  }
} finally {
  await chrome.kill();
}
fs.writeFileSync(out, JSON.stringify(runs));
