import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { InputError } from '../../../src/core/inputError';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { cameraPreset, CAMERA_PRESETS, parseCameraSpec } from '../../../src/engines/view/cameraPresets';
import { suspensionPoints } from '../../../src/core/model/rails/suspensionPoints';
import { aimedOrientation } from '../../../src/core/model/modules/aim';
import { fixturesFromConfiguration, RAIL_HEIGHT } from '../../../src/engines/view/fixtures';
import { modelHeight } from '../../../src/engines/view/luminaires/luminaireDimensions';

const room = { width: 5, height: 2.8, depth: 4 };

describe('camera presets and --camera', () => {
  it('eye: inside the room at eye height; top: above, looking down; corner: outside, above the south-east corner', () => {
    const eye = cameraPreset('eye', room);
    expect(eye.position[1]).toBeCloseTo(1.6, 9);
    for (let a = 0; a < 3; a++) expect(eye.position[a]).toBeGreaterThan(0);
    expect(eye.position[0]).toBeLessThan(room.width);
    expect(eye.position[2]).toBeLessThan(room.depth);
    const top = cameraPreset('top', room);
    expect(top.position[1]).toBeGreaterThan(room.height);
    expect(Math.hypot(top.position[0] - top.target[0], top.position[2] - top.target[2])).toBeLessThan(0.01);
    const corner = cameraPreset('corner', room);
    expect(corner.position[0]).toBeGreaterThan(room.width);
    expect(corner.position[1]).toBeGreaterThan(room.height);
    expect(corner.position[2]).toBeGreaterThan(room.depth);
  });

  it('top view sees the whole floor: half-extent within the half field of view', () => {
    const top = cameraPreset('top', room);
    const dist = top.position[1];
    const halfFov = ((top.fov / 2) * Math.PI) / 180;
    expect(Math.max(room.width, room.depth) / 2).toBeLessThan(dist * Math.tan(halfFov));
  });

  it('parses presets and JSON; rejects bad specs with an InputError naming the field', () => {
    for (const p of CAMERA_PRESETS) expect(parseCameraSpec(p, room)).toEqual(cameraPreset(p, room));
    expect(parseCameraSpec('{"position":[1,2,3],"target":[2,1,2],"fov":50}', room)).toEqual({ position: [1, 2, 3], target: [2, 1, 2], fov: 50 });
    expect(parseCameraSpec('{"position":[1,2,3],"target":[2,1,2]}', room).fov).toBe(60);
    const bad: [string, RegExp][] = [
      ['side', /neither a preset/],
      ['{"position":[1,2],"target":[0,0,0]}', /position must be three/],
      ['{"position":[1,2,3],"target":"x"}', /target must be three/],
      ['{"position":[1,2,3],"target":[0,0,0],"fov":500}', /fov must be/],
      ['{"position":[1,2,3],"target":[1,2,3]}', /must differ/],
      ['[1,2,3]', /position must be three/],
      // Unknown fields are refused (issue 18), with a suggestion for a misspelling.
      ['{"position":[1,2,3],"target":[0,0,0],"fovy":50}', /^--camera: unknown field 'fovy' \(did you mean 'fov'\?\); expected position, target and fov$/],
      ['{"postion":[1,2,3],"target":[0,0,0]}', /^--camera: unknown field 'postion' \(did you mean 'position'\?\)/],
      ['{"position":[1,2,3],"target":[0,0,0],"up":[0,1,0]}', /^--camera: unknown field 'up'; expected position, target and fov$/],
    ];
    for (const [spec, message] of bad) {
      expect(() => parseCameraSpec(spec, room)).toThrow(InputError);
      expect(() => parseCameraSpec(spec, room)).toThrow(message);
    }
  });
});

describe('fixtures', () => {
  it('modules sit at the photometric centres the baker uses, turned as the baker turns them; rails above the tallest model; cables reach the ceiling', () => {
    const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
    expect(store.getState().dispatch('placePreset', { presetId: 'corner-l' })).toEqual({ ok: true });
    const config = store.getState().config;
    const f = fixturesFromConfiguration(config, defaultCatalog);
    const scene = toLightingScene(config, defaultCatalog);
    expect(f.modules.map((m) => m.id)).toEqual(scene.luminaires.map((l) => l.id));
    f.modules.forEach((m, i) => {
      expect(m.centre).toEqual(scene.luminaires[i].position);
      const { yaw, pitch, roll } = scene.luminaires[i];
      expect(m.orientation).toEqual({ yaw, pitch, roll });
    });
    const y = scene.luminaires[0].position[1];
    // The rail's underside clears the tallest model (the spot's yoke and a 2 cm stem).
    const drop = Math.max(...f.modules.map((m) => modelHeight({ kind: m.kind, opening: null, length: m.length })));
    expect(f.modules.map((m) => m.kind)).toContain('spot');
    expect(f.rails).toHaveLength(config.systems[0].rails.length);
    expect(f.railWidth).toBe(defaultCatalog.rail.width);
    for (const r of f.rails) expect(r.start[1]).toBeCloseTo(y + drop + RAIL_HEIGHT / 2, 12);
    for (const m of f.modules) expect(m.mount).toBeCloseTo(drop, 12);
    // Cables at the fixing points the bill of materials counts (spacing and overhang rules), ceiling to rail top.
    const points = suspensionPoints(config.systems[0], defaultCatalog);
    expect(f.cables).toHaveLength(points.length);
    f.cables.forEach((c, i) => {
      expect(c.top).toEqual([points[i].plan[0], config.room.height, points[i].plan[1]]);
      expect(c.bottom[1]).toBeCloseTo(y + drop + RAIL_HEIGHT, 12);
    });
    // The corner connector's sleeve: its two arms (systemElementTree), at the rails' height.
    expect(f.connectors).toHaveLength(2);
    for (const c of f.connectors) expect(c.y).toBe(f.rails[0].start[1]);
  });

  it("an aimed module keeps the rail heading and takes the lighting scene's orientation", () => {
    const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
    expect(store.getState().dispatch('placePreset', { presetId: 'corner-l' })).toEqual({ ok: true });
    const c0 = store.getState().config;
    const m = c0.systems[0].rails[0].modules[0];
    const aim = { rotation: 30, tilt: 40 };
    const config = { ...c0, systems: [{ ...c0.systems[0], rails: [{ ...c0.systems[0].rails[0], modules: [{ ...m, aim }, ...c0.systems[0].rails[0].modules.slice(1)] }, ...c0.systems[0].rails.slice(1)] }] };
    const f = fixturesFromConfiguration(config, defaultCatalog);
    expect(f.modules[0].orientation).toEqual(aimedOrientation(f.modules[0].heading, 0, aim));
    expect(f.modules[0].orientation.pitch).toBe(40);
  });

  it('a ceiling-surface system: modules at the mount drop, rails under the ceiling, no cables', () => {
    const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
    expect(store.getState().dispatch('placePreset', { presetId: 'single' })).toEqual({ ok: true });
    const systemId = store.getState().config.systems[0].id;
    expect(store.getState().dispatch('setMounting', { systemId, mounting: 'surface' })).toEqual({ ok: true });
    const config = store.getState().config;
    const f = fixturesFromConfiguration(config, defaultCatalog);
    const H = config.room.height;
    expect(f.cables).toEqual([]);
    for (const m of f.modules) expect(m.centre[1]).toBeCloseTo(H - defaultCatalog.surfaceMount.drop, 12);
    for (const m of f.modules) expect(m.centre[1]).toBe(toLightingScene(config, defaultCatalog).luminaires[0].position[1]);
    for (const r of f.rails) expect(r.start[1] + RAIL_HEIGHT / 2).toBeLessThanOrEqual(H + 1e-12);
  });
});
