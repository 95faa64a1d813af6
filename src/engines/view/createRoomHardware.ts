import type * as THREE from 'three';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { SharedDisplayUniforms } from './createRoomSurfaces';
import type { Fixtures } from './fixtures';
import { addModule, addTrack } from './hardware/hardwareModule';
import { clearHardware, initialHardwareState, paintSelection, setEmitterWeight } from './hardware/hardwareState';

export { frameMatrix } from './hardware/hardwareModule';

/** The drawn hardware (rails, connectors, cables, luminaire models with their glow) as a three.js group, rebuilt on each setFixtures. */
export interface RoomHardware {
  readonly group: THREE.Group;
  setFixtures(fixtures: Fixtures): void;
  /** Each module's weight now (dimming × colour, linear RGB) by id: the glow follows relights (live levels, crossfades). */
  setModuleWeights(weights: ReadonlyMap<string, Rgb>): void;
  /** The room's mean illuminance (RGB lux, area-weighted over its surfaces): what lights the housings. */
  setAmbient(illuminance: Rgb): void;
  /** Draw one module in the selection colour (null: none); kept across setFixtures. */
  setSelectedModule(id: string | null): void;
  /** The meshes a pick may hit, each named `module:<id>`. */
  moduleMeshes(): THREE.Mesh[];
  dispose(): void;
}

/**
 * `shading.linear`: the parts write adapt·(L·exposure), the value before the tone curve
 * (luminaireShading.glsl.ts), for a float target; the view itself never sets it.
 *
 * Its parts share one HardwareState (hardware/hardwareState.ts: materials, selection, emitter
 * weights); hardware/hardwareModule.ts builds the track and each module's parts.
 */
export function createRoomHardware(display: SharedDisplayUniforms, shading: { linear?: boolean } = {}): RoomHardware {
  const s = initialHardwareState(display, shading);
  return {
    group: s.group,
    setFixtures(fixtures) {
      clearHardware(s);
      addTrack(s, fixtures);
      for (const m of fixtures.modules) addModule(s, m);
      paintSelection(s);
    },
    setModuleWeights(weights) {
      for (const [id, w] of weights) {
        const m = s.modules.get(id);
        if (m) setEmitterWeight(m.emitters, w);
      }
    },
    setAmbient(e) {
      s.ambient.value.set(...(e.map((c) => (Number.isFinite(c) && c > 0 ? c : 0)) as Rgb));
    },
    setSelectedModule(id) {
      s.selected = id;
      paintSelection(s);
    },
    moduleMeshes() {
      return [...s.modules.values()].flatMap((m) => m.all);
    },
    dispose() {
      clearHardware(s);
      s.housing.dispose();
      s.cable.dispose();
      s.selectedMaterial.dispose();
    },
  };
}
