/** `luxbox probe` on a room of any shape (issue 29): every point checked against the room's own surfaces, each refusal naming the point; sound points are baked and probed. */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it, vi } from 'vitest';
import { run } from '../../../src/hosts/cli/probeCommand';

const SCENE = 'tests/fixtures/scenes/attic-l-room.json';
const dir = mkdtempSync(join(tmpdir(), 'luxbox-probe-shape-'));
const pointsFile = (points: number[][]): string => {
  const path = join(dir, `p${Math.random().toString(36).slice(2)}.json`);
  writeFileSync(path, JSON.stringify({ points }));
  return path;
};
// The scene names ../models/table.obj, outside its folder: given with --allow.
const probe = (points: number[][]) => run([SCENE, pointsFile(points), '--allow', 'tests/fixtures/models']);

describe('probe in a room of any shape', () => {
  it('refuses a point in the notch, in the door, or off every surface, naming it and the nearest surface', async () => {
    await expect(
      probe([
        [1, 0, 1],
        [5, 0, 4],
      ]),
    ).rejects.toThrow(/: points\[1\]: \[5, 0, 4\] is on no surface of the room \(nearest: wall-2, 1\.00 m away\); probe points must lie within 0\.01 m of a surface$/);
    await expect(probe([[2.2, 1, 5]])).rejects.toThrow(/: points\[0\]: \[2\.2, 1, 5\] lies in opening 0 of wall-4, where the room has no surface$/);
    await expect(
      probe([
        [1, 0, 1, 0, 1, 0],
        [5, 1, 4, 0, 1, 0],
      ]),
    ).rejects.toThrow(/: points\[1\]: \[5, 1, 4\] is outside the room \(its outline, floor, ceiling and slopes\)$/);
  });

  it('bakes the room and prints the light at points on the floor, the slope and two walls, and at a plane point', async () => {
    const t = Math.tan((40 * Math.PI) / 180);
    const points = [
      [1, 0, 1],
      [2, 1.2 + 0.5 * t, 0.5],
      [6, 1, 1],
      [3.5, 1, 4],
      [2, 1, 3, 0, 1, 0],
    ];
    const write = vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
    try {
      // Coarse and quick: what is checked here is the command; the accuracy is tests/hosts/node/shapedRoomProbe.test.ts's.
      // The fixture's table lies in tests/fixtures/models, beside the scene's folder: named with --allow (docs/scene-format.md).
      await expect(run([SCENE, pointsFile(points), '--texel', '0.2', '--samples', '8', '--bounces', '1', '--allow', 'tests/fixtures/models'])).resolves.toBe(0);
      const printed = JSON.parse(String(write.mock.calls.at(-1)![0])) as { total: number[]; direct: number[]; indirect: number[] };
      expect(Object.keys(printed)).toEqual(['total', 'direct', 'indirect']);
      for (const key of ['total', 'direct', 'indirect'] as const) expect(printed[key]).toHaveLength(points.length);
      printed.total.forEach((total, i) => {
        expect(printed.direct[i]).toBeGreaterThan(0);
        expect(printed.indirect[i]).toBeGreaterThan(0);
        expect(total).toBeCloseTo(printed.direct[i] + printed.indirect[i], 6);
      });
    } finally {
      write.mockRestore();
    }
  }, 120_000);
});
