import type { BakeScene } from '../bake/bakeScene';
import { cameraPreset, type CameraPose, type CameraPresetName } from './cameraPresets';

/**
 * A camera preset framed for a view of the given aspect (width / height).
 * Presets frame the room for a landscape view; on a portrait screen the top
 * and corner cameras step back from their target by 1/aspect, so the room's
 * width still fits. Eye height stays where a person stands; the eye preset frames the scene's
 * light when a scene is given (frameTheLight.ts), its field widened on a portrait screen.
 */
export function framePreset(name: CameraPresetName, room: { width: number; height: number; depth: number }, aspect: number, scene?: BakeScene): CameraPose {
  const p = cameraPreset(name, room, scene ? { scene, aspect } : undefined);
  if (name !== 'eye' && aspect < 1) {
    const k = 1 / aspect;
    p.position = p.position.map((v, i) => p.target[i] + (v - p.target[i]) * k) as typeof p.position;
  }
  return p;
}
