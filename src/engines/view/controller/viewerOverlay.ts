import type { BakeScene } from '../../bake/bakeScene';
import { applyLiveLevels } from '../applyLiveLevels';
import { luminaireWeight } from '../luminaireWeight';
import { beamAndFieldDeg, withoutModule, type SpotlightDeps } from '../createSpotlight';
import type { Viewer } from './viewer';

/** The service lights the scene with the live overlay and the spotlight's dimmed module, if any (a relight: only dimming and colour change). */
export function applyOverlay(v: Viewer): void {
  const { live, dimmed, ids } = v;
  v.service.setOverlay(
    live || dimmed
      ? (s: BakeScene) => {
          const levels = live ? applyLiveLevels(s, ids, live) : s;
          return dimmed ? withoutModule(levels, ids, dimmed) : levels;
        }
      : null,
  );
}

/** The spotlight view the host asked for, shown once the scene has its module's luminaire (beam and field from its photometry). */
export function syncSpotlight(v: Viewer): void {
  const request = v.spotRequest;
  const i = request ? v.ids.indexOf(request.moduleId) : -1;
  const l = i >= 0 ? v.scene?.luminaires[i] : undefined;
  v.spotlight.set(request && l ? { ...request, ...beamAndFieldDeg(l.photometry) } : null);
  v.frames.request();
}

/** What the spotlight view takes from the viewer (`viewer` is read when called: the spotlight is one of its parts). */
export function viewerSpotlightDeps(canvas: HTMLCanvasElement, controls: SpotlightDeps['controls'], linearFloat: boolean, viewer: () => Viewer): SpotlightDeps {
  return {
    canvas,
    view: () => viewer().view,
    controls,
    request: () => viewer().frames.request(),
    room: () => viewer().scene?.room ?? null,
    lamp(moduleId) {
      const v = viewer();
      const i = v.ids.indexOf(moduleId);
      const l = i >= 0 ? v.scene?.luminaires[i] : undefined;
      if (!l) return null;
      return { photometry: l.photometry, weight: luminaireWeight(l) };
    },
    setDimmed(moduleId) {
      const v = viewer();
      if (moduleId === v.dimmed) return;
      v.dimmed = moduleId;
      if (v.scene) applyOverlay(v);
    },
    onAim: (moduleId, aim) => viewer().events.onAim?.(moduleId, aim),
    linearFloat,
  };
}
