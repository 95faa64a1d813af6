import type { BakeScene } from '../bake/bakeScene';
import { resolveBakeSettings, type BakeSettings } from '../bake/bakeSettings';
import { nearFieldOf, scenePointSources } from '../bake/scenePointSources';
import { cameraPreset } from '../view/cameraPresets';
import { roomPlaneGrid, rtracePoints } from './illuminanceGrid';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { luminairesRad } from './luminairesRad';
import { exportReadme } from './exportReadme';
import { EXPORT_GRIDS, EXPORT_VIEWS, GRID_SPACING, IMAGE_SIZE, renderScript } from './renderScript';
import { roomRad } from './roomRad';
import { SOURCE_CAL } from './sourceCal';
import { viewFile } from './viewFile';

/** One file of the export folder: path relative to the folder, text, and whether it is a script to run. */
export interface ExportFile {
  path: string;
  text: string;
  executable?: boolean;
}

/**
 * A self-contained Radiance folder for a scene (docs/radiance.md): `scene.rad` (room and every
 * luminaire), the candela distributions as brightdata files, source.cal, view files for the
 * eye, top and corner cameras, illuminance grids, `render.sh` and a README. The near field
 * follows the scene's `nearField` (or the settings' override) through the baker's own point
 * sources, so Radiance and luxbox solve the same physical problem.
 */
export function exportRadiance(scene: BakeScene, settings: Partial<BakeSettings> = {}, title = 'luxbox scene'): ExportFile[] {
  const resolved = resolveBakeSettings(settings);
  const lamps = scenePointSources(scene, resolved);
  const luminaires = luminairesRad(scene, lamps);
  const nearField = nearFieldOf(scene, resolved);
  const header = [
    `# ${title}: exported by luxbox for Radiance.`,
    '# Frame: Radiance (X, Y, Z) = luxbox (x, -z, y), metres; Z up, north is +Y.',
    `# Near field: ${nearField} (${nearField === 'split' ? 'luminous openings as grids of point sources, as luxbox bakes them' : 'one point source per luminaire'}).`,
    '',
  ].join('\n');
  const aspect = IMAGE_SIZE.width / IMAGE_SIZE.height;
  return [
    { path: 'scene.rad', text: header + roomRad(scene) + '\n' + luminaires.rad },
    ...luminaires.files,
    { path: 'source.cal', text: SOURCE_CAL },
    ...EXPORT_VIEWS.map((name) => ({ path: `views/${name}.vf`, text: viewFile(cameraPreset(name, scene.room, { scene, aspect }), aspect) })),
    ...EXPORT_GRIDS.map((g) => ({ path: `points/${g.name}.pts`, text: rtracePoints(roomPlaneGrid(scene.room as BakeScene['room'] & { shape?: ShapedRoom }, g.height, GRID_SPACING)) })),
    { path: 'render.sh', text: renderScript(), executable: true },
    { path: 'README.md', text: exportReadme(title, scene, nearField, lamps.length) },
  ];
}
