#!/usr/bin/env bash
# The hour of `biodyn assess` (random:rms=1,band=0.5-80,seed=1, 3600 s at
# 1 kHz, JSON) as a whole process under /usr/bin/time: wall, user + system
# CPU and the largest resident size, for each of RUNS runs (default 5).
# Needs: cargo, GNU time at /usr/bin/time.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel)
cd "$root"
[ -x /usr/bin/time ] || { echo "GNU time is not at /usr/bin/time (apt-get install time)" >&2; exit 2; }
cargo build --release --bin biodyn >&2
bin=${CARGO_TARGET_DIR:-$root/target}/release/biodyn
"$here/provenance.sh"
args=(assess --signal random:rms=1,band=0.5-80,seed=1 --duration 3600 --fs 1000 --format json)
echo "command: /usr/bin/time -f '%e s wall, %U+%S s CPU, %M KB' $bin ${args[*]} > /dev/null"
for _ in $(seq "${RUNS:-5}"); do
    /usr/bin/time -f '%e s wall, %U+%S s CPU, %M KB max resident' "$bin" "${args[@]}" 2>&1 >/dev/null
done
echo "load after: $(uptime | sed 's/.*load average: //')"
