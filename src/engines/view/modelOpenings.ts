import { findBeam, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../bake/bakeScene';
import type { L3dBody } from './luminaires/l3dBody';
import { l3dOpening } from './luminaires/l3dOpening';
import { modelBodyKey } from './luminaires/modelBodyKey';

/** One photometry object per file and opening, so luminaires sharing both still share a profile (prepareLamps, luminaireGroups key on the object). */
const withOpening = new WeakMap<Photometry, Map<string, Photometry>>();

function photometryWithOpening(ph: Photometry, opening: Photometry['luminousOpening']): Photometry {
  const o = ph.luminousOpening;
  if (o.width === opening.width && o.length === opening.length && o.height === opening.height && o.shape === opening.shape) return ph;
  let byOpening = withOpening.get(ph);
  if (!byOpening) withOpening.set(ph, (byOpening = new Map()));
  const key = `${opening.shape} ${opening.width} ${opening.length} ${opening.height}`;
  let out = byOpening.get(key);
  if (!out) byOpening.set(key, (out = { ...ph, luminousOpening: opening }));
  return out;
}

/**
 * The bake scene with the luminous opening of every module whose type has a loaded L3D body
 * replaced by the body's light-emitting object (l3dOpening; docs/gldf.md "The L3D's opening in the
 * near field"): the L3D wins over the photometric file's header dimensions, since it is the
 * geometry the glow divides the flux by and the one drawn. `ids` is the module id of each bake
 * luminaire (toLightingScene's luminaire ids), `bodies` keyed by modelBodyKey.
 */
export function withModelOpenings(bake: BakeScene, ids: readonly string[], config: Configuration, catalog: Catalog, bodies: ReadonlyMap<string, L3dBody>): BakeScene {
  if (bodies.size === 0) return bake;
  const modules = new Map(config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)).map((m) => [m.id, m]));
  let changed = false;
  const luminaires = bake.luminaires.map((l, i) => {
    const m = modules.get(ids[i]);
    const type = m ? catalog.moduleTypes.find((t) => t.id === m.type) : undefined;
    const key = type ? modelBodyKey(type) : null;
    const body = key ? bodies.get(key) : undefined;
    if (!m || !type || !body) return l;
    const photometry = photometryWithOpening(l.photometry, l3dOpening(body, findBeam(type, m.beam).roll));
    if (photometry === l.photometry) return l;
    changed = true;
    return { ...l, photometry };
  });
  return changed ? { ...bake, luminaires } : bake;
}
