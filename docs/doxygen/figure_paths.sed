# Doxygen's input filter for the Markdown pages (FILTER_PATTERNS in docs/CMakeLists.txt).
# The READMEs name their figures by repository path so that the repository view shows them:
# ![..](../../docs/figures/NAME.svg) in a chapter, ![..](docs/figures/NAME.svg) at the top.
# Doxygen finds images by bare name in IMAGE_PATH (which holds docs/figures), so the path before
# the name is dropped. Only links that lead into docs/figures/ change; line numbers stay the same.
s#](\(\.\./\)*docs/figures/#](#g
