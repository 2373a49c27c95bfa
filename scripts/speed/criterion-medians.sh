#!/usr/bin/env bash
# Runs a criterion bench and prints the median of every benchmark it ran,
# read from criterion's own estimates (target/criterion/*/new/estimates.json),
# with the provenance before and the load after.
#
#   scripts/speed/criterion-medians.sh --bench response -- sweep
#   scripts/speed/criterion-medians.sh -p biodyn --bench time -- --warm-up-time 1 --measurement-time 3 simulate/
#
# Arguments go to `cargo bench` unchanged. Needs: cargo, python3.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel)
cd "$root"
"$here/provenance.sh"
echo "command: cargo bench $*"
stamp=$(mktemp)
trap 'rm -f "$stamp"' EXIT
cargo bench "$@" >&2
echo "load after: $(uptime | sed 's/.*load average: //')"
target=${CARGO_TARGET_DIR:-$root/target}
find "$target/criterion" -path '*/new/estimates.json' -newer "$stamp" -print0 |
    xargs -0 -r python3 "$here/medians.py"
