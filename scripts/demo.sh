#!/usr/bin/env bash
# The main job: set up (packages, build) if needed, then run the default case (spin ratio 1).
# Extra arguments go to `magnus run`, e.g. scripts/demo.sh --set grid.n_theta=512
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$here/scripts/setup.sh"
exec "${MAGNUS_BUILD_DIR:-$here/build}/magnus" run "$here/cases/spin_ratio_1.toml" "$@"
