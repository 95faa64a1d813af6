import { spawnSync } from 'node:child_process';
import { describe, expect, it } from 'vitest';
import { listFilters } from '../../../src/hosts/cli/filtersCommand';

function luxbox(...args: string[]): { status: number | null; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, ['bin/luxbox.js', ...args], { encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('luxbox filters', () => {
  it('--json lists the library for a 3000 K source by default; --cct changes the source', () => {
    const r = luxbox('filters', '--json');
    expect(r.status).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out.sourceCct).toBe(3000);
    expect(out.filters).toHaveLength(43);
    expect(out).toEqual(listFilters(3000));
    const nd = out.filters.find((f: { id: string }) => f.id === 'lee-209');
    // 0.3 ND: ≈ 50 % (LEE states 50.0 % tungsten), near white, a little above the locus.
    expect(nd).toMatchObject({ maker: 'LEE Filters', number: '209', name: '0.3ND', kind: 'nd' });
    expect(Math.abs(nd.transmission - 0.5)).toBeLessThan(0.007);
    expect(nd.cct).toBeGreaterThan(3000);
    const hot = JSON.parse(luxbox('filters', '--json', '--cct', '3200').stdout);
    const ctb = hot.filters.find((f: { id: string }) => f.id === 'lee-201');
    // Full CTB on 3200 K: 5689 K measured (LEE: "3200 K to 5700 K"; see docs/colour-filters.md).
    expect(ctb.cct).toBeGreaterThan(5650);
    expect(ctb.cct).toBeLessThan(5730);
    const red = hot.filters.find((f: { id: string }) => f.id === 'lee-106');
    expect(red).toMatchObject({ cct: null, duv: null });
    expect(Math.abs(red.x - 0.693)).toBeLessThan(0.003); // LEE's stated tungsten x for 106
  });

  it('text output: one row per filter with x, y, transmission and CCT/Duv where near white', () => {
    const r = luxbox('filters', '--cct', '3200');
    expect(r.status).toBe(0);
    const lines = r.stdout.trimEnd().split('\n');
    expect(lines[0]).toMatch(/^43 colour filters through a 3200 K Planckian source/);
    expect(lines[1]).toMatch(/^id\s+filter\s+kind\s+x\s+y\s+transmission\s+CCT\s+Duv$/);
    expect(lines).toHaveLength(45);
    expect(lines.find((l) => l.startsWith('lee-201'))).toMatch(/LEE 201 Full C\.T\. Blue\s+ctb\s+0\.328\d\s+0\.339\d\s+33\.0 %\s+56[5-9]\d K\s+0\.00\d\d$/);
    expect(lines.find((l) => l.startsWith('lee-106'))).toMatch(/12\.7 %$/);
  });

  it('refuses a bad --cct and unknown arguments in one line, exit 1', () => {
    for (const args of [['--cct', '500'], ['--cct'], ['--cct', 'warm'], ['--csv']]) {
      const r = luxbox('filters', ...args);
      expect(r.status).toBe(1);
      expect(r.stderr.trim().split('\n')).toHaveLength(1);
      expect(r.stderr).toMatch(/^luxbox filters: (--cct needs a colour temperature from 1000 to 20000 K|unknown argument --csv)/);
    }
  });
});
