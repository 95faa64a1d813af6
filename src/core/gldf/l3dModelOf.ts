/**
 * A GLDF product's L3D geometry for the catalog (docs/gldf.md "L3D in the 3D view"): the lead
 * variant's ModelGeometry, its first local `geo/l3d` file, read and checked with readL3dStructure
 * (the upload checks: a refused L3D refuses the product), written as `geo/<type id>.l3d`; and the
 * aiming ranges its joints give.
 */
import type { ModuleTypeSpec } from '../model/catalogSchema/moduleTypeSchema';
import type { Photometry } from '../photometry/types';
import { GldfError, quoteName } from './GldfError';
import type { GldfProduct, GldfVariant } from './gldfProduct';
import { l3dJoints, readL3dStructure, type L3dGeometryNode, type L3dLuminaire } from './readL3dStructure';
import type { UploadZip } from './readUploadZip';

export interface ProductModel {
  /** Catalog path of the written file: `geo/<type id>.l3d`. */
  path: string;
  bytes: Uint8Array;
  luminaire: L3dLuminaire;
  /** The container entry it came from. */
  entry: string;
  /** The light-emitting object the lead variant's emitter names (EmitterObjectExternalName), checked to exist; the catalog's `modelEmitter`. */
  emitterObject?: string;
}

/** Every LightEmittingObject's partName, depth first. */
export function l3dLightEmittingObjectNames(nodes: readonly L3dGeometryNode[]): string[] {
  return nodes.flatMap((n) => [...n.lightEmittingObjects.map((o) => o.partName), ...n.joints.flatMap((j) => l3dLightEmittingObjectNames(j.geometries))]);
}

/**
 * The EmitterObjectExternalName of each variant drawn with `model` must name one of its
 * LightEmittingObjects (docs/gldf.md "Which object emits"): refused otherwise, naming the product,
 * the variant and the missing name. Returns the lead variant's (its first emitter's), if any.
 */
export function checkEmitterObjects(product: GldfProduct, model: Pick<ProductModel, 'luminaire' | 'entry'>, variants: readonly GldfVariant[]): string | undefined {
  const known = l3dLightEmittingObjectNames(model.luminaire.structure);
  for (const v of variants) {
    for (const name of v.emitterObjects?.values() ?? []) {
      if (!known.includes(name)) {
        const has = known.length
          ? `it has ${known
              .slice(0, 3)
              .map((k) => quoteName(k, 30))
              .join(', ')}${known.length > 3 ? ', …' : ''}`
          : 'it has none';
        throw new GldfError(
          `${product.source}: product ${quoteName(product.uniqueProductId, 40)}: Variant ${quoteName(v.id, 40)}: EmitterObjectExternalName ${quoteName(name, 40)} is no LightEmittingObject of ${quoteName(model.entry, 40)} (${has})`,
        );
      }
    }
  }
  const lead = variants[0];
  return lead ? lead.emitterObjects?.get(lead.emitterIds[0]) : undefined;
}

/** The L3D a variant is drawn with (its ModelGeometry's first local L3D file), or null. */
export function l3dModelOf(product: GldfProduct, zip: UploadZip, variant: GldfVariant, typeId: string): ProductModel | null {
  const geometry = variant.geometryId ? product.geometries.get(variant.geometryId) : undefined;
  if (!geometry || geometry.kind !== 'model') return null;
  const file = geometry.fileIds.map((id) => product.files.get(id)).find((f) => f?.contentType === 'geo/l3d' && f.type === 'localFileName');
  if (!file) return null;
  const bytes = zip.read(file.path);
  const { luminaire } = readL3dStructure(bytes, `${product.source}: entry '${file.path}'`);
  return { path: `geo/${typeId}.l3d`, bytes, luminaire, entry: file.path };
}

/** Whole degrees within the catalog's rules: `stops` only where min and max lie on its grid (and, for rotation, it divides 360). */
function range(min: number, max: number, step: number, limit: number, circle: boolean): { min: number; max: number; stops?: number } {
  const lo = Math.max(0, Math.min(limit - 1, min));
  const hi = Math.max(lo, Math.min(limit - 1, max));
  const onGrid = (v: number) => Math.abs(v / step - Math.round(v / step)) < 1e-9;
  const stops = step > 0 && step <= 90 && onGrid(lo) && onGrid(hi) && (!circle || onGrid(360)) ? step : undefined;
  return { min: lo, max: hi, ...(stops ? { stops } : {}) };
}

/**
 * The aiming ranges of an L3D's joints (depth first: the first joint with a Z axis is the swivel,
 * the first with an X or Y axis the tilt), or null when it has neither.
 * - tilt: the angles from straight down the tilt axis reaches, |angle| over its min–max (a head
 *   tilting −90…90° reaches 0…90° from straight down, both ways);
 * - rotation: from 0 over the swivel's span (max − min; 180° more when the tilt goes both ways,
 *   since tilting the other way points the other side), at most 355°. The catalog's rotation
 *   has no offset, so where the gap of a swivel under a full turn lies is not carried over: the 3D
 *   view's joints stop at their own limits.
 * A joint's step becomes the range's stops where the catalog allows it.
 */
export function l3dAimLimits(luminaire: L3dLuminaire): ModuleTypeSpec['adjustable'] | null {
  const joints = l3dJoints(luminaire.structure);
  const swivel = joints.flatMap((j) => j.axes).find((a) => a.axis === 'z');
  const tilt = joints.flatMap((j) => j.axes).find((a) => a.axis === 'x' || a.axis === 'y');
  if (!swivel && !tilt) return null;
  const both = tilt !== undefined && tilt.min < 0 && tilt.max > 0;
  // |angle| over [min, max]: from 0 when the range holds 0, else from its end nearer 0.
  const tiltRange = tilt ? range(tilt.min <= 0 && tilt.max >= 0 ? 0 : Math.min(Math.abs(tilt.min), Math.abs(tilt.max)), Math.max(Math.abs(tilt.min), Math.abs(tilt.max)), tilt.step, 180, false) : { min: 0, max: 0 };
  const span = swivel ? swivel.max - swivel.min + (both ? 180 : 0) : both ? 180 : 0;
  const rotationRange = range(0, Math.min(355, span), swivel?.step ?? 0, 360, true);
  return { tilt: tiltRange, rotation: rotationRange };
}

function lightEmittingObject(nodes: readonly L3dGeometryNode[], name: string | undefined): L3dGeometryNode['lightEmittingObjects'][number] | undefined {
  for (const n of nodes) {
    const here = n.lightEmittingObjects.find((o) => name === undefined || o.partName === name);
    if (here) return here;
    for (const j of n.joints) {
      const found = lightEmittingObject(j.geometries, name);
      if (found) return found;
    }
  }
  return undefined;
}

const mm = (m: number): string => `${Math.round(Math.abs(m) * 1e4) / 10}`;

/**
 * A report note where a beam's photometric header gives another luminous opening than the L3D's
 * light-emitting object (`emitterObject`, else the first): the 3D view's near field uses the L3D's
 * (docs/gldf.md "The L3D's opening in the near field"), so a shop sees which numbers it gets. Sizes
 * agreeing within 1 mm (either way round) make no note.
 */
export function openingNote(luminaire: L3dLuminaire, emitterObject: string | undefined, beamId: string, opening: Photometry['luminousOpening']): string | null {
  const object = lightEmittingObject(luminaire.structure, emitterObject);
  if (!object) return null;
  const [a, b] = object.shape.kind === 'circle' ? [object.shape.diameter, object.shape.diameter] : [object.shape.sizeX, object.shape.sizeY];
  const [w, l] = [Math.abs(opening.width), Math.abs(opening.length)];
  const near = (x: number, y: number) => Math.abs(x - y) <= 0.001;
  if ((near(a, w) && near(b, l)) || (near(a, l) && near(b, w))) return null;
  const header = w === 0 && l === 0 ? 'a point' : opening.shape === 'circular' && w === l ? `Ø ${mm(w)} mm` : `${mm(w)} × ${mm(l)} mm (${opening.shape})`;
  const l3d = object.shape.kind === 'circle' ? `Ø ${mm(a)} mm` : `${mm(a)} × ${mm(b)} mm`;
  return `beam ${beamId}: the photometry's luminous opening is ${header}, the L3D's light-emitting object ${quoteName(object.partName, 40)} ${l3d}; the near field uses the L3D's`;
}
