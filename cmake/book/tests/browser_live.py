#!/usr/bin/env python3
"""The live scenes of the book in a real browser (cmake/book/web/live.js, cmake/book/live/).

Opens every page with a live scene (<div class="live" data-module>) from file:// in headless
Chromium (over its DevTools pipe: browser_motion.py's Browser) and, for each live scene:

  * its module loads and gives a first result (no console error, no uncaught exception);
  * it moves each control (the slider, as a reader drags it) to a new value, waits for the run,
    and checks every number the page shows against the native scene run with the same command
    line (`<scene> <the page's arguments> --json --no-figure`): to the relative or absolute
    tolerance its spec states (cmake/book/live/<scene>.json; timings are not compared);
  * after each move the plot changed (unless the control's spec says why it cannot: "same_plot"),
    and, where the spec feeds a viewer, the viewer's motion changed (rebuilt on new samples);
  * nothing was fetched from the network (every request is file: or data:);
  * it keeps a screenshot per live scene: <book>/screenshots/live-<scene>.png.

It reports (LIVE lines) per live scene: the module's size, the time to its first result, and the
recompute-and-redraw time (the median of 20 runs in the page): measurements, not checks.

    browser_live.py <book folder> <build folder> [<scratch folder>] [--expect N]
                    N: the live scenes the chapters mark; fewer or more fails (less those the
                    build left out for want of GSL: <build>/live/<scene>.missing.txt)
    browser_live.py --selftest <book folder> <build folder> <scratch folder>
                    the checks must fail on a module that returns a wrong number, on a module that
                    does not load, and on a page that fetches from the network; and the tolerance
                    rules (abs, rel, abs + rel) must pass and fail a few numbers as they should

Exit status: 0 all well; 1 a check failed; 77 no Chromium, a book without live modules (no
emscripten), or live scenes left out for want of GSL (offline: no Debian source package; the
others are checked): CTest reports it skipped, unless CI=true (then 1).
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from browser_motion import Browser, find_browser, changed_fraction  # noqa: E402


def live_pages(book):
    pages = []
    with open(os.path.join(book, "pages.txt")) as f:
        for line in f:
            name = line.split("\t")[0]
            path = os.path.join(book, name)
            if name.endswith(".html") and os.path.exists(path):
                with open(path, encoding="utf-8") as h:
                    html = h.read()
                n = len(re.findall(r'<div class="live" id="live-[^"]+" data-module=', html))
                if n:
                    pages.append((name, n))
    return pages


def native(build, argv, work):
    """The native scene's report for the page's command line (scene name first)."""
    out = os.path.join(work, "native-" + argv[0])
    os.makedirs(out, exist_ok=True)
    cmd = [os.path.join(build, "scenes", argv[0])] + argv[1:] + ["--json", "--no-figure", "--out", out]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    return r.returncode, (json.loads(r.stdout) if r.returncode == 0 else None), r.stderr.strip()


def lookup(report, key):
    v = report
    for part in re.findall(r"[^.\[\]]+|\[\d+\]", key):
        if isinstance(v, dict) and "columns" in v and "rows" in v and part.startswith("["):
            v = {"__row__": v["rows"][int(part[1:-1])], "__columns__": v["columns"]}
        elif isinstance(v, dict) and "__row__" in v:
            v = v["__row__"][v["__columns__"].index(part)]
        elif part.startswith("["):
            v = v[int(part[1:-1])]
        else:
            v = v[part]
    return v


def agree(spec, page_value, native_value):
    """None when the page's number is the native scene's within the spec's tolerance, else why not."""
    if not isinstance(native_value, (int, float)) or isinstance(native_value, bool):
        return None if page_value == native_value else "page %r, native %r" % (page_value, native_value)
    if not isinstance(page_value, (int, float)):
        return "page shows %r, native %r" % (page_value, native_value)
    d = abs(page_value - native_value)
    # abs, rel, or both: |page - native| <= abs + rel |native| (an integrated error agrees to a
    # relative tolerance far above round-off and to an absolute one near it).
    if "abs" in spec and "rel" in spec:
        ok = d <= spec["abs"] + spec["rel"] * abs(native_value)
        tol = "absolute %g + relative %g" % (spec["abs"], spec["rel"])
    elif "abs" in spec:
        ok = d <= spec["abs"]
        tol = "absolute %g" % spec["abs"]
    else:
        rel = spec.get("rel", 1e-12)
        ok = d <= rel * abs(native_value)
        tol = "relative %g" % rel
    return None if ok else "page %.17g, native %.17g: differ by %.3g (tolerance %s)" % (page_value, native_value, d, tol)


STATE = """(() => { const s = window.liveScenes || [];
  return s.map(x => ({scene: x.scene, state: x.state, runs: x.runs, first: x.firstResultMs})); })()"""


def wait_ready(b, count, timeout=60):
    deadline, state = time.time() + timeout, []
    while time.time() < deadline:
        state = b.js(STATE)
        if len(state) == count and all(s["state"] != "loading" and (s["state"] == "failed" or s["first"]) for s in state):
            break
        time.sleep(0.2)
    return state


def shown(b, i):
    return b.js("""(() => { const s = window.liveScenes[%d], out = {};
      for (const td of s.div.querySelectorAll('td.live-number'))
        out[td.dataset.key] = td.dataset.value === '' ? null : JSON.parse(td.dataset.value);
      const plot = s.div.querySelector('.live-figure');
      const v = (window.motionViewers || []).find(v => v.data && v.data.scene === s.scene);
      return {numbers: out, argv: s.argv(), runs: s.runs, status: s.result && s.result.status,
              message: s.message.textContent, plot: plot ? plot.innerHTML : '',
              motion: v ? JSON.stringify([v.data.t.slice(0, 40), v.data.R.slice(0, 40)]) : null}; })()""" % i)


def move(b, i, c, k):
    """Drags control c's slider to a new place (k-th move), or picks the menu's next word, and
    waits for the scene's next run."""
    runs = b.js("window.liveScenes[%d].runs" % i)
    b.js("""(() => { const s = window.liveScenes[%d];
      const r = s.div.querySelector("input[type=range][data-option='%s']");
      if (r) { r.value = String((Number(r.value) + %d) %% 1001); r.dispatchEvent(new Event('input')); return; }
      const m = s.div.querySelector("select[data-option='%s']");
      m.selectedIndex = (m.selectedIndex + 1) %% m.options.length; m.dispatchEvent(new Event('change')); })()"""
         % (i, c, 290 + 130 * k, c))
    deadline = time.time() + 30
    while time.time() < deadline and b.js("window.liveScenes[%d].runs" % i) == runs:
        time.sleep(0.05)


def check_numbers(spec, got, build, work, fail, where):
    code, report, err = native(build, got["argv"], work)
    if code != 0:
        if got["status"] == code and got["message"]:
            return  # the page shows the scene's own refusal, as the native scene refuses
        fail("%s: the native scene exits %d (%s); the page shows status %s" % (where, code, err, got["status"]))
        return
    for n in spec["numbers"]:
        if n.get("timing"):
            continue
        why = agree(n, got["numbers"].get(n["key"]), lookup(report, n["key"]))
        if why:
            fail("%s: %s: %s" % (where, n["key"], why))


def check_scene(b, i, book, build, work, shots, fail, out):
    spec = b.js("window.liveScenes[%d].spec" % i)
    scene = spec["scene"]
    got = shown(b, i)
    check_numbers(spec, got, build, work, fail, scene + " (defaults)")
    for k, c in enumerate(spec["controls"]):
        before = got
        move(b, i, c["option"], k)
        got = shown(b, i)
        where = "%s --%s %s" % (scene, c["option"], got["argv"][got["argv"].index("--" + c["option"]) + 1])
        if got["runs"] == before["runs"]:
            fail(where + ": moving the control did not run the scene")
            continue
        check_numbers(spec, got, build, work, fail, where)
        # A control whose figure does not move says so, and why, in its spec ("same_plot").
        if spec.get("plot") and not c.get("same_plot") and got["status"] == 0 and got["plot"] == before["plot"]:
            fail(where + ": the plot did not change")
        if spec.get("motion") and got["status"] == 0 and got["motion"] == before["motion"]:
            fail(where + ": the motion viewer still shows the old motion")
    # Measurements: the module's size, the first result, and 20 recomputations with redraw.
    # Each run: the module's computation (its live_run, the JSON text included), then the page's
    # work (parse, numbers, plot, viewer update); the WebGL frame is drawn later, by the viewer.
    times = b.js("""(() => { const s = window.liveScenes[%d], t = [], c = [], d = [];
      for (let k = 0; k < 20; k++) { s.run(); t.push(s.lastRunMs); c.push(s.lastComputeMs); d.push(s.lastRunMs - s.lastComputeMs); }
      for (const a of [t, c, d]) a.sort((x, y) => x - y);
      return {median: t[10], max: t[19], compute: c[10], draw: d[10], first: s.firstResultMs}; })()""" % i)
    size = os.path.getsize(os.path.join(book, "live", scene + ".js"))
    out.append("LIVE %s: module %d bytes; first result %.0f ms; recompute and redraw %.1f ms (median of 20, max %.1f; "
               "medians: compute %.1f, redraw %.1f)"
               % (scene, size, times["first"], times["median"], times["max"], times["compute"], times["draw"]))
    box = b.js("""(() => { const d = window.liveScenes[%d].div; d.scrollIntoView({block: 'start'});
      const r = d.getBoundingClientRect(); return {x: r.left + window.scrollX, y: r.top + window.scrollY,
      width: r.width, height: Math.min(r.height, 1600)}; })()""" % i)
    png = b.shot(box)
    name = os.path.join(shots, "live-%s.png" % scene)
    with open(name, "wb") as f:
        f.write(png)
    out.append("screenshot: " + name)


def network_requests(b):
    urls = []
    for e in b.events:
        if e.get("method") == "Network.requestWillBeSent":
            urls.append(e["params"]["request"]["url"])
    return [u for u in urls if not (u.startswith("file:") or u.startswith("data:"))]


def check_page(exe, book, build, page, count, work, shots):
    out, ok = [], True

    def fail(text):
        nonlocal ok
        ok = False
        out.append("FAIL %s: %s" % (page, text))

    b = Browser(exe, work)
    try:
        b.open_page("about:blank")
        b.send("Network.enable")
        b.send("Page.navigate", {"url": "file://" + os.path.join(book, page)})
        b.wait_event("Page.loadEventFired", 60)
        state = wait_ready(b, count)
        if len(state) != count:
            fail("%d live scene(s) on the page, live.js started %d" % (count, len(state)))
        for i, s in enumerate(state):
            if s["state"] != "ready":
                why = b.js("window.liveScenes[%d].status.textContent" % i)
                fail("the live scene %s did not start: %s" % (s["scene"], why))
                continue
            check_scene(b, i, book, build, work, shots, fail, out)
        b.drain(0.3)
        for e in b.errors():
            fail(e)
        for u in network_requests(b):
            fail("fetched from the network: " + u)
    except Exception as e:  # a hung or crashed browser, a page that does not load
        fail("the browser check crashed: %s" % e)
    finally:
        b.close()
    return out, ok


def check_book(exe, book, build, work, expect=None):
    shots = os.path.join(book, "screenshots")
    os.makedirs(shots, exist_ok=True)
    os.makedirs(work, exist_ok=True)
    pages = live_pages(book)
    lines, ok = ["Live scenes on %d page(s): %s" % (len(pages), " ".join(p for p, _ in pages))], True
    for page, count in pages:
        out, good = check_page(exe, book, build, page, count, work, shots)
        lines += out
        ok = ok and good
    total = sum(n for _, n in pages)
    if expect is not None and total != expect:
        lines.append("FAIL the book has %d live scene(s); the chapters mark %d (<!-- live: -->)" % (total, expect))
        ok = False
    return lines, ok


# ---------------------------------------------------------------------------- self-test
WRONG = """
;(function () { const real = live_%s;
  live_%s = function () { return real.apply(this, arguments).then(function (m) { const call = m.ccall;
    m.ccall = function (name, ret, types, args) { const r = JSON.parse(call.call(m, name, ret, types, args));
      if (r.report) r.report.run_time_s = r.report.run_time_s;  // untouched: timings are not compared
      %s
      return JSON.stringify(r); }; return m; }); }; })();
"""


def tolerance_cases():
    """The tolerance rules on numbers alone: each case passes or fails as it says (names of those that do not)."""
    both = {"abs": 1e-12, "rel": 1e-6}
    cases = [("abs + rel: within rel far above abs", both, 1 + 5e-7, 1.0, True),
             ("abs + rel: beyond rel far above abs", both, 1 + 2e-6, 1.0, False),
             ("abs + rel: within abs near 0", both, 5e-13, 0.0, True),
             ("abs + rel: beyond abs near 0", both, 3e-12, 0.0, False),
             ("abs alone ignores the size", {"abs": 1e-12}, 1 + 2e-12, 1.0, False),
             ("rel alone", {"rel": 1e-9}, 1 + 5e-10, 1.0, True)]
    return [name for name, spec, page, native, good in cases if (agree(spec, page, native) is None) != good]


def selftest(exe, book, build, work):
    """A copy of the book, damaged three ways; each damage must fail the check."""
    wrong = tolerance_cases()
    if wrong:
        return [], ["tolerance: " + w for w in wrong]
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)
    pages = live_pages(book)
    if not pages:
        return ["the book has no live scene to damage"], ["no live scene"]
    page, _ = pages[0]
    with open(os.path.join(book, page), encoding="utf-8") as f:
        scene = re.search(r'<div class="live" id="live-([^"]+)"', f.read()).group(1)
    with open(os.path.join(book, "live", scene + ".js"), encoding="utf-8") as f:
        module = f.read()
    spec_key = None
    with open(os.path.join(build, "live", scene + ".live.json"), encoding="utf-8") as f:
        spec = json.load(f)
    spec_key = next(n["key"] for n in spec["numbers"] if not n.get("timing"))
    path = json.dumps(re.findall(r"[^.\[\]]+|\[\d+\]", spec_key))
    # One number of the report one part in 1e9 off: what a module built from other code would show.
    perturb = """const p = %s; let o = r.report, k = 0; if (o) { for (; k < p.length - 1; k++) {
        const q = p[k]; if (q[0] === '[') { const i = Number(q.slice(1, -1)); if (o.rows) { const row = o.rows[i];
          const col = o.columns.indexOf(p[k + 1]); row[col] *= 1 + 1e-9; o = null; break; } o = o[i]; } else o = o[q]; }
        const last = p[k][0] === '[' ? Number(p[k].slice(1, -1)) : p[k];
        if (o) o[last] *= 1 + 1e-9; }""" % path
    damage = {
        "sound": (lambda d: None, None),
        "wrong-number": (lambda d: open(os.path.join(d, "live", scene + ".js"), "a").write(WRONG % (scene, scene, perturb)),
                         r"differ by .*tolerance"),
        "no-module": (lambda d: os.remove(os.path.join(d, "live", scene + ".js")), r"did not start: The live scene cannot run here"),
        "network": (lambda d: open(os.path.join(d, "live.js"), "a").write(
            "\n;document.head.appendChild(Object.assign(document.createElement('img'), {src: 'http://192.0.2.1/x.png'}));\n"),
            r"fetched from the network: http://192\.0\.2\.1"),
    }
    lines, missed = [], []
    for name, (hurt, expect) in damage.items():
        copy = os.path.join(work, name)
        shutil.copytree(book, copy, ignore=shutil.ignore_patterns("screenshots"))
        hurt(copy)
        out, ok = check_book(exe, copy, build, os.path.join(work, name + "-scratch"))
        lines += ["[%s] %s" % (name, l) for l in out]
        text = "\n".join(out)
        if expect is None:
            if not ok:
                missed.append("sound: the sound copy failed a check")
        elif ok or not re.search(expect, text):
            missed.append("%s: expected a failure /%s/" % (name, expect))
    del module
    return lines, missed


def main(argv):
    ci = os.environ.get("CI") == "true"
    exe = find_browser()
    if not exe:
        print("No Chromium here: install it (sudo apt-get install chromium) or run cmake/workbook test, which does.")
        return 1 if ci else 77
    expect = None
    if "--expect" in argv:
        i = argv.index("--expect")
        expect, argv = int(argv[i + 1]), argv[:i] + argv[i + 2:]
    if len(argv) == 5 and argv[1] == "--selftest":
        book, build, work = (os.path.abspath(a) for a in argv[2:5])
        if not live_pages(book):
            print("The book at %s has no live modules (built without emscripten): nothing to damage." % book)
            return 1 if ci else 77
        lines, missed = selftest(exe, book, build, work)
        print("\n".join(lines))
        if missed:
            print("The live checks missed damage done on purpose:\n  " + "\n  ".join(missed))
            return 1
        print("The live checks pass the sound book and fail each damage done on purpose.")
        return 0
    if len(argv) not in (3, 4):
        print(__doc__)
        return 2
    book, build = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    work = os.path.abspath(argv[3]) if len(argv) == 4 else tempfile.mkdtemp(prefix="live-check.")
    if not os.path.isdir(os.path.join(book, "live")):
        print("The book at %s has no live modules: it was built without emscripten "
              "(sudo apt-get install emscripten; cmake/workbook run installs it)." % book)
        return 1 if ci else 77
    # Scenes the build left out (they need GSL and it has none for WebAssembly), with its reason.
    left_out = {}
    live = os.path.join(build, "live")
    for name in sorted(os.listdir(live)) if os.path.isdir(live) else []:
        if name.endswith(".missing.txt"):
            with open(os.path.join(live, name), encoding="utf-8") as f:
                left_out[name[:-len(".missing.txt")]] = f.read().strip()
    if expect is not None:
        expect -= len(left_out)
    lines, ok = check_book(exe, book, build, work, expect)
    lines += ["LEFT OUT %s: %s" % (scene, why) for scene, why in left_out.items()]
    print("\n".join(lines))
    if ok and left_out:
        print("%d live scene(s) left out by the build (see above); the others pass." % len(left_out))
        return 1 if ci else 77
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
