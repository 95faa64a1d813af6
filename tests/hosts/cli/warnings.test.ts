/**
 * Photometry warnings (issue 18) in `luxbox bake`: report.json's `warnings`
 * (`<file>: <warning>`, each file once) and one stderr line each; none and an
 * empty stderr for a clean scene.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

const root = join(__dirname, '../../..');
const warned = join(root, 'tests/fixtures/scenes/warned-room.json');
const clean = join(root, 'tests/fixtures/scenes/small-room.json');
// warned-room names ../photometry/: outside its folder, so given with --allow (docs/scene-format.md, "Which files a scene may name").
const quick = ['--texel', '0.25', '--samples', '8', '--bounces', '1', '--allow', 'tests/fixtures/photometry'];

function luxbox(args: string[]) {
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

const expected = [
  '../photometry/lumens_mismatch_60x.ies: stated lumens 34 lm and integrated flux 2047 lm differ by 5921 % (ratio 60.21); the integrated flux of the candela data is used',
  '../photometry/c_full_360_seam_differs.ies: the 360° plane differs from the 0° plane (by up to 30 cd, 16.7 % of their peak, at γ 0°); the 0° plane is used for both',
];

describe('luxbox bake: photometry warnings', () => {
  it('report.json carries them as "warnings", stderr has one line each, exit 0', () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-warn-'));
    const r = luxbox(['bake', warned, '--out', out, ...quick]);
    expect(r.status).toBe(0);
    const report = JSON.parse(readFileSync(join(out, 'report.json'), 'utf8'));
    // The file used by two luminaires is reported once.
    expect(report.warnings).toEqual(expected);
    expect(r.stderr).toBe(expected.map((w) => `luxbox bake: warning: ${w}\n`).join(''));
    for (const line of r.stderr.trimEnd().split('\n')) expect(line.length).toBeLessThanOrEqual(300);
  });

  it('a clean scene: "warnings": [] and nothing on stderr', () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-warn-'));
    const r = luxbox(['bake', clean, '--out', out, ...quick]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(JSON.parse(readFileSync(join(out, 'report.json'), 'utf8')).warnings).toEqual([]);
  });

  it("a batch: each report has its own scene's warnings, stderr each line once", () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-warn-'));
    const r = luxbox(['bake', clean, warned, warned, '--out', out, ...quick]);
    expect(r.status).toBe(0);
    expect(r.stderr).toBe(expected.map((w) => `luxbox bake: warning: ${w}\n`).join(''));
    const reports = ['small-room', 'warned-room', 'warned-room-2'].map((n) => JSON.parse(readFileSync(join(out, n, 'report.json'), 'utf8')));
    expect(reports.map((rep) => rep.warnings)).toEqual([[], expected, expected]);
  });
});
