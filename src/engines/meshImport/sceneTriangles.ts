import { excerpt } from '../../core/untrustedJson';
import { formatCount, MAX_IMPORT_TRIANGLES } from './triangleBudget';
import type { Json, GltfJson } from './gltfJson';
import { list, objectAt } from './gltfJson';

/**
 * Triangles of the default scene, from the JSON (glTF 2.0 §3.7.2.1: mode 4 triangles, 5 strip,
 * 6 fan; points and lines have none), each node's mesh counted once per use; the node graph
 * must be a forest (§3.5.3), which also rules out cycles before GLTFLoader walks it.
 */
export function sceneTriangles(json: GltfJson, fail: (p: string) => never): number {
  const scenes = list(json, 'scenes', fail);
  if (scenes.length === 0) fail('no scene');
  const sceneIndex = json.scene ?? 0;
  if (typeof sceneIndex !== 'number' || !Number.isInteger(sceneIndex) || sceneIndex < 0 || sceneIndex >= scenes.length) fail(`scene ${excerpt(sceneIndex)} is not one of the file's scenes`);
  const nodes = list(json, 'nodes', fail);
  const meshes = list(json, 'meshes', fail);
  const accessors = list(json, 'accessors', fail);
  const countOf = (k: unknown): number => {
    if (typeof k !== 'number' || !Number.isInteger(k) || k < 0 || k >= accessors.length) fail(`a primitive refers to accessor ${excerpt(k ?? null)}, which does not exist`);
    return (accessors[k as number] as Json).count as number;
  };
  const meshTriangles = (m: unknown): number => {
    if (typeof m !== 'number' || !Number.isInteger(m) || m < 0 || m >= meshes.length) fail(`a node refers to mesh ${excerpt(m)}, which does not exist`);
    const mesh = objectAt(meshes, m as number, 'meshes', fail);
    let n = 0;
    for (const [pi, primitive] of list(mesh, 'primitives', fail, `meshes[${m}].primitives`).entries()) {
      if (typeof primitive !== 'object' || primitive === null) fail(`meshes[${m}].primitives[${pi}] must be an object`);
      const p = primitive as Json;
      const attributes = p.attributes as Json | undefined;
      if (typeof attributes !== 'object' || attributes === null || attributes.POSITION === undefined) fail(`meshes[${m}].primitives[${pi}] has no POSITION attribute`);
      const vertices = p.indices !== undefined ? countOf(p.indices) : countOf(attributes!.POSITION);
      const mode = p.mode ?? 4;
      if (mode === 4) n += Math.floor(vertices / 3);
      else if (mode === 5 || mode === 6) n += Math.max(0, vertices - 2);
    }
    return n;
  };
  const seen = new Set<number>();
  let triangles = 0;
  const stack = list(objectAt(scenes, sceneIndex as number, 'scenes', fail), 'nodes', fail, `scenes[${sceneIndex}].nodes`).slice();
  while (stack.length > 0) {
    const k = stack.pop();
    if (typeof k !== 'number' || !Number.isInteger(k) || k < 0 || k >= nodes.length) fail(`the scene refers to node ${excerpt(k ?? null)}, which does not exist`);
    if (seen.has(k as number)) fail(`nodes[${k}] appears twice in the node hierarchy (it must be a tree)`);
    seen.add(k as number);
    const node = objectAt(nodes, k as number, 'nodes', fail);
    const instancing = (node.extensions as Json | undefined)?.EXT_mesh_gpu_instancing as Json | undefined;
    const instanceAccessor = (instancing?.attributes as Json | undefined)?.TRANSLATION ?? (instancing?.attributes as Json | undefined)?.ROTATION ?? (instancing?.attributes as Json | undefined)?.SCALE;
    const copies = instanceAccessor !== undefined ? countOf(instanceAccessor) : 1;
    // Instances of a mesh without triangles add none, but GLTFLoader still builds a matrix for each.
    if (copies > MAX_IMPORT_TRIANGLES) fail(`nodes[${k}] has ${formatCount(copies)} instances; at most ${formatCount(MAX_IMPORT_TRIANGLES)}`);
    if (node.mesh !== undefined) triangles += meshTriangles(node.mesh) * copies;
    for (const child of list(node, 'children', fail, `nodes[${k}].children`)) stack.push(child);
  }
  return triangles;
}
