/**
 * The product catalog as data: what a manufacturer replaces to put its own
 * rail system into the configurator (docs/catalog-format.md). Validated with
 * zod so a broken catalog fails loudly at load time, naming the field.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import { colourFilter } from '../../colour/colourFilterLibrary';
import { formatPath as formatFieldPath, jsonShapeProblem, oneLine, parseUntrustedJson } from '../../untrustedJson';
import { describeIssues, schemaFieldNames } from '../../zodIssues';
import { nonEmpty, onGrid, price } from './catalogFields';
import { allowedTurn, connectorPorts, turnRange } from './connectorTurns';
import { moduleTypeSchema, type BeamSpec, type ModuleTypeSpec } from './moduleTypeSchema';
import { driverSchema, feedSchema, type DriverSpec } from './powerSchema';
import { presetSchema } from './presetSchema';
import { connectorSchema, railSchema, surfaceMountSchema, suspensionSchema, type ConnectorSpec } from './railSystemSchema';
import { safeParseInEnglish } from '../../zodEnglish';

export const catalogSchema = z
  .strictObject({
    formatVersion: z.literal(1),
    id: nonEmpty,
    name: nonEmpty,
    /** ISO 4217 code; every price in the catalog is in this currency. */
    currency: z.string().check(z.regex(/^[A-Z]{3}$/, 'must be an ISO 4217 code such as EUR')),
    rail: railSchema,
    connectors: z.array(connectorSchema).check(z.minLength(1)),
    suspension: suspensionSchema,
    /** Mounting the rail directly on the ceiling (setMounting 'surface'): clips instead of suspensions. */
    surfaceMount: surfaceMountSchema,
    /** Where power feeds may sit and the feed kit each one needs (docs/model.md, "Power feeds"). */
    feed: feedSchema,
    drivers: z.array(driverSchema).check(z.minLength(1)),
    moduleTypes: z.array(moduleTypeSchema).check(z.minLength(1)),
    presets: z.array(presetSchema),
    /**
     * Colour filters sold as accessories (docs/colour-filters.md): `id` names a filter of the library
     * (src/core/colour/colour-filters.json); modules of a type with `filterHolder` take one.
     */
    filters: z.optional(z.array(z.strictObject({ id: nonEmpty, article: nonEmpty, price, source: z.optional(z.string()) }))),
  })
  .check(
    z.superRefine((c, ctx) => {
      const r = c.rail;
      if (r.minLength > r.maxLength) ctx.addIssue({ code: 'custom', path: ['rail', 'minLength'], message: 'must not exceed maxLength' });
      for (const key of ['minLength', 'maxLength', 'defaultLength'] as const) {
        if (!onGrid(r[key], r.step)) ctx.addIssue({ code: 'custom', path: ['rail', key], message: `must be a multiple of step ${r.step}` });
      }
      if (r.defaultLength < r.minLength || r.defaultLength > r.maxLength) ctx.addIssue({ code: 'custom', path: ['rail', 'defaultLength'], message: 'must lie within minLength..maxLength' });
      const s = c.suspension;
      if (s.min > s.max) ctx.addIssue({ code: 'custom', path: ['suspension', 'min'], message: 'must not exceed max' });
      if (s.default < s.min || s.default > s.max) ctx.addIssue({ code: 'custom', path: ['suspension', 'default'], message: 'must lie within min..max' });
      if (!c.feed.positions.includes('ends')) ctx.addIssue({ code: 'custom', path: ['feed', 'positions'], message: "must include 'ends' (a one-rail system has no joints)" });
      if (new Set(c.feed.positions).size !== c.feed.positions.length) ctx.addIssue({ code: 'custom', path: ['feed', 'positions'], message: 'must not repeat a position' });
      if (!c.drivers.some((d) => d.id === c.feed.defaultDriver)) ctx.addIssue({ code: 'custom', path: ['feed', 'defaultDriver'], message: `'${c.feed.defaultDriver}' is not a driver id` });
      c.drivers.forEach((d, i) => {
        if (d.output !== c.feed.output) ctx.addIssue({ code: 'custom', path: ['drivers', i, 'output'], message: `'${d.output}' does not match feed.output '${c.feed.output}'` });
      });
      if (s.maxOverhang > s.maxSpacing) ctx.addIssue({ code: 'custom', path: ['suspension', 'maxOverhang'], message: 'must not exceed maxSpacing' });
      if (c.surfaceMount.maxOverhang > c.surfaceMount.spacing) ctx.addIssue({ code: 'custom', path: ['surfaceMount', 'maxOverhang'], message: 'must not exceed spacing' });
      c.connectors.forEach((con, i) => {
        if (connectorPorts(con) > 2 && (con.flex || con.angle === 0)) ctx.addIssue({ code: 'custom', path: ['connectors', i, 'ports'], message: 'a T or X connector has a fixed branch angle (angle > 0, no flex)' });
        if (!con.flex) return;
        if (!onGrid(con.flex.maxAngle, con.flex.step)) ctx.addIssue({ code: 'custom', path: ['connectors', i, 'flex', 'maxAngle'], message: `must be a multiple of step ${con.flex.step}` });
        if (!allowedTurn(con, con.angle)) ctx.addIssue({ code: 'custom', path: ['connectors', i, 'angle'], message: `a flexible connector's angle (its default turn) must be a multiple of ${con.flex.step} up to ${con.flex.maxAngle}` });
      });
      uniqueIds(c.drivers, ['drivers'], ctx);
      uniqueIds(c.connectors, ['connectors'], ctx);
      uniqueIds(c.moduleTypes, ['moduleTypes'], ctx);
      uniqueIds(c.filters ?? [], ['filters'], ctx);
      c.filters?.forEach((f, i) => {
        if (!colourFilter(f.id)) ctx.addIssue({ code: 'custom', path: ['filters', i, 'id'], message: `'${f.id}' is not a filter of the colour-filter library` });
      });
      uniqueIds(c.presets, ['presets'], ctx);
      c.presets.forEach((p, i) => {
        if (p.joints.length !== p.rails.length - 1) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints'], message: `needs ${p.rails.length - 1} joints for ${p.rails.length} rails` });
        p.joints.forEach((j, k) => {
          const con = c.connectors.find((x) => x.id === j.connector);
          if (!con) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints', k, 'connector'], message: `unknown connector '${j.connector}'` });
          else if (!allowedTurn(con, j.turn)) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints', k, 'turn'], message: `${turnRange(con)} for connector '${con.id}'` });
          if (j.parent !== undefined && j.parent > k) ctx.addIssue({ code: 'custom', path: ['presets', i, 'joints', k, 'parent'], message: `must be a rail before rail ${k + 2} (at most ${k})` });
        });
        if (p.driver !== undefined) {
          const d = c.drivers.find((x) => x.id === p.driver);
          // The preset's load: its modules' beams (the type's default beam where none is named), as the feeds count it.
          let load = 0;
          for (const m of p.rails.flatMap((r) => r.modules)) {
            const t = c.moduleTypes.find((x) => x.id === m.type);
            load += t?.beams.find((b) => b.id === (m.beam ?? t.defaultBeam))?.watts ?? 0;
          }
          if (!d) ctx.addIssue({ code: 'custom', path: ['presets', i, 'driver'], message: `'${p.driver}' is not a driver id` });
          else if (load > d.capacity + 1e-6) ctx.addIssue({ code: 'custom', path: ['presets', i, 'driver'], message: `the ${d.capacity} W '${d.id}' cannot carry the preset's ${Math.round(load * 100) / 100} W` });
        }
        p.rails.forEach((rail, k) =>
          rail.modules.forEach((m, n) => {
            const t = c.moduleTypes.find((x) => x.id === m.type);
            const at = ['presets', i, 'rails', k, 'modules', n];
            if (!t) ctx.addIssue({ code: 'custom', path: [...at, 'type'], message: `unknown module type '${m.type}'` });
            else {
              if (m.beam !== undefined && !t.beams.some((b) => b.id === m.beam)) ctx.addIssue({ code: 'custom', path: [...at, 'beam'], message: `unknown beam '${m.beam}'` });
              if (m.cct !== undefined && !t.ccts.includes(m.cct)) ctx.addIssue({ code: 'custom', path: [...at, 'cct'], message: `${m.cct} K not offered` });
            }
          }),
        );
      });
    }),
  );

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
  const r = safeParseInEnglish(catalogSchema, data);
  if (!r.success) throw new CatalogError(`${source}: ${describeIssues(r.error.issues, CATALOG_FIELDS)}`);
  return r.data;
}

/** Reads a catalog file's text (size, syntax, duplicate keys, depth limits first); throws CatalogError, one line. */
export function parseCatalogText(text: string, source = 'catalog'): Catalog {
  return parseCatalog(
    parseUntrustedJson(text, source, (m) => new CatalogError(m)),
    source,
  );
}

/** 'presets[2].rails[0].length' style path for messages; '(root)' for the root. */
export function formatPath(path: readonly PropertyKey[]): string {
  return formatFieldPath(path) || '(root)';
}

function uniqueIds(items: readonly { id: string }[], path: PropertyKey[], ctx: z.core.$RefinementCtx): void {
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
