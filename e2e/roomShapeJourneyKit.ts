import { readFileSync } from 'node:fs';
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { roomShapeSupportChunk } from '../src/core/model/actions/roomShapeChunk';
import { installRoomShapeSupport } from '../src/core/model/configuration/roomShapeSupport';
import { deserializeConfiguration } from '../src/core/model/files/sceneFile';
import type { LightingScene, Vec3 } from '../src/core/model/lightingScene/lightingScene';
import { suspensionPoints, suspensionWireLengths } from '../src/core/model/rails/suspensionPoints';
import { parsePhotometry } from '../src/core/photometry/parsePhotometry';
import type { Photometry } from '../src/core/photometry/types';
import { referencePointSources } from '../src/reference/pointSources';
import { roomDirectAt } from '../src/reference/roomDirect';
import { luminanceOf } from '../src/reference/solveRoomReference';
import { visibleDirectAt } from '../src/reference/visibleDirectAt';

/**
 * The Node side of e2e/roomShapeJourney.spec.ts, run by tsx (the model imports JSON, which
 * Playwright's ES-module loader refuses without import attributes): the model's own rules and the
 * independent reference (src/reference, no code shared with the baker) applied to what the running
 * app reports (getConfig, getLightingScene), so the journey's numbers are checked against code
 * that did not produce them. Reads { sceneFile, scene?, points? } as JSON on stdin and writes
 * { wires, direct } as JSON on stdout.
 */
installRoomShapeSupport(roomShapeSupportChunk);

/** Each fixing point's plan position and wire length (suspensionWireLengths), for the configuration the app saved. */
function wiresOf(sceneFileJson: string): { plan: [number, number]; wire: number }[] {
  const config = deserializeConfiguration(sceneFileJson, defaultCatalog);
  const system = config.systems[0];
  const wires = suspensionWireLengths(system, config.room, defaultCatalog);
  return suspensionPoints(system, defaultCatalog).map((p, i) => ({ plan: [p.plan[0], p.plan[1]], wire: wires[i] }));
}

/** The luminaires' photometric files from public/ies (the browser's scene names them by URL). */
function photometries(scene: LightingScene): Map<string, Photometry> {
  const files = new Map<string, Photometry>();
  for (const l of scene.luminaires) {
    const name = l.photometry.split('/').pop()!;
    if (!files.has(l.photometry)) files.set(l.photometry, parsePhotometry(readFileSync(`public/ies/${name}`), name));
  }
  return files;
}

/** Direct floor illuminance (lux, Y) at a plan point by the reference: with the room's own shadows, and as if the walls let the light through. */
interface FloorDirect {
  point: [number, number];
  shadowed: number;
  unoccluded: number;
}

/**
 * The reference's direct light on the floor at plan points of a shaped room: roomDirectAt decides
 * exactly whether the room stands between the point and each source (CIE 171:2006 §5.2 with V),
 * visibleDirectAt with every sight line clear gives the same sources unshadowed.
 */
function referenceFloorDirect(scene: LightingScene, points: readonly [number, number][]): FloorDirect[] {
  // The contract's normalised room (src/core/room, which the reference also builds its rooms with): corners, height, convexity.
  const room = scene.room.shape!;
  const xs = room.corners.map((c) => c[0]);
  const zs = room.corners.map((c) => c[1]);
  // The box the point sources are expanded in: the outline's bounding box, which starts at the origin for the app's shapes (they span 0 to width and depth).
  const box: LightingScene = {
    version: 1,
    room: { width: Math.max(...xs), height: room.height, depth: Math.max(...zs), reflectance: { floor: 0, ceiling: 0, north: 0, south: 0, west: 0, east: 0 } },
    luminaires: scene.luminaires,
  };
  const sources = referencePointSources(box, photometries(scene));
  const up: Vec3 = [0, 1, 0];
  return points.map(([x, z]) => {
    const q: Vec3 = [x, 0, z];
    const shadowed = luminanceOf(roomDirectAt(sources, { convex: room.convex, corners: room.corners }, q, up), 0);
    const unoccluded = luminanceOf(
      visibleDirectAt(sources, q, up, () => true, [0, 0, 0]),
      0,
    );
    return { point: [x, z], shadowed, unoccluded };
  });
}

const input = JSON.parse(readFileSync(0, 'utf8')) as { sceneFile: string; scene?: LightingScene; points?: [number, number][] };
process.stdout.write(JSON.stringify({ wires: wiresOf(input.sceneFile), direct: input.scene ? referenceFloorDirect(input.scene, input.points ?? []) : [] }));
