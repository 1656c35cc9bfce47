// raytree's step-through players for the book's pages (the checked
// questions are questions.js). Plain JavaScript with no build step.
// Everything it shows was made by raytree at book build: a chapter's
// player.js files the data under the lesson's number (window.raytreePlayers).
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
    // ?stop=N: the first player at stop N, moved to the top of the page, for
    // the screenshots in docs/ (a headless browser shoots the page's top).
    var m = /[?&]stop=(\d+)/.exec(location.search);
    if (m && players[0]) {
      players[0].go(Number(m[1]) - 1);
      var main = document.querySelector("main") || document.body;
      main.insertBefore(players[0].root, main.firstChild);
    }
    // The players started, for the browser test's probe, which the test
    // alone adds to the page (tests/suite/docs/probe.js).
    (window.raytreeBook = window.raytreeBook || {}).players = players;
    document.dispatchEvent(new Event("raytree-players"));
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
