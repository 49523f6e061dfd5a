#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, AddressSanitizer + UndefinedBehaviorSanitizer) in
# build-fuzz/ and runs each for a bounded time. docs/robustness.md, "Fuzzing".
#   bash scripts/fuzz.sh                 every target, 60 s each
#   bash scripts/fuzz.sh 300             every target, 300 s each
#   bash scripts/fuzz.sh 60 mesh_file    one target (json_scene, scene_parameters, mesh_file,
#                                        grid_file)
#   bash scripts/fuzz.sh --runs 5000 mesh_file
#                                        a fixed number of inputs: with VISSORT_FUZZ_SEED set,
#                                        the same inputs on every machine (what CI runs)
# Seeds: tests/fuzz/corpus/TARGET/ (read only). What a run finds interesting goes to
# build-fuzz/corpus/TARGET/; a crash, hang or leak is written to tests/fuzz/crashes/TARGET/ and
# the script fails at the end. Keep the reproducer there once fixed: the normal build's
# fuzz_replay_tests runs it from then on.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "${1:-}" = --runs ]; then
  runs=${2:-}
  case "$runs" in '' | *[!0-9]*)
    echo "fuzz.sh: --runs needs a whole number of inputs, not '$runs'" >&2; exit 2 ;;
  esac
  budget=(-runs="$runs")
  budget_text="$runs inputs"
  shift 2
else
  seconds=${1:-60}
  case "$seconds" in '' | *[!0-9]*)
    echo "fuzz.sh: the time must be whole seconds, not '$seconds'" >&2; exit 2 ;;
  esac
  budget=(-max_total_time="$seconds")
  budget_text="$seconds s"
  shift || true
fi
all_targets=(json_scene scene_parameters mesh_file grid_file)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] ||
    { echo "fuzz.sh: unknown target '$t' (expected ${all_targets[*]})" >&2; exit 2; }
done

bash scripts/install-deps.sh
# Fuzzing only, so installed here rather than by install-deps.sh: clang 14 and its runtime
# libraries (libclang-rt-14-dev holds libFuzzer and the sanitizer runtimes).
fuzz_packages=(clang-14 libclang-rt-14-dev)
missing=()
for p in "${fuzz_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "fuzz.sh: missing ${missing[*]}; run as root or install them" >&2
    exit 1
  fi
  DEBIAN_FRONTEND=noninteractive apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# No OpenGL: the fuzz targets need only the scene library.
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DVISSORT_FUZZ=ON -DVISSORT_BUILD_TESTS=ON -DVISSORT_BUILD_BENCHMARKS=OFF \
  -DVISSORT_WITH_GL=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]/%/_fuzzer}"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
# Leaks inside assimp itself are not ours to fix (the file says which); ours are still found.
export LSAN_OPTIONS=suppressions=$PWD/tests/fuzz/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# VISSORT_FUZZ_SEED fixes libFuzzer's seed; with --runs the inputs tried are then the same on
# every machine, fast or slow (CI does: a new finding then shows up in a change that can cause
# it, not at random in a later run); unset, each run explores anew.
seed=()
[ -z "${VISSORT_FUZZ_SEED:-}" ] || seed=(-seed="$VISSORT_FUZZ_SEED")
failed=()
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t" "tests/fuzz/crashes/$t"
  echo "== fuzzing $t for $budget_text"
  # -timeout: one input taking 10 s is a hang; -rss_limit_mb: memory out of proportion.
  if ! "build-fuzz/${t}_fuzzer" "${budget[@]}" -timeout=10 -rss_limit_mb=2048 \
      -max_len=4096 -print_final_stats=1 "${seed[@]}" -artifact_prefix="tests/fuzz/crashes/$t/" \
      "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" "tests/fuzz/crashes/$t"; then
    failed+=("$t")
  fi
done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz.sh: ${failed[*]} found a crash, hang or leak: see tests/fuzz/crashes/" >&2
  exit 1
fi
echo "fuzz.sh: no crash, hang or leak in ${targets[*]} ($budget_text each)"
