#!/usr/bin/env python3
"""Opens the tutorial's Doxygen site in headless Chromium the way a reader would and fails on
what a reader would trip over: a figure that does not load, a link into the site that leads
nowhere, a chapter missing from the navigation or out of order, a chapter without links to its
neighbours, a chapter without a C++ listing or an SVG diagram, a main page without the chapter
map or the speed-vs-error plot.

    check_site.py HTML_DIR [--chapters-dir DIR] [--chromium PATH] [--timeout SECONDS]

The site is served by a local HTTP server bound to 127.0.0.1 only; Chromium may reach nothing
else. Exit status: 0 when the site is correct, 1 when it has problems, 2 when it could not be
checked (no Chromium, no site, time budget exhausted).
"""

import argparse
import functools
import http.server
import shutil
import signal
import sys
import threading
from pathlib import Path

import site_rules
from chromium_pipe import BrowserError, Chromium, Deadline

HERE = Path(__file__).resolve().parent
CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")
PAGE_TIMEOUT_S = 30


class _Handler(http.server.SimpleHTTPRequestHandler):
    """Serves the site's folder and remembers every request it could not answer."""

    def log_request(self, code="-", size="-"):
        if isinstance(code, int) and code >= 400 and not self.path.endswith("/favicon.ico"):
            self.server.failed_requests.append((self.path, code))

    def log_message(self, *args):
        pass  # quiet: failures are reported through failed_requests


def serve(html_dir):
    handler = functools.partial(_Handler, directory=str(html_dir))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    server.daemon_threads = True
    server.failed_requests = []
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def exception_text(details):
    """The message of an uncaught exception as DevTools reports it (e.g. "ReferenceError: ...")."""
    return details.get("exception", {}).get("description") or details.get("text", "?")


def visit(browser, server, url, facts_script):
    """Loads one page and returns its facts, with its script errors and failed requests."""
    server.failed_requests.clear()
    browser.load(url, timeout=PAGE_TIMEOUT_S)
    facts = browser.evaluate(facts_script, timeout=PAGE_TIMEOUT_S)
    facts["exceptions"] = [exception_text(event["params"]["exceptionDetails"])
                           for event in browser.take_events("Runtime.exceptionThrown")]
    facts["failedRequests"] = list(server.failed_requests)
    return facts


def check(html_dir, chapters_dir, chromium, timeout_s):
    """Returns (problems, summary line)."""
    pages = site_rules.chapter_pages(html_dir)
    problems = []
    if not pages:
        problems.append("the site has no chapter page (chapterNN.html)")
    if chapters_dir:
        problems += site_rules.source_problems(pages, site_rules.source_chapters(chapters_dir))
    to_visit = [site_rules.MAIN_PAGE, site_rules.HARD_CASES_PAGE, *pages.values()]
    missing = [name for name in to_visit if not (html_dir / name).is_file()]
    problems += [f"the site has no {name}" for name in missing]
    to_visit = [name for name in to_visit if name not in missing]
    to_visit += [name for name in site_rules.OTHER_PAGES if (html_dir / name).is_file()]

    deadline = Deadline(timeout_s)
    facts_script = (HERE / "page_facts.js").read_text(encoding="utf-8")
    browser = Chromium(chromium, deadline)  # before the server's thread: it forks
    server = None
    try:
        server = serve(html_dir)
        site = site_rules.Site(html_dir, f"http://127.0.0.1:{server.server_address[1]}/")
        browser.open_tab((HERE / "record_failed_loads.js").read_text(encoding="utf-8"))
        facts_of = {name: visit(browser, server, site.page_url(name), facts_script)
                    for name in to_visit}
    finally:
        browser.close()
        if server:
            server.shutdown()
            server.server_close()

    for name, facts in facts_of.items():
        problems += site_rules.loading_problems(name, facts)
        problems += site_rules.link_problems(site, name, facts)
        problems += site_rules.request_problems(name, facts["failedRequests"])
        problems += site_rules.script_problems(name, facts["exceptions"])
        problems += site_rules.visible_navigation_problems(site, name, facts, pages)
        if name in pages.values():
            problems += site_rules.chapter_content_problems(name, facts)
    if site_rules.MAIN_PAGE in facts_of:
        problems += site_rules.navigation_problems(site, facts_of[site_rules.MAIN_PAGE], pages)
        problems += site_rules.main_page_problems(site, facts_of[site_rules.MAIN_PAGE], pages)
    problems += site_rules.neighbour_problems(
        site, {number: name for number, name in pages.items() if name in facts_of}, facts_of)

    problems = list(dict.fromkeys(problems))  # a link repeated on a page is one problem
    images = sum(len(facts["images"]) + len(facts["objects"]) for facts in facts_of.values())
    links = sum(len(facts["links"]) for facts in facts_of.values())
    numbers = ", ".join(f"{number:02d}" for number in pages)
    summary = (f"{len(facts_of)} pages opened ({len(pages)} chapters: {numbers}), "
               f"{images} figures and {links} links checked")
    return problems, summary


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("html_dir", type=Path, help="the folder with the site's index.html")
    parser.add_argument("--chapters-dir", type=Path,
                        help="the sources' chapters/ folder: every NN_name/README.md needs a page")
    parser.add_argument("--chromium", help="the browser (default: the first of %s on PATH)"
                        % ", ".join(CHROMIUM_NAMES))
    parser.add_argument("--timeout", type=float, default=180,
                        help="time budget for the whole check in seconds (default 180)")
    args = parser.parse_args(argv)
    # A terminated check (a CTest timeout) still closes its browser in check()'s finally.
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(2))

    chromium = args.chromium or next(filter(None, map(shutil.which, CHROMIUM_NAMES)), None)
    if not chromium:
        print("site check: no Chromium found (Debian: apt-get install chromium)", file=sys.stderr)
        return 2
    if not (args.html_dir / site_rules.MAIN_PAGE).is_file():
        print(f"site check: no {site_rules.MAIN_PAGE} in {args.html_dir}", file=sys.stderr)
        return 2
    try:
        problems, summary = check(args.html_dir.resolve(), args.chapters_dir, chromium,
                                  args.timeout)
    except BrowserError as error:
        print(f"site check: could not check {args.html_dir}: {error}", file=sys.stderr)
        return 2
    print(f"site check: {summary}")
    for problem in problems:
        print(f"  problem: {problem}")
    print(f"site check: {'FAILED, %d problems' % len(problems) if problems else 'passed'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
