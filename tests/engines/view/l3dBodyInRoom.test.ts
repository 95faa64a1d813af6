/**
 * An imported GLDF track spot with its L3D (buildGldf.ts, buildL3dSpot.ts) drawn on the demo's
 * single rail (docs/gldf.md "L3D in the 3D view"): the fixtures carry the body of the catalog's
 * `model`, the rail hangs above the body's top, and the room's hardware draws the body in the
 * world: the lens glowing at the module's photometric centre (0.5 mm proud), facing down, then
 * along the beam's axis once aimed, with the yoke turned and the body's top under the rail.
 */
import { readFileSync } from 'node:fs';
import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { importGldfCatalog } from '../../../src/core/gldf/importGldfCatalog';
import { parseGldfMapping } from '../../../src/core/gldf/gldfMapping';
import { parseCatalogText } from '../../../src/core/model/catalogSchema/catalogSchema';
import { aimAxis } from '../../../src/core/model/modules/aim';
import { createRoomHardware } from '../../../src/engines/view/createRoomHardware';
import type { SharedDisplayUniforms } from '../../../src/engines/view/createRoomSurfaces';
import { fixturesFromConfiguration, RAIL_HEIGHT } from '../../../src/engines/view/fixtures';
import { PROUD } from '../../../src/engines/view/luminaires/luminaireDimensions';
import { modelBodyKey } from '../../../src/engines/view/luminaires/modelBodyKey';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { gldfBytes, MAPPING_TEXT, trackSpotSpec } from '../../core/gldf/buildGldf';
import { SPOT } from '../../core/gldf/buildL3dSpot';
import { only, run, withPreset } from '../../core/model/helpers';

const base = parseCatalogText(readFileSync('src/core/catalog/default-catalog.json', 'utf8'), 'default-catalog.json');
const imported = importGldfCatalog(base, [{ name: 'track-spot.gldf', bytes: gldfBytes(trackSpotSpec()) }], parseGldfMapping(MAPPING_TEXT, 'mapping.json'));
const catalog = imported.catalog;
const modelFile = imported.files.find((f) => f.path === 'geo/track-spot.l3d')!;
const spotType = catalog.moduleTypes.find((t) => t.id === 'track-spot')!;
const bodies = new Map([[modelBodyKey(spotType)!, readL3dBody(modelFile.bytes, 'geo/track-spot.l3d', spotType.modelEmitter)]]);
const display: SharedDisplayUniforms = { uExposure: { value: 2.5e-5 }, uAdapt: { value: new THREE.Matrix3() }, uMode: { value: 0 }, uLevels: { value: [] }, uLevelCount: { value: 0 } };

function placed(aim?: { rotation: number; tilt: number }) {
  let c = withPreset('single', 3, 3);
  const railId = only(c).rails[0].id;
  c = run(c, 'addModule', { railId, type: 'track-spot' }, catalog);
  const id = only(c).rails[0].modules.find((m) => m.type === 'track-spot')!.id;
  if (aim) c = run(c, 'setAim', { moduleId: id, aim }, catalog);
  const fixtures = fixturesFromConfiguration(c, catalog, new Map(), bodies);
  const hardware = createRoomHardware(display);
  hardware.setFixtures(fixtures);
  hardware.group.updateMatrixWorld(true);
  const module = fixtures.modules.find((m) => m.id === id)!;
  const meshes = hardware.moduleMeshes().filter((m) => m.name === `module:${id}`);
  return { fixtures, module, meshes, hardware };
}

/** World-space centroid and normal of an emitter mesh (its first vertex normal). */
function worldFace(mesh: THREE.Mesh): { centre: THREE.Vector3; normal: THREE.Vector3 } {
  const pos = mesh.geometry.getAttribute('position');
  const centre = new THREE.Vector3();
  for (let i = 0; i < pos.count; i++) centre.add(new THREE.Vector3().fromBufferAttribute(pos, i).applyMatrix4(mesh.matrixWorld));
  centre.divideScalar(pos.count);
  const normal = new THREE.Vector3().fromBufferAttribute(mesh.geometry.getAttribute('normal'), 0).transformDirection(mesh.matrixWorld);
  return { centre, normal };
}

const emitterOf = (meshes: THREE.Mesh[]) => meshes.filter((m) => (m.material as THREE.ShaderMaterial).uniforms.uEmitter.value === 1);

describe('an imported L3D body on the rail', () => {
  it('the fixtures carry the body; the rail hangs just above its top', () => {
    const { fixtures, module, hardware } = placed();
    expect(module.body).toBe(bodies.get(modelBodyKey(spotType)!));
    // The rail clears the tallest module: the body's top (128 mm) or the preset's own spots, whichever is taller.
    expect(module.mount).toBeGreaterThanOrEqual(SPOT.insert);
    expect(fixtures.rails[0].start[1] - RAIL_HEIGHT / 2 - module.centre[1]).toBeCloseTo(module.mount, 9);
    // Alone on the rail, the body's top sets it: the rail's underside 128 mm above the photometric centre.
    let c = withPreset('single', 3, 3);
    const railId = only(c).rails[0].id;
    for (const m of only(c).rails[0].modules) c = run(c, 'removeModule', { moduleId: m.id }, catalog);
    c = run(c, 'addModule', { railId, type: 'track-spot' }, catalog);
    const alone = fixturesFromConfiguration(c, catalog, new Map(), bodies);
    expect(alone.modules).toHaveLength(1);
    expect(alone.modules[0].mount).toBeCloseTo(SPOT.insert, 6); // float32 vertices
    hardware.dispose();
  });

  it('draws the lens glowing at the photometric centre, facing down, and nothing of the body above the rail', () => {
    const { module, meshes, hardware } = placed();
    const [lens] = emitterOf(meshes);
    const { centre, normal } = worldFace(lens);
    expect(centre.x).toBeCloseTo(module.centre[0], 6);
    expect(centre.y).toBeCloseTo(module.centre[1] - PROUD, 6);
    expect(centre.z).toBeCloseTo(module.centre[2], 6);
    expect(normal.y).toBeCloseTo(-1, 6);
    const box = new THREE.Box3();
    for (const m of meshes) box.expandByObject(m);
    // The body's 128 mm, a stem up to the rail's underside and the adapter (28 mm) inside the profile.
    expect(box.max.y).toBeCloseTo(module.centre[1] + module.mount + 0.028, 5);
    // The head (Ø 70 mm) and the yoke (84 mm across) are the widest parts: within 42 mm of the axis.
    expect(box.max.x - module.centre[0]).toBeLessThanOrEqual(0.042 + 1e-6);
    hardware.dispose();
  });

  it('aimed, the lens faces along the beam: rotation 60°, tilt 40°', () => {
    const aim = { rotation: 60, tilt: 40 };
    const { module, meshes, hardware } = placed(aim);
    const { normal } = worldFace(emitterOf(meshes)[0]);
    const axis = aimAxis(module.heading, aim);
    expect(normal.angleTo(new THREE.Vector3(...axis))).toBeLessThan(1e-4);
    hardware.dispose();
  });
});
