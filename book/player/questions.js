// raytree's checked questions for the book's pages: a box that takes a
// reader's predicted number and says whether it is raytree's (the players
// are player.js). Plain JavaScript with no build step. Each question carries
// its answer and tolerance as attributes, written by raytree at book build.
(function () {
  "use strict";

  function el(tag, cls, text) {
    var e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
  }

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

  // Turns every question on the page into an answer box. What they hold,
  // and how a typed answer is read, are kept for the browser test's probe,
  // which the test alone adds to the page (tests/suite/docs/probe.js).
  function start() {
    var book = window.raytreeBook = window.raytreeBook || {};
    book.questions = Array.prototype.map.call(document.querySelectorAll(".raytree-question"), Question);
    book.parseAnswer = parseAnswer;
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
