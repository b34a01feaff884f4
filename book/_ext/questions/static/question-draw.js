/* The draws the sheet builder and the mock test share (pure: it runs under Node for the
 * tests too). They repeat physics_figures.worksheets exactly: the same FNV-1a hash
 * (seededOrder), the same subset sums over each type's templates, shared among the types by
 * their exam counts (chooseTemplates), the same tie-breaking and the same errors, so the sheet
 * builder (sheet-builder.js) gives what `python -m physics_figures.worksheets` gives. The mock
 * test (mock-draw.js) draws with them too, in its own order of a type's templates. */
(function (root) {
  "use strict";

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

  /* The message is Python's ValueError's; `details` says what a page needs to say it in its
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
   * questions (worksheets.choose_templates). `orderType(group, seed)` puts one type's templates
   * in the order the subset sums try them (the first found wins); by default the worksheets'
   * seeded order of their keys. */
  function chooseTemplates(data, templates, marks, seed, orderType) {
    orderType = orderType || sheetOrder;
    var byType = new Map();
    templates.forEach(function (template) {
      if (!byType.has(template.type)) byType.set(template.type, []);
      byType.get(template.type).push(template);
    });
    byType.forEach(function (group, type) {
      byType.set(type, orderType(group, seed));
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
      { available: available },
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
      throw new DrawError(
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

  var api = {
    fnv1a: fnv1a,
    seededOrder: seededOrder,
    subsetSums: subsetSums,
    chooseTemplates: chooseTemplates,
    check: require_,
    isWhole: isWhole,
    DrawError: DrawError,
  };
  if (typeof module !== "undefined" && module.exports) module.exports = api;
  else root.QuestionDraw = api; // the sheet builder's and the mock test's
})(this);
