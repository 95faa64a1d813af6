import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Photometry } from '../../core/photometry/types';
import type { L3dBody } from '../../engines/view/luminaires/l3dBody';
import { modelBodyKey } from '../../engines/view/luminaires/modelBodyKey';
import { readL3dBody } from '../../engines/view/luminaires/readL3dBody';
import { pageFileLoaderOf } from './pagePhotometryLoader';

const caches = new WeakMap<(path: string) => Promise<Uint8Array>, Map<string, Promise<L3dBody | null>>>();

/**
 * The L3D bodies (catalog `model`, docs/gldf.md "L3D in the 3D view") of the module types a
 * configuration uses, by modelBodyKey (the path, and the `modelEmitter` the photometry belongs
 * to), loaded from the folder of the page's photometry loader (pageFileLoaderOf) and read with
 * readL3dBody, each once per folder. A file that cannot be loaded
 * or read (or lacks the named emitter) is left out, with a console warning: its modules are drawn
 * as their kind.
 */
export async function loadModelBodies(loadPhotometry: (path: string) => Promise<Photometry>, config: Configuration, catalog: Catalog): Promise<Map<string, L3dBody>> {
  const used = new Set(config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.type))));
  const wanted = new Map(catalog.moduleTypes.filter((t) => used.has(t.id) && t.model).map((t) => [modelBodyKey(t)!, { path: t.model!, emitter: t.modelEmitter }]));
  const loadFile = pageFileLoaderOf(loadPhotometry);
  if (!loadFile || wanted.size === 0) return new Map();
  let cache = caches.get(loadFile);
  if (!cache) caches.set(loadFile, (cache = new Map()));
  const keys = [...wanted.keys()];
  const bodies = await Promise.all(
    keys.map((key) => {
      let body = cache.get(key);
      if (!body) {
        const { path, emitter } = wanted.get(key)!;
        body = loadFile(path)
          .then((bytes) => readL3dBody(bytes, path, emitter))
          .catch((e: unknown) => {
            console.warn('luxbox: the luminaire body', path, 'is drawn as its kind:', e instanceof Error ? e.message : e);
            return null;
          });
        cache.set(key, body);
      }
      return body;
    }),
  );
  return new Map(keys.flatMap((k, i) => (bodies[i] ? [[k, bodies[i]] as [string, L3dBody]] : [])));
}
