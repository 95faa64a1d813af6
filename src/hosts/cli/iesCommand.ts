import { basename, dirname, join } from 'node:path';
import { InputError } from '../../core/inputError';
import { beamAndField, integrateFlux, MAX_PHOTOMETRY_BYTES, parsePhotometry, peakIntensity, photometryWarnings, PhotometryParseError, type Photometry } from '../../core/photometry';
import { readRegularFile, realFolders } from '../node/readRegularFile';

/** A command-line usage problem (missing file argument, unknown option, unreadable file). */
export class IesCommandError extends InputError {
  override name = 'IesCommandError';
}

const USAGE = 'usage: luxbox ies info <file.ies|file.ldt> [--json]';

/** `luxbox ies info <file> [--json]`: describes a photometric file. */
export async function run(args: string[]): Promise<number> {
  const [sub, ...rest] = args;
  if (sub !== 'info') throw new IesCommandError(sub ? `unknown subcommand "${sub}"; ${USAGE}` : USAGE);
  const json = rest.includes('--json');
  const unknown = rest.filter((a) => a.startsWith('-') && a !== '--json');
  if (unknown.length) throw new IesCommandError(`unknown option ${unknown[0]}; ${USAGE}`);
  const files = rest.filter((a) => !a.startsWith('-'));
  if (files.length !== 1) throw new IesCommandError(USAGE);
  const info = describe(files[0]);
  process.stdout.write(json ? JSON.stringify(info, null, 2) + '\n' : toText(info));
  return 0;
}

export interface IesInfo {
  file: string;
  format: Photometry['format'];
  version: string;
  manufacturer: string;
  luminaire: string;
  catalogNumber: string;
  photometricType: Photometry['photometricType'];
  symmetry: Photometry['symmetry'];
  angles: {
    file: { vertical: number; horizontal: number; verticalRange: [number, number]; horizontalRange: [number, number] } | null;
    expanded: { vertical: number; horizontal: number };
  };
  absolute: boolean;
  statedLumens: number | null;
  statedLumensSource: string | null;
  integratedLumens: number;
  lumensRatio: number | null;
  peak: { candela: number; gamma: number; c: number };
  beam: { c0: number; c90: number };
  field: { c0: number; c90: number };
  inputWatts: number | null;
  luminousOpening: Photometry['luminousOpening'];
  warnings: string[];
}

function readFile(path: string): Uint8Array {
  try {
    // A regular file only, its size checked while reading (a device reports size 0; issue 32).
    return readRegularFile(path, { maxBytes: MAX_PHOTOMETRY_BYTES });
  } catch (error) {
    if (!(error instanceof InputError)) throw error;
    if (error.message.startsWith('file is too large')) {
      throw new PhotometryParseError(basename(path), null, `${error.message.replace(/^file is too large/, 'the file is too large')}: over the ${MAX_PHOTOMETRY_BYTES / 1048576} MB limit for photometric files`);
    }
    throw new IesCommandError(error.message === 'no such file' ? `${path}: no such file` : `${path}: cannot read (${error.message})`);
  }
}

export function describe(path: string): IesInfo {
  const ph = parsePhotometry(readFile(path), basename(path), {
    // TILT=<file> names a file next to the photometric file.
    resolveTilt: (name) => {
      try {
        // Only next to the photometric file, and only a regular file (docs/scene-format.md, "Which files a scene may name").
        return new TextDecoder('latin1').decode(readRegularFile(join(dirname(path), name), { maxBytes: MAX_PHOTOMETRY_BYTES, within: realFolders([dirname(path)]) }));
      } catch {
        return undefined;
      }
    },
  });
  const flux = integrateFlux(ph);
  const bf = beamAndField(ph);
  const r2 = (x: number): number => Math.round(x * 100) / 100;
  return {
    file: path,
    format: ph.format,
    version: ph.version,
    manufacturer: ph.manufacturer,
    luminaire: ph.luminaire,
    catalogNumber: ph.catalogNumber,
    photometricType: ph.photometricType,
    symmetry: ph.symmetry,
    angles: {
      file: ph.fileGrid
        ? {
            vertical: ph.fileGrid.verticalCount,
            horizontal: ph.fileGrid.horizontalCount,
            verticalRange: ph.fileGrid.verticalRange,
            horizontalRange: ph.fileGrid.horizontalRange,
          }
        : null,
      expanded: { vertical: ph.verticalAngles.length, horizontal: ph.horizontalAngles.length },
    },
    absolute: ph.absolute,
    statedLumens: ph.statedLumens,
    statedLumensSource: ph.statedLumensSource ?? null,
    integratedLumens: r2(flux),
    lumensRatio: ph.statedLumens ? Math.round((flux / ph.statedLumens) * 10000) / 10000 : null,
    peak: peakIntensity(ph),
    beam: { c0: r2(bf.c0.beam), c90: r2(bf.c90.beam) },
    field: { c0: r2(bf.c0.field), c90: r2(bf.c90.field) },
    inputWatts: ph.inputWatts,
    luminousOpening: ph.luminousOpening,
    // Non-fatal findings (360° ≠ 0° plane, stated vs integrated lumens, sorted angles, …).
    warnings: photometryWarnings(ph),
  };
}

function toText(i: IesInfo): string {
  const f = i.angles.file;
  const o = i.luminousOpening;
  const m = (x: number): string => `${Math.round(x * 1000) / 1000} m`;
  const lines = [
    `file:              ${i.file}`,
    `format:            ${i.format} ${i.version}`,
    `manufacturer:      ${i.manufacturer || '—'}`,
    `luminaire:         ${i.luminaire || '—'}`,
    `catalog number:    ${i.catalogNumber || '—'}`,
    `photometric type:  ${i.photometricType}${i.photometricType !== 'C' ? ' (converted to type C)' : ''}`,
    `symmetry:          ${i.symmetry}`,
    `angles in file:    ${f ? `${f.vertical} vertical (${f.verticalRange.join('..')}°) × ${f.horizontal} horizontal (${f.horizontalRange.join('..')}°)` : '—'}`,
    `angles expanded:   ${i.angles.expanded.vertical} vertical × ${i.angles.expanded.horizontal} horizontal`,
    `photometry:        ${i.absolute ? 'absolute' : 'relative'}`,
    `stated lumens:     ${i.statedLumens === null ? '—' : `${Math.round(i.statedLumens * 10) / 10} lm (${i.statedLumensSource})`}`,
    `integrated lumens: ${i.integratedLumens} lm${i.lumensRatio === null ? '' : ` (ratio to stated ${i.lumensRatio})`}`,
    `peak:              ${Math.round(i.peak.candela * 10) / 10} cd at γ ${i.peak.gamma}°, C ${i.peak.c}°`,
    `beam (50 %):       C0 ${i.beam.c0}°, C90 ${i.beam.c90}°`,
    `field (10 %):      C0 ${i.field.c0}°, C90 ${i.field.c90}°`,
    `input watts:       ${i.inputWatts === null ? '—' : `${i.inputWatts} W`}`,
    `luminous opening:  ${o.shape}${o.shape === 'point' ? '' : `, ${m(o.width)} along C0–C180 × ${m(o.length)} along C90–C270 × height ${m(o.height)}`}`,
    `warnings:          ${i.warnings.length ? i.warnings.join('\n                   ') : 'none'}`,
  ];
  return lines.join('\n') + '\n';
}
