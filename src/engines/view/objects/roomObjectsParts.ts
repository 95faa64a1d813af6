import * as THREE from 'three';
import { objectFinishRgb } from '../../../core/model/objects/furniture/objectFinishes';
import type { PreparedObjects } from '../../bake/objects/preparedObjects';
import { uploadModulation } from '../createFinishTextures';
import { dilateReflectance } from '../dilateReflectance';
import { finishModulation } from '../finishTexture';
import type { ObjectLight } from '../objectLight';
import { objectRenderGeometry, type ObjectRenderGeometry } from '../objectRenderGeometry';
import { ROOM_OBJECT_PREFIX } from '../../bake/shapedRoom/roomSurfaceObjects';
import { clearEdges, clearObjects, type ObjectsState } from './roomObjectsState';

/** Name of the objects' three.js mesh (tests and picking find it by name). */
export const OBJECTS_MESH_NAME = 'objects';

/** A shaped room's surfaces come first among the objects (encloseShapedRoom): how many ids lead with the room's prefix. */
function roomSurfaceCount(ids: readonly string[]): number {
  const k = ids.findIndex((id) => !id.startsWith(ROOM_OBJECT_PREFIX));
  return k < 0 ? ids.length : k;
}

/** The textured finishes' slots of the shader: their patterns (made on first use, once a mesh shows) or off. */
export function applySlots(s: ObjectsState): void {
  const u = s.material.uniforms;
  if (s.texturesOn && s.mesh && !s.slots) {
    const anisotropy = Math.min(8, s.renderer.capabilities.getMaxAnisotropy());
    s.slots = s.slotFinishes.map(([id, kind]) => uploadModulation(finishModulation(kind, objectFinishRgb(id), 1), anisotropy));
  }
  s.slotFinishes.forEach(([id], i) => {
    const t = s.texturesOn && s.slots ? s.slots[i] : null;
    u[`uSlot${i}`].value = t?.texture ?? null;
    (u.uSlotRho.value as THREE.Vector3[])[i].set(...objectFinishRgb(id));
    (u.uSlotGain.value as THREE.Vector3[])[i].set(...(t?.gain ?? [1, 1, 1]));
    (u.uSlotPeriod.value as number[])[i] = t?.period ?? 1;
    (u.uSlotOn.value as number[])[i] = t ? 1 : 0;
  });
}

/** The selected object's feature edges (creases over 20°), drawn with the depth test (hidden edges stay hidden; the surfaces' polygon offset keeps the visible ones from z-fighting). */
export function showSelection(s: ObjectsState): void {
  clearEdges(s);
  const geometry = s.geometry;
  const index = geometry && s.selectedId !== null ? geometry.ids.indexOf(s.selectedId) : -1;
  s.selected.value = index;
  if (!geometry || index < 0) return;
  const picked: number[] = [];
  for (let k = 0; k < geometry.triangleCount; k++) {
    if (geometry.objectOfTriangle[k] === index) for (let c = 0; c < 9; c++) picked.push(geometry.positions[9 * k + c]);
  }
  const solid = new THREE.BufferGeometry();
  solid.setAttribute('position', new THREE.Float32BufferAttribute(picked, 3));
  const edges = new THREE.LineSegments(new THREE.EdgesGeometry(solid, 20), s.edgeMaterial);
  solid.dispose();
  edges.name = 'objects-selection';
  edges.visible = s.mesh?.visible ?? false;
  edges.renderOrder = 1;
  s.edges = edges;
  s.group.add(edges);
}

/** The mesh of the objects' render geometry, with each vertex's object index for the selection tint. */
function objectsMesh(s: ObjectsState, geometry: ObjectRenderGeometry): THREE.Mesh {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(geometry.positions, 3));
  g.setAttribute('normal', new THREE.BufferAttribute(geometry.normals, 3));
  g.setAttribute('uv', new THREE.BufferAttribute(geometry.uvs, 2));
  const index = new Float32Array(geometry.triangleCount * 3);
  for (let k = 0; k < geometry.triangleCount; k++) index.fill(geometry.objectOfTriangle[k], 3 * k, 3 * k + 3);
  g.setAttribute('objectIndex', new THREE.BufferAttribute(index, 1));
  g.computeBoundingSphere();
  g.computeBoundingBox();
  const mesh = new THREE.Mesh(g, s.material);
  mesh.name = OBJECTS_MESH_NAME;
  mesh.visible = false;
  return mesh;
}

/** The atlas's reflectance as a nearest-filtered float texture (dilated past the charts' edges). */
function reflectanceTexture(atlas: PreparedObjects['atlas']): THREE.DataTexture {
  const reflectance = new THREE.DataTexture(dilateReflectance(atlas), atlas.width, atlas.height, THREE.RGBAFormat, THREE.FloatType);
  reflectance.minFilter = reflectance.magFilter = THREE.NearestFilter;
  reflectance.generateMipmaps = false;
  reflectance.needsUpdate = true;
  return reflectance;
}

/** New objects: their mesh (hidden until their light arrives) and reflectance; the same ones again change nothing. */
export function setObjectsGeometry(s: ObjectsState, next: PreparedObjects | null): void {
  if (next === s.prepared) return;
  clearObjects(s);
  if (!next || next.triangleCount === 0) return;
  s.prepared = next;
  const geometry = (s.geometry = objectRenderGeometry(next));
  s.frontOnlyBelow.value = roomSurfaceCount(geometry.ids);
  s.mesh = objectsMesh(s, geometry);
  s.group.add(s.mesh);
  s.reflectance = reflectanceTexture(next.atlas);
  s.material.uniforms.uReflectance.value = s.reflectance;
  applySlots(s);
  showSelection(s);
}

/** The illuminance texture of this atlas size, made once (RGBA float: three has no RGB float format; alpha unused). */
function illuminanceTexture(s: ObjectsState, width: number, height: number): THREE.DataTexture {
  if (!s.illuminance) {
    const t = new THREE.DataTexture(new Float32Array(width * height * 4), width, height, THREE.RGBAFormat, THREE.FloatType);
    t.minFilter = t.magFilter = s.linear ? THREE.LinearFilter : THREE.NearestFilter;
    t.wrapS = t.wrapT = THREE.ClampToEdgeWrapping;
    t.generateMipmaps = false;
    s.illuminance = t;
  }
  return s.illuminance;
}

/** The objects' relit light shown, or the objects hidden when it is none or of another atlas. */
export function setObjectsLight(s: ObjectsState, light: ObjectLight | null): void {
  if (!s.mesh || !s.prepared) return;
  const { width, height } = s.prepared.atlas;
  if (!light || light.atlas.width !== width || light.atlas.height !== height || light.atlas.texelSize !== s.prepared.atlas.texelSize) {
    // No light yet, or light of the objects before a move (another atlas): hidden until the new bake's first maps.
    s.mesh.visible = false;
    if (s.edges) s.edges.visible = false;
    return;
  }
  const n = width * height;
  const illuminance = illuminanceTexture(s, width, height);
  s.material.uniforms.uIlluminance.value = illuminance;
  const dst = illuminance.image.data as Float32Array;
  const src = light.total;
  for (let i = 0; i < n; i++) {
    dst[i * 4] = src[i * 3];
    dst[i * 4 + 1] = src[i * 3 + 1];
    dst[i * 4 + 2] = src[i * 3 + 2];
    dst[i * 4 + 3] = 1;
  }
  illuminance.needsUpdate = true;
  s.mesh.visible = true;
  if (s.edges) s.edges.visible = true;
}
