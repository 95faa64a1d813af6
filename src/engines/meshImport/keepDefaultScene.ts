import type { Json, GltfJson } from './gltfJson';

/**
 * Only the default scene (`scene`, else the first) as the file's one scene: GLTFLoader builds every
 * scene (issue 32: a GLB declaring 285 714 scenes took 30 s), luxbox imports one. Cameras are
 * dropped too (a camera carries no surface; GLTFLoader would build each).
 */
export function keepDefaultScene(json: GltfJson): void {
  const scenes = json.scenes as unknown[];
  json.scenes = [scenes[(json.scene as number | undefined) ?? 0]];
  json.scene = 0;
  delete json.cameras;
  for (const node of (Array.isArray(json.nodes) ? json.nodes : []) as unknown[]) if (typeof node === 'object' && node !== null) delete (node as Json).camera;
}
