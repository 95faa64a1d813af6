/**
 * The product catalog as data: what a manufacturer replaces to put its own
 * rail system into the configurator (docs/catalog-format.md). Validated with
 * zod so a broken catalog fails loudly at load time, naming the field.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import { colourFilter } from '../../colour/colourFilterLibrary';
import { formatPath as formatFieldPath, jsonShapeProblem, oneLine, parseUntrustedJson } from '../../untrustedJson';
import { describeIssues, schemaFieldNames } from '../../zodIssues';
import { nonEmpty, price } from './catalogFields';
import { moduleTypeSchema, type BeamSpec, type ModuleTypeSpec } from './moduleTypeSchema';
import { driverSchema, feedSchema, powerIssues, type DriverSpec } from './powerSchema';
import { presetIssues, presetSchema } from './presetSchema';
import { connectorIssues, connectorSchema, overhangIssues, railIssues, railSchema, surfaceMountSchema, suspensionRangeIssues, suspensionSchema, type ConnectorSpec } from './railSystemSchema';

export const catalogSchema = z
  .strictObject({
    formatVersion: z.literal(1),
    id: nonEmpty,
    name: nonEmpty,
    /** ISO 4217 code; every price in the catalog is in this currency. */
    currency: z.string().regex(/^[A-Z]{3}$/, 'must be an ISO 4217 code such as EUR'),
    rail: railSchema,
    connectors: z.array(connectorSchema).min(1),
    suspension: suspensionSchema,
    /** Mounting the rail directly on the ceiling (setMounting 'surface'): clips instead of suspensions. */
    surfaceMount: surfaceMountSchema,
    /** Where power feeds may sit and the feed kit each one needs (docs/model.md, "Power feeds"). */
    feed: feedSchema,
    drivers: z.array(driverSchema).min(1),
    moduleTypes: z.array(moduleTypeSchema).min(1),
    presets: z.array(presetSchema),
    /**
     * Colour filters sold as accessories (docs/colour-filters.md): `id` names a filter of the library
     * (src/core/colour/colour-filters.json); modules of a type with `filterHolder` take one.
     */
    filters: z.array(z.strictObject({ id: nonEmpty, article: nonEmpty, price, source: z.string().optional() })).optional(),
  })
  .superRefine((c, ctx) => {
    // In this order (a reader sees the first issue): rail, suspension, power, overhangs, connectors, ids, filters, presets.
    railIssues(c.rail, ctx);
    suspensionRangeIssues(c.suspension, ctx);
    powerIssues(c, ctx);
    overhangIssues(c.suspension, c.surfaceMount, ctx);
    connectorIssues(c.connectors, ctx);
    uniqueIds(c.drivers, ['drivers'], ctx);
    uniqueIds(c.connectors, ['connectors'], ctx);
    uniqueIds(c.moduleTypes, ['moduleTypes'], ctx);
    uniqueIds(c.filters ?? [], ['filters'], ctx);
    c.filters?.forEach((f, i) => {
      if (!colourFilter(f.id)) ctx.addIssue({ code: 'custom', path: ['filters', i, 'id'], message: `'${f.id}' is not a filter of the colour-filter library` });
    });
    uniqueIds(c.presets, ['presets'], ctx);
    presetIssues(c, ctx);
  });

export type Catalog = z.infer<typeof catalogSchema>;

/** A catalog that does not match the format: the message names the field. */
export class CatalogError extends InputError {
  override name = 'CatalogError';
  constructor(message: string) {
    super(oneLine(message));
  }
}

/** Newest catalog format this program reads. */
export const CATALOG_FORMAT_VERSION = 1;
const CATALOG_FIELDS = schemaFieldNames(catalogSchema);

/**
 * The checks every versioned data file gets before its schema: depth and array
 * length (nothing may recurse into a hostile value), then the format version,
 * so a newer file is told apart from a broken one. Returns `path: problem` or null.
 */
export function versionedDataProblem(data: unknown, field: string, newest: number): string | null {
  const shape = jsonShapeProblem(data);
  if (shape) return shape;
  const v = typeof data === 'object' && data !== null ? (data as Record<string, unknown>)[field] : undefined;
  if (typeof v === 'number' && Number.isInteger(v) && v > newest) return `${field}: made by a newer luxbox (version ${v}; this one reads up to ${newest})`;
  return null;
}

/** Validates unknown data (parsed JSON) as a catalog; throws CatalogError naming the first bad field (unknown fields included). */
export function parseCatalog(data: unknown, source = 'catalog'): Catalog {
  const problem = versionedDataProblem(data, 'formatVersion', CATALOG_FORMAT_VERSION);
  if (problem) throw new CatalogError(`${source}: ${problem}`);
  const r = catalogSchema.safeParse(data);
  if (!r.success) throw new CatalogError(`${source}: ${describeIssues(r.error.issues, CATALOG_FIELDS)}`);
  return r.data;
}

/** Reads a catalog file's text (size, syntax, duplicate keys, depth limits first); throws CatalogError, one line. */
export function parseCatalogText(text: string, source = 'catalog'): Catalog {
  return parseCatalog(parseUntrustedJson(text, source, (m) => new CatalogError(m)), source);
}

/** 'presets[2].rails[0].length' style path for messages; '(root)' for the root. */
export function formatPath(path: readonly PropertyKey[]): string {
  return formatFieldPath(path) || '(root)';
}

function uniqueIds(items: readonly { id: string }[], path: PropertyKey[], ctx: z.RefinementCtx): void {
  const seen = new Set<string>();
  items.forEach((it, i) => {
    if (seen.has(it.id)) ctx.addIssue({ code: 'custom', path: [...path, i, 'id'], message: `duplicate id '${it.id}'` });
    seen.add(it.id);
  });
}

/** Lookups that throw InputError with a clear message instead of returning undefined. */
export function findModuleType(catalog: Catalog, id: string): ModuleTypeSpec {
  const t = catalog.moduleTypes.find((x) => x.id === id);
  if (!t) throw new InputError(`unknown module type '${id}' (catalog ${catalog.id})`);
  return t;
}

export function findBeam(type: ModuleTypeSpec, id: string): BeamSpec {
  const b = type.beams.find((x) => x.id === id);
  if (!b) throw new InputError(`module type '${type.id}' has no beam '${id}'`);
  return b;
}

export function findConnector(catalog: Catalog, id: string): ConnectorSpec {
  const c = catalog.connectors.find((x) => x.id === id);
  if (!c) throw new InputError(`unknown connector '${id}' (catalog ${catalog.id})`);
  return c;
}

export function findDriver(catalog: Catalog, id: string): DriverSpec {
  const d = catalog.drivers.find((x) => x.id === id);
  if (!d) throw new InputError(`unknown driver '${id}' (catalog ${catalog.id})`);
  return d;
}
