import { InputError } from '../../core/inputError';
import { parseCatalogText, type Catalog } from '../../core/model/catalogSchema/catalogSchema';

/** A catalog and the folder its photometry paths (`ies/…`) are relative to: mountLuxbox's `catalog` and `assetBase`. */
export interface CatalogFolder {
  catalog: Catalog;
  /** The catalog file's folder as an absolute URL ending in `/`. */
  assetBase: string;
}

/**
 * Fetches a catalog.json (a folder as `luxbox catalog import` writes it, docs/gldf.md) and
 * validates it. Its folder becomes the asset base, the convention of the standalone app's
 * `?catalog=` (docs/embedding.md): the photometry lies beside the catalog. `<Luxbox catalog="…">`
 * and `<luxbox-configurator catalog="…">` use it for a catalog given as a URL.
 * Throws an InputError naming the URL for a failed request, and a CatalogError for text that is
 * not JSON or a catalog the schema refuses.
 */
export async function loadCatalogFromUrl(url: string, fetchImpl: typeof fetch = (...args) => fetch(...args)): Promise<CatalogFolder> {
  const base = typeof document === 'undefined' ? undefined : document.baseURI;
  const absolute = new URL(url, base);
  let response: Response;
  try {
    response = await fetchImpl(absolute.href);
  } catch (e) {
    throw new InputError(`catalog ${absolute.href}: request failed (${e instanceof Error ? e.message : String(e)})`);
  }
  if (!response.ok) throw new InputError(`catalog ${absolute.href}: HTTP ${response.status}`);
  // parseCatalogText: the size, duplicate-key and depth limits of untrusted JSON first (src/core/untrustedJson.ts).
  return { catalog: parseCatalogText(await response.text(), `catalog ${absolute.href}`), assetBase: new URL('.', absolute).href };
}
