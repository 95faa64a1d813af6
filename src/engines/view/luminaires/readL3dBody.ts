import { readL3dStructure } from '../../../core/gldf/readL3dStructure';
import { readL3dEmittingFaces } from '../../meshImport/readL3dEmittingFaces';
import { readL3dMeshes } from '../../meshImport/readL3dMeshes';
import { l3dBody, type L3dBody } from './l3dBody';

/**
 * An L3D container (a catalog `model` file) read into the body the 3D view draws: structure.xml
 * and its OBJ parts through the upload checks and the triangle budget (readL3dStructure,
 * readL3dMeshes) with its light-emitting faces (readL3dEmittingFaces), then prepared for posing (l3dBody) with `emitter` (catalog `modelEmitter`) as the
 * photometry's light-emitting object. Throws, naming `source`, on a refused file.
 */
export function readL3dBody(bytes: Uint8Array, source: string, emitter?: string): L3dBody {
  const { luminaire, zip } = readL3dStructure(bytes, source);
  return l3dBody(luminaire, readL3dMeshes(luminaire, zip).parts, emitter, readL3dEmittingFaces(luminaire, zip));
}
