/**
 * Issue #35: whatever winding a model file has, the light in the room is the one of a correctly
 * wound copy. Models go through the real importer (OBJ text, glTF JSON) and the real baker on
 * headless-gl; the raw mis-wound meshes (not imported) show what the orientation prevents.
 * Analytic reference: the closed-box law mean E = Φ/(S(1−ρ)) (CIE 171:2006 §5.8, generalised to a
 * box with an object of the same ρ, as tests/engines/bake/furnished.test.ts).
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { TriangleMesh } from '../../../src/core/mesh/triangleMesh';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import type { BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import { insideOut, objText, quadMesh, wedgeMesh } from '../../core/mesh/orientFixtures';
import { boxMesh } from './objects/objectFixtures';
import { atlasArea, atlasFlux, isotropic, totalFlux, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';
import { textFile } from '../meshImport/modelFixtures';

const gl = withHeadlessGL();
const baker = createBaker(gl);

async function importObj(mesh: TriangleMesh, name = 'model.obj'): Promise<TriangleMesh> {
  return (await importMesh([textFile(name, objText(mesh))])).mesh;
}

/**
 * Each triangle's corners in winding order (9 numbers a triangle): the mesh as the baker sees it.
 * Importers number welded vertices by first use, so files listing corners in another order give
 * other index arrays for the same triangles.
 */
function corners(mesh: TriangleMesh): number[] {
  return Array.from(mesh.indices, (v) => [mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]]).flat();
}

function placed(id: string, mesh: TriangleMesh, position: Vec3, reflectance: number): BakeObject {
  return { id, mesh, position, yaw: 0, scale: 1, reflectance };
}

/** Largest |a − b| over every map of every surface and the atlas, relative to the largest value. */
function mapDifference(a: BakedMaps, b: BakedMaps): number {
  let diff = 0;
  let peak = 0;
  const pairs: Array<[Float32Array, Float32Array]> = [];
  for (const n of SURFACE_NAMES) for (const k of ['direct', 'indirect', 'total'] as const) pairs.push([a[n][k], b[n][k]]);
  if (a.objects && b.objects) for (const k of ['direct', 'indirect', 'total'] as const) pairs.push([a.objects[k], b.objects[k]]);
  for (const [x, y] of pairs) {
    expect(x.length).toBe(y.length);
    for (let i = 0; i < x.length; i++) {
      diff = Math.max(diff, Math.abs(x[i] - y[i]));
      peak = Math.max(peak, Math.abs(x[i]), Math.abs(y[i]));
    }
  }
  return diff / peak;
}

function meanLux(maps: BakedMaps, surface: 'floor' | 'ceiling', kind: 'direct' | 'indirect' | 'total', inside: (x: number, z: number) => boolean = () => true): number {
  const m = maps[surface];
  const lux = luxOf(m[kind]);
  let sum = 0;
  let n = 0;
  for (let j = 0; j < m.layout.height; j++) {
    for (let i = 0; i < m.layout.width; i++) {
      const [x, , z] = texelCentre(m.layout, i, j);
      if (!inside(x, z)) continue;
      sum += lux[j * m.layout.width + i];
      n++;
    }
  }
  return sum / n;
}

describe('an attic wedge (issue #35): imported as written, inside out or half flipped, the same light', async () => {
  // 4 × 2.5 × 4 m room, ρ 0.5; a closed wedge (8 triangles, ρ 0.8) along the west wall, its slope facing the lamp.
  const wedge = wedgeMesh(1.5, 1, 3);
  const halfFlipped: TriangleMesh = { ...wedge, indices: insideOut(wedge).indices.map((v, i) => (Math.floor(i / 3) % 2 === 0 ? v : wedge.indices[i])) };
  const [written, inverted, mixed] = await Promise.all([importObj(wedge), importObj(insideOut(wedge)), importObj(halfFlipped)]);
  const scene = (mesh: TriangleMesh): BakeScene => ({
    room: uniformRoom(4, 2.5, 4, 0.5),
    luminaires: [{ photometry: isotropic(300), position: [2.6, 2.2, 2], yaw: 0, pitch: 0, roll: 0 }],
    objects: [placed('wedge', mesh, [0.01, 0, 0.5], 0.8)],
  });
  const settings = { texelSize: 0.2, samples: 16, bounces: 3 };
  const reference = baker.bake(scene(written), settings);

  it('the inside-out and the half-flipped files import to the outward mesh, triangle for triangle, and bake identical maps', () => {
    expect(corners(inverted)).toEqual(corners(written));
    expect(corners(mixed)).toEqual(corners(written));
    expect(mapDifference(baker.bake(scene(inverted), settings).maps, reference.maps)).toBeLessThanOrEqual(1e-6);
    expect(mapDifference(baker.bake(scene(mixed), settings).maps, reference.maps)).toBeLessThanOrEqual(1e-6);
  });

  it('without the orientation (the raw inside-out mesh) the room loses a large part of its indirect light: what the import prevents', () => {
    const raw = baker.bake(scene(insideOut(wedge)), settings);
    const oriented = meanLux(reference.maps, 'floor', 'indirect');
    const wrong = meanLux(raw.maps, 'floor', 'indirect');
    console.info(`attic floor indirect: outward ${oriented.toFixed(1)} lx, raw inside-out ${wrong.toFixed(1)} lx`);
    expect(wrong).toBeLessThan(0.95 * oriented);
  });
});

describe('library furniture written out and read back in any winding: the same mesh', () => {
  it('sofa, shelf and person as OBJ, as written, inside out and with every third triangle flipped', async () => {
    for (const id of ['sofa', 'open-shelf', 'person']) {
      const mesh = furnitureMesh(id);
      const third: TriangleMesh = { ...mesh, indices: insideOut(mesh).indices.map((v, i) => (Math.floor(i / 3) % 3 === 0 ? v : mesh.indices[i])) };
      const [a, b, c] = await Promise.all([importObj(mesh, `${id}.obj`), importObj(insideOut(mesh), `${id}.obj`), importObj(third, `${id}.obj`)]);
      expect(corners(b), id).toEqual(corners(a));
      expect(corners(c), id).toEqual(corners(a));
      expect(a.indices.length, id).toBe(mesh.indices.length);
    }
  });
});

describe('library furniture imported as written and inside out: identical maps', async () => {
  // The sofa (closed parts, glued cushions) in a 4 × 2.5 × 4 m room, centred on the floor, lit from above.
  const sofa = furnitureMesh('sofa');
  const [written, inverted] = await Promise.all([importObj(sofa, 'sofa.obj'), importObj(insideOut(sofa), 'sofa.obj')]);
  const p = written.positions;
  const centre = [0, 2].map((a) => {
    let lo = Infinity;
    let hi = -Infinity;
    for (let i = a; i < p.length; i += 3) [lo, hi] = [Math.min(lo, p[i]), Math.max(hi, p[i])];
    return 2 - (lo + hi) / 2;
  });
  const scene = (mesh: TriangleMesh): BakeScene => ({
    room: uniformRoom(4, 2.5, 4, 0.5),
    luminaires: [{ photometry: isotropic(300), position: [2, 2.3, 2], yaw: 0, pitch: 0, roll: 0 }],
    objects: [placed('sofa', mesh, [centre[0], 0, centre[1]], 0.6)],
  });
  const settings = { texelSize: 0.2, samples: 16, bounces: 3 };

  it('the inside-out sofa bakes the maps of the sofa as written (1e-6 relative), and the raw inside-out one does not', () => {
    const reference = baker.bake(scene(written), settings).maps;
    expect(mapDifference(baker.bake(scene(inverted), settings).maps, reference)).toBeLessThanOrEqual(1e-6);
    // Without the orientation the difference is visible to this comparison.
    expect(mapDifference(baker.bake(scene(insideOut(sofa)), settings).maps, reference)).toBeGreaterThan(0.01);
  });
});

describe('two-sided open surfaces cast shadows whichever side the lamp is on', async () => {
  // 3 m cube, ρ 0.3; the 1 × 1 m quad at 2 m height between x, z = 1 … 2. A lamp 0.8 m above it
  // shadows the whole floor patch |x − 1.5|, |z − 1.5| < 1.75 (similar triangles: 0.5 · 2.8 / 0.8);
  // one 0.8 m below it shadows the ceiling patch within 1.125 (0.5 · 1.8 / 0.8). Texels whose
  // every point lies within 0.9 of the centre are wholly in the umbra: their direct light is 0.
  const inside = (x: number, z: number) => Math.abs(x - 1.5) < 0.9 - 0.15 && Math.abs(z - 1.5) < 0.9 - 0.15;
  const settings = { texelSize: 0.15, samples: 4, bounces: 1 };
  const scene = (mesh: TriangleMesh | null, lampY: number): BakeScene => ({
    room: uniformRoom(3, 3, 3, 0.3),
    luminaires: [{ photometry: isotropic(200), position: [1.5, lampY, 1.5], yaw: 0, pitch: 0, roll: 0 }],
    objects: mesh ? [placed('quad', mesh, [1, 2, 1], 0.8)] : [],
  });
  const open = {
    floor: meanLux(baker.bake(scene(null, 2.8), settings).maps, 'floor', 'direct', inside),
    ceiling: meanLux(baker.bake(scene(null, 1.2), settings).maps, 'ceiling', 'direct', inside),
  };
  const models: Array<[string, string, string]> = [
    ['an OBJ quad facing up', 'quad.obj', objText(quadMesh())],
    ['an OBJ quad facing down', 'quad.obj', objText(insideOut(quadMesh()))],
    ['a glTF doubleSided plane', 'plane.gltf', gltfQuad(true)],
  ];

  it.each(models)('%s: the floor under it (lamp above) and the ceiling over it (lamp below) get no direct light', async (_, name, text) => {
    const imported = await importMesh([textFile(name, text)]);
    expect(imported.orientation.twoSided).toBe(1);
    expect(open.floor).toBeGreaterThan(10);
    expect(open.ceiling).toBeGreaterThan(10);
    const floor = meanLux(baker.bake(scene(imported.mesh, 2.8), settings).maps, 'floor', 'direct', inside);
    const ceiling = meanLux(baker.bake(scene(imported.mesh, 1.2), settings).maps, 'ceiling', 'direct', inside);
    expect(floor).toBeLessThanOrEqual(1e-6 * open.floor);
    expect(ceiling).toBeLessThanOrEqual(1e-6 * open.ceiling);
  });
});

describe('closed box, ρ 0.5 everywhere, an inside-out object: flux balance', async () => {
  const phi = 1000;
  const block = await importObj(insideOut(boxMesh(0.8, 0.9, 0.7)));
  const outward = await importObj(boxMesh(0.8, 0.9, 0.7));
  const scene = (mesh: TriangleMesh): BakeScene => ({
    room: uniformRoom(3, 2.5, 3, 0.5),
    luminaires: [{ photometry: isotropic(phi / (4 * Math.PI)), position: [1.5, 1.9, 1.5], yaw: 0, pitch: 0, roll: 0 }],
    objects: [placed('block', mesh, [1.2, 0, 1.4], 0.5)],
  });
  const settings = { texelSize: 0.15, samples: 32, bounces: 4 };

  it('the maps equal the outward object’s (1e-6), Σ E·A within 0.5 %, and mean E = Φ/(S(1−ρ)) within 3 %', () => {
    const inv = baker.bake(scene(block), settings).maps;
    const out = baker.bake(scene(outward), settings).maps;
    // The inside-out box imports to the outward one: the same maps, texel for texel.
    expect(mapDifference(inv, out)).toBeLessThanOrEqual(1e-6);
    const fluxInv = totalFlux(inv, 'total') + atlasFlux(inv, 'total');
    const fluxOut = totalFlux(out, 'total') + atlasFlux(out, 'total');
    expect(Math.abs(fluxInv / fluxOut - 1)).toBeLessThan(0.005);
    let wallArea = 0;
    for (const n of SURFACE_NAMES) wallArea += inv[n].layout.lengthU * inv[n].layout.lengthV;
    const S = wallArea + atlasArea(inv);
    const expected = phi / (S * 0.5);
    console.info(`inside-out block imported: mean E ${(fluxInv / S).toFixed(2)} lx vs Φ/(S(1−ρ)) ${expected.toFixed(2)} lx`);
    expect(Math.abs(fluxInv / S / expected - 1)).toBeLessThan(0.03);
    // The raw inside-out box reflects nothing: its outside faces are back faces.
    const raw = baker.bake(scene(insideOut(boxMesh(0.8, 0.9, 0.7))), settings).maps;
    expect((totalFlux(raw, 'total') + atlasFlux(raw, 'total')) / S).toBeLessThan(0.97 * expected);
  });
});

describe('open surfaces: lit and reflecting on the side the light comes from', async () => {
  // 3 m cube, ρ 0.3; a 1 × 1 m quad (ρ 0.8) at 2 m whose file normal points up, lit from below by a lamp 1 m under it.
  const up = quadMesh();
  const down = insideOut(up);
  const scene = (mesh: TriangleMesh): BakeScene => ({
    room: uniformRoom(3, 3, 3, 0.3),
    luminaires: [{ photometry: isotropic(200), position: [1.5, 1, 1.5], yaw: 0, pitch: 0, roll: 0 }],
    objects: [placed('quad', mesh, [1, 2, 1], 0.8)],
  });
  const settings = { texelSize: 0.15, samples: 32, bounces: 2 };
  const under = (x: number, z: number) => Math.abs(x - 1.5) < 0.75 && Math.abs(z - 1.5) < 0.75;
  const rawUp = baker.bake(scene(up), settings).maps;
  const rawDown = baker.bake(scene(down), settings).maps;
  const upLux = meanLux(rawUp, 'floor', 'indirect', under);
  const downLux = meanLux(rawDown, 'floor', 'indirect', under);

  it('the raw one-sided quads differ: facing away from the lamp it reflects nothing down (the test can see the difference)', () => {
    console.info(`floor indirect under the quad: one-sided facing the lamp ${downLux.toFixed(2)} lx, facing away ${upLux.toFixed(2)} lx`);
    expect(upLux).toBeLessThan(0.9 * downLux);
  });

  it('an OBJ quad wound away from the lamp is two-sided: under it the floor gets what a quad facing the lamp gives (within 3 %)', async () => {
    const imported = await importMesh([textFile('quad.obj', objText(up))]);
    expect(imported.orientation).toMatchObject({ twoSided: 1, backTriangles: 2 });
    const maps = baker.bake(scene(imported.mesh), settings).maps;
    const lux = meanLux(maps, 'floor', 'indirect', under);
    console.info(`two-sided OBJ quad: ${lux.toFixed(2)} lx`);
    expect(Math.abs(lux / downLux - 1)).toBeLessThan(0.03);
  });

  it('a glTF plane: doubleSided reflects like the quad facing the lamp; one-sided (the spec’s default) stays as the file winds it', async () => {
    const two = await importMesh([textFile('plane.gltf', gltfQuad(true))]);
    const one = await importMesh([textFile('plane.gltf', gltfQuad(false))]);
    expect(two.orientation).toMatchObject({ twoSided: 1, oneSided: 0 });
    expect(one.orientation).toMatchObject({ twoSided: 0, oneSided: 1, backTriangles: 0 });
    const twoLux = meanLux(baker.bake(scene(two.mesh), settings).maps, 'floor', 'indirect', under);
    const oneMaps = baker.bake(scene(one.mesh), settings).maps;
    expect(Math.abs(twoLux / downLux - 1)).toBeLessThan(0.03);
    expect(mapDifference(oneMaps, rawUp)).toBeLessThanOrEqual(1e-6);
  });
});

/** A glTF 2.0 file of the 1 × 1 m quad of quadMesh() (normal +y), one material, doubleSided as given; buffer as a data URI. */
function gltfQuad(doubleSided: boolean): string {
  const positions = new Float32Array([0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0]);
  const indices = new Uint16Array([0, 1, 2, 0, 2, 3]);
  const bytes = new Uint8Array(positions.byteLength + indices.byteLength);
  bytes.set(new Uint8Array(positions.buffer), 0);
  bytes.set(new Uint8Array(indices.buffer), positions.byteLength);
  const uri = `data:application/octet-stream;base64,${Buffer.from(bytes).toString('base64')}`;
  return JSON.stringify({
    asset: { version: '2.0' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0 }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1, material: 0 }] }],
    materials: [{ name: 'plane', doubleSided, pbrMetallicRoughness: { baseColorFactor: [0.8, 0.8, 0.8, 1] } }],
    buffers: [{ byteLength: bytes.byteLength, uri }],
    bufferViews: [
      { buffer: 0, byteOffset: 0, byteLength: positions.byteLength },
      { buffer: 0, byteOffset: positions.byteLength, byteLength: indices.byteLength },
    ],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 4, type: 'VEC3', min: [0, 0, 0], max: [1, 0, 1] },
      { bufferView: 1, componentType: 5123, count: 6, type: 'SCALAR' },
    ],
  });
}
