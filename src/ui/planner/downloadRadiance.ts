import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../core/model/configuration/configuration';
import { loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import type { Photometry } from '../../core/photometry/types';
import { downloadBlob } from './downloadText';
import { sceneFileName } from './sceneFileName';

/**
 * "Download for Radiance": the configuration as a Radiance folder in a zip (docs/radiance.md),
 * built in the browser from the same photometry the plan and the 3D view load. The exporter and
 * the zip writer are a separate chunk, fetched on first use. Resolves to the file name offered.
 */
export async function downloadRadiance(config: Configuration, catalog: Catalog, loadPhotometry: (path: string) => Promise<Photometry>): Promise<string> {
  const [{ resolveBakeScene }, { exportRadiance }, { radianceZip }, { loadModelBodies }, { fixturesFromConfiguration }] = await Promise.all([
    import('../../engines/bake/resolveBakeScene'),
    import('../../engines/radiance/exportRadiance'),
    import('../../engines/radiance/radianceZip'),
    import('../shared/loadModelBodies'),
    import('../../engines/view/fixtures'),
    loadColourFilterSpectra(), // a filtered module's colour (docs/colour-filters.md, "Two files")
  ]);
  const stem = sceneFileName(config)
    .replace(/\.json$/i, '')
    .replace(/\.luxbox$/i, '');
  const scene = await resolveBakeScene(toLightingScene(config, catalog), loadPhotometry);
  const folder = `${stem}-radiance`;
  // Modules with an L3D body (catalog `model`) get it as grey polygons (bodiesRad.ts), placed and aimed as in the 3D view.
  const modules = fixturesFromConfiguration(config, catalog, new Map(), await loadModelBodies(loadPhotometry, config, catalog)).modules;
  const zip = radianceZip(exportRadiance(scene, {}, stem, modules), folder);
  const name = `${folder}.zip`;
  downloadBlob(name, new Blob([zip as BlobPart], { type: 'application/zip' }));
  return name;
}
