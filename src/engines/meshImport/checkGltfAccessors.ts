import { excerpt } from '../../core/untrustedJson';
import { formatCount } from './triangleBudget';

type Json = Record<string, unknown>;

/** Bytes per component (glTF 2.0 §3.6.2.2, componentType). */
const COMPONENT_BYTES: Record<number, number> = { 5120: 1, 5121: 1, 5122: 2, 5123: 2, 5125: 4, 5126: 4 };
/** Components per element and, for matrices, columns (§3.6.2.2, type). */
const TYPES: Record<string, { components: number; columns: number }> = {
  SCALAR: { components: 1, columns: 0 },
  VEC2: { components: 2, columns: 0 },
  VEC3: { components: 3, columns: 0 },
  VEC4: { components: 4, columns: 0 },
  MAT2: { components: 4, columns: 2 },
  MAT3: { components: 9, columns: 3 },
  MAT4: { components: 16, columns: 4 },
};

/** Largest accessor (elements): bounds what a hostile count can make the loader allocate. */
export const MAX_ACCESSOR_COUNT = 1 << 20;
/** Most bytes all accessors together may describe (what GLTFLoader allocates at most, zero-filled ones included). */
export const MAX_ACCESSOR_BYTES = 128e6;

/**
 * Bytes of one element of `type` with components of `bytes` each: matrix columns start on 4-byte
 * boundaries (§3.6.2.4 "Data Alignment"), so a MAT2 of bytes is 8 bytes and a MAT3 of shorts 24.
 */
function elementBytes(type: { components: number; columns: number }, bytes: number): number {
  if (type.columns === 0) return type.components * bytes;
  const rows = type.components / type.columns;
  return type.columns * Math.ceil((rows * bytes) / 4) * 4;
}

const whole = (v: unknown): v is number => typeof v === 'number' && Number.isInteger(v);

/**
 * Every accessor of a packed glTF checked against its buffer view before anything reads it, the
 * one place both import paths (the app's and the CLI's, through packGltf) go through (issue 32: a
 * negative byteOffset reached a DataView read). `views` are already relocated into the packed
 * binary of `binaryLength` bytes (each view's range checked there). Checked: componentType, type,
 * count (1 … MAX_ACCESSOR_COUNT), byteOffset (whole, ≥ 0, aligned to its component), the view's
 * byteStride (4 … 252, a multiple of 4, at least one element, §3.6.2.4), the last element inside
 * the view, and sparse indices and values likewise, their index values below the accessor's count.
 * A message names the accessor or view and the numbers.
 */
export function checkGltfAccessors(json: Json, binary: Uint8Array, fail: (problem: string) => never): void {
  const accessors = Array.isArray(json.accessors) ? (json.accessors as unknown[]) : [];
  const views = Array.isArray(json.bufferViews) ? (json.bufferViews as Json[]) : [];
  let total = 0;
  /** Check `count` elements of `size` bytes from `offset` in view `k` (`where` names the reader); returns the view's stride. */
  const inView = (k: unknown, offset: unknown, count: number, size: number, align: number, where: string, strided: boolean): void => {
    if (!whole(k) || k < 0 || k >= views.length) fail(`${where}.bufferView ${excerpt(k ?? null)} is not a buffer view of this file`);
    const view = views[k as number];
    const at = offset ?? 0;
    if (!whole(at) || at < 0) fail(`${where}.byteOffset ${excerpt(at)} must be a whole number of bytes, at least 0`);
    if ((at as number) % align !== 0) fail(`${where}.byteOffset ${at} is not a multiple of its component size ${align}`);
    const stride = view.byteStride;
    let step = size;
    if (stride !== undefined && strided) {
      if (!whole(stride) || stride < 4 || stride > 252 || stride % 4 !== 0) fail(`bufferViews[${k}].byteStride ${excerpt(stride)} must be a multiple of 4 from 4 to 252`);
      if ((stride as number) < size) fail(`bufferViews[${k}].byteStride ${stride} is shorter than one element of ${where} (${size} bytes)`);
      step = stride as number;
    }
    const length = view.byteLength as number;
    const end = (at as number) + (count - 1) * step + size;
    if (end > length) {
      fail(`${where}: ${formatCount(count)} elements of ${size} bytes${step !== size ? ` every ${step}` : ''} from byte ${at} need ${formatCount(end)} bytes, bufferViews[${k}] has ${formatCount(length)}`);
    }
  };
  accessors.forEach((raw, i) => {
    const where = `accessors[${i}]`;
    if (typeof raw !== 'object' || raw === null || Array.isArray(raw)) fail(`${where} must be an object`);
    const a = raw as Json;
    const bytes = COMPONENT_BYTES[a.componentType as number];
    if (!whole(a.componentType) || bytes === undefined) fail(`${where}.componentType ${excerpt(a.componentType ?? null)} is not a glTF component type`);
    const type = typeof a.type === 'string' && Object.hasOwn(TYPES, a.type) ? TYPES[a.type] : undefined;
    if (!type) fail(`${where}.type ${excerpt(a.type ?? null)} is not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4`);
    const count = a.count;
    if (!whole(count) || count < 1 || count > MAX_ACCESSOR_COUNT) fail(`${where}.count ${excerpt(count ?? null)} is not a whole number from 1 to ${formatCount(MAX_ACCESSOR_COUNT)}`);
    const size = elementBytes(type!, bytes);
    total += (count as number) * size;
    if (total > MAX_ACCESSOR_BYTES) fail(`the accessors describe more than ${MAX_ACCESSOR_BYTES / 1e6} MB of data (${where} reaches ${(total / 1e6).toFixed(0)} MB)`);
    if (a.bufferView !== undefined) inView(a.bufferView, a.byteOffset, count as number, size, bytes, where, true);
    else if (a.byteOffset !== undefined && a.byteOffset !== 0) fail(`${where} has a byteOffset (${excerpt(a.byteOffset)}) but no bufferView`);
    if (a.sparse === undefined) return;
    const sparse = a.sparse as Json;
    if (typeof sparse !== 'object' || sparse === null || Array.isArray(sparse)) fail(`${where}.sparse must be an object`);
    const n = sparse.count;
    if (!whole(n) || n < 1 || n > (count as number)) fail(`${where}.sparse.count ${excerpt(n ?? null)} is not a whole number from 1 to the accessor's count ${formatCount(count as number)}`);
    const indices = sparse.indices as Json | undefined;
    const values = sparse.values as Json | undefined;
    if (typeof indices !== 'object' || indices === null || typeof values !== 'object' || values === null) fail(`${where}.sparse needs indices and values`);
    const indexBytes = { 5121: 1, 5123: 2, 5125: 4 }[indices!.componentType as number];
    if (indexBytes === undefined) fail(`${where}.sparse.indices.componentType ${excerpt(indices!.componentType ?? null)} must be 5121, 5123 or 5125 (unsigned)`);
    // Sparse data is tightly packed (§3.6.2.3): a view's stride does not apply.
    inView(indices!.bufferView, indices!.byteOffset, n as number, indexBytes!, indexBytes!, `${where}.sparse.indices`, false);
    inView(values!.bufferView, values!.byteOffset, n as number, size, bytes, `${where}.sparse.values`, false);
    // The index values themselves: every one must name an element of the accessor.
    const view = views[indices!.bufferView as number];
    const data = new DataView(binary.buffer, binary.byteOffset, binary.byteLength);
    const base = (view.byteOffset as number) + ((indices!.byteOffset as number | undefined) ?? 0);
    for (let s = 0; s < (n as number); s++) {
      const at = base + s * indexBytes!;
      const index = indexBytes === 1 ? data.getUint8(at) : indexBytes === 2 ? data.getUint16(at, true) : data.getUint32(at, true);
      if (index >= (count as number)) fail(`${where}.sparse.indices[${s}] = ${index} is past the accessor's ${formatCount(count as number)} elements`);
    }
  });
}

/**
 * Every primitive's index values against its POSITION count, read once per (indices, POSITION)
 * pair after checkGltfAccessors has bounded them, so a message can name the primitive and both
 * accessors (collectTriangles checks again as it reads, for any path that skips this). Index
 * accessors must be unsigned SCALARs (§3.7.2.1); sparse or view-less ones are left to that check.
 */
export function checkPrimitiveIndices(json: Json, binary: Uint8Array, fail: (problem: string) => never): void {
  const accessors = Array.isArray(json.accessors) ? (json.accessors as Json[]) : [];
  const views = Array.isArray(json.bufferViews) ? (json.bufferViews as Json[]) : [];
  const meshes = Array.isArray(json.meshes) ? (json.meshes as unknown[]) : [];
  const data = new DataView(binary.buffer, binary.byteOffset, binary.byteLength);
  const checked = new Set<string>();
  meshes.forEach((mesh, m) => {
    const primitives = typeof mesh === 'object' && mesh !== null && Array.isArray((mesh as Json).primitives) ? ((mesh as Json).primitives as unknown[]) : [];
    primitives.forEach((primitive, p) => {
      if (typeof primitive !== 'object' || primitive === null) return;
      const { indices: k, attributes } = primitive as Json;
      const position = typeof attributes === 'object' && attributes !== null ? (attributes as Json).POSITION : undefined;
      if (!whole(k) || !whole(position) || !accessors[k] || !accessors[position]) return;
      const key = `${k}/${position}`;
      if (checked.has(key)) return;
      checked.add(key);
      const a = accessors[k];
      const bytes = { 5121: 1, 5123: 2, 5125: 4 }[a.componentType as number];
      if (bytes === undefined || a.type !== 'SCALAR') fail(`meshes[${m}].primitives[${p}]: indices accessors[${k}] must be unsigned SCALARs (componentType 5121, 5123 or 5125)`);
      if (a.bufferView === undefined || a.sparse !== undefined) return;
      const vertices = accessors[position].count as number;
      const view = views[a.bufferView as number];
      const stride = typeof view.byteStride === 'number' ? view.byteStride : bytes!;
      const base = (view.byteOffset as number) + ((a.byteOffset as number | undefined) ?? 0);
      for (let i = 0; i < (a.count as number); i++) {
        const at = base + i * stride;
        const value = bytes === 1 ? data.getUint8(at) : bytes === 2 ? data.getUint16(at, true) : data.getUint32(at, true);
        if (value >= vertices) fail(`meshes[${m}].primitives[${p}]: indices accessors[${k}][${i}] = ${value}, but POSITION accessors[${position}] has ${formatCount(vertices)} vertices`);
      }
    });
  });
}
