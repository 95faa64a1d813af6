import type { Json, GltfJson } from './gltfJson';

/**
 * POSITION accessors must carry min and max (glTF 2.0 §3.7.2.1); GLTFLoader warns on the console
 * when they are missing, which would break the CLI's promise of an empty stderr. Fill them in for
 * plain float positions (what exporters write when they omit them); anything else stays as it is.
 */
export function fillPositionBounds(json: GltfJson, binary: Uint8Array): void {
  const accessors = (json.accessors ?? []) as Json[];
  const views = (json.bufferViews ?? []) as Json[];
  const data = new DataView(binary.buffer, binary.byteOffset, binary.byteLength);
  const positionAccessors = new Set<number>();
  for (const mesh of (json.meshes ?? []) as Json[]) {
    for (const p of (Array.isArray(mesh?.primitives) ? mesh.primitives : []) as Json[]) {
      const k = (p?.attributes as Json | undefined)?.POSITION;
      if (typeof k === 'number') positionAccessors.add(k);
    }
  }
  for (const k of positionAccessors) {
    const a = accessors[k];
    if (!a || (Array.isArray(a.min) && Array.isArray(a.max)) || a.componentType !== 5126 || a.type !== 'VEC3' || a.sparse !== undefined) continue;
    const view = typeof a.bufferView === 'number' ? views[a.bufferView] : undefined;
    if (!view) continue;
    const start = (view.byteOffset as number) + (typeof a.byteOffset === 'number' ? a.byteOffset : 0);
    const stride = typeof view.byteStride === 'number' ? view.byteStride : 12;
    const count = a.count as number;
    const end = (view.byteOffset as number) + (view.byteLength as number);
    if (count === 0 || start + (count - 1) * stride + 12 > end) continue;
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < count; i++) {
      for (let c = 0; c < 3; c++) {
        const v = data.getFloat32(start + i * stride + 4 * c, true);
        min[c] = Math.min(min[c], v);
        max[c] = Math.max(max[c], v);
      }
    }
    if (min.every(Number.isFinite) && max.every(Number.isFinite)) {
      a.min = min;
      a.max = max;
    }
  }
}
