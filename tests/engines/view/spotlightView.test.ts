/**
 * The spotlight view (docs/aiming.md) rendered with three.js on headless-gl:
 * - aimed straight down at the floor from a known height h, the drawn beam (50 %) outline is a
 *   circle whose radius in the image is the projection of h·tan(beam/2) (beam from the optic's
 *   photometry, photometry/beam.ts), and the field (10 %) outline likewise;
 * - the preview light (spotPreview.glsl.ts, per fragment) falls to half its peak where the beam
 *   outline is drawn, and its pixels equal the CPU mirror's E through the display transform;
 * - the GLSL candela lookup equals previewIlluminance, which equals the reference's direct
 *   illuminance (src/reference/directIlluminance) for the aimed lamp;
 * - dragging: the module leaves the maps (a relight), the aim follows within its limits, the
 *   release reports one aim, and the preview stays until the new bake is done.
 */
import createGL from 'gl';
import * as THREE from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { afterAll, describe, expect, it } from 'vitest';
import { aimedOrientation } from '../../../src/core/model/modules/aim';
import type { ModuleAim } from '../../../src/core/model/configuration/configuration';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { beamAndField } from '../../../src/core/photometry/beam';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { luminaireRotation } from '../../../src/engines/bake/luminaireRotation';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { createSpotlight, type SpotlightTarget } from '../../../src/engines/view/createSpotlight';
import { createRoomView } from '../../../src/engines/view/roomView';
import { previewIlluminance } from '../../../src/engines/view/spotPreview';
import { spotlightFov } from '../../../src/engines/view/spotlightPose';
import { displayColor } from '../../../src/engines/view/toneMap';
import { directIlluminanceAt } from '../../../src/reference/directIlluminance';
import { worldToLuminaire } from '../../../src/reference/luminaireRotation';
import { loadReal } from '../../core/photometry/helpers';

const N = 240;
const gl = createGL(N, N, { createWebGL2Context: true, preserveDrawingBuffer: true, antialias: false }) as unknown as WebGL2RenderingContext & { getExtension(n: 'STACKGL_destroy_context'): { destroy(): void } | null };
const listeners = new Map<string, (e: PointerEvent) => void>();
const canvas = {
  width: N,
  height: N,
  style: {},
  addEventListener: (type: string, f: (e: PointerEvent) => void) => listeners.set(type, f),
  removeEventListener: (type: string) => listeners.delete(type),
  getBoundingClientRect: () => ({ left: 0, top: 0, width: N, height: N }),
} as unknown as HTMLCanvasElement;
Object.defineProperty(gl, 'canvas', { value: canvas, configurable: true });
const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
renderer.setSize(N, N, false);
afterAll(() => {
  renderer.dispose();
  gl.getExtension('STACKGL_destroy_context')?.destroy();
});

const room = { width: 5, height: 3, depth: 5, reflectance: { floor: 0.5, ceiling: 0.5, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } };
const grey = (v: number): [number, number, number] => [v, v, v];
const reflectance = { floor: grey(0.5), ceiling: grey(0.5), north: grey(0.5), south: grey(0.5), west: grey(0.5), east: grey(0.5) };
const medium = loadReal('zumtobel_arcos3_spot_isym1.ldt');
const bf = beamAndField(medium);
const beamDeg = (bf.c0.beam + bf.c90.beam) / 2;
const fieldDeg = (bf.c0.field + bf.c90.field) / 2;
const h = 2.5;
const position: Vec3 = [2.5, h, 2.5];
const limits = { tilt: { min: 0, max: 90 }, rotation: { min: 0, max: 355 } };
const WEIGHT: [number, number, number] = [1, 1, 1];

function setup() {
  const view = createRoomView(renderer);
  view.setMaps(emptyLitMaps(surfaceLayouts(room, 0.1, 256)), reflectance);
  const controls = { enabled: true, target: new THREE.Vector3(), update() {} } as unknown as OrbitControls;
  const events = { dimmed: [] as (string | null)[], aims: [] as ModuleAim[] };
  const spotlight = createSpotlight({
    canvas,
    view: () => view,
    controls,
    request: () => {},
    room: () => room,
    lamp: () => ({ photometry: medium, weight: WEIGHT }),
    setDimmed: (id) => events.dimmed.push(id),
    onAim: (_id, aim) => events.aims.push(aim),
    linearFloat: renderer.extensions.has('OES_texture_float_linear'),
  });
  const target = (aim: ModuleAim): SpotlightTarget => ({ moduleId: 'm1', position, heading: 0, roll: 0, aim, limits, beamDeg, fieldDeg });
  return { view, controls, spotlight, events, target };
}

function readRgb(): Uint8Array {
  const px = new Uint8Array(N * N * 4);
  gl.readPixels(0, 0, N, N, gl.RGBA, gl.UNSIGNED_BYTE, px);
  return px;
}

/** Mean distance from the image centre of pixels matching `test` (and how many). */
function ringRadius(px: Uint8Array, test: (r: number, g: number, b: number) => boolean): { radius: number; count: number } {
  let sum = 0;
  let count = 0;
  for (let y = 0; y < N; y++) {
    for (let x = 0; x < N; x++) {
      const i = (y * N + x) * 4;
      if (!test(px[i], px[i + 1], px[i + 2])) continue;
      sum += Math.hypot(x + 0.5 - N / 2, y + 0.5 - N / 2);
      count++;
    }
  }
  return { radius: sum / count, count };
}

/** Pixels per unit of tan(angle off the axis) in a view of vertical field of view `fov` and N pixels. */
const pxPerTan = (fov: number) => N / 2 / Math.tan((fov * Math.PI) / 360);

describe('spotlight view outlines', () => {
  it('aimed straight down: the beam and field outlines are circles of radius h·tan(angle/2) on the floor, as the image shows them', () => {
    const { view, spotlight, target } = setup();
    spotlight.set(target({ rotation: 0, tilt: 0 }));
    expect(view.camera.fov).toBe(spotlightFov(fieldDeg));
    view.render(renderer);
    const px = readRgb();
    const scale = pxPerTan(view.camera.fov);
    // The floor distance h·tan(β/2) seen from height h is tan(β/2) off the axis: its image radius is scale·tan(β/2).
    const beam = ringRadius(px, (r, g, b) => r > 200 && g > 170 && b < 120);
    const field = ringRadius(px, (r, g, b) => r > 200 && g > 80 && g < 160 && b < 80);
    const floorBeam = h * Math.tan((beamDeg * Math.PI) / 360);
    const floorField = h * Math.tan((fieldDeg * Math.PI) / 360);
    console.info(
      `spotlight outlines: beam ${beamDeg.toFixed(2)}° → ${floorBeam.toFixed(3)} m on the floor, ${beam.radius.toFixed(2)} px (want ${((scale * floorBeam) / h).toFixed(2)}); field ${fieldDeg.toFixed(2)}° → ${field.radius.toFixed(2)} px (want ${((scale * floorField) / h).toFixed(2)})`,
    );
    expect(beam.count).toBeGreaterThan(100);
    expect(field.count).toBeGreaterThan(100);
    // Within one pixel (line rasterisation).
    expect(Math.abs(beam.radius - (scale * floorBeam) / h)).toBeLessThan(1);
    expect(Math.abs(field.radius - (scale * floorField) / h)).toBeLessThan(1);
    spotlight.dispose();
    view.dispose();
  });
});

describe('fast preview', () => {
  it('the preview light is at half its peak on the beam outline, and its pixels match the CPU mirror through the display transform', () => {
    const { view, spotlight, target, events } = setup();
    spotlight.set(target({ rotation: 0, tilt: 0 }));
    // A drag of 0 px leaves nothing; a real drag turns the preview on (tested below). Here: the preview lamp at this aim.
    listeners.get('pointerdown')!({ pointerId: 1, clientX: 100, clientY: 100, button: 0, pointerType: 'mouse' } as PointerEvent);
    listeners.get('pointermove')!({ pointerId: 1, clientX: 100, clientY: 99, button: 0, pointerType: 'mouse' } as PointerEvent);
    listeners.get('pointermove')!({ pointerId: 1, clientX: 100, clientY: 100, button: 0, pointerType: 'mouse' } as PointerEvent);
    expect(events.dimmed).toEqual(['m1']);
    expect(view.preview.uSpotOn.value).toBe(1);
    view.scene.getObjectByName('spotlight-outlines')!.visible = false;
    const scale = pxPerTan(view.camera.fov);
    const floorPoint = (x: number, y: number): Vec3 => {
      // Image → floor: the view looks straight down with up = +x (tilt direction at rotation 0), so image up is +x, image right is +z.
      const tx = (y + 0.5 - N / 2) / scale;
      const tz = (x + 0.5 - N / 2) / scale;
      return [position[0] + h * tx, 0, position[2] + h * tz];
    };
    const lamp = { position, toLocal: [1, 0, 0, 0, 1, 0, 0, 0, 1], photometry: medium, weight: WEIGHT };
    // Exposure that puts the peak luminance at 0.6 before the tone curve: mid-range bytes, not clipped.
    const peak = previewIlluminance(lamp, floorPoint(N / 2, N / 2), [0, 1, 0])[1];
    const exposure = 0.6 / ((0.5 * peak) / Math.PI);
    view.setExposure(exposure);
    view.render(renderer);
    const px = readRgb();
    let worst = 0;
    for (const [x, y] of [
      [120, 120],
      [130, 118],
      [140, 125],
      [150, 120],
      [120, 160],
      [100, 100],
    ]) {
      const e = previewIlluminance(lamp, floorPoint(x, y), [0, 1, 0]);
      const want = displayColor([(0.5 * e[0]) / Math.PI, (0.5 * e[1]) / Math.PI, (0.5 * e[2]) / Math.PI], exposure).map((v) => v * 255);
      const i = (y * N + x) * 4;
      for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(px[i + k] - want[k]));
    }
    expect(worst).toBeLessThanOrEqual(3);
    // Along the image's row through the centre, where the intensity is half its peak (the floor's E there is
    // ½·I₀·cos³(β/2)/h²: inverse square and incidence) lies the beam outline.
    const row = N / 2;
    const cos3 = Math.cos((beamDeg * Math.PI) / 360) ** 3;
    const half = displayColor([0, (0.5 * 0.5 * peak * cos3) / Math.PI, 0], exposure)[1] * 255;
    let edge = 0;
    for (let x = N / 2; x < N; x++) if (px[(row * N + x) * 4 + 1] >= half) edge = x + 1 - N / 2;
    const outline = scale * Math.tan((beamDeg * Math.PI) / 360);
    console.info(`preview half-peak radius ${edge} px, beam outline ${outline.toFixed(2)} px`);
    expect(Math.abs(edge - outline)).toBeLessThan(2);
    spotlight.dispose();
    view.dispose();
  });

  it('CPU mirror = reference direct illuminance for an aimed lamp (floor and wall points)', () => {
    const aim = { rotation: 40, tilt: 35 };
    const o = aimedOrientation(30, 0, aim);
    const m = luminaireRotation(o.yaw, o.pitch, o.roll);
    const toLocal = [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]];
    const lamp = { position, toLocal, photometry: medium, weight: [0.9, 0.8, 0.7] as [number, number, number] };
    const source = { position, toLocal: worldToLuminaire(o.yaw, o.pitch, o.roll), photometry: medium, scale: lamp.weight, luminaire: 0, hemisphere: 0 as const };
    const points: [Vec3, Vec3][] = [
      [
        [3.3, 0, 1.6],
        [0, 1, 0],
      ],
      [
        [3.8, 0, 1.2],
        [0, 1, 0],
      ],
      [
        [2.5, 0, 2.5],
        [0, 1, 0],
      ],
      [
        [5, 1.2, 1.5],
        [-1, 0, 0],
      ],
      [
        [4, 1.5, 0],
        [0, 0, 1],
      ],
    ];
    for (const [p, n] of points) {
      const got = previewIlluminance(lamp, p, n);
      const want = directIlluminanceAt([source], p, n);
      expect(want[1]).toBeGreaterThan(0);
      for (let k = 0; k < 3; k++) expect(Math.abs(got[k] - want[k])).toBeLessThan(1e-6 * Math.max(1, want[k]));
    }
  });
});

describe('dragging in the spotlight view', () => {
  it('the aim follows the pointer within its limits; the release reports it once; the preview stays until the new bake is done', () => {
    const { view, spotlight, target, events, controls } = setup();
    spotlight.set(target({ rotation: 10, tilt: 20 }));
    expect(controls.enabled).toBe(false);
    const down = (x: number, y: number) => listeners.get('pointerdown')!({ pointerId: 7, clientX: x, clientY: y, button: 0, pointerType: 'touch' } as PointerEvent);
    const move = (x: number, y: number) => listeners.get('pointermove')!({ pointerId: 7, clientX: x, clientY: y, button: 0, pointerType: 'touch' } as PointerEvent);
    const up = (x: number, y: number) => listeners.get('pointerup')!({ pointerId: 7, clientX: x, clientY: y, button: 0, pointerType: 'touch' } as PointerEvent);
    const fov = view.camera.fov;
    down(100, 100);
    move(100, 100 - 60);
    // 60 px up at fov/N degrees per pixel: the tilt grows by 60·fov/N.
    expect(events.dimmed).toEqual(['m1']);
    // far past the 90° limit: stops there
    move(100, -5000);
    up(100, -5000);
    expect(events.aims).toHaveLength(1);
    expect(events.aims[0].tilt).toBe(90);
    expect(events.aims[0].rotation).toBe(10);
    // the store answers with the new aim (new scene): the preview holds until that bake is done
    spotlight.set(target(events.aims[0]));
    spotlight.sceneChanged();
    spotlight.bakeProgress(false);
    expect(view.preview.uSpotOn.value).toBe(1);
    spotlight.bakeProgress(true);
    expect(view.preview.uSpotOn.value).toBe(0);
    expect(events.dimmed).toEqual(['m1', null]);
    // a sideways drag at tilt 90: −rotation per pixel to the right, the camera follows
    down(100, 100);
    move(120, 100);
    up(120, 100);
    expect(events.aims[1].tilt).toBe(90);
    expect(events.aims[1].rotation).toBeCloseTo(10 - (20 * fov) / N, 9);
    spotlight.set(null);
    expect(controls.enabled).toBe(true);
    spotlight.dispose();
    view.dispose();
  });
});
