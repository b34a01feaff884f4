/* The teachers' sheet builder (book/teachers.md, "Make your own"): worksheets in several
 * versions, each with its own answer key, made in this browser with no Python and no server.
 *
 * The questions come from the teachers-only data file the build writes (sheet_builder.py:
 * teachers/sheet-data.js, loaded by a <script> element on the first "Make the sheets", so it
 * works from file:// too): every bank template's reserve variants, their sheets and keys as
 * HTML and their graphs as SVG, all computed by physics_figures. This script computes no
 * physics and no key. It repeats physics_figures.worksheets.plan exactly: the same FNV-1a
 * draws (seededOrder), the same subset sums over each type's templates in the same order,
 * with the same tie-breaking (Python's dicts keep insertion order: Maps here; totals tried
 * from the largest; a new cost wins only when lower by more than 1e-9), and the same errors.
 * So the same types, marks, versions and seed give the same questions as
 * `python -m physics_figures.worksheets`. This file is the draws (it runs under Node for the
 * tests too); sheet-builder-page.js is the page: the form and the sheets it prints. */
(function (root) {
  "use strict";

  var MAX_VERSIONS = 26;
  var LETTERS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";

  /* The 32-bit FNV-1a hash of a text's UTF-8 bytes (worksheets.fnv1a). */
  function fnv1a(text) {
    var bytes = new TextEncoder().encode(text);
    var value = 0x811c9dc5;
    for (var i = 0; i < bytes.length; i++) {
      value = Math.imul(value ^ bytes[i], 0x01000193) >>> 0;
    }
    return value;
  }

  /* The items in the order a seed draws: by the hash of "label:seed:name(item)", ties in the
   * given order (Array.prototype.sort is stable, as Python's sorted is). */
  function seededOrder(items, label, seed, name) {
    name = name || String;
    return items
      .map(function (item) {
        return { item: item, hash: fnv1a(label + ":" + seed + ":" + name(item)) };
      })
      .sort(function (a, b) {
        return a.hash - b.hash;
      })
      .map(function (entry) {
        return entry.item;
      });
  }

  /* Python's repr of what a form gives: a number as written, a text in quotes, a list of texts. */
  function pyRepr(value) {
    if (Array.isArray(value)) return "[" + value.map(pyRepr).join(", ") + "]";
    if (typeof value === "string") return "'" + value + "'";
    return String(value);
  }

  function SheetError(message) {
    this.name = "SheetError";
    this.message = message;
  }
  SheetError.prototype = Object.create(Error.prototype);

  function require_(ok, name, value, rule) {
    if (!ok) throw new SheetError(name + " " + rule + " (got " + name + "=" + pyRepr(value) + ")");
  }

  function isWhole(value) {
    return typeof value === "number" && Number.isInteger(value);
  }

  /* For each total up to `most`, one set of templates that makes it: the first found in the
   * given order (worksheets._subset_sums). */
  function subsetSums(templates, most) {
    var sums = new Map([[0, []]]);
    templates.forEach(function (template) {
      var entries = Array.from(sums.entries()).sort(function (a, b) {
        return b[0] - a[0];
      });
      entries.forEach(function (entry) {
        var total = entry[0] + template.marks;
        if (total <= most && !sums.has(total)) sums.set(total, entry[1].concat([template]));
      });
    });
    return sums;
  }

  /* Templates making exactly `marks`, shared among their types as the exam shares its
   * questions (worksheets.choose_templates). */
  function chooseTemplates(data, templates, marks, seed) {
    var byType = new Map();
    templates.forEach(function (template) {
      if (!byType.has(template.type)) byType.set(template.type, []);
      byType.get(template.type).push(template);
    });
    byType.forEach(function (group, type) {
      byType.set(
        type,
        seededOrder(group, "worksheet-templates", seed, function (template) {
          return template.key;
        }),
      );
    });
    var available = templates.reduce(function (sum, t) {
      return sum + t.marks;
    }, 0);
    require_(
      marks <= available,
      "marks",
      marks,
      "is more than the " +
        available +
        " marks the bank holds for " +
        Array.from(byType.keys()).sort().join(", ") +
        " (" +
        templates.length +
        " templates)",
    );
    var counts = new Map();
    byType.forEach(function (group, type) {
      counts.set(type, examCount(data, type));
    });
    var weight = 0;
    counts.forEach(function (count) {
      weight += count;
    });
    weight = weight || 1;
    var options = new Map();
    byType.forEach(function (group, type) {
      options.set(type, subsetSums(group, marks));
    });
    // Over the types: the exact total that strays least from each type's share.
    var best = new Map([[0, { cost: 0, picks: [] }]]);
    options.forEach(function (sums, type) {
      var target = (marks * counts.get(type)) / weight;
      var following = new Map();
      best.forEach(function (entry, total) {
        sums.forEach(function (chosen, amount) {
          if (total + amount > marks) return;
          var next = { cost: entry.cost + Math.abs(amount - target), picks: entry.picks.concat([[type, amount]]) };
          var there = following.get(total + amount);
          if (!there || next.cost < there.cost - 1e-9) following.set(total + amount, next);
        });
      });
      best = following;
    });
    if (!best.has(marks)) {
      var below = 0;
      best.forEach(function (entry, total) {
        if (total < marks && total > below) below = total;
      });
      var above = available;
      subsetSums(templates, available).forEach(function (chosen, total) {
        if (total > marks && total < above) above = total;
      });
      throw new SheetError(
        "marks cannot be made exactly from the questions of these templates (" +
          templates
            .map(function (t) {
              return t.key + ": " + t.marks;
            })
            .join(", ") +
          "); the nearest totals that can are " +
          below +
          " and " +
          above +
          " (got marks=" +
          pyRepr(marks) +
          ")",
      );
    }
    var chosen = [];
    best.get(marks).picks.forEach(function (pick) {
      chosen = chosen.concat(options.get(pick[0]).get(pick[1]));
    });
    var order = bankOrder(data);
    return chosen.sort(function (a, b) {
      return order.get(a.key) - order.get(b.key);
    });
  }

  function examCount(data, type) {
    for (var i = 0; i < data.types.length; i++) if (data.types[i].key === type) return data.types[i].examCount;
    return 0;
  }

  function bankOrder(data) {
    var order = new Map();
    data.templates.forEach(function (template, index) {
      order.set(template.key, index);
    });
    return order;
  }

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
   * holds it, last (worksheets.variant_order). */
  function variantOrder(template, seed) {
    var drawn = seededOrder(
      template.reserve.filter(function (i) {
        return i;
      }),
      "worksheet-variants:" + template.key,
      seed,
    );
    return drawn.concat(
      template.reserve.filter(function (i) {
        return !i;
      }),
    );
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
    fnv1a: fnv1a,
    seededOrder: seededOrder,
    subsetSums: subsetSums,
    chooseTemplates: chooseTemplates,
    variantOrder: variantOrder,
    plan: plan,
    SheetError: SheetError,
  };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.SheetBuilder = api; // the page's part: sheet-builder-page.js
})(this);
