import { reflectanceRgb, type BakeScene } from '../../bake/bakeScene';
import type { RelightEngine } from '../../relight/RelightEngine';
import { litMapsOf, moduleWeightsOf } from '../compareMaps';
import { objectLightOf } from '../objectLight';
import { createRoomView, type RoomView } from '../roomView';
import { glareNow, type CompareRequest, type Viewer } from './viewer';

/** Both sides' maps from the engine (relights, no bake): A on the main view, B on the compare view; the exposure and adaptation stay the held ones. False: not shown. */
export function showCompare(v: Viewer, engine: RelightEngine, request: CompareRequest): boolean {
  const lit = litMapsOf(engine, [request.a, request.b]);
  if (!lit || !v.scene) return false;
  const reflectance = reflectanceRgb(v.scene.room);
  if (!v.compareView) {
    v.compareView = createRoomView(v.renderer);
    v.compareView.setGlare(glareNow(v));
    if (v.fixtures) v.compareView.setFixtures(v.fixtures);
    v.compareView.setRoomShape(v.scene.room.shape ?? null);
    v.compareView.setObjects(v.prepared);
  }
  const sides: [RoomView, BakeScene][] = [
    [v.view, request.a],
    [v.compareView, request.b],
  ];
  sides.forEach(([side, s], k) => {
    side.setMaps(lit[k], reflectance);
    side.setObjectLight(objectLightOf(lit[k]));
    side.setModuleWeights(moduleWeightsOf(s, v.ids));
  });
  return true;
}

/** B over the part of the canvas right of the wipe: same camera, same exposure, adaptation and mode as A. */
export function drawCompare(v: Viewer, request: CompareRequest, b: RoomView): void {
  const from = v.view.display;
  const to = b.display;
  to.uExposure.value = from.uExposure.value;
  to.uAdapt.value.copy(from.uAdapt.value);
  to.uMode.value = from.uMode.value;
  to.uLevelCount.value = from.uLevelCount.value;
  from.uLevels.value.forEach((level, i) => (to.uLevels.value[i] = level));
  b.camera.copy(v.view.camera);
  b.camera.updateMatrixWorld();
  const { width, height } = v.camera.size;
  const x = Math.round(Math.min(1, Math.max(0, request.split)) * width);
  v.renderer.setScissor(x, 0, width - x, height);
  v.renderer.setScissorTest(true);
  b.render(v.renderer);
  v.renderer.setScissorTest(false);
}
