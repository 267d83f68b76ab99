#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan: the build-asan tree of scripts/sanitize.sh)
# and fuzzes one of them.
#   scripts/fuzz.sh list                     the targets
#   scripts/fuzz.sh build                    build them all
#   scripts/fuzz.sh TARGET [SECONDS] [ARGS]  fuzz TARGET (default 600 s) from its saved corpus;
#                                            new inputs go to build-asan/corpus/TARGET, crashes to
#                                            build-asan/findings/TARGET (see tests/fuzz/README.md);
#                                            tests/fuzz/dict/TARGET.dict, when present, is the
#                                            libFuzzer dictionary (tokens of the input's format)
#   scripts/fuzz.sh merge TARGET             adds to tests/fuzz/corpus/TARGET the inputs of
#                                            build-asan/corpus/TARGET that reach new edges
#                                            (-merge=1 -use_counters=0: hit counts are not
#                                            features, which keeps the saved corpus small)
# PADDY_FUZZ_NO_BUILD=1 runs the built fuzzer as it is (e.g. while the tree is rebuilt for
# something else); PADDY_JOBS sets the build's parallelism (default: nproc).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build-asan
jobs="${PADDY_JOBS:-$(nproc)}"
targets=(mesh csv doe_analyze doe_optimize doe_diagnose read_json set calibration_input discovery_input checkpoint)
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
  cmake --build $dir -j"$jobs" --target "${targets[@]/#/fuzz_}" ;;
merge)
  t="${2:?usage: scripts/fuzz.sh merge TARGET}"
  ASAN_OPTIONS="halt_on_error=1:detect_leaks=1" $dir/bin/fuzz_$t -merge=1 -use_counters=0 -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 tests/fuzz/corpus/$t $dir/corpus/$t
  echo "tests/fuzz/corpus/$t: $(ls tests/fuzz/corpus/$t | wc -l) files, $(du -sk tests/fuzz/corpus/$t | cut -f1) kB" ;;
*)
  t="$1"; secs="${2:-600}"; shift; [ $# -gt 0 ] && shift
  configure
  [ "${PADDY_FUZZ_NO_BUILD:-0}" = 1 ] || cmake --build $dir -j"$jobs" --target "fuzz_$t"
  dict=()
  [ -f tests/fuzz/dict/$t.dict ] && dict=(-dict=tests/fuzz/dict/$t.dict)
  mkdir -p $dir/corpus/$t $dir/findings/$t
  export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
  export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
  # New inputs go to the first corpus directory; the saved one (tests/fuzz/corpus) seeds the run.
  exec $dir/bin/fuzz_$t $dir/corpus/$t tests/fuzz/corpus/$t -max_total_time="$secs" -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -artifact_prefix=$dir/findings/$t/ -print_final_stats=1 "${dict[@]}" "$@" ;;
esac
