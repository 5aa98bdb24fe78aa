#!/usr/bin/env bash
# Bounded fuzzing of genmesh's readers and of the genmesh program's argument
# and crease parsing (docs/fuzzing.md).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]   default: 60 seconds each, every target
#
# Builds the libFuzzer targets with clang (ASan + UBSan) in build-fuzz/
# (GENMESH_JOBS parallel jobs, default 1), writes the seed corpus
# (fuzz/make_seeds.cpp, the same generator the tests use) to
# build-fuzz/seeds/, and runs each target from it plus the regression corpus
# (tests/fuzz/regressions/). New inputs go to build-fuzz/corpus/TARGET/;
# findings (crash-*, timeout-*, oom-*, leak-*) to build-fuzz/findings/TARGET/.
# Exits non-zero if any target found something.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(fuzz_off fuzz_obj fuzz_ply fuzz_stl fuzz_cli)
jobs=${GENMESH_JOBS:-1}

command -v clang++ >/dev/null || { echo "fuzz.sh: needs clang++ (scripts/run.sh fuzz installs it)" >&2; exit 2; }
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DGENMESH_BUILD_FUZZERS=ON -DGENMESH_BUILD_TESTS=OFF -DGENMESH_BUILD_EXAMPLES=OFF -DGENMESH_BUILD_TOOLS=OFF >/dev/null
cmake --build build-fuzz -j"$jobs" --target fuzz_seeds "${targets[@]}"
rm -rf build-fuzz/seeds build-fuzz/regressions
build-fuzz/fuzz/fuzz_seeds build-fuzz/seeds

status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t findings=build-fuzz/findings/$t
  mkdir -p "$corpus" "$findings"
  case $t in
    fuzz_cli)
      # The regression inputs without their "# expect N" and "# message" lines.
      mkdir -p build-fuzz/regressions/cli
      for f in tests/fuzz/regressions/cli/*.args; do
        sed -e '/^# expect /d' -e '/^# message /d' "$f" >"build-fuzz/regressions/cli/$(basename "$f")"
      done
      seeds=(build-fuzz/seeds/cli build-fuzz/regressions/cli)
      max_len=4096 ;;
    *)
      fmt=${t#fuzz_}
      mkdir -p "build-fuzz/regressions/$fmt"
      cp tests/fuzz/regressions/reader/*."$fmt" "build-fuzz/regressions/$fmt/" 2>/dev/null || true
      seeds=("build-fuzz/seeds/$fmt" "build-fuzz/regressions/$fmt")
      max_len=65536 ;;
  esac
  echo "== $t: ${seconds}s"
  if ! build-fuzz/fuzz/$t "$corpus" "${seeds[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
      -close_fd_mask=3 -artifact_prefix="$findings/" -print_final_stats=1 >"build-fuzz/$t.log" 2>&1; then
    status=1
    echo "   FINDING: see build-fuzz/$t.log and $findings/"
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^Done" "build-fuzz/$t.log" | tr '\n' ' '
  echo
done
exit $status
