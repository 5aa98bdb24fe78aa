#!/usr/bin/env bash
# Bounded fuzzing of genmesh's readers and of the genmesh program's argument
# and crease parsing (docs/cli.md, "Fuzzing").
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]   default: 60 seconds each, every target
#
# Builds the libFuzzer targets with clang (ASan + UBSan) in build-fuzz/, and
# runs each from the seed corpus the tests write (build/tests/fuzz_seeds/, made
# by test_io; run the tests first) plus the regression corpus
# (tests/fuzz/regressions/). New inputs go to build-fuzz/corpus/TARGET/;
# findings to build-fuzz/findings/TARGET/. Exits non-zero if any target
# found something.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(fuzz_off fuzz_obj fuzz_ply fuzz_stl fuzz_cli)

cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DGENMESH_BUILD_FUZZERS=ON -DGENMESH_BUILD_TESTS=OFF -DGENMESH_BUILD_EXAMPLES=OFF -DGENMESH_BUILD_TOOLS=OFF >/dev/null
cmake --build build-fuzz -j2 --target "${targets[@]}"

status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t findings=build-fuzz/findings/$t
  mkdir -p "$corpus" "$findings"
  seeds=()
  case $t in
    fuzz_cli)
       # The regression inputs without their "# expect N" line.
       mkdir -p build-fuzz/regressions/cli
       for f in tests/fuzz/regressions/cli/*.args; do tail -n +2 "$f" >"build-fuzz/regressions/cli/$(basename "$f")"; done
       seeds=(build-fuzz/regressions/cli) ;;
    *) fmt=${t#fuzz_}
       [[ -d build/tests/fuzz_seeds/$fmt ]] && seeds+=(build/tests/fuzz_seeds/$fmt)
       # The regression inputs of this format.
       mkdir -p build-fuzz/regressions/$fmt
       cp tests/fuzz/regressions/reader/*."$fmt" build-fuzz/regressions/$fmt/ 2>/dev/null || true
       seeds+=(build-fuzz/regressions/$fmt) ;;
  esac
  echo "== $t: ${seconds}s"
  if ! ASAN_OPTIONS=detect_leaks=0 build-fuzz/fuzz/$t "$corpus" "${seeds[@]}" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -close_fd_mask=3 -artifact_prefix="$findings/" -print_final_stats=1 2>build-fuzz/$t.log; then
    status=1
    echo "   FINDING: see build-fuzz/$t.log and $findings/"
  fi
  grep -E "^stat::number_of_executed_units|^Done" build-fuzz/$t.log | tr '\n' ' '
  echo
done
exit $status
