#!/usr/bin/env bash
# Fuzz the case-file parser and the --set parser with libFuzzer (+ ASan + UBSan) for SECONDS (default 60).
#   scripts/fuzz.sh [SECONDS]
# Installs clang and libFuzzer's runtime if missing (Debian packages), configures build-fuzz/ with clang++,
# seeds from cases/*.toml and fuzz/corpus/, and exits non-zero on any finding: a crash, an exception other
# than CaseError, a hang (> 5 s per input), memory use above 2 GB, a sanitizer report or a broken invariant.
# Findings are saved as build-fuzz/findings/crash-*, timeout-*, oom-* (replay: build-fuzz/fuzz_case FILE).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MAGNUS_FUZZ_BUILD_DIR:-$here/build-fuzz}"
seconds="${1:-60}"
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS]" >&2; exit 2; }

# clang, and the package that ships libclang_rt.fuzzer for it (libclang-rt-14-dev on Debian 12).
source "$here/scripts/install-packages.sh"
rt="libclang-rt-14-dev"
command -v clang++ >/dev/null && rt="libclang-rt-$(clang++ -dumpversion | cut -d. -f1)-dev"
install_packages fuzz clang "$rt" build-essential cmake pkg-config libtomlplusplus-dev libfmt-dev

cmake -S "$here" -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMAGNUS_FUZZ=ON >/dev/null
cmake --build "$build" --target fuzz_case -j "$(nproc)" >&2

# A fresh working corpus each run, from the checked-in seeds: libFuzzer adds what it finds there.
corpus="$build/corpus"
findings="$build/findings"
rm -rf "$corpus" "$findings"
mkdir -p "$corpus" "$findings"
cp "$here"/cases/*.toml "$here"/fuzz/corpus/* "$corpus"/

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=0:allocator_may_return_null=0:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
log="$build/fuzz.log"
echo "fuzz: running fuzz_case for ${seconds} s (log: $log)" >&2
status=0
"$build/fuzz_case" "$corpus" -dict="$here/fuzz/case.dict" -max_total_time="$seconds" -timeout=5 \
  -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 -artifact_prefix="$findings/" >"$log" 2>&1 || status=$?

# The final figures: executions, coverage, corpus.
grep -E '^#[0-9]+.*DONE|stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb' "$log" >&2 || true
found=("$findings"/*)
if [ "$status" -ne 0 ] || [ -e "${found[0]}" ]; then
  echo "fuzz: FINDING (exit $status); see $log and ${findings}/" >&2
  grep -E 'ERROR|runtime error|invariant broken|terminate called|deadly signal|timeout' "$log" | head -n 20 >&2 || true
  exit 1
fi
echo "fuzz: no findings in ${seconds} s" >&2
