#!/usr/bin/env bash
# The whole test suite: lint, types, unit + headless-gl tests, build, e2e in Chromium, then the
# same scenario in Chromium, Firefox ESR and WebKitGTK (e2e-engines/, docs/browsers.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
echo "== lint";       npx eslint . && npx prettier --check .
echo "== typecheck";  npx tsc --noEmit
echo "== unit + headless WebGL (vitest under xvfb)"
# Issue 11's bar: 10 000 seeded random action sequences in the always-valid property test (about
# 3 ms each since the model caches its derived data; docs/benchmarks.md, "Test suite time").
# One fork per core: Vitest's default keeps a core for its main process, one fork on the 2-core CI machine.
ALWAYS_VALID_RUNS=10000 xvfb-run -a npx vitest run --maxWorkers=100%
echo "== build";      npx vite build
echo "== first-screen download budget (docs/benchmarks.md)"; node scripts/firstScreenBudget.mjs dist
# The npm package's public API against its reviewed reports (docs/package.md, "API report"; ~1 min).
# The whole package (pack, install, consumer pages) is `node scripts/checkPackage.mjs`, ~4 min, run by hand.
echo "== npm package API report (docs/api)"; node scripts/packageApi.mjs
echo "== e2e (Playwright, Debian chromium)"
npx playwright test
echo "== cross-engine e2e (Chromium, Firefox ESR, WebKitGTK; xvfb)"
xvfb-run -a npx vitest run -c e2e-engines/vitest.config.ts
