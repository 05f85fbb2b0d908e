#!/usr/bin/env python3
"""Doxygen's input filter for the Markdown pages (FILTER_PATTERNS in docs/CMakeLists.txt): turns
a README written for the repository view into the Markdown Doxygen needs. Line numbers stay.

- A figure named by its repository path, ![..](../../docs/figures/NAME.svg), becomes NAME.svg:
  Doxygen finds images by bare name in IMAGE_PATH, which holds the rendered figures.
- Every heading gets its site id, {#id}: the id hidden in `<!-- doxygen: {#id} -->` at its end,
  or the page's id, '_' and GitHub's anchor of the heading (repository_markdown.py).
- A link to a heading, [..](#anchor) or [..](other.md#anchor), becomes [..](@ref id), and a link
  to another page, [..](other.md), becomes [..](@ref page_id), when that page names its id.
- `<!-- doxygen: COMMAND -->` becomes COMMAND (for example \\htmlinclude).

    markdown_filter.py FILE      (writes the filtered text to standard output)
"""

import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import repository_markdown as md  # noqa: E402

FIGURE_PATH = re.compile(r"^(\.\./)*docs/figures/")


class Filter:
    def __init__(self, path):
        self.page = md.read_page(path)
        self._pages = {self.page.path.resolve(): self.page}

    def _page_at(self, path):
        path = path.resolve()
        if path not in self._pages:
            self._pages[path] = md.read_page(path) if path.is_file() else None
        return self._pages[path]

    def site_target(self, target):
        """The target as the site needs it, or the target unchanged when the site has no better
        one (an outside address, a page that names no id, an anchor no heading has)."""
        if md.is_external(target) or target.startswith("@ref"):
            return target
        path, anchor = md.split_target(target)
        if path and not path.endswith(".md"):
            return FIGURE_PATH.sub("", target)
        page = self._page_at(self.page.path.parent / path) if path else self.page
        if page is None or page.page_id is None:
            return target
        site_id = page.doxygen_id(anchor) if anchor else page.page_id
        return f"@ref {site_id}" if site_id else target

    def lines(self):
        headings = {heading.line: heading for heading in self.page.headings}
        links_on = {}
        for link in md.links(self.page.text):
            links_on.setdefault(link.line, []).append(link)
        code = {number for number, _ in enumerate(self.page.text.split("\n"), start=1)}
        code -= {number for number, _ in md.prose_lines(self.page.text)}
        for number, line in enumerate(self.page.text.split("\n"), start=1):
            if number in code:
                yield line
                continue
            for link in sorted(links_on.get(number, []), key=lambda link: -link.start):
                line = line[:link.start] + self.site_target(link.target) + line[link.end:]
            heading = headings.get(number)
            if heading:
                line = md.DOXYGEN_COMMENT.sub(
                    lambda match: "" if md.HEADING_ID.match(match.group(1)) else match.group(0),
                    line).rstrip()
                if heading.doxygen_id:
                    line += f" {{#{heading.doxygen_id}}}"
            yield self._unwrapped(line)

    @staticmethod
    def _unwrapped(line):
        """The line with its hidden commands unwrapped, except inside inline code."""
        pieces, done = [], 0
        for code in md.INLINE_CODE.finditer(line):
            pieces += [md.DOXYGEN_COMMENT.sub(r"\1", line[done:code.start()]), code.group(0)]
            done = code.end()
        return "".join(pieces + [md.DOXYGEN_COMMENT.sub(r"\1", line[done:])])


def main(argv):
    if len(argv) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    sys.stdout.write("\n".join(Filter(Path(argv[0])).lines()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
