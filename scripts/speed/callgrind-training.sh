#!/usr/bin/env bash
# Instructions per training pattern of the paper's back-propagation, the
# stable measure docs/networks.md#training-speed quotes: `biodyn train` runs
# under callgrind twice per architecture, with 200 and 400 epochs, and the
# difference of the two instruction totals (set-up, data and the hold-out
# check cancel) is divided by 200 epochs × PATTERNS (default 120, the
# training set of every paper case: 3 training values × 40 frequencies).
# Needs: cargo, valgrind.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel)
cd "$root"
command -v valgrind >/dev/null || { echo "valgrind is not installed (apt-get install valgrind)" >&2; exit 2; }
cargo build --release --bin biodyn >&2
bin=${CARGO_TARGET_DIR:-$root/target}/release/biodyn
patterns=${PATTERNS:-120}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$here/provenance.sh"
echo "command: valgrind --tool=callgrind $bin train --case CASE --trainer backprop --epochs E (E = 200, 400)"
total() { # instructions executed by one run
    valgrind --tool=callgrind --callgrind-out-file="$dir/out" "$bin" train --case "$1" \
        --trainer backprop --epochs "$2" >/dev/null 2>"$dir/err"
    sed -n 's/^summary: //p' "$dir/out"
}
for pair in "k4-stht 2-5-3-1" "mass-dpmi 5-6-4-1" "mass-stht 5-6-4-2-1"; do
    set -- $pair
    a=$(total "$1" 200)
    b=$(total "$1" 400)
    echo "$2 ($1): $(( (b - a) / (200 * patterns) )) instructions per pattern ($(( (b - a) / 200 )) per epoch)"
done
