/* The teachers' sheet builder's page (book/teachers.md, "Make your own"): the form, the data
 * file loaded on the first "Make the sheets" (teachers/sheet-data.js), and each version's
 * question sheet and answer key, assembled from the HTML that physics_figures wrote into the
 * data: nothing here computes a number. The draws are sheet-builder.js (window.SheetBuilder).
 *
 * The data comes by fetch() and is kept in this page's own cache (the Cache API, KEPT) before
 * the sheets are made, so the builder works offline the next day, however early the first
 * sheets were made (the service worker takes the page only after its precache). Offline, the
 * kept copy (or the service worker's, whoever fetched it) is read. From file://, where fetch()
 * cannot read, or where no Cache API exists (a page not served securely), a <script> element
 * loads it. */
(function (root) {
  "use strict";

  var plan = root.SheetBuilder.plan;
  var SheetError = root.SheetBuilder.SheetError;
  var readyMadeRepeats = root.SheetBuilder.readyMadeRepeats;
  var variantHtml = root.SheetBuilder.variantHtml;
  /* The page's own cache of the data file (not "dynamics-…": a new build's worker keeps it). */
  var KEPT = "sheet-builder-data";
  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();

  // ----------------------------------------------------------------------- the page

  function esc(text) {
    var div = document.createElement("div");
    div.textContent = String(text);
    return div.innerHTML;
  }

  function marksText(n) {
    return n + (n === 1 ? " mark" : " marks");
  }

  /* "[6 marks]" that never wraps (a no-break space; sheet-builder.css: nowrap). */
  function marksTag(n) {
    return "[" + marksText(n).replace(" ", "\u00a0") + "]";
  }

  function today() {
    return new Date().toLocaleDateString("en-GB", { day: "numeric", month: "long", year: "numeric" });
  }

  /* One version's question sheet: its heading (title, version, the date made, name and class
   * lines, the data line, the total, a table of the marks), then each question. */
  function sheetHtml(data, sheet, version, made) {
    var rows = version.items
      .map(function (item, i) {
        return "<tr><td>" + (i + 1) + "</td><td>" + item.template.marks + "</td><td></td></tr>";
      })
      .join("");
    var questions = version.items
      .map(function (item, i) {
        var page = variantHtml(data, item.template.key, item.variant);
        return (
          '<section class="sb-question" data-question="' +
          esc(item.template.key) +
          '" data-variant="' +
          item.variant +
          '"><h4>Question ' +
          (i + 1) +
          "</h4>" +
          page.sheet +
          '<p class="sb-question-total">[Total for question ' +
          (i + 1) +
          ": " +
          marksText(item.template.marks) +
          "]</p></section>"
        );
      })
      .join("");
    return (
      '<section class="sb-sheet" data-version="' +
      version.letter +
      '"><h3 class="sb-title">' +
      esc(sheet.title) +
      '</h3><p class="sb-version">Version ' +
      version.letter +
      " · " +
      esc(made) +
      '</p><p class="sb-fields"><span>Name <span class="sb-blank sb-wide"></span></span> ' +
      '<span>Class <span class="sb-blank"></span></span> <span>Date <span class="sb-blank"></span></span></p>' +
      '<ul class="sb-instructions"><li>Answer <strong>all</strong> questions in the spaces provided.</li>' +
      "<li>Show your working: marks are given for the method as well as the answer.</li>" +
      "<li>Give each numerical answer to an appropriate number of significant figures, with its unit.</li>" +
      "<li>The number of marks is given in brackets [ ] at the end of each part.</li></ul>" +
      '<p class="sb-data"><strong>' +
      esc(data.dataLine) +
      '</strong></p><p class="sb-total">Total: ' +
      marksText(version.marks) +
      '</p><table class="sb-table"><thead><tr><th scope="col">Question</th><th scope="col">Marks available</th>' +
      '<th scope="col">Marks awarded</th></tr></thead><tbody>' +
      rows +
      '</tbody><tfoot><tr><th scope="row">Total</th><td>' +
      version.marks +
      "</td><td></td></tr></tfoot></table>" +
      questions +
      '<p class="sb-end">End of the questions.</p></section>'
    );
  }

  /* One version's answer key: per question its template and variant, the answers, working,
   * ecf notes, common wrong answers and the mark scheme (all from the data file). */
  function keyHtml(data, sheet, version, made) {
    var questions = version.items
      .map(function (item, i) {
        var page = variantHtml(data, item.template.key, item.variant);
        return (
          '<section class="sb-key-question"><h4>Question ' +
          (i + 1) +
          ": " +
          esc(item.template.title) +
          ' <span class="sb-which">(' +
          esc(item.template.key) +
          ", variant " +
          item.variant +
          ')</span> <span class="sb-marks">' +
          marksTag(item.template.marks) +
          "</span></h4>" +
          page.key +
          "</section>"
        );
      })
      .join("");
    return (
      '<section class="sb-key" data-version="' +
      version.letter +
      '"><h3 class="sb-title">' +
      esc(sheet.title) +
      '</h3><p class="sb-version">Answer key, version ' +
      version.letter +
      " · " +
      esc(made) +
      "</p><p>Total: " +
      marksText(version.marks) +
      ". Seed " +
      sheet.seed +
      ". " +
      esc(data.keyCodes) +
      " " +
      esc(data.dataLine) +
      "</p>" +
      questions +
      "</section>"
    );
  }

  /* A whole number as typed, or the text itself (an error then quotes it, as Python would). */
  function whole(input) {
    var text = input.value.trim();
    return /^-?\d+$/.test(text) ? Number(text) : text;
  }

  // ------------------------------------------------------------------- the data file

  function runScript(text) {
    var script = document.createElement("script");
    script.text = text;
    document.head.appendChild(script);
    script.remove();
  }

  /* The data file's text from the network, kept in KEPT before it is used; offline (or a
   * failed reply), the kept copy, this page's or the service worker's. */
  function fetchKept(url) {
    return fetch(url)
      .then(function (response) {
        if (!response.ok) throw new Error("HTTP " + response.status);
        return response.text().then(function (text) {
          var copy = new Response(text, { headers: { "Content-Type": "text/javascript; charset=utf-8" } });
          return root.caches
            .open(KEPT)
            .then(function (cache) {
              return cache.put(url, copy);
            })
            .then(
              function () {
                return text;
              },
              function () {
                return text; // a full disk keeps nothing, but these sheets are still made
              },
            );
        });
      })
      .catch(function () {
        return root.caches.match(url).then(function (kept) {
          if (!kept) throw new Error("unreachable");
          return kept.text();
        });
      });
  }

  function scriptLoad(url) {
    return new Promise(function (resolve, reject) {
      var script = document.createElement("script");
      script.src = url;
      script.onload = resolve;
      script.onerror = function () {
        script.remove();
        reject(new Error("unreachable"));
      };
      document.head.appendChild(script);
    });
  }

  function loader(src) {
    var loading = null;
    return function load() {
      if (root.SheetBuilderData) return Promise.resolve(root.SheetBuilderData);
      if (!loading) {
        var url = new URL(src, document.baseURI).href;
        var kept = /^https?:$/.test(location.protocol) && root.caches && root.fetch;
        loading = (kept ? fetchKept(url).then(runScript) : scriptLoad(url)).then(function () {
          if (!root.SheetBuilderData) throw new Error("empty");
          return root.SheetBuilderData;
        });
        loading.catch(function () {
          loading = null; // try again next time (back online)
        });
      }
      return loading;
    };
  }

  // ------------------------------------------------------------------- the form

  function checkedTypes(form) {
    return Array.from(form.querySelectorAll('input[name="types"]:checked'));
  }

  function typeTitle(input) {
    return input.parentElement.textContent.trim();
  }

  function listed(names) {
    return names.length < 2 ? names.join("") : names.slice(0, -1).join("; ") + " and " + names[names.length - 1];
  }

  /* How many versions the types ticked allow (each type's data-versions, from
   * worksheets.usable_versions), and the types that set that limit. */
  function versionLimit(form) {
    var boxes = checkedTypes(form);
    var most = 26;
    boxes.forEach(function (input) {
      most = Math.min(most, Number(input.getAttribute("data-versions")));
    });
    var fewest = boxes.filter(function (input) {
      return Number(input.getAttribute("data-versions")) === most;
    });
    return { most: most, limiting: fewest.map(typeTitle), all: boxes.length === fewest.length };
  }

  /* The Versions field's label, limit and hint follow the types ticked. */
  function showVersionLimit(form) {
    var limit = versionLimit(form);
    var input = form.querySelector("#sb-versions");
    input.max = String(limit.most);
    form.querySelector(".sb-versions-range").textContent = "1 to " + limit.most;
    form.querySelector("#sb-versions-why").textContent =
      "The types ticked allow up to " +
      limit.most +
      " versions: each version has its own numbers for every question, from those the site does not show, and " +
      listed(limit.limiting) +
      (limit.limiting.length === 1 ? " has" : " have") +
      " the fewest." +
      (limit.all ? "" : " Untick " + (limit.limiting.length === 1 ? "it" : "them") + " to allow more.");
  }

  /* A refusal in the form's words: what was chosen, and what to change on the form. */
  function teacherMessage(error, form, options) {
    var field = error.field;
    var limit = versionLimit(form);
    if (field === "types") return "Tick at least one question type.";
    if (field === "seed") return "The seed must be a whole number, 0 or more (the same seed makes the same sheets).";
    if (field === "versions" && typeof options.versions === "number" && options.versions > limit.most) {
      return (
        "The types ticked allow at most " +
        limit.most +
        (limit.most === 1 ? " version" : " versions") +
        ": every version needs its own numbers for each question, and " +
        listed(limit.limiting) +
        (limit.limiting.length === 1 ? " has" : " have") +
        " no more that the site does not show. Ask for " +
        limit.most +
        " or fewer" +
        (limit.all ? "." : ", or untick " + listed(limit.limiting) + ".")
      );
    }
    if (field === "versions") return "Versions must be a whole number from 1 to " + limit.most + ".";
    if (error.available !== undefined) {
      return (
        "The types ticked hold " +
        error.available +
        " marks of questions in all: ask for " +
        error.available +
        " marks or fewer, or tick more types."
      );
    }
    if (error.nearest) {
      return (
        "No set of questions of the types ticked adds up to exactly " +
        options.marks +
        " marks: the nearest totals are " +
        error.nearest[0] +
        " and " +
        error.nearest[1] +
        ". Change Total marks to one of those, or tick other types."
      );
    }
    return "Total marks must be a whole number, 1 or more.";
  }

  /* What the status says of a ready-made worksheet's numbers: avoided, or where repeated. */
  function repeatsNote(sheet) {
    var repeats = readyMadeRepeats(sheet);
    if (!repeats.length) return " No question repeats the numbers of a ready-made worksheet on this page.";
    return (
      " Too many versions to avoid the ready-made worksheets' numbers everywhere: " +
      repeats
        .map(function (r) {
          return "version " + r.letter + ", question " + r.number + " is as in " + r.where;
        })
        .join("; ") +
      ". Fewer versions avoid them."
    );
  }

  function madeText(sheet, what) {
    var count = sheet.versions.length;
    var each = marksText(sheet.marks) + ", " + sheet.versions[0].items.length + " questions each";
    var made = {
      both: count + (count === 1 ? " version" : " versions") + " of " + each + ", with their keys",
      sheets: count + (count === 1 ? " question sheet" : " question sheets") + " of " + each + " (no keys)",
      keys:
        "the answer " +
        (count === 1 ? "key" : "keys") +
        " of " +
        count +
        (count === 1 ? " version" : " versions") +
        " of " +
        each +
        " (no question sheets)",
    }[what];
    return "Made " + made + ", below. Print them with the Print button (each starts a new page).";
  }

  /* The form's choices, as the plan takes them. */
  function formOptions(form) {
    return {
      types: checkedTypes(form).map(function (input) {
        return input.value;
      }),
      marks: whole(form.querySelector("#sb-marks")),
      versions: whole(form.querySelector("#sb-versions")),
      seed: whole(form.querySelector("#sb-seed")),
      make: (form.querySelector('input[name="make"]:checked') || { value: "both" }).value,
    };
  }

  function pages(data, sheet, what) {
    var made = today();
    return sheet.versions
      .map(function (version) {
        return (
          (what === "keys" ? "" : sheetHtml(data, sheet, version, made)) +
          (what === "sheets" ? "" : keyHtml(data, sheet, version, made))
        );
      })
      .join("");
  }

  function start() {
    var box = document.querySelector(".sb");
    if (!box) return;
    var form = box.querySelector(".sb-form");
    var status = box.querySelector(".sb-status");
    var output = box.querySelector(".sb-output");
    var printButton = box.querySelector(".sb-print");
    box.querySelector(".sb-needs-js").hidden = true;
    form.hidden = false;
    var load = loader(box.getAttribute("data-src"));
    showVersionLimit(form);
    form.addEventListener("change", function (event) {
      if (event.target.name === "types") showVersionLimit(form);
    });

    function say(message, isError) {
      status.textContent = message;
      status.classList.toggle("sb-error", Boolean(isError));
    }

    /* Printing shows the sheets alone: every element beside the path from the article to them
     * is hidden in print (sheet-builder.css), whatever the page around them holds. */
    function markPath() {
      var article = output.closest(".bd-article") || document.body;
      for (var node = output.parentElement; node && node !== article.parentElement; node = node.parentElement) {
        node.classList.add("sb-path");
      }
      document.documentElement.classList.add("sb-has-sheets");
    }

    function make(data, options) {
      var sheet;
      try {
        sheet = plan(data, options);
      } catch (error) {
        if (!(error instanceof SheetError)) throw error;
        say("The sheets cannot be made. " + teacherMessage(error, form, options), true);
        return;
      }
      output.innerHTML = pages(data, sheet, options.make);
      output.hidden = false;
      printButton.hidden = false;
      markPath();
      say(madeText(sheet, options.make) + repeatsNote(sheet));
    }

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      var options = formOptions(form);
      say("Loading the questions…");
      load().then(
        function (data) {
          make(data, options);
        },
        function () {
          say(
            "The questions could not be loaded (" +
              box.getAttribute("data-src") +
              "): this browser has no copy of them yet. Connect to the internet and press Make the sheets " +
              "once; from then on the builder works offline in this browser.",
            true,
          );
        },
      );
    });

    printButton.addEventListener("click", function () {
      window.print();
    });
  }
})(this);
