/* The worksheet draw, the one implementation: which templates a sheet asks and which variant of
 * each every version (A, B, C...) prints, drawn from a seed. The teachers' sheet builder
 * (sheet-builder.js) and the mock test (mock-draw.js) run it in the browser; the command line
 * and `make worksheets` run it under Node (physics_figures/worksheets/draw.py), so the same
 * choices and seed give the same sheets everywhere. It is pure: it reads the index it is given
 * (the topic's types with their exam counts, the templates with their marks and reserve
 * variants) and computes no physics. Its errors name the field, the value and the rule. */
(function (root) {
  "use strict";

  /* The 32-bit FNV-1a hash of a text's UTF-8 bytes: a draw any machine repeats exactly. */
  function fnv1a(text) {
    var bytes = new TextEncoder().encode(text);
    var value = 0x811c9dc5;
    for (var i = 0; i < bytes.length; i++) {
      value = Math.imul(value ^ bytes[i], 0x01000193) >>> 0;
    }
    return value;
  }

  /* The items in the order a seed draws: by the hash of "label:seed:name(item)", ties in the
   * given order (Array.prototype.sort is stable). */
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

  /* A value as an error quotes it: a number as written, a text in quotes, a list of texts. */
  function pyRepr(value) {
    if (Array.isArray(value)) return "[" + value.map(pyRepr).join(", ") + "]";
    if (typeof value === "string") return "'" + value + "'";
    return String(value);
  }

  /* The message is the ValueError the command line raises; `details` says what a page needs to say it in its
   * own words: the field (types, marks, versions, seed) and, for marks, the marks available or
   * the nearest totals that can be made. */
  function DrawError(message, details) {
    this.name = "DrawError";
    this.message = message;
    Object.assign(this, details || {});
  }
  DrawError.prototype = Object.create(Error.prototype);

  function require_(ok, name, value, rule, details) {
    if (!ok) {
      throw new DrawError(
        name + " " + rule + " (got " + name + "=" + pyRepr(value) + ")",
        Object.assign({ field: name }, details),
      );
    }
  }

  function isWhole(value) {
    return typeof value === "number" && Number.isInteger(value);
  }

  /* For each total up to `most`, one set of templates that makes it: the first found in the
   * given order, which the seed has shuffled. */
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

  /* The templates by type (in the order they come), each type's in the order `orderType`
   * puts them. */
  function templatesByType(templates, seed, orderType) {
    var byType = new Map();
    templates.forEach(function (template) {
      if (!byType.has(template.type)) byType.set(template.type, []);
      byType.get(template.type).push(template);
    });
    byType.forEach(function (group, type) {
      byType.set(type, orderType(group, seed));
    });
    return byType;
  }

  /* The marks the templates hold between them; asking for more is an error. */
  function marksInBank(templates, byType, marks) {
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
      { available: available },
    );
    return available;
  }

  /* Each type's share of the marks, as the exam shares its questions (its exam count). */
  function typeShares(data, byType, marks) {
    var counts = new Map();
    byType.forEach(function (group, type) {
      counts.set(type, examCount(data, type));
    });
    var weight = 0;
    counts.forEach(function (count) {
      weight += count;
    });
    weight = weight || 1;
    var shares = new Map();
    counts.forEach(function (count, type) {
      shares.set(type, (marks * count) / weight);
    });
    return shares;
  }

  /* Over the types: for each total up to `marks`, the picks ([type, its marks]) that stray
   * least from each type's share. `options` holds each type's subset sums. */
  function leastStrayingTotals(options, shares, marks) {
    var best = new Map([[0, { cost: 0, picks: [] }]]);
    options.forEach(function (sums, type) {
      var target = shares.get(type);
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
    return best;
  }

  /* The error when `marks` cannot be made exactly: the nearest totals below (shared among the
   * types) and above (from any of the templates) that can. */
  function nearestTotalsError(best, templates, marks, available) {
    var below = 0;
    best.forEach(function (entry, total) {
      if (total < marks && total > below) below = total;
    });
    var above = available;
    subsetSums(templates, available).forEach(function (chosen, total) {
      if (total > marks && total < above) above = total;
    });
    return new DrawError(
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
      { field: "marks", nearest: [below, above] },
    );
  }

  /* Templates making exactly `marks`, shared among their types as the exam shares its
   * questions (each type's exam count). `orderType(group, seed)` puts one type's templates
   * in the order the subset sums try them (the first found wins); by default the worksheets'
   * seeded order of their keys. */
  function chooseTemplates(data, templates, marks, seed, orderType) {
    var byType = templatesByType(templates, seed, orderType || sheetOrder);
    var available = marksInBank(templates, byType, marks);
    var options = new Map();
    byType.forEach(function (group, type) {
      options.set(type, subsetSums(group, marks));
    });
    var best = leastStrayingTotals(options, typeShares(data, byType, marks), marks);
    if (!best.has(marks)) throw nearestTotalsError(best, templates, marks, available);
    var chosen = [];
    best.get(marks).picks.forEach(function (pick) {
      chosen = chosen.concat(options.get(pick[0]).get(pick[1]));
    });
    var order = bankOrder(data);
    return chosen.sort(function (a, b) {
      return order.get(a.key) - order.get(b.key);
    });
  }

  function sheetOrder(group, seed) {
    return seededOrder(group, "worksheet-templates", seed, function (template) {
      return template.key;
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

  var MAX_VERSIONS = 26; // A to Z

  /* How many versions a template can still give after `used` of its variants went to other
   * sheets of the kit: every version its own variant; a one-wording statement (a definition)
   * has one variant, the same in every version, once in a kit. */
  function usableVersions(template, used) {
    if (template.oneWording) return used ? 0 : MAX_VERSIONS;
    return template.reserve.length - (used || 0);
  }

  /* A template's reserve variants in the order a seed draws them; variant 0 (the book's
   * printed numbers), when the reserve holds it, last; before it, the variants in `avoid` (a
   * ready-made worksheet's: {variant: where}) after all the others. */
  function variantOrder(template, seed, avoid) {
    avoid = avoid || {};
    var drawn = seededOrder(
      template.reserve.filter(function (i) {
        return i;
      }),
      "worksheet-variants:" + template.key,
      seed,
    );
    function avoided(i) {
      return String(i) in avoid;
    }
    return drawn
      .filter(function (i) {
        return !avoided(i);
      })
      .concat(
        drawn.filter(avoided),
        template.reserve.filter(function (i) {
          return !i;
        }),
      );
  }

  /* One sheet of a kit: checks the choices, picks the templates (all, or a set making
   * `sheet.marks`) and takes each one's next unused variants. `sheet.fitting` leaves out the
   * templates the kit cannot give every version of (none left: null); `sheet.marksAtMost` asks
   * for that many marks, or all the fitting templates hold when fewer. */
  function drawSheet(data, kit, used, sheet) {
    var byKey = templatesByKey(data);
    var templates = sheet.templates.map(function (key) {
      return byKey.get(key);
    });
    var versions = kit.versions;
    var marks = sheet.marks;
    if (sheet.fitting) {
      templates = templates.filter(function (t) {
        return usableVersions(t, used[t.key]) >= versions;
      });
      if (!templates.length) return null;
      var held = templates.reduce(function (sum, t) {
        return sum + t.marks;
      }, 0);
      if (sheet.marksAtMost !== undefined) marks = Math.min(sheet.marksAtMost, held);
    }
    checkSheet(templates, used, versions, kit.seed, sheet.templates);
    if (marks !== undefined) {
      require_(isWhole(marks) && marks >= 1, "marks", marks, "must be a whole number, 1 or more");
      templates = chooseTemplates(data, templates, marks, kit.seed);
    }
    return {
      templates: templates.map(function (t) {
        return t.key;
      }),
      variants: templates.map(function (t) {
        return take(t, kit, used);
      }),
    };
  }

  function checkSheet(templates, used, versions, seed, keys) {
    require_(
      isWhole(versions) && versions >= 1 && versions <= MAX_VERSIONS,
      "versions",
      versions,
      "must be a whole number from 1 to " + MAX_VERSIONS + " (A to Z)",
    );
    require_(isWhole(seed) && seed >= 0, "seed", seed, "must be a whole number, 0 or more");
    require_(templates.length > 0, "templates", keys, "must hold at least one template");
    var short = templates.filter(function (t) {
      return usableVersions(t, used[t.key]) < versions;
    });
    require_(
      !short.length,
      "versions",
      versions,
      "needs that many different variants of every template, but " +
        short
          .map(function (t) {
            return t.key + " has " + usableVersions(t, used[t.key]) + " the site does not show";
          })
          .join(", ") +
        ": ask for fewer versions or leave those templates out",
    );
  }

  /* A template's variants for the versions of a sheet: its next unused ones in the seed's
   * order (a one-wording statement: the same, variant 0, in every version). */
  function take(template, kit, used) {
    if (template.oneWording) {
      used[template.key] = 1;
      return Array(kit.versions).fill(0);
    }
    var start = used[template.key] || 0;
    used[template.key] = start + kit.versions;
    var avoid = (kit.avoid || {})[template.key];
    return variantOrder(template, kit.seed, avoid).slice(start, start + kit.versions);
  }

  function templatesByKey(data) {
    var byKey = new Map();
    data.templates.forEach(function (template) {
      byKey.set(template.key, template);
    });
    return byKey;
  }

  /* A kit's sheets, in order, none asking a question (template and variant) another asked:
   * kit = {seed, versions, avoid: {key: {variant: where}}, used: {key: count}, sheets: [{templates:
   * [key], marks, fitting, marksAtMost}]}. Gives each sheet's templates and, per template, its
   * variant in each version (or null: no template fitted), and the versions each template of
   * the index can still give. Throws a DrawError at the first sheet that cannot be made. */
  function drawKit(data, kit) {
    var used = Object.assign({}, kit.used);
    var sheets = kit.sheets.map(function (sheet) {
      return drawSheet(data, kit, used, sheet);
    });
    var left = {};
    data.templates.forEach(function (template) {
      left[template.key] = usableVersions(template, used[template.key]);
    });
    return { sheets: sheets, left: left };
  }

  var api = {
    fnv1a: fnv1a,
    seededOrder: seededOrder,
    subsetSums: subsetSums,
    chooseTemplates: chooseTemplates,
    usableVersions: usableVersions,
    variantOrder: variantOrder,
    drawKit: drawKit,
    MAX_VERSIONS: MAX_VERSIONS,
    check: require_,
    isWhole: isWhole,
    DrawError: DrawError,
  };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.QuestionDraw = api; // the sheet builder's and the mock test's
})(this);
