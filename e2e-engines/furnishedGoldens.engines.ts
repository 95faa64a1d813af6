import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { mkdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { PNG } from 'pngjs';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { launchChromium } from './chromiumDriver';
import type { EngineDriver, EngineName } from './engineDriver';
import { launchFirefox } from './firefoxDriver';
import { goldenFile, goldenRoomsToRun, GOLDEN_TOLERANCE, GOLDENS_DIR } from './furnishedGoldens';
import { captureFurnishedViews, type FurnishedView } from './furnishedViewsScenario';
import { formatDifference, imageDifference, withinTolerance, type ImageDifference } from './imageDifference';
import { startPreview, type PreviewServer } from './previewServer';
import { launchWebkit } from './webkitDriver';

/**
 * The furnished living room, dining room and shop window at eye height and from the corner in
 * Chromium, Firefox ESR and WebKitGTK, each compared with the reviewed golden of its view
 * (tests/goldens/furnished-*.png, taken in Chromium and looked at). Tolerance: GOLDEN_TOLERANCE
 * (mean and 90th percentile of the per-pixel difference; docs/viewer.md, "Furnished goldens").
 * LUXBOX_UPDATE_GOLDENS=1 writes Chromium's pictures as the new goldens (review them before
 * committing); LUXBOX_GOLDEN_ROOMS=all (or a comma list) compares more rooms than the living room alone. Pictures and report.json go to
 * LUXBOX_ENGINES_OUT/goldens (else test-results/engines/goldens).
 */
const LAUNCH: Record<EngineName, () => Promise<EngineDriver>> = { chromium: launchChromium, firefox: launchFirefox, webkit: launchWebkit };
const ENGINES = (process.env.LUXBOX_ENGINES ?? 'chromium,firefox,webkit').split(',').map((e) => e.trim()) as EngineName[];
const ROOMS = goldenRoomsToRun();
const OUT_DIR = join(process.env.LUXBOX_ENGINES_OUT ?? 'test-results/engines', 'goldens');
const UPDATE = process.env.LUXBOX_UPDATE_GOLDENS === '1';
// WebKitGTK bakes the furnished rooms several times slower than the other engines (docs/browsers.md).
const BAKE_TIMEOUT_MS = 600_000;

let server: PreviewServer;
const report: Record<string, { bakeMs: number; difference: ImageDifference | null }> = {};

beforeAll(async () => {
  for (const e of ENGINES) if (!(e in LAUNCH)) throw new Error(`LUXBOX_ENGINES: unknown engine "${e}" (chromium, firefox, webkit)`);
  server = await startPreview();
});

afterAll(async () => {
  await server?.stop();
  await mkdir(OUT_DIR, { recursive: true });
  await writeFile(join(OUT_DIR, 'report.json'), JSON.stringify(report, null, 2));
});

/** The golden of the view, written from Chromium's picture under LUXBOX_UPDATE_GOLDENS=1. */
function golden(engine: EngineName, view: FurnishedView): PNG {
  const file = join(GOLDENS_DIR, goldenFile(view.room, view.camera));
  if (UPDATE && engine === 'chromium') writeFileSync(file, PNG.sync.write(view.image));
  if (!existsSync(file)) throw new Error(`golden ${file} is missing: run the Chromium suite with LUXBOX_UPDATE_GOLDENS=1 and review it`);
  return PNG.sync.read(readFileSync(file));
}

describe.sequential('furnished goldens in three engines', () => {
  for (const engine of ENGINES) {
    test(`${engine}: ${ROOMS.join(', ')} at eye height and from the corner match the reviewed goldens`, { timeout: ROOMS.length * BAKE_TIMEOUT_MS + 60_000 }, async () => {
      const driver = await LAUNCH[engine]();
      let views: FurnishedView[];
      try {
        views = await captureFurnishedViews(driver, server.url, OUT_DIR, ROOMS, BAKE_TIMEOUT_MS);
      } finally {
        await driver.close();
      }
      const failures: string[] = [];
      for (const view of views) {
        const expected = golden(engine, view);
        const difference = imageDifference(view.image, expected);
        report[`${engine} ${view.room} ${view.camera}`] = { bakeMs: view.bakeMs, difference };
        console.log(`${engine} ${view.room} ${view.camera}: bake ${view.bakeMs} ms; against the golden ${formatDifference(difference)}`);
        if (!withinTolerance(difference, GOLDEN_TOLERANCE)) failures.push(`${view.room} ${view.camera}: ${formatDifference(difference)} (picture: ${view.path})`);
      }
      expect(failures, `beyond the tolerance (mean ≤ ${GOLDEN_TOLERANCE.mean}, p90 ≤ ${GOLDEN_TOLERANCE.p90})`).toEqual([]);
    });
  }
});
