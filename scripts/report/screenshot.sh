#!/usr/bin/env bash
# Renders biodyn's HTML reports in headless Chromium, as a reader's browser
# would: a PNG of the screen (an A4 page's width at 150 dpi) and the PDF the
# print dialog makes, for looking at before calling a change to the page done.
# Not part of `cargo test` (nothing there needs Chromium).
#
#   scripts/report/screenshot.sh [OUT_DIR]      (default /tmp/biodyn-report)
#
# Needs Debian's chromium (`apt-get install -y chromium`) and a built
# biodyn (`cargo build`; BIODYN=path overrides target/debug/biodyn).
set -euo pipefail
cd "$(dirname "$0")/../.."
out="${1:-/tmp/biodyn-report}"
biodyn="${BIODYN:-target/debug/biodyn}"
browser="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$browser" ]; then
  echo "screenshot.sh: no chromium on PATH; apt-get install -y chromium" >&2
  exit 1
fi
mkdir -p "$out"
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT

"$biodyn" assess --input examples/tractor-seat-xyz-g.csv --axes x=ax_g,y=ay_g,z=az_g \
  --exposure 6 --report "$out/assess.html" > /dev/null
"$biodyn" assess --signal random:rms=0.8,band=1-20,seed=1+shock:peak=15,width=0.1,at=30 \
  --duration 60 --spine age=25,years=10,days=240,sex=male --report "$out/assess-spine.html" > /dev/null
"$biodyn" day examples/day-shocks.toml --report "$out/day.html" > /dev/null
"$biodyn" day examples/day.toml examples/day-shocks.toml --week --report "$out/week.html" > /dev/null

# The flags keep a closed network quiet: no background fetches, no updates.
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run
  --disable-background-networking --disable-component-update --disable-sync
  --hide-scrollbars --user-data-dir="$profile")
for page in assess assess-spine day week; do
  url="file://$(realpath "$out/$page.html")"
  "$browser" "${flags[@]}" --screenshot="$out/$page.png" --window-size=1240,1754 "$url" 2> /dev/null
  "$browser" "${flags[@]}" --no-pdf-header-footer --print-to-pdf="$out/$page.pdf" "$url" 2> /dev/null
  echo "$out/$page.png $out/$page.pdf"
done
