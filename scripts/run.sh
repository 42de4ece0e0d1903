#!/usr/bin/env bash
# scripts/run.sh [SETTINGS] [more cic options...]
# Installs what building and running cic needs (install-deps.sh run: no test,
# fuzzing or video tools), builds Release into build/ when needed (incremental,
# without the tests) with the Python package (build/python: docs/python.md),
# then runs the main job: cic --settings SETTINGS.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# shellcheck source=scripts/setup.sh
source "$ROOT/scripts/setup.sh"

SETTINGS="${1:-$ROOT/settings/r1_settings.xml}"
[ $# -gt 0 ] && shift
CIC_DEPS=run cic_setup release "$ROOT/build" cic cic_python
exec "$ROOT/build/cic" --settings "$SETTINGS" "$@"
