/**
 * Every generated shader variant compiles and links on a real WebGL2 context
 * (headless-gl / ANGLE): the features are enumerated, not sampled. Also the
 * program cache: an identical scene compiles nothing new.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { blurPass } from '../../../shaders/blurPass.glsl';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import { fluxRatioPass, reduceSumPass, seriesRatioPass } from '../../../shaders/fluxReduce.glsl';
import { brightGatherPass } from '../../../shaders/brightGatherPass.glsl';
import { residualPass } from '../../../shaders/residualPass.glsl';
import { chartTileSums, tileSums } from '../../../src/engines/bake/readTileSums';
import { chartResidualPass } from '../../../shaders/chartTileSumPass.glsl';
import { blockSumPass, patchMaskPass, topMergePass } from '../../../shaders/brightSelection.glsl';
import { gpuChartPatchTable, gpuPatchTable, gpuTileKeys, gpuTopBlock } from '../../../src/engines/bake/selectBrightPatchesOnGpu';
import { cachedProgramCount, getProgram } from '../../../src/engines/bake/glResources';
import { generateDirectShader, generateShadowedDirectShader, type DirectLamp } from '../../../src/engines/bake/generateDirectShader';
import { generateGatherShader, generateObjectAwareGatherShader, generateObjectGatherShader } from '../../../src/engines/bake/generateGatherShader';
import { generateObjectDirectShader } from '../../../src/engines/bake/objects/objectPassDirectShader';
import { occludedBrightGatherPass } from '../../../shaders/occludedBrightGatherPass.glsl';
import { chartBlurPass } from '../../../shaders/chartBlurPass.glsl';
import { chartDilatePass } from '../../../shaders/chartDilatePass.glsl';
import { objectFluxRatioPass, objectReduceSumPass, objectReflectedFluxPass } from '../../../shaders/objectFluxReduce.glsl';
import { buildProfileTable } from '../../../src/engines/bake/profileTable';
import { luminaireRotation } from '../../../src/engines/bake/luminaireRotation';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { basePhotometry, isotropic, spot, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
gl.getExtension('EXT_color_buffer_float');

// Profiles covering each lookup path: rotational + uniform γ; rotational + mapped γ;
// full C grid, uniform both; bilateral-like mapped C; mapped γ finer than the bin cap.
const profiles = [
  isotropic(100),
  spot(1000, 5, 2, 0.5),
  basePhotometry({ verticalAngles: [0, 3, 10, 45, 90, 90.01, 180], candela: [[5, 5, 4, 2, 1, 0, 0]] }),
  basePhotometry({ symmetry: 'none', verticalAngles: [0, 90, 180], horizontalAngles: [0, 90, 180, 270, 360], candela: Array.from({ length: 5 }, (_, h) => [10 + h, 5, 0]) }),
  basePhotometry({ symmetry: 'none', verticalAngles: [0, 45, 90, 90.01, 180], horizontalAngles: [0, 10, 90, 300, 360], candela: Array.from({ length: 5 }, () => [3, 2, 1, 0, 0]) }),
  basePhotometry({ verticalAngles: Array.from({ length: 20001 }, (_, i) => (i * 180) / 20000), candela: [Array.from({ length: 20001 }, () => 1)] }),
  basePhotometry({ verticalAngles: [0, ...Array.from({ length: 9000 }, (_, i) => 0.001 + i * 0.01), 180], candela: [Array.from({ length: 9002 }, () => 1)] }),
];
const table = buildProfileTable(profiles, 'measured');
// The default lookup: the same profiles resampled onto dense grids (denseProfileGrid.ts).
const denseTable = buildProfileTable(profiles);
const layouts = surfaceLayouts({ width: 3, height: 2.5, depth: 4 }, 0.25, 64);
const compiles = (pass: { source: string }) => expect(() => getProgram(gl, pass.source)).not.toThrow();

describe('generated shaders compile', () => {
  it('the profile table takes every lookup path', () => {
    const measured = table.layouts.map((l) => (l.lookup.kind === 'measured' ? l.lookup : null));
    const kinds = measured.map((l) => (l ? `${l.horizontal ? 'C' : 'rot'}:${l.vertical.uniform ? 'u' : 'm'}${l.horizontal ? (l.horizontal.uniform ? 'u' : 'm') : ''}` : 'dense'));
    expect(kinds).toEqual(['rot:u', 'rot:u', 'rot:m', 'C:uu', 'C:mm', 'rot:u', 'rot:m']);
    // The last grid is finer than the bin-table cap: several angles share a bin.
    expect(measured[6]?.vertical.mapSize).toBe(8192);
    // Dense: rotational profiles are 1D, the others keep their C axis.
    expect(denseTable.layouts.map((l) => (l.lookup.kind === 'dense' ? (l.lookup.c ? 'C' : 'rot') : 'measured'))).toEqual(['rot', 'rot', 'rot', 'C', 'C', 'rot', 'rot']);
  });

  for (const [p, profile] of [...table.layouts.entries(), ...denseTable.layouts.map((l, i) => [i + table.layouts.length, l] as const)]) {
    for (const sources of [1, 6]) {
      it(`direct: profile ${p}, ${sources} point source(s), every surface`, () => {
        const lamp: DirectLamp = {
          profile,
          rotation: luminaireRotation(10, 20, 30),
          sources: Array.from({ length: sources }, (_, k) => [1 + 0.01 * k, 1.2, 2]),
          weight: [1, 0.5, 0.25],
        };
        for (const layout of layouts) compiles(generateDirectShader(layout, [lamp]));
      });
    }
  }

  it('direct: many luminaires with all profiles in one shader', () => {
    const lamps: DirectLamp[] = table.layouts.map((profile, k) => ({ profile, rotation: luminaireRotation(k * 40, k * 10, 0), sources: [[0.5 + 0.3 * k, 1, 1]], weight: [1, 1, 1] }));
    compiles(generateDirectShader(layouts[0], lamps));
  });

  const reflectances: [string, Rgb[]][] = [
    ['all grey', SURFACE_NAMES.map((): Rgb => [0.5, 0.5, 0.5])],
    ['some black', SURFACE_NAMES.map((_, i): Rgb => (i % 2 ? [0, 0, 0] : [0.3, 0.6, 0.9]))],
    ['only one reflecting', SURFACE_NAMES.map((_, i): Rgb => (i === 0 ? [0.2, 0.2, 0.2] : [0, 0, 0]))],
  ];
  for (const [name, rho] of reflectances) {
    it(`gather: ${name}, every receiving surface`, () => {
      for (const layout of layouts) compiles(generateGatherShader(layout, [3, 2.5, 4], rho));
    });
  }

  it('direct: texel means (sub-sampling) and a tall opening (faces emitting one hemisphere each)', () => {
    const lamp: DirectLamp = {
      profile: table.layouts[1],
      rotation: luminaireRotation(0, 10, 0),
      sources: [
        [1, 2.2, 2],
        [1, 2.4, 2],
      ],
      sides: [-1, 1],
      weight: [1, 1, 1],
    };
    for (const layout of layouts) compiles(generateDirectShader(layout, [lamp, { ...lamp, sides: undefined }], 8));
  });

  it('with objects: shadowed direct (texel means, tall opening), atlas direct, object-aware gathers, occluded bright gather', () => {
    const lamp: DirectLamp = {
      profile: table.layouts[3],
      rotation: luminaireRotation(0, 10, 0),
      sources: [
        [1, 2.2, 2],
        [1, 2.4, 2],
      ],
      sides: [-1, 1],
      weight: [1, 1, 1],
    };
    const lamps = [lamp, { ...lamp, sides: undefined, profile: table.layouts[1] }];
    const objects = { bvhWidth: 1024, atlasWidth: 37, atlasHeight: 21 };
    for (const layout of layouts) {
      compiles(generateShadowedDirectShader(layout, lamps, 8, objects.bvhWidth));
      compiles(generateShadowedDirectShader(layout, lamps, 1, objects.bvhWidth));
      for (const [, rho] of reflectances) compiles(generateObjectAwareGatherShader(layout, [3, 2.5, 4], rho, objects));
    }
    compiles(generateObjectDirectShader(lamps, objects.bvhWidth));
    for (const [, rho] of reflectances) compiles(generateObjectGatherShader([3, 2.5, 4], rho, objects));
    compiles(occludedBrightGatherPass(objects.bvhWidth));
    // Rooms of any shape: patches on the atlas's charts (one-sided, an atlas texel skipping its own chart).
    compiles(occludedBrightGatherPass(objects.bvhWidth, true));
    for (const pass of [chartBlurPass, chartDilatePass, objectReduceSumPass, objectFluxRatioPass, objectReflectedFluxPass]) compiles(pass);
  });

  it('fixed passes: combine, tail, flux reduction, blur', () => {
    compiles(combinePass);
    compiles(combineTailPass);
    compiles(reduceSumPass);
    compiles(fluxRatioPass);
    // A room with openings: the tail's ratio of successive reflected fluxes (issue 30).
    compiles(seriesRatioPass);
    // Bright-patch passes (runBrightPatchPass.ts).
    compiles(tileSums);
    compiles(residualPass);
    compiles(brightGatherPass);
    // The selection on the GPU (selectBrightPatchesOnGpu.ts).
    for (const pass of [gpuTileKeys, blockSumPass, gpuTopBlock, topMergePass, gpuPatchTable, patchMaskPass]) compiles(pass);
    // Bright patches on the atlas's charts (rooms of any shape): chart tile sums, the table over any frame, the atlas residual.
    for (const pass of [chartTileSums, gpuChartPatchTable, chartResidualPass]) compiles(pass);
    compiles(blurPass);
  });

  it('identical scenes reuse compiled programs (cache keyed by source)', () => {
    const baker = createBaker(gl);
    const scene = { room: uniformRoom(2, 2, 2, 0.5), luminaires: [{ photometry: spot(500, 20, 5, 1), position: [1, 1.9, 1] as [number, number, number], yaw: 0, pitch: 0, roll: 0 }] };
    const first = baker.bake(scene, { texelSize: 0.2, samples: 4, bounces: 1 }).report;
    const before = cachedProgramCount(gl);
    const second = baker.bake(scene, { texelSize: 0.2, samples: 4, bounces: 1 }).report;
    expect(cachedProgramCount(gl)).toBe(before);
    expect(first.shaders.some((s) => !s.cached)).toBe(true);
    expect(second.shaders.every((s) => s.cached)).toBe(true);
    // A downlight spot never reaches the ceiling: no direct shader for it.
    expect(second.shaders.filter((s) => s.pass === 'direct')).toHaveLength(5);
  });

  it('a black room generates no indirect code', () => {
    const { report } = createBaker(gl).bake({ room: uniformRoom(2, 2, 2, 0), luminaires: [{ photometry: isotropic(10), position: [1, 1, 1], yaw: 0, pitch: 0, roll: 0 }] }, { texelSize: 0.2 });
    expect(report.indirectEnabled).toBe(false);
    expect(report.shaders.map((s) => s.pass)).not.toContain('gather');
    expect(report.shaders.map((s) => s.pass)).not.toContain('blur');
  });
});
