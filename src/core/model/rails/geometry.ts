/**
 * Plan geometry of placed systems (docs/scene-format.md "Units and frames": world y up, plan x = world x,
 * plan "down" = world z). Headings are degrees counterclockwise seen from above,
 * so a heading h points along (cos h, 0, −sin h) = Ry(h)·(+x): the same rotation
 * as the luminaire yaw, which makes C0 run along the rail.
 */
import { findConnector, findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { twoArmed } from '../catalogSchema/connectorTurns';
import type { LightSystem, Rail } from '../configuration/configuration';
import { layoutModules } from './distribution';
import { freeOffsets, isFreeRail } from './freePositions';
import { jointParent } from './railTree';
import { perCatalog } from '../catalogSchema/perCatalog';

/** A point or vector in the plan: [x, z]. */
export type PlanVec = readonly [number, number];

/** An oriented rectangle in the plan. */
export interface PlanRect {
  readonly centre: PlanVec;
  /** Unit vector along the rectangle's length. */
  readonly axis: PlanVec;
  readonly halfLength: number;
  readonly halfWidth: number;
}

export interface RailPlacement {
  readonly railId: string;
  readonly index: number;
  readonly start: PlanVec;
  readonly end: PlanVec;
  /** Degrees, normalised to [0, 360). */
  readonly heading: number;
  /** Unit direction from start to end. */
  readonly direction: PlanVec;
  readonly length: number;
}

export interface ModulePlacement {
  readonly moduleId: string;
  readonly railId: string;
  readonly systemId: string;
  /** Distance from the rail start to the module start, metres. */
  readonly offset: number;
  readonly length: number;
  /** Plan position of the module centre (its photometric centre in plan). */
  readonly centre: PlanVec;
  /** Rail heading, degrees in [0, 360). */
  readonly heading: number;
  readonly footprint: PlanRect;
}

export function normaliseDegrees(deg: number): number {
  const r = deg % 360;
  const n = r < 0 ? r + 360 : r;
  // −0 and float residue like 359.9999999999 near a full turn both read as 0.
  return n === 0 || 360 - n < 1e-9 ? 0 : n;
}

/** Ry(h)·(+x) in plan coordinates. */
export function headingVector(deg: number): PlanVec {
  const t = (deg * Math.PI) / 180;
  return [Math.cos(t), -Math.sin(t)];
}

/** Rotates a plan vector like Ry(deg) rotates (x, 0, z): counterclockwise seen from above. */
export function rotatePlan(v: PlanVec, deg: number): PlanVec {
  const t = (deg * Math.PI) / 180;
  const c = Math.cos(t);
  const s = Math.sin(t);
  return [v[0] * c + v[1] * s, -v[0] * s + v[1] * c];
}

const add = (a: PlanVec, b: PlanVec, k = 1): PlanVec => [a[0] + k * b[0], a[1] + k * b[1]];

/**
 * Start, end and heading of every rail of a system, following the tree of joints (docs/model.md,
 * "Trees of rails"): rail i+1 starts where its connector puts it past the end of its parent rail.
 */
export function railPlacements(system: LightSystem, catalog: Catalog): RailPlacement[] {
  const out: RailPlacement[] = [];
  const headings: number[] = [];
  system.rails.forEach((rail, i) => {
    let start: PlanVec = [system.x, system.z];
    let heading = system.rotation;
    const joint = i > 0 ? system.joints[i - 1] : undefined;
    const parent = joint ? out[jointParent(joint, i - 1)] : undefined;
    if (joint && parent) {
      const con = findConnector(catalog, joint.connector);
      const pivot = add(parent.end, parent.direction, con.arm);
      heading = headings[jointParent(joint, i - 1)] + joint.turn;
      // A corner, flexible, T or X connector: the rail starts one arm past the hinge, along its own heading.
      start = twoArmed(con) ? add(pivot, headingVector(heading), con.arm) : pivot;
    }
    headings.push(heading);
    const direction = headingVector(heading);
    const end = add(start, direction, rail.length);
    out.push({ railId: rail.id, index: i, start, end, heading: normaliseDegrees(heading), direction, length: rail.length });
  });
  return out;
}

function segmentRect(from: PlanVec, to: PlanVec, width: number): PlanRect {
  const dx = to[0] - from[0];
  const dz = to[1] - from[1];
  const len = Math.hypot(dx, dz);
  const axis: PlanVec = len > 0 ? [dx / len, dz / len] : [1, 0];
  return { centre: [(from[0] + to[0]) / 2, (from[1] + to[1]) / 2], axis, halfLength: len / 2, halfWidth: width / 2 };
}

/**
 * The plan footprint of a system as elements in list order: rail 0, the connector node at its
 * end (if any), rail 1, its node, … (a snake: rail 0, connector 0, rail 1, …). Each element is
 * one or more rectangles: a rail; a straight connector's gap; a two-armed node (corner, flexible,
 * T, X) its incoming arm and one arm per branch, each reaching half a profile width past the
 * hinge point so the corner is covered.
 */
export function systemElements(system: LightSystem, catalog: Catalog): PlanRect[][] {
  return systemElementTree(system, catalog).elements;
}

/** What an element is: rail i, or the connector node at the end of rail i. */
export type ElementKind = { readonly kind: 'rail' | 'node'; readonly rail: number };

export interface SystemElementTree {
  readonly elements: PlanRect[][];
  /** For each element, the elements it may touch (itself included). */
  readonly near: Set<number>[];
  readonly kinds: ElementKind[];
}

/**
 * The elements (systemElements) and, for each, the elements that touch it by design: a rail and
 * the nodes at its two ends, and everything within two such steps (a rail and the next rail
 * through their connector, two branches of one node, two nodes at a short rail's ends). The
 * self-overlap rule skips exactly these pairs; on a snake they are the elements less than three
 * apart in chain order.
 */
export function systemElementTree(system: LightSystem, catalog: Catalog): SystemElementTree {
  return elementTrees(system, catalog);
}

/**
 * Once per system object and catalog (perCatalog.ts): validate() and the checks of an action's
 * result ask for every other system's footprint again and again (each placement a preset search
 * tries, each clash test), and a system that an action left alone is the same object. Callers
 * read the tree and never change it.
 */
const elementTrees = perCatalog(buildElementTree);

function buildElementTree(system: LightSystem, catalog: Catalog): SystemElementTree {
  const w = catalog.rail.width;
  const rails = railPlacements(system, catalog);
  const elements: PlanRect[][] = [];
  const railElement: number[] = [];
  const nodeElement = new Map<number, number>();
  const links: number[][] = [];
  const link = (a: number, b: number) => (links[a].push(b), links[b].push(a));
  // Branches per rail in one pass (a hostile file's long chain stays linear).
  const branchesOf: number[][] = rails.map(() => []);
  system.joints.forEach((j, k) => {
    const p = jointParent(j, k);
    if (rails[k + 1] && branchesOf[p]) branchesOf[p].push(k);
  });
  rails.forEach((r, i) => {
    railElement[i] = elements.length;
    elements.push([segmentRect(r.start, r.end, w)]);
    links.push([]);
    const branches = branchesOf[i];
    if (branches.length === 0) return;
    const con = findConnector(catalog, system.joints[branches[0]].connector);
    const group: PlanRect[] = [];
    if (!twoArmed(con)) {
      for (const k of branches) group.push(segmentRect(r.end, rails[k + 1].start, w));
    } else {
      const pivot = add(r.end, r.direction, con.arm);
      group.push(segmentRect(r.end, add(pivot, r.direction, w / 2), w));
      for (const k of branches) group.push(segmentRect(add(pivot, rails[k + 1].direction, -w / 2), rails[k + 1].start, w));
    }
    nodeElement.set(i, elements.length);
    elements.push(group);
    links.push([]);
    link(railElement[i], elements.length - 1);
  });
  system.joints.forEach((j, k) => {
    const node = nodeElement.get(jointParent(j, k));
    if (node !== undefined && railElement[k + 1] !== undefined) link(node, railElement[k + 1]);
  });
  const near = links.map((ls, a) => {
    const set = new Set<number>([a, ...ls]);
    for (const b of ls) for (const c of links[b]) set.add(c);
    return set;
  });
  const kinds: ElementKind[] = [];
  railElement.forEach((e, rail) => (kinds[e] = { kind: 'rail', rail }));
  nodeElement.forEach((e, rail) => (kinds[e] = { kind: 'node', rail }));
  return { elements, near, kinds };
}

export function rectCorners(r: PlanRect): PlanVec[] {
  const [ax, az] = r.axis;
  const nx = -az;
  const nz = ax;
  const out: PlanVec[] = [];
  for (const a of [-1, 1]) {
    for (const b of [-1, 1]) {
      out.push([r.centre[0] + a * r.halfLength * ax + b * r.halfWidth * nx, r.centre[1] + a * r.halfLength * az + b * r.halfWidth * nz]);
    }
  }
  return out;
}

/**
 * True when two rectangles overlap by more than `tolerance` (separating axis
 * theorem: two convex shapes are disjoint iff some edge normal separates their
 * projections; rectangles have two edge directions each). Touching is allowed.
 */
export function rectsOverlap(a: PlanRect, b: PlanRect, tolerance = 1e-6): boolean {
  const axes: PlanVec[] = [a.axis, [-a.axis[1], a.axis[0]], b.axis, [-b.axis[1], b.axis[0]]];
  const ca = rectCorners(a);
  const cb = rectCorners(b);
  for (const ax of axes) {
    const pa = ca.map((p) => p[0] * ax[0] + p[1] * ax[1]);
    const pb = cb.map((p) => p[0] * ax[0] + p[1] * ax[1]);
    const overlap = Math.min(Math.max(...pa), Math.max(...pb)) - Math.max(Math.min(...pa), Math.min(...pb));
    if (overlap <= tolerance) return false;
  }
  return true;
}

export interface PlanBounds {
  readonly minX: number;
  readonly maxX: number;
  readonly minZ: number;
  readonly maxZ: number;
}

/** Axis-aligned bounds of a system's whole footprint. */
export function systemBounds(system: LightSystem, catalog: Catalog): PlanBounds {
  const pts = systemElements(system, catalog).flat().flatMap(rectCorners);
  return {
    minX: Math.min(...pts.map((p) => p[0])),
    maxX: Math.max(...pts.map((p) => p[0])),
    minZ: Math.min(...pts.map((p) => p[1])),
    maxZ: Math.max(...pts.map((p) => p[1])),
  };
}

/** Module offsets (starts) of a rail: its free positions, or its distribution's; null if they do not fit. */
export function railModuleOffsets(rail: Rail, catalog: Catalog): number[] | null {
  const lengths = rail.modules.map((m) => findModuleType(catalog, m.type).length);
  return isFreeRail(rail) ? freeOffsets(rail, lengths) : layoutModules(lengths, rail.length, rail.distribution);
}

/** Placement of every module of a system (rails whose modules do not fit are skipped: validate() reports them). */
export function modulePlacements(system: LightSystem, catalog: Catalog): ModulePlacement[] {
  const out: ModulePlacement[] = [];
  const rails = railPlacements(system, catalog);
  system.rails.forEach((rail, i) => {
    const offsets = railModuleOffsets(rail, catalog);
    if (!offsets) return;
    const p = rails[i];
    rail.modules.forEach((m, k) => {
      const length = findModuleType(catalog, m.type).length;
      const from = add(p.start, p.direction, offsets[k]);
      const to = add(p.start, p.direction, offsets[k] + length);
      const footprint = segmentRect(from, to, catalog.rail.width);
      out.push({ moduleId: m.id, railId: rail.id, systemId: system.id, offset: offsets[k], length, centre: footprint.centre, heading: p.heading, footprint });
    });
  });
  return out;
}
