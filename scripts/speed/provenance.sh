#!/usr/bin/env bash
# Prints what a speed figure needs beside it: the commit (and whether the
# tree had changes), rustc, the CPU, its cores and the load at this moment.
# Sourced or run by the other scripts here, before and after they measure.
set -euo pipefail
root=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
commit=$(git -C "$root" rev-parse --short HEAD)
if ! git -C "$root" diff --quiet HEAD -- crates src benches Cargo.toml Cargo.lock 2>/dev/null; then
    commit="$commit (with uncommitted changes to the code)"
fi
echo "commit:  $commit"
echo "rustc:   $(rustc -V)"
echo "cpu:     $(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1), $(nproc) cores"
echo "load:    $(uptime | sed 's/.*load average: //') (1, 5, 15 min) at $(date -u +%FT%TZ)"
