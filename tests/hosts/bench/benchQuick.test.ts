/**
 * `luxbox bench --quick` machinery end to end (~10 s): it bakes on headless-gl,
 * compares with the CPU reference and prints well-formed markdown tables. The
 * full benchmark never runs in CI.
 */
import { describe, expect, it } from 'vitest';
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const root = fileURLToPath(new URL('../../..', import.meta.url));

describe('luxbox bench --quick', () => {
  it('prints the error-vs-time table and the scaling table with plausible numbers', () => {
    const run = spawnSync(process.execPath, ['bin/luxbox.js', 'bench', '--quick'], { cwd: root, encoding: 'utf8', timeout: 110_000 });
    expect(run.status, run.stderr).toBe(0);
    const lines = run.stdout.split('\n');
    const header = lines.findIndex((l) => l.startsWith('| scene | method | rung | texel | samples | bounces |'));
    expect(header).toBeGreaterThan(0);
    const rows = lines.slice(header + 2).filter((l) => l.startsWith('| cie-cube |'));
    // Two rungs, each with today's method and the Monte Carlo-only one beside it.
    expect(rows).toHaveLength(4);
    expect(rows.filter((r) => r.includes('| Monte Carlo only |'))).toHaveLength(2);
    for (const row of rows) {
      const cells = row
        .split('|')
        .slice(1, -1)
        .map((c) => c.trim());
      expect(cells).toHaveLength(14);
      const [rms, max] = [parseFloat(cells[9]), parseFloat(cells[10])];
      // A real bake against the converged reference: errors finite, > 0 (Monte Carlo noise), RMS ≤ max, and the
      // cheapest rung of the CIE cube still within 20 % RMS.
      expect(rms).toBeGreaterThan(0);
      expect(rms).toBeLessThanOrEqual(max);
      expect(rms).toBeLessThan(20);
      const [bake, ref] = cells[13].split('/').map((s) => parseFloat(s));
      // Mean total over the cube's points vs Φ/(S(1−ρ)) = 520.8 lx (the points are cell centres, not an area mean).
      expect(Math.abs(ref - 520.8) / 520.8).toBeLessThan(0.02);
      expect(Math.abs(bake - ref) / ref).toBeLessThan(0.05);
    }
    expect(run.stdout).toMatch(/\| luminaires \| 1 \| 1 \|/);
    expect(run.stdout).toMatch(/Machine: .+ logical cores/);
  });

  it('rejects unknown arguments with one line and exit code 1', () => {
    const run = spawnSync(process.execPath, ['bin/luxbox.js', 'bench', '--fast'], { cwd: root, encoding: 'utf8' });
    expect(run.status).toBe(1);
    expect(run.stderr.trim().split('\n')).toHaveLength(1);
    expect(run.stderr).toMatch(/unknown argument "--fast"/);
  });
});
