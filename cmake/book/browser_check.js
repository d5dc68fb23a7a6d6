// The browser test's checks (cmake/book/browser_test.sh puts this into a harness page).
// Loads every page of the book in an iframe, as a reader's browser would, and checks:
//   * every image loaded (complete, with a natural size);
//   * the math is MathML that the browser lays out (MathMLElement, display "math", a size),
//     and no TeX was left behind as text ($...$, \frac, a .math span without <math>);
//   * every link leads somewhere: pages of the book with the named anchor, files that load;
//   * the page has a title, and chapters have their previous/next navigation.
// Then it checks itself on a page that is broken on purpose: the checks must see the damage.
// The result goes into <pre id="book-test-result">, one line per finding, ending with DONE.
/* global BOOK_PAGES, SELFTEST_PAGE */
"use strict";

const lines = [];
const say = (s) => lines.push(s);

function load(url) {
  return new Promise((resolve) => {
    const frame = document.createElement("iframe");
    frame.style.width = "1200px";
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
    if (!span.querySelector("math")) problems.push("math left as TeX: " + span.textContent.slice(0, 60));
  const walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT, {
    acceptNode: (n) =>
      n.parentElement.closest("code, pre, math, script, style") ? NodeFilter.FILTER_REJECT : NodeFilter.FILTER_ACCEPT,
  });
  for (let n = walker.nextNode(); n; n = walker.nextNode()) {
    const m = n.textContent.match(TEX_LEFT_BEHIND);
    if (m) problems.push("TeX left as text: '" + m[0].slice(0, 40) + "' in '" + n.textContent.trim().slice(0, 60) + "'");
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
  return { problems, links, ids: new Set([...doc.querySelectorAll("[id]")].map((e) => e.id)), maths: maths.length, images: images.length };
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
