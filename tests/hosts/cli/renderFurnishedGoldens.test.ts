import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { furnishedSceneFile, GOLDEN_CAMERAS, GOLDEN_QUALITY, GOLDEN_TOLERANCE, GOLDENS_DIR, goldenFile, goldenRoomsToRun } from '../../../e2e-engines/furnishedGoldens';
import { formatDifference, imageDifference, withinTolerance } from '../../../e2e-engines/imageDifference';
import { QUALITY_LEVELS } from '../../../src/engines/relight/qualityLevels';
import { VIEWER_BAKE_SETTINGS } from '../../../src/engines/relight/createRelightEngine';

/**
 * `luxbox render` of the furnished goldens' views equals the browser's (issue 26): the same scene
 * files, the eye and corner cameras at the browser canvas's size, the bake settings of the
 * browser's quality level, compared with the reviewed goldens (taken in Chromium; the three
 * engines are compared with the same goldens in e2e-engines/furnishedGoldens.engines.ts) within
 * the same tolerance. One process, one bake per room. Pictures beyond the tolerance go to
 * test-results/goldens/.
 */
const ROOT = join(__dirname, '../../..');
const OUT = mkdtempSync(join(tmpdir(), 'luxbox-furnished-'));
/** The living room by default (one bake); LUXBOX_GOLDEN_ROOMS=all adds the dining room and the shop window. */
const ROOMS = goldenRoomsToRun();

/** The browser's quality level as `luxbox render` flags (one definition: QUALITY_LEVELS). */
function qualityFlags(): string[] {
  const q = QUALITY_LEVELS[GOLDEN_QUALITY];
  return ['--texel', String(q.texelSize), '--max-texture', String(q.maxTextureSize), '--samples', String(q.samples), '--bounces', String(q.bounces), '--blur', String(q.blurRadius)];
}

describe('luxbox render of the furnished goldens', () => {
  it('has no flag for the samples per draw: the level uses the CLI default', () => {
    expect(QUALITY_LEVELS[GOLDEN_QUALITY].samplesPerDraw).toBe(VIEWER_BAKE_SETTINGS.samplesPerDraw);
  });

  it(`draws ${ROOMS.join(', ')} at eye height and from the corner as the browser does (within the golden tolerance)`, { timeout: 600_000 }, () => {
    const size = PNG.sync.read(readFileSync(join(ROOT, GOLDENS_DIR, goldenFile('living-room', 'eye'))));
    const files = ROOMS.map((room) => {
      const file = join(OUT, `${room}.luxbox.json`);
      writeFileSync(file, furnishedSceneFile(room));
      return file;
    });
    const out = join(OUT, 'images') + '/';
    const args = ['render', ...files, '--camera', GOLDEN_CAMERAS.join(','), '--width', String(size.width), '--height', String(size.height), ...qualityFlags(), '--out', out];
    const run = spawnSync(process.execPath, [join(ROOT, 'bin/luxbox.js'), ...args], { cwd: ROOT, encoding: 'utf8', timeout: 580_000 });
    expect(run.status, run.stderr).toBe(0);
    const failures: string[] = [];
    for (const room of ROOMS) {
      for (const camera of GOLDEN_CAMERAS) {
        const name = goldenFile(room, camera);
        const actual = PNG.sync.read(readFileSync(join(out, `${room}-${camera}.png`)));
        const golden = PNG.sync.read(readFileSync(join(ROOT, GOLDENS_DIR, name)));
        const difference = imageDifference(actual, golden);
        console.log(`luxbox render ${room} ${camera} against the browser's golden: ${formatDifference(difference)}`);
        if (!withinTolerance(difference, GOLDEN_TOLERANCE)) {
          const dir = join(ROOT, 'test-results/goldens');
          mkdirSync(dir, { recursive: true });
          writeFileSync(join(dir, name.replace('.png', '.cli.png')), PNG.sync.write(actual));
          failures.push(`${room} ${camera}: ${formatDifference(difference)}`);
        }
      }
    }
    expect(failures, `beyond the tolerance (mean ≤ ${GOLDEN_TOLERANCE.mean}, p90 ≤ ${GOLDEN_TOLERANCE.p90})`).toEqual([]);
  });
});
