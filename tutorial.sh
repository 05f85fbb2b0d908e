#!/usr/bin/env bash
# The tutorial's two commands (see README.md), and the fuzzing run (see fuzz/README.md):
#   ./tutorial.sh run    install what is missing, build, render every chapter's figures and the docs
#   ./tutorial.sh test   install what is missing, build, run every test
#   ./tutorial.sh fuzz [SECONDS]   build the libFuzzer targets (clang), run each SECONDS (60)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"

# The Debian packages the tutorial needs: compiler and build tools, the four libraries, and the
# docs site (Doxygen, and Python 3 for its Markdown filter).
PACKAGES=(g++ make cmake libglm-dev libstb-dev catch2 doxygen python3)
# The run command also builds the docs site's playground: the chapters' C++ compiled to
# WebAssembly (docs/playground.md).
DOCS_PACKAGES=(emscripten)
# The fuzzing run builds with clang and libFuzzer instead, and without the docs.
FUZZ_PACKAGES=(clang libclang-rt-14-dev make cmake libglm-dev libstb-dev catch2)

usage() {
  sed -n '2,5s/^# \{0,1\}//p' "$0"
  exit "${1:-0}"
}

# install_missing_packages PACKAGE...: installs those of the Debian packages that are missing.
install_missing_packages() {
  if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "This is not a Debian system: install the equivalents of $* yourself." >&2
    return 0
  fi
  local missing=()
  for package in "$@"; do
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

FUZZ_BUILD=build/fuzz

# run_fuzzer TARGET SECONDS [libFuzzer options...]: fuzzes on a copy of the seed corpus in the
# build folder (the repository's corpus stays as it is), prints the speed and the number of runs,
# and returns non-zero on a finding, naming the file that reproduces it.
run_fuzzer() {
  local target=$1 seconds=$2
  shift 2
  local work="$FUZZ_BUILD/fuzz-runs/$target"
  mkdir -p "$work/corpus"
  cp fuzz/corpus/"$target"/* "$work/corpus/"
  echo
  echo "== $target: fuzzing for $seconds s (log: $work/fuzz.log)"
  local status=0
  UBSAN_OPTIONS=print_stacktrace=1 "$FUZZ_BUILD/fuzz/$target" "$work/corpus" \
    -max_total_time="$seconds" -timeout=10 -print_final_stats=1 -artifact_prefix="$work/" \
    "$@" >"$work/fuzz.log" 2>&1 || status=$?
  local runs speed
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/fuzz.log")
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/fuzz.log")
  echo "$target: ${runs:-?} runs, ${speed:-?} executions per second"
  if [ "$status" -ne 0 ]; then
    grep -E '^(FINDING|==[0-9]+==ERROR|SUMMARY)|runtime error' "$work/fuzz.log" |
      head -n 20 >&2 || true
    local artifact
    artifact=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$work/fuzz.log" | tail -n 1)
    echo "error: $target found a problem (exit status $status); input: ${artifact:-see the log}" >&2
    [ -n "$artifact" ] && echo "Reproduce: $FUZZ_BUILD/fuzz/$target $artifact" >&2
    return 1
  fi
}

fuzz() {
  local seconds=${1:-60}
  if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
    echo "error: SECONDS must be a positive whole number, got '$seconds'" >&2
    exit 2
  fi
  install_missing_packages "${FUZZ_PACKAGES[@]}"
  cmake --preset fuzz
  cmake --build --preset fuzz
  local failed=0
  run_fuzzer fuzz_scene_parser "$seconds" -dict=fuzz/scene.dict || failed=1
  run_fuzzer fuzz_rasterizers "$seconds" || failed=1
  run_fuzzer fuzz_coverage "$seconds" || failed=1
  [ "$failed" -eq 0 ] && echo && echo "No findings."
  return "$failed"
}

case "${1:-}" in
  run)
    install_missing_packages "${PACKAGES[@]}" "${DOCS_PACKAGES[@]}"
    configure_and_build
    cmake --build --preset release --target docs  # renders every chapter's figures first
    echo
    echo "Figures:  $(pwd)/build/release/figures"
    echo "Docs:     $(pwd)/build/release/docs/html/index.html"
    ;;
  test)
    install_missing_packages "${PACKAGES[@]}"
    configure_and_build
    ctest --preset release
    ;;
  fuzz) fuzz "${2:-}" ;;
  -h | --help | help) usage 0 ;;
  *)
    echo "error: expected 'run', 'test' or 'fuzz', got '${1:-}'" >&2
    usage 2 >&2
    ;;
esac
