// Run with tsx inside a checkout of the commit (tests/fixtures/formats/README.md): it imports that checkout's TypeScript sources.
// Makes a real file of this checkout's scene-file version: the demo configuration, then every
// action this version knows that uses a field an earlier version lacked (tried in order; a refused
// or unknown one is skipped and logged). Run in a checkout of the version's last commit.
import { writeFileSync } from 'node:fs';
import { defaultCatalog } from './src/core/catalog/defaultCatalog';
import { demoConfiguration } from './src/core/catalog/demoConfiguration';
// The model's files moved into domain folders (core/model/files, core/model/actions) after version 8: the first path that exists.
async function load(...paths) {
  for (const p of paths) {
    try {
      return await import(p);
    } catch {
      /* not in this checkout */
    }
  }
  return null;
}
const sf = await load('./src/core/model/files/sceneFile', './src/core/model/sceneFile');
// Share links moved out of the scene file's module (core/model/files/shareLink) too.
const share = (await load('./src/core/model/files/shareLink')) ?? sf;
const defs = await load('./src/core/model/actions/actionDefinitions', './src/core/model/actionDefinitions');
const { toLightingScene } = await load('./src/core/model/files/toLightingScene', './src/core/model/toLightingScene');
// Version 3 lighting scenes are written through lightingSceneJson (the room as its author wrote it); older ones as the object.
const sceneJson = (await load('./src/core/model/lightingScene/lightingSceneJson'))?.lightingSceneJson ?? ((scene) => scene);
const out = process.argv[2];
let config = demoConfiguration(defaultCatalog);
const v = sf.SCENE_FILE_VERSION ?? (await load('./src/core/model/files/sceneFileSchema')).SCENE_FILE_VERSION;
const mods = () => config.systems.flatMap((s) => (s.rails ?? []).flatMap((r) => r.modules));
const sys = () => config.systems[0];
const rails = () => sys().rails;
function run(name, params) {
  if (!defs.attemptAction || !(name in defs.actionDefinitions)) return console.log('  skip', name);
  const o = defs.attemptAction(config, name, params, defaultCatalog);
  if (o.ok === false) return console.log('  refused', name, o.reason);
  config = o.state ?? o.config ?? o.next ?? o.value;
  if (!config) throw new Error('outcome shape ' + Object.keys(o));
  console.log('  ok', name);
}
// The room-shape chunk's actions (version 10's daylight among them) are not in the first screen's table.
function runChunk(name, params) {
  const o = defs.attemptAction(config, name, params, defaultCatalog);
  if (o.ok === false) throw new Error(`${name} refused: ${o.reason}`);
  config = o.next;
  console.log('  ok', name);
}
const cube = {
  positions: new Float32Array([0, 0, 0, 0.4, 0, 0, 0.4, 0, 0.4, 0, 0, 0.4, 0, 0.4, 0, 0.4, 0.4, 0, 0.4, 0.4, 0.4, 0, 0.4, 0.4]),
  indices: new Uint32Array([0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1, 1, 5, 6, 1, 6, 2, 2, 6, 7, 2, 7, 3, 3, 7, 4, 3, 4, 0]),
  materialOfTriangle: new Uint16Array(12),
  materials: [{ name: 'oak', colour: [0.55, 0.4, 0.25], reflectance: [0.55, 0.4, 0.25] }],
};
run('autoPatch', { universe: 1, address: 1, resolution: 16, cct: true });
if (v >= 3) run('addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 1.6, z: 2.6 } });
if (v >= 3) run('addObject', { source: { kind: 'library', item: 'picture' }, placement: { on: 'wall', wall: 'north', u: 1.2, y: 1.5 } });
run('setFeedDriver', { feedId: sys().feeds?.[0]?.id, driver: 'hlg-320h-48' });
run('addFeed', { systemId: sys().id, at: 'end' });
run('moveModule', { moduleId: rails()[0].modules[0].id, offset: 0.1 });
run('moveFixingPoint', { systemId: sys().id, index: 0, s: 0.3 });
run('setModuleDimming', { moduleId: mods()[1].id, dimming: 0.4 });
run('setModuleFilter', { moduleId: mods()[0].id, filter: 'lee-106' });
run('setAim', { moduleId: mods()[0].id, aim: { rotation: 30, tilt: 20 } });
run('setModuleOn', { moduleId: mods()[2].id, on: false });
run('recordScene', { name: 'Evening', fade: 2 });
run('addBranch', { railId: rails()[rails().length - 1].id, connector: 'tee', turn: 90, length: 1 });
// Version 9: a room shape. No action writes one yet (the plan editor of issue 29 will), so the
// shape is set on the room directly and the file's reader (validate()) judges it below: an L whose
// notch misses the demo's systems and objects, a slope on its east wall, a door and a window, and
// its own finish on one wall.
if (v >= 9) {
  // Rooms of any shape are a lazy chunk in the browser (roomShapeSupport.ts); here it is loaded before the shape goes in.
  await (await import('./src/core/model/actions/loadRoomShapeSupport')).loadRoomShapeSupport();
  const shape = {
    outline: [
      [0, 0],
      [5, 0],
      [5, 2.5],
      [4.2, 2.5],
      [4.2, 4],
      [0, 4],
    ],
    slopes: [{ wall: 1, kneeHeight: 1.9, pitch: 35 }],
    openings: [
      { wall: 4, offset: 0.5, width: 0.9, sill: 0, height: 2, kind: 'door' },
      { wall: 0, offset: 2.5, width: 1.2, sill: 0.9, height: 1.2, kind: 'window' },
    ],
    wallReflectance: [0.5, 0.5, [0.6, 0.55, 0.5], 0.5, 0.5, 0.5],
  };
  config = { ...config, room: { ...config.room, shape } };
  sf.deserializeConfiguration(sf.serializeConfiguration(config, defaultCatalog), defaultCatalog, 'the shaped room');
  console.log('  ok room shape');
}
// Version 10: daylight (a clear day in Zurich, 17:00 on 21 December: the sun has set) and the window's glazing, through their actions.
if (v >= 10) {
  runChunk('setDaylight', { on: true, city: 'Zurich', date: '2026-12-21', time: '17:00', sky: 'cie-clear', groundReflectance: 0.25 });
  runChunk('setWindowGlazing', { opening: 1, transmittance: 'triple' });
}
const shareText = share.encodeShareString(config, defaultCatalog);
if (v >= 3) run('addObject', { source: { kind: 'import', name: 'crate.obj', mesh: cube, units: 'm' }, placement: { on: 'floor', x: 3.8, z: 0.8 } });
writeFileSync(`${out}/configuration-v${v}.luxbox.json`, sf.serializeConfiguration(config, defaultCatalog) + '\n');
writeFileSync(`${out}/share-link-v${v}.txt`, shareText + '\n');
try {
  await (await import('./src/core/colour/colourFilterSpectra')).loadColourFilterSpectra();
} catch {
  /* older versions load them eagerly */
}
const scene = toLightingScene(config, defaultCatalog);
writeFileSync(`${out}/lighting-scene-v${scene.version}.json`, JSON.stringify(sceneJson(scene), null, 2) + '\n');
console.log('version', v, 'lighting scene', scene.version);
