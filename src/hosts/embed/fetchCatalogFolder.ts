/**
 * A catalog folder as `luxbox catalog import` writes it (docs/gldf.md), named by the URL of its
 * catalog.json: the JSON for the embedding API's `catalog`, the folder's path for its
 * `assetBase` (the photometry and the L3D bodies lie beside it). The standalone app's and the
 * demo shop's `?catalog=` both open one this way. Throws "HTTP <status>" when it cannot be fetched.
 */
export async function fetchCatalogFolder(catalogUrl: string, base: string): Promise<{ catalog: unknown; assetBase: string }> {
  const url = new URL(catalogUrl, base);
  const response = await fetch(url);
  if (!response.ok) throw new Error(`HTTP ${response.status} ${response.statusText}`.trim());
  return { catalog: await response.json(), assetBase: new URL('.', url).pathname };
}
