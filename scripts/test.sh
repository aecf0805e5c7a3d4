#!/usr/bin/env bash
# Set up (packages, build) if needed, then run the whole default test suite through ctest.
# MAGNUS_TEST_LABEL=stress scripts/test.sh runs the long stability suite instead; MAGNUS_TEST_LABEL=slurm
# the Slurm job-array test (setting up munge and Slurm first).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${MAGNUS_BUILD_DIR:-$here/build}"
if [ "${MAGNUS_TEST_LABEL:-}" = slurm ]; then "$here/scripts/setup.sh" --slurm; else "$here/scripts/setup.sh"; fi
cd "$build"
exec ctest --output-on-failure -j "$(nproc)" -L "${MAGNUS_TEST_LABEL:-default}"
