import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { FURNISHED_PRESETS } from '../src/core/catalog/furnishedPresets';
import { serializeConfiguration } from '../src/core/model/files/sceneFile';
import type { QualityLevel } from '../src/engines/relight/qualityLevels';
import type { CameraPresetName } from '../src/engines/view/cameraPresets';
import type { GoldenTolerance } from './imageDifference';

/**
 * The furnished goldens (docs/viewer.md, "Furnished goldens"): each furnished room at eye height
 * and from the corner, baked at one quality level. The same definitions serve the three browser
 * engines (furnishedGoldens.engines.ts) and `luxbox render` (tests/hosts/cli/renderFurnishedGoldens.test.ts),
 * so both sides draw the same configuration, camera and bake settings.
 */
export const GOLDEN_ROOMS = ['living-room', 'dining-room', 'shop-window'] as const;
export type GoldenRoom = (typeof GOLDEN_ROOMS)[number];

export const GOLDEN_CAMERAS = ['eye', 'corner'] as const satisfies readonly CameraPresetName[];
export type GoldenCamera = (typeof GOLDEN_CAMERAS)[number];

/**
 * The rooms a run compares: LUXBOX_GOLDEN_ROOMS, a comma list of rooms or `all`; by default the
 * living room alone, which keeps the suites short on the 2-core CI machine (each furnished bake
 * takes 0.5–2 min on software GL; docs/viewer.md, "Furnished goldens").
 */
export function goldenRoomsToRun(value = process.env.LUXBOX_GOLDEN_ROOMS): GoldenRoom[] {
  if (value === undefined || value.trim() === '') return ['living-room'];
  if (value.trim() === 'all') return [...GOLDEN_ROOMS];
  const rooms = value.split(',').map((r) => r.trim());
  for (const r of rooms) if (!(GOLDEN_ROOMS as readonly string[]).includes(r)) throw new Error(`LUXBOX_GOLDEN_ROOMS: unknown room "${r}" (${GOLDEN_ROOMS.join(', ')} or all)`);
  return rooms as GoldenRoom[];
}

/** The bake quality of the goldens: fixed texel size, samples and bounces (QUALITY_LEVELS.fast), seed 1. */
export const GOLDEN_QUALITY: QualityLevel = 'fast';

/** The goldens' folder (beside the CLI's render goldens) and file name of one view. */
export const GOLDENS_DIR = 'tests/goldens';
export const goldenFile = (room: GoldenRoom, camera: GoldenCamera) => `furnished-${room}-${camera}.png`;

/**
 * The largest difference allowed between any engine's picture, or `luxbox render`'s, and the
 * reviewed golden of a view (per pixel the largest channel difference, 0–255). Set from the
 * differences measured between the engines and the CLI (docs/viewer.md, "Furnished goldens"):
 * mean ≤ 0.64 and p90 1 measured; edges differ by anti-aliasing and rasterisation (p99 up to 9,
 * unbounded here). A camera moved 5 cm (mean 2.71, p90 5) or 11 % more exposure (3.25, 4) fail.
 */
export const GOLDEN_TOLERANCE: GoldenTolerance = { mean: 1.5, p90: 3 };

/** The scene file of a furnished room as the app writes it (default catalog). */
export function furnishedSceneFile(room: GoldenRoom): string {
  const preset = FURNISHED_PRESETS.find((p) => p.id === room);
  if (!preset) throw new Error(`no furnished preset "${room}"`);
  return serializeConfiguration(preset.build(defaultCatalog), defaultCatalog);
}
