import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from './bakeScene';
import { resolveBakeSettings, type BakeSettings } from './bakeSettings';
import type { Baker, GivenObjectDirect } from './bakeJob';
import { requireFloatTargets } from './floatTarget';
import { encloseShapedRoom } from './shapedRoom/encloseShapedRoom';
import { daylightBakeInput } from './daylight/daylightBakeInput';
import { startDaylightBakeJob } from './daylight/startDaylightBakeJob';
import { startBakeJob } from './startBakeJob';
import { createTargetPool } from './targetPool';

export type { BakeJob, BakeProgress, BakeReport, Baker, DirectMaps, GivenObjectDirect } from './bakeJob';

/** Create a baker on any WebGL2 context (browser canvas or headless-gl). */
export function createBaker(gl: WebGL2RenderingContext): Baker {
  const { linear } = requireFloatTargets(gl);
  // Render targets outlive a job: the next bake of the same room reuses them (targetPool.ts).
  const pool = createTargetPool(gl, linear);
  // A room of any shape bakes as its enclosure (shapedRoom/encloseShapedRoom.ts); a box scene passes unchanged.
  const start = (scene: BakeScene, partial: Partial<BakeSettings> | undefined, direct: Record<SurfaceName, Float32Array> | null, objectDirect: Float32Array | null = null) => {
    const enclosed = encloseShapedRoom(scene);
    // Windows with a sky or a sun are sources (daylight/startDaylightBakeJob.ts); a room without them bakes exactly as before.
    const daylight = direct ? null : daylightBakeInput(scene, enclosed);
    if (daylight) return startDaylightBakeJob(gl, linear, pool, daylight, resolveBakeSettings(partial));
    return startBakeJob(gl, linear, pool, enclosed, resolveBakeSettings(partial), direct, objectDirect);
  };
  return {
    dispose: () => pool.dispose(),
    start: (scene, settings) => start(scene, settings, null),
    startFromDirect: (room, direct, settings, objects?: GivenObjectDirect) =>
      // A shaped room's surfaces are objects: its given maps always include the atlas (objects.objects may be empty).
      objects && (objects.objects.length > 0 || room.shape || room.enclosure) ? start({ room, luminaires: [], objects: objects.objects }, settings, direct, objects.direct) : start({ room, luminaires: [] }, settings, direct),
    bake(scene, settings) {
      const job = start(scene, settings, null);
      try {
        job.run();
        return { maps: job.readMaps(), report: job.report() };
      } finally {
        job.dispose();
      }
    },
  };
}
