import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { InputError } from '../../core/inputError';
import { formatImportReport } from '../../core/gldf/gldfImportReport';
import { parseGldfMapping, type GldfMapping } from '../../core/gldf/gldfMapping';
import { exportGldfProduct, type GldfExport } from '../../core/gldf/exportGldfProduct';
import { catalogSlug } from '../../core/gldf/gldfDefaults';
import { importGldfCatalog, type GldfInput } from '../../core/gldf/importGldfCatalog';
import { UPLOAD_LIMITS } from '../../core/gldf/uploadLimits';
import { parseCatalogText } from '../../core/model/catalogSchema/catalogSchema';
import { INPUT_LIMITS } from '../../core/untrustedJson';
import { MAX_PHOTOMETRY_BYTES } from '../../core/photometry';
import { readRegularFile } from '../node/readRegularFile';

export const catalogUsage = 'catalog import <product.gldf> [more.gldf …] --into <catalog.json> --out <dir> [--mapping <mapping.json>] [--assets <dir>] | catalog export <catalog.json> --out <dir> [--type <id> …] [--assets <dir>]';

const decoder = new TextDecoder('utf-8');

interface ImportArgs {
  files: string[];
  into: string;
  out: string;
  mapping?: string;
  assets?: string;
}

function parseArgs(args: string[]): ImportArgs {
  const files: string[] = [];
  const options: Record<string, string> = {};
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    if (a === '--into' || a === '--out' || a === '--mapping' || a === '--assets') {
      const v = args[++i];
      if (v === undefined || v.startsWith('--')) throw new InputError(`import: ${a} needs a path (usage: luxbox ${catalogUsage})`);
      options[a] = v;
    } else if (a.startsWith('--')) throw new InputError(`import: unknown argument ${a} (usage: luxbox ${catalogUsage})`);
    else files.push(a);
  }
  if (files.length === 0) throw new InputError(`import: no GLDF file given (usage: luxbox ${catalogUsage})`);
  if (!options['--into']) throw new InputError(`import: --into <catalog.json> is required: the catalog whose rail the modules join (usage: luxbox ${catalogUsage})`);
  if (!options['--out']) throw new InputError(`import: --out <dir> is required (usage: luxbox ${catalogUsage})`);
  return { files, into: options['--into'], out: options['--out'], mapping: options['--mapping'], assets: options['--assets'] };
}

/**
 * `luxbox catalog import`: GLDF products into a catalog folder the app and the embedding API
 * load like the demo's (catalog.json, ies/…, images/…, the import report; docs/gldf.md). Every
 * file is read and checked before anything is written: a refused file writes nothing.
 */
export async function run(args: string[]): Promise<number> {
  const [sub, ...rest] = args;
  if (sub === 'export') return runExport(rest);
  if (sub !== 'import') throw new InputError(`unknown subcommand ${sub === undefined ? '(none)' : `"${sub}"`} (usage: luxbox ${catalogUsage})`);
  const a = parseArgs(rest);
  const baseText = decoder.decode(readRegularFile(a.into, { maxBytes: INPUT_LIMITS.maxTextLength }));
  const base = parseCatalogText(baseText, basename(a.into));
  let mapping: GldfMapping | null = null;
  if (a.mapping) mapping = parseGldfMapping(decoder.decode(readRegularFile(a.mapping, { maxBytes: INPUT_LIMITS.maxTextLength })), basename(a.mapping));
  const inputs: GldfInput[] = a.files.map((f) => ({ name: basename(f), bytes: readRegularFile(f, { maxBytes: UPLOAD_LIMITS.maxContainerBytes }) }));
  const result = importGldfCatalog(base, inputs, mapping, basename(a.into));

  // The base catalog's own photometry, so the folder is complete: found under --assets (default: beside --into).
  const assets = resolve(a.assets ?? dirname(a.into));
  const written = new Set(result.files.map((f) => f.path));
  const baseFiles: { path: string; bytes: Uint8Array }[] = [];
  const missing: string[] = [];
  for (const path of new Set(result.catalog.moduleTypes.flatMap((t) => t.beams.map((b) => b.photometry)))) {
    if (written.has(path)) continue;
    const from = join(assets, path);
    if (existsSync(from)) baseFiles.push({ path, bytes: readRegularFile(from, { maxBytes: MAX_PHOTOMETRY_BYTES, within: [assets] }) });
    else missing.push(path);
  }
  if (missing.length > 0) result.report.unusedMapping.push(`not copied (not under ${assets}; serve them beside the folder): ${missing.join(', ')}`);

  const reportText = formatImportReport(result.report);
  mkdirSync(a.out, { recursive: true });
  for (const f of [...result.files, ...baseFiles]) {
    const path = join(a.out, f.path);
    mkdirSync(dirname(path), { recursive: true });
    writeFileSync(path, f.bytes);
  }
  writeFileSync(join(a.out, 'catalog.json'), JSON.stringify(result.catalog, null, 2) + '\n');
  writeFileSync(join(a.out, 'import-report.json'), JSON.stringify(result.report, null, 2) + '\n');
  writeFileSync(join(a.out, 'import-report.txt'), reportText);
  for (const p of result.report.products) {
    process.stdout.write(
      `${p.source}: ${p.typeId ? `module type '${p.typeId}'${p.replaced ? ' (replaced)' : ''}` : 'nothing imported'}, ${p.imported.length} variants imported, ${p.skipped.length} skipped, ${p.assumed.length} values assumed, ${p.flux.filter((f) => f.warning).length} flux differences\n`,
    );
  }
  process.stdout.write(`${a.out}: catalog.json (${result.catalog.moduleTypes.length} module types), ${result.files.length + baseFiles.length} files, import-report.txt\n`);
  return 0;
}

interface ExportArgs {
  catalog: string;
  out: string;
  types: string[];
  assets?: string;
}

function parseExportArgs(args: string[]): ExportArgs {
  const files: string[] = [];
  const types: string[] = [];
  const options: Record<string, string> = {};
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    if (a === '--out' || a === '--assets' || a === '--type') {
      const v = args[++i];
      if (v === undefined || v.startsWith('--')) throw new InputError(`export: ${a} needs a value (usage: luxbox ${catalogUsage})`);
      if (a === '--type') types.push(v);
      else options[a] = v;
    } else if (a.startsWith('--')) throw new InputError(`export: unknown argument ${a} (usage: luxbox ${catalogUsage})`);
    else files.push(a);
  }
  if (files.length !== 1) throw new InputError(`export: give one catalog.json (usage: luxbox ${catalogUsage})`);
  if (!options['--out']) throw new InputError(`export: --out <dir> is required (usage: luxbox ${catalogUsage})`);
  return { catalog: files[0], out: options['--out'], types, assets: options['--assets'] };
}

/**
 * `luxbox catalog export`: module types back to GLDF (docs/gldf.md, "Export"): one
 * `<type id>.gldf` per type, and `mapping.json` with what GLDF cannot say, so that
 * `luxbox catalog import` of those files with that mapping gives the types back. Every type is
 * exported before anything is written.
 */
async function runExport(args: string[]): Promise<number> {
  const a = parseExportArgs(args);
  const catalog = parseCatalogText(decoder.decode(readRegularFile(a.catalog, { maxBytes: INPUT_LIMITS.maxTextLength })), basename(a.catalog));
  const assets = resolve(a.assets ?? dirname(a.catalog));
  const readFile = (path: string): Uint8Array => readRegularFile(join(assets, path), { maxBytes: Math.max(MAX_PHOTOMETRY_BYTES, UPLOAD_LIMITS.maxEntryBytes), within: [assets] });
  const ids = a.types.length > 0 ? a.types : catalog.moduleTypes.map((t) => t.id);
  const createdAt = new Date();
  const exports: { id: string; file: string; result: GldfExport }[] = [];
  for (const id of ids) {
    // The file is named by the id made safe as a file name; two ids that become one name are refused.
    const file = `${catalogSlug(id)}.gldf`;
    const twin = exports.find((e) => e.file === file);
    if (twin) throw new InputError(`export: module types '${twin.id}' and '${id}' would both be written as ${file}; export them one at a time`);
    // The picture an import wrote beside the catalog (images/<type id>.png|jpg), when there is one.
    const pictureName = ['png', 'jpg', 'jpeg'].map((ext) => `${catalogSlug(id)}.${ext}`).find((n) => existsSync(join(assets, 'images', n)));
    const picture = pictureName ? { name: pictureName, bytes: readFile(`images/${pictureName}`) } : undefined;
    exports.push({ id, file, result: exportGldfProduct(catalog, id, { createdAt, readFile, ...(picture ? { picture } : {}) }) });
  }
  mkdirSync(a.out, { recursive: true });
  for (const { file, result } of exports) {
    writeFileSync(join(a.out, file), result.bytes);
    process.stdout.write(`${file}: ${(result.productXml.match(/<Variant /g) ?? []).length} variants${result.notes.length ? `; ${result.notes.join('; ')}` : ''}\n`);
  }
  const mapping: GldfMapping = { formatVersion: 1, products: Object.fromEntries(exports.map(({ id, result }) => [id, result.mapping])) };
  writeFileSync(join(a.out, 'mapping.json'), JSON.stringify(mapping, null, 2) + '\n');
  process.stdout.write(`${a.out}: ${exports.length} GLDF files, mapping.json (import them with --mapping ${join(a.out, 'mapping.json')})\n`);
  return 0;
}
