#!/usr/bin/env bash
# scripts/tune-sine.sh ROBOT [cic simulate options...]
# Grid search over sine gaits (amplitude x frequency x phase step between joints) with
# `cic simulate`, printing the ten best: a hand-tuned baseline to compare evolved
# controllers with. ROBOT is R0|R1|R2 or a robot file. Uses the default simulator settings
# unless --settings FILE is passed through.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CIC="${CIC:-$ROOT/build/cic}"
[ $# -ge 1 ] || { sed -n '2,6p' "$0"; exit 2; }
robot="$1"; shift
[ -x "$CIC" ] || { echo "tune-sine.sh: no $CIC; build first (scripts/run.sh builds it)" >&2; exit 2; }
for a in 0.3 0.5 0.8 1.1 1.5; do
  for f in 0.25 0.5 0.75 1 1.5 2; do
    for p in 0 0.785 1.571 2.356 3.142 4.712; do
      fit=$("$CIC" simulate --robot "$robot" --controller "sine:$a,$f,$p" "$@" | awk '/^fitness/ {print $2}')
      echo "$fit sine:$a,$f,$p"
    done
  done
done | sort -gr | head -10
