"""The tutorial's Markdown as the repository view (GitHub) reads it: which lines are code, which
text is an HTML comment, what anchor each heading gets, and where each link leads.

The READMEs are written for that view: plain headings and plain links, with anchors as GitHub
makes them from the heading's text. What only Doxygen needs sits in an HTML comment that the
repository view hides: `<!-- doxygen: {#chapter01} -->` at the end of a heading names its page or
section for the site, `<!-- doxygen: \\htmlinclude file.html -->` on a line of its own is a
command. The site's Markdown filter (markdown_filter.py) unwraps those comments and turns the
links into Doxygen references; the repository-view check (tests/site_check) reads the same
structure. One module, so the two cannot disagree about an anchor.
"""

import re
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
HEADING = re.compile(r"^ {0,3}(#{1,6})[ \t]+(.*?)[ \t]*$")
# A Doxygen-only command hidden from the repository view in an HTML comment.
DOXYGEN_COMMENT = re.compile(r"<!--\s*doxygen:\s*(.*?)\s*-->")
HEADING_ID = re.compile(r"^\{#([A-Za-z_][\w-]*)\}$")
COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)
INLINE_CODE = re.compile(r"(`+)(.+?)\1")
# An inline link or image: [text](target "title"); link text may hold one level of brackets.
LINK = re.compile(r"(!?)\[((?:[^\[\]]|\[[^\]]*\])*)\]\(\s*(<[^>]*>|[^\s)]+)(\s+\"[^\"]*\")?\s*\)")
EXTERNAL = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")  # https:, mailto:, ...


def github_anchor(text):
    """The anchor GitHub gives a heading with this rendered text: lower case, every character
    that is not a letter, mark, digit, connector (such as '_'), space or hyphen dropped, each
    space a hyphen."""
    kept = []
    for character in text.strip().lower():
        category = unicodedata.category(character)
        if character in " -" or category[0] in "LMN" or category == "Pc":
            kept.append("-" if character == " " else character)
    return "".join(kept)


def rendered_text(markdown):
    """The text a heading shows: without HTML comments, code backticks, link targets and
    emphasis marks (underscores inside words stay, as they do on GitHub)."""
    text = COMMENT.sub("", markdown)
    text = INLINE_CODE.sub(lambda match: match.group(2).strip(), text)
    text = LINK.sub(lambda match: match.group(2), text)
    text = re.sub(r"\*+|(?<!\w)_+|_+(?!\w)", "", text)
    return re.sub(r"<[^>]+>", "", text).strip()


def prose_lines(text):
    """(line number from 1, line) for every line outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.split("\n"), start=1):
        match = FENCE.match(line)
        if fence:
            if match and match.group(1)[0] == fence[0] and len(match.group(1)) >= len(fence):
                fence = None
            continue
        if match:
            fence = match.group(1)
            continue
        yield number, line


def visible_text(line):
    """A prose line as the reader sees its characters: inline code and HTML comments blanked
    (multi-line comments are blanked by without_comments first)."""
    line = INLINE_CODE.sub(lambda match: " " * len(match.group(0)), line)
    return COMMENT.sub(lambda match: " " * len(match.group(0)), line)


def without_comments(text):
    """The text with every HTML comment replaced by spaces (its newlines kept), so that line
    numbers and columns stay."""
    return COMMENT.sub(lambda match: re.sub(r"[^\n]", " ", match.group(0)), text)


@dataclass
class Heading:
    line: int
    level: int
    text: str         # as written, the hidden id removed
    anchor: str       # GitHub's anchor
    doxygen_id: str   # the id the site gives it


@dataclass
class Link:
    line: int
    image: bool
    text: str
    target: str
    start: int        # the target's span within the line
    end: int


@dataclass
class Page:
    path: Path
    text: str
    headings: list = field(default_factory=list)

    @property
    def page_id(self):
        return self.headings[0].doxygen_id if self.headings else None

    def doxygen_id(self, anchor):
        """The site's id of the heading GitHub calls `anchor`, or None."""
        for heading in self.headings:
            if heading.anchor == anchor:
                return heading.doxygen_id
        return None


def read_page(path):
    """The Markdown file with its headings: each gets GitHub's anchor (repeats numbered -1, -2,
    ... as GitHub does) and a site id. A heading's hidden id wins; the page title's hidden id is
    the page's id; any other heading's id is the page's id, '_' and its anchor, with what Doxygen
    does not accept in an id turned into '_'."""
    path = Path(path)
    text = path.read_text(encoding="utf-8")
    page = Page(path, text)
    seen = {}
    for number, line in prose_lines(text):
        match = HEADING.match(line)
        if not match:
            continue
        written = re.sub(r"[ \t]+#+$", "", match.group(2))  # a closing sequence of #
        hidden = None
        for command in DOXYGEN_COMMENT.finditer(written):
            id_match = HEADING_ID.match(command.group(1))
            if id_match:
                hidden = id_match.group(1)
        written = DOXYGEN_COMMENT.sub("", written).strip()
        anchor = github_anchor(rendered_text(written))
        count = seen.get(anchor, 0)
        seen[anchor] = count + 1
        if count:
            anchor = f"{anchor}-{count}"
        if hidden is None and page.headings and page.page_id:
            hidden = page.page_id + "_" + re.sub(r"[^A-Za-z0-9_-]", "_", anchor)
        page.headings.append(Heading(number, len(match.group(1)), written, anchor, hidden))
    return page


def links(text):
    """Every inline link and image outside code blocks, inline code and HTML comments."""
    found = []
    for number, line in prose_lines(without_comments(text)):
        for match in LINK.finditer(visible_text(line)):
            target = match.group(3)
            start, end = match.span(3)
            if target.startswith("<") and target.endswith(">"):
                target, start, end = target[1:-1], start + 1, end - 1
            found.append(Link(number, match.group(1) == "!", match.group(2), target, start, end))
    return found


def split_target(target):
    """(path, anchor) of a link target; either may be empty."""
    path, _, anchor = target.partition("#")
    return path, anchor


def is_external(target):
    return bool(EXTERNAL.match(target))
