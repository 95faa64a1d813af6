import * as THREE from 'three';
import { headlessRenderer } from './headlessRenderer';
import { describe, expect, it } from 'vitest';
import { falseColorGlsl } from '../../../shaders/falseColor.glsl';
import { legendPosition, luxLevels, MAX_LEVELS, turbo, TURBO_B, TURBO_G, TURBO_R } from '../../../src/engines/view/falseColorScale';

const falseColorChunk = falseColorGlsl({ maxLevels: MAX_LEVELS, turbo: [TURBO_R, TURBO_G, TURBO_B] });
import { adaptedLinear, agxMaxRgb, displayColor, gamutMap, linearToSrgb } from '../../../src/engines/view/toneMap';
import { degreeOfAdaptation, IDENTITY3 } from '../../../src/engines/view/cat16';
import { adaptationFor, adaptingLuminance } from '../../../src/engines/view/chromaticAdaptation';
import type { Mat3 } from '../../../src/engines/view/colourMatrices';
import { cctToLinearRgb } from '../../../src/core/photometry/cct';
import { chroma, hueAngle, hueDifference, hueOfChromaticity, linearSrgbToXyz, srgbToLinear, xyzToLab } from '../../../src/core/colour/cielab';
import { loadColourFilterSpectra } from '../../../src/core/colour/colourFilterSpectra';
import { moduleColour } from '../../../src/core/colour/moduleColour';
import { toneMapGlsl } from '../../../shaders/toneMap.glsl';

// The viewer's GLSL chunks compiled and run (three.js on headless-gl), checked against their TypeScript mirrors.
const N = 16;
const renderer = headlessRenderer(N, 1);
const gl = renderer.getContext();

/** Runs `body` (GLSL computing `vec3 c` from `float x` = the pixel's input) for N inputs; returns RGB bytes. */
function runShader(inputs: number[], prelude: string, body: string, uniforms: Record<string, THREE.IUniform> = {}): number[][] {
  const material = new THREE.ShaderMaterial({
    glslVersion: THREE.GLSL3,
    uniforms: { uInputs: { value: inputs }, ...uniforms },
    vertexShader: 'void main() { gl_Position = vec4(position.xy * 2.0, 0.0, 1.0); }',
    fragmentShader: `precision highp float;\nuniform float uInputs[${N}];\nout vec4 o;\n${prelude}\nvoid main() { float x = uInputs[int(gl_FragCoord.x)]; vec3 c; ${body} o = vec4(c, 1.0); }`,
  });
  const scene = new THREE.Scene();
  scene.add(new THREE.Mesh(new THREE.PlaneGeometry(1, 1), material));
  renderer.render(scene, new THREE.Camera());
  const px = new Uint8Array(N * 4);
  gl.readPixels(0, 0, N, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
  material.dispose();
  return Array.from({ length: N }, (_, i) => [px[i * 4], px[i * 4 + 1], px[i * 4 + 2]]);
}

describe('display transform (exposure → adaptation → gamut map → AgX on max(R,G,B) → sRGB)', () => {
  it('sRGB OETF hits the IEC 61966-2-1 reference points', () => {
    expect(linearToSrgb(0)).toBe(0);
    expect(linearToSrgb(1)).toBeCloseTo(1, 12);
    expect(linearToSrgb(0.0031308)).toBeCloseTo(0.04045, 5);
    expect(linearToSrgb(0.18)).toBeCloseTo(0.4614, 4);
  });

  it('AgX on max(R,G,B): black stays black, strictly increasing to white, grey stays grey, a colour keeps its ratios', () => {
    expect(agxMaxRgb([0, 0, 0])).toEqual([0, 0, 0]);
    let prev = -1;
    for (let x = 0.001; x < 20; x *= 1.5) {
      const [r, g, b] = agxMaxRgb([x, x, x]);
      expect(r).toBeGreaterThan(prev);
      expect(Math.abs(r - g)).toBeLessThan(1e-12);
      expect(Math.abs(g - b)).toBeLessThan(1e-12);
      prev = r;
    }
    expect(prev).toBeLessThanOrEqual(1);
    // Middle grey lands at sRGB 128 (AgX's anchor), as ACES did (127).
    expect(Math.round(linearToSrgb(agxMaxRgb([0.18, 0.18, 0.18])[1]) * 255)).toBe(128);
    const red = agxMaxRgb([3, 0.3, 0.03]);
    expect(red[1] / red[0]).toBeCloseTo(0.1, 12);
    expect(red[2] / red[0]).toBeCloseTo(0.01, 12);
  });

  it('gamut mapping lifts a negative component to 0 at the same luminance, towards grey (chromaticity on the line to white)', () => {
    const c: [number, number, number] = [1.2, 0.3, -0.2];
    const m = gamutMap(c);
    const Y = (v: number[]) => 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
    expect(Math.min(...m)).toBeCloseTo(0, 12);
    expect(Y(m)).toBeCloseTo(Y(c), 12);
    // m − Y = t · (c − Y) with one t for all channels: the same direction from grey.
    const t = (m[0] - Y(c)) / (c[0] - Y(c));
    for (let k = 0; k < 3; k++) expect(m[k] - Y(c)).toBeCloseTo(t * (c[k] - Y(c)), 12);
    expect(gamutMap([-1, -1, -1])).toEqual([0, 0, 0]);
    expect(gamutMap([0.2, 0.3, 0.4])).toEqual([0.2, 0.3, 0.4]);
  });

  it('GLSL luxDisplay equals the TypeScript mirror within 1/255 (+ rounding) on a grid of levels, colours and adaptations', () => {
    const inputs = Array.from({ length: N }, (_, i) => 0.002 * 1.9 ** i);
    const adaptations: [string, Mat3][] = [
      ['identity', IDENTITY3],
      ['camera 3000 K', adaptationFor({ kind: 'camera', cct: 3000 }, null, 0).matrix],
      ['eye 2700 K at L_A 20', adaptationFor({ kind: 'eye' }, cctToLinearRgb(2700), 20).matrix],
      ['camera 6500 K', adaptationFor({ kind: 'camera', cct: 6500 }, null, 0).matrix],
    ];
    const colours: [number, number, number][] = [
      [1, 0.5, 0.25],
      [1.77, 0.84, 0.27],
      [4.7, 0, 0],
      [0, 1.2, 0.1],
      [0.2, 0.3, 1.5],
      [1, 1, 1],
    ];
    for (const [, m] of adaptations) {
      for (const col of colours) {
        const got = runShader(inputs, `uniform mat3 uAdapt;\n${toneMapGlsl}`, `c = luxDisplay(vec3(${col.map((v) => v.toFixed(6)).join(', ')}) * x, 0.7, uAdapt);`, { uAdapt: { value: new THREE.Matrix3().set(...m) } });
        inputs.forEach((x, i) => {
          const want = displayColor([col[0] * x, col[1] * x, col[2] * x], 0.7, m).map((v) => v * 255);
          for (let k = 0; k < 3; k++) expect(Math.abs(got[i][k] - want[k])).toBeLessThanOrEqual(1.01);
        });
      }
    }
  });
});

describe('chromatic adaptation on the compiled GLSL (CAT16, docs/viewer.md "Adaptation")', () => {
  // A grey card (ρ 0.5) under 3000 K light at 300 lx, exposed as auto exposure does a room of it: L̄ = 0.5·300/π.
  const lamp = cctToLinearRgb(3000);
  const E = 300;
  const card = lamp.map((v) => (0.5 * E * v) / Math.PI) as [number, number, number];
  const auto = 0.18 / ((0.5 * E) / Math.PI);
  const glsl = (m: Mat3, L: [number, number, number], exposure: number) =>
    runShader([1], `uniform mat3 uAdapt;\n${toneMapGlsl}`, `c = luxDisplay(vec3(${L.map((v) => v.toFixed(6)).join(', ')}) * x, ${exposure.toFixed(9)}, uAdapt);`, { uAdapt: { value: new THREE.Matrix3().set(...m) } })[0];
  const labOf = (bytes: number[]) => xyzToLab(linearSrgbToXyz(bytes.map((v) => srgbToLinear(v / 255)) as [number, number, number]));

  it('camera white balance 3000 K: the grey card is neutral within 1/255 per channel (GLSL and TypeScript)', () => {
    const m = adaptationFor({ kind: 'camera', cct: 3000 }, null, 0).matrix;
    const ts = displayColor(card, auto, m).map((v) => v * 255);
    expect(Math.max(...ts) - Math.min(...ts)).toBeLessThanOrEqual(1);
    const gl = glsl(m, card, auto);
    expect(Math.max(...gl) - Math.min(...gl)).toBeLessThanOrEqual(1);
    // Not black: a mid grey (ρ 0.5 at the key).
    expect(gl[1]).toBeGreaterThan(100);
  });

  it('eye: D from L_A as CAM16 defines it, the card warm, its chroma strictly between camera (0) and none (physical)', () => {
    // Hand-computed: D = 1 − (1/3.6)·exp((−L_A − 42)/92).
    expect(degreeOfAdaptation(20)).toBeCloseTo(0.858414, 6); // e^(−62/92) = 0.509709
    expect(degreeOfAdaptation(0)).toBeCloseTo(0.824032, 6); // e^(−42/92) = 0.633488
    expect(degreeOfAdaptation(1000)).toBeCloseTo(0.999997, 6);
    // L_A = 0.2 · L̄ / 0.18 = 0.2 / auto = 53.0516 cd/m² → D = 1 − 0.277778 · e^(−95.0516/92) = 0.901145.
    const la = adaptingLuminance(auto);
    expect(la).toBeCloseTo(53.0516, 3);
    const eye = adaptationFor({ kind: 'eye' }, lamp, la);
    expect(eye.d).toBeCloseTo(0.901145, 5);
    // The adapted linear colour is exactly D·(camera-balanced) + (1 − D)·(physical): CAT16's one step is affine in D.
    const full = adaptationFor({ kind: 'eye' }, lamp, 1e9).matrix; // D = 1 to the same white
    const linEye = adaptedLinear(card, auto, eye.matrix);
    const linFull = adaptedLinear(card, auto, full);
    const linNone = adaptedLinear(card, auto);
    for (let k = 0; k < 3; k++) expect(linEye[k]).toBeCloseTo(eye.d * linFull[k] + (1 - eye.d) * linNone[k], 9);
    const cEye = glsl(eye.matrix, card, auto);
    const cNone = glsl(IDENTITY3, card, auto);
    const cCamera = glsl(adaptationFor({ kind: 'camera', cct: 3000 }, null, 0).matrix, card, auto);
    const [lEye, lNone, lCamera] = [labOf(cEye), labOf(cNone), labOf(cCamera)];
    expect(chroma(lCamera)).toBeLessThan(1.5);
    expect(chroma(lEye)).toBeGreaterThan(chroma(lCamera) + 2);
    expect(chroma(lEye)).toBeLessThan(chroma(lNone) - 10);
    // Warm: red above blue, hue in the orange–yellow quadrant like the physical colour's.
    expect(cEye[0]).toBeGreaterThan(cEye[2]);
    expect(hueDifference(hueAngle(lEye), hueAngle(lNone))).toBeLessThan(15);
  });

  it("a LEE 106 primary red patch on a white wall at 300 lx keeps the gel's hue within 10° (not peach)", async () => {
    await loadColourFilterSpectra();
    const gel = moduleColour(3000, 'lee-106');
    const want = hueOfChromaticity(gel.x, gel.y);
    // The gel's light per lux, on a ρ 0.8 wall, in a room exposed for 300 lx on ρ 0.5; the gel is no white, so eye adaptation adapts to the room's 3000 K white.
    const patch = gel.linearRgb.map((v) => (0.8 * 300 * v) / gel.transmission / Math.PI) as [number, number, number];
    for (const m of [IDENTITY3, adaptationFor({ kind: 'eye' }, lamp, adaptingLuminance(auto)).matrix]) {
      const px = glsl(m, patch, auto);
      expect(hueDifference(hueAngle(labOf(px)), want)).toBeLessThan(10);
      // Red, not peach: green and blue far below red.
      expect(px[1]).toBeLessThan(0.35 * px[0]);
      expect(px[2]).toBeLessThan(0.35 * px[0]);
    }
  });

  it('highlight roll-off: a ρ 0.4/0.6 pattern under 5 000 and 9 000 lx keeps its texture (std-dev > 0 of 255, GLSL and TypeScript)', () => {
    for (const lux of [5000, 9000]) {
      const L = [0.4, 0.6].map((rho) => (rho * lux) / Math.PI);
      const gl = L.map((l) => glsl(IDENTITY3, [l, l, l], auto)[1]);
      const ts = L.map((l) => displayColor([l, l, l], auto)[1] * 255);
      // docs/viewer.md "Choosing the tone curve": 4.27 at 5 000 lx and 2.76 at 9 000 lx (ACES: 2.11 and 1.14).
      expect(Math.abs(ts[1] - ts[0]) / 2).toBeGreaterThan(lux === 5000 ? 4 : 2.5);
      expect(Math.abs(gl[1] - gl[0]) / 2).toBeGreaterThan(1);
    }
  });
});

describe('false colour', () => {
  it('legend levels: a 1-2-5 series covering max/100..max, ascending, at most MAX_LEVELS', () => {
    for (const max of [0.7, 3, 42, 340, 999, 1000, 12_345, 2e6]) {
      const levels = luxLevels(max);
      expect(levels.length).toBeGreaterThanOrEqual(2);
      expect(levels.length).toBeLessThanOrEqual(MAX_LEVELS);
      expect(levels.every((v, i) => i === 0 || v > levels[i - 1])).toBe(true);
      expect(levels[levels.length - 1]).toBeGreaterThanOrEqual(max);
      expect(levels[levels.length - 1]).toBeLessThan(max * 2.5 + 1e-9);
      expect(levels[0]).toBeLessThanOrEqual(max / 40);
      for (const v of levels) expect([1, 2, 5]).toContain(Number((v / 10 ** Math.floor(Math.log10(v) + 1e-9)).toPrecision(3)));
    }
    expect(luxLevels(340)).toEqual([5, 10, 20, 50, 100, 200, 500]);
  });

  it('legend position is piecewise log-linear: levels land on i/(n−1), geometric midpoints halfway', () => {
    const levels = [10, 100, 1000];
    expect(legendPosition(10, levels)).toBeCloseTo(0, 12);
    expect(legendPosition(100, levels)).toBeCloseTo(0.5, 12);
    expect(legendPosition(Math.sqrt(10 * 100), levels)).toBeCloseTo(0.25, 12);
    expect(legendPosition(1000, levels)).toBeCloseTo(1, 12);
    expect(legendPosition(1e6, levels)).toBe(1);
    expect(legendPosition(0, levels)).toBe(0);
  });

  it('GLSL colour of a lux value equals the legend swatch (TypeScript) within 1/255', () => {
    const levels = luxLevels(3000);
    const inputs = Array.from({ length: N }, (_, i) => 17 * 1.45 ** i);
    const padded = [...levels, ...new Array(MAX_LEVELS - levels.length).fill(1)];
    const got = runShader(inputs, falseColorChunk, 'c = luxTurbo(luxLegendPosition(x));', { uLevels: { value: padded }, uLevelCount: { value: levels.length } });
    inputs.forEach((lux, i) => {
      const want = turbo(legendPosition(lux, levels)).map((v) => v * 255);
      for (let k = 0; k < 3; k++) expect(Math.abs(got[i][k] - want[k])).toBeLessThanOrEqual(1.01);
    });
  });

  it('isolines: a surface at a legend level is drawn dark, one between levels in its swatch colour', () => {
    const levels = luxLevels(3000);
    const padded = [...levels, ...new Array(MAX_LEVELS - levels.length).fill(1)];
    const uniforms = { uLevels: { value: padded }, uLevelCount: { value: levels.length } };
    // Constant input over the quad: no screen-space variation, so only an exact level crossing draws a line.
    const onLevel = runShader(new Array(N).fill(levels[3]), falseColorChunk, 'c = luxFalseColor(x, x, 1.0);', uniforms)[N >> 1];
    const between = Math.sqrt(levels[3] * levels[4]);
    const offLevel = runShader(new Array(N).fill(between), falseColorChunk, 'c = luxFalseColor(x, x, 1.0);', uniforms)[N >> 1];
    const swatch = turbo(legendPosition(between, levels)).map((v) => v * 255);
    const line = turbo(legendPosition(levels[3], levels)).map((v) => (v * 0.15 + 0.05 * 0.85) * 255);
    for (let k = 0; k < 3; k++) {
      expect(Math.abs(offLevel[k] - swatch[k])).toBeLessThanOrEqual(1.01);
      expect(Math.abs(onLevel[k] - line[k])).toBeLessThanOrEqual(1.01);
    }
    expect(Math.max(...onLevel)).toBeLessThan(60);
  });

  it('isolines fade out where they are ill-conditioned: grazing views, lines under ~2 px apart; and follow the line illuminance, not the fill', () => {
    const levels = luxLevels(3000);
    const padded = [...levels, ...new Array(MAX_LEVELS - levels.length).fill(1)];
    const uniforms = { uLevels: { value: padded }, uLevelCount: { value: levels.length } };
    const between = Math.sqrt(levels[3] * levels[4]);
    const swatch = turbo(legendPosition(levels[3], levels)).map((v) => v * 255);
    const near = (a: number[], b: number[]) => a.every((v, k) => Math.abs(v - b[k]) <= 1.01);
    // At a level, seen at 80° from the normal (|cos| 0.17 < 0.3): no line, the fill colour.
    const grazing = runShader(new Array(N).fill(levels[3]), falseColorChunk, 'c = luxFalseColor(x, x, 0.05);', uniforms)[N >> 1];
    expect(near(grazing, swatch)).toBe(true);
    // At |cos| 0.3 and above the line is fully drawn (same as head-on).
    const head = runShader(new Array(N).fill(levels[3]), falseColorChunk, 'c = luxFalseColor(x, x, 1.0);', uniforms)[N >> 1];
    const at30 = runShader(new Array(N).fill(levels[3]), falseColorChunk, 'c = luxFalseColor(x, x, 0.3);', uniforms)[N >> 1];
    expect(near(at30, head)).toBe(true);
    // The line follows the second argument: fill between levels, line illuminance on a level → dark.
    const lineOnly = runShader(new Array(N).fill(between), falseColorChunk, `c = luxFalseColor(x, ${levels[3].toFixed(6)}, 1.0);`, uniforms)[N >> 1];
    expect(Math.max(...lineOnly)).toBeLessThan(60);
    // Alpha as a function of the per-pixel change w of log E: exactly on a level, w = log(2)/1.5 (levels 1.5 px apart) → 0;
    // w = log(2)/4 (4 px apart) → 1; w = log(2)/2.75 (midway in the fade) → between.
    const alpha = (w: number) => runShader(new Array(N).fill(levels[3]), falseColorChunk, `c = vec3(luxIsolineAlpha(log(x), ${w.toFixed(6)}, 1.0));`, uniforms)[N >> 1][0] / 255;
    expect(alpha(Math.LN2 / 1.5)).toBeLessThanOrEqual(1 / 255);
    expect(alpha(Math.LN2 / 4)).toBeGreaterThanOrEqual(254 / 255);
    const mid = alpha(Math.LN2 / 2.75);
    expect(mid).toBeGreaterThan(0.2);
    expect(mid).toBeLessThan(0.8);
  });
});
