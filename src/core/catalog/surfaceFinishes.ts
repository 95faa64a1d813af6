/**
 * The finishes the app offers for floor, ceiling and walls: the JSON next to
 * this file, validated at load (format: docs/catalog-format.md).
 */
import data from './surface-finishes.json';
import { parseSurfaceFinishes, type SurfaceFinish } from '../model/catalogSchema/surfaceFinish';

export const defaultSurfaceFinishes: readonly SurfaceFinish[] = parseSurfaceFinishes(data, 'src/core/catalog/surface-finishes.json');
