import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import type { Photometry } from '../../core/photometry/types';
import type { L3dBody } from '../../engines/view/luminaires/l3dBody';
import { readL3dBody } from '../../engines/view/luminaires/readL3dBody';
import { pageFileLoaderOf } from './pagePhotometryLoader';

const caches = new WeakMap<(path: string) => Promise<Uint8Array>, Map<string, Promise<L3dBody | null>>>();

/**
 * The L3D bodies (catalog `model`, docs/gldf.md "L3D in the 3D view") of the module types a
 * configuration uses, by model path, loaded from the folder of the page's photometry loader
 * (pageFileLoaderOf) and read with readL3dBody, each file once per folder. A file that cannot be
 * loaded or read is left out, with a console warning: its modules are drawn as their kind.
 */
export async function loadModelBodies(loadPhotometry: (path: string) => Promise<Photometry>, config: Configuration, catalog: Catalog): Promise<Map<string, L3dBody>> {
  const used = new Set(config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.type))));
  const paths = [...new Set(catalog.moduleTypes.filter((t) => used.has(t.id) && t.model).map((t) => t.model!))];
  const loadFile = pageFileLoaderOf(loadPhotometry);
  if (!loadFile || paths.length === 0) return new Map();
  let cache = caches.get(loadFile);
  if (!cache) caches.set(loadFile, (cache = new Map()));
  const bodies = await Promise.all(
    paths.map((path) => {
      let body = cache.get(path);
      if (!body) {
        body = loadFile(path)
          .then((bytes) => readL3dBody(bytes, path))
          .catch((e: unknown) => {
            console.warn('luxbox: the luminaire body', path, 'is drawn as its kind:', e instanceof Error ? e.message : e);
            return null;
          });
        cache.set(path, body);
      }
      return body;
    }),
  );
  return new Map(paths.flatMap((p, i) => (bodies[i] ? [[p, bodies[i]] as [string, L3dBody]] : [])));
}
