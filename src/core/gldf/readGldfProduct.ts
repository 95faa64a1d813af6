/**
 * A GLDF container (.gldf: a zip with product.xml and the files it names) into a GldfProduct.
 * Element names and order follow globallightingdata/gldf xsd/gldf.xsd (MIT; vendored in
 * vendor/gldf/). Checked here, each refused with one line naming the file and the element:
 * the container (readUploadZip), the XML (parseUploadXml: no DTD, no entities), every id
 * unique across the document (xs:ID), every reference resolving (fileId, photometryId,
 * fixedLightSourceId, equipmentId, emitterId, geometryId), every local file present in the
 * container, numbers finite and in range. What luxbox does not use is not read.
 */
import { GldfError, quoteName } from './GldfError';
import { containerFolder, type GldfEmitter, type GldfEquipment, type GldfFile, type GldfGeometry, type GldfLightEmitter, type GldfLightSource, type GldfPhotometry, type GldfProduct, type GldfVariant, type LocaleTexts } from './gldfProduct';
import { attr, child, children, parseUploadXml, path, text, type XmlElement } from './parseUploadXml';
import { readUploadZip, unsafeEntryName, type UploadZip } from './readUploadZip';

/**
 * xs:double as GLDF files write it. No two quantifiers may split the same run of digits (the
 * fuzzer found `\d+\.?\d*` backtracking quadratically over a 10⁶-digit numeral), and text
 * longer than any real number is refused before the expression runs.
 */
const DECIMAL = /^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d{1,3})?$/;
const MAX_NUMBER_TEXT = 40;

/** Reads the container and its product.xml. */
export function readGldfProduct(bytes: Uint8Array, source: string): { product: GldfProduct; zip: UploadZip } {
  const zip = readUploadZip(bytes, source);
  if (!zip.has('product.xml')) throw new GldfError(`${source}: no product.xml in the container`);
  const label = `${source}: entry 'product.xml'`;
  const root = parseUploadXml(zip.read('product.xml'), label, 'Root');
  const product = new ProductReader(label, source).read(root);
  for (const file of product.files.values()) {
    if (file.type === 'localFileName' && !zip.has(file.path)) throw new GldfError(`${label}: File ${quoteName(file.id)} names ${quoteName(file.path)}, which is not in the container`);
  }
  return { product, zip };
}

class ProductReader {
  private readonly ids = new Set<string>();
  constructor(
    private readonly label: string,
    private readonly source: string,
  ) {}

  private fail(where: string, problem: string): never {
    throw new GldfError(`${this.label}: ${where}: ${problem}`);
  }

  /** Registers an xs:ID; the schema makes ids unique across the whole document. */
  private id(el: XmlElement, where: string): string {
    const id = attr(el, 'id');
    if (id === undefined || id === '') this.fail(where, 'has no id');
    if (!/^[A-Za-z_][\w.-]*$/.test(id)) this.fail(where, `id ${quoteName(id)} is not an XML name`);
    if (this.ids.has(id)) this.fail(where, `duplicate id ${quoteName(id)}`);
    this.ids.add(id);
    return id;
  }

  private number(el: XmlElement | undefined, where: string, min: number, max: number): number {
    const t = text(el);
    if (t.length > MAX_NUMBER_TEXT || !DECIMAL.test(t)) this.fail(where, `${quoteName(t)} is not a number`);
    const v = Number(t);
    if (!(v >= min && v <= max)) this.fail(where, `${v} is out of range (${min} to ${max})`);
    return v;
  }

  private optionalNumber(el: XmlElement | undefined, where: string, min: number, max: number): number | undefined {
    return el === undefined ? undefined : this.number(el, where, min, max);
  }

  private locale(el: XmlElement | undefined, where: string, required: boolean): LocaleTexts {
    const out = children(el, 'Locale', this.label).map((l) => ({ language: attr(l, 'language') ?? '', text: text(l) }));
    if (required && !out.some((l) => l.text !== '')) this.fail(where, 'has no text');
    return out;
  }

  private ref(el: XmlElement | undefined, name: string, where: string, table: ReadonlyMap<string, unknown>, what: string): string {
    const id = attr(el, name);
    if (id === undefined) this.fail(where, `has no ${name}`);
    if (!table.has(id)) this.fail(where, `${name} ${quoteName(id)} names no ${what}`);
    return id;
  }

  read(root: XmlElement): GldfProduct {
    const h = child(root, 'Header');
    if (!h) this.fail('Root', 'has no Header');
    const fv = child(h, 'FormatVersion');
    const header = {
      manufacturer: text(child(h, 'Manufacturer')),
      formatVersion: `${attr(fv, 'major') ?? '?'}.${attr(fv, 'minor') ?? '?'}`,
      createdWithApplication: text(child(h, 'CreatedWithApplication')),
      uniqueGldfId: text(child(h, 'UniqueGldfId')),
      ...(child(h, 'DefaultLanguage') ? { defaultLanguage: text(child(h, 'DefaultLanguage')) } : {}),
    };
    if (!header.manufacturer) this.fail('Header', 'has no Manufacturer');
    const g = child(root, 'GeneralDefinitions');
    if (!g) this.fail('Root', 'has no GeneralDefinitions');
    const files = this.files(g);
    const photometries = this.photometries(g, files);
    const lightSources = this.lightSources(g);
    const equipments = this.equipments(g, lightSources);
    const emitters = this.emitters(g, photometries, lightSources, equipments);
    const geometries = this.geometries(g, files);
    const defs = child(root, 'ProductDefinitions');
    const meta = child(defs, 'ProductMetaData');
    if (!meta) this.fail('ProductDefinitions', 'has no ProductMetaData');
    const uniqueProductId = text(child(meta, 'UniqueProductId'));
    if (!uniqueProductId) this.fail('ProductMetaData', 'has no UniqueProductId');
    const variants = children(child(defs, 'Variants'), 'Variant', this.label).map((v) => this.variant(v, files, emitters, geometries));
    if (variants.length === 0) this.fail('ProductDefinitions', 'has no Variant');
    return {
      source: this.source,
      header,
      uniqueProductId,
      productNumber: this.locale(child(meta, 'ProductNumber'), 'ProductMetaData/ProductNumber', false),
      name: this.locale(child(meta, 'Name'), 'ProductMetaData/Name', true),
      pictureFileIds: this.images(child(meta, 'Pictures'), 'ProductMetaData/Pictures', files),
      files,
      photometries,
      lightSources,
      equipments,
      emitters,
      geometries,
      variants,
    };
  }

  private files(g: XmlElement): Map<string, GldfFile> {
    const out = new Map<string, GldfFile>();
    for (const f of children(child(g, 'Files'), 'File', this.label)) {
      const where = 'File';
      const id = this.id(f, where);
      const contentType = attr(f, 'contentType') ?? '';
      const type = attr(f, 'type');
      if (type !== 'localFileName' && type !== 'url') this.fail(`File ${quoteName(id)}`, `type ${quoteName(type ?? '')} is neither localFileName nor url`);
      const name = text(f);
      if (!name) this.fail(`File ${quoteName(id)}`, 'names no file');
      let filePath = name;
      if (type === 'localFileName') {
        filePath = `${containerFolder(contentType)}/${name}`;
        const unsafe = unsafeEntryName(filePath);
        if (unsafe || name.includes('/')) this.fail(`File ${quoteName(id)}`, `${quoteName(name)} ${unsafe ?? 'is not a plain file name'}`);
      }
      out.set(id, { id, contentType, type, path: filePath });
    }
    return out;
  }

  private photometries(g: XmlElement, files: ReadonlyMap<string, GldfFile>): Map<string, GldfPhotometry> {
    const out = new Map<string, GldfPhotometry>();
    for (const p of children(child(g, 'Photometries'), 'Photometry', this.label)) {
      const id = this.id(p, 'Photometry');
      const fileId = this.ref(child(p, 'PhotometryFileReference'), 'fileId', `Photometry ${quoteName(id)}`, files, 'File');
      out.set(id, { id, fileId });
    }
    return out;
  }

  private lightSources(g: XmlElement): Map<string, GldfLightSource> {
    const out = new Map<string, GldfLightSource>();
    const ls = child(g, 'LightSources');
    for (const [tag, kind] of [
      ['FixedLightSource', 'fixed'],
      ['ChangeableLightSource', 'changeable'],
    ] as const) {
      for (const s of children(ls, tag, this.label)) {
        const id = this.id(s, tag);
        const where = `${tag} ${quoteName(id)}`;
        const colour = child(s, 'ColorInformation');
        const gtin = text(child(s, 'GTIN'));
        const flux = this.optionalNumber(child(s, 'RatedLuminousFlux'), `${where}/RatedLuminousFlux`, 0, 1e7);
        const cct = this.optionalNumber(child(colour, 'CorrelatedColorTemperature'), `${where}/CorrelatedColorTemperature`, 1000, 20000);
        const cri = this.optionalNumber(child(colour, 'ColorRenderingIndex'), `${where}/ColorRenderingIndex`, -100, 100);
        out.set(id, {
          id,
          kind,
          name: this.locale(child(s, 'Name'), `${where}/Name`, false),
          ratedInputPower: this.number(child(s, 'RatedInputPower'), `${where}/RatedInputPower`, 0, 1e6),
          ...(gtin ? { gtin } : {}),
          ...(flux !== undefined ? { ratedLuminousFlux: flux } : {}),
          ...(cct !== undefined ? { cct } : {}),
          ...(cri !== undefined ? { cri } : {}),
        });
      }
    }
    for (const s of children(ls, 'MultiChannelLightSource', this.label)) this.id(s, 'MultiChannelLightSource');
    return out;
  }

  private equipments(g: XmlElement, lightSources: ReadonlyMap<string, GldfLightSource>): Map<string, GldfEquipment> {
    const out = new Map<string, GldfEquipment>();
    for (const e of children(child(g, 'Equipments'), 'Equipment', this.label)) {
      const id = this.id(e, 'Equipment');
      const where = `Equipment ${quoteName(id)}`;
      const ref = child(e, 'LightSourceReference');
      const lightSourceId = this.ref(ref, 'changeableLightSourceId', where, lightSources, 'ChangeableLightSource');
      const countText = attr(ref, 'lightSourceCount') ?? '1';
      if (!/^\d{1,5}$/.test(countText) || Number(countText) < 1) this.fail(where, `lightSourceCount ${quoteName(countText)} is not a positive whole number`);
      out.set(id, { id, lightSourceId, lightSourceCount: Number(countText), ratedInputPower: this.number(child(e, 'RatedInputPower'), `${where}/RatedInputPower`, 0, 1e6) });
    }
    return out;
  }

  private emitters(g: XmlElement, photometries: ReadonlyMap<string, GldfPhotometry>, lightSources: ReadonlyMap<string, GldfLightSource>, equipments: ReadonlyMap<string, GldfEquipment>): Map<string, GldfEmitter> {
    const out = new Map<string, GldfEmitter>();
    for (const e of children(child(g, 'Emitters'), 'Emitter', this.label)) {
      const id = this.id(e, 'Emitter');
      const where = `Emitter ${quoteName(id)}`;
      const lightEmitters: GldfLightEmitter[] = [];
      for (const f of children(e, 'FixedLightEmitter', this.label)) {
        const lightSourceId = this.ref(child(f, 'LightSourceReference'), 'fixedLightSourceId', where, lightSources, 'light source');
        if (lightSources.get(lightSourceId)?.kind !== 'fixed') this.fail(where, `fixedLightSourceId ${quoteName(lightSourceId)} names a ChangeableLightSource`);
        lightEmitters.push({
          kind: 'fixed',
          ...(child(f, 'Name') ? { name: this.locale(child(f, 'Name'), `${where}/Name`, false) } : {}),
          photometryId: this.ref(child(f, 'PhotometryReference'), 'photometryId', where, photometries, 'Photometry'),
          lightSourceId,
          ratedLuminousFlux: this.number(child(f, 'RatedLuminousFlux'), `${where}/RatedLuminousFlux`, 0, 1e7),
        });
      }
      for (const c of children(e, 'ChangeableLightEmitter', this.label)) {
        const equipment = child(c, 'EquipmentReference');
        const equipmentId = equipment ? this.ref(equipment, 'equipmentId', where, equipments, 'Equipment') : undefined;
        lightEmitters.push({
          kind: 'changeable',
          ...(child(c, 'Name') ? { name: this.locale(child(c, 'Name'), `${where}/Name`, false) } : {}),
          photometryId: this.ref(child(c, 'PhotometryReference'), 'photometryId', where, photometries, 'Photometry'),
          ...(equipmentId ? { equipmentId, lightSourceId: equipments.get(equipmentId)?.lightSourceId } : {}),
        });
      }
      for (const _ of children(e, 'MultiChannelLightEmitter', this.label)) lightEmitters.push({ kind: 'multi-channel' });
      for (const _ of children(e, 'SensorEmitter', this.label)) lightEmitters.push({ kind: 'sensor' });
      if (lightEmitters.length === 0) this.fail(where, 'holds no light emitter');
      out.set(id, { id, lightEmitters });
    }
    return out;
  }

  private geometries(g: XmlElement, files: ReadonlyMap<string, GldfFile>): Map<string, GldfGeometry> {
    const out = new Map<string, GldfGeometry>();
    const geo = child(g, 'Geometries');
    for (const s of children(geo, 'SimpleGeometry', this.label)) {
      const id = this.id(s, 'SimpleGeometry');
      out.set(id, { id, kind: 'simple', fileIds: [] });
    }
    for (const m of children(geo, 'ModelGeometry', this.label)) {
      const id = this.id(m, 'ModelGeometry');
      const fileIds = children(m, 'GeometryFileReference', this.label).map((r) => this.ref(r, 'fileId', `ModelGeometry ${quoteName(id)}`, files, 'File'));
      out.set(id, { id, kind: 'model', fileIds });
    }
    return out;
  }

  private images(el: XmlElement | undefined, where: string, files: ReadonlyMap<string, GldfFile>): string[] {
    return children(el, 'Image', this.label).map((i) => this.ref(i, 'fileId', where, files, 'File'));
  }

  private variant(v: XmlElement, files: ReadonlyMap<string, GldfFile>, emitters: ReadonlyMap<string, GldfEmitter>, geometries: ReadonlyMap<string, GldfGeometry>): GldfVariant {
    const id = this.id(v, 'Variant');
    const where = `Variant ${quoteName(id)}`;
    const sortText = attr(v, 'sortOrder');
    if (sortText !== undefined && !/^-?\d{1,9}$/.test(sortText)) this.fail(where, `sortOrder ${quoteName(sortText)} is not a whole number`);
    const emitterIds: string[] = [];
    const emitterObjects = new Map<string, string>();
    let geometryId: string | undefined;
    const geo = child(v, 'Geometry');
    const emitterRef = (el: XmlElement | undefined): void => {
      emitterIds.push(this.ref(el, 'emitterId', `${where}/Geometry`, emitters, 'Emitter'));
    };
    if (geo) {
      const direct = child(geo, 'EmitterReference');
      const simple = child(geo, 'SimpleGeometryReference') ?? path(geo, 'GeometryReferences', 'SimpleGeometryReference');
      const model = child(geo, 'ModelGeometryReference') ?? path(geo, 'GeometryReferences', 'ModelGeometryReference');
      if (direct) emitterRef(direct);
      if (simple) {
        geometryId = this.ref(simple, 'geometryId', `${where}/Geometry`, geometries, 'geometry');
        emitterRef(simple);
      }
      if (model) {
        geometryId = this.ref(model, 'geometryId', `${where}/Geometry`, geometries, 'geometry');
        for (const r of children(model, 'EmitterReference', this.label)) {
          emitterRef(r);
          // The light-emitting object of the L3D this emitter is (checked against the L3D by gldfToModuleType).
          const name = text(child(r, 'EmitterObjectExternalName')).trim();
          if (name.length > 200) this.fail(`${where}/Geometry`, `EmitterObjectExternalName is longer than 200 characters`);
          if (name) emitterObjects.set(emitterIds[emitterIds.length - 1], name);
        }
      }
    }
    const mountingsEl = child(v, 'Mountings');
    const mountings: string[] = [];
    for (const place of ['Ceiling', 'Wall', 'Ground', 'WorkingPlane'] as const) {
      const p = child(mountingsEl, place);
      if (!p) continue;
      const kinds = Object.keys(p).filter((k) => !k.startsWith('@') && k !== '#text');
      if (kinds.length === 0) mountings.push(slug(place));
      for (const k of kinds) mountings.push(`${slug(place)}-${slug(k === 'SurfaceMounted' ? 'Surface' : k)}`);
    }
    const mech = path(v, 'DescriptiveAttributes', 'Mechanical');
    const size = child(mech, 'ProductSize');
    const gtin = text(child(v, 'GTIN'));
    const listPrices = children(path(v, 'DescriptiveAttributes', 'Marketing', 'ListPrices'), 'ListPrice', this.label).map((p) => ({
      currency: attr(p, 'currency') ?? '',
      price: this.number(p, `${where}/ListPrice`, 0, 1e9),
    }));
    return {
      id,
      ...(sortText !== undefined ? { sortOrder: Number(sortText) } : {}),
      productNumber: this.locale(child(v, 'ProductNumber'), `${where}/ProductNumber`, false),
      name: this.locale(child(v, 'Name'), `${where}/Name`, true),
      ...(gtin ? { gtin } : {}),
      mountings: mountingsEl ? mountings : null,
      emitterIds,
      ...(emitterObjects.size ? { emitterObjects } : {}),
      ...(geometryId ? { geometryId } : {}),
      pictureFileIds: this.images(child(v, 'Pictures'), `${where}/Pictures`, files),
      ...(size
        ? {
            productSize: {
              length: this.number(child(size, 'Length'), `${where}/ProductSize/Length`, 0, 1e6),
              width: this.number(child(size, 'Width'), `${where}/ProductSize/Width`, 0, 1e6),
              height: this.number(child(size, 'Height'), `${where}/ProductSize/Height`, 0, 1e6),
            },
          }
        : {}),
      adjustabilities: children(child(mech, 'Adjustabilities'), 'Adjustability', this.label).map((a) => text(a)),
      listPrices,
    };
  }
}

/** 'WorkingPlane' → 'working-plane'. */
function slug(name: string): string {
  return name.replace(/([a-z])([A-Z])/g, '$1-$2').toLowerCase();
}
