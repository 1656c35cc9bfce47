// The browser test's probe (tests/suite/docs/browser.rs): never part of the
// book. The test adds it to each built page it opens, after the book's own
// player.js and questions.js; it drives the players and answer boxes those
// started (window.raytreeBook) through their real controls, and writes what
// the page then shows, as JSON in a pre element (id raytree-selftest) at the
// page's end, for the test to judge against the trace.
(function () {
  "use strict";

  function el(tag, cls, text) {
    var e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // Typed answers; browser.rs knows what each should read as.
  var PARSE_CASES = ["0,9514", "\u22120,2328", "1,5", "0.5", "\u22120.2328",
    "336 120", "1,234.5", "1,234,567", "2,5 px", "\u2212 7", "45\u00b0", "1e3",
    "1,2,3", "1.234,5", "1e"];

  // Presses the real buttons and keys and writes what the page then shows.
  function selftest(players, questions, parseAnswer) {
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

  // After questions.js has made the answer boxes (its DOMContentLoaded
  // handler comes before this one) and player.js has started the players
  // (they wait for their chapters' data).
  function run() {
    var book = window.raytreeBook || {};
    selftest(book.players || [], book.questions || [], book.parseAnswer);
  }
  document.addEventListener("DOMContentLoaded", function () {
    if (window.raytreeBook && window.raytreeBook.players) run();
    else document.addEventListener("raytree-players", run);
  });
})();
