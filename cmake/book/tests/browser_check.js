// The browser test's checks (cmake/book/tests/browser_test.sh puts this into a harness page).
// Loads every page of the book in an iframe, as a reader's browser would, and checks:
//   * every image loaded (complete, with a natural size);
//   * the math is MathML that the browser lays out (MathMLElement, display "math", a size),
//     and no TeX was left behind as text ($...$, \frac, a .math span without <math>);
//   * every link leads somewhere: pages of the book with the named anchor, files that load;
//   * the page has a title, and chapters have their previous/next navigation;
//   * nothing is wider than the content column (<main>'s content box) at a 1200 px wide
//     window, and nothing hides part of itself: a code block, a table or an equation that does
//     not fit must wrap, break or shrink, not scroll or be cut off. Each offender is named, with
//     its page, its tag and its first words;
//   * at the common screen widths, 1024, 1280, 1366 and 1920 px, nothing of the page (the
//     "On this page" sidebar included) extends past the window's left or right edge.
// It also reports each page's height (HEIGHT <name> <px>), for the full-page screenshots. Then
// it checks itself on a page that is broken on purpose: the checks must see the damage. The
// result goes into <pre id="book-test-result">, one line per finding, ending with DONE.
/* global BOOK_PAGES, SELFTEST_PAGE */
"use strict";

const lines = [];
const say = (s) => lines.push(s);

function load(url, width = 1200) {
  return new Promise((resolve) => {
    const frame = document.createElement("iframe");
    frame.style.width = width + "px";
    frame.style.height = "900px";
    const timer = setTimeout(() => resolve(null), 15000);
    frame.onload = () => {
      clearTimeout(timer);
      resolve(frame);
    };
    frame.src = url;
    document.body.appendChild(frame);
  });
}

// A file of the book exists when the browser can read it.
function exists(url) {
  return new Promise((resolve) => {
    const xhr = new XMLHttpRequest();
    xhr.onload = () => resolve(xhr.status === 0 || xhr.status === 200);
    xhr.onerror = () => resolve(false);
    try {
      xhr.open("GET", url);
      xhr.send();
    } catch (e) {
      resolve(false);
    }
  });
}

const TEX_LEFT_BEHIND = /\$[^$\s][^$]*\$|\\(frac|tfrac|mathbf|boldsymbol|alpha|beta|epsilon|delta|hat|sqrt|operatorname|times|cdot)\b/;

// What a reader would call an element: its tag, id or class, and its first words.
function describe(el) {
  let what = "<" + el.tagName.toLowerCase();
  if (el.id) what += " id=" + el.id;
  else if (el.classList && el.classList.length) what += " class=" + [...el.classList].join(".");
  what += ">";
  // By code points: cutting a surrogate pair (math letters such as 𝐚) in two would leave a
  // string the browser cannot write out.
  const text = [...(el.textContent || el.getAttribute("src") || el.getAttribute("alt") || "").replace(/\s+/g, " ").trim()];
  return what + (text.length ? " '" + text.slice(0, 50).join("") + (text.length > 50 ? "…" : "") + "'" : "");
}

// Elements that stick out of the content column, or hide part of their content (scroll or
// clip). The outermost offender of a subtree is named; what is inside it is not repeated.
function overflowProblems(doc) {
  const problems = [];
  const win = doc.defaultView;
  const main = doc.querySelector("main");
  if (!main) return ["no <main> element"];
  const cs = win.getComputedStyle(main);
  const box = main.getBoundingClientRect();
  const left = box.left + parseFloat(cs.paddingLeft) - 1;
  const right = box.right - parseFloat(cs.paddingRight) + 1;
  const reported = [];
  const inside = (el) => reported.some((r) => r.contains(el));
  for (const el of main.querySelectorAll("*")) {
    if (el.closest("math") && el.tagName.toLowerCase() !== "math") continue;  // the <math> itself speaks for its parts
    if (inside(el)) continue;
    let r = el.getBoundingClientRect();
    if (r.width === 0 && r.height === 0) continue;
    const style = win.getComputedStyle(el);
    if (style.display === "none" || style.visibility === "hidden") continue;
    if (el.tagName.toLowerCase() === "math") {
      // A display equation's box is the column; what it draws may stick out of it.
      let l = r.left, rt = r.right;
      for (const part of el.querySelectorAll("*")) {
        const b = part.getBoundingClientRect();
        if (b.width > 0) l = Math.min(l, b.left), rt = Math.max(rt, b.right);
      }
      r = { left: l, right: rt };
    }
    if (r.right > right || r.left < left) {
      problems.push("wider than the content column (" + Math.round(right - left - 2) + " px): " + describe(el) + " spans " +
                    Math.round(r.left - left - 1) + " to " + Math.round(r.right - left - 1) + " px");
      reported.push(el);
      continue;
    }
    // Content wider than its own box: a scroll bar or a cut-off edge. A <math> or <pre> that
    // does not fit must break or wrap instead; nothing may hide what it holds.
    const ox = style.overflowX;
    if (el.clientWidth > 0 && el.scrollWidth > el.clientWidth + 1) {
      if (ox !== "visible") {
        problems.push((ox === "hidden" || ox === "clip" ? "cut off" : "scrolls sideways") + " (" + el.scrollWidth +
                      " px of content in " + el.clientWidth + " px): " + describe(el));
        reported.push(el);
      } else if (r.left + el.scrollWidth > right) {  // text or a child that sticks out of its box, and the column
        problems.push("its content sticks out of the content column (" + el.scrollWidth + " px of content in " +
                      el.clientWidth + " px): " + describe(el));
        reported.push(el);
      }
    }
  }
  if (doc.documentElement.scrollWidth > win.innerWidth + 1)
    problems.push("the page is wider than the window (" + doc.documentElement.scrollWidth + " px in " + win.innerWidth + " px)");
  return problems;
}

// Elements that extend past the window's left or right edge: what a reader of that width
// cannot see (a sidebar whose first letters are cut off).
function edgeProblems(doc, width) {
  const problems = [];
  const win = doc.defaultView;
  const reported = [];
  for (const el of doc.body.querySelectorAll("*")) {
    if (el.closest("math") && el.tagName.toLowerCase() !== "math") continue;
    if (reported.some((r) => r.contains(el))) continue;
    const r = el.getBoundingClientRect();
    if (r.width === 0 || r.height === 0) continue;
    const style = win.getComputedStyle(el);
    if (style.display === "none" || style.visibility === "hidden") continue;
    if (r.left < -1 || r.right > win.innerWidth + 1) {
      problems.push("at " + width + " px, past the window's " + (r.left < -1 ? "left" : "right") + " edge (" +
                    Math.round(r.left) + " to " + Math.round(r.right) + " px of " + win.innerWidth + "): " + describe(el));
      reported.push(el);
    }
  }
  return problems;
}

const WIDTHS = [1024, 1280, 1366, 1920];

function checkPage(name, doc, kind) {
  const problems = [];
  const win = doc.defaultView;
  if (!doc.title.trim()) problems.push("no <title>");

  const images = [...doc.images];
  for (const img of images)
    if (!(img.complete && img.naturalWidth > 0 && img.naturalHeight > 0))
      problems.push("image did not load: " + img.getAttribute("src"));

  const maths = [...doc.getElementsByTagName("math")];
  let laidOut = 0;
  for (const m of maths) {
    const box = m.getBoundingClientRect();
    const display = win.getComputedStyle(m).display;
    if (m.constructor.name === "MathMLElement" && /math/.test(display) && box.width > 0 && box.height > 0) laidOut++;
  }
  if (laidOut < maths.length)
    problems.push((maths.length - laidOut) + " of " + maths.length + " <math> elements not laid out as MathML");
  for (const span of doc.querySelectorAll("span.math"))
    if (!span.querySelector("math")) problems.push("math left as TeX: " + [...span.textContent].slice(0, 60).join(""));
  const walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT, {
    acceptNode: (n) =>
      n.parentElement.closest("code, pre, math, script, style") ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT,
  });
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const m = n.textContent.match(TEX_LEFT_BEHIND);
    if (m) problems.push("TeX left as text: '" + [...m[0]].slice(0, 40).join("") + "' in '" + [...n.textContent.trim()].slice(0, 60).join("") + "'");
  }

  if (kind === "chapter") {
    if (!doc.querySelector("nav.pager a.prev") || !doc.querySelector("nav.pager a.next"))
      problems.push("a chapter without previous/next navigation");
  }

  const links = [];
  for (const a of doc.querySelectorAll("a[href]")) {
    const href = a.getAttribute("href");
    if (/^(https?:|mailto:)/.test(href)) {
      links.push({ external: href });
      continue;
    }
    const url = new URL(href, doc.baseURI);
    const fragment = decodeURIComponent(url.hash.slice(1));
    url.hash = "";
    links.push({ href, url: url.href, fragment });
  }
  problems.push(...overflowProblems(doc));
  const height = Math.ceil(Math.max(doc.documentElement.scrollHeight, doc.body ? doc.body.scrollHeight : 0));
  return { problems, links, ids: new Set([...doc.querySelectorAll("[id]")].map((e) => e.id)), maths: maths.length, images: images.length, height };
}

async function checkAll(pages) {
  const results = new Map();  // url -> result
  for (const p of pages) {
    const frame = await load(p.url);
    if (!frame || !frame.contentDocument) {
      results.set(p.url, { page: p, problems: ["the page did not load"], links: [], ids: new Set() });
      continue;
    }
    const r = checkPage(p.name, frame.contentDocument, p.kind);
    r.page = p;
    results.set(p.url, r);
    frame.remove();
    if (p.kind === "code") continue;  // source listings: a <pre> in the column, checked above
    for (const width of WIDTHS) {
      const wide = await load(p.url, width);
      if (wide && wide.contentDocument) r.problems.push(...edgeProblems(wide.contentDocument, width));
      if (wide) wide.remove();
    }
  }
  for (const r of results.values()) {
    for (const l of r.links) {
      if (l.external) continue;
      const target = results.get(l.url);
      if (target) {
        if (l.fragment && !target.ids.has(l.fragment)) r.problems.push("broken link: " + l.href + " (no such anchor)");
      } else if (!(await exists(l.url))) {
        r.problems.push("broken link: " + l.href);
      }
    }
  }
  return results;
}

(async () => {
  try {
    const results = await checkAll(BOOK_PAGES);
    let failures = 0;
    for (const r of results.values()) {
      const ext = r.links.filter((l) => l.external).length;
      say("PAGE " + r.page.name + ": " + r.images + " images, " + r.maths + " math, " + r.links.length + " links (" + ext + " external)");
      if (r.height) say("HEIGHT " + r.page.name + " " + r.height);
      for (const p of r.problems) {
        say("FAIL " + r.page.name + ": " + p);
        failures++;
      }
    }
    // The checks must be able to fail: a page broken on purpose must show each kind of damage.
    const self = (await checkAll([SELFTEST_PAGE])).get(SELFTEST_PAGE.url).problems.join("\n");
    for (const [what, pattern] of [
      ["a missing image", /image did not load/],
      ["a broken link", /broken link: missing-page\.html/],
      ["a missing anchor", /no such anchor/],
      ["TeX left as text", /TeX left as text/],
      ["a code block wider than the column", /wider than the content column .*<pre[^>]*> 'a line of code/],
      ["a code block that scrolls", /scrolls sideways .*<pre[^>]*> 'a scrolling line/],
      ["a table wider than the column", /wider than the content column .*<table>/],
      ["an equation wider than the column", /(wider than the content column|scrolls sideways) .*<math/],
      ["an image cut off", /cut off .*<div class=clip>/],
      ["a word too long for the column", /sticks out of the content column .*<h1>/],
      ["a sidebar cut off at the left edge at 1280 px", /at 1280 px, past the window's left edge .*<nav class=toc>/],
    ]) {
      if (!pattern.test(self)) {
        say("FAIL self-test: the checks did not notice " + what + " on the broken page");
        failures++;
      }
    }
    say(failures ? "FAILED " + failures : "PASSED");
  } catch (e) {
    say("FAIL the checks crashed: " + e);
  }
  say("DONE");
  document.getElementById("book-test-result").textContent = lines.join("\n");
})();
