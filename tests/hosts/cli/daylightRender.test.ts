/**
 * `luxbox render` on a daylight scene (issue 30, "shop images at a given time of day"):
 * tests/fixtures/scenes/daylight-room.json (5 × 4 × 2.8 m box, double-glazed south window 1.5 ×
 * 1.4 m at sill 0.9 m, CIE clear sky, Zurich, 21 June) drawn from above at 10:00 and, with
 * `--time`, at 15:00. Where the sun patch falls comes from geometry alone (NOAA's sun position,
 * the window's rectangle, a ray from the floor point toward the sun), not from the baker: the
 * floor pixel at the 10:00 patch's centre is brighter than a floor pixel in the shade, and at
 * 15:00 (the patch elsewhere) the same pixel is darker, at the same fixed exposure.
 */
import { basename, join } from 'node:path';
import * as THREE from 'three';
import { describe, expect, it, vi } from 'vitest';
import { cityNamed } from '../../../src/core/daylight/cities';
import { solarPosition, sunDirection } from '../../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { run } from '../../../src/hosts/cli/renderCommand';
import { withDaylightTime } from '../../../src/hosts/node/daylightTimeOverride';
import { createRenderSession, type RenderOptions } from '../../../src/hosts/node/renderImage';
import { loadRenderInputAsync } from '../../../src/hosts/node/renderInput';

const ROOT = join(__dirname, '../../..');
const SCENE = join(ROOT, 'tests/fixtures/scenes/daylight-room.json');
const [W, H] = [240, 160];
// Straight down from under the ceiling, a little tilted so that "up" stays defined; the whole floor in view.
const CAMERA = { position: [2.5, 2.7, 2.2] as Vec3, target: [2.5, 0, 2.1] as Vec3, fov: 100 };
const WINDOW = { x0: 1.75, x1: 3.25, y0: 0.9, y1: 2.3, z: 4 };

/** The sun's direction in Zurich on 21 June at `hours` (summer time, UTC+2). */
function sunAt(hours: number): Vec3 {
  const zurich = cityNamed('Zurich')!;
  const p = solarPosition({ latitude: zurich.latitude, longitude: zurich.longitude, timeZone: 2 }, { year: 2026, month: 6, day: 21, hours });
  return sunDirection(p.elevation, p.azimuth);
}

/** Whether a ray from the floor point toward the sun leaves through the window (the room is convex and empty). */
function sunlit(p: Vec3, s: Vec3): boolean {
  if (!(s[2] > 0)) return false;
  const t = (WINDOW.z - p[2]) / s[2];
  const [x, y] = [p[0] + t * s[0], p[1] + t * s[1]];
  return x > WINDOW.x0 && x < WINDOW.x1 && y > WINDOW.y0 && y < WINDOW.y1;
}

/** The floor point under the window's centre along the sun: the patch's centre. */
function patchCentre(s: Vec3): Vec3 {
  const t = 1.6 / s[1];
  return [2.5 - t * s[0], 0, WINDOW.z - t * s[2]];
}

/** Mean sRGB level (0–255, the three channels) of the 3 × 3 pixels round the world point's image. */
function pixelAt(pixels: Uint8Array, p: Vec3): number {
  const camera = new THREE.PerspectiveCamera(CAMERA.fov, W / H, 0.01, 100);
  camera.position.set(...CAMERA.position);
  camera.up.set(0, 1, 0);
  camera.lookAt(new THREE.Vector3(...CAMERA.target));
  camera.updateMatrixWorld();
  const ndc = new THREE.Vector3(...p).project(camera);
  const [px, py] = [Math.round(((ndc.x + 1) / 2) * W), Math.round(((1 - ndc.y) / 2) * H)];
  expect(px > 1 && px < W - 2 && py > 1 && py < H - 2, `[${p.join(', ')}] is in the image`).toBe(true);
  let sum = 0;
  for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) for (let c = 0; c < 3; c++) sum += pixels[4 * ((py + dy) * W + px + dx) + c];
  return sum / 27;
}

describe('luxbox render with daylight', () => {
  it('draws the sun patch where geometry puts it, and moves it with --time', async () => {
    const [s10, s15] = [sunAt(10), sunAt(15)];
    const patch = patchCentre(s10);
    const shade: Vec3 = [4, 0, 1.2];
    // The points mean what the test says, by geometry alone.
    expect(sunlit(patch, s10)).toBe(true);
    expect(sunlit(patch, s15)).toBe(false);
    expect(sunlit(shade, s10)).toBe(false);

    const input = await loadRenderInputAsync(SCENE);
    const session = createRenderSession(W, H);
    try {
      const options: RenderOptions = { width: W, height: H, camera: CAMERA, exposureEv: 0, mode: 'light', glare: false, settings: { texelSize: 0.1, samples: 32 } };
      const [ten] = session.renderViews(input, options, [CAMERA]);
      const [three] = session.renderViews(withDaylightTime(input, { time: '15:00' }, 'render', basename(SCENE)), { ...options, ev100: ten.ev100 }, [CAMERA]);
      const [inPatch, inShade, later] = [pixelAt(ten.pixels, patch), pixelAt(ten.pixels, shade), pixelAt(three.pixels, patch)];
      console.info(`sun patch at [${patch.map((v) => v.toFixed(2)).join(', ')}]: level ${inPatch.toFixed(1)} at 10:00 (shade ${inShade.toFixed(1)}), ${later.toFixed(1)} at 15:00; EV100 ${ten.ev100.toFixed(2)}`);
      for (const v of [inPatch, inShade, later]) expect(Number.isFinite(v)).toBe(true);
      expect(inPatch).toBeGreaterThan(1.5 * inShade);
      expect(later).toBeLessThan(0.8 * inPatch);
      expect(ten.floor.avg).toBeGreaterThan(0);
    } finally {
      session.destroy();
    }
  }, 240_000);

  it('documents --date and --time in --help, and refuses a time the scene cannot take, naming the flag', async () => {
    const write = vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
    try {
      await expect(run(['--help'])).resolves.toBe(0);
      const help = String(write.mock.calls.at(-1)![0]);
      expect(help).toMatch(/--date YYYY-MM-DD/);
      expect(help).toMatch(/--time HH:MM/);
    } finally {
      write.mockRestore();
    }
    // A clear sky needs the sun above the horizon (the contract's own rule, read again).
    await expect(run([SCENE, '--out', '/tmp/never.png', '--time', '23:30'])).rejects.toThrow(/^--time 23:30 \(daylight-room\.json\): sky\.sun\.time: the sun is below the horizon then \(elevation -\d+\.\d°\)/);
    await expect(run([SCENE, '--out', '/tmp/never.png', '--date', '2026-02-30'])).rejects.toThrow(/^--date 2026-02-30 \(daylight-room\.json\): sky\.sun\.date: /);
    // A scene without a sun has nothing to move.
    await expect(run([join(ROOT, 'tests/fixtures/scenes/small-room.json'), '--out', '/tmp/never.png', '--time', '10:00'])).rejects.toThrow(/render: --time 10:00: small-room\.json has no sun to move/);
  });
});
