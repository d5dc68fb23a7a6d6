#!/usr/bin/env python3
"""The motion viewers of the book in a real browser (cmake/book/web/motion_viewer.js).

Drives headless Chromium over the DevTools protocol on a pipe (--remote-debugging-pipe: JSON
messages ended by NUL on the browser's file descriptors 3 and 4), with the standard library
only. For every page of the book with a viewer (<figure class="motion">), offline:

  * no console error, no uncaught exception, no resource that fails to load;
  * every viewer is ready, its canvas is not blank (the body, axes and cones drew something);
  * while playing, two screenshots of the viewer a second apart differ;
  * after a click on Pause, two screenshots a second apart are identical;
  * a click on the time scrubber moves the body (the screenshot changes, the time follows);
  * and it keeps a screenshot of each viewer: <book>/screenshots/motion-<page>-<n>.png.

It reports the frames per second each viewer keeps while playing (FPS lines) and each page's
weight (WEIGHT lines: the motion data embedded, the page, the GIF fallbacks it links):
measurements, not checks. Screenshots are pixels the compositor produced (Page.captureScreenshot), decoded
here (zlib + PNG filters) to count the pixels that changed.

    browser_motion.py [--expect N] <book folder> [<scratch folder>]
                                   N: the viewers the chapters mark; fewer or more fails
    browser_motion.py --selftest <scratch folder>   the checks must fail on broken viewers (and on a
                                                    book that lost a viewer its chapters mark)

Exit status: 0 all well; 1 a check failed; 77 no Chromium here (CTest: skipped), unless CI=true.
"""
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
THREE = "/usr/share/javascript/three/three.min.js"


def find_browser():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


# ---------------------------------------------------------------------------- PNG, by hand
def png_pixels(data):
    """(width, height, rows of RGB(A) bytes) of an 8-bit RGB or RGBA PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                raise ValueError("PNG of depth %d, colour type %d" % (depth, colour))
            bpp = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * bpp, [], bytearray(width * bpp)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b, c = prev[x], prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, bpp, rows


def changed_fraction(png1, png2):
    w1, h1, bpp, r1 = png_pixels(png1)
    w2, h2, _, r2 = png_pixels(png2)
    if (w1, h1) != (w2, h2):
        return 1.0
    changed = 0
    for a, b in zip(r1, r2):
        if a != b:
            changed += sum(1 for x in range(0, len(a), bpp) if a[x:x + 3] != b[x:x + 3])
    return changed / (w1 * h1)


def ink_fraction(png):
    """The share of pixels that are not the background (the commonest colour): a blank canvas,
    white, black or any one colour, has none."""
    w, h, bpp, rows = png_pixels(png)
    counts = {}
    for r in rows:
        for x in range(0, len(r), bpp):
            c = r[x:x + 3]
            counts[c] = counts.get(c, 0) + 1
    return 1 - max(counts.values()) / (w * h)


# ---------------------------------------------------------------------- the browser, on a pipe
class Browser:
    def __init__(self, exe, work):
        self.profile = tempfile.mkdtemp(prefix="profile.", dir=work)
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()
        # The browser reads commands on its fd 3 and writes answers on its fd 4: the shell puts
        # our pipe ends there just before it becomes the browser.
        args = [exe, "--headless", "--no-sandbox", "--remote-debugging-pipe", "--no-first-run",
                "--disable-background-networking", "--disable-component-update", "--disable-sync",
                "--disable-dev-shm-usage", "--hide-scrollbars", "--enable-unsafe-swiftshader",
                "--use-angle=swiftshader", "--window-size=1200,900", "--user-data-dir=" + self.profile,
                "about:blank"]
        log = open(os.path.join(work, "chromium-motion.log"), "ab")
        shell = 'exec "$0" "$@" 3<&%d 4>&%d' % (to_browser_r, from_browser_w)
        self.proc = subprocess.Popen(["bash", "-c", shell] + args, stdin=subprocess.DEVNULL, stdout=log, stderr=log,
                                     pass_fds=(to_browser_r, from_browser_w))
        log.close()
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.buffer, self.next_id, self.events, self.session = b"", 0, [], None

    def send(self, method, params=None, session=True, timeout=30):
        self.next_id += 1
        msg = {"id": self.next_id, "method": method, "params": params or {}}
        if session and self.session:
            msg["sessionId"] = self.session
        os.write(self.to_browser, json.dumps(msg).encode() + b"\0")
        deadline = time.time() + timeout
        while True:
            m = self.read(deadline)
            if m.get("id") == self.next_id:
                if "error" in m:
                    raise RuntimeError("%s: %s" % (method, m["error"].get("message")))
                return m.get("result", {})
            self.events.append(m)

    def read(self, deadline):
        import select
        while b"\0" not in self.buffer:
            left = deadline - time.time()
            if left <= 0 or not select.select([self.from_browser], [], [], left)[0]:
                raise TimeoutError("the browser did not answer in time")
            chunk = os.read(self.from_browser, 1 << 20)
            if not chunk:
                raise RuntimeError("the browser closed its pipe")
            self.buffer += chunk
        msg, self.buffer = self.buffer.split(b"\0", 1)
        return json.loads(msg)

    def wait_event(self, method, timeout=30):
        deadline = time.time() + timeout
        while True:
            for i, e in enumerate(self.events):
                if e.get("method") == method:
                    return self.events.pop(i)
            self.events.append(self.read(deadline))

    def open_page(self, url):
        target = self.send("Target.createTarget", {"url": "about:blank"}, session=False)["targetId"]
        self.session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True}, session=False)["sessionId"]
        for domain in ("Page", "Runtime", "Log"):
            self.send(domain + ".enable")
        self.send("Emulation.setDeviceMetricsOverride",
                  {"width": 1200, "height": 900, "deviceScaleFactor": 1, "mobile": False})
        self.send("Page.navigate", {"url": url})
        self.wait_event("Page.loadEventFired", 60)

    def js(self, expression):
        r = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True, "awaitPromise": True})
        if "exceptionDetails" in r:
            raise RuntimeError("page script failed: " + json.dumps(r["exceptionDetails"])[:300])
        return r["result"].get("value")

    def click(self, x, y):
        for kind in ("mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": "left", "clickCount": 1})

    def shot(self, clip):
        import base64
        r = self.send("Page.captureScreenshot", {"format": "png", "clip": dict(clip, scale=1), "captureBeyondViewport": False})
        return base64.b64decode(r["data"])

    def errors(self):
        """Console errors, uncaught exceptions and failed loads seen so far."""
        found = []
        for e in self.events:
            m, p = e.get("method"), e.get("params", {})
            if m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "assert"):
                found.append("console error: " + " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", [])))
            elif m == "Runtime.exceptionThrown":
                d = p.get("exceptionDetails", {})
                found.append("uncaught exception: " + (d.get("exception", {}).get("description") or d.get("text", "")).split("\n")[0])
            elif m == "Log.entryAdded" and p.get("entry", {}).get("level") == "error":
                found.append("browser error: " + p["entry"].get("text", "") + " " + p["entry"].get("url", ""))
        return found

    def drain(self, seconds):
        deadline = time.time() + seconds
        while True:
            try:
                self.events.append(self.read(deadline))
            except TimeoutError:
                return

    def close(self):
        try:
            self.send("Browser.close", session=False, timeout=5)
        except Exception:
            pass
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        os.close(self.to_browser)
        os.close(self.from_browser)
        shutil.rmtree(self.profile, ignore_errors=True)


# ---------------------------------------------------------------------------- the checks
def check_page(exe, book, page, work, shots):
    """Lines: FAIL ..., FPS ..., screenshot: ...; and whether the page passed."""
    out, ok = [], True

    def fail(text):
        nonlocal ok
        ok = False
        out.append("FAIL %s: %s" % (page, text))

    b = Browser(exe, work)
    try:
        b.open_page("file://" + os.path.join(book, page))
        # The viewers started, and the page's live scenes (live.js) settled: a live scene grows when
        # its module has loaded and its first run is drawn, which moves whatever is below it.
        deadline = time.time() + 60
        state = None
        while time.time() < deadline:
            state = b.js("""(() => { const v = window.motionViewers || [], l = window.liveScenes || [];
                return { figures: document.querySelectorAll('figure.motion').length, viewers: v.length,
                         ready: v.filter(x => x.ready).length, errors: v.filter(x => x.error).map(x => x.error),
                         live_busy: l.filter(x => x.state === 'loading' || (x.state === 'ready' && !x.runs)).length }; })()""")
            if (state["figures"] and state["viewers"] == state["figures"] and not state["live_busy"]
                    and (state["ready"] == state["figures"] or state["errors"])):
                break
            time.sleep(0.2)
        time.sleep(0.3)  # the live scenes' last layout
        if not state or not state["figures"]:
            fail("no motion viewer on the page")
            return out, False
        if state["ready"] != state["figures"]:
            fail("%d of %d viewers did not start (%s)" % (state["figures"] - state["ready"], state["figures"],
                                                          "; ".join(state["errors"]) or "motion_viewer.js did not run"))
        for n in range(state["ready"]):
            where = "viewer %d" % (n + 1)
            # Its canvas, on screen: scrolled into the middle of the window.
            box = b.js("""(() => { const v = window.motionViewers[%d], c = v.renderer.domElement;
                c.scrollIntoView({block: 'center'});
                const r = c.getBoundingClientRect(), s = v.ui.scrub.getBoundingClientRect(), p = v.ui.play.getBoundingClientRect();
                return { x: r.left + window.scrollX, y: r.top + window.scrollY, width: r.width, height: r.height,
                         scrub: { x: s.left, y: s.top + s.height / 2, width: s.width },
                         play: { x: p.left + p.width / 2, y: p.top + p.height / 2 } }; })()""" % n)
            # Screenshots clip in page coordinates; clicks go to the window's.
            clip = {"x": box["x"], "y": box["y"], "width": box["width"], "height": box["height"]}
            time.sleep(0.5)
            a = b.shot(clip)
            ink = ink_fraction(a)
            if ink < 0.01:
                fail("%s: the canvas is blank (%.2g%% of its pixels drawn)" % (where, 100 * ink))
            frames0, t0 = b.js("window.motionViewers[%d].frames" % n), time.time()
            time.sleep(1.0)
            a2 = b.shot(clip)
            frames1, t1 = b.js("window.motionViewers[%d].frames" % n), time.time()
            moved = changed_fraction(a, a2)
            if moved < 0.001:
                fail("%s: while playing, two screenshots a second apart are the same (%.3g%% of the pixels changed)"
                     % (where, 100 * moved))
            out.append("FPS %s %s: %.1f frames per second while playing (%d frames in %.2f s; %.2g%% of the pixels drawn, "
                       "%.2g%% changed in 1 s)" % (page, where, (frames1 - frames0) / (t1 - t0), frames1 - frames0, t1 - t0,
                                                   100 * ink, 100 * moved))
            name = "motion-%s-%d.png" % (os.path.splitext(page)[0], n + 1)
            with open(os.path.join(shots, name), "wb") as f:
                f.write(a2)
            out.append("screenshot: " + os.path.join(shots, name))
            # Pause, with a click on the button, then the picture must hold still.
            b.click(box["play"]["x"], box["play"]["y"])
            time.sleep(0.4)
            if b.js("window.motionViewers[%d].playing" % n):
                fail("%s: a click on Pause did not pause it" % where)
            p1 = b.shot(clip)
            time.sleep(1.0)
            p2 = b.shot(clip)
            still = changed_fraction(p1, p2)
            if still > 0:
                fail("%s: paused, two screenshots a second apart differ (%.3g%% of the pixels)" % (where, 100 * still))
            # The scrubber: a click at three quarters of its length moves the time, and the body.
            before = b.js("window.motionViewers[%d].time" % n)
            s = box["scrub"]
            b.click(s["x"] + 0.75 * s["width"], s["y"])
            time.sleep(0.4)
            after = b.js("(() => { const v = window.motionViewers[%d]; return [v.time, v.t[0], v.t[v.t.length - 1]]; })()" % n)
            frac = (after[0] - after[1]) / (after[2] - after[1])
            if not (abs(frac - 0.75) < 0.05):
                fail("%s: a click at 3/4 of the scrubber took the time to %.3g of the motion (from %.3g)" % (where, frac, before))
            s2 = b.shot(clip)
            if changed_fraction(p2, s2) < 0.001:
                fail("%s: the scrubber moved the time but not the body (the picture did not change)" % where)
        b.drain(0.3)
        for e in b.errors():
            fail(e)
    except Exception as e:  # a hung or crashed browser, a page that does not load
        fail("the browser check crashed: %s" % e)
    finally:
        b.close()
    return out, ok


def pages_with_viewers(book):
    pages = []
    with open(os.path.join(book, "pages.txt")) as f:
        for line in f:
            name = line.split("\t")[0]
            if name.endswith(".html") and os.path.exists(os.path.join(book, name)):
                with open(os.path.join(book, name), encoding="utf-8") as h:
                    if 'class="motion"' in h.read():
                        pages.append(name)
    return pages


def check_book(exe, book, work, expect=None):
    shots = os.path.join(book, "screenshots")
    os.makedirs(shots, exist_ok=True)
    os.makedirs(work, exist_ok=True)
    pages = pages_with_viewers(book)
    lines, ok = ["Motion viewers on %d page(s): %s" % (len(pages), " ".join(pages))], True
    for page in pages:
        out, good = check_page(exe, book, page, work, shots)
        lines += out
        ok = ok and good
    weight, viewers = [], 0
    for page in pages:
        size = os.path.getsize(os.path.join(book, page))
        with open(os.path.join(book, page), encoding="utf-8") as h:
            html = h.read()
        data = sum(len(m) for m in re.findall(r'<script type="application/json" class="motion-data">(.*?)</script>', html))
        viewers += html.count('<figure class="motion"')
        # The GIF fallbacks the page links (hidden behind the viewer, fetched only without it).
        gifs = sorted(set(re.findall(r'src="([^"]+\.motion\.gif)"', html)))
        gif_bytes = sum(os.path.getsize(os.path.join(book, g)) for g in gifs if os.path.exists(os.path.join(book, g)))
        weight.append("WEIGHT %s: %d bytes of motion data in a page of %d bytes; %d GIF fallback(s) of %d bytes"
                      % (page, data, size, len(gifs), gif_bytes))
    lines += weight
    if expect is not None and viewers != expect:
        lines.append("FAIL the book has %d motion viewer(s); the chapters' sources mark %d (<!-- motion: -->)"
                     % (viewers, expect))
        ok = False
    return lines, ok


# ---------------------------------------------------------------------------- self-test
def selftest(exe, work):
    """Viewers broken on purpose: each check must catch its own damage, a sound one none."""
    if os.path.exists(work):
        shutil.rmtree(work)
    os.makedirs(work)
    # A quarter turn per second about a tilted axis, sampled: R(t) = exp(t w^) by Rodrigues.
    ts = [i * 0.05 for i in range(161)]
    axis = [0.3, 0.2, 0.93]
    norm = math.sqrt(sum(a * a for a in axis))
    u = [a / norm for a in axis]
    rs = []
    for t in ts:
        c, s, v = math.cos(1.2 * t), math.sin(1.2 * t), 1 - math.cos(1.2 * t)
        x, y, z = u
        rs.append([c + x * x * v, x * y * v - z * s, x * z * v + y * s,
                   y * x * v + z * s, c + y * y * v, y * z * v - x * s,
                   z * x * v - y * s, z * y * v + x * s, c + z * z * v])
    motion = {"format": "workbook-motion-1", "scene": "selftest", "title": "a rotation", "parameters": "",
              "error": 0, "error_measure": "", "body": {"shape": "ellipsoid", "moments": [1, 2, 2.5],
              "half_axes": [1, 0.75, 0.5]}, "fixed_point": [0, 0, 0], "k": [0, 0, 1], "centre_of_mass": [0, 0, 0.5],
              "t": ts, "R": rs, "trails": {"centre_of_mass": [], "tip_R_B": []},
              "cones": [{"name": "a cone", "axis": u, "half_angle": 0.4, "frame": "lab", "length": 1.5}]}
    with open(os.path.join(HERE, "..", "web", "motion_viewer.js"), encoding="utf-8") as f:
        viewer = f.read()
    broken = {
        "sound": (viewer, None),
        "frozen": (viewer.replace("this.time + dt * this.speed * this.base", "this.time"), r"while playing, two screenshots a second apart are the same"),
        "unpausable": (viewer.replace("this.playing = false;", "this.playing = true;"), r"paused, two screenshots a second apart differ|did not pause"),
        "scrubber": (viewer.replace("this.seek(t0 + (t1 - t0) * scrub.value / 1000);", ""), r"a click at 3/4 of the scrubber"),
        "blank": (viewer.replace("this.renderer.render(this.scene, this.camera);", ""), r"the canvas is blank"),
        "no-three": (viewer, r"did not start|browser error|uncaught exception"),
        "dropped": (viewer, r"the book has 1 motion viewer\(s\); the chapters' sources mark 2"),
    }
    lines, missed = [], []
    for name, (script, expect) in broken.items():
        if name != "sound" and script == viewer and name not in ("no-three", "dropped"):
            missed.append("%s: motion_viewer.js no longer has the line this self-test breaks" % name)
            continue
        book = os.path.join(work, name)
        os.makedirs(book)
        shutil.copy(os.path.join(HERE, "..", "web", "book.css"), book)
        if name != "no-three":
            shutil.copy(THREE, book)
        with open(os.path.join(book, "motion_viewer.js"), "w", encoding="utf-8") as f:
            f.write(script)
        with open(os.path.join(book, "page.html"), "w", encoding="utf-8") as f:
            f.write('<!DOCTYPE html><html><head><meta charset="utf-8"><title>%s</title><link rel="stylesheet" href="book.css">'
                    '<script src="three.min.js" defer></script><script src="motion_viewer.js" defer></script></head>'
                    '<body><main><figure class="motion"><script type="application/json" class="motion-data">%s</script>'
                    '<figcaption>Motion</figcaption></figure></main></body></html>' % (name, json.dumps(motion)))
        with open(os.path.join(book, "pages.txt"), "w") as f:
            f.write("page.html\tpage\t%s\n" % name)
        # "dropped": a sound viewer, but the chapters mark two (the renderer lost one).
        out, ok = check_book(exe, book, os.path.join(work, name + "-scratch"), 2 if name == "dropped" else None)
        lines += ["[%s] %s" % (name, l) for l in out]
        text = "\n".join(out)
        if expect is None:
            if not ok:
                missed.append("sound: the sound viewer failed a check")
        elif ok or not re.search(expect, text):
            missed.append("%s: expected a failure /%s/" % (name, expect))
    return lines, missed


def main(argv):
    exe = find_browser()
    if not exe:
        print("No Chromium here: install it (sudo apt-get install chromium) or run cmake/workbook test, which does.")
        return 1 if os.environ.get("CI") == "true" else 77
    if not os.path.exists(THREE):
        print("No three.js: %s is missing (Debian: sudo apt-get install libjs-three)" % THREE)
        return 1
    if len(argv) == 3 and argv[1] == "--selftest":
        lines, missed = selftest(exe, os.path.abspath(argv[2]))
        print("\n".join(lines))
        if missed:
            print("The motion checks missed damage done on purpose:\n  " + "\n  ".join(missed))
            return 1
        print("The motion checks pass a sound viewer and fail each viewer broken on purpose.")
        return 0
    expect = None
    if len(argv) >= 3 and argv[1] == "--expect":
        expect, argv = int(argv[2]), argv[:1] + argv[3:]
    if len(argv) not in (2, 3):
        print(__doc__)
        return 2
    book = os.path.abspath(argv[1])
    work = os.path.abspath(argv[2]) if len(argv) == 3 else tempfile.mkdtemp(prefix="motion-check.")
    lines, ok = check_book(exe, book, work, expect)
    print("\n".join(lines))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
