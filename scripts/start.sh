#!/usr/bin/env bash
# Starts the configurator (Vite dev server) on the default demo scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec npx vite --host "${HOST:-localhost}" --port "${PORT:-5173}"
