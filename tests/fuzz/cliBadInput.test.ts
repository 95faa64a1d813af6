/**
 * `luxbox bake` on hostile scene files (issue 18): one line on stderr, exit 1,
 * never a stack trace — before issue 18 a 5000-deep field printed an 18-line
 * RangeError trace.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';

const root = process.cwd();
const dir = mkdtempSync(join(tmpdir(), 'luxbox-bad-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

const regression = (name: string) => readFileSync(join(root, 'tests/fixtures/fuzz-regressions/scene', name), 'utf8');

function bake(name: string, text: string): { status: number | null; stderr: string } {
  const file = join(dir, name);
  writeFileSync(file, text);
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), 'bake', file, '--out', join(dir, 'out')], { cwd: root, encoding: 'utf8' });
  return { status: r.status, stderr: r.stderr };
}

describe('luxbox bake on hostile input', () => {
  it.each([
    ['deep.json', regression('issue18-dimming-nested-5000.bin'), /^luxbox bake: deep\.json: luminaires\[0\]\.dimming(\[0\])+…?: nested deeper than 32 levels$/],
    ['typo.json', regression('issue18-misspelt-dimming.bin'), /^luxbox bake: typo\.json: luminaires\[0\]\.dimmming: unknown field 'dimmming' \(did you mean 'dimming'\?\)$/],
    ['huge.json', `{"version":1,"luminaires":[${'0,'.repeat(600_000)}0]}`, /^luxbox bake: huge\.json: file is too large \(1\.2 MB; at most 1 MB\)$/],
    ['dup.json', '{"version":1,"version":2}', /^luxbox bake: dup\.json: line 1, column 14: field 'version' appears twice in one object$/],
  ])('%s: one line, exit 1', (name, text, message) => {
    const r = bake(name, text);
    expect(r.status).toBe(1);
    const lines = r.stderr.split('\n').filter((l) => l.length > 0 && !l.startsWith('npm warn'));
    expect(lines).toHaveLength(1);
    expect(lines[0]).toMatch(message);
    expect(lines[0].length).toBeLessThanOrEqual(220); // "luxbox bake: " + a message of at most 200
  });
});
