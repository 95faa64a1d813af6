import { positionBounds, type Bounds3, type TriangleMesh } from '../../core/mesh/triangleMesh';
import { checkTriangleBudget } from './triangleBudget';
import { checkExtent } from './checkExtent';
import { checkStorable } from './checkStorable';
import { keptName } from './keptName';
import { detectUnits, METRES_PER_UNIT, PLAUSIBLE_EXTENT_M, type MeshUnit, type MeshUnitsOption } from './meshUnits';

/** One file the user picked or the host read: its name (for messages and references) and bytes. */
export interface MeshFile {
  name: string;
  bytes: Uint8Array;
}

export interface MeshImportOptions {
  /** Length unit of the file; 'auto' (default) detects it from the size (meshUnits.ts). */
  units?: MeshUnitsOption;
  /**
   * Reads a file the model refers to that is not among the files given (an MTL library, a glTF
   * .bin buffer), by the name the model uses; throws when it cannot. Node: relative to the model's
   * folder. Absent: only the given files exist.
   */
  readFile?: (name: string) => Uint8Array | Promise<Uint8Array>;
}

export interface ImportedMesh {
  /** The model's file name (the .obj, .gltf or .glb). */
  name: string;
  /** In metres, y up (the chosen unit applied). */
  mesh: TriangleMesh;
  /** The unit applied. */
  units: MeshUnit;
  /** What 'auto' picks for this file (glTF: always 'm'), so the UI can show it and offer to override. */
  detectedUnits: MeshUnit;
  triangleCount: number;
  /** Bounds of `mesh`, metres. */
  bounds: Bounds3;
  /** Problems that did not stop the import (missing MTL, textures ignored, clamped colours), one line each. */
  warnings: string[];
}

/**
 * The last step of every import: unit detection and scaling, the triangle budget, the bounds
 * (checkExtent), names cut to the file format's limits, the size in a saved file (checkStorable).
 * `fixedUnit` is the unit the format itself defines (glTF: metres), else null (OBJ).
 */
export function finishImport(name: string, fileMesh: TriangleMesh, fixedUnit: MeshUnit | null, options: MeshImportOptions, warnings: string[]): ImportedMesh {
  const triangleCount = fileMesh.indices.length / 3;
  checkTriangleBudget(name, triangleCount);
  const fileBounds = positionBounds(fileMesh.positions);
  const extent = Math.max(...fileBounds.max.map((hi, a) => hi - fileBounds.min[a]));
  const detected = fixedUnit ?? detectUnits(extent);
  const detectedUnits: MeshUnit = detected ?? 'm';
  const requested = options.units ?? 'auto';
  const units: MeshUnit = requested === 'auto' ? detectedUnits : requested;
  if (requested === 'auto' && detected === null) {
    warnings.push(`${name}: its largest extent (${round(extent)} file units) is not a plausible object size in m, cm, mm or inches (${PLAUSIBLE_EXTENT_M.min}–${PLAUSIBLE_EXTENT_M.max} m); metres assumed`);
  }
  const scale = METRES_PER_UNIT[units];
  const positions = scale === 1 ? fileMesh.positions : fileMesh.positions.map((x) => x * scale);
  // Extents in metres whatever the unit choice; names cut to what a saved configuration accepts.
  const bounds = positionBounds(positions);
  checkExtent(name, bounds, units, warnings, requested === 'auto' && detected === null);
  const materials = fileMesh.materials.map((m) => ({ ...m, name: keptName(m.name, `${name}: material`, warnings) }));
  const mesh: TriangleMesh = { ...fileMesh, positions, materials };
  const kept = keptName(name, 'the model name', warnings);
  checkStorable(kept, mesh);
  return { name: kept, mesh, units, detectedUnits, triangleCount, bounds, warnings };
}

function round(x: number): number {
  return Number(x.toPrecision(4));
}
