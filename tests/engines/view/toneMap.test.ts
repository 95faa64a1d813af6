import createGL from 'gl';
import * as THREE from 'three';
import { afterAll, describe, expect, it } from 'vitest';
import { falseColorGlsl } from '../../../shaders/falseColor.glsl';
import { legendPosition, luxLevels, MAX_LEVELS, turbo, TURBO_B, TURBO_G, TURBO_R } from '../../../src/engines/view/falseColorScale';

const falseColorChunk = falseColorGlsl({ maxLevels: MAX_LEVELS, turbo: [TURBO_R, TURBO_G, TURBO_B] });
import { acesFilmic, displayColor, linearToSrgb } from '../../../src/engines/view/toneMap';
import { toneMapGlsl } from '../../../shaders/toneMap.glsl';

// The viewer's GLSL chunks compiled and run (three.js on headless-gl), checked against their TypeScript mirrors.
const N = 16;
const gl = createGL(N, 1, { createWebGL2Context: true, preserveDrawingBuffer: true, antialias: false }) as unknown as WebGL2RenderingContext & { getExtension(n: string): { destroy?(): void } | null };
const canvas = { width: N, height: 1, style: {}, addEventListener() {}, removeEventListener() {} } as unknown as HTMLCanvasElement;
Object.defineProperty(gl, 'canvas', { value: canvas });
const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
renderer.setSize(N, 1, false);
afterAll(() => {
  renderer.dispose();
  (gl.getExtension('STACKGL_destroy_context') as { destroy(): void } | null)?.destroy();
});

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

describe('display transform (exposure → ACES filmic → sRGB)', () => {
  it('sRGB OETF hits the IEC 61966-2-1 reference points', () => {
    expect(linearToSrgb(0)).toBe(0);
    expect(linearToSrgb(1)).toBeCloseTo(1, 12);
    expect(linearToSrgb(0.0031308)).toBeCloseTo(0.04045, 5);
    expect(linearToSrgb(0.18)).toBeCloseTo(0.4614, 4);
  });

  it('ACES curve: black stays black, monotonic, saturates below 1, grey stays grey', () => {
    expect(acesFilmic([0, 0, 0]).every((v) => Math.abs(v) < 1e-3)).toBe(true);
    let prev = -1;
    for (let x = 0.01; x < 100; x *= 1.5) {
      const [r, g, b] = acesFilmic([x, x, x]);
      // Strictly increasing until it reaches the clamp at 1.
      if (prev < 0.999) expect(r).toBeGreaterThan(prev);
      else expect(r).toBeGreaterThanOrEqual(prev);
      expect(Math.abs(r - g)).toBeLessThan(2e-3);
      expect(Math.abs(g - b)).toBeLessThan(2e-3);
      prev = r;
    }
    expect(prev).toBeLessThanOrEqual(1);
    expect(prev).toBeGreaterThan(0.95);
  });

  it('GLSL luxDisplay equals the TypeScript mirror within 1/255 (+ rounding)', () => {
    const inputs = Array.from({ length: N }, (_, i) => 0.002 * 1.8 ** i);
    const exposure = 0.7;
    const got = runShader(inputs, toneMapGlsl, 'c = luxDisplay(vec3(x, 0.5 * x, 0.25 * x), 0.7);');
    inputs.forEach((x, i) => {
      const want = displayColor([x, 0.5 * x, 0.25 * x], exposure).map((v) => v * 255);
      for (let k = 0; k < 3; k++) expect(Math.abs(got[i][k] - want[k])).toBeLessThanOrEqual(1.01);
    });
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
