import { formatCount } from './triangleBudget';

/**
 * Most entries of each top-level glTF array (issue 32: files with 20 000-entry arrays or thousands
 * of nodes took over 2 s in GLTFLoader, one declaring 285 714 scenes 30 s). Furniture exported
 * from Blender or SketchUp has tens of nodes and meshes and a few materials; a whole kitchen a few
 * hundred. Only the default scene is built (packGltf keeps it alone), so `scenes` only bounds the
 * JSON walk. Documented in docs/scene-format.md, "Importing meshes".
 */
export const GLTF_COUNT_CAPS = {
  scenes: 64,
  nodes: 4096,
  meshes: 1024,
  materials: 1024,
  accessors: 8192,
  bufferViews: 8192,
  buffers: 64,
  cameras: 256,
  skins: 256,
} as const;

/** Most primitives one mesh may have (each becomes a three.js mesh and a material group). */
export const MAX_GLTF_PRIMITIVES = 1024;

/** Refuse an array above its cap, naming it and both numbers. */
export function checkGltfCounts(json: Record<string, unknown>, fail: (problem: string) => never): void {
  for (const [key, cap] of Object.entries(GLTF_COUNT_CAPS)) {
    const value = json[key];
    if (Array.isArray(value) && value.length > cap) fail(`${formatCount(value.length)} ${key}; at most ${formatCount(cap)} are read`);
  }
  const meshes = Array.isArray(json.meshes) ? json.meshes : [];
  meshes.forEach((m: unknown, i) => {
    const primitives = typeof m === 'object' && m !== null ? (m as Record<string, unknown>).primitives : undefined;
    if (Array.isArray(primitives) && primitives.length > MAX_GLTF_PRIMITIVES) fail(`meshes[${i}] has ${formatCount(primitives.length)} primitives; at most ${formatCount(MAX_GLTF_PRIMITIVES)} are read`);
  });
}
