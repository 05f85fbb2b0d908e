#!/usr/bin/env bash
# The tutorial's two commands (see README.md):
#   ./tutorial.sh run    install what is missing, build, render every chapter's figures and the docs
#   ./tutorial.sh test   install what is missing, build, run every test
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

# The Debian packages the tutorial needs: compiler and build tools, then the four libraries.
PACKAGES=(g++ make cmake libglm-dev libstb-dev catch2 doxygen)

usage() {
  sed -n '2,4s/^# \{0,1\}//p' "$0"
  exit "${1:-0}"
}

install_missing_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "This is not a Debian system: install the equivalents of ${PACKAGES[*]} yourself." >&2
    return 0
  fi
  local missing=()
  for package in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' ||
      missing+=("$package")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "Installing missing Debian packages: ${missing[*]}"
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then
      sudo=(sudo)
    else
      echo "error: missing Debian packages: ${missing[*]}" >&2
      echo "Install them as root: apt-get install ${missing[*]}" >&2
      exit 1
    fi
  fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
}

configure_and_build() {
  cmake --preset release
  cmake --build --preset release
}

case "${1:-}" in
  run)
    install_missing_packages
    configure_and_build
    cmake --build --preset release --target docs  # renders every chapter's figures first
    echo
    echo "Figures:  $(pwd)/build/release/figures"
    echo "Docs:     $(pwd)/build/release/docs/html/index.html"
    ;;
  test)
    install_missing_packages
    configure_and_build
    ctest --preset release
    ;;
  -h | --help | help) usage 0 ;;
  *)
    echo "error: expected 'run' or 'test', got '${1:-}'" >&2
    usage 2 >&2
    ;;
esac
