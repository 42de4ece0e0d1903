#!/usr/bin/env bash
# scripts/run.sh [SETTINGS] [more cic options...]
# Installs missing dependencies, builds Release into build/ when needed
# (incremental), then runs the main job: cic --settings SETTINGS.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/setup.sh
source "$ROOT/scripts/setup.sh"

SETTINGS="${1:-$ROOT/settings/r1_settings.xml}"
[ $# -gt 0 ] && shift
cic_setup release "$ROOT/build" cic
exec "$ROOT/build/cic" --settings "$SETTINGS" "$@"
