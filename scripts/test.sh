#!/usr/bin/env bash
# The whole test suite: lint, types, unit + headless-gl tests, build, e2e in Chromium, then the
# same scenario in Chromium, Firefox ESR and WebKitGTK (e2e-engines/, docs/browsers.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
# The type check runs beside the lint: each is one thread, so the two share the 2-core CI machine's cores
# (docs/benchmarks.md, "Test suite time"); its output is printed under its own heading once the lint is through.
typecheckLog=$(mktemp)
node_modules/.bin/tsc --noEmit >"$typecheckLog" 2>&1 &
typecheckPid=$!
trap 'kill "$typecheckPid" 2>/dev/null || true; rm -f "$typecheckLog"' EXIT
echo "== lint";       npx eslint . && npx prettier --check .
echo "== typecheck"
typecheckStatus=0
wait "$typecheckPid" || typecheckStatus=$?
cat "$typecheckLog"
[ "$typecheckStatus" -eq 0 ]
echo "== unit + headless WebGL (vitest under xvfb)"
# Issue 11's bar: 10 000 seeded random action sequences in the always-valid property test (about
# 3 ms each since the model caches its derived data; docs/benchmarks.md, "Test suite time").
# One fork per core: Vitest's default keeps a core for its main process, one fork on the 2-core CI machine.
ALWAYS_VALID_RUNS=10000 xvfb-run -a npx vitest run --maxWorkers=100%
echo "== build";      npx vite build
echo "== first-screen download budget (docs/benchmarks.md)"; node scripts/firstScreenBudget.mjs dist
# What ships (docs/package.md, "Checking the package"; about 2 min): the package built with its public API
# against the reviewed reports (docs/api), packed, installed into a fresh consumer outside the repository,
# type-checked, its bin and engine run, and its React page and element page opened in Chromium (issue 33).
echo "== npm package: API report, tarball in a fresh consumer (docs/package.md)"; node scripts/checkPackage.mjs
echo "== e2e (Playwright, Debian chromium)"
npx playwright test
echo "== cross-engine e2e (Chromium, Firefox ESR, WebKitGTK; xvfb)"
xvfb-run -a npx vitest run -c e2e-engines/vitest.config.ts
