/* The teachers' sheet builder's page (book/teachers.md, "Make your own"): the form, the data
 * file loaded on the first "Make the sheets" (teachers/sheet-data.js, by a <script> element, so
 * file:// works too), and each version's question sheet and answer key, assembled from the
 * HTML that physics_figures wrote into the data: nothing here computes a number. The draws are
 * sheet-builder.js (window.SheetBuilder). */
(function (root) {
  "use strict";

  var plan = root.SheetBuilder.plan;
  var SheetError = root.SheetBuilder.SheetError;
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
        var page = data.variants[item.template.key][String(item.variant)];
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
      '<span>Class <span class="sb-blank"></span></span></p>' +
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
        var page = data.variants[item.template.key][String(item.variant)];
        return (
          '<section class="sb-key-question"><h4>Question ' +
          (i + 1) +
          ": " +
          esc(item.template.title) +
          ' <span class="sb-which">(' +
          esc(item.template.key) +
          ", variant " +
          item.variant +
          ')</span> <span class="sb-marks">[' +
          marksText(item.template.marks) +
          "]</span></h4>" +
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

  function start() {
    var box = document.querySelector(".sb");
    if (!box) return;
    var form = box.querySelector(".sb-form");
    var status = box.querySelector(".sb-status");
    var output = box.querySelector(".sb-output");
    var printButton = box.querySelector(".sb-print");
    box.querySelector(".sb-needs-js").hidden = true;
    form.hidden = false;
    var loading = null;

    function load() {
      if (root.SheetBuilderData) return Promise.resolve(root.SheetBuilderData);
      if (!loading) {
        loading = new Promise(function (resolve, reject) {
          var script = document.createElement("script");
          script.src = box.getAttribute("data-src");
          script.onload = function () {
            if (root.SheetBuilderData) resolve(root.SheetBuilderData);
            else reject(new Error("empty"));
          };
          script.onerror = function () {
            loading = null; // try again next time (back online)
            script.remove();
            reject(new Error("unreachable"));
          };
          document.head.appendChild(script);
        });
      }
      return loading;
    }

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

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      var types = Array.from(form.querySelectorAll('input[name="types"]:checked')).map(function (input) {
        return input.value;
      });
      var options = {
        types: types,
        marks: whole(form.querySelector("#sb-marks")),
        versions: whole(form.querySelector("#sb-versions")),
        seed: whole(form.querySelector("#sb-seed")),
      };
      say("Loading the questions…");
      load().then(
        function (data) {
          var sheet;
          try {
            sheet = plan(data, options);
          } catch (error) {
            if (!(error instanceof SheetError)) throw error;
            say("The sheets cannot be made: " + error.message + ".", true);
            return;
          }
          var made = today();
          output.innerHTML = sheet.versions
            .map(function (version) {
              return sheetHtml(data, sheet, version, made) + keyHtml(data, sheet, version, made);
            })
            .join("");
          output.hidden = false;
          printButton.hidden = false;
          markPath();
          say(
            "Made " +
              sheet.versions.length +
              (sheet.versions.length === 1 ? " version" : " versions") +
              " of " +
              marksText(sheet.marks) +
              ", " +
              sheet.versions[0].items.length +
              " questions each, with their keys, below. Print them with the Print button " +
              "(each sheet and each key starts a new page).",
          );
        },
        function () {
          say(
            "The questions could not be loaded (" +
              box.getAttribute("data-src") +
              "). Open this page once while online; after that the builder works offline.",
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
