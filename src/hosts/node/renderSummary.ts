/** Format tag of the summary.json a `luxbox render` batch writes (docs/viewer.md, "Batch"). */
export const RENDER_SUMMARY_FORMAT = 'luxbox-render-summary-v1';

/** One image of a batch: the scene file, its name in the batch, the camera, the image file and what was measured. */
export interface RenderSummaryImage {
  file: string;
  scene: string;
  camera: string;
  /** File name inside the output folder: <scene>-<camera>.png. */
  image: string;
  /** EV100 of the exposure applied (the fixed one, or what auto exposure chose). */
  ev100: number;
  /** Multiplier on luminance before the display curve, 1/(cd/m²). */
  exposure: number;
  /** Floor illuminance, lux: average, minimum, uniformity Emin/Ē. */
  floor: { avg: number; min: number; u0: number };
  /** Bake time of the scene on its first camera's entry, 0 on the others (one bake per scene). */
  bake_ms: number;
  render_ms: number;
}

export interface RenderSummary {
  format: typeof RENDER_SUMMARY_FORMAT;
  width: number;
  height: number;
  mode: string;
  exposure: { mode: 'auto'; compensation: number } | { mode: 'fixed'; ev100: number };
  /** Chromatic adaptation: eye, none or camera:<K> (`--adapt`, docs/viewer.md). */
  adaptation: string;
  cameras: { name: string; spec: string }[];
  /**
   * Shader programs linked on the batch's one GL context: the baker's (specialised per scene layout,
   * e.g. per lamp source count: scenes of one product family share them) and the view's (three.js).
   */
  programs_linked: { baker: number; view: number };
  /** The same counts after each scene that rendered: flat after the first for scenes of one kind. */
  programs_linked_after_scene: { baker: number; view: number }[];
  total_ms: number;
  images: RenderSummaryImage[];
  /** Scene files that failed, with the one-line reason. */
  failed: { file: string; error: string }[];
}
