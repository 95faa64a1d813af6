/**
 * Lamps as uniforms (issue #15, docs/baker.md "Lamps as uniforms"): the relight engine's direct
 * bases bake with `lampUniforms`, whose programs depend only on the surface, the photometry and
 * the source count. Checked here: the maps equal the constant-folded variant's (walls with texel
 * supersampling near a wall, a tall opening with per-source hemispheres, a pitched lamp, the
 * objects' atlas) to 1e-5 of the peak; equal photometry gives equal programs wherever the lamp
 * is; and a moved module, or a second module of the same type, compiles nothing in the relight
 * engine (every gl.shaderSource call is counted).
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import type { Photometry } from '../../../src/core/photometry/types';
import type { BakeLuminaire, BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { generateDirectShader, lampUniformVectors, MAX_LAMP_UNIFORM_VECTORS } from '../../../src/engines/bake/generateDirectShader';
import { prepareLamps } from '../../../src/engines/bake/prepareLamps';
import { profileFunction } from '../../../src/engines/bake/profileFunction';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { boxMesh } from './objects/objectFixtures';
import { basePhotometry, spot, uniformRoom } from './bakeTestKit';
import { recordShaderSources } from './recordShaderSources';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const compiled = recordShaderSources(gl);
const baker = createBaker(gl);

/** A tall opening (10 cm > sourceSpacing): two 4×4 grids, the bottom one emitting down, the top one up. */
const pendant = { ...spot(2000, 35, 10, 1), luminousOpening: { width: 0.2, length: 0.2, height: 0.1, shape: 'rectangular' as const } };
/** Emits into every direction (an up-light share too), so every surface is reached wherever it hangs. */
const globe = basePhotometry({ verticalAngles: [0, 60, 120, 180], candela: [[400, 300, 120, 60]], luminousOpening: { width: 0.15, length: 0.15, height: 0, shape: 'rectangular' } });
const room = uniformRoom(2.6, 2.5, 2.8, [0.6, 0.5, 0.4]);
const table: BakeObject = { id: 'table', mesh: boxMesh(0.8, 0.7, 0.6, 0.6), position: [1.2, 0, 1.3], yaw: 20, scale: 1 };
const SETTINGS = { texelSize: 0.1, maxTextureSize: 64, samples: 8, bounces: 0, samplesPerDraw: 8, blurRadius: 1, seed: 3 };

const scene: BakeScene = {
  room,
  luminaires: [
    // 8 cm from the north wall (z = 0): the wall's texels near it are sub-sampled.
    { photometry: pendant, position: [0.9, 1.9, 0.08], yaw: 25, pitch: 20, roll: 5, color: [1, 0.8, 0.6] },
    { photometry: globe, position: [1.9, 2.3, 1.9], yaw: 0, pitch: 0, roll: 0, dimming: 0.7 },
  ],
  objects: [table],
};

function directMaps(s: BakeScene, lampUniforms: boolean) {
  const before = compiled.length;
  const job = baker.start(s, { ...SETTINGS, lampUniforms });
  try {
    return { direct: job.readDirect(), sources: compiled.slice(before), shaders: job.report().shaders };
  } finally {
    job.dispose();
  }
}

/** Worst |a − b| over every map, relative to the peak of b. */
function worstRelative(a: Float32Array[], b: Float32Array[]): { worst: number; peak: number } {
  let peak = 0;
  let worst = 0;
  b.forEach((m, k) => {
    expect(a[k].length).toBe(m.length);
    for (let i = 0; i < m.length; i++) {
      peak = Math.max(peak, m[i]);
      worst = Math.max(worst, Math.abs(a[k][i] - m[i]));
    }
  });
  return { worst: worst / peak, peak };
}

describe('direct passes with the lamps as uniforms', () => {
  it('give the maps of the constant-folded passes (walls sub-sampled near a wall, tall opening, pitched lamp, objects atlas) to 1e-5 of the peak', () => {
    const constant = directMaps(scene, false);
    const uniform = directMaps(scene, true);
    // The uniform variant really ran: every direct program says so, no constant variant's does.
    const directSources = (r: { sources: string[] }) => r.sources.filter((s) => s.includes('// direct pass'));
    expect(directSources(uniform).length).toBeGreaterThan(0);
    expect(directSources(uniform).every((s) => s.includes('lamps as uniforms'))).toBe(true);
    expect(directSources(uniform).some((s) => /uniform vec3 uLamp\dSources\[32\];/.test(s))).toBe(true);
    expect(directSources(constant).some((s) => s.includes('lamps as uniforms'))).toBe(false);
    expect(uniform.sources.some((s) => s.includes("objects' atlas") && s.includes('lamps as uniforms'))).toBe(true);
    expect(uniform.sources.some((s) => s.includes('texel means') && /LAMP\d_SIDE\[32\]/.test(s))).toBe(true);
    const walls = worstRelative(
      SURFACE_NAMES.map((n) => uniform.direct.surfaces[n]),
      SURFACE_NAMES.map((n) => constant.direct.surfaces[n]),
    );
    expect(walls.peak).toBeGreaterThan(1000); // the pendant 8 cm from the north wall
    expect(walls.worst).toBeLessThan(1e-5);
    const atlas = worstRelative([uniform.direct.objects!.emitted], [constant.direct.objects!.emitted]);
    expect(atlas.peak).toBeGreaterThan(10);
    expect(atlas.worst).toBeLessThan(1e-5);
  });

  it('are the same programs for the same photometry wherever the lamp is (profile code included)', () => {
    const settings = resolveBakeSettings(SETTINGS);
    const layouts = surfaceLayouts(room, settings.texelSize, settings.maxTextureSize);
    const at = (position: BakeLuminaire['position'], yaw: number, photometry: Photometry = pendant) => prepareLamps({ room, luminaires: [{ photometry, position, yaw, pitch: 0, roll: 0 }] }, settings).lamps;
    const a = at([0.9, 2.0, 0.9], 0);
    const b = at([1.7, 2.2, 2.1], 70);
    expect(a[0].sources).not.toEqual(b[0].sources);
    // One group's table holds only its own profile: same id, same offsets, the same lookup code.
    expect(profileFunction(a[0].profile)).toBe(profileFunction(b[0].profile));
    // Another photometry alone in its table also gets id 0 and offset 0.
    expect(at([1, 1, 1], 0, globe)[0].profile.id).toBe(a[0].profile.id);
    for (const layout of layouts) {
      expect(generateDirectShader(layout, b, 8, true).source).toBe(generateDirectShader(layout, a, 8, true).source);
      expect(generateDirectShader(layout, b, 8, false).source).not.toBe(generateDirectShader(layout, a, 8, false).source);
    }
  });

  it('keep the constants when a pass would need more uniform vectors than any GPU must offer', () => {
    const settings = resolveBakeSettings({ ...SETTINGS, maxSourcesPerAxis: 12, sourceSpacing: 0.01 });
    const lamps = prepareLamps({ room, luminaires: [{ photometry: pendant, position: [1, 2, 1], yaw: 0, pitch: 0, roll: 0 }] }, settings).lamps;
    expect(lampUniformVectors(lamps, true)).toBeGreaterThan(MAX_LAMP_UNIFORM_VECTORS);
    const pass = generateDirectShader(surfaceLayouts(room, 0.1, 64)[0], lamps, 8, true);
    expect(pass.lampValues).toBeUndefined();
    expect(pass.source).not.toContain('lamps as uniforms');
  });

  it('let the relight engine move a module and add a second one of the same type without compiling a program', () => {
    const engine = createRelightEngine(gl, { texelSize: 0.2, maxTextureSize: 32, samples: 8, bounces: 1, samplesPerDraw: 8, blurRadius: 1 });
    try {
      const module = (position: BakeLuminaire['position'], yaw = 0): BakeLuminaire => ({ photometry: globe, position, yaw, pitch: 0, roll: 0 });
      const base: BakeScene = { room, luminaires: [module([0.8, 2.3, 0.9])], objects: [table] };
      engine.setScene(base);
      const first = compiled.length;
      engine.finish();
      expect(compiled.length).toBeGreaterThan(first); // the first module and the solve compile
      const moved = { ...base, luminaires: [module([1.9, 2.2, 1.7], 40)] };
      expect(engine.setScene(moved).bake).toBe(1);
      const beforeMove = compiled.length;
      engine.finish();
      expect(engine.counters.groupBakes).toBe(2);
      expect(compiled.length - beforeMove).toBe(0);
      const two = { ...base, luminaires: [module([1.9, 2.2, 1.7], 40), module([0.6, 2.1, 2.2], 90)] };
      expect(engine.setScene(two).bake).toBe(1);
      const beforeSecond = compiled.length;
      engine.finish();
      expect(engine.counters.groupBakes).toBe(3);
      expect(compiled.length - beforeSecond).toBe(0);
    } finally {
      engine.dispose();
    }
  });

  it('a moved lamp in a constant-folded bake compiles its direct programs again (what the flag avoids)', () => {
    const s = (x: number): BakeScene => ({ room, luminaires: [{ photometry: globe, position: [x, 2.3, 1.2], yaw: 0, pitch: 0, roll: 0 }] });
    directMaps(s(1.0), false);
    const constantMoved = directMaps(s(1.5), false).shaders.filter((e) => e.pass === 'direct');
    expect(constantMoved.some((e) => !e.cached)).toBe(true);
    directMaps(s(1.0), true);
    const uniformMoved = directMaps(s(1.5), true).shaders.filter((e) => e.pass === 'direct');
    expect(uniformMoved.length).toBe(6);
    expect(uniformMoved.every((e) => e.cached)).toBe(true);
  });
});
