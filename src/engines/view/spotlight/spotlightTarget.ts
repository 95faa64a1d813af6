import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { AimLimits } from '../../../core/model/modules/aim';
import type { RoomBox } from '../../../core/model/modules/coneOutline';
import type { ModuleAim } from '../../../core/model/configuration/configuration';
import type { Rgb, Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../../core/photometry/types';
import type { RoomView } from '../roomView';

/** What the spotlight view needs of the selected module (the host derives it from the configuration). */
export interface SpotlightTarget {
  moduleId: string;
  /** Photometric centre, world metres. */
  position: Vec3;
  /** Rail heading, degrees. */
  heading: number;
  /** The optic's catalog roll, degrees. */
  roll: number;
  aim: ModuleAim;
  limits: AimLimits;
  /** Full beam (50 %) and field (10 %) angles of the optic, degrees (photometry/beam.ts). */
  beamDeg: number;
  fieldDeg: number;
}

/** What the host knows of the module (the controller adds beam and field from the scene's photometry). */
export type SpotlightRequest = Omit<SpotlightTarget, 'beamDeg' | 'fieldDeg'>;

export interface SpotlightDeps {
  canvas: HTMLCanvasElement;
  view: () => RoomView;
  controls: OrbitControls;
  request: () => void;
  room: () => RoomBox | null;
  /** The module's luminaire in the scene: photometry and RGB weight (dimming × colour), or null. */
  lamp: (moduleId: string) => { photometry: Photometry; weight: Rgb } | null;
  /** Dim one module out of the relit maps (null: none). */
  setDimmed: (moduleId: string | null) => void;
  /** A drag ended on a new aim. */
  onAim: (moduleId: string, aim: ModuleAim) => void;
  /** Whether the device filters float textures (else the candela texture is sampled nearest). */
  linearFloat: boolean;
}
