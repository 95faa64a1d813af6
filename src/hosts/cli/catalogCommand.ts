import { existsSync, mkdirSync, writeFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { InputError } from '../../core/inputError';
import { formatImportReport } from '../../core/gldf/gldfImportReport';
import { parseGldfMapping, type GldfMapping } from '../../core/gldf/gldfMapping';
import { importGldfCatalog, type GldfInput } from '../../core/gldf/importGldfCatalog';
import { UPLOAD_LIMITS } from '../../core/gldf/uploadLimits';
import { parseCatalogText } from '../../core/model/catalogSchema/catalogSchema';
import { INPUT_LIMITS } from '../../core/untrustedJson';
import { MAX_PHOTOMETRY_BYTES } from '../../core/photometry';
import { readRegularFile } from '../node/readRegularFile';

export const catalogUsage = 'catalog import <product.gldf> [more.gldf …] --into <catalog.json> --out <dir> [--mapping <mapping.json>] [--assets <dir>]';

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
