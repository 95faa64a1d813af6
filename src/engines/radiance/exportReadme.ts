import type { NearField } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';
import { EXPORT_GRIDS, GRID_SPACING, EXPORT_VIEWS, IMAGE_SIZE, LUX_EXPRESSION, RPICT_SETTINGS, RTRACE_SETTINGS } from './renderScript';
import { SOURCE_RADIUS } from './luminairesRad';

/** The README of an export folder: what is there, the frame, how to render, what the numbers mean. */
export function exportReadme(title: string, scene: BakeScene, nearField: NearField, emitting: number): string {
  const { width, height, depth } = scene.room;
  return `# ${title} — Radiance export

Written by \`luxbox export radiance\`. Room ${width} × ${depth} m, ${height} m high; ${scene.luminaires.length} luminaires (${emitting} emitting).

## Render

    sh render.sh

needs Radiance's \`oconv\`, \`rtrace\`, \`rcalc\` and \`rpict\` on the PATH (Radiance from
radiance-online.org, or the PyPI package \`pyradiance\`, whose binaries are in
\`<site-packages>/pyradiance/bin\`). It writes:

${EXPORT_GRIDS.map((g) => `- \`${g.name}.lux\`: illuminance in lux on ${g.label}, one value per line for the points of \`points/${g.name}.pts\` (a ${GRID_SPACING} m grid, cell centres, row by row along X);`).join('\n')}
- ${EXPORT_VIEWS.map((v) => `\`${v}.hdr\``).join(', ')}: ${IMAGE_SIZE.width} × ${IMAGE_SIZE.height} HDR images for the views in \`views/\` (luxbox's eye, top and corner cameras).

Settings: \`rtrace ${RTRACE_SETTINGS}\`, \`rpict ${RPICT_SETTINGS}\`; raise \`-ad\`/\`-as\` for less noise.
Lux = 179 lm/W × (0.2126 R + 0.7152 G + 0.0722 B) of the irradiance (\`rcalc -e '${LUX_EXPRESSION}'\`):
luxbox's luminance weights, so the numbers compare with \`luxbox probe\` directly.

## Frame and units

Radiance's frame is Z up: (X, Y, Z) = luxbox's (x, −z, y). Metres. The room spans
X ∈ [0, ${width}], Y ∈ [−${depth}, 0], Z ∈ [0, ${height}]; north (luxbox z = 0) is the wall at Y = 0.

## What is in the scene

- \`scene.rad\`: the room's six surfaces (\`plastic\`, no specular part: Lambertian with the
  scene's reflectances), then the objects (furniture, imported models: one polygon per triangle,
  \`plastic\` with each material's reflectance, or the object's where it overrides them, as luxbox
  bakes them), then every luminaire.
- Luminaires: near field **${nearField}** — ${nearField === 'split' ? 'each luminous opening larger than 5 cm is the same grid of point sources luxbox bakes with' : 'one point source per luminaire at its photometric centre'}.
  Each point source is a sphere of ${SOURCE_RADIUS * 1000} mm radius with \`light\` material; its \`brightdata\`
  modifier holds the luminaire's candela distribution (\`luminaires/*.dat\`, W/sr = cd / 179, in
  \`ies2rad\`'s layout, read with Radiance's \`source.cal\`: a copy of the definitions used is in
  this folder), turned by the luminaire's roll, pitch and yaw. The light's RGB is the colour ×
  dimming × TILT factor, divided among the sources of the luminaire. Luminaire housings are not
  modelled (luxbox's bake does not occlude with them either).
- \`source.cal\`: \`src_theta\`, \`src_phi\` and \`corr\`, unchanged from Radiance's standard file.
`;
}
