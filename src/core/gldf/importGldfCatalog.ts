/**
 * `luxbox catalog import`'s core: GLDF products into a copy of a base catalog (the rail,
 * connectors, drivers and presets stay the base's), all or nothing. Every file is read,
 * checked and converted before anything is returned; any refused file refuses the import
 * (one line naming the file and entry), and the result is validated like any catalog
 * (parseCatalog), so nothing partial or invalid comes out.
 */
import { parseCatalog, type Catalog } from '../model/catalogSchema/catalogSchema';
import { type ModuleTypeSpec } from '../model/catalogSchema/moduleTypeSchema';
import { GldfError } from './GldfError';
import type { GldfImportReport, ProductReport } from './gldfImportReport';
import type { GldfMapping } from './gldfMapping';
import { gldfToModuleType } from './gldfToModuleType';
import { readGldfProduct } from './readGldfProduct';

export interface GldfInput {
  /** File name, for messages and the report. */
  name: string;
  bytes: Uint8Array;
}

export interface GldfImportResult {
  catalog: Catalog;
  /** Photometry and pictures to write beside catalog.json, paths relative to the catalog folder. */
  files: { path: string; bytes: Uint8Array }[];
  report: GldfImportReport;
}

export function importGldfCatalog(base: Catalog, inputs: readonly GldfInput[], mapping: GldfMapping | null, baseSource = 'catalog'): GldfImportResult {
  if (inputs.length === 0) throw new GldfError('no GLDF file to import');
  const products: ProductReport[] = [];
  const types: ModuleTypeSpec[] = [];
  const files: GldfImportResult['files'] = [];
  const seenProducts = new Map<string, string>();
  for (const input of inputs) {
    const { product, zip } = readGldfProduct(input.bytes, input.name);
    const earlier = seenProducts.get(product.uniqueProductId);
    if (earlier) throw new GldfError(`${input.name}: product '${product.uniqueProductId}' was already imported from ${earlier}`);
    seenProducts.set(product.uniqueProductId, input.name);
    const converted = gldfToModuleType(product, zip, { mapping: mapping?.products?.[product.uniqueProductId], mountings: mapping?.mountings, currency: base.currency });
    products.push(converted.report);
    if (!converted.type) continue;
    const clash = types.find((t) => t.id === converted.type?.id);
    if (clash) throw new GldfError(`${input.name}: its module type id '${clash.id}' is another product's too; give one an id in the mapping file`);
    types.push(converted.type);
    files.push(...converted.files);
  }
  if (types.length === 0) throw new GldfError(`nothing to import: no variant of ${inputs.map((i) => i.name).join(', ')} fits the rail catalog`);
  const moduleTypes = base.moduleTypes.map((t) => types.find((n) => n.id === t.id) ?? t);
  for (const t of types) {
    const report = products.find((p) => p.typeId === t.id);
    if (base.moduleTypes.some((b) => b.id === t.id)) {
      if (report) report.replaced = true;
    } else moduleTypes.push(t);
  }
  const unusedMapping = Object.keys(mapping?.products ?? {})
    .filter((id) => !seenProducts.has(id))
    .map((id) => `products.${id}: no imported file holds that product`);
  const catalog = parseCatalog({ ...base, moduleTypes }, `${baseSource} with the imported module types`);
  return { catalog, files, report: { catalog: catalog.id, products, unusedMapping } };
}
