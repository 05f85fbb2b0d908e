#!/bin/sh
# Checks the Markdown filter (figure_paths.sed): repository paths into docs/figures/ lose their
# folder, every other link stays as it is. Exit status 0 when the filter is right.
set -eu
here=$(dirname "$0")
input='![a](../../docs/figures/01_star.svg) and ![b](docs/figures/02_joints.png)
![c](../docs/figures/x.svg "title") ![d](03_plain.png)
[design](../../docs/DESIGN.md) [site check](../../docs/site_check/README.md) [f](../figures/y.svg)
`docs/figures/` in a code span, and text (docs/figures/z.svg) outside a link'
expected='![a](01_star.svg) and ![b](02_joints.png)
![c](x.svg "title") ![d](03_plain.png)
[design](../../docs/DESIGN.md) [site check](../../docs/site_check/README.md) [f](../figures/y.svg)
`docs/figures/` in a code span, and text (docs/figures/z.svg) outside a link'
actual=$(printf '%s\n' "$input" | sed -f "$here/figure_paths.sed")
if [ "$actual" != "$expected" ]; then
  printf 'figure_paths.sed turned\n%s\ninto\n%s\nexpected\n%s\n' "$input" "$actual" "$expected"
  exit 1
fi
echo "figure_paths.sed: repository figure paths become bare names, other links unchanged"
