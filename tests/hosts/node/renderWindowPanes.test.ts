/**
 * `luxbox render` draws the window panes as the browser does (issue 30, docs/daylight.md "On the
 * command line"): the render session's exposed linear value before the tone curve (RenderResult.hdr,
 * the glare pass's HDR input) at every pane pixel clear of the frame, against L_outside(d) · τ(θ) ·
 * exposure computed on the CPU along the pixel's own view ray with the core's sky (skies.ts) and
 * glazing (glazing.ts), not the shader's code: the sky above the horizon and the ground below for
 * tests/fixtures/scenes/daylight-room.json at 10:00 in June and (with --date/--time) at 17:00 in
 * December; the night sky (NIGHT_SKY_LUMINANCE) for the shopper's configuration after sunset. The
 * bar is the browser's pane test's (tests/engines/view/windowPanes.test.ts): 1 %.
 */
import { basename, join } from 'node:path';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { cityNamed } from '../../../src/core/daylight/cities';
import { glazingFrom, glazingTransmittance, type Glazing } from '../../../src/core/daylight/glazing';
import { solarPosition, sunDirection } from '../../../src/core/daylight/solarPosition';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { NIGHT_SKY_LUMINANCE, WINDOW_FRAME_WIDTH } from '../../../src/engines/view/windowPaneUniforms';
import { withDaylightTime } from '../../../src/hosts/node/daylightTimeOverride';
import { renderInputAtTime } from '../../../src/hosts/node/renderDaylightTime';
import { createRenderSession, type RenderOptions, type RenderResult } from '../../../src/hosts/node/renderImage';
import { loadRenderInputAsync, type RenderInput } from '../../../src/hosts/node/renderInput';

const ROOT = join(__dirname, '../../..');
const SCENE = join(ROOT, 'tests/fixtures/scenes/daylight-room.json');
/** A version-10 configuration: an L-shaped room, a triple-glazed window in its north wall, daylight on in Zurich at 17:00 on 21 December (after sunset). */
const NIGHT_CONFIGURATION = join(ROOT, 'tests/fixtures/formats/configuration-v10.luxbox.json');
const [W, H] = [96, 96];
const FAST = { texelSize: 0.2, samples: 8, bounces: 1 };

/** A window's glass in world coordinates: x and y ranges on the plane z = `z`. */
interface WindowRect {
  x: [number, number];
  y: [number, number];
  z: number;
}

/** daylight-room.json's south window (z = 4, 1.5 × 1.4 m at sill 0.9 m from x = 1.75); the configuration's north window (wall 0, offset 2.5, 1.2 × 1.2 m at sill 0.9 m). */
const SOUTH_WINDOW: WindowRect = { x: [1.75, 3.25], y: [0.9, 2.3], z: 4 };
const NORTH_WINDOW: WindowRect = { x: [2.5, 3.7], y: [0.9, 2.1], z: 0 };

/** The sun in Zurich on `date` at `hours` of the clock at `zone` hours ahead of UTC (NOAA, solarPosition.ts). */
function zurichSun(month: number, day: number, hours: number, zone: number): Vec3 {
  const zurich = cityNamed('Zurich')!;
  const p = solarPosition({ latitude: zurich.latitude, longitude: zurich.longitude, timeZone: zone }, { year: 2026, month, day, hours });
  return sunDirection(p.elevation, p.azimuth);
}

function render(input: RenderInput, camera: { position: Vec3; target: Vec3; fov: number }): RenderResult {
  const session = createRenderSession(W, H);
  try {
    const options: RenderOptions = { width: W, height: H, camera, exposureEv: 0, mode: 'light', adaptation: { kind: 'none' }, glare: false, hdr: true, settings: FAST };
    return session.renderViews(input, options, [camera])[0];
  } finally {
    session.destroy();
  }
}

/**
 * Every pixel whose view ray crosses the window's glass clear of the frame (and of the wall's depth
 * round it): its HDR value against `outside(d) · τ(θ) · exposure`; the worst relative error and how
 * many sky (d_y > 0) and ground pixels were compared.
 */
function comparePanes(result: RenderResult, camera: { position: Vec3; target: Vec3; fov: number }, window: WindowRect, glazing: Glazing, outside: (d: Vec3) => number): { worst: number; sky: number; ground: number } {
  const cam = new THREE.PerspectiveCamera(camera.fov, W / H, 0.05, 50);
  cam.position.set(...camera.position);
  cam.up.set(0, 1, 0);
  cam.lookAt(new THREE.Vector3(...camera.target));
  cam.updateMatrixWorld();
  const margin = WINDOW_FRAME_WIDTH + 0.03;
  const hdr = result.hdr!;
  let [worst, sky, ground] = [0, 0, 0];
  for (let row = 0; row < H; row++) {
    for (let i = 0; i < W; i++) {
      // hdr's rows run top first; NDC y runs up.
      const ndcY = 1 - ((row + 0.5) / H) * 2;
      const v = new THREE.Vector3(((i + 0.5) / W) * 2 - 1, ndcY, 0.5).unproject(cam).sub(cam.position).normalize();
      const t = (window.z - cam.position.z) / v.z;
      if (!(t > 0)) continue;
      const [x, y] = [cam.position.x + t * v.x, cam.position.y + t * v.y];
      if (x < window.x[0] + margin || x > window.x[1] - margin || y < window.y[0] + margin || y > window.y[1] - margin) continue;
      const d: Vec3 = [v.x, v.y, v.z];
      // θ: the ray's angle to the window's normal.
      const expected = outside(d) * glazingTransmittance(glazing, Math.abs(v.z)) * result.exposure;
      const got = hdr[(row * W + i) * 4];
      expect(hdr[(row * W + i) * 4 + 2]).toBeCloseTo(got, 6);
      worst = Math.max(worst, Math.abs(got / expected - 1));
      if (d[1] > 0) sky++;
      else ground++;
    }
  }
  return { worst, sky, ground };
}

describe('luxbox render draws the windows as the browser does', () => {
  // Inside the box, looking at its south window from the north, a little below the window's centre.
  const camera = { position: [2.3, 1.4, 2.6] as Vec3, target: [2.5, 1.5, 4] as Vec3, fov: 70 };

  const times = [
    { name: '10:00 on 21 June (the scene as written)', when: null, sun: zurichSun(6, 21, 10, 2) },
    { name: '17:00 on 21 December (--date, --time)', when: { date: '2026-12-21', time: '17:00' }, sun: zurichSun(12, 21, 17, 2) },
  ];
  for (const t of times) {
    it(`daylight-room.json at ${t.name}: every pane pixel is the sky or the ground × τ(θ) × exposure within 1 %`, async () => {
      const input = withDaylightTime(await loadRenderInputAsync(SCENE), t.when, 'render', basename(SCENE));
      const daylight = input.bakeScene.daylight!;
      // The scene's sky is the CIE clear sky round NOAA's sun for the file's place and clock (its zone is +02:00).
      expect(daylight.sky!.kind).toBe('cie-general');
      const s = daylight.sky!.sunDirection!;
      for (let k = 0; k < 3; k++) expect(s[k]).toBeCloseTo(t.sun[k], 9);
      const result = render(input, camera);
      const r = comparePanes(result, camera, SOUTH_WINDOW, glazingFrom('double'), (d) => (d[1] > 0 ? daylight.sky!.luminance(d) : daylight.groundLuminance));
      console.info(`render, ${t.name}: ${r.sky} sky and ${r.ground} ground pixels, worst ${(100 * r.worst).toFixed(3)} %; EV100 ${result.ev100.toFixed(2)}`);
      expect(r.sky).toBeGreaterThan(200);
      expect(r.ground).toBeGreaterThan(100);
      expect(r.worst).toBeLessThan(0.01);
    }, 120_000);
  }
  it('the shopper’s configuration after sunset (17:00 on 21 December in Zurich): the panes show the night sky through the triple glazing, and nothing is NaN', async () => {
    const input = await loadRenderInputAsync(NIGHT_CONFIGURATION);
    // The sun is down: the scene the baker gets lets no daylight in (its windows keep their glazing), as in the browser.
    expect(zurichSun(12, 21, 17, 1)[1]).toBeLessThan(0);
    expect(input.bakeScene.daylight).toMatchObject({ sky: null, sun: null, groundLuminance: 0 });
    const night = { position: [3.1, 1.4, 2.2] as Vec3, target: [3.1, 1.5, 0] as Vec3, fov: 70 };
    const result = render(input, night);
    for (const v of result.hdr!) expect(Number.isFinite(v)).toBe(true);
    const r = comparePanes(result, night, NORTH_WINDOW, glazingFrom('triple'), () => NIGHT_SKY_LUMINANCE);
    console.info(`render, night: ${r.sky + r.ground} pane pixels, worst ${(100 * r.worst).toFixed(3)} %`);
    expect(r.sky + r.ground).toBeGreaterThan(300);
    expect(r.worst).toBeLessThan(0.01);
  }, 120_000);
  it('a configuration moved by --date/--time as the Daylight panel moves it: 10:00 on 21 June in Zurich (summer time) shows the sky through the triple glazing', async () => {
    const input = renderInputAtTime(await loadRenderInputAsync(NIGHT_CONFIGURATION), { date: '2026-06-21', time: '10:00' }, basename(NIGHT_CONFIGURATION));
    const daylight = input.bakeScene.daylight!;
    // The clock of Zurich in June is UTC+2 (clockOffset.ts): NOAA's sun at 08:00 UTC.
    const s = daylight.sky!.sunDirection!;
    const expected = zurichSun(6, 21, 10, 2);
    for (let k = 0; k < 3; k++) expect(s[k]).toBeCloseTo(expected[k], 9);
    expect(daylight.groundReflectance).toBe(0.25);
    const camera = { position: [3.1, 1.4, 2.2] as Vec3, target: [3.1, 1.5, 0] as Vec3, fov: 70 };
    const result = render(input, camera);
    const r = comparePanes(result, camera, NORTH_WINDOW, glazingFrom('triple'), (d) => (d[1] > 0 ? daylight.sky!.luminance(d) : daylight.groundLuminance));
    console.info(`render, configuration at 10:00 in June: ${r.sky} sky and ${r.ground} ground pixels, worst ${(100 * r.worst).toFixed(3)} %`);
    expect(r.sky).toBeGreaterThan(100);
    expect(r.ground).toBeGreaterThan(50);
    expect(r.worst).toBeLessThan(0.01);
  }, 120_000);

  it('refuses a configuration time the Daylight panel cannot take, naming the flag', async () => {
    const input = await loadRenderInputAsync(NIGHT_CONFIGURATION);
    const file = basename(NIGHT_CONFIGURATION);
    expect(() => renderInputAtTime(input, { time: '10:00:30' }, file)).toThrow(/^render: --time 10:00:30 \(configuration-v10\.luxbox\.json\): a configuration's time is HH:MM/);
    expect(() => renderInputAtTime(input, { date: '2026-02-30' }, file)).toThrow(/^render: --date 2026-02-30 \(configuration-v10\.luxbox\.json\): a configuration's date is YYYY-MM-DD/);
    const off = { ...input, configuration: { ...input.configuration!, daylight: undefined } };
    expect(() => renderInputAtTime(off, { time: '10:00' }, file)).toThrow(/has no daylight to move/);
  });
});
