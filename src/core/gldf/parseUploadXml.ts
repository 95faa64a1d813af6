/**
 * XML from an upload (GLDF product.xml, L3D structure.xml) into a plain tree, with
 * fast-xml-parser. Refused before parsing: anything over the size cap, and any DTD or entity
 * declaration (`<!DOCTYPE`, `<!ENTITY`): neither format uses one, and a DTD is how "billion
 * laughs" entity expansion and external entities (XXE) get in. Without a DTD only XML's five
 * predefined entities and character references are decoded. Well-formedness is checked by
 * fast-xml-parser's validator first, so a broken file is refused with its line.
 */
import { XMLParser, XMLValidator } from 'fast-xml-parser';
import { GldfError } from './GldfError';
import { UPLOAD_LIMITS } from './uploadLimits';

/** An element: its attributes as `@name`, its text as `#text`, its child elements by name (always arrays). */
export interface XmlElement {
  readonly [key: string]: string | XmlElement[] | undefined;
}

const parser = new XMLParser({
  ignoreAttributes: false,
  attributeNamePrefix: '@',
  textNodeName: '#text',
  parseTagValue: false,
  parseAttributeValue: false,
  trimValues: true,
  alwaysCreateTextNode: true,
  ignoreDeclaration: true,
  ignorePiTags: true,
  removeNSPrefix: true,
  processEntities: true,
  htmlEntities: false,
  maxNestedTags: UPLOAD_LIMITS.maxXmlDepth,
  isArray: (_name, _path, _leaf, isAttribute) => !isAttribute,
});

const decoder = new TextDecoder('utf-8', { fatal: true });

/** Decodes and parses one XML entry; returns its root element. Throws GldfError naming `label` (file and entry). */
export function parseUploadXml(bytes: Uint8Array, label: string, rootName: string): XmlElement {
  if (bytes.length > UPLOAD_LIMITS.maxXmlBytes) throw new GldfError(`${label}: ${bytes.length} bytes, over the ${UPLOAD_LIMITS.maxXmlBytes}-byte limit for XML`);
  let text: string;
  try {
    text = decoder.decode(bytes);
  } catch {
    throw new GldfError(`${label}: not UTF-8 text`);
  }
  if (text.charCodeAt(0) === 0xfeff) text = text.slice(1);
  if (/<!DOCTYPE/i.test(text)) throw new GldfError(`${label}: has a DTD (<!DOCTYPE); DTDs and entity declarations are refused`);
  if (/<!ENTITY/i.test(text)) throw new GldfError(`${label}: declares an entity (<!ENTITY); DTDs and entity declarations are refused`);
  const valid = XMLValidator.validate(text);
  if (valid !== true) throw new GldfError(`${label} line ${valid.err.line}: ${valid.err.msg}`);
  let doc: XmlElement;
  try {
    doc = parser.parse(text) as XmlElement;
  } catch (error) {
    throw new GldfError(`${label}: ${(error as Error).message}`);
  }
  const roots = Object.keys(doc).filter((k) => !k.startsWith('@') && k !== '#text');
  const root = doc[rootName];
  if (roots.length !== 1 || !Array.isArray(root) || root.length !== 1) throw new GldfError(`${label}: the root element must be <${rootName}>`);
  return root[0];
}

/** Child elements named `name` (none: []). Refuses more than UPLOAD_LIMITS.maxSiblings. */
export function children(el: XmlElement | undefined, name: string, label: string): XmlElement[] {
  const v = el?.[name];
  if (!Array.isArray(v)) return [];
  if (v.length > UPLOAD_LIMITS.maxSiblings) throw new GldfError(`${label}: ${v.length} <${name}> elements, over the limit of ${UPLOAD_LIMITS.maxSiblings}`);
  return v;
}

/** The one child named `name`, or undefined (the first where the file repeats it). */
export function child(el: XmlElement | undefined, name: string): XmlElement | undefined {
  const v = el?.[name];
  return Array.isArray(v) ? v[0] : undefined;
}

/** Follows a path of single children: path(root, 'Header', 'Manufacturer'). */
export function path(el: XmlElement | undefined, ...names: string[]): XmlElement | undefined {
  let at = el;
  for (const n of names) at = child(at, n);
  return at;
}

/** The element's text ('' when it has none). */
export function text(el: XmlElement | undefined): string {
  const t = el?.['#text'];
  return typeof t === 'string' ? t : '';
}

/** An attribute's value, or undefined. */
export function attr(el: XmlElement | undefined, name: string): string | undefined {
  const v = el?.[`@${name}`];
  return typeof v === 'string' ? v : undefined;
}
