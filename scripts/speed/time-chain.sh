#!/usr/bin/env bash
# The time domain against model size: `biodyn simulate` on a chain of N
# one-kilogram segments (k = 1e6 N/m, c = 50 N·s/m to the next, the last to
# the seat), one second of a 5 Hz sine at the default 1 kHz, under
# /usr/bin/time. Each size runs twice: with 1 s of signal, and with 10 ms
# (ten samples), which is nearly all discretising (the step's matrix
# exponential) and start-up. A refused model (past the 500-segment limit)
# prints its exit status and the error's first line. Sizes: the arguments, default 50 100 200 300 400 500 1000.
# Needs: cargo, GNU time at /usr/bin/time.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(git -C "$here" rev-parse --show-toplevel)
cd "$root"
[ -x /usr/bin/time ] || { echo "GNU time is not at /usr/bin/time (apt-get install time)" >&2; exit 2; }
cargo build --release --bin biodyn >&2
bin=${CARGO_TARGET_DIR:-$root/target}/release/biodyn
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
chain() {
    local n=$1 i lower
    printf 'schema = 1\nname = "chain%s"\nhead = "s1"\n' "$n"
    for i in $(seq "$n"); do printf '\n[[segment]]\nname = "s%s"\nmass_kg = 1.0\n' "$i"; done
    for i in $(seq "$n"); do
        if [ "$i" -lt "$n" ]; then lower="s$((i + 1))"; else lower=seat; fi
        printf '\n[[link]]\nname = "s%s-%s"\nupper = "s%s"\nlower = "%s"\nk_n_per_m = 1e6\nc_ns_per_m = 50.0\n' \
            "$i" "$lower" "$i" "$lower"
    done
}
"$here/provenance.sh"
echo "command: /usr/bin/time -f '%e s, %M KB' $bin simulate --preset chainN.toml --signal sine:freq=5,amp=1 --duration D --format csv > /dev/null"
printf '%-9s %-32s %s\n' segments "1 s of signal" "10 ms of signal"
for n in "${@:-50 100 200 300 400 500 1000}"; do
    for m in $n; do
        chain "$m" > "$dir/chain$m.toml"
        row=()
        for d in 1 0.01; do
            out=$(/usr/bin/time -f '%e s, %M KB, exit %x' "$bin" simulate --preset "$dir/chain$m.toml" \
                --signal sine:freq=5,amp=1 --duration "$d" --format csv 2>&1 >/dev/null || true)
            if [[ $(tail -1 <<<"$out") != *"exit 0" ]]; then
                out="$(tail -1 <<<"$out") ($(grep -m1 'error:' <<<"$out" | cut -c1-60))"
            else
                out=$(tail -1 <<<"$out" | sed 's/, exit 0$//')
            fi
            row+=("$out")
        done
        printf '%-9s %-32s %s\n' "$m" "${row[0]}" "${row[1]}"
    done
done
echo "load after: $(uptime | sed 's/.*load average: //')"
