/** `luxbox export radiance` from the command line: the folder for both input kinds, and clear one-line errors. */
import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, statSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

const root = join(__dirname, '../../..');

function luxbox(args: string[]) {
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('luxbox export radiance', () => {
  it('a configurator scene file: catalog photometry, every module a luminaire, an executable render.sh', () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-export-'));
    const r = luxbox(['export', 'radiance', 'tests/fixtures/configurations/corner-l.luxbox.json', '--out', out]);
    expect(r.stderr).toBe('');
    expect(r.status).toBe(0);
    expect(r.stdout).toMatch(/files \(scene\.rad, render\.sh, README\.md, \d+ distributions\)/);
    const rad = readFileSync(join(out, 'scene.rad'), 'utf8');
    expect(rad).toMatch(/^# corner-l\.luxbox: exported by luxbox for Radiance\./);
    expect(rad.match(/ light lum\d+_light/g)!.length).toBeGreaterThan(2);
    expect(statSync(join(out, 'render.sh')).mode & 0o111).not.toBe(0);
    for (const dat of rad.matchAll(/corr (\S+) source\.cal/g)) expect(existsSync(join(out, dat[1]))).toBe(true);
  });

  it('--near-field point: one sphere per luminaire', () => {
    const out = mkdtempSync(join(tmpdir(), 'luxbox-export-'));
    expect(luxbox(['export', 'radiance', 'tests/fixtures/scenes/small-room.json', '--near-field', 'point', '--out', out]).status).toBe(0);
    expect(readFileSync(join(out, 'scene.rad'), 'utf8').match(/ sphere /g)).toHaveLength(2);
  });

  it.each([
    [['export', 'obj', 'x.json', '--out', '/tmp/x'], /^luxbox export: unknown format "obj" \(usage: luxbox export radiance/],
    [['export', 'radiance', 'tests/fixtures/scenes/small-room.json'], /^luxbox export: radiance: --out <dir> is required/],
    [['export', 'radiance', '--out', '/tmp/x'], /^luxbox export: radiance: expected one scene file/],
    [['export', 'radiance', 'tests/fixtures/scenes/nope.json', '--out', '/tmp/x'], /^luxbox export: nope\.json: cannot read .*no such file/],
    [['export', 'radiance', 'tests/fixtures/scenes/small-room.json', '--out', '/tmp/x', '--near-field', 'far'], /^luxbox export: radiance: --near-field must be split or point, got "far"/],
  ])('%j fails with one clear line', (args, message) => {
    const r = luxbox(args as string[]);
    expect(r.status).not.toBe(0);
    expect(r.stderr).toMatch(message);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
  });
});
