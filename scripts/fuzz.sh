#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan: the build-asan tree of scripts/sanitize.sh)
# and fuzzes one of them.
#   scripts/fuzz.sh list                     the targets
#   scripts/fuzz.sh build                    build them all
#   scripts/fuzz.sh TARGET [SECONDS] [ARGS]  fuzz TARGET (default 600 s) from its saved corpus;
#                                            new inputs go to build-asan/corpus/TARGET, crashes to
#                                            build-asan/findings/TARGET (see tests/fuzz/README.md)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build-asan
targets=(mesh csv doe_analyze doe_optimize doe_diagnose read_json set calibration_input discovery_input)
configure() {
  # The same configuration as scripts/sanitize.sh address (which configures it when missing).
  [ -f $dir/CMakeCache.txt ] && return
  launcher=()
  if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
  CC=clang CXX=clang++ cmake -S . -B $dir -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g" -DPADDY_NATIVE=OFF \
    -DPADDY_SANITIZE=address,undefined -DPADDY_FUZZ=ON "-DPADDY_COMPONENTS=plugins;doe;engine/app" "${launcher[@]}"
}
case "${1:?usage: scripts/fuzz.sh list|build|TARGET [SECONDS] [libFuzzer args]}" in
list) printf '%s\n' "${targets[@]}" ;;
build)
  configure
  cmake --build $dir -j"$(nproc)" --target "${targets[@]/#/fuzz_}" ;;
*)
  t="$1"; secs="${2:-600}"; shift; [ $# -gt 0 ] && shift
  configure
  cmake --build $dir -j"$(nproc)" --target "fuzz_$t"
  mkdir -p $dir/corpus/$t $dir/findings/$t
  export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
  # New inputs go to the first corpus directory; the saved one (tests/fuzz/corpus) seeds the run.
  exec $dir/bin/fuzz_$t $dir/corpus/$t tests/fuzz/corpus/$t -max_total_time="$secs" -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -artifact_prefix=$dir/findings/$t/ -print_final_stats=1 "$@" ;;
esac
