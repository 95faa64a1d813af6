import type { BakeScene } from '../../bake/bakeScene';
import type { QualityLevel } from '../../relight/qualityLevels';
import type { LightSources } from '../../relight/daylightGroups';
import type { BakeStatus } from '../bakeService';
import { applyFade, type ServiceFade } from './serviceFade';
import { currentSettings, lightEngine, litScene, type ServiceCore } from './serviceCore';
import { encloseShapedRoom } from '../../bake/shapedRoom/encloseShapedRoom';

/** A new scene: replaces pending work; the engine keeps unchanged groups. */
export function setServiceScene(c: ServiceCore, next: BakeScene): void {
  if (c.disposed) return;
  c.scene = next;
  c.prepared = c.prepareFor(encloseShapedRoom(next).objects, currentSettings(c));
  lightEngine(c, c.context.engine, next);
  c.slicer.queue();
}

/** Live control's levels over the scene (a relight), or null. */
export function setServiceOverlay(c: ServiceCore, next: ((scene: BakeScene) => BakeScene) | null): void {
  c.overlay = next;
  if (!c.scene || c.disposed) return;
  lightEngine(c, c.context.engine, c.scene);
  c.slicer.queue();
}

/** A crossfade step (or its end): a relight, announced as a slice at once. */
export function setServiceFade(c: ServiceCore, next: ServiceFade | null): void {
  if (c.disposed || (next === null && c.fade === null)) return;
  c.fade = next;
  const engine = c.context.engine;
  if (!engine || !c.scene) return;
  // A scene faded from that does not match the one the engine holds (its luminaires changed) ends the fade: the scene shows.
  if (!c.fade) engine.setFade(null);
  else c.fade = applyFade(engine, litScene(c, c.scene), c.fade);
  // Drawn now (a relight), not after the input-quiet hold of bake work; the end state's solve, if new, is queued.
  c.emit({ type: 'slice', engine, progress: engine.progress });
  c.slicer.queue();
}

/**
 * Which light is shown: 'electric', 'daylight', 'both' (RelightEngine.setLightSources: weights, no
 * basis rebaked) or 'daylight-factor' (the overcast basis alone, baked when first asked for;
 * docs/daylight.md, "The daylight factor's light"); a relight announced as a slice at once, the
 * re-solve or the overcast basis's bake (if new) queued.
 */
export function setServiceLightSources(c: ServiceCore, sources: LightSources): void {
  if (c.disposed || sources === c.lightSources) return;
  const engine = c.context.engine;
  // The engine checks the value first (it throws on an unknown one), so the service never keeps a wrong one.
  engine?.setLightSources(sources);
  c.lightSources = sources;
  if (!engine || !c.scene) return;
  c.emit({ type: 'slice', engine, progress: engine.progress });
  c.slicer.queue();
}

/** Another quality level: a fresh engine, which rebakes the scene. */
export function setServiceQuality(c: ServiceCore, level: QualityLevel): void {
  if (level === c.quality || c.disposed) return;
  c.quality = level;
  const engine = c.context.setSettings(c.levelSettings(level));
  if (c.scene) c.prepared = c.prepareFor(encloseShapedRoom(c.scene).objects, currentSettings(c));
  if (c.scene) lightEngine(c, engine, c.scene);
  c.emit({ type: 'engine', engine });
  c.slicer.queue();
}

/** A stalled engine replaced (as a quality change would) and the scene baked afresh. */
export function restartService(c: ServiceCore): void {
  c.stall.restarted();
  const engine = c.context.setSettings(c.levelSettings(c.quality));
  if (c.scene) lightEngine(c, engine, c.scene);
  c.emit({ type: 'engine', engine });
  c.slicer.queue();
}

export function serviceStatus(c: ServiceCore): BakeStatus {
  const engine = c.context.engine;
  const done = c.scene !== null && engine !== null && engine.progress.done;
  return { running: !done && !c.slicer.paused && c.scene !== null && engine !== null, paused: c.slicer.paused, done, ...c.context.counters(), restarts: c.stall.restarts, quality: c.quality };
}

/** Stops listening and baking and frees the bake context (once). */
export function disposeService(c: ServiceCore, stopVisibility: () => void): void {
  if (c.disposed) return;
  c.disposed = true;
  stopVisibility();
  c.userInput.dispose();
  c.slicer.stop();
  c.listeners.clear();
  c.context.dispose();
}
