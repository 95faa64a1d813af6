import { parsePhotometry } from '../../core/photometry/parsePhotometry';
import type { Photometry } from '../../core/photometry/types';

const cache = new Map<string, Promise<Photometry>>();

/** Fetch and parse a photometric file once per URL (relative paths resolve against the page, i.e. the app's public folder). */
export function loadPhotometry(path: string): Promise<Photometry> {
  let p = cache.get(path);
  if (!p) {
    const url = new URL(path, document.baseURI).href;
    p = fetch(url)
      .then((r) => {
        if (!r.ok) throw new Error(`${path}: HTTP ${r.status}`);
        return r.arrayBuffer();
      })
      .then((buf) => parsePhotometry(new Uint8Array(buf), path));
    p.catch(() => cache.delete(path));
    cache.set(path, p);
  }
  return p;
}
