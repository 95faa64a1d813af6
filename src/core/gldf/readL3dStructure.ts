/**
 * An L3D luminaire geometry (globallightingdata/l3d, xsd/l3d.xsd, MIT: a zip of OBJ parts, each
 * in a folder named by its GeometryFileDefinition id, plus `structure.xml`) read into a tree of
 * plain data: geometry parts, joints with their axes and angle limits, light-emitting objects
 * and surfaces. The container goes through the same upload checks as a GLDF (readUploadZip,
 * parseUploadXml: no DTDs); every geometryId and lightEmittingPartName must resolve, part names
 * must be unique, every OBJ must be in the container, numbers finite. Positions are metres
 * relative to the parent part; rotations are degrees about the local axes, applied in the order
 * Z, X, Y (the L3D reference: "The rotation order is fixed to ZXY"). The OBJ meshes themselves
 * are not read here (engines/meshImport does that, with its triangle budget).
 */
import { GldfError, quoteName } from './GldfError';
import { attr, child, children, parseUploadXml, text, type XmlElement } from './parseUploadXml';
import { readUploadZip, unsafeEntryName, type UploadZip } from './readUploadZip';

export type Vec3 = [number, number, number];

/** Metres per unit of the GeometryFileDefinition `units` (yard, foot and inch are the international ones). */
export const L3D_UNITS: Readonly<Record<string, number>> = { m: 1, dm: 0.1, cm: 0.01, mm: 0.001, yard: 0.9144, foot: 0.3048, inch: 0.0254 };

export interface L3dGeometryFile {
  id: string;
  /** Entry path in the container: `<id>/<filename>`. */
  path: string;
  /** Metres per OBJ unit. */
  scale: number;
}

export interface L3dAxis {
  axis: 'x' | 'y' | 'z';
  min: number;
  max: number;
  step: number;
}

export interface L3dJoint {
  partName: string;
  position: Vec3;
  rotation: Vec3;
  /** The degrees of freedom: rotation about each listed local axis within [min, max], in steps. */
  axes: L3dAxis[];
  defaultRotation?: Vec3;
  geometries: L3dGeometryNode[];
}

export interface L3dLightEmittingObject {
  partName: string;
  position: Vec3;
  rotation: Vec3;
  shape: { kind: 'rectangle'; sizeX: number; sizeY: number } | { kind: 'circle'; diameter: number };
  /** LuminousHeights c0, c90, c180, c270 (metres), where given. */
  luminousHeights?: [number, number, number, number];
}

export interface L3dLightEmittingSurface {
  partName: string;
  objects: { partName: string; intensity?: number }[];
  /** Face ranges of the part's OBJ, inclusive (a single FaceAssignment is begin = end). */
  faces: { begin: number; end: number; groupIndex?: number }[];
}

export interface L3dGeometryNode {
  partName: string;
  position: Vec3;
  rotation: Vec3;
  geometryId: string;
  includedInMeasurement: boolean;
  joints: L3dJoint[];
  lightEmittingObjects: L3dLightEmittingObject[];
  lightEmittingSurfaces: L3dLightEmittingSurface[];
}

export interface L3dLuminaire {
  source: string;
  header: { name?: string; createdWithApplication: string; formatVersion: string };
  geometryFiles: ReadonlyMap<string, L3dGeometryFile>;
  structure: L3dGeometryNode[];
}

const DECIMAL = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d{1,3})?$/;
/** Largest coordinate (metres) and angle magnitude (degrees) accepted. */
const MAX_METRES = 1000;
const MAX_DEGREES = 3600;

export function readL3dStructure(bytes: Uint8Array, source: string): { luminaire: L3dLuminaire; zip: UploadZip } {
  const zip = readUploadZip(bytes, source);
  if (!zip.has('structure.xml')) throw new GldfError(`${source}: no structure.xml in the container`);
  const label = `${source}: entry 'structure.xml'`;
  const root = parseUploadXml(zip.read('structure.xml'), label, 'Luminaire');
  const luminaire = new StructureReader(label, source, zip).read(root);
  return { luminaire, zip };
}

class StructureReader {
  private readonly parts = new Set<string>();
  private readonly emitting = new Set<string>();
  private readonly references: { name: string; where: string }[] = [];
  private files = new Map<string, L3dGeometryFile>();

  constructor(
    private readonly label: string,
    private readonly source: string,
    private readonly zip: UploadZip,
  ) {}

  private fail(where: string, problem: string): never {
    throw new GldfError(`${this.label}: ${where}: ${problem}`);
  }

  private number(value: string | undefined, where: string, max: number, min = -max): number {
    if (value === undefined) this.fail(where, 'is missing');
    if (value.length > 40 || !DECIMAL.test(value)) this.fail(where, `${quoteName(value)} is not a number`);
    const v = Number(value);
    if (!(v >= min && v <= max)) this.fail(where, `${v} is out of range (${min} to ${max})`);
    return v;
  }

  private vector(el: XmlElement | undefined, where: string, max: number): Vec3 {
    if (!el) this.fail(where, 'is missing');
    return [this.number(attr(el, 'x'), `${where} x`, max), this.number(attr(el, 'y'), `${where} y`, max), this.number(attr(el, 'z'), `${where} z`, max)];
  }

  private partName(el: XmlElement, what: string): string {
    const name = attr(el, 'partName');
    if (!name) this.fail(what, 'has no partName');
    if (this.parts.has(name)) this.fail(`${what} ${quoteName(name)}`, 'duplicate partName');
    this.parts.add(name);
    return name;
  }

  read(root: XmlElement): L3dLuminaire {
    const h = child(root, 'Header');
    if (!h) this.fail('Luminaire', 'has no Header');
    const fv = child(h, 'FormatVersion');
    const name = text(child(h, 'Name'));
    for (const g of children(child(root, 'GeometryDefinitions'), 'GeometryFileDefinition', this.label)) {
      const id = attr(g, 'id') ?? '';
      const where = `GeometryFileDefinition ${quoteName(id)}`;
      if (!/^[A-Za-z_][\w.-]*$/.test(id)) this.fail('GeometryFileDefinition', `id ${quoteName(id)} is not an XML name`);
      if (this.files.has(id)) this.fail(where, 'duplicate id');
      const filename = attr(g, 'filename') ?? '';
      const path = `${id}/${filename}`;
      const unsafe = unsafeEntryName(path);
      if (unsafe || filename.includes('/')) this.fail(where, `filename ${quoteName(filename)} ${unsafe ?? 'is not a plain file name'}`);
      if (!this.zip.has(path)) this.fail(where, `${quoteName(path)} is not in the container`);
      const units = attr(g, 'units') ?? '';
      const scale = L3D_UNITS[units];
      if (scale === undefined) this.fail(where, `units ${quoteName(units)} is not one of ${Object.keys(L3D_UNITS).join(', ')}`);
      this.files.set(id, { id, path, scale });
    }
    if (this.files.size === 0) this.fail('GeometryDefinitions', 'defines no geometry file');
    const structure = children(child(root, 'Structure'), 'Geometry', this.label).map((g) => this.geometry(g));
    if (structure.length === 0) this.fail('Structure', 'has no Geometry');
    for (const r of this.references) if (!this.emitting.has(r.name)) this.fail(r.where, `lightEmittingPartName ${quoteName(r.name)} names no LightEmittingObject`);
    return {
      source: this.source,
      header: { ...(name ? { name } : {}), createdWithApplication: text(child(h, 'CreatedWithApplication')), formatVersion: `${attr(fv, 'major') ?? '?'}.${attr(fv, 'minor') ?? '?'}` },
      geometryFiles: this.files,
      structure,
    };
  }

  private geometry(g: XmlElement): L3dGeometryNode {
    const partName = this.partName(g, 'Geometry');
    const where = `Geometry ${quoteName(partName)}`;
    const ref = child(g, 'GeometryReference');
    const geometryId = attr(ref, 'geometryId');
    if (geometryId === undefined) this.fail(where, 'has no GeometryReference');
    if (!this.files.has(geometryId)) this.fail(where, `geometryId ${quoteName(geometryId)} names no GeometryFileDefinition`);
    const included = attr(g, 'includedInMeasurement');
    return {
      partName,
      position: this.vector(child(g, 'Position'), `${where} Position`, MAX_METRES),
      rotation: this.vector(child(g, 'Rotation'), `${where} Rotation`, MAX_DEGREES),
      geometryId,
      includedInMeasurement: included !== 'false' && included !== '0',
      joints: children(child(g, 'Joints'), 'Joint', this.label).map((j) => this.joint(j)),
      lightEmittingObjects: children(child(g, 'LightEmittingObjects'), 'LightEmittingObject', this.label).map((o) => this.lightEmittingObject(o)),
      lightEmittingSurfaces: children(child(g, 'LightEmittingSurfaces'), 'LightEmittingSurface', this.label).map((s) => this.lightEmittingSurface(s)),
    };
  }

  private joint(j: XmlElement): L3dJoint {
    const partName = this.partName(j, 'Joint');
    const where = `Joint ${quoteName(partName)}`;
    const axes: L3dAxis[] = [];
    for (const axis of ['x', 'y', 'z'] as const) {
      const a = child(j, `${axis.toUpperCase()}Axis`);
      if (!a) continue;
      const at = `${where} ${axis.toUpperCase()}Axis`;
      const range = { axis, min: this.number(attr(a, 'min'), `${at} min`, MAX_DEGREES), max: this.number(attr(a, 'max'), `${at} max`, MAX_DEGREES), step: this.number(attr(a, 'step'), `${at} step`, 360, 0) };
      if (range.min > range.max) this.fail(at, `min ${range.min} exceeds max ${range.max}`);
      axes.push(range);
    }
    const dr = child(j, 'DefaultRotation');
    const geometries = children(child(j, 'Geometries'), 'Geometry', this.label).map((g) => this.geometry(g));
    if (geometries.length === 0) this.fail(where, 'holds no Geometry');
    return {
      partName,
      position: this.vector(child(j, 'Position'), `${where} Position`, MAX_METRES),
      rotation: this.vector(child(j, 'Rotation'), `${where} Rotation`, MAX_DEGREES),
      axes,
      ...(dr ? { defaultRotation: this.vector(dr, `${where} DefaultRotation`, MAX_DEGREES) } : {}),
      geometries,
    };
  }

  private lightEmittingObject(o: XmlElement): L3dLightEmittingObject {
    const partName = this.partName(o, 'LightEmittingObject');
    this.emitting.add(partName);
    const where = `LightEmittingObject ${quoteName(partName)}`;
    const rect = child(o, 'Rectangle');
    const circle = child(o, 'Circle');
    let shape: L3dLightEmittingObject['shape'];
    if (rect) shape = { kind: 'rectangle', sizeX: this.number(attr(rect, 'sizeX'), `${where} sizeX`, MAX_METRES, 0), sizeY: this.number(attr(rect, 'sizeY'), `${where} sizeY`, MAX_METRES, 0) };
    else if (circle) shape = { kind: 'circle', diameter: this.number(attr(circle, 'diameter'), `${where} diameter`, MAX_METRES, 0) };
    else this.fail(where, 'has neither a Rectangle nor a Circle');
    const lh = child(o, 'LuminousHeights');
    return {
      partName,
      position: this.vector(child(o, 'Position'), `${where} Position`, MAX_METRES),
      rotation: this.vector(child(o, 'Rotation'), `${where} Rotation`, MAX_DEGREES),
      shape,
      ...(lh ? { luminousHeights: (['c0', 'c90', 'c180', 'c270'] as const).map((c) => this.number(attr(lh, c), `${where} LuminousHeights ${c}`, MAX_METRES, 0)) as [number, number, number, number] } : {}),
    };
  }

  private lightEmittingSurface(s: XmlElement): L3dLightEmittingSurface {
    const partName = this.partName(s, 'LightEmittingSurface');
    const where = `LightEmittingSurface ${quoteName(partName)}`;
    const objects = children(s, 'LightEmittingObjectReference', this.label).map((r) => {
      const name = attr(r, 'lightEmittingPartName') ?? '';
      this.references.push({ name, where });
      const intensity = attr(r, 'intensity');
      return { partName: name, ...(intensity !== undefined ? { intensity: this.number(intensity, `${where} intensity`, 1e6, 0) } : {}) };
    });
    if (objects.length === 0) this.fail(where, 'references no LightEmittingObject');
    const fa = child(s, 'FaceAssignments');
    const index = (v: string | undefined, what: string): number => this.number(v, `${where} ${what}`, 2 ** 31 - 1, 0);
    const group = (el: XmlElement): { groupIndex?: number } => (attr(el, 'groupIndex') !== undefined ? { groupIndex: index(attr(el, 'groupIndex'), 'groupIndex') } : {});
    const faces = [
      ...children(fa, 'FaceAssignment', this.label).map((f) => {
        const i = index(attr(f, 'faceIndex'), 'faceIndex');
        return { begin: i, end: i, ...group(f) };
      }),
      ...children(fa, 'FaceRangeAssignment', this.label).map((f) => {
        const begin = index(attr(f, 'faceIndexBegin'), 'faceIndexBegin');
        const end = index(attr(f, 'faceIndexEnd'), 'faceIndexEnd');
        if (begin > end) this.fail(where, `faceIndexBegin ${begin} exceeds faceIndexEnd ${end}`);
        return { begin, end, ...group(f) };
      }),
    ];
    if (faces.length === 0) this.fail(where, 'assigns no face');
    return { partName, objects, faces };
  }
}

/** Every joint of the tree, depth first (the aiming joints a module type's `adjustable` could come from). */
export function l3dJoints(nodes: readonly L3dGeometryNode[]): L3dJoint[] {
  const out: L3dJoint[] = [];
  const walk = (ns: readonly L3dGeometryNode[]): void => {
    for (const n of ns) {
      for (const j of n.joints) {
        out.push(j);
        walk(j.geometries);
      }
    }
  };
  walk(nodes);
  return out;
}
