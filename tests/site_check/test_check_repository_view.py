"""The repository-view check proven on small trees: a correct one passes, and each single fault
makes it fail with a message that names the fault.

    python3 -B -m unittest test_check_repository_view
"""

import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
CHECKER = HERE / "check_repository_view.py"

# Doxygen syntax hidden in comments, in code and in inline code is fine; so are links that work.
CORRECT = {
    "README.md": """# Top <!-- doxygen: {#contents} -->

[Chapter 01](chapters/01_one/README.md) · [its first step](chapters/01_one/README.md#step-1--a-start)
![figure](docs/figures/a.svg) [a folder](chapters/01_one) [web](https://example.org/x.md#nowhere)
""",
    "chapters/01_one/README.md": """# Chapter 01 · One <!-- doxygen: {#chapter01} -->

Back to [the top](../../README.md), on to [Step 1](#step-1--a-start).
`{#inline}` and `@ref inline` are code.

<!-- doxygen: \\htmlinclude body.html -->
<!--
a comment over lines: @ref hidden
-->

## Step 1 · A start

```md
# Shown as code {#code} with @ref code and \\htmlinclude code.html [x](missing.md)
```
""",
    "docs/figures/a.svg": "<svg xmlns='http://www.w3.org/2000/svg'/>",
}

# Each fault: the file it changes, the line appended to it, and the message expected.
FAULTS = {
    "heading id": ("chapters/01_one/README.md", "## Step 2 {#chapter01_step2}",
                   "shows a literal {#"),
    "ref": ("README.md", "See [the matrix](@ref hard_cases).", "shows a literal @ref"),
    "htmlinclude": ("README.md", "\\htmlinclude body.html", "shows a literal \\htmlinclude"),
    "missing file": ("README.md", "[Chapter 02](chapters/02_two/README.md)",
                     "leads to a missing file"),
    "missing anchor": ("chapters/01_one/README.md", "[next](#chapter01_next)",
                       "leads to a missing anchor #chapter01_next"),
    "missing anchor elsewhere": ("README.md", "[step](chapters/01_one/README.md#step-1)",
                                 "leads to a missing anchor #step-1"),
}


def write_tree(root, files):
    for relative, text in files.items():
        path = Path(root) / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")


def run_checker(root):
    return subprocess.run([sys.executable, "-B", str(CHECKER), str(root)], capture_output=True,
                          text=True, timeout=60)


class RepositoryViewCheckTest(unittest.TestCase):
    def test_a_correct_tree_passes(self):
        with tempfile.TemporaryDirectory() as root:
            write_tree(root, CORRECT)
            result = run_checker(root)
            self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
            self.assertIn("2 Markdown files checked: passed", result.stdout)

    def test_each_fault_fails_with_its_message_alone(self):
        for fault, (relative, line, message) in FAULTS.items():
            with self.subTest(fault=fault), tempfile.TemporaryDirectory() as root:
                files = dict(CORRECT)
                files[relative] = files[relative] + line + "\n"
                write_tree(root, files)
                result = run_checker(root)
                self.assertEqual(result.returncode, 1, result.stdout + result.stderr)
                problems = [text for text in result.stdout.splitlines() if "problem:" in text]
                self.assertEqual(len(problems), 1, result.stdout)
                self.assertIn(message, problems[0])
                self.assertIn(relative, problems[0])

    def test_a_root_that_is_not_a_folder_is_refused(self):
        self.assertEqual(run_checker(HERE / "no_such_folder").returncode, 2)


if __name__ == "__main__":
    unittest.main()
