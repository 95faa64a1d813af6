/**
 * The package's first-screen budgets (scripts/packageBudgets.mjs, checked by scripts/checkPackage.mjs
 * on the packed tarball): issue 33's limits, 110 kB for what `luxbox/react` adds to a React page and
 * 150 kB for the single-file element, and the static-import closure the element's size is counted over.
 */
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
// @ts-expect-error: a plain .mjs script without type declarations
import { budgetFailures, gzipBytes, REACT_DOOR_BUDGET_BYTES, STANDALONE_BUDGET_BYTES, staticClosure } from '../../scripts/packageBudgets.mjs';

describe('package budgets', () => {
  it('are the issue’s limits, kB = 1000 B', () => {
    expect(REACT_DOOR_BUDGET_BYTES).toBe(110_000);
    expect(STANDALONE_BUDGET_BYTES).toBe(150_000);
  });

  it('fail a door one byte over its limit and pass it at the limit', () => {
    expect(budgetFailures({ reactAdds: 110_000, standalone: 150_000 })).toEqual([]);
    expect(budgetFailures({ reactAdds: 110_001, standalone: 150_000 })).toEqual(['luxbox/react adds 110001 B, over 110000 B']);
    expect(budgetFailures({ reactAdds: 108_100, standalone: 150_001 })).toEqual(["the single-file element's first screen is 150001 B, over 150000 B"]);
    expect(budgetFailures({ reactAdds: 112_400, standalone: 151_700 })).toHaveLength(2);
  });

  it('count what an entry imports statically, transitively, and never a lazy chunk', () => {
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-package-budget-'));
    mkdirSync(join(dir, 'chunks'));
    writeFileSync(join(dir, 'luxbox-element.js'), 'import { a } from "./chunks/first-screen.js";\nexport * from "./chunks/types.js";\nconst lazy = () => import("./chunks/view3d.js");\nconsole.log(a, lazy);');
    writeFileSync(join(dir, 'chunks/first-screen.js'), 'import "../side.js";\nexport const a = 1;');
    writeFileSync(join(dir, 'chunks/types.js'), 'export const t = 2;');
    writeFileSync(join(dir, 'side.js'), 'globalThis.x = 3;');
    writeFileSync(join(dir, 'chunks/view3d.js'), 'export const big = "' + 'x'.repeat(100_000) + '";');
    const files = staticClosure(dir, ['luxbox-element.js']);
    expect([...files].sort()).toEqual(['chunks/first-screen.js', 'chunks/types.js', 'luxbox-element.js', 'side.js']);
    // Each file gzipped alone at level 9, as a server sends it.
    const expected = files.reduce((sum: number, f: string) => sum + gzipSync(readFileSync(join(dir, f)), { level: 9 }).length, 0);
    expect(gzipBytes(dir, files)).toBe(expected);
  });
});
