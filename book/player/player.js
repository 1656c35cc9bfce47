// raytree's players and checked questions for the book's pages. Plain
// JavaScript with no build step. Everything it shows was made by raytree at
// book build: a chapter's player.js files the data under the lesson's number
// (window.raytreePlayers), the questions carry their answers as attributes.
// This file only shows and hides: a part of the diagram is drawn once it
// has been spawned by the stop's step (its data-step), as `raytree lesson N`
// narrates it.
(function () {
  "use strict";

  function el(tag, cls, text) {
    var e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
  }

  function stepOf(node) {
    var s = node.getAttribute("data-step");
    return s === "end" ? Infinity : Number(s);
  }

  function Player(root, data) {
    this.root = root;
    this.data = data;
    this.at = 0;
    root.setAttribute("tabindex", "0");
    root.setAttribute("aria-label", "Step-through player of lesson " + data.lesson);
    var bar = el("div", "rp-bar");
    this.prev = el("button", "rp-prev", "◀ Previous");
    this.next = el("button", "rp-next", "Next ▶");
    this.where = el("span", "rp-where");
    bar.appendChild(this.prev);
    bar.appendChild(this.where);
    bar.appendChild(this.next);
    this.diagram = el("div", "rp-diagram");
    this.diagram.innerHTML = data.svg;
    this.say = el("p", "rp-say");
    this.lines = el("pre", "rp-lines");
    var below = el("div", "rp-below");
    var treeBox = el("div", "rp-tree");
    treeBox.appendChild(el("div", "rp-label", "The rays spawned so far (click one)"));
    this.tree = el("ul");
    treeBox.appendChild(this.tree);
    this.ray = el("pre", "rp-ray");
    below.appendChild(treeBox);
    below.appendChild(this.ray);
    root.appendChild(el("div", "rp-title", "Step through it: " + data.title +
      " (pixel " + data.pixel.join(",") + " of " + data.scene + ")"));
    root.appendChild(bar);
    root.appendChild(this.diagram);
    root.appendChild(this.say);
    root.appendChild(this.lines);
    root.appendChild(below);
    this.parts = Array.prototype.slice.call(this.diagram.querySelectorAll("[data-step]"));
    var self = this;
    this.prev.addEventListener("click", function () { self.go(self.at - 1); });
    this.next.addEventListener("click", function () { self.go(self.at + 1); });
    root.addEventListener("keydown", function (e) {
      var k = e.key;
      if (k === "ArrowRight" || k === "n" || k === "j") self.go(self.at + 1);
      else if (k === "ArrowLeft" || k === "p" || k === "k") self.go(self.at - 1);
      else if (k === "Home") self.go(0);
      else if (k === "End") self.go(self.data.stops.length - 1);
      else return;
      // The book's own arrow keys turn the page: not while stepping here.
      e.preventDefault();
      e.stopPropagation();
    });
    this.diagram.addEventListener("click", function (e) {
      var t = e.target.closest ? e.target.closest("[data-ray]") : null;
      if (!t) return;
      var shadow = t.getAttribute("data-shadow");
      self.pick(Number(t.getAttribute("data-ray")), shadow === null ? undefined : Number(shadow));
    });
    this.go(0);
  }

  Player.prototype.go = function (i) {
    var stops = this.data.stops;
    if (i < 0 || i >= stops.length) return;
    this.at = i;
    var stop = stops[i];
    this.parts.forEach(function (p) {
      // A ray's stand-in (data-until) shows from its spawn until its hit is found.
      var until = p.getAttribute("data-until");
      var shown = stepOf(p) <= stop.step && (until === null || stop.step <= Number(until));
      p.style.display = shown ? "inline" : "none";
    });
    this.where.textContent = "stop " + (i + 1) + " of " + stops.length +
      " · step " + stop.step + " of " + this.data.steps;
    this.prev.disabled = i === 0;
    this.next.disabled = i === stops.length - 1;
    this.say.textContent = stop.say;
    this.lines.textContent = stop.lines.map(function (l, k) {
      return (k === 0 ? stop.step + ". " : "    ") + l;
    }).join("\n");
    this.drawTree(stop);
    this.pick(stop.ray);
  };

  // What the algorithm knows of ray r by step: what it meets only once found.
  function known(r, step) {
    return r.found !== null && r.found <= step;
  }

  // The list holds what the diagram draws: its rays, each with the shadow
  // rays its hit has cast so far.
  Player.prototype.drawTree = function (stop) {
    var rays = this.data.rays, self = this;
    this.tree.textContent = "";
    var lists = {};
    function item(parent, cls, text, ray, shadow) {
      var li = el("li");
      var b = el("button", cls, text);
      b.setAttribute("data-ray", ray);
      if (shadow !== undefined) b.setAttribute("data-shadow", shadow);
      b.addEventListener("click", function () { self.pick(ray, shadow); });
      li.appendChild(b);
      parent.appendChild(li);
      return li;
    }
    rays.forEach(function (r, i) {
      if (r.spawn > stop.step || !r.drawn) return;
      var meets = known(r, stop.step) ? " → " + (r.hit || "nothing") : "";
      var parent = (r.parent === null ? null : lists[r.parent]) || self.tree;
      var li = item(parent, "rp-node", "ray " + (i + 1) + " · " + r.kind +
        " (depth " + r.depth + ")" + meets, i);
      var sub = el("ul");
      li.appendChild(sub);
      lists[i] = sub;
      r.shadows.forEach(function (s, k) {
        if (s.step <= stop.step) item(sub, "rp-node rp-shadow", "shadow ray → " + s.light + " · " + s.outcome, i, k);
      });
    });
  };

  // Shows ray i's numbers (shadow ray k of it, if given), marked in the list
  // and the diagram. Rays are numbered from 1, as raytree's tree graph
  // numbers them.
  Player.prototype.pick = function (i, k) {
    var r = this.data.rays[i], step = this.data.stops[this.at].step;
    if (!r || r.spawn > step) return;
    var s = k === undefined ? null : r.shadows[k];
    if (s && s.step > step) return;
    var mine = function (node) {
      var shadow = node.getAttribute("data-shadow");
      return Number(node.getAttribute("data-ray")) === i &&
        (s ? shadow === String(k) : shadow === null);
    };
    this.parts.forEach(function (p) { p.classList.toggle("rp-current", mine(p)); });
    Array.prototype.forEach.call(this.tree.querySelectorAll(".rp-node"), function (b) {
      b.classList.toggle("rp-current", mine(b));
    });
    if (s) {
      this.ray.textContent = "shadow ray to '" + s.light + "', cast from ray " + (i + 1) +
        "'s hit\n" + s.lines.join("\n");
      return;
    }
    var lines = known(r, step) ? r.lines : r.lines.slice(0, r.spawn_lines);
    this.ray.textContent = "ray " + (i + 1) + ": " + r.kind + ", depth " + r.depth + "\n" +
      lines.join("\n") + (known(r, step) ? "" : "\n(what it meets: not found yet at step " + step + ")");
  };

  // A number as a reader types it: a typographic minus (−), a decimal comma
  // (0,9514) or point, thousands apart by spaces (336 120), a unit after it.
  // Anything else after the number makes it no number ("1,2,3", "1.234,5",
  // "1e"), rather than the number its first digits happen to spell.
  // A lone comma is always a decimal comma: "0,9514" is read as the 9514 of
  // thousands only where nothing else fits, commas grouping by three before
  // a point (1,234.5) or more than one of them (1,234,567).
  function parseAnswer(text) {
    var t = normalise(text);
    if (/^[-+]?\d{1,3}(,\d{3})+\./.test(t) || /^[-+]?\d{1,3}(,\d{3}){2,}(?![\d,])/.test(t)) {
      t = t.replace(/,/g, "");
    } else {
      t = t.replace(",", ".");
    }
    var m = /^([-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?)([^\d.,e+\-][^\d.,]*)?$/i.exec(t);
    return m ? Number(m[1]) : NaN;
  }

  // Every reading of a typed answer. "336,120" is 336.12 with a decimal
  // comma and 336120 with a thousands comma; a question takes the reading
  // nearer its answer, so neither way of writing is told it is wrong.
  function readings(text) {
    var t = normalise(text);
    var all = [parseAnswer(t)];
    if (/^[-+]?[1-9]\d{0,2},\d{3}(?![\d.,])/.test(t)) all.push(parseAnswer(t.replace(",", "")));
    return all;
  }

  // The typed text with a typographic minus made ASCII and the spaces
  // (thousands apart, or around a unit) gone.
  function normalise(text) {
    return text.trim().replace(/\u2212/g, "-").replace(/\s+/g, "");
  }

  function Question(root) {
    var answer = Number(root.getAttribute("data-answer"));
    var within = Number(root.getAttribute("data-within"));
    var unit = root.getAttribute("data-unit") || "";
    var hint = root.querySelector(".raytree-hint");
    var worked = root.querySelector(".raytree-worked");
    var form = el("form", "rq-form");
    var input = el("input", "rq-input");
    input.setAttribute("inputmode", "decimal");
    input.setAttribute("aria-label", "your answer");
    var check = el("button", "rq-check", "Check");
    var verdict = el("span", "rq-verdict");
    verdict.setAttribute("aria-live", "polite");
    form.appendChild(input);
    if (unit) form.appendChild(el("span", "rq-unit", unit));
    form.appendChild(check);
    form.appendChild(verdict);
    var tol = root.querySelector(".raytree-tolerance");
    root.insertBefore(form, tol);
    if (hint) hint.style.display = "none";
    if (worked) worked.style.display = "none";
    form.addEventListener("submit", function (e) {
      e.preventDefault();
      var given = readings(input.value).reduce(function (a, b) {
        return Math.abs(b - answer) < Math.abs(a - answer) ? b : a;
      });
      if (isNaN(given)) {
        verdict.textContent = "Type a number.";
        verdict.className = "rq-verdict";
        return;
      }
      var right = Math.abs(given - answer) <= within;
      verdict.textContent = right ? "Right: raytree says " + answer + unit + "." :
        "Not yet: that is too " + (given > answer ? "high" : "low") +
        ". Read the hint and try again.";
      verdict.className = "rq-verdict " + (right ? "rq-right" : "rq-wrong");
      if (hint) { hint.style.display = right ? "none" : ""; hint.open = !right; }
      if (worked && right) { worked.style.display = ""; worked.open = true; }
    });
    return { input: input, check: check, verdict: verdict, answer: answer, within: within };
  }

  // Typed answers for the probe; browser.rs knows what each should read as.
  var PARSE_CASES = ["0,9514", "\u22120,2328", "1,5", "0.5", "\u22120.2328",
    "336 120", "1,234.5", "1,234,567", "2,5 px", "\u2212 7", "45\u00b0", "1e3",
    "1,2,3", "1.234,5", "1e"];

  // ?selftest: the browser test's probe. It presses the real buttons and keys
  // and writes what the page then shows; the test judges it against the trace.
  function selftest(players, questions) {
    var report = { players: [], questions: [], scrollWidth: 0, width: 0 };
    players.forEach(function (p) {
      var seen = [];
      function look(how) {
        var shown = {}, shadows = {};
        p.parts.forEach(function (part) {
          if (getComputedStyle(part).display === "none") return;
          var cls = part.getAttribute("class").split(" ");
          if (cls.indexOf("ray") >= 0) shown[part.getAttribute("data-ray")] = 1;
          if (cls.indexOf("shadow") >= 0) {
            shadows[part.getAttribute("data-ray") + "/" + part.getAttribute("data-shadow")] = 1;
          }
        });
        seen.push({ how: how, stop: p.at, step: p.data.stops[p.at].step,
          rays: Object.keys(shown).map(Number).sort(function (a, b) { return a - b; }),
          tree: p.tree.querySelectorAll(".rp-node:not(.rp-shadow)").length,
          shadows: p.tree.querySelectorAll(".rp-shadow").length,
          shadowsShown: Object.keys(shadows).length });
      }
      look("start");
      while (!p.next.disabled) { p.next.click(); look("next"); }
      while (p.at > 0) {
        p.root.dispatchEvent(new KeyboardEvent("keydown", { key: "ArrowLeft", bubbles: true }));
        look("key");
      }
      // Click the last ray the tree lists at the last stop, and the diagram's
      // primary ray: each shows its own numbers.
      p.go(p.data.stops.length - 1);
      var nodes = p.tree.querySelectorAll(".rp-node:not(.rp-shadow)");
      var last = nodes[nodes.length - 1];
      var clicked = [];
      if (last) {
        last.click();
        clicked.push({ ray: Number(last.getAttribute("data-ray")), shows: p.ray.textContent.split("\n")[0] });
      }
      // A listed shadow ray shows its own line, and the diagram marks it.
      var shadows = p.tree.querySelectorAll(".rp-shadow");
      var shadow = null;
      if (shadows.length) {
        var sb = shadows[shadows.length - 1];
        sb.click();
        var marked = p.diagram.querySelectorAll(".rp-current");
        shadow = { ray: Number(sb.getAttribute("data-ray")), shadow: Number(sb.getAttribute("data-shadow")),
          shows: p.ray.textContent.split("\n")[0], marked: marked.length,
          markedShadow: Array.prototype.every.call(marked, function (m) {
            return m.getAttribute("data-shadow") === sb.getAttribute("data-shadow");
          }) };
      }
      var line = p.diagram.querySelector('.ray[data-ray="0"]');
      if (line) {
        line.dispatchEvent(new MouseEvent("click", { bubbles: true }));
        clicked.push({ ray: 0, shows: p.ray.textContent.split("\n")[0] });
      }
      p.go(0);
      report.players.push({ lesson: p.data.lesson, stops: p.data.stops.length, seen: seen, clicked: clicked,
        shadow: shadow });
    });
    questions.forEach(function (q) {
      var out = {};
      q.input.value = String(q.answer + 10 * q.within + 1);
      q.check.click();
      out.wrong = q.verdict.className;
      q.input.value = String(q.answer);
      q.check.click();
      out.right = q.verdict.className;
      // As a reader types it: a typographic minus, thousands apart by
      // spaces, a decimal comma.
      var abs = Math.abs(q.answer).toString();
      if (Number.isInteger(q.answer)) abs = abs.replace(/\B(?=(\d{3})+$)/g, " ");
      else abs = abs.replace(".", ",");
      q.input.value = (q.answer < 0 ? "\u2212" : "") + abs;
      q.check.click();
      out.typed = q.input.value;
      out.typedVerdict = q.verdict.className;
      if (Number.isInteger(q.answer) && Math.abs(q.answer) >= 1000) {
        // The English way: thousands apart by commas.
        q.input.value = q.answer.toString().replace(/\B(?=(\d{3})+$)/g, ",");
        q.check.click();
        out.commas = q.input.value;
        out.commasVerdict = q.verdict.className;
      }
      report.questions.push(out);
    });
    // The reading of answers typed the ways readers type them; the test
    // holds each to the number meant.
    report.parsed = PARSE_CASES.map(function (c) { return [c, parseAnswer(c)]; });
    report.scrollWidth = document.documentElement.scrollWidth;
    report.width = document.documentElement.clientWidth;
    var pre = el("pre", "", JSON.stringify(report));
    pre.id = "raytree-selftest";
    document.body.appendChild(pre);
  }

  // The book's root, from where this file was loaded (ROOT/player/…): a
  // chapter's data is fetched relative to it, so a player works in its
  // chapter and in mdBook's print page alike.
  var here = document.currentScript ? document.currentScript.src : "";
  var root = here.replace(/player\/[^\/]*$/, "");

  // Loads each player's data (a chapter's player.js), then starts them all.
  function start() {
    var roots = Array.prototype.slice.call(document.querySelectorAll(".raytree-player"));
    var pending = roots.length;
    if (pending === 0) ready(roots);
    roots.forEach(function (div) {
      var script = document.createElement("script");
      script.src = root + div.getAttribute("data-src");
      script.onload = script.onerror = function () {
        pending -= 1;
        if (pending === 0) ready(roots);
      };
      document.head.appendChild(script);
    });
  }

  function ready(roots) {
    var data = window.raytreePlayers || {};
    var players = [];
    roots.forEach(function (div) {
      var d = data[div.getAttribute("data-lesson")];
      if (d) players.push(new Player(div, d));
      else console.error("raytree: no player data at " + div.getAttribute("data-src"));
    });
    var questions = Array.prototype.map.call(document.querySelectorAll(".raytree-question"), Question);
    if (/[?&]selftest\b/.test(location.search)) selftest(players, questions);
    // ?stop=N: the first player at stop N, moved to the top of the page, for
    // the screenshots in docs/ (a headless browser shoots the page's top).
    var m = /[?&]stop=(\d+)/.exec(location.search);
    if (m && players[0]) {
      players[0].go(Number(m[1]) - 1);
      var main = document.querySelector("main") || document.body;
      main.insertBefore(players[0].root, main.firstChild);
    }
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
