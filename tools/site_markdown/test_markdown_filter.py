"""The Markdown filter on small pages: what the repository view reads becomes what Doxygen needs,
and nothing else changes.

    python3 -B -m unittest test_markdown_filter
"""

import tempfile
import unittest
from pathlib import Path

import repository_markdown as md
from markdown_filter import Filter

CHAPTER = """# Chapter 01 · Lines <!-- doxygen: {#chapter01} -->

![a](../../docs/figures/01_star.svg) and ![b](docs/figures/02_joints.png "title")
See [the exact answer](#step-1--the-exact-answer), [the next step](#step-2--dont-stop),
[design](../../docs/DESIGN.md#3-the-canvas) and [chapter 02](../02_second/README.md).
[web](https://example.org/a.md#x) [stays](@ref stays) [no page id](../../notes/README.md)
[file](../../tools/raster_app.cpp) `[code](#step-1--the-exact-answer)` and {text}

## Step 1 · The exact answer

```cpp
## not a heading [x](#step-1--the-exact-answer)
```

## Step 2 · Don't stop

<!-- doxygen: \\htmlinclude body.html -->
<!-- listing: chapters/01_lines/lines.cpp draw_line -->
Written as `<!-- doxygen: {#id} -->` in code, <!-- doxygen: @ref it --> outside.

## Step 2 · Don't stop
"""

DESIGN = """# Design <!-- doxygen: {#design} -->

## 3. The canvas <!-- doxygen: {#design_canvas} -->
"""

SECOND = """# Chapter 02 · Second <!-- doxygen: {#chapter02} -->
"""


class MarkdownFilterTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        root = Path(self.folder.name)
        for relative, text in {"chapters/01_lines/README.md": CHAPTER, "docs/DESIGN.md": DESIGN,
                               "chapters/02_second/README.md": SECOND,
                               "notes/README.md": "# Notes\n\n## A part\n"}.items():
            (root / relative).parent.mkdir(parents=True, exist_ok=True)
            (root / relative).write_text(text, encoding="utf-8")
        self.lines = list(Filter(root / "chapters/01_lines/README.md").lines())

    def tearDown(self):
        self.folder.cleanup()

    def test_line_numbers_stay(self):
        self.assertEqual(len(self.lines), len(CHAPTER.split("\n")))

    def test_the_title_gets_the_hidden_page_id(self):
        self.assertEqual(self.lines[0], "# Chapter 01 · Lines {#chapter01}")

    def test_headings_get_the_page_id_and_githubs_anchor_repeats_numbered(self):
        self.assertEqual(self.lines[8], "## Step 1 · The exact answer {#chapter01_step-1--the-exact-answer}")
        self.assertEqual(self.lines[14], "## Step 2 · Don't stop {#chapter01_step-2--dont-stop}")
        self.assertEqual(self.lines[20], "## Step 2 · Don't stop {#chapter01_step-2--dont-stop-1}")

    def test_figures_lose_their_repository_folder(self):
        self.assertEqual(self.lines[2], '![a](01_star.svg) and ![b](02_joints.png "title")')

    def test_links_to_headings_and_pages_become_references(self):
        self.assertEqual(self.lines[3], "See [the exact answer](@ref chapter01_step-1--the-exact-answer), "
                         "[the next step](@ref chapter01_step-2--dont-stop),")
        self.assertEqual(self.lines[4], "[design](@ref design_canvas) and [chapter 02](@ref chapter02).")

    def test_other_links_code_and_text_stay_as_they_are(self):
        self.assertEqual(self.lines[5], CHAPTER.split("\n")[5])
        self.assertEqual(self.lines[6], CHAPTER.split("\n")[6])
        self.assertEqual(self.lines[10:13], CHAPTER.split("\n")[10:13])

    def test_hidden_commands_are_unwrapped_and_other_comments_kept(self):
        self.assertEqual(self.lines[16], "\\htmlinclude body.html")
        self.assertEqual(self.lines[17], "<!-- listing: chapters/01_lines/lines.cpp draw_line -->")
        self.assertEqual(self.lines[18], "Written as `<!-- doxygen: {#id} -->` in code, @ref it outside.")


class GithubAnchorTest(unittest.TestCase):
    def test_anchors_as_github_makes_them(self):
        self.assertEqual(md.github_anchor("Step 3 · Gambetta's DrawLine"), "step-3--gambettas-drawline")
        self.assertEqual(md.github_anchor("Hard cases × algorithms"), "hard-cases--algorithms")
        self.assertEqual(md.github_anchor("1. What the tutorial is"), "1-what-the-tutorial-is")
        self.assertEqual(md.github_anchor("vertex_far_1e5"), "vertex_far_1e5")
        self.assertEqual(md.github_anchor(md.rendered_text("Step 4 · `fill_lower_half`, *fast*")),
                         "step-4--fill_lower_half-fast")


if __name__ == "__main__":
    unittest.main()
