/* The teachers' sheet builder (book/teachers.md, "Make your own"): worksheets in several
 * versions, each with its own answer key, made in this browser with no Python and no server.
 *
 * The questions come from the teachers-only data file the build writes (sheet_builder.py:
 * teachers/sheet-data.js, loaded on the first "Make the sheets" and kept for offline use by
 * sheet-builder-page.js): every bank template's reserve variants, their sheets and keys as
 * HTML and their graphs as SVG, all computed by physics_figures. This script computes no
 * physics and no key, and draws nothing itself: the draw is question-draw.js, the one the
 * command line (`python -m physics_figures.worksheets`) runs under Node, so the same types,
 * marks, versions and seed give the same questions. This file turns the form's choices into a
 * draw and the draw into versions (it runs under Node for the tests too);
 * sheet-builder-page.js is the page: the form and the sheets it prints. */
(function (root) {
  "use strict";

  // the draw (question-draw.js): loaded before this script, or required under Node
  var Draw = typeof module !== "undefined" && module.exports ? require("./question-draw.js") : root.QuestionDraw;
  var require_ = Draw.check;
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

  /* The variants the ready-made worksheets print, to take only when no other is left. */
  function readyMade(data) {
    var avoid = {};
    data.templates.forEach(function (template) {
      if (template.readyMade) avoid[template.key] = template.readyMade;
    });
    return avoid;
  }

  /* A custom sheet, as the command line makes one (a fresh kit that avoids the ready-made
   * worksheets' numbers): {title, seed, marks, versions: [{letter, marks, items: [{template,
   * variant}]}]}. Throws a Draw.DrawError saying what cannot be made. */
  function plan(data, options) {
    var keys = select(data, options.types).map(function (t) {
      return t.key;
    });
    var kit = { seed: options.seed, versions: options.versions, avoid: readyMade(data) };
    kit.sheets = [{ templates: keys, marks: options.marks }];
    var drawn = Draw.drawKit(data, kit).sheets[0];
    var byKey = {};
    data.templates.forEach(function (t) {
      byKey[t.key] = t;
    });
    var titles = options.types.map(function (type) {
      return data.types.filter(function (t) {
        return t.key === type;
      })[0].title;
    });
    var out = [];
    for (var v = 0; v < options.versions; v++) {
      out.push({
        letter: LETTERS[v],
        marks: options.marks,
        items: drawn.templates.map(function (key, i) {
          return { template: byKey[key], variant: drawn.variants[i][v] };
        }),
      });
    }
    return { title: "Worksheet: " + titles.join("; "), seed: options.seed, marks: options.marks, versions: out };
  }

  /* A variant's sheet and key as HTML ({sheet, key}), joined from their pieces in the data file
   * (sheet_pieces.py): a piece is HTML, or the number of one the file holds once (data.pieces)
   * for every sheet and key that prints it; a graph's ids are written data.idMark, for the
   * variant's own prefix (page.ids). */
  function variantHtml(data, key, variant) {
    var page = data.variants[key][String(variant)];
    function join(pieces) {
      var html = pieces
        .map(function (piece) {
          return typeof piece === "number" ? data.pieces[piece] : piece;
        })
        .join("");
      return page.ids ? html.split(data.idMark).join(page.ids) : html;
    }
    return { sheet: join(page.sheet), key: join(page.key) };
  }

  var api = {
    variantHtml: variantHtml,
    readyMadeRepeats: readyMadeRepeats,
    plan: plan,
    SheetError: Draw.DrawError,
  };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.SheetBuilder = api; // the page's part: sheet-builder-page.js
})(this);
