#!/usr/bin/env bash
# `biodyn response --format csv` as a process, start to exit, timed by
# hyperfine (200 runs after 20 warm-ups, no shell between). Prints hyperfine's
# mean and median with the provenance. Needs: cargo, hyperfine
# (`apt-get install hyperfine`), python3.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel)
cd "$root"
command -v hyperfine >/dev/null || { echo "hyperfine is not installed (apt-get install hyperfine)" >&2; exit 2; }
cargo build --release --bin biodyn >&2
bin=${CARGO_TARGET_DIR:-$root/target}/release/biodyn
"$here/provenance.sh"
runs=${RUNS:-200}
echo "command: hyperfine -N --warmup 20 --runs $runs '$bin response --format csv'"
json=$(mktemp)
trap 'rm -f "$json"' EXIT
hyperfine -N --warmup 20 --runs "$runs" --export-json "$json" "$bin response --format csv" >&2
echo "load after: $(uptime | sed 's/.*load average: //')"
python3 - "$json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["results"][0]
print(f"mean {r['mean'] * 1e3:.2f} ms ± {r['stddev'] * 1e3:.2f}, median {r['median'] * 1e3:.2f} ms, "
      f"min {r['min'] * 1e3:.2f} ms, {len(r['times'])} runs")
PY
