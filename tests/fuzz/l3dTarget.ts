/**
 * Fuzz target `l3d` (issue 31): L3D containers through readL3dStructure (zip reader,
 * structure.xml, every reference) and readL3dMeshes (each OBJ part through the OBJ importer, placed
 * down the part tree). Seed: the tests' hand-made track spot (tests/core/gldf/
 * buildL3d.ts). Most mutants change structure.xml inside a container that holds the OBJ parts
 * (l3dCodec); raw container bytes are mutated too. Accepted means every number in the tree is
 * finite, every part's geometry file is in the container, and every part's mesh has finite
 * positions and indices within them.
 */
import { unzipSync, zipSync } from 'fflate';
import { GldfError } from '../../src/core/gldf/GldfError';
import { readL3dStructure, type L3dGeometryNode } from '../../src/core/gldf/readL3dStructure';
import { readL3dMeshes, type L3dMeshes } from '../../src/engines/meshImport/readL3dMeshes';
import { readL3dEmittingFaces } from '../../src/engines/meshImport/readL3dEmittingFaces';
import { l3dBody, type L3dBody } from '../../src/engines/view/luminaires/l3dBody';
import { l3dLuminaireModel } from '../../src/engines/view/luminaires/l3dLuminaireModel';
import { l3dOpening } from '../../src/engines/view/luminaires/l3dOpening';
import { files, l3d } from '../core/gldf/buildL3d';
import { nonFinitePaths } from './checks';
import type { FuzzOutcome, FuzzSeed, FuzzTarget } from './fuzzTarget';

/** structure.xml out of a container and back into one with the seed's OBJ parts. */
export const l3dCodec = {
  decode(zip: Uint8Array): Uint8Array | null {
    try {
      return unzipSync(zip, { filter: (f) => f.name === 'structure.xml' })['structure.xml'] ?? null;
    } catch {
      return null;
    }
  },
  encode: (xml: Uint8Array): Uint8Array => zipSync({ ...files(), 'structure.xml': xml }),
};

export const l3dFuzzTarget: FuzzTarget = {
  name: 'l3d',
  seeds: (): FuzzSeed[] => [{ name: 'track-spot.l3d', bytes: l3d() }],
  run(input: Uint8Array): FuzzOutcome {
    let result: ReturnType<typeof readL3dStructure>;
    try {
      result = readL3dStructure(input, 'fuzz.l3d');
    } catch (error) {
      if (error instanceof GldfError) return { kind: 'refused', message: error.message };
      throw error;
    }
    const { luminaire, zip } = result;
    const problems = nonFinitePaths(luminaire.structure).map((p) => `non-finite ${p}`);
    const walk = (nodes: readonly L3dGeometryNode[]): void => {
      for (const n of nodes) {
        const file = luminaire.geometryFiles.get(n.geometryId);
        if (!file || !zip.has(file.path)) problems.push(`part ${n.partName}: geometry ${n.geometryId} not in the container`);
        for (const j of n.joints) walk(j.geometries);
      }
    };
    walk(luminaire.structure);
    let meshes: L3dMeshes;
    try {
      meshes = readL3dMeshes(luminaire, zip);
    } catch (error) {
      if (error instanceof GldfError) return { kind: 'refused', message: error.message };
      throw error;
    }
    for (const part of meshes.parts) {
      const { positions, indices } = part.mesh;
      if (!positions.every(Number.isFinite)) problems.push(`part ${part.partName}: non-finite vertex`);
      if (indices.some((i) => i >= positions.length / 3)) problems.push(`part ${part.partName}: index beyond its vertices`);
    }
    // The 3D view's body (l3dBody, with its light-emitting faces): prepared, its opening, then posed for an aim; every vertex and joint angle finite.
    let body: L3dBody;
    try {
      body = l3dBody(luminaire, meshes.parts, undefined, readL3dEmittingFaces(luminaire, zip));
    } catch (error) {
      if (error instanceof GldfError) return { kind: 'refused', message: error.message };
      throw error;
    }
    const opening = l3dOpening(body, 90);
    if (![opening.width, opening.length, opening.height].every((v) => Number.isFinite(v) && v >= 0)) problems.push('opening not finite');
    const { model, angles } = l3dLuminaireModel(body, { heading: 30, orientation: { yaw: 15, pitch: 40, roll: 0 }, mount: 0.3 });
    if (![...angles.values()].flat().every(Number.isFinite)) problems.push('non-finite joint angle');
    for (const p of model.parts) if (!p.positions.every(Number.isFinite) || !p.normals.every(Number.isFinite)) problems.push(`posed ${p.role}: non-finite vertex`);
    return { kind: 'accepted', problems };
  },
};
