import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { parsePhotometry } from '../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../src/core/photometry/types';

/** An isotropic point source of the given flux (I = Φ/4π), as a Photometry literal. */
export function isotropic(lumens: number): Photometry {
  const I = lumens / (4 * Math.PI);
  return {
    format: 'IES',
    version: 'LM-63-2002',
    manufacturer: 'test',
    luminaire: 'isotropic',
    catalogNumber: '',
    keywords: {},
    photometricType: 'C',
    symmetry: 'rotational',
    verticalAngles: [0, 180],
    horizontalAngles: [0],
    candela: [[I, I]],
    statedLumens: lumens,
    absolute: false,
    inputWatts: null,
    luminousOpening: { width: 0, length: 0, height: 0, shape: 'point' },
    warnings: [],
  };
}

/** A real file from public/ies, parsed by src/core/photometry. */
export function realPhotometry(fileName: string): Photometry {
  const path = fileURLToPath(new URL(`../../public/ies/${fileName}`, import.meta.url));
  return parsePhotometry(readFileSync(path), fileName);
}
