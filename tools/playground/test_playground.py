#!/usr/bin/env python3
"""Opens the built playground page from file:// in headless Chromium and uses it as a learner
would: drags a vertex with the mouse, types a coordinate, moves a vertex by 1/256 pixel with the
keyboard, picks every triangle algorithm and several presets. For each, the write counts the page
reports must equal those `raster --counts` writes for the scene the page shows (and the oracle's
those of `raster --algo exact_oracle`). Typing NaN, a word or a huge value must show a message and
draw nothing, and the page must log no error.

    test_playground.py PAGE --raster RASTER [--chromium PATH] [--screenshot FILE] [--timeout S]

Exit status: 0 when every check passed, 1 when one failed, 2 when the page could not be tested.
"""

import argparse
import base64
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "tests" / "site_check"))
from chromium_pipe import BrowserError, Chromium, Deadline  # noqa: E402

# The scene colours of the two triangles (playground_api.cpp), as the page fills them.
FILL_RGB = [(230, 159, 0), (86, 180, 233)]
VIEWPORT = {"width": 1400, "height": 1500, "deviceScaleFactor": 1, "mobile": False}


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def read_pgm_bottom_row_first(data):
    """The pixels of a binary PGM (maxval 255, or 65535 with two bytes a pixel, big-endian),
    bottom row first as the page reports them."""
    fields = []
    position = 0
    while len(fields) < 4:
        while data[position:position + 1].isspace():
            position += 1
        start = position
        while not data[position:position + 1].isspace():
            position += 1
        fields.append(data[start:position].decode())
    position += 1
    magic, width, height, maxval = fields[0], int(fields[1]), int(fields[2]), int(fields[3])
    if magic != "P5" or maxval not in (255, 65535):
        raise Failure(f"raster wrote an unexpected PGM header: {fields}")
    size = 1 if maxval == 255 else 2
    raw = data[position:position + width * height * size]
    pixels = list(raw) if size == 1 else [
        (raw[i] << 8) | raw[i + 1] for i in range(0, len(raw), 2)]
    rows = [pixels[y * width:(y + 1) * width] for y in range(height)]
    return width, height, [value for row in reversed(rows) for value in row]


class Page:
    def __init__(self, browser):
        self.browser = browser

    def js(self, expression):
        return self.browser.evaluate(expression)

    def state(self):
        return self.js("window.playground.state()")

    def mouse(self, kind, x, y, buttons):
        self.browser.call("Input.dispatchMouseEvent", {
            "type": kind, "x": x, "y": y, "button": "left", "buttons": buttons,
            "clickCount": 1 if kind != "mouseMoved" else 0})

    def drag(self, start, end, steps=6):
        self.mouse("mouseMoved", start[0], start[1], 0)
        self.mouse("mousePressed", start[0], start[1], 1)
        for i in range(1, steps + 1):
            self.mouse("mouseMoved", start[0] + (end[0] - start[0]) * i / steps,
                       start[1] + (end[1] - start[1]) * i / steps, 1)
        self.mouse("mouseReleased", end[0], end[1], 0)

    def type_into(self, element_id, text):
        """Focuses a field, selects its text and types over it, as a keyboard would."""
        self.js(f"(() => {{ const f = document.getElementById({json.dumps(element_id)}); "
                "f.focus(); f.select(); })()")
        self.browser.call("Input.insertText", {"text": text})

    def key(self, key, code, key_code, shift=False):
        for kind in ("rawKeyDown", "keyUp"):
            self.browser.call("Input.dispatchKeyEvent", {
                "type": kind, "key": key, "code": code, "windowsVirtualKeyCode": key_code,
                "modifiers": 8 if shift else 0})

    def select(self, element_id, value):
        self.js(f"(() => {{ const s = document.getElementById({json.dumps(element_id)}); "
                f"s.value = {json.dumps(value)}; "
                "s.dispatchEvent(new Event('change', {bubbles: true})); })()")

    def filled_pixels(self):
        """Screen pixels of both grids painted exactly in a triangle's fill colour."""
        return self.js("""(() => {
          let n = 0;
          for (const id of ['pg-canvas-algorithm', 'pg-canvas-oracle']) {
            const c = document.getElementById(id);
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            for (let i = 0; i < d.length; i += 4) {
              if ((d[i] === 230 && d[i + 1] === 159 && d[i + 2] === 0) ||
                  (d[i] === 86 && d[i + 1] === 180 && d[i + 2] === 233)) ++n;
            }
          }
          return n;
        })()""")

    def message(self):
        return self.js("(() => { const m = document.getElementById('pg-message'); "
                       "return {shown: !m.hidden && m.offsetParent !== null, "
                       "text: m.textContent}; })()")


def raster_counts(raster, algorithm, scene_text, work, option="--counts"):
    """What `raster --algo ALGORITHM --scene S --counts F` (or --coverage) writes."""
    scene = work / "playground.scene"
    pgm = work / "playground.pgm"
    scene.write_text(scene_text, encoding="utf-8")
    run = subprocess.run([str(raster), "--algo", algorithm, "--scene", str(scene),
                          option, str(pgm)], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        raise Failure(f"raster --algo {algorithm} failed on the page's scene:\n{scene_text}\n"
                      f"{run.stderr}")
    return read_pgm_bottom_row_first(pgm.read_bytes())


def compare_with_raster(page, raster, work, label):
    """Every algorithm on the page's current scene against raster: write counts against
    --counts, a coverage algorithm's 16-bit values against --coverage. Returns the chapters
    checked."""
    chapters = set()
    compared = 0
    refused_area = 0
    for algorithm in page.state()["algorithms"]:
        name = algorithm["name"]
        area = algorithm["rule"] == "area"
        page.select("pg-algorithm", name)
        state = page.state()
        check(state["algorithm"] == name, f"the page did not switch to {name}")
        check(f"--{'coverage' if area else 'counts'} playground.pgm" in state["command"],
              f"{label}: the command line for {name} is {state['command']!r}")
        if area and not state["drawn"] and "exact area: a vertex lies beyond" in state["error"]:
            refused_area += 1  # chapter 09's truth is exact within ±32768 pixels only
            continue
        check(state["drawn"], f"{label}: {name} drew nothing: {state['error']}")
        option = "--coverage" if area else "--counts"
        width, height, values = raster_counts(raster, name, state["scene"], work, option)
        check((width, height) == (state["width"], state["height"]),
              f"{label}: raster's canvas is {width}x{height}, the page's "
              f"{state['width']}x{state['height']}")
        page_values = state["coverage"] if area else [min(c, 255) for c in state["counts"]]
        differing = [i for i, (a, b) in enumerate(zip(page_values, values)) if a != b]
        if differing:
            raise Failure(f"{label}: {name}: {len(differing)} pixels differ from raster "
                          f"{option}, the first at ({differing[0] % width}, "
                          f"{differing[0] // width}); scene:\n{state['scene']}")
        chapters.add(algorithm["chapter"][:2])
        compared += 1
    # The oracle the page draws beside them is the registry's exact_oracle, pixel for pixel.
    page.select("pg-algorithm", "exact_oracle")
    state = page.state()
    _, _, oracle = raster_counts(raster, "exact_oracle", state["scene"], work)
    check([min(c, 255) for c in state["oracleCounts"]] == oracle,
          f"{label}: the page's oracle differs from raster --algo exact_oracle")
    note = (f"; {refused_area} coverage algorithms refused, as chapter 09's exact area is "
            "beyond its range" if refused_area else "")
    print(f"  {label}: {compared} algorithms equal raster ({sum(1 for c in oracle if c)} "
          f"pixels covered){note}")
    return chapters


def poll(read, done, seconds=5.0, interval=0.1):
    """read() until done(value) or `seconds` pass; the last value either way."""
    end = time.monotonic() + seconds
    value = read()
    while not done(value) and time.monotonic() < end:
        time.sleep(interval)
        value = read()
    return value


def stable_handle_position(page):
    """Vertex A's handle once two reads in a row agree: the page's layout has settled."""
    previous = page.js("window.playground.handlePosition(0)")
    end = time.monotonic() + 5.0
    while time.monotonic() < end:
        time.sleep(0.2)
        current = page.js("window.playground.handlePosition(0)")
        if current == previous:
            return current
        previous = current
    return previous


def run_checks(page, raster, work):
    check(page.js("window.playground.ready") is True,
          "the playground's module is not built (the page says so); build with emscripten")
    state = page.state()
    check(state["drawn"], f"the first preset drew nothing: {state['error']}")
    check(page.filled_pixels() > 0, "the grids show no filled pixel")
    first = state["points"][0]

    # Drag vertex A three cells right and two up: it lands on a pixel centre. The handle is read
    # once the layout has settled (a busy machine may still be placing the page when it is ready),
    # and the state once the page has taken the drag.
    handle = stable_handle_position(page)
    cell = handle["cell"]
    page.drag((handle["x"], handle["y"]), (handle["x"] + 3 * cell + 2, handle["y"] - 2 * cell - 1))
    target = (first["x"] + 3, first["y"] + 2)
    moved = poll(lambda: page.state()["points"][0],
                 lambda point: (point["x"], point["y"]) == target)
    check((moved["x"], moved["y"]) == (first["x"] + 3, first["y"] + 2),
          f"dragging A by (+3, +2) cells left it at ({moved['x']}, {moved['y']})")
    print(f"  dragged A from ({first['x']}, {first['y']}) to ({moved['x']}, {moved['y']})")

    # Type another vertex's coordinates, then move it 1/256 pixel with Shift+arrow.
    page.type_into("pg-x3", "17.25")
    page.type_into("pg-y3", "15.5")
    page.js("document.getElementById('pg-canvas-algorithm').focus()")
    page.key("ArrowRight", "ArrowRight", 39, shift=True)
    typed = page.state()["points"][3]
    check((typed["x"], typed["y"]) == (17.25 + 1 / 256, 15.5),
          f"typing D = (17.25, 15.5) and Shift+Right left it at ({typed['x']}, {typed['y']})")
    print(f"  typed D = (17.25, 15.5), Shift+Right moved it to ({typed['x']}, {typed['y']})")

    chapters = compare_with_raster(page, raster, work, "after the drag and the typing")
    presets = page.js("document.getElementById('pg-preset').options.length")
    for preset in range(1, presets):
        page.select("pg-preset", str(preset))
        title = page.js("document.getElementById('pg-preset').selectedOptions[0].textContent")
        chapters |= compare_with_raster(page, raster, work, f"preset '{title}'")
    for chapter in ("03", "04", "05", "06", "07", "08", "09"):
        check(chapter in chapters, f"no algorithm of chapter {chapter} was checked")

    # Chapter 03's steps: the book's arrays for triangle 1, one value per row.
    page.select("pg-preset", "0")
    page.select("pg-algorithm", "gambetta_interpolate_fill")
    page.select("pg-step", "2")
    state = page.state()
    steps = state["steps"]
    check(steps is not None and page.js("!document.getElementById('pg-steps').hidden"),
          "chapter 03's step control is not shown for gambetta_interpolate_fill")
    (x0, y0), _, (x2, y2) = steps["sorted"]
    rows = y2 - y0 + 1
    for name in ("x02", "x012", "x_left", "x_right"):
        check(steps[name]["first"] == y0 and len(steps[name]["values"]) == rows,
              f"chapter 03's {name} does not have one value for each of rows {y0} to {y2}")
    # Interpolate adds its slope once a row, so the last value may be off by rounding.
    check(steps["x02"]["values"][0] == x0 and abs(steps["x02"]["values"][-1] - x2) < 1e-9,
          f"chapter 03's x02 does not run from P0 to P2: {steps['x02']}")
    print(f"  chapter 03's steps: x02, x012, x_left and x_right have {rows} values, rows "
          f"{y0} to {y2}")
    page.select("pg-step", "0")

    # Chapter 04's steps 5 and 6 are its two registered fills: on triangle 1 alone they paint
    # exactly the pixels raster draws for a scene of triangle 1 alone.
    for step, name in ((5, "scanline_two_loops"), (6, "scanline_single_loop")):
        page.select("pg-algorithm", name)
        page.select("pg-step", str(step))
        state = page.state()
        check(state["step"] == step and state["stepPixels"] is not None,
              f"chapter 04's step {step} is not shown for {name}")
        painted = [int(any(state["stepPixels"][4 * k:4 * k + 3]))
                   for k in range(state["width"] * state["height"])]
        canvas_line, first_triangle = state["scene"].splitlines()[1:3]
        _, _, counts = raster_counts(raster, name, f"{canvas_line}\n{first_triangle}\n", work)
        check(painted == [int(c > 0) for c in counts],
              f"chapter 04's step {step} does not paint the pixels of raster --algo {name}")
        print(f"  chapter 04's step {step}: the {sum(painted)} pixels of {name} on triangle 1")
    page.select("pg-step", "0")

    # Bad input: a message, and not one pixel drawn.
    page.select("pg-preset", "0")
    page.select("pg-algorithm", "scanline_two_loops")
    for text, expected in (("NaN", "NaN or infinite"), ("abc", "is not a number"),
                           ("1e12", "outside \u00b12^30"), ("-inf", "NaN or infinite")):
        page.type_into("pg-y1", text)
        state = page.state()
        message = page.message()
        check(message["shown"] and expected in message["text"],
              f"typing {text!r} shows {message}, expected a visible message with {expected!r}")
        check(not state["drawn"] and state["counts"] is None,
              f"typing {text!r} still drew pixels")
        check(page.filled_pixels() == 0, f"typing {text!r} left filled pixels on the grids")
        print(f"  typing {text!r}: \"{message['text']}\", nothing drawn")
    page.type_into("pg-y1", "5")
    check(page.state()["drawn"] and not page.message()["shown"],
          "a valid number after NaN does not draw again")

    # The grid is bounded.
    page.type_into("pg-width", "5000")
    check(not page.state()["drawn"] and page.message()["shown"],
          "a 5000-pixel-wide grid was not refused")
    page.type_into("pg-width", "24")
    check(page.state()["drawn"], "the grid does not draw again at 24 pixels wide")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("page", type=Path, help="the built playground.html")
    parser.add_argument("--raster", type=Path, required=True, help="the raster executable")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--screenshot", type=Path, help="save a screenshot of the page here")
    parser.add_argument("--timeout", type=float, default=240)
    args = parser.parse_args(argv)
    if not args.page.is_file():
        print(f"playground test: no page {args.page} (build the target docs)", file=sys.stderr)
        return 2
    errors = []
    try:
        browser = Chromium(args.chromium, Deadline(args.timeout))
    except BrowserError as error:
        print(f"playground test: {error}", file=sys.stderr)
        return 2
    try:
        browser.open_tab("")
        browser.call("Log.enable")
        browser.call("Emulation.setDeviceMetricsOverride", VIEWPORT)
        browser.load(args.page.resolve().as_uri(), timeout=60)
        page = Page(browser)
        with tempfile.TemporaryDirectory(prefix="playground-test-") as work:
            try:
                run_checks(page, args.raster, Path(work))
            except Failure as failure:
                errors.append(str(failure))
        if args.screenshot:
            page.select("pg-preset", "0")
            page.select("pg-algorithm", "scanline_two_loops")
            height = page.js("document.documentElement.scrollHeight")
            shot = browser.call("Page.captureScreenshot", {
                "format": "png", "captureBeyondViewport": True,
                "clip": {"x": 0, "y": 0, "width": VIEWPORT["width"], "height": height,
                         "scale": 1}})
            args.screenshot.write_bytes(base64.b64decode(shot["data"]))
        for event in browser.take_events("Runtime.exceptionThrown"):
            details = event["params"]["exceptionDetails"]
            errors.append("script error: " + details.get("exception", {}).get(
                "description", details.get("text", "?")))
        for event in browser.take_events("Runtime.consoleAPICalled"):
            if event["params"]["type"] in ("error", "assert"):
                errors.append("console error: " + " ".join(
                    str(arg.get("value", arg.get("description", "")))
                    for arg in event["params"]["args"]))
        for event in browser.take_events("Log.entryAdded"):
            entry = event["params"]["entry"]
            if entry["level"] == "error":
                errors.append(f"console error ({entry['source']}): {entry['text']}")
    except BrowserError as error:
        print(f"playground test: could not test {args.page}: {error}", file=sys.stderr)
        return 2
    finally:
        browser.close()
    for error in errors:
        print(f"  problem: {error}")
    print("playground test: " + ("FAILED" if errors else "passed"))
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
