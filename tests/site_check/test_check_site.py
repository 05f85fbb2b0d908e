"""The checker proven on tiny sites: a correct one passes, and each single fault makes it fail
with a message that names the fault. Every case runs the real checker in real headless Chromium.

    python3 -m unittest test_check_site        (SITE_CHECK_CHROMIUM=/path picks the browser)
"""

import os
import struct
import subprocess
import sys
import tempfile
import unittest
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
CHECKER = HERE / "check_site.py"
CHAPTERS = (1, 2, 3, 10)  # a gap, as while chapters 04-09 are being written; 10 needs the plot


def one_pixel_png():
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", 1, 1, 8, 2, 0, 0, 0)  # 1x1, 8-bit RGB
    pixels = zlib.compress(b"\x00\xff\x00\x00")
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", pixels) +
            chunk(b"IEND", b""))


PLOT_SVG = ('<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20" viewBox="0 0 40 20">'
            '<rect width="40" height="20" fill="teal"/></svg>')

# Renders the visible tree from NAVTREE after the document is ready, as Doxygen's navtree.js does.
NAVTREE_JS = """
document.addEventListener('DOMContentLoaded', () => {
  const list = document.getElementById('nav-tree-contents');
  for (const [title, href] of NAVTREE[0][2]) {
    const link = document.createElement('a');
    link.href = href;
    link.textContent = title;
    list.appendChild(link);
  }
});
"""


def page(title, body, head=""):
    return (f'<!DOCTYPE html><html><head><meta charset="utf-8"><title>{title}</title>'
            f'<script src="navtreedata.js"></script><script src="navtree.js"></script>{head}'
            f'</head><body><div id="nav-tree"><div id="nav-tree-contents"></div></div>'
            f'<div class="contents">{body}</div>{FOOTER}</body></html>')


# Doxygen's footer shows an SVG logo on every page: it is not a chapter's diagram.
FOOTER = '<div class="footer"><img src="logo.svg" alt="doxygen"></div>'



def chapter_body(number, previous, following):
    links = []
    if previous:
        links.append(f'<a href="chapter{previous:02d}.html">\u2190 {previous:02d} Before</a>')
    if following:
        links.append(f'<a href="chapter{following:02d}.html">{following:02d} After \u2192</a>')
    separator = " \u00b7 "
    return (f'<h1>Chapter {number:02d}</h1><p>{separator.join(links)}</p>'
            f'<p><a href="#step1">to step 1</a> \u00b7 <a href="index.html#map">the map</a></p>'
            f'<h2 id="step1">Step 1</h2><img src="figure_{number:02d}.png" alt="">'
            f'{SHELL_FRAGMENT}{CPP_FRAGMENT}{diagram(number)}')


# A chapter's code listing as Doxygen writes it (C++ is highlighted), and a shell command (plain).
CPP_FRAGMENT = ('<div class="fragment"><div class="line"><span class="keywordtype">int</span> '
                'step = 1;</div></div>')
SHELL_FRAGMENT = '<div class="fragment"><div class="line">./tutorial.sh run</div></div>'


def diagram(number):
    """A chapter's SVG diagram: chapter 01 as an <img>, the others as Doxygen's <object>."""
    if number == 1:
        return '<img src="diagram_01.svg" alt="">'
    return f'<object type="image/svg+xml" data="diagram_{number:02d}.svg"></object>'


def correct_site(chapters=CHAPTERS):
    """File name -> content of a small site that satisfies every rule."""
    entries = [f'["Chapter {n:02d}", "chapter{n:02d}.html", null]' for n in chapters]
    entries.append('["Hard cases", "hard_cases.html", null]')
    chapter_map = "".join(f'<li><a href="chapter{n:02d}.html">{n:02d}</a></li>' for n in chapters)
    plot = '<object type="image/svg+xml" data="10_speed_vs_error.svg"></object>'
    files = {
        "navtreedata.js": f'var NAVTREE = [["Site", "index.html", [{", ".join(entries)}]]];',
        "navtree.js": NAVTREE_JS,
        "index.html": page("Main", f'<h2 id="map">Chapter map</h2><ul>{chapter_map}</ul>'
                           f'<img src="cover.png" alt="">{plot if 10 in chapters else ""}'),
        "hard_cases.html": page("Hard cases", '<p><a href="chapter01.html">01</a></p>'),
        "cover.png": one_pixel_png(),
        "10_speed_vs_error.svg": PLOT_SVG,
        "logo.svg": PLOT_SVG,
    }
    for index, number in enumerate(chapters):
        previous = chapters[index - 1] if index > 0 else None
        following = chapters[index + 1] if index + 1 < len(chapters) else None
        files[f"chapter{number:02d}.html"] = page(f"Chapter {number:02d}",
                                                  chapter_body(number, previous, following))
        files[f"figure_{number:02d}.png"] = one_pixel_png()
        files[f"diagram_{number:02d}.svg"] = PLOT_SVG
    return files


def replaced(files, name, old, new):
    assert old in files[name], f"{old!r} is not in {name}"
    return {**files, name: files[name].replace(old, new)}


class CheckerTest(unittest.TestCase):
    def run_checker(self, files, chapter_folders=()):
        with tempfile.TemporaryDirectory(prefix="site-check-test-") as folder:
            html = Path(folder, "html")
            html.mkdir()
            for name, content in files.items():
                data = content if isinstance(content, bytes) else content.encode()
                (html / name).write_bytes(data)
            command = [sys.executable, "-B", str(CHECKER), str(html), "--timeout", "60"]
            if chapter_folders:
                for name in chapter_folders:
                    Path(folder, "chapters", name).mkdir(parents=True)
                    Path(folder, "chapters", name, "README.md").write_text("# A chapter\n")
                command += ["--chapters-dir", str(Path(folder, "chapters"))]
            if os.environ.get("SITE_CHECK_CHROMIUM"):
                command += ["--chromium", os.environ["SITE_CHECK_CHROMIUM"]]
            result = subprocess.run(command, capture_output=True, text=True, timeout=120)
            return result.returncode, result.stdout + result.stderr

    def assert_edit_fails_with(self, edit, *expected):
        """The correct site with one text replaced, edit = (file, old, new), fails with exactly
        the expected problems."""
        self.assert_fails_with(replaced(correct_site(), *edit), *expected)

    def assert_fails_with(self, files, *expected, chapter_folders=()):
        status, output = self.run_checker(files, chapter_folders)
        self.assertEqual(status, 1, output)
        for text in expected:
            self.assertIn(text, output)
        # Only the injected fault is reported: the rest of the site is still correct.
        self.assertEqual(output.count("problem:"), len(expected), output)

    def test_a_correct_site_passes(self):
        status, output = self.run_checker(correct_site(),
                                          ("01_a", "02_b", "03_c", "10_d", "notes"))
        self.assertEqual(status, 0, output)
        self.assertIn("6 pages opened (4 chapters: 01, 02, 03, 10)", output)
        self.assertIn("site check: passed", output)

    def test_an_image_file_that_is_missing_fails(self):
        self.assert_edit_fails_with(
            ("chapter02.html", "figure_02.png", "missing.png"),
            "chapter02.html: image does not load: http",
            "chapter02.html: the server answered 404 for /missing.png")

    def test_an_image_file_that_is_not_an_image_fails(self):
        files = {**correct_site(), "figure_03.png": b"this is not a PNG"}
        self.assert_fails_with(files, "chapter03.html: image does not load: http")

    def test_an_embedded_svg_that_is_missing_fails(self):
        files = dict(correct_site())
        del files["10_speed_vs_error.svg"]
        self.assert_fails_with(files, "index.html: embedded figure does not load",
                               "index.html: the server answered 404 for /10_speed_vs_error.svg")

    def test_a_link_to_a_missing_page_fails(self):
        self.assert_edit_fails_with(
            ("chapter01.html", 'href="index.html#map"', 'href="chapter_missing.html"'),
            'chapter01.html: broken link to chapter_missing.html ("the map")')

    def test_a_link_to_a_missing_anchor_fails(self):
        self.assert_edit_fails_with(
            ("chapter02.html", 'href="#step1"', 'href="#step9"'),
            "chapter02.html: broken link to chapter02.html#step9, "
            'no such anchor ("to step 1")')

    def test_a_broken_link_on_the_design_page_fails(self):
        files = {**correct_site(), "design.html": page(
            "Design", '<p><a href="chapter01.html#step9">step 9</a></p>')}
        self.assert_fails_with(files, "design.html: broken link to chapter01.html#step9, "
                               'no such anchor ("step 9")')

    def test_a_chapter_missing_from_the_navigation_tree_fails(self):
        self.assert_edit_fails_with(
            ("navtreedata.js", '["Chapter 02", "chapter02.html", null], ', ""),
            "navigation tree: chapter02.html is missing")

    def test_a_navigation_tree_out_of_chapter_order_fails(self):
        first, second = ('["Chapter 01", "chapter01.html", null]',
                         '["Chapter 02", "chapter02.html", null]')
        self.assert_edit_fails_with(
            ("navtreedata.js", f"{first}, {second}", f"{second}, {first}"),
            "navigation tree: the chapters are out of order: 02, 01, 03, 10")

    def test_a_broken_link_in_the_navigation_tree_fails(self):
        self.assert_edit_fails_with(
            ("navtreedata.js", '"hard_cases.html"', '"hard_case.html"'),
            "navigation tree: hard_cases.html is missing",
            'navigation tree: broken link to hard_case.html ("Hard cases")')

    def test_a_navigation_tree_that_its_script_does_not_show_fails(self):
        self.assert_edit_fails_with(
            ("navtree.js", "of NAVTREE[0][2]) {", "of NAVTREE[0][2].slice(1)) {"),
            *(f"{name}: the visible navigation tree does not show chapter01.html"
              for name in ("index.html", "hard_cases.html", "chapter01.html", "chapter02.html",
                           "chapter03.html", "chapter10.html")))

    def test_a_missing_link_to_the_previous_chapter_fails(self):
        self.assert_edit_fails_with(
            ("chapter03.html", "\u2190 02", "02"),
            "chapter03.html: no link to the previous chapter chapter02.html")

    def test_a_next_link_to_the_wrong_chapter_fails(self):
        self.assert_edit_fails_with(
            ("chapter02.html", 'href="chapter03.html"', 'href="chapter10.html"'),
            "chapter02.html: the next-chapter link leads to chapter10.html, expected "
            "chapter03.html", "chapter02.html: no link to the next chapter chapter03.html")

    def test_a_chapter_without_a_cpp_listing_fails(self):
        self.assert_edit_fails_with(
            ("chapter02.html", CPP_FRAGMENT, ""),
            "chapter02.html: no C++ code listing")

    def test_a_chapter_whose_only_listing_is_a_shell_command_fails(self):
        self.assert_edit_fails_with(
            ("chapter03.html", CPP_FRAGMENT, SHELL_FRAGMENT),
            "chapter03.html: no C++ code listing")

    def test_a_chapter_without_an_svg_diagram_fails(self):
        self.assert_edit_fails_with(
            ("chapter10.html", diagram(10), ""),
            "chapter10.html: no SVG diagram that loaded")

    def test_a_chapter_whose_svg_diagram_does_not_load_fails(self):
        files = {**correct_site(), "diagram_01.svg": "this is not an SVG"}
        self.assert_fails_with(files, "chapter01.html: image does not load: http",
                               "chapter01.html: no SVG diagram that loaded")

    def test_a_chapter_map_without_a_chapter_fails(self):
        self.assert_edit_fails_with(
            ("index.html", '<li><a href="chapter03.html">03</a></li>', ""),
            "index.html: the chapter map does not link chapter03.html")

    def test_a_main_page_without_the_speed_plot_fails_once_chapter_10_exists(self):
        self.assert_edit_fails_with(
            ("index.html",
             '<object type="image/svg+xml" data="10_speed_vs_error.svg"></object>', ""),
            "index.html: chapter 10 exists but the main page does not "
            "show 10_speed_vs_error.svg")

    def test_the_speed_plot_is_not_required_before_chapter_10_exists(self):
        status, output = self.run_checker(correct_site(chapters=(1, 2)))
        self.assertEqual(status, 0, output)

    def test_a_chapter_readme_without_its_page_fails(self):
        self.assert_fails_with(correct_site(), "chapter 04 (04_d/README.md) has no page "
                               "chapter04.html", chapter_folders=("01_a", "02_b", "03_c", "04_d"))

    def test_a_script_error_fails(self):
        self.assert_edit_fails_with(
            ("hard_cases.html", "</body>", "<script>undefined_function();</script></body>"),
            "hard_cases.html: script error: ReferenceError: "
            "undefined_function is not defined")

    def test_a_missing_stylesheet_fails(self):
        self.assert_edit_fails_with(
            ("chapter01.html", "</head>", '<link rel="stylesheet" href="missing.css"></head>'),
            "chapter01.html: the server answered 404 for /missing.css")

    def test_a_site_without_a_main_page_cannot_be_checked(self):
        files = dict(correct_site())
        del files["index.html"]
        status, output = self.run_checker(files)
        self.assertEqual(status, 2, output)
        self.assertIn("no index.html", output)


if __name__ == "__main__":
    unittest.main()
