import { createRoomView } from '../roomView';
import { drawCompare } from './compareSides';
import { bakeCounters, showMaps, syncObjects } from './showViewerMaps';
import { glareNow, syncGlare, type Viewer } from './viewer';
import { countGpuFrame, resetViewerGpu } from './gpuRelightFrame';

/** After a context loss: three re-creates its GL objects; the room is rebuilt so every texture and program is uploaded anew. */
export function restoreViewer(v: Viewer): void {
  v.view.dispose();
  v.compareView?.dispose();
  v.compareView = null;
  v.view = createRoomView(v.renderer);
  resetViewerGpu(v);
  v.view.setGlare(glareNow(v));
  v.camera.attach(v.view);
  if (v.fixtures) v.view.setFixtures(v.fixtures);
  v.view.setRoomShape(v.scene?.room.shape ?? null);
  v.view.setObjects(v.prepared);
  v.view.setSelectedObject(v.selectedObject);
  v.view.setSelectedModule(v.selectedModule);
  v.spotlight.reattach();
  v.shownVersion = -1;
  if (v.service.engine) showMaps(v, v.service.engine);
  v.events.onContext('restored');
  v.frames.request();
}

/** One frame: the room (and the compare's B side right of the wipe). */
export function drawViewerFrame(v: Viewer): void {
  // The eye adapting after a cut or a Re-adapt: one more frame while it moves (eyeAdaptation.ts).
  if (v.maps.advance(performance.now())) v.frames.request();
  v.view.render(v.renderer);
  if (v.compare && v.compareView) drawCompare(v, v.compare, v.compareView);
  countGpuFrame(v.gpu);
}

/** A tap at canvas pixel (x, y): an aim-at point, or a pick (none in the spotlight view, where a tap ends a drag of the head). */
export function tapViewer(v: Viewer, x: number, y: number): void {
  if (v.aimAt) {
    const point = v.view.pickPoint(x, y);
    if (point) v.events.onAimAt?.(point);
    return;
  }
  if (!v.spotlight.active()) v.events.onPick?.(v.view.pick(x, y));
}

/** The viewer follows the bake service's slices, engines, context and errors; returns the unsubscribe. */
export function followBakeService(v: Viewer): () => void {
  return v.service.subscribe((e) => {
    if (e.type === 'slice') {
      const p = e.progress;
      if (e.engine.version !== v.shownVersion && (p.lit || p.done)) showMaps(v, e.engine);
      else if (p.done !== v.lightDone) {
        // Done (or baking again) without new maps: the glare follows.
        v.lightDone = p.done;
        syncGlare(v);
        v.frames.request();
      }
      v.spotlight.bakeProgress(p.done);
      v.events.onProgress({ fraction: p.fraction, done: p.done, lit: p.lit, ...bakeCounters(v) });
    } else if (e.type === 'engine') {
      v.shownVersion = -1;
      syncObjects(v);
    } else if (e.type === 'context') v.events.onContext(e.state);
    else if (e.type === 'error') v.events.onError(e.message);
  });
}
