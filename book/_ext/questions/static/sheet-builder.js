/* The teachers' sheet builder (book/teachers.md, "Make your own"): worksheets in several
 * versions, each with its own answer key, made in this browser with no Python and no server.
 *
 * The questions come from the teachers-only data file the build writes (sheet_builder.py:
 * teachers/sheet-data.js, loaded on the first "Make the sheets" and kept for offline use by
 * sheet-builder-page.js): every bank template's reserve variants, their sheets and keys as
 * HTML and their graphs as SVG, all computed by physics_figures. This script computes no
 * physics and no key. It repeats physics_figures.worksheets.plan exactly: the same FNV-1a
 * draws (seededOrder), the same subset sums over each type's templates in the same order,
 * with the same tie-breaking (Python's dicts keep insertion order: Maps here; totals tried
 * from the largest; a new cost wins only when lower by more than 1e-9), and the same errors.
 * So the same types, marks, versions and seed give the same questions as
 * `python -m physics_figures.worksheets`. This file is the plan (it runs under Node for the
 * tests too), from the draws it shares with the mock test (question-draw.js);
 * sheet-builder-page.js is the page: the form and the sheets it prints. */
(function (root) {
  "use strict";

  // the shared draws (question-draw.js): loaded before this script, or required under Node
  var Draw = typeof module !== "undefined" && module.exports ? require("./question-draw.js") : root.QuestionDraw;
  var seededOrder = Draw.seededOrder,
    chooseTemplates = Draw.chooseTemplates,
    require_ = Draw.check,
    isWhole = Draw.isWhole,
    SheetError = Draw.DrawError;

  var MAX_VERSIONS = 26;
  var LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";

  /* The templates of the types asked, in the bank's order (worksheets.select). */
  function select(data, types) {
    require_(types.length > 0, "types", types, "or templates must name something to ask");
    var keys = data.types.map(function (t) {
      return t.key;
    });
    types.forEach(function (type) {
      require_(keys.indexOf(type) >= 0, "types", type, "must name question types of the bank: " + keys.join(", "));
    });
    return data.templates.filter(function (template) {
      return types.indexOf(template.type) >= 0;
    });
  }

  /* A template's reserve variants in the order a seed draws them; variant 0, when the reserve
   * holds it, last; before it, the variants a ready-made worksheet prints (template.readyMade)
   * after all the others (worksheets.variant_order with the ready-made ones to avoid). */
  function variantOrder(template, seed) {
    var drawn = seededOrder(
      template.reserve.filter(function (i) {
        return i;
      }),
      "worksheet-variants:" + template.key,
      seed,
    );
    var made = template.readyMade || {};
    return drawn
      .filter(function (i) {
        return !(String(i) in made);
      })
      .concat(
        drawn.filter(function (i) {
          return String(i) in made;
        }),
        template.reserve.filter(function (i) {
          return !i;
        }),
      );
  }

  /* Where a sheet repeats a ready-made worksheet's numbers (worksheets.ready_made_repeats):
   * [{letter, number, where}]. */
  function readyMadeRepeats(sheet) {
    var out = [];
    sheet.versions.forEach(function (version) {
      version.items.forEach(function (item, i) {
        var made = item.template.readyMade || {};
        if (String(item.variant) in made)
          out.push({ letter: version.letter, number: i + 1, where: made[item.variant] });
      });
    });
    return out;
  }

  /* How many versions a template can give (worksheets.usable_versions, in a fresh kit). */
  function usableVersions(template) {
    return template.oneWording ? MAX_VERSIONS : template.reserve.length;
  }

  /* A custom sheet (worksheets.plan with a fresh Kit): {title, seed, marks, versions: [{letter,
   * marks, items: [{template, variant}]}]}. Throws a SheetError saying what cannot be made. */
  function plan(data, options) {
    var versions = options.versions;
    var seed = options.seed;
    var marks = options.marks;
    var templates = select(data, options.types);
    require_(
      isWhole(versions) && versions >= 1 && versions <= MAX_VERSIONS,
      "versions",
      versions,
      "must be a whole number from 1 to " + MAX_VERSIONS + " (A to Z)",
    );
    require_(isWhole(seed) && seed >= 0, "seed", seed, "must be a whole number, 0 or more");
    var short = templates.filter(function (t) {
      return usableVersions(t) < versions;
    });
    require_(
      !short.length,
      "versions",
      versions,
      "needs that many different variants of every template, but " +
        short
          .map(function (t) {
            return t.key + " has " + usableVersions(t) + " the site does not show";
          })
          .join(", ") +
        ": ask for fewer versions or leave those templates out",
    );
    require_(isWhole(marks) && marks >= 1, "marks", marks, "must be a whole number, 1 or more");
    templates = chooseTemplates(data, templates, marks, seed);
    var drawn = templates.map(function (t) {
      if (t.oneWording) return Array(versions).fill(0); // a definition: the same in every version
      return variantOrder(t, seed).slice(0, versions);
    });
    var titles = options.types.map(function (type) {
      return data.types.filter(function (t) {
        return t.key === type;
      })[0].title;
    });
    var out = [];
    for (var v = 0; v < versions; v++) {
      out.push({
        letter: LETTERS[v],
        marks: marks,
        items: templates.map(function (t, i) {
          return { template: t, variant: drawn[i][v] };
        }),
      });
    }
    return { title: "Worksheet: " + titles.join("; "), seed: seed, marks: marks, versions: out };
  }

  var api = {
    fnv1a: Draw.fnv1a,
    seededOrder: seededOrder,
    subsetSums: Draw.subsetSums,
    chooseTemplates: chooseTemplates,
    variantOrder: variantOrder,
    usableVersions: usableVersions,
    readyMadeRepeats: readyMadeRepeats,
    plan: plan,
    SheetError: SheetError,
  };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.SheetBuilder = api; // the page's part: sheet-builder-page.js
})(this);
