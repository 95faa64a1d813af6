import { InputError } from '../../core/inputError';
import { checkByteCap, MODEL_BYTE_CAPS } from './byteCaps';
import { checkTriangleBudget, formatCount, MAX_IMPORT_TRIANGLES } from './triangleBudget';

/**
 * Most vertices an OBJ file may define: three per triangle of the budget, what an exporter that
 * shares no vertex writes (welding then merges them). Reading them costs about 1 µs each.
 */
export const MAX_OBJ_VERTICES = 3 * MAX_IMPORT_TRIANGLES;

export interface ScannedObj {
  /** The geometry as OBJLoader should read it: `v x y z`, `f a b c …` with absolute 1-based indices, `usemtl` where the material changes. */
  text: string;
  /** Triangles after fan triangulation of every face. */
  triangles: number;
  vertices: number;
  /** Material library file names from `mtllib` lines, in order, each once. */
  mtllibs: string[];
  /** Statements luxbox does not use (normals, texture coordinates, lines, points, curves …) and how often each appeared. */
  ignored: Map<string, number>;
}

/** Most material changes (`usemtl` naming another material) an OBJ file may make: each becomes a geometry group. */
export const MAX_OBJ_MATERIAL_CHANGES = 16_384;

/** Statements that carry nothing the baker needs; dropped without a warning. */
const SILENT = new Set(['vn', 'vt', 's', 'vp']);

/** Bytes decoded at a time: each piece ends at a line break, so no line is split (and none may be longer). */
const PIECE_BYTES = 1 << 20;

/**
 * Check an OBJ file line by line before three's OBJLoader reads it (OBJLoader trusts its input:
 * an index out of range or a bad number becomes NaN silently) and rewrite it to the statements
 * luxbox uses. Every problem is an InputError naming the file and the line
 * (Wavefront OBJ, Appendix B1 of the Advanced Visualizer manual: `v`, `f`, `g`, `o`, `usemtl`, `mtllib`).
 * The bytes are decoded a piece at a time and the scan stops at the first cap it passes (bytes,
 * vertices, triangles), so a huge file costs no more than its first few megabytes (issue 32).
 */
export function scanObjText(bytes: Uint8Array, file: string): ScannedObj {
  checkByteCap(file, bytes.length, MODEL_BYTE_CAPS.obj, 'an OBJ file');
  const scan: ObjScan = { file, out: [], mtllibs: [], ignored: new Map(), vertices: 0, triangles: 0, currentMaterial: '', materialChanges: 0 };
  forEachObjStatement(bytes, file, (line, lineNumber) => statement(scan, line, lineNumber));
  if (scan.triangles === 0) throw new InputError(`${file}: no faces (luxbox needs a surface model with 'f' lines)`);
  return { text: scan.out.join('\n'), triangles: scan.triangles, vertices: scan.vertices, mtllibs: scan.mtllibs, ignored: scan.ignored };
}

/** What the scan has read so far. */
interface ObjScan {
  readonly file: string;
  readonly out: string[];
  readonly mtllibs: string[];
  readonly ignored: Map<string, number>;
  vertices: number;
  triangles: number;
  currentMaterial: string;
  materialChanges: number;
}

/**
 * Calls `statement` for each logical line (continuations joined) with the number of its first line.
 * The bytes are decoded a piece at a time, each ending at a line break.
 */
function forEachObjStatement(bytes: Uint8Array, file: string, statement: (line: string, lineNumber: number) => void): void {
  const decoder = new TextDecoder('utf-8', { fatal: false, ignoreBOM: false });
  let lineNumber = 0;
  // A trailing backslash continues the statement on the next line (OBJ spec, "Line continuation");
  // the pieces are joined once at the end (joining line by line would be quadratic).
  let continued: string[] = [];
  let continuedLength = 0;
  let continuedFrom = 0;
  for (let start = 0; start < bytes.length;) {
    let end = Math.min(bytes.length, start + PIECE_BYTES);
    if (end < bytes.length) {
      const newline = bytes.lastIndexOf(10, end - 1);
      if (newline < start) throw new InputError(`${file}: line ${lineNumber + 1} is longer than ${PIECE_BYTES / 1024} kB: not a text OBJ file`);
      end = newline + 1;
    }
    const lines = decoder.decode(bytes.subarray(start, end), { stream: end < bytes.length }).split('\n');
    if (end < bytes.length || lines[lines.length - 1] === '') lines.pop();
    start = end;
    for (const raw of lines) {
      lineNumber++;
      const line = raw.endsWith('\r') ? raw.slice(0, -1) : raw;
      if (continued.length === 0) continuedFrom = lineNumber;
      if (line.endsWith('\\')) {
        continued.push(line.slice(0, -1));
        continuedLength += line.length;
        if (continuedLength > PIECE_BYTES) throw new InputError(`${file}: line ${continuedFrom} continues past ${PIECE_BYTES / 1024} kB: not a text OBJ file`);
        continue;
      }
      const joined = continued.length === 0 ? line : continued.join('') + line;
      continued = [];
      continuedLength = 0;
      statement(joined, continuedFrom);
    }
  }
  if (continued.length > 0) statement(continued.join(''), continuedFrom);
}

function statement(scan: ObjScan, line: string, lineNumber: number): void {
  // The common statements luxbox drops (comments, groups, objects, smoothing, normals, texture
  // coordinates) are recognised by their first bytes, without trimming or tokenising.
  const c0 = line.charCodeAt(0);
  const c1 = line.charCodeAt(1);
  if (c0 === 35 /* # */) return;
  if ((c0 === 103 /* g */ || c0 === 111 /* o */ || c0 === 115) /* s */ && (c1 === 32 || c1 === 9 || line.length === 1)) return;
  if (c0 === 118 /* v */ && (c1 === 110 /* n */ || c1 === 116) /* t */ && (line.charCodeAt(2) === 32 || line.charCodeAt(2) === 9)) return;
  const trimmed = line.trim();
  if (trimmed === '' || trimmed.charCodeAt(0) === 35 /* # */) return;
  const where = `${scan.file}: line ${lineNumber}`;
  if (trimmed.includes('\0')) {
    if (/^[\0\s]*$/.test(trimmed)) return;
    throw new InputError(`${where}: binary data (a NUL byte): not a text OBJ file`);
  }
  const space = trimmed.search(/\s/);
  const keyword = space < 0 ? trimmed : trimmed.slice(0, space);
  switch (keyword) {
    case 'v':
      return vertex(scan, trimmed, where);
    case 'f':
      return face(scan, trimmed, where);
    case 'o':
    case 'g':
      // Objects and groups carry nothing luxbox keeps (materials come from usemtl), and OBJLoader
      // builds a mesh for each: 600 000 `g` lines took 5 s (issue 32). Not passed on.
      return;
    case 'usemtl':
      return materialChange(scan, space > 0 ? trimmed.slice(6).trim() : '', where);
    case 'mtllib':
      // File names may not contain spaces in OBJ; several libraries may share one line.
      for (const name of trimmed.split(/\s+/).slice(1)) if (!scan.mtllibs.includes(name)) scan.mtllibs.push(name);
      return;
    default:
      if (!SILENT.has(keyword)) scan.ignored.set(keyword.slice(0, 16), (scan.ignored.get(keyword.slice(0, 16)) ?? 0) + 1);
  }
}

function vertex(scan: ObjScan, trimmed: string, where: string): void {
  const tokens = trimmed.split(/\s+/);
  if (tokens.length < 4) throw new InputError(`${where}: a vertex needs three coordinates, got ${tokens.length - 1}`);
  const xyz = tokens.slice(1, 4).map((t) => {
    const value = Number(t);
    if (!Number.isFinite(value)) throw new InputError(`${where}: vertex coordinate ${quote(t)} is not a finite number`);
    return value;
  });
  scan.vertices++;
  if (scan.vertices > MAX_OBJ_VERTICES) throw new InputError(`${scan.file}: more than ${formatCount(MAX_OBJ_VERTICES)} vertices; simplify the model and import again`);
  scan.out.push(`v ${xyz[0]} ${xyz[1]} ${xyz[2]}`);
}

function face(scan: ObjScan, trimmed: string, where: string): void {
  const tokens = trimmed.split(/\s+/);
  if (tokens.length < 4) throw new InputError(`${where}: a face needs at least 3 vertices, got ${tokens.length - 1}`);
  const vertices = scan.vertices;
  const indices = tokens.slice(1).map((t) => {
    const part = t.split('/')[0];
    if (!/^[+-]?\d{1,9}$/.test(part)) throw new InputError(`${where}: face vertex ${quote(t)} is not a vertex index`);
    const k = Number(part);
    // Negative indices count back from the last vertex defined so far (OBJ spec, "Referencing vertex data").
    const absolute = k < 0 ? vertices + 1 + k : k;
    if (k === 0 || absolute < 1 || absolute > vertices) {
      throw new InputError(`${where}: face refers to vertex ${k}, but ${vertices === 1 ? 'only 1 vertex is' : `${vertices} vertices are`} defined so far`);
    }
    return absolute;
  });
  scan.triangles += indices.length - 2;
  // Refuse at once: the rest of a huge file is not worth reading.
  checkTriangleBudget(scan.file, scan.triangles, true);
  scan.out.push(`f ${indices.join(' ')}`);
}

/** Only a change of material starts a new group in OBJLoader; each costs a draw group. */
function materialChange(scan: ObjScan, material: string, where: string): void {
  if (material === '' || material === scan.currentMaterial) return;
  scan.currentMaterial = material;
  scan.materialChanges++;
  if (scan.materialChanges > MAX_OBJ_MATERIAL_CHANGES) throw new InputError(`${where}: more than ${formatCount(MAX_OBJ_MATERIAL_CHANGES)} changes of material (usemtl); merge faces of one material`);
  scan.out.push(`usemtl ${material}`);
}

function quote(token: string): string {
  return JSON.stringify(token.length > 24 ? `${token.slice(0, 24)}…` : token);
}
