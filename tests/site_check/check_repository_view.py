#!/usr/bin/env python3
"""Checks the Markdown files as the repository view (GitHub) shows them, without a browser:

- no literal `{#`, `@ref` or `\\htmlinclude` a reader would see: outside code blocks, inline code
  and HTML comments (the site's Markdown filter unwraps `<!-- doxygen: ... -->` comments);
- every relative link and image leads to a file or folder that exists, and a link with an anchor
  to a heading that has it, as GitHub makes anchors from a heading's text.

    check_repository_view.py ROOT

Checks every .md file under ROOT outside hidden folders and build/. Exit status: 0 when every
file passes, 1 when one does not, 2 when ROOT is not a folder.
"""

import sys
from pathlib import Path
from urllib.parse import unquote

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "tools" / "site_markdown"))
import repository_markdown as md  # noqa: E402

DOXYGEN_ONLY = ("{#", "@ref", "\\htmlinclude")
SKIPPED_FOLDERS = {"build", "node_modules"}


def markdown_files(root):
    root = Path(root)
    for path in sorted(root.rglob("*.md")):
        parts = path.relative_to(root).parts[:-1]
        if not any(part.startswith(".") or part in SKIPPED_FOLDERS for part in parts):
            yield path


def literal_problems(path, text, name):
    """Doxygen syntax that the repository view would show as text."""
    problems = []
    for number, line in md.prose_lines(md.without_comments(text)):
        visible = md.visible_text(line)
        problems += [f"{name}:{number}: the repository view shows a literal {literal}"
                     for literal in DOXYGEN_ONLY if literal in visible]
    return problems


def link_problems(path, text, name, pages):
    """Relative links to a missing file or folder, or to an anchor no heading has."""
    problems = []
    for link in md.links(text):
        if md.is_external(link.target) or not link.target:
            continue
        target_path, anchor = md.split_target(unquote(link.target))
        target = (path.parent / target_path).resolve() if target_path else path.resolve()
        shown = f"{name}:{link.line}: link [{link.text}]({link.target})"
        if not target.exists():
            problems.append(f"{shown} leads to a missing file")
            continue
        if not anchor or target.suffix != ".md" or target.is_dir():
            continue
        if target not in pages:
            pages[target] = md.read_page(target)
        if anchor not in {heading.anchor for heading in pages[target].headings}:
            problems.append(f"{shown} leads to a missing anchor #{anchor}")
    return problems


def check(root):
    root = Path(root).resolve()
    problems, pages, count = [], {}, 0
    for path in markdown_files(root):
        count += 1
        name = path.relative_to(root).as_posix()
        text = path.read_text(encoding="utf-8")
        problems += literal_problems(path, text, name)
        problems += link_problems(path, text, name, pages)
    return problems, count


def main(argv):
    if len(argv) != 1 or not Path(argv[0]).is_dir():
        print(__doc__, file=sys.stderr)
        return 2
    problems, count = check(argv[0])
    for problem in problems:
        print(f"  problem: {problem}")
    verdict = f"FAILED, {len(problems)} problems" if problems else "passed"
    print(f"repository view: {count} Markdown files checked: {verdict}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
