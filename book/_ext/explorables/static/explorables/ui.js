/* Shared pieces for the explorables: controls, read-outs, SVG plots, start-up.
 *
 * The directive writes <div class="explorable" data-explorable="NAME" hidden> with the
 * scenario data as JSON. Each explorable script calls Explorables.register(NAME, build);
 * on DOMContentLoaded every container is built and only then revealed, so a reader
 * without JavaScript never sees half an explorable (the static figure stands in).
 */
(function () {
  "use strict";

  var SVG_NS = "http://www.w3.org/2000/svg";
  var uid = 0;

  function nextId(prefix) {
    uid += 1;
    return "ex-" + prefix + "-" + uid;
  }

  /** Element with attributes and children: el("p", {class: "x"}, ["text", child]). */
  function el(tag, attrs, children) {
    var node = document.createElement(tag);
    setAttrs(node, attrs);
    append(node, children);
    return node;
  }

  function svg(tag, attrs, children) {
    var node = document.createElementNS(SVG_NS, tag);
    setAttrs(node, attrs);
    append(node, children);
    return node;
  }

  function setAttrs(node, attrs) {
    Object.keys(attrs || {}).forEach(function (key) {
      var value = attrs[key];
      if (value === null || value === undefined || value === false) node.removeAttribute(key);
      else node.setAttribute(key, value === true ? "" : value);
    });
    return node;
  }

  function append(node, children) {
    [].concat(children === undefined ? [] : children).forEach(function (child) {
      if (child === null || child === undefined) return;
      node.appendChild(typeof child === "object" ? child : document.createTextNode(String(child)));
    });
    return node;
  }

  /* ---- numbers as the notes print them: book/_ext/notation/static/notation.js ---- */

  var formatNumber = window.Notation.formatNumber,
    MINUS = window.Notation.MINUS;
  var UNIT_SPACE = window.Notation.UNIT_SPACE,
    unitText = window.Notation.unitText;

  /** A read-out: x to opts.sf significant figures (3 unless given) or opts.decimals places;
   *  a dash when there is no value. */
  function fmt(x, opts) {
    opts = opts || {};
    if (x === null || x === undefined || !isFinite(x)) return "\u2014";
    if (Math.abs(x) < 1e-9) x = 0; // rounding noise, e.g. 1e-16 for an exact zero
    return opts.decimals !== undefined
      ? formatNumber(x, null, { decimals: opts.decimals })
      : formatNumber(x, opts.sf || 3);
  }

  /** Fill "{name}" in a text of physics_figures.explorables with numbers to 3 s.f., as Python does. */
  function fill(template, numbers) {
    return template.replace(/\{(\w+)\}/g, function (all, name) {
      return fmt(numbers[name]);
    });
  }

  /** A tick value with as many places as the spacing of `all` the ticks needs: 5, 0.5, 10 000. */
  function tickText(v, all) {
    var step = all.length > 1 ? all[1] - all[0] : 1;
    return formatNumber(v, null, { decimals: Math.max(0, -Math.floor(Math.log10(step) + 1e-9)) });
  }

  function Quantity(opts) {
    var id = nextId("q");
    var self = this;
    this.value = opts.value;
    this.onChange = opts.onChange;
    this.unit = opts.unit;
    this.unitSpoken = opts.unitSpoken || opts.unit;
    this.range = el("input", {
      type: "range",
      id: id + "-range",
      min: opts.min,
      max: opts.max,
      step: opts.step,
      "aria-labelledby": id + "-label",
    });
    this.number = el("input", {
      type: "number",
      id: id,
      min: opts.numberMin !== undefined ? opts.numberMin : opts.min,
      max: opts.numberMax !== undefined ? opts.numberMax : opts.max,
      step: "any",
      inputmode: "decimal",
    });
    var unitLabel = opts.unit ? el("span", { class: "ex-unit", "aria-hidden": "true" }, unitText(opts.unit)) : null;
    // a typed value out of range is not dropped in silence: this says what the box takes
    // data-announce: the announcer says it too, when it appears
    this.message = el("p", { class: "ex-range-message", id: id + "-message", "data-announce": "" });
    this.message.hidden = true;
    this.number.setAttribute("aria-describedby", id + "-message");
    this.element = el("div", { class: "ex-quantity" }, [
      el("label", { for: id, id: id + "-label" }, [
        opts.label,
        opts.unit ? el("span", { class: "ex-sr" }, " in " + this.unitSpoken) : null,
      ]),
      el("div", { class: "ex-quantity-inputs" }, [
        this.range,
        el("span", { class: "ex-number" }, [this.number, unitLabel]),
      ]),
      this.message,
    ]);
    this.range.addEventListener("input", function () {
      self.set(Number(self.range.value), self.range);
    });
    this.number.addEventListener("input", function () {
      if (self.number.value === "" || !self.number.validity.valid) {
        self.warn(self.number.value === "" && !self.number.validity.badInput ? null : self.number.value);
        return;
      }
      self.warn(null);
      self.set(Number(self.number.value), self.number);
    });
    this.number.addEventListener("change", function () {
      // leaving the box with something out of range or empty: the box goes back to the
      // value in use, and the message (if any) stays to say why
      if (self.number.value === "" || !self.number.validity.valid) self.show();
    });
    this.show();
  }

  /** Say (or stop saying) that `typed` is outside what this quantity takes. */
  Quantity.prototype.warn = function (typed) {
    var lo = Number(this.number.min),
      hi = Number(this.number.max);
    var unit = this.unit ? (this.unit === "%" || this.unit === "\u00b0" ? "" : UNIT_SPACE) + unitText(this.unit) : "";
    if (typed === null) {
      this.message.hidden = true;
      this.message.textContent = "";
      this.number.removeAttribute("aria-invalid");
      return;
    }
    var shown = fmt(this.value);
    this.message.textContent =
      (isFinite(Number(typed)) && typed !== "" ? typed + " is out of range: " : "That is not a number: ") +
      "type a value from " +
      fmt(lo) +
      " to " +
      fmt(hi) +
      unit +
      " (still using " +
      shown +
      unit +
      ").";
    this.message.hidden = false;
    this.number.setAttribute("aria-invalid", "true");
  };

  Quantity.prototype.set = function (value, from) {
    var lo = Number(this.number.min),
      hi = Number(this.number.max);
    this.value = Math.min(hi, Math.max(lo, value));
    if (from !== this.number) this.warn(null);
    this.show(from);
    if (this.onChange) this.onChange(this.value);
  };

  Quantity.prototype.show = function (from) {
    if (from !== this.range) this.range.value = this.value;
    if (from !== this.number) this.number.value = Number(this.value.toPrecision(6));
    // "70 kilograms": also what the announcer (announce.js) says the slider is at
    this.range.setAttribute("aria-valuetext", fmt(this.value) + " " + (this.unitSpoken || this.unit || ""));
  };

  Quantity.prototype.setRange = function (min, max) {
    this.range.min = min;
    this.number.min = min;
    if (max !== undefined) {
      this.range.max = max;
      this.number.max = max;
    }
  };

  /** A read-out: label and <output> showing "value unit [direction]"; data-value holds the number. */
  function Readout(label, unit, opts) {
    var id = nextId("out");
    this.opts = opts || {};
    this.unit = unit;
    this.output = el("output", { id: id, "aria-live": "off", "aria-labelledby": id + "-label " + id });
    this.output.setAttribute("data-label", label); // what the announcer calls it (announce.js)
    this.element = el("div", { class: "ex-readout" }, [
      el("span", { id: id + "-label", class: "ex-readout-label" }, label),
      this.output,
    ]);
  }

  Readout.prototype.set = function (value, direction) {
    this.output.setAttribute("data-value", value === null ? "" : String(value));
    // the number, its unit and the unit's symbols are joined by no-break spaces (notation.js)
    var text = fmt(value, this.opts).replace(/ /g, UNIT_SPACE);
    if (value !== null && this.unit)
      text += (this.unit === "%" || this.unit === "\u00b0" ? "" : UNIT_SPACE) + unitText(this.unit);
    this.output.textContent = text + (direction ? " " + direction : "");
  };

  /** A paragraph that says in words what the graphs show now. Not live: the announcer
   *  (announce.js) says what changed, and a screen reader reads this paragraph in its place. */
  function Description(className) {
    this.element = el("p", { class: "ex-description " + (className || "") });
  }

  Description.prototype.set = function (text) {
    this.element.textContent = window.Notation.joinUnits(text); // numbers never part from their units
  };

  /** Give each read-out of a {key: Readout} map the key as its output's name. */
  function nameReadouts(readouts) {
    Object.keys(readouts).forEach(function (key) {
      readouts[key].output.setAttribute("name", key);
    });
    return readouts;
  }

  /* ---- plots ---- */

  /** About `count` tick values at 1, 2 or 5 x 10^n spacing covering [lo, hi]. */
  function ticks(lo, hi, count) {
    var span = hi - lo;
    if (!(span > 0)) return [lo];
    var raw = span / (count || 5);
    var power = Math.pow(10, Math.floor(Math.log10(raw)));
    var step = [1, 2, 5, 10]
      .map(function (f) {
        return f * power;
      })
      .filter(function (s) {
        return s >= raw;
      })[0];
    var out = [];
    for (var v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
      out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return out;
  }

  /**
   * A pair of axes in an SVG that scales to its container.
   * opts: {width, height, margin: [top, right, bottom, left], xLabel, yLabel, label}
   */
  function Plot(opts) {
    this.w = opts.width || 600;
    this.h = opts.height || 260;
    var m = opts.margin || [12, 14, 44, 64];
    this.box = { top: m[0], right: this.w - m[1], bottom: this.h - m[2], left: m[3] };
    this.clipId = nextId("clip");
    this.svg = svg("svg", {
      viewBox: "0 0 " + this.w + " " + this.h,
      class: "ex-plot",
      role: "img",
      "aria-label": opts.label,
    });
    var b = this.box;
    this.svg.appendChild(
      svg("defs", {}, [
        svg("clipPath", { id: this.clipId }, [
          svg("rect", { x: b.left, y: b.top - 1, width: b.right - b.left, height: b.bottom - b.top + 2 }),
        ]),
        arrowMarker(this.clipId + "-arrow"),
      ]),
    );
    this.arrowId = this.clipId + "-arrow";
    this.grid = this.svg.appendChild(svg("g", { class: "ex-grid" }));
    this.data = this.svg.appendChild(svg("g", { "clip-path": "url(#" + this.clipId + ")" }));
    this.marks = this.svg.appendChild(svg("g"));
    this.svg.appendChild(
      svg(
        "text",
        { class: "ex-axis-label", x: (b.left + b.right) / 2, y: this.h - 6, "text-anchor": "middle" },
        opts.xLabel,
      ),
    );
    this.svg.appendChild(
      svg(
        "text",
        {
          class: "ex-axis-label",
          x: 0,
          y: 0,
          "text-anchor": "middle",
          transform: "translate(14 " + (b.top + b.bottom) / 2 + ") rotate(-90)",
        },
        opts.yLabel,
      ),
    );
  }

  Plot.prototype.setDomain = function (x0, x1, y0, y1, opts) {
    opts = opts || {};
    this.dom = [x0, x1, y0, y1];
    var b = this.box,
      g = this.grid;
    while (g.firstChild) g.removeChild(g.firstChild);
    var self = this;
    ticks(x0, x1, opts.xTicks || 6).forEach(function (t, i, all) {
      var x = self.x(t);
      g.appendChild(svg("line", { x1: x, x2: x, y1: b.top, y2: b.bottom }));
      g.appendChild(
        svg("text", { class: "ex-tick", x: x, y: b.bottom + 16, "text-anchor": "middle" }, tickText(t, all)),
      );
    });
    ticks(y0, y1, opts.yTicks || 5).forEach(function (v, i, all) {
      var y = self.y(v);
      g.appendChild(svg("line", { x1: b.left, x2: b.right, y1: y, y2: y, class: v === 0 ? "ex-zero" : null }));
      g.appendChild(svg("text", { class: "ex-tick", x: b.left - 6, y: y + 4, "text-anchor": "end" }, tickText(v, all)));
    });
    g.appendChild(
      svg("rect", { class: "ex-frame", x: b.left, y: b.top, width: b.right - b.left, height: b.bottom - b.top }),
    );
  };

  Plot.prototype.x = function (t) {
    var d = this.dom,
      b = this.box;
    return b.left + ((t - d[0]) / (d[1] - d[0])) * (b.right - b.left);
  };

  Plot.prototype.y = function (v) {
    var d = this.dom,
      b = this.box;
    return b.bottom - ((v - d[2]) / (d[3] - d[2])) * (b.bottom - b.top);
  };

  /** Keep an annotation (an SVG text already in the plot) inside the frame, clear of it by
   *  `pad` units: never on a tick label (they sit outside the frame) nor on the frame. */
  Plot.prototype.keepInside = function (text, pad) {
    pad = pad === undefined ? 4 : pad;
    var b = this.box,
      box;
    try {
      box = text.getBBox();
    } catch {
      return text; // not rendered (hidden): left as it is
    }
    if (!box.width && !box.height) return text;
    var dx = 0,
      dy = 0;
    if (box.x < b.left + pad) dx = b.left + pad - box.x;
    else if (box.x + box.width > b.right - pad) dx = b.right - pad - (box.x + box.width);
    if (box.y < b.top + pad) dy = b.top + pad - box.y;
    else if (box.y + box.height > b.bottom - pad) dy = b.bottom - pad - (box.y + box.height);
    if (dx) text.setAttribute("x", Number(text.getAttribute("x")) + dx);
    if (dy) text.setAttribute("y", Number(text.getAttribute("y")) + dy);
    return text;
  };

  /** SVG path through (xs[i], ys[i]). */
  Plot.prototype.path = function (xs, ys) {
    var self = this;
    return xs
      .map(function (t, i) {
        return (i ? "L" : "M") + self.x(t).toFixed(2) + " " + self.y(ys[i]).toFixed(2);
      })
      .join("");
  };

  /** Call onScrub(x in data units) while a pointer moves over (or drags on) the plot. */
  Plot.prototype.scrub = function (onScrub) {
    var self = this;
    function handle(event) {
      if (event.pointerType !== "mouse" && event.type === "pointermove" && !event.buttons) return;
      var rect = self.svg.getBoundingClientRect();
      var px = ((event.clientX - rect.left) / rect.width) * self.w;
      var d = self.dom,
        b = self.box;
      var t = d[0] + ((px - b.left) / (b.right - b.left)) * (d[1] - d[0]);
      onScrub(Math.min(d[1], Math.max(d[0], t)));
    }
    this.svg.addEventListener("pointerdown", handle);
    this.svg.addEventListener("pointermove", handle);
  };

  function arrowMarker(id) {
    return svg(
      "marker",
      {
        id: id,
        viewBox: "0 0 10 10",
        refX: 8,
        refY: 5,
        markerWidth: 7,
        markerHeight: 7,
        orient: "auto-start-reverse",
        markerUnits: "userSpaceOnUse",
      },
      [svg("path", { d: "M0 0L10 5L0 10z", class: "ex-arrowhead" })],
    );
  }

  /** An arrow from (x1, y1) to (x2, y2) as an SVG path with a filled head. */
  function arrow(x1, y1, x2, y2, className, head) {
    var dx = x2 - x1,
      dy = y2 - y1,
      len = Math.hypot(dx, dy);
    var g = svg("g", { class: "ex-arrow " + (className || "") });
    if (len < 0.5) return g;
    var size = Math.min(head || 12, len);
    var ux = dx / len,
      uy = dy / len;
    var bx = x2 - ux * size,
      by = y2 - uy * size;
    g.appendChild(svg("line", { x1: x1, y1: y1, x2: bx, y2: by }));
    g.appendChild(
      svg("path", {
        class: "ex-arrowhead",
        d:
          "M" +
          x2 +
          " " +
          y2 +
          "L" +
          (bx - uy * size * 0.45) +
          " " +
          (by + ux * size * 0.45) +
          "L" +
          (bx + uy * size * 0.45) +
          " " +
          (by - ux * size * 0.45) +
          "z",
      }),
    );
    return g;
  }

  /** Drawing width in SVG units: the container's width in CSS pixels, so text keeps its size. */
  function widthFor(node) {
    var w = node.getBoundingClientRect().width || 600;
    return Math.round(Math.max(320, Math.min(640, w - 26)));
  }

  function clear(node) {
    while (node.firstChild) node.removeChild(node.firstChild);
    return node;
  }

  /* ---- start-up ---- */

  /** Build every container of this explorable once the page has been parsed. */
  function register(name, build) {
    function buildAll() {
      var containers = document.querySelectorAll('.explorable[data-explorable="' + name + '"]');
      Array.prototype.forEach.call(containers, function (container) {
        var source = container.querySelector("script.explorable-data");
        if (!source || container.getAttribute("data-built")) return;
        container.hidden = false; // shown while building, so that it has a width
        try {
          build(container, JSON.parse(source.textContent));
          window.Explorables.speakFor(container); // announce.js: its description and live region
        } catch (error) {
          container.hidden = true; // never show half an explorable; the static figure stays
          throw error;
        }
        container.setAttribute("data-built", "true");
      });
    }
    if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", buildAll);
    else buildAll();
  }

  window.Explorables = {
    el: el,
    svg: svg,
    fmt: fmt,
    fill: fill,
    joinUnits: window.Notation.joinUnits,
    MINUS: MINUS,
    Quantity: Quantity,
    Readout: Readout,
    nameReadouts: nameReadouts,
    Description: Description,
    Plot: Plot,
    ticks: ticks,
    arrow: arrow,
    clear: clear,
    widthFor: widthFor,
    nextId: nextId,
    register: register,
    models: window.ExplorableModels,
  };
})();
