/**
 * `luxbox probe`'s points file is strict (issue 18): an unknown field is one
 * stderr line naming it (with a suggestion for a misspelling), exit 1.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

const root = join(__dirname, '../../..');
const scene = join(root, 'tests/fixtures/scenes/small-room.json');

function probe(points: unknown) {
  const dir = mkdtempSync(join(tmpdir(), 'luxbox-points-'));
  const file = join(dir, 'points.json');
  writeFileSync(file, JSON.stringify(points));
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), 'probe', scene, file], { cwd: root, encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('luxbox probe: points file', () => {
  const cases: [string, unknown, string][] = [
    ['misspelt "points"', { pointz: [[1.5, 0, 1]] }, "points.json: pointz: unknown field 'pointz' (did you mean 'points'?)"],
    ['an extra field beside "points"', { points: [[1.5, 0, 1]], units: 'm' }, "points.json: units: unknown field 'units'"],
  ];
  for (const [name, points, message] of cases) {
    it(`refuses ${name}: one stderr line, exit 1`, () => {
      const r = probe(points);
      expect(r.status).toBe(1);
      expect(r.stdout).toBe('');
      expect(r.stderr).toBe(`luxbox probe: ${message}\n`);
    });
  }

  it('still reports a missing "points" as the expected shape', () => {
    const r = probe({});
    expect(r.status).toBe(1);
    expect(r.stderr).toMatch(/^luxbox probe: points\.json: points: /);
  });
});
