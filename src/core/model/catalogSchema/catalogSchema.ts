/**
 * The product catalog as data: what a manufacturer replaces to put its own
 * rail system into the configurator (docs/catalog-format.md). Validated with
 * zod so a broken catalog fails loudly at load time, naming the field.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import { colourFilter } from '../../colour/colourFilterLibrary';
import { dimmingCurveSchema } from './dimmingCurve';
import { describeIssues, formatPath as formatFieldPath, jsonShapeProblem, oneLine, parseUntrustedJson, schemaFieldNames } from '../../untrustedJson';

/** Module distributions along a rail; defined precisely in docs/model.md and src/core/model/distribution.ts. */
export const DISTRIBUTIONS = ['start', 'end', 'inside-centred', 'outside-centred'] as const;
export type Distribution = (typeof DISTRIBUTIONS)[number];

/** Where the catalog lets power feeds sit: the chain's two ends, its connectors. */
export const FEED_POSITION_KINDS = ['ends', 'joints'] as const;

const positive = z.number().finite().positive();
const price = z.number().finite().nonnegative();
const nonEmpty = z.string().min(1);
/**
 * A catalog text in the UI's other languages (docs/catalog-format.md, "Translations"): the entry's
 * own `name`/`label`/`description` is the fallback for a language not given.
 */
const translations = z.strictObject({ en: nonEmpty.optional(), de: nonEmpty.optional(), fr: nonEmpty.optional(), it: nonEmpty.optional() }).optional();

const beamSchema = z.strictObject({
  id: nonEmpty,
  label: nonEmpty,
  labels: translations,
  /** Full beam angle (degrees) where the optic has one; omitted for diffusers and washers. */
  beamAngle: positive.optional(),
  article: nonEmpty,
  /** Photometric file, relative to the web root (public/), e.g. 'ies/bega_84693_narrow_spot.ies'. */
  photometry: z.string().regex(/^[\w./-]+\.(ies|IES|ldt|LDT)$/, 'must be a relative path to an .ies or .ldt file'),
  /** Luminaire lumens and input watts as the photometric file states them. */
  lumens: positive,
  watts: positive,
  /** Roll (degrees) that turns the file's frame so the optic sits as intended on the rail (C0 along the rail when 0). */
  roll: z.number().finite().min(-180).max(180),
  price,
  /** Where lumens and watts come from (free text). */
  source: z.string().optional(),
});

/**
 * One axis of an adjustable head: min..max degrees (0 ≤ min ≤ max < `limit`; rotation is relative to the
 * rail, tilt from straight down) and optional detents every `stops` degrees from 0, on which min and
 * max must lie (and which divide 360 for rotation, so the circle closes on a stop).
 */
function aimRangeSchema(limit: number) {
  return z
    .strictObject({ min: z.number().finite().min(0).lt(limit), max: z.number().finite().min(0).lt(limit), stops: positive.max(90).optional() })
    .superRefine((r, ctx) => {
      if (r.min > r.max) ctx.addIssue({ code: 'custom', path: ['min'], message: 'must not exceed max' });
      if (r.stops !== undefined) {
        for (const key of ['min', 'max'] as const) if (!onGrid(r[key], r.stops)) ctx.addIssue({ code: 'custom', path: [key], message: `must be a multiple of stops ${r.stops}` });
        if (limit === 360 && !onGrid(360, r.stops)) ctx.addIssue({ code: 'custom', path: ['stops'], message: 'must divide 360' });
      }
    });
}

const moduleTypeSchema = z
  .strictObject({
    id: nonEmpty,
    name: nonEmpty,
    names: translations,
    /** Length of rail the module occupies, metres. */
    length: positive,
    ccts: z.array(z.number().int().min(1000).max(20000)).min(1),
    defaultCct: z.number().int(),
    beams: z.array(beamSchema).min(1),
    defaultBeam: nonEmpty,
    /** Takes a colour filter (gel) from the catalog's `filters` (docs/colour-filters.md); absent: no holder. */
    filterHolder: z.boolean().optional(),
    /** An adjustable head (docs/aiming.md): how far it turns and tilts, degrees; absent: fixed, straight down. */
    adjustable: z.strictObject({ tilt: aimRangeSchema(180), rotation: aimRangeSchema(360) }).optional(),
    /** How the CCT follows the level (dimmingCurve.ts, docs/catalog-format.md "Dimming curve"); omitted: constant-cct. */
    dimming: dimmingCurveSchema.optional(),
  })
  .superRefine((t, ctx) => {
    if (t.dimming?.curve === 'dim-to-warm') {
      const d = t.dimming;
      if (d.cctMin >= d.cctFull) ctx.addIssue({ code: 'custom', path: ['dimming', 'cctMin'], message: `${d.cctMin} K must be below cctFull (${d.cctFull} K)` });
      if (t.ccts.length !== 1 || t.ccts[0] !== d.cctFull) ctx.addIssue({ code: 'custom', path: ['ccts'], message: `a dim-to-warm type offers exactly its cctFull (${d.cctFull} K)` });
    }
    if (!t.ccts.includes(t.defaultCct)) ctx.addIssue({ code: 'custom', path: ['defaultCct'], message: `${t.defaultCct} K is not one of ccts` });
    if (!t.beams.some((b) => b.id === t.defaultBeam)) ctx.addIssue({ code: 'custom', path: ['defaultBeam'], message: `'${t.defaultBeam}' is not a beam id` });
    if (new Set(t.beams.map((b) => b.id)).size !== t.beams.length) ctx.addIssue({ code: 'custom', path: ['beams'], message: 'beam ids must be unique' });
  });

const presetModuleSchema = z.strictObject({ type: nonEmpty, beam: nonEmpty.optional(), cct: z.number().int().optional() });
const presetSchema = z.strictObject({
  id: nonEmpty,
  name: nonEmpty,
  names: translations,
  description: z.string(),
  descriptions: translations,
  rails: z
    .array(z.strictObject({ length: positive, distribution: z.enum(DISTRIBUTIONS), modules: z.array(presetModuleSchema) }))
    .min(1),
  joints: z.array(z.strictObject({ connector: nonEmpty, turn: z.number().finite(), parent: z.number().int().nonnegative().optional() })),
  /**
   * The driver the preset ships with (a driver id): its one feed at the chain start gets it instead
   * of the smallest driver that carries the load, so the shopper can add modules before the driver
   * is full (docs/catalog-format.md, "A preset's own driver"). Must carry the preset's own load.
   */
  driver: nonEmpty.optional(),
});

export const catalogSchema = z
  .strictObject({
    formatVersion: z.literal(1),
    id: nonEmpty,
    name: nonEmpty,
    /** ISO 4217 code; every price in the catalog is in this currency. */
    currency: z.string().regex(/^[A-Z]{3}$/, 'must be an ISO 4217 code such as EUR'),
    rail: z.strictObject({
      article: nonEmpty,
      name: nonEmpty,
      names: translations,
      minLength: positive,
      maxLength: positive,
      step: positive,
      defaultLength: positive,
      /** Profile width in plan, metres (for footprints and clash tests). */
      width: positive,
      /** Grid a freely placed module's start snaps to, metres from the rail start (docs/model.md, "Free positions"); default: step. */
      placementStep: positive.optional(),
      /** Unit price of a rail of length L: base + perMetre·L, rounded to cents. */
      price: z.strictObject({ base: price, perMetre: price }),
    }),
    connectors: z
      .array(
        z.strictObject({
          id: nonEmpty,
          article: nonEmpty,
          name: nonEmpty,
          names: translations,
          /** 0 for a straight connector, otherwise the corner angle in degrees (used turning left or right); a flexible connector: the turn a new joint gets. */
          angle: z.number().finite().min(0).lt(180),
          /** Straight: gap between the joined rail ends. Corner or flexible: distance from each rail end to the hinge (corner) point. Metres. */
          arm: z.number().finite().nonnegative(),
          price,
          /**
           * A flexible-angle (hinge) connector (docs/catalog-format.md): it turns by any multiple of
           * `step` degrees from −maxAngle to +maxAngle, 0 included; setJointTurn adjusts a joint's turn.
           */
          flex: z.strictObject({ maxAngle: z.number().finite().positive().lt(180), step: z.number().finite().positive() }).optional(),
          /**
           * Rail ends it joins (docs/catalog-format.md, "Connectors"): 2 (default) for straight, corner and
           * flexible; 3 for a T, 4 for an X. A node of more than two ports takes branches at −angle, 0 and +angle.
           */
          ports: z.number().int().min(2).max(4).optional(),
          source: z.string().optional(),
        }),
      )
      .min(1),
    suspension: z.strictObject({
      article: nonEmpty,
      name: nonEmpty,
      names: translations,
      /** Ceiling to photometric centre, metres. */
      min: positive,
      max: positive,
      default: positive,
      /** The photometric centre must stay at least this high above the floor (head room), metres. */
      minHeightAboveFloor: positive,
      price,
      /** Largest distance between two suspension points along the chain, metres (docs/model.md, "Suspension points"). */
      maxSpacing: positive,
      /** Largest overhang of a free chain end past its last suspension point, metres. */
      maxOverhang: positive,
      /** Where the mounting rules come from (free text). */
      source: z.string().optional(),
    }),
    /** Mounting the rail directly on the ceiling (setMounting 'surface'): clips instead of suspensions. */
    surfaceMount: z.strictObject({
      article: nonEmpty,
      name: nonEmpty,
      names: translations,
      price,
      /** Largest distance between two clips along the chain, metres. */
      spacing: positive,
      /** Largest overhang of a free chain end past its last clip, metres. */
      maxOverhang: positive,
      /** Ceiling to photometric centre of a surface-mounted system, metres. */
      drop: positive,
      source: z.string().optional(),
    }),
    /** Where power feeds may sit and the feed kit each one needs (docs/model.md, "Power feeds"). */
    feed: z.strictObject({
      article: nonEmpty,
      name: nonEmpty,
      names: translations,
      price,
      /** 'ends': the chain's start and end; 'joints': any connector. A one-rail system has no joints, so 'ends' is required. */
      positions: z.array(z.enum(FEED_POSITION_KINDS)).min(1),
      /** What the rail takes, e.g. '48 V DC'; every driver must supply it. */
      output: nonEmpty,
      /** Driver id a new system's feed gets. */
      defaultDriver: nonEmpty,
    }),
    drivers: z
      .array(
        z.strictObject({
          id: nonEmpty,
          name: nonEmpty,
          article: nonEmpty,
          /** Rated output power, watts: the most module input power one feed may carry. */
          capacity: positive,
          /** Output, e.g. '48 V DC'; must equal feed.output. */
          output: nonEmpty,
          price,
          source: z.string().optional(),
        }),
      )
      .min(1),
    moduleTypes: z.array(moduleTypeSchema).min(1),
    presets: z.array(presetSchema),
    /**
     * Colour filters sold as accessories (docs/colour-filters.md): `id` names a filter of the library
     * (src/core/colour/colour-filters.json); modules of a type with `filterHolder` take one.
     */
    filters: z.array(z.strictObject({ id: nonEmpty, article: nonEmpty, price, source: z.string().optional() })).optional(),
  })
  .superRefine((c, ctx) => {
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
  });

export type Catalog = z.infer<typeof catalogSchema>;
export type RailSpec = Catalog['rail'];
export type ConnectorSpec = Catalog['connectors'][number];
export type ModuleTypeSpec = Catalog['moduleTypes'][number];
export type BeamSpec = ModuleTypeSpec['beams'][number];
export type PresetSpec = Catalog['presets'][number];
export type DriverSpec = Catalog['drivers'][number];

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

/** True when x is an integer multiple of step, to within float noise (1e-6 of a step). */
export function onGrid(x: number, step: number): boolean {
  const k = x / step;
  return Math.abs(k - Math.round(k)) < 1e-6;
}

function uniqueIds(items: readonly { id: string }[], path: PropertyKey[], ctx: z.RefinementCtx): void {
  const seen = new Set<string>();
  items.forEach((it, i) => {
    if (seen.has(it.id)) ctx.addIssue({ code: 'custom', path: [...path, i, 'id'], message: `duplicate id '${it.id}'` });
    seen.add(it.id);
  });
}

/**
 * Whether a connector may turn by `turn` degrees: a fixed one by exactly ±angle (0 for straight),
 * a flexible one by a multiple of its step within ±maxAngle.
 */
export function allowedTurn(con: Pick<ConnectorSpec, 'angle' | 'flex' | 'ports'>, turn: number): boolean {
  if (!Number.isFinite(turn)) return false;
  if (connectorPorts(con) > 2) return turn === 0 || Math.abs(turn) === con.angle;
  if (!con.flex) return Math.abs(turn) === con.angle;
  return Math.abs(turn) <= con.flex.maxAngle + 1e-9 && onGrid(turn, con.flex.step);
}

/** Rail ends a connector joins: 2 unless the catalog says 3 (T) or 4 (X); a node takes ports − 1 branches. */
export function connectorPorts(con: Pick<ConnectorSpec, 'ports'>): number {
  return con.ports ?? 2;
}

/** The turns a connector allows, in words ('must be ±90', 'must be a multiple of 5 within ±90'). */
export function turnRange(con: Pick<ConnectorSpec, 'angle' | 'flex' | 'ports'>): string {
  if (connectorPorts(con) > 2) return `must be 0 or ±${con.angle}`;
  return con.flex ? `must be a multiple of ${con.flex.step}° within ±${con.flex.maxAngle}°` : `must be ±${con.angle}`;
}

/**
 * True when a connector bridges its rails with two arms through a hinge (corner) point: a corner
 * or a flexible connector, whatever its turn (a flexible one at 0° is still two arms long).
 */
export function twoArmed(con: Pick<ConnectorSpec, 'angle' | 'flex'>): boolean {
  return con.angle !== 0 || con.flex !== undefined;
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
