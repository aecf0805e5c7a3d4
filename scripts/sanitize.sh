#!/usr/bin/env bash
# Build the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer (cmake -DMAGNUS_SANITIZE=ON)
# in build-asan/ and run the default ctest label. Fails on any failing test and on any sanitizer report,
# including reports from the magnus binaries the CLI tests start (they are the sanitized ones of this build).
#   scripts/sanitize.sh            # MAGNUS_TEST_LABEL=stress scripts/sanitize.sh for the long suite
# Leaks are reported (detect_leaks=1); scripts/lsan.supp suppresses only leaks inside third-party libraries.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export MAGNUS_BUILD_DIR="${MAGNUS_ASAN_BUILD_DIR:-$here/build-asan}"
export MAGNUS_BUILD_TYPE="${MAGNUS_BUILD_TYPE:-RelWithDebInfo}"
export MAGNUS_CMAKE_ARGS="-DMAGNUS_SANITIZE=ON ${MAGNUS_CMAKE_ARGS:-}"
build="$MAGNUS_BUILD_DIR"

# Every report goes to a log file as well as failing the process: a report from a child process whose
# exit status a test does not check still fails the run. fast_unwind_on_malloc=0: full stacks through the
# Debian libraries (built without frame pointers), so the suppressions match library-internal functions.
logs="$build/sanitizer-logs"
rm -rf "$logs"
mkdir -p "$logs"
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:fast_unwind_on_malloc=0:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1:log_path=$logs/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$logs/ubsan"
export LSAN_OPTIONS="suppressions=$here/scripts/lsan.supp:print_suppressions=0"

"$here/scripts/setup.sh"   # packages, configure, build (with the variables above)
cd "$build"
status=0
ctest --output-on-failure -j "$(nproc)" -L "${MAGNUS_TEST_LABEL:-default}" || status=$?

reports=("$logs"/*)
if [ -e "${reports[0]}" ]; then
  echo "sanitize: ${#reports[@]} sanitizer report(s):" >&2
  for r in "${reports[@]}"; do echo "--- $r" >&2; head -n 40 "$r" >&2; done
  status=1
fi
if [ "$status" -ne 0 ]; then
  echo "sanitize: FAILED" >&2
  exit "$status"
fi
echo "sanitize: all tests passed, no sanitizer reports" >&2
