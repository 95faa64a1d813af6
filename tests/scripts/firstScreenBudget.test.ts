/**
 * The first-screen budget check (scripts/firstScreenBudget.mjs, run by scripts/test.sh after the
 * build): which files a page requests before any interaction, their gzip size, and the exit code
 * that fails the suite when a page is over issue 13's 120 kB. Checked on small built-looking folders.
 */
import { execFileSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
// @ts-expect-error: a plain .mjs script without type declarations
import { FIRST_SCREEN_BUDGET_BYTES, firstScreenScripts, measurePage } from '../../scripts/firstScreenBudget.mjs';
import { createRng } from '../fuzz/mutate';

const SCRIPT = join(__dirname, '../../scripts/firstScreenBudget.mjs');

/** A dist folder with index.html and embed.html requesting `entry` and preloading `shared`. */
function fakeDist(shared: Buffer): string {
  const dist = mkdtempSync(join(tmpdir(), 'luxbox-budget-'));
  mkdirSync(join(dist, 'assets'));
  const entry = Buffer.from('import "./app.js";console.log("luxbox");');
  writeFileSync(join(dist, 'assets/main.js'), entry);
  writeFileSync(join(dist, 'assets/app.js'), shared);
  writeFileSync(join(dist, 'assets/lazy.js'), Buffer.alloc(500_000, 7)); // a lazy chunk: never counted
  const html = '<script type="module" crossorigin src="/assets/main.js"></script><link rel="modulepreload" crossorigin href="/assets/app.js">';
  writeFileSync(join(dist, 'index.html'), html);
  writeFileSync(join(dist, 'embed.html'), html);
  return dist;
}

/** Bytes gzip cannot shrink (seeded), so the gzip size is about the raw size. */
function incompressible(n: number): Buffer {
  const rng = createRng(20261124);
  return Buffer.from(Array.from({ length: n }, () => rng.int(256)));
}

describe('first-screen budget script', () => {
  it('counts the entry script and every modulepreload, once each, in document order', () => {
    const html = '<link rel="modulepreload" href="/assets/b.js"><script type="module" src="/assets/a.js"></script><link rel="modulepreload" href="/assets/b.js"><link rel="stylesheet" href="/assets/c.css">';
    expect(firstScreenScripts(html)).toEqual(['assets/a.js', 'assets/b.js']);
  });

  it('measures gzip -9 of those files only, and the budget is 120 000 bytes', () => {
    const shared = incompressible(20_000);
    const dist = fakeDist(shared);
    const page = measurePage(dist, 'index.html');
    expect(page.files.map((f: { file: string }) => f.file)).toEqual(['assets/main.js', 'assets/app.js']);
    const expected = gzipSync(Buffer.from('import "./app.js";console.log("luxbox");'), { level: 9 }).length + gzipSync(shared, { level: 9 }).length;
    expect(page.gzip).toBe(expected);
    expect(FIRST_SCREEN_BUDGET_BYTES).toBe(120_000);
  });

  it('exits 0 under the budget and 1 over it, naming the page', () => {
    const small = fakeDist(incompressible(100_000));
    expect(execFileSync('node', [SCRIPT, small], { encoding: 'utf8' })).toMatch(/index\.html: first screen .* budget 120 kB: ok/);
    const big = fakeDist(incompressible(121_000));
    let status = 0;
    let out = '';
    try {
      execFileSync('node', [SCRIPT, big], { encoding: 'utf8' });
    } catch (e) {
      status = (e as { status: number }).status;
      out = (e as { stdout: string }).stdout;
    }
    expect(status).toBe(1);
    expect(out).toMatch(/embed\.html: first screen .* budget 120 kB: OVER/);
  });
});
