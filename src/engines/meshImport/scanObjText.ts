import { InputError } from '../../core/inputError';
import { checkTriangleBudget, formatCount, MAX_IMPORT_TRIANGLES } from './triangleBudget';

/** Most vertices an OBJ file may define (three per triangle of the budget, with room for unused ones). */
export const MAX_OBJ_VERTICES = 5 * MAX_IMPORT_TRIANGLES;

export interface ScannedObj {
  /** The geometry as OBJLoader should read it: `v x y z`, `f a b c …` with absolute 1-based indices, `o`/`g`, `usemtl`. */
  text: string;
  /** Triangles after fan triangulation of every face. */
  triangles: number;
  vertices: number;
  /** Material library file names from `mtllib` lines, in order, each once. */
  mtllibs: string[];
  /** Statements luxbox does not use (normals, texture coordinates, lines, points, curves …) and how often each appeared. */
  ignored: Map<string, number>;
}

/** Statements that carry nothing the baker needs; dropped without a warning. */
const SILENT = new Set(['vn', 'vt', 's', 'vp']);

/**
 * Check an OBJ file line by line before three's OBJLoader reads it (OBJLoader trusts its input:
 * an index out of range or a bad number becomes NaN silently) and rewrite it to the statements
 * luxbox uses. Every problem is an InputError naming the file and the line
 * (Wavefront OBJ, Appendix B1 of the Advanced Visualizer manual: `v`, `f`, `g`, `o`, `usemtl`, `mtllib`).
 */
export function scanObjText(text: string, file: string): ScannedObj {
  const nul = text.indexOf('\0');
  if (nul >= 0 && text.slice(nul).replace(/[\0\s]/g, '') !== '') {
    throw new InputError(`${file}: line ${lineOf(text, nul)}: binary data (a NUL byte): not a text OBJ file`);
  }
  const raw = text.split('\n');
  const out: string[] = [];
  const mtllibs: string[] = [];
  const ignored = new Map<string, number>();
  let vertices = 0;
  let triangles = 0;
  for (let i = 0; i < raw.length; i++) {
    const lineNumber = i + 1;
    let line = raw[i].replace(/\r$/, '');
    // A trailing backslash continues the statement on the next line (OBJ spec, "Line continuation").
    while (line.endsWith('\\') && i + 1 < raw.length) line = line.slice(0, -1) + raw[++i].replace(/\r$/, '');
    const trimmed = line.trim();
    if (trimmed === '' || trimmed.startsWith('#') || /^\0+$/.test(trimmed)) continue;
    const tokens = trimmed.split(/\s+/);
    const keyword = tokens[0];
    const where = `${file}: line ${lineNumber}`;
    switch (keyword) {
      case 'v': {
        if (tokens.length < 4) throw new InputError(`${where}: a vertex needs three coordinates, got ${tokens.length - 1}`);
        const xyz = tokens.slice(1, 4).map((t) => {
          const value = Number(t);
          if (!Number.isFinite(value)) throw new InputError(`${where}: vertex coordinate ${quote(t)} is not a finite number`);
          return value;
        });
        vertices++;
        if (vertices > MAX_OBJ_VERTICES) throw new InputError(`${file}: more than ${formatCount(MAX_OBJ_VERTICES)} vertices; simplify the model and import again`);
        out.push(`v ${xyz[0]} ${xyz[1]} ${xyz[2]}`);
        break;
      }
      case 'f': {
        if (tokens.length < 4) throw new InputError(`${where}: a face needs at least 3 vertices, got ${tokens.length - 1}`);
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
        triangles += indices.length - 2;
        // Refuse early: a huge file is not worth building.
        if (triangles > MAX_IMPORT_TRIANGLES) checkTriangleBudget(file, countTriangles(raw, i + 1, triangles));
        out.push(`f ${indices.join(' ')}`);
        break;
      }
      case 'o':
      case 'g':
        out.push(tokens.length > 1 ? `${keyword} ${tokens.slice(1).join(' ')}` : keyword);
        break;
      case 'usemtl':
        if (tokens.length > 1) out.push(`usemtl ${trimmed.slice(6).trim()}`);
        break;
      case 'mtllib':
        // File names may not contain spaces in OBJ; several libraries may share one line.
        for (const name of tokens.slice(1)) if (!mtllibs.includes(name)) mtllibs.push(name);
        break;
      default:
        if (!SILENT.has(keyword)) ignored.set(keyword.slice(0, 16), (ignored.get(keyword.slice(0, 16)) ?? 0) + 1);
    }
  }
  if (triangles === 0) throw new InputError(`${file}: no faces (luxbox needs a surface model with 'f' lines)`);
  return { text: out.join('\n'), triangles, vertices, mtllibs, ignored };
}

/** Triangles of the faces from line `from` on, added to `sofar` (for the budget message's exact count). */
function countTriangles(raw: readonly string[], from: number, sofar: number): number {
  let n = sofar;
  for (let i = from; i < raw.length; i++) {
    const t = raw[i].trim();
    if (t.startsWith('f ') || t.startsWith('f\t')) n += Math.max(0, t.split(/\s+/).length - 3);
  }
  return n;
}

function lineOf(text: string, offset: number): number {
  let line = 1;
  for (let i = 0; i < offset; i++) if (text.charCodeAt(i) === 10) line++;
  return line;
}

function quote(token: string): string {
  return JSON.stringify(token.length > 24 ? `${token.slice(0, 24)}…` : token);
}
