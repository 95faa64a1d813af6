// Public API of the photometry module: parsing IES LM-63 / EULUMDAT into one
// expanded type-C model, lookups, flux, beam figures and colour helpers.
export type { Photometry, TiltTable } from './types';
export { PhotometryParseError } from './PhotometryParseError';
export { photometryWarnings } from './checks';
export { MAX_PHOTOMETRY_BYTES } from './limits';
export { parsePhotometry, type ParsePhotometryOptions } from './parsePhotometry';
export { parseIes } from './parseIes';
export { parseLdt } from './parseLdt';
export { intensity } from './intensity';
export { integrateFlux } from './flux';
export { tiltFactorAt, tiltMultiplier } from './tilt';
export { beamAndField, peakIntensity, type BeamField } from './beam';
export { cctToLinearRgb, planckianXyz, ColorTemperatureError, CCT_MIN_K, CCT_MAX_K } from './cct';
export { PhotometryReadError } from './PhotometryReadError';
export { createPhotometryLoader } from './createPhotometryLoader';
