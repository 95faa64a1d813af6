import { mkdir, writeFile } from 'node:fs/promises';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, test } from 'vitest';
import { launchChromium } from './chromiumDriver';
import { runCrossEngineScenario, type EngineReport, type FloorStats } from './crossEngineScenario';
import { VIEWPORT, type EngineDriver, type EngineName } from './engineDriver';
import { launchFirefox } from './firefoxDriver';
import { startPreview, type PreviewServer } from './previewServer';
import { launchWebkit } from './webkitDriver';

const LAUNCH: Record<EngineName, () => Promise<EngineDriver>> = { chromium: launchChromium, firefox: launchFirefox, webkit: launchWebkit };
const ENGINES = (process.env.LUXBOX_ENGINES ?? 'chromium,firefox,webkit').split(',').map((e) => e.trim()) as EngineName[];
// 'fast' keeps each engine's bake under about a minute on software GL (docs/viewer.md, "Quality levels");
// the three engines bake the same scene at the same level, which is what is compared.
const QUALITY = process.env.LUXBOX_ENGINES_QUALITY ?? 'fast';
const BAKE_TIMEOUT_MS = 150_000;
/** Largest relative spread of a floor statistic across the engines (issue 13). */
const TOLERANCE = 0.005;
/** Screenshots, saved scene files and report.json (LUXBOX_ENGINES_OUT, else test-results/engines). */
const OUT_DIR = process.env.LUXBOX_ENGINES_OUT ?? 'test-results/engines';

let server: PreviewServer;
const reports = new Map<EngineName, EngineReport>();

beforeAll(async () => {
  for (const e of ENGINES) if (!(e in LAUNCH)) throw new Error(`LUXBOX_ENGINES: unknown engine "${e}" (chromium, firefox, webkit)`);
  await mkdir(OUT_DIR, { recursive: true });
  server = await startPreview();
});

afterAll(async () => {
  await server?.stop();
  await mkdir(OUT_DIR, { recursive: true });
  await writeFile(join(OUT_DIR, 'report.json'), JSON.stringify(Object.fromEntries(reports), null, 2));
});

describe.sequential('the built app in three engines', () => {
  for (const engine of ENGINES) {
    test(`${engine}: room setup → L-corner → 3D bake → relight → lux → save/open`, async () => {
      const driver = await LAUNCH[engine]();
      try {
        const report = await runCrossEngineScenario(driver, server.url, OUT_DIR, QUALITY, BAKE_TIMEOUT_MS);
        reports.set(engine, report);
        console.log(
          `${engine}: floor Ē ${report.baked.avg.toFixed(2)} lx, Emin ${report.baked.min.toFixed(2)}, Emax ${report.baked.max.toFixed(2)}; dimmed Ē ${report.dimmed.avg.toFixed(2)}; price ${report.price}; first light ${report.firstLitMs} ms, bake ${report.bakeMs} ms, all ${report.totalMs} ms`,
        );
        // One module of six off: the floor is darker, but not dark.
        expect(report.dimmed.avg).toBeLessThan(report.baked.avg * 0.97);
        expect(report.dimmed.avg).toBeGreaterThan(report.baked.avg * 0.5);
      } finally {
        await driver.close();
      }
    });
  }

  test('the engines agree: floor statistics within 0.5 % of Chromium and of each other; the same price and room', () => {
    const missing = ENGINES.filter((e) => !reports.has(e));
    expect(missing, `engines whose scenario failed: ${missing.join(', ')}`).toEqual([]);
    const all = ENGINES.map((e) => reports.get(e)!);
    const reference = reports.get('chromium') ?? all[0];
    for (const phase of ['baked', 'dimmed'] as const) {
      for (const key of ['avg', 'min', 'max'] as const satisfies readonly (keyof FloorStats)[]) {
        const values = all.map((r) => r[phase][key]);
        const spread = (Math.max(...values) - Math.min(...values)) / reference[phase][key];
        expect(spread, `${phase} floor ${key}: ${all.map((r) => `${r.engine} ${r[phase][key]}`).join(', ')}`).toBeLessThanOrEqual(TOLERANCE);
        for (const r of all) expect(Math.abs(r[phase][key] - reference[phase][key]) / reference[phase][key]).toBeLessThanOrEqual(TOLERANCE);
      }
    }
    for (const r of all) {
      expect(r.price, `${r.engine} shows the price as ${r.price}, ${reference.engine} as ${reference.price}`).toBe(reference.price);
      expect(r.room).toEqual(reference.room);
      expect(r.viewport, `${r.engine} viewport`).toEqual([VIEWPORT.width, VIEWPORT.height]);
      expect(r.floorRow).toBe(reference.floorRow);
    }
  });
});
