import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { num } from './radianceFrame';
import { WHITE_EFFICACY } from './brightdataFile';

/** The cameras the export writes view files for (luxbox's presets: docs/viewer.md). */
export const EXPORT_VIEWS = ['eye', 'top', 'corner'] as const;

/** The illuminance grids of the export: file stem, height above the floor (m), what it is. */
export const EXPORT_GRIDS = [
  { name: 'floor', height: 0.001, label: 'the floor (1 mm above it)' },
  { name: 'workplane', height: 0.75, label: 'a horizontal work plane 0.75 m above the floor' },
] as const;

/** Spacing of the illuminance grids of the export, metres. */
export const GRID_SPACING = 0.25;

/** Image size of `render.sh`'s pictures. */
export const IMAGE_SIZE = { width: 1024, height: 768 };

/**
 * rcalc expression: lux from `rtrace -I` RGB irradiance (W/m²), with Radiance's white efficacy
 * (179 lm/W) and luxbox's luminance weights (Rec. 709 Y, bakedMaps.ts), so the numbers are
 * those `luxbox probe` reports. Radiance's own tools use 0.265/0.670/0.065; for white light both
 * give the same lux.
 */
export const LUX_EXPRESSION = `$1=${WHITE_EFFICACY}*(${LUMINANCE_WEIGHTS.map((w, c) => `${num(w)}*$${c + 1}`).join('+')})`;

/**
 * Settings of the script. Illuminance grids: pure Monte Carlo (-aa 0: ambient caching with 16
 * bounces ran for many minutes on a small room), 16 bounces with the reflection limit above them
 * (Radiance's default -lr 10 cuts the interreflection series of a ρ = 0.8 box 11 % short: 371.5 lx
 * instead of 416.7 lx on CIE 171:2006 §5.8; with -lr 40, 416.6 lx), every source tested at every
 * bounce (-dt 0 -dc 1): the settings of the cross-check test, which agree with luxbox within
 * 3 % RMS. Images: the look, not the numbers, so a few cached bounces; back faces invisible
 * (-bv-): the room's surfaces face inward, so the top and corner cameras, outside the room, see
 * through the walls that face away from them, as luxbox's viewer culls them.
 */
export const RTRACE_SETTINGS = '-ab 16 -ad 512 -aa 0 -lr 20 -lw 1e-6 -dt 0 -dc 1';
export const RPICT_SETTINGS = '-ab 3 -ad 256 -as 128 -aa 0.15 -ar 32 -lr 8 -ps 4 -bv-';

export function renderScript(): string {
  const { width, height } = IMAGE_SIZE;
  return `#!/bin/sh
# Render this luxbox scene with Radiance (oconv, rpict, rtrace, rcalc on PATH).
# Written by \`luxbox export radiance\`; see README.md in this folder.
set -e
cd "$(dirname "$0")"
# Radiance's default search path starts with "."; a RAYPATH of your own gets "." in front, so
# the source.cal of this folder (Radiance's own definitions) is found either way.
if [ -n "\${RAYPATH:-}" ]; then RAYPATH=".:$RAYPATH"; export RAYPATH; fi

oconv scene.rad > scene.oct

# Illuminance grids (lux, one value per line, in the order of the .pts file).
${EXPORT_GRIDS.map((g) => `rtrace -h -I ${RTRACE_SETTINGS} scene.oct < points/${g.name}.pts | rcalc -e '${LUX_EXPRESSION}' > ${g.name}.lux`).join('\n')}

# Images (HDR, radiance in W/sr/m²; view with ximage or convert with pcond/ra_tiff).
for view in ${EXPORT_VIEWS.join(' ')}; do
  rpict -vf views/$view.vf -x ${width} -y ${height} ${RPICT_SETTINGS} scene.oct > $view.hdr
done
`;
}
