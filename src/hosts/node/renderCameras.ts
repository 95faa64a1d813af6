import { InputError } from '../../core/inputError';
import { parseCameraSpec } from '../../engines/view/cameraPresets';
import { INPUT_LIMITS } from '../../core/untrustedJson';
import { readRegularFile } from './readRegularFile';

/** One camera of a render: its name (the image file's suffix) and its spec (a preset name or pose JSON for parseCameraSpec). */
export interface RenderCamera {
  name: string;
  spec: string;
}

/** A camera name becomes part of a file name: letters, digits, `_ . -` only. */
const CAMERA_NAME = /^[\w.-]{1,64}$/;

/** A room to check the pose JSON against before the first scene is read (presets fit any room; JSON does not depend on it). */
const CHECK_ROOM = { width: 4, height: 2.5, depth: 4 };

/**
 * `luxbox render` cameras from the arguments (docs/viewer.md, "Batch"):
 * `--camera` may be repeated; each value is a preset (`eye`), a comma list of
 * presets (`eye,top`) or a pose JSON (named `camera`, `camera-2`, …);
 * `--cameras <file.json>` adds a JSON object of named cameras, each a preset
 * name or a pose: `{ "front": "eye", "detail": { "position": [...], "target": [...], "fov": 40 } }`.
 * Default: `corner`. Every pose is checked here, before any scene is baked;
 * the other arguments come back in `rest`.
 */
export function takeRenderCameras(args: string[]): { cameras: RenderCamera[]; rest: string[] } {
  const cameras: RenderCamera[] = [];
  const rest: string[] = [];
  const add = (name: string, spec: string, where: string) => {
    if (!CAMERA_NAME.test(name)) throw new InputError(`render: ${where}: camera name "${name}" must be 1–64 letters, digits, _ . or -`);
    if (cameras.some((c) => c.name === name)) throw new InputError(`render: ${where}: camera "${name}" is given twice`);
    try {
      parseCameraSpec(spec, CHECK_ROOM);
    } catch (error) {
      if (where === '--camera' || !(error instanceof InputError)) throw error;
      throw new InputError(`render: ${where}: camera "${name}": ${error.message}`);
    }
    cameras.push({ name, spec });
  };
  for (let i = 0; i < args.length; i++) {
    const arg = args[i];
    const [flag, inline] = arg.includes('=') && arg.startsWith('--') ? [arg.slice(0, arg.indexOf('=')), arg.slice(arg.indexOf('=') + 1)] : [arg, undefined];
    if (flag !== '--camera' && flag !== '--cameras') {
      rest.push(arg);
      continue;
    }
    const value = inline ?? args[++i];
    if (value === undefined) throw new InputError(`render: ${flag} needs a value`);
    if (flag === '--cameras') {
      for (const [name, spec] of readCamerasFile(value)) add(name, spec, `--cameras ${value}`);
      continue;
    }
    const trimmed = value.trim();
    if (trimmed.startsWith('{')) {
      let name = 'camera';
      for (let k = 2; cameras.some((c) => c.name === name); k++) name = `camera-${k}`;
      add(name, trimmed, '--camera');
      continue;
    }
    const names = trimmed
      .split(',')
      .map((s) => s.trim())
      .filter(Boolean);
    if (names.length === 0) throw new InputError('render: --camera needs a preset name or JSON');
    for (const name of names) if (!cameras.some((c) => c.name === name)) add(name, name, '--camera');
  }
  if (cameras.length === 0) add('corner', 'corner', 'default camera');
  return { cameras, rest };
}

/** A cameras file: a JSON object, name → preset name or pose object. */
function readCamerasFile(path: string): [string, string][] {
  let text: string;
  try {
    text = new TextDecoder('utf-8').decode(readRegularFile(path, { maxBytes: INPUT_LIMITS.maxTextLength }));
  } catch (error) {
    if (!(error instanceof InputError)) throw error;
    throw new InputError(`render: --cameras ${path}: cannot read (${error.message})`);
  }
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (error) {
    throw new InputError(`render: --cameras ${path}: not JSON (${(error as Error).message})`);
  }
  if (typeof data !== 'object' || data === null || Array.isArray(data)) {
    throw new InputError(`render: --cameras ${path}: expected an object of named cameras, e.g. {"front":"eye","detail":{"position":[1,1.6,3],"target":[2,1,1],"fov":40}}`);
  }
  const entries = Object.entries(data as Record<string, unknown>);
  if (entries.length === 0) throw new InputError(`render: --cameras ${path}: no cameras in the file`);
  return entries.map(([name, v]) => {
    if (typeof v === 'string') return [name, v];
    if (typeof v === 'object' && v !== null && !Array.isArray(v)) return [name, JSON.stringify(v)];
    throw new InputError(`render: --cameras ${path}: camera "${name}" must be a preset name or a pose object`);
  });
}
