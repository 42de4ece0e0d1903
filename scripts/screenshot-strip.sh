#!/usr/bin/env bash
# scripts/screenshot-strip.sh RUN OUT.png [--at "2 5 8 11 14"] [--width 320] [--height 240] [--view "ARGS"]
# A strip of screenshots of a run's best individual (any input `cic view` takes:
# a run folder or a population file), one frame per time in --at (seconds of
# the replay), side by side in one PNG: `cic view --screenshot OUT --strip`
# (offscreen; xvfb-run when there is no display), a fixed camera framing the
# whole path, the trail on the ground and the distance walked so far in each
# frame. --view adds arguments for `cic view` (e.g. "--camera follow
# --no-trail"); with RUN "-" they say what to replay instead, e.g.
# - OUT.png --view "--robot R1 --controller sine:1.1,1,1.571".
# Environment: CIC=path to the cic binary (default: build/cic, then cic on PATH).
set -euo pipefail
usage() { sed -n '2,11p' "$0" >&2; exit 2; }
[ $# -ge 2 ] || usage
RUN=$1 OUT=$2
shift 2
AT="2 5 8 11 14" W=320 H=240 VIEW=""
while [ $# -gt 0 ]; do
  case "$1" in
    --view) VIEW=$2; shift 2 ;;
    --at) AT=$2; shift 2 ;;
    --width) W=$2; shift 2 ;;
    --height) H=$2; shift 2 ;;
    *) echo "screenshot-strip.sh: unknown option '$1'" >&2; usage ;;
  esac
done
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CIC=${CIC:-}
if [ -z "$CIC" ]; then
  # Installed (cic-screenshot-strip beside bin/cic), then the source tree's build, then PATH.
  HERE_BIN="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
  if [ -x "$HERE_BIN/cic" ]; then CIC="$HERE_BIN/cic"
  elif [ -x "$ROOT/build/cic" ]; then CIC="$ROOT/build/cic"
  else CIC=$(command -v cic || true); fi
fi
[ -n "$CIC" ] && [ -x "$CIC" ] || { echo "screenshot-strip.sh: no cic binary (set CIC)" >&2; exit 2; }
INPUT=()
if [ "$RUN" = - ]; then
  [ -n "$VIEW" ] || { echo "screenshot-strip.sh: RUN '-' needs --view saying what to replay" >&2; exit 2; }
else
  [ -e "$RUN" ] || { echo "screenshot-strip.sh: $RUN: no such run folder or file" >&2; exit 2; }
  INPUT=("$RUN")
fi
read -r -a VIEW_ARGS <<< "$VIEW"
TIMES=$(echo $AT | tr ' ' ',')
[ -n "$TIMES" ] || { echo "screenshot-strip.sh: --at gives no time" >&2; exit 2; }
n=$(echo $AT | wc -w)
mkdir -p "$(dirname "$OUT")"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
"$CIC" view "${INPUT[@]}" "${VIEW_ARGS[@]}" --screenshot "$TMP/strip.png" --strip "$TIMES" --width "$W" --height "$H" \
  >"$TMP/view.log" 2>&1 || { cat "$TMP/view.log" >&2; exit 1; }
mv "$TMP/strip.png" "$OUT"
echo "wrote $OUT ($n frames at t = $AT s)"
