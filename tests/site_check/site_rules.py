"""What a correct tutorial site is: the rules the checker applies to the facts a browser saw.

Pure functions of the facts gathered by page_facts.js and of the files in the site's folder, so
that every rule reads on its own. Each rule returns a list of problems, one sentence each.
"""

import re
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urljoin, urlsplit

CHAPTER_PAGE = re.compile(r"^chapter(\d{2})\.html$")
CHAPTER_FOLDER = re.compile(r"^(\d{2})_\w+$")
MAIN_PAGE = "index.html"
HARD_CASES_PAGE = "hard_cases.html"
# The other Markdown pages: opened, and their figures and links checked, where the site has them.
OTHER_PAGES = ("design.html", "playground.html", "fuzzing.html", "scorecards.html",
               "scorecards_peers.html")
# The report chapter's plot, which the main page shows once that chapter exists.
SPEED_VS_ERROR_CHAPTER = 10
SPEED_VS_ERROR_PLOT = "10_speed_vs_error.svg"
# A chapter's link whose text starts with an arrow left leads to the previous chapter, one whose
# text ends with an arrow right to the next one.
PREVIOUS_MARK = "\u2190"
NEXT_MARK = "\u2192"
NAVIGATION = "navigation tree"


def chapter_pages(html_dir):
    """The site's chapter pages {number: file name}, found by name (chapterNN.html)."""
    pages = {}
    for path in Path(html_dir).iterdir():
        match = CHAPTER_PAGE.match(path.name)
        if match:
            pages[int(match.group(1))] = path.name
    return dict(sorted(pages.items()))


def source_chapters(chapters_dir):
    """The chapters that have a README.md in the sources {number: folder name}."""
    chapters = {}
    for folder in Path(chapters_dir).iterdir():
        match = CHAPTER_FOLDER.match(folder.name)
        if match and (folder / "README.md").is_file():
            chapters[int(match.group(1))] = folder.name
    return dict(sorted(chapters.items()))


class _Anchors(HTMLParser):
    def __init__(self):
        super().__init__()
        self.names = set()

    def handle_starttag(self, tag, attrs):
        for key, value in attrs:
            if value is not None and (key == "id" or (tag == "a" and key == "name")):
                self.names.add(value)


class Site:
    """The site's folder as the local server publishes it at `root_url`."""

    def __init__(self, html_dir, root_url):
        self.html_dir = Path(html_dir).resolve()
        self.root_url = root_url if root_url.endswith("/") else root_url + "/"
        self._anchors = {}

    def local_path(self, url):
        """The site-relative file a URL names (without its #anchor), or None for a URL outside
        the site."""
        parts, root = urlsplit(url), urlsplit(self.root_url)
        if (parts.scheme, parts.netloc) != (root.scheme, root.netloc):
            return None
        path = unquote(parts.path)
        if not path.startswith(root.path):
            return None
        relative = path[len(root.path):]
        return relative + MAIN_PAGE if relative == "" or relative.endswith("/") else relative

    def page_url(self, name):
        return urljoin(self.root_url, name)

    def exists(self, relative):
        target = (self.html_dir / relative).resolve()
        return target.is_file() and self.html_dir in target.parents

    def anchors(self, relative):
        if relative not in self._anchors:
            parser = _Anchors()
            parser.feed((self.html_dir / relative).read_text(encoding="utf-8", errors="replace"))
            self._anchors[relative] = parser.names
        return self._anchors[relative]


def loading_problems(page, facts):
    """Every image and embedded SVG of the page must have loaded."""
    problems = [f"{page}: image does not load: {image['src']}"
                for image in facts["images"] if not image["loaded"]]
    problems += [f"{page}: embedded figure does not load: {figure['src']}"
                 for figure in facts["objects"] if not figure["loaded"]]
    return problems


def _is_svg(url):
    return urlsplit(url).path.lower().endswith(".svg")


def chapter_content_problems(page, facts):
    """A chapter page shows its code and its geometry: at least one C++ listing (a Doxygen code
    fragment highlighted as C++; shell commands come out plain) and at least one SVG diagram that
    loaded (Doxygen's <object type="image/svg+xml">, or an <img> of an .svg file) in its text."""
    problems = []
    if not any(fragment["cpp"] for fragment in facts["fragments"]):
        problems.append(f"{page}: no C++ code listing (a div.fragment highlighted as C++)")
    # Only the page's text counts: Doxygen's search box and footer logo are SVG images too.
    svgs = [figure for figure in facts["objects"]
            if figure["inContents"] and figure["type"] == "image/svg+xml" and figure["loaded"]]
    svgs += [image for image in facts["images"]
             if image["inContents"] and _is_svg(image["src"]) and image["loaded"]]
    if not svgs:
        problems.append(f"{page}: no SVG diagram that loaded (an <object type=\"image/svg+xml\"> "
                        f"or an <img> of an .svg file)")
    return problems


def link_problems(site, page, facts):
    """Every link of the page's text into the site must name an existing file and, for a page,
    an existing anchor. (The navigation tree is the same on every page: navigation_problems
    checks its links once.)"""
    return _broken_links(site, page, [link for link in facts["links"] if not link["inNavTree"]])


def _broken_links(site, page, links):
    problems = []
    for link in links:
        target = site.local_path(link["href"])
        if target is None:
            continue  # javascript:, mailto:, the outside web: not internal
        if not site.exists(target):
            problems.append(f"{page}: broken link to {target} (\"{link['text']}\")")
            continue
        fragment = unquote(urlsplit(link["href"]).fragment)
        if fragment and target.endswith(".html") and fragment not in site.anchors(target):
            problems.append(f"{page}: broken link to {target}#{fragment}, no such anchor "
                            f"(\"{link['text']}\")")
    return problems


def request_problems(page, failed_requests):
    """Anything the page asked the server for and did not get (scripts, styles, figures)."""
    return [f"{page}: the server answered {status} for {path}" for path, status in failed_requests]


def script_problems(page, exceptions):
    """The page's scripts (Doxygen's tree, search and menus) must run without an exception."""
    return [f"{page}: script error: {text}" for text in exceptions]


def _linked_pages(site, links):
    return [(site.local_path(link["href"]), link) for link in links]


def source_problems(pages, chapters):
    """Every chapter with a README.md in the sources must have its page on the site."""
    return [f"chapter {number:02d} ({folder}/README.md) has no page chapter{number:02d}.html: "
            f"its title must end with <!-- doxygen: {{#chapter{number:02d}}} -->"
            for number, folder in chapters.items() if number not in pages]


def navigation_problems(site, facts, pages):
    """The navigation tree (one navtreedata.js for every page) lists every chapter, in chapter
    order, and the hard-case page; its own links are checked like the pages' links."""
    if facts["navTree"] is None:
        return []  # reported for each page by visible_navigation_problems
    entry_pages = _page_names(site, [urljoin(site.root_url, entry["href"])
                                     for entry in facts["navTree"]])
    problems = [f"{NAVIGATION}: {name} is missing" for name in [*pages.values(), HARD_CASES_PAGE]
                if name not in entry_pages]
    listed = [number for number, name in pages.items() if name in entry_pages]
    in_tree_order = sorted(listed, key=lambda number: entry_pages.index(pages[number]))
    if in_tree_order != listed:
        problems.append(f"{NAVIGATION}: the chapters are out of order: " +
                        ", ".join(f"{number:02d}" for number in in_tree_order))
    return problems + _broken_links(site, NAVIGATION,
                                    [link for link in facts["links"] if link["inNavTree"]])


def visible_navigation_problems(site, page, facts, pages):
    """Each page has the navigation tree, and its scripts show every chapter the tree lists."""
    if facts["navTree"] is None:
        return [f"{page}: no navigation tree (NAVTREE is not defined)"]
    listed = _page_names(site, [urljoin(site.root_url, entry["href"])
                                for entry in facts["navTree"]])
    shown = _page_names(site, [link["href"] for link in facts["links"] if link["inNavTree"]])
    return [f"{page}: the visible navigation tree does not show {name}"
            for name in pages.values() if name in listed and name not in shown]


def _page_names(site, urls):
    return [site.local_path(url) for url in urls]


def main_page_problems(site, facts, pages):
    """The main page's text links every chapter (the chapter map) and shows the speed plot."""
    linked = {target for target, link in _linked_pages(site, facts["links"])
              if target and link["inContents"]}
    problems = [f"{MAIN_PAGE}: the chapter map does not link {name}"
                for name in pages.values() if name not in linked]
    if SPEED_VS_ERROR_CHAPTER in pages:
        figures = [item["src"] for item in facts["images"] + facts["objects"]]
        if not any(urlsplit(src).path.endswith("/" + SPEED_VS_ERROR_PLOT) for src in figures):
            problems.append(f"{MAIN_PAGE}: chapter {SPEED_VS_ERROR_CHAPTER:02d} exists but the "
                            f"main page does not show {SPEED_VS_ERROR_PLOT}")
    return problems


def neighbour_problems(site, pages, facts_of):
    """Each chapter links its previous chapter (text starting with an arrow left) and its next one
    (text ending with an arrow right); such a link may not lead to any other chapter."""
    problems = []
    order = list(pages.values())
    for index, page in enumerate(order):
        wanted = {"previous": order[index - 1] if index > 0 else None,
                  "next": order[index + 1] if index + 1 < len(order) else None}
        found = {"previous": [], "next": []}
        for target, link in _linked_pages(site, facts_of[page]["links"]):
            if not target or not link["inContents"]:
                continue
            if link["text"].startswith(PREVIOUS_MARK):
                found["previous"].append(target)
            if link["text"].endswith(NEXT_MARK):
                found["next"].append(target)
        for direction, targets in found.items():
            want = wanted[direction]
            chapters_linked = [target for target in targets if CHAPTER_PAGE.match(target)]
            problems += [f"{page}: the {direction}-chapter link leads to {target}, expected "
                         f"{want or 'none (no ' + direction + ' chapter)'}"
                         for target in chapters_linked if target != want]
            if want and want not in targets:
                problems.append(f"{page}: no link to the {direction} chapter {want}")
    return problems
