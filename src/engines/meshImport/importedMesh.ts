import { orientMesh, type OrientationSummary } from '../../core/mesh/orientMesh';
import { positionBounds, type Bounds3, type TriangleMesh } from '../../core/mesh/triangleMesh';
import type { CollectedTriangles } from './collectTriangles';
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
  /** Triangles the file has (what the budget counts); `mesh` also has `orientation.backTriangles` back sides, less `orientation.droppedCopies`. */
  triangleCount: number;
  /** What orienting the parts did (closed parts turned outward, open ones given a back side; docs/furniture.md). */
  orientation: OrientationSummary;
  /** Bounds of the file's geometry in metres (the fronts of two-sided surfaces lie up to BACK_SIDE_OFFSET, 0.5 mm, beyond). */
  bounds: Bounds3;
  /** Problems that did not stop the import (missing MTL, textures ignored, clamped colours), one line each. */
  warnings: string[];
}

/**
 * The last step of every import: unit detection and scaling, the triangle budget, the extents in
 * metres, names cut to what a saved configuration accepts, orientation (orientMesh: closed parts
 * outward, two-sided open parts with their back sides), the stored size, the bounds.
 * `fixedUnit` is the unit the format itself defines (glTF: metres), else null (OBJ).
 */
export function finishImport(name: string, collected: CollectedTriangles, fixedUnit: MeshUnit | null, options: MeshImportOptions, warnings: string[]): ImportedMesh {
  const fileMesh = collected.mesh;
  checkTriangleBudget(name, fileMesh.indices.length / 3);
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
  // After scaling: the two sides of a two-sided surface lie a fixed distance in metres apart.
  const { mesh, summary } = orientMesh({ ...fileMesh, positions, materials }, (t) => collected.twoSided[t] === 1);
  const kept = keptName(name, 'the model name', warnings);
  // What is stored is the oriented mesh, back sides included: that is what must fit a saved file.
  checkStorable(kept, mesh);
  // The budget counts the file's triangles; back sides add at most as many again.
  const triangleCount = fileMesh.indices.length / 3;
  return { name: kept, mesh, units, detectedUnits, triangleCount, orientation: summary, bounds, warnings };
}

function round(x: number): number {
  return Number(x.toPrecision(4));
}
