import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { demoConfiguration } from '../../../src/core/catalog/demoConfiguration';
import type { Configuration, LightSystem } from '../../../src/core/model/configuration/configuration';
import { modulePlacements, railPlacements } from '../../../src/core/model/rails/geometry';
import { newModule } from '../../../src/core/model/actions/presets';
import { validate } from '../../../src/core/model/validation/validate';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { createUiStore } from '../../../src/core/store/uiStore';
import type { KeyChord } from '../../../src/ui/planner/keyChord';
import { PlannerController } from '../../../src/ui/planner/PlannerController';
import { type PlanPoint, type ScreenPoint, worldToScreen } from '../../../src/ui/planner/viewTransform';
import { systemAtOneOne } from '../../core/model/helpers';

export const catalog = defaultCatalog;

/** System s1 at (1, 1) heading +x: rail r2 of 1.5 m packed from the start (spot m3 0–0.15, linear m4 0.15–0.75), then rail r5. */
export function twoRailSystem(): Configuration {
  return systemAtOneOne(
    [
      { id: 'r2', length: 1.5, distribution: 'start', modules: [newModule(catalog, 'm3', 'spot'), newModule(catalog, 'm4', 'linear')] },
      { id: 'r5', length: 1, distribution: 'start', modules: [] },
    ],
    [{ connector: 'straight', turn: 0 }],
    'f6',
    7,
  );
}

/**
 * A planner without React or a DOM, driven like a user would (in the manner of tldraw's
 * TestEditor): pointer, wheel and key input in plan pixels go to the same PlannerController
 * the React hooks feed, and the stores show what came of it.
 */
export class TestPlanner {
  readonly store;
  readonly ui = createUiStore({ phase: 'planner' });
  readonly controller: PlannerController;

  constructor(initial: Configuration = demoConfiguration(catalog), viewport = { width: 1000, height: 800 }) {
    this.store = createConfiguratorStore({ catalog, initial });
    this.controller = new PlannerController(this.store, this.ui);
    this.controller.setViewport(viewport);
  }

  get config(): Configuration {
    return this.store.getState().config;
  }

  get view() {
    return this.controller.view;
  }

  get status(): string | undefined {
    return this.ui.getState().status?.text;
  }

  /**
   * Moves a system (through the store, not the UI) to the nearest whole-centimetre position,
   * so a drag's snapping to centimetres changes nothing and moves can be checked exactly.
   */
  alignToCentimetres(index = 0): this {
    const s = this.system(index);
    const r = this.store.getState().dispatch('moveSystem', { systemId: s.id, x: Math.round(s.x * 100) / 100, z: Math.round(s.z * 100) / 100 });
    if (!r.ok) throw new Error(r.reason);
    return this;
  }

  system(index = 0): LightSystem {
    return this.config.systems[index];
  }

  /** Where a world point (metres) is on screen now. */
  screenOf(p: PlanPoint): ScreenPoint {
    return worldToScreen(this.view, p);
  }

  /** The middle of a system's rail on screen. */
  railCentre(railIndex = 0, system = this.system()): ScreenPoint {
    const r = railPlacements(system, catalog)[railIndex];
    return this.screenOf({ x: (r.start[0] + r.end[0]) / 2, z: (r.start[1] + r.end[1]) / 2 });
  }

  /** The centre of a module on screen. */
  moduleCentre(moduleIndex = 0, system = this.system()): ScreenPoint {
    const m = modulePlacements(system, catalog)[moduleIndex];
    return this.screenOf({ x: m.centre[0], z: m.centre[1] });
  }

  /** Press at `from`, move there in `steps` and release: a drag (or a tap when it does not move). */
  drag(from: ScreenPoint, to: ScreenPoint, steps = 5): this {
    this.controller.pointerDown(from);
    for (let i = 1; i <= steps; i++) {
      this.controller.pointerMove({ sx: from.sx + ((to.sx - from.sx) * i) / steps, sy: from.sy + ((to.sy - from.sy) * i) / steps });
    }
    this.controller.pointerUp(to);
    return this;
  }

  tap(at: ScreenPoint): this {
    this.controller.pointerDown(at);
    this.controller.pointerUp(at);
    return this;
  }

  /** A key chord as written in the command table: 'r', 'Shift+r', 'Mod+z', 'ArrowLeft'. Returns whether a command took it. */
  press(spec: string): boolean {
    // The key is what follows the last '+' separator; '+' itself ends the spec ('Shift++').
    const key = spec.endsWith('+') ? '+' : spec.slice(spec.lastIndexOf('+') + 1);
    const mods = spec.slice(0, spec.length - key.length).split('+');
    const chord: KeyChord = { key, mod: mods.includes('Mod'), shift: mods.includes('Shift'), alt: mods.includes('Alt') };
    if (chord.shift && chord.key.length === 1) chord.key = chord.key.toUpperCase();
    return this.controller.keyDown(chord);
  }

  /** The model's problems with the configuration now (none: it is valid). */
  problems() {
    return validate(this.config, catalog);
  }
}
