import type { BakeSettings } from '../../bake/bakeSettings';
import type { BakeScene } from '../../bake/bakeScene';
import type { PreparedObjects } from '../../bake/objects/preparedObjects';
import type { RelightEngine } from '../../relight/RelightEngine';
import type { LightSources } from '../../relight/daylightGroups';
import type { QualityLevel } from '../../relight/qualityLevels';
import type { BakeContext } from '../createBakeContext';
import type { BakeSlicer } from '../createBakeSlicer';
import type { createObjectsMemo } from '../createObjectsMemo';
import type { BakeEvent } from '../bakeService';
import type { StallWatch } from './createStallWatch';
import { applyFade, type ServiceFade } from './serviceFade';
import type { UserInputWatch } from './watchUserInput';
import { encloseShapedRoom } from '../../bake/shapedRoom/encloseShapedRoom';

/** What the bake service's pieces share: its state and its parts (createBakeService wires them). */
export interface ServiceCore {
  quality: QualityLevel;
  scene: BakeScene | null;
  /** Live control's levels over the scene (a relight), or null. */
  overlay: ((s: BakeScene) => BakeScene) | null;
  fade: ServiceFade | null;
  /** Which light the engine shows (RelightEngine.setLightSources); kept for every engine the service makes. */
  lightSources: LightSources;
  error: string | null;
  disposed: boolean;
  prepared: PreparedObjects | null;
  /** Targets freed for the engine version that finished (low memory), so the free runs once per bake. */
  trimmedAt: number;
  readonly lowMemory: boolean;
  readonly context: BakeContext;
  readonly slicer: BakeSlicer;
  readonly stall: StallWatch;
  readonly userInput: UserInputWatch;
  readonly emit: (event: BakeEvent) => void;
  readonly listeners: Set<(event: BakeEvent) => void>;
  readonly levelSettings: (level: QualityLevel) => BakeSettings;
  readonly prepareFor: ReturnType<typeof createObjectsMemo>;
}

/**
 * The scene as the engine lights it: with the overlay, if any; a room of any shape inside its
 * enclosure (encloseShapedRoom: remembered per shape and objects, so every change of dimming keeps one atlas).
 */
export function litScene(c: ServiceCore, s: BakeScene): BakeScene {
  return encloseShapedRoom(c.overlay ? c.overlay(s) : s);
}

/** The engine's scene and, during a fade, its fade; a fade whose scenes no longer match (a module added meanwhile) ends. */
export function lightEngine(c: ServiceCore, engine: RelightEngine | null, s: BakeScene): void {
  if (!engine) return;
  const given = c.overlay ? c.overlay(s) : s;
  engine.setLightSources(c.lightSources);
  // The scene as given: the engine encloses a shaped room itself (the same remembered enclosure),
  // and its daylight groups need the room's shape and `daylight`, which the enclosed scene drops.
  engine.setScene(given);
  const shown = encloseShapedRoom(given);
  if (!c.fade) return;
  c.fade = applyFade(engine, shown, c.fade);
}

/** The engine's settings, or the quality level's while there is no engine. */
export function currentSettings(c: ServiceCore): BakeSettings {
  return c.context.engine?.settings ?? c.levelSettings(c.quality);
}

/** The service's state before its parts are made (the bake context reports errors while it is created). */
export type ServiceState = Omit<ServiceCore, 'context' | 'slicer' | 'stall' | 'userInput'>;

/** The last error, kept and told to the subscribers. */
export function reportError(c: ServiceState, message: string): void {
  c.error = message;
  c.emit({ type: 'error', message });
}
