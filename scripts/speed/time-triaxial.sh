#!/usr/bin/env bash
# The tri-axial hour of docs/speed.md as whole processes: the library's
# example `triaxial_hour` (a generated hour at 1 kHz on x, y and z through
# everything `assess` does; it prints its own wall time) under /usr/bin/time,
# then the same hour as CSV (about 248 MB, written once by the example to a
# temporary folder) through `biodyn assess --input` under /usr/bin/time, with
# MB/s. RUNS runs of each (default 3). Needs: cargo, GNU time at
# /usr/bin/time, 250 MB free in TMPDIR.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel)
cd "$root"
[ -x /usr/bin/time ] || { echo "GNU time is not at /usr/bin/time (apt-get install time)" >&2; exit 2; }
cargo build --release --bin biodyn >&2
cargo build --release -p biodyn --example triaxial_hour >&2
target=${CARGO_TARGET_DIR:-$root/target}
bin=$target/release/biodyn
example=$target/release/examples/triaxial_hour
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$example" "$dir/hour3.csv" >/dev/null
bytes=$(stat -c %s "$dir/hour3.csv")
"$here/provenance.sh"
echo "command: /usr/bin/time -f '%e s, %M KB' $example"
for _ in $(seq "${RUNS:-3}"); do
    /usr/bin/time -f '  process %e s wall, %U+%S s CPU, %M KB max resident' "$example" 2>&1 | sed 's/^generated/  generated/'
done
echo "command: /usr/bin/time -f '%e s, %M KB' $bin assess --input hour3.csv --format json > /dev/null ($bytes bytes)"
for _ in $(seq "${RUNS:-3}"); do
    out=$(/usr/bin/time -f '%e %U %S %M' "$bin" assess --input "$dir/hour3.csv" --format json 2>&1 >/dev/null | tail -1)
    read -r wall user sys kb <<<"$out"
    echo "  $wall s wall, $user+$sys s CPU, $kb KB max resident, $(awk -v b="$bytes" -v t="$wall" 'BEGIN { printf "%.0f", b / t / 1e6 }') MB/s"
done
echo "load after: $(uptime | sed 's/.*load average: //')"
