#!/usr/bin/env bash
# The script behind the README's two commands.
#
#   scripts/run.sh demo   install what is missing, build, run `genmesh demo`
#   scripts/run.sh test   install what is missing, build, run the whole test suite
#   scripts/run.sh setup  only install packages and fetch the real test meshes
#   scripts/run.sh bench  set up, build the benchmarks and run them
#   scripts/run.sh fuzz [SECONDS] [TARGET...]
#                         install clang too, then the bounded fuzz run
#                         (scripts/fuzz.sh, docs/fuzzing.md)
#
# Packages come from Debian 12 (apt-get; as root, or through sudo). The real
# meshes come from Debian's libcgal-demo package, extracted (not installed)
# into $GENMESH_DATA_DIR (default ~/.cache/genmesh/data) and reused afterwards.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GENMESH_BUILD_DIR:-$root/build}"
data="${GENMESH_DATA_DIR:-$HOME/.cache/genmesh/data}"
jobs="${GENMESH_JOBS:-$(nproc)}"

packages=(
  g++ cmake ninja-build ccache pkg-config
  libboost-dev libboost-graph-dev libeigen3-dev
  libcgal-dev libgmp-dev libmpfr-dev
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  libopenmesh-dev libmeshoptimizer-dev libtbb-dev
)

log() { printf '[genmesh] %s\n' "$*" >&2; }

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else log "need root (or sudo) to run: $*"; exit 1
  fi
}

install_packages() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    log "installing: ${missing[*]}"
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
  fi
}

fetch_meshes() {
  if [ -f "$data/meshes/armadillo.off" ]; then return; fi
  log "fetching real meshes (libcgal-demo) into $data"
  local tmp; tmp="$(mktemp -d)"
  chmod 755 "$tmp"
  ( cd "$tmp"
    # apt-get download needs an up-to-date list on a fresh machine.
    apt-get download libcgal-demo >/dev/null 2>&1 || { as_root apt-get update -qq; apt-get download libcgal-demo >/dev/null; }
    dpkg-deb -x libcgal-demo_*.deb x
    mkdir -p d && tar xzf x/usr/share/doc/libcgal-dev/data.tar.gz -C d data/meshes )
  mkdir -p "$data"
  rm -rf "$data/meshes.partial"
  mv "$tmp/d/data/meshes" "$data/meshes.partial"
  mv "$data/meshes.partial" "$data/meshes"
  rm -rf "$tmp"
}

setup() {
  install_packages
  fetch_meshes
}

configure() {
  local gen=()
  command -v ninja >/dev/null && gen=(-G Ninja)
  cmake -S "$root" -B "$build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release \
        -DGENMESH_DATA_DIR="$data" "$@" >/dev/null
}

case "${1:-}" in
  setup) setup ;;
  demo)
    setup
    configure
    cmake --build "$build" -j "$jobs" --target genmesh_cli
    "$build/tools/genmesh" demo ;;
  test)
    packages+=(clang)   # the install.consumer_clang test (tests/consumer.cmake)
    setup
    configure
    cmake --build "$build" -j "$jobs"
    ctest --test-dir "$build" --output-on-failure -j "$jobs" ;;
  fuzz)
    shift
    packages+=(clang libclang-rt-14-dev)   # libFuzzer's runtime is only recommended by clang
    setup
    GENMESH_JOBS="$jobs" exec "$root/scripts/fuzz.sh" "$@" ;;
  bench)
    setup
    configure -DGENMESH_BUILD_BENCHMARKS=ON
    cmake --build "$build" -j "$jobs"
    "$build/benchmarks/genmesh_benchmarks" ;;
  *) echo "usage: scripts/run.sh demo|test|setup|bench|fuzz" >&2; exit 2 ;;
esac
