import { existsSync, lstatSync, readdirSync, readFileSync, readlinkSync, symlinkSync, unlinkSync } from 'node:fs';
import { createRequire } from 'node:module';
import { delimiter, dirname, join } from 'node:path';
import { InputError } from '../../core/inputError';

/**
 * Which graphics back end headless-gl (ANGLE) uses (docs/gpu-server.md):
 * - `vulkan`: ANGLE's Vulkan back end. Needs no X display; runs on a GPU's
 *   Vulkan driver, or on Mesa's software driver (lavapipe) on a CPU-only box.
 * - `glx`: ANGLE on desktop OpenGL through GLX. Needs an X display (the CLI
 *   re-runs itself under `xvfb-run -a`); on a CPU-only box that is Mesa llvmpipe.
 * - `auto`: Vulkan when a hardware Vulkan device is present; otherwise GLX
 *   (under xvfb-run when no display is set), and software Vulkan only when
 *   neither an X display nor xvfb-run is there. Measured on the 2-core CI
 *   machine (docs/benchmarks.md, "Command line: GL back ends and batches"):
 *   lavapipe compiles the large generated shaders far more slowly than
 *   llvmpipe (a 10-lamp living room: 64.7 s against 3.5 s for the whole
 *   process, Xvfb start included), and its warm passes are slower too.
 */
export type GlBackend = 'vulkan' | 'glx';
export type GlBackendChoice = GlBackend | 'auto';

/** Environment variable with the same meaning as `--gl`. */
export const GL_BACKEND_ENV = 'LUXBOX_GL';

export function parseGlChoice(value: string | undefined, source: string): GlBackendChoice {
  const v = (value ?? 'auto').trim().toLowerCase();
  if (v === 'auto' || v === 'vulkan' || v === 'glx') return v;
  throw new InputError(`${source} must be vulkan, glx or auto, got "${String(value).slice(0, 40)}"`);
}

const require = createRequire(import.meta.url);

/** Folder of headless-gl's native files (ANGLE's libGLESv2.so): ANGLE dlopens libvulkan.so.1 from here. */
export function glReleaseDir(): string {
  return join(dirname(require.resolve('gl/package.json')), 'build', 'Release');
}

const LOADER = 'libvulkan.so.1';
const SYSTEM_LIB_DIRS = ['/usr/lib/x86_64-linux-gnu', '/usr/lib/aarch64-linux-gnu', '/usr/lib64', '/usr/lib', '/lib/x86_64-linux-gnu', '/lib64'];

/** The system's Vulkan loader (Debian `libvulkan1`), searched on LD_LIBRARY_PATH then the usual folders. */
export function systemVulkanLoader(): string | null {
  const dirs = [...(process.env.LD_LIBRARY_PATH ?? '').split(delimiter).filter(Boolean), ...SYSTEM_LIB_DIRS];
  for (const dir of dirs) {
    const p = join(dir, LOADER);
    if (existsSync(p)) return p;
  }
  return null;
}

/**
 * Make ANGLE find the Vulkan loader: a link `libvulkan.so.1` next to
 * libGLESv2.so pointing at the system's loader (run by `npm ci`'s prepare
 * and again here at run time, so a moved system library is followed). A real
 * file already there (a packed GPU folder ships one) is left alone. Returns
 * the loader ANGLE will load, or null when there is none.
 */
export function ensureVulkanLoader(releaseDir = glReleaseDir()): string | null {
  const local = join(releaseDir, LOADER);
  let stat: ReturnType<typeof lstatSync> | null;
  try {
    stat = lstatSync(local);
  } catch {
    stat = null;
  }
  if (stat && !stat.isSymbolicLink()) return local;
  const system = systemVulkanLoader();
  if (stat?.isSymbolicLink()) {
    if (existsSync(local) && (!system || readlinkSync(local) === system)) return local;
    try {
      unlinkSync(local);
    } catch {
      return existsSync(local) ? local : null;
    }
  }
  if (!system) return null;
  try {
    symlinkSync(system, local);
    return local;
  } catch {
    return null; // read-only install: the caller names what is missing
  }
}

export interface VulkanDrivers {
  /** ICD manifests found (VK_DRIVER_FILES / VK_ICD_FILENAMES, else the standard folders). */
  manifests: string[];
  /** Any manifest that is not Mesa's software rasteriser (lavapipe). */
  hardwareManifests: string[];
  /** A GPU device node exists (/dev/nvidia*, /dev/dri/renderD*). */
  deviceNode: boolean;
}

function listManifests(): string[] {
  const explicit = process.env.VK_DRIVER_FILES ?? process.env.VK_ICD_FILENAMES;
  const entries = explicit ? explicit.split(delimiter).filter(Boolean) : ['/usr/share/vulkan/icd.d', '/etc/vulkan/icd.d', '/usr/local/share/vulkan/icd.d'];
  const files: string[] = [];
  for (const entry of entries) {
    try {
      if (entry.endsWith('.json')) {
        if (existsSync(entry)) files.push(entry);
      } else {
        for (const f of readdirSync(entry)) if (f.endsWith('.json')) files.push(join(entry, f));
      }
    } catch {
      // folder absent
    }
  }
  return files;
}

function isSoftware(manifest: string): boolean {
  if (/lvp|lavapipe|swiftshader/i.test(manifest)) return true;
  try {
    return /lvp|lavapipe|swiftshader/i.test(readFileSync(manifest, 'utf8').slice(0, 4096));
  } catch {
    return false;
  }
}

function hasDeviceNode(): boolean {
  try {
    if (readdirSync('/dev').some((f) => /^nvidia\d+$/.test(f))) return true;
  } catch {
    // no /dev listing
  }
  try {
    return readdirSync('/dev/dri').some((f) => f.startsWith('renderD'));
  } catch {
    return false;
  }
}

export function vulkanDrivers(): VulkanDrivers {
  const manifests = listManifests();
  return { manifests, hardwareManifests: manifests.filter((m) => !isSoftware(m)), deviceNode: hasDeviceNode() };
}

function onPath(program: string): boolean {
  return (process.env.PATH ?? '').split(delimiter).some((dir) => dir && existsSync(join(dir, program)));
}

export interface BackendSelection {
  backend: GlBackend;
  /** Why this one (shown by `--verbose` callers and in errors). */
  reason: string;
}

/** Resolve `auto` (see the type's comment); explicit choices are kept. */
export function selectGlBackend(choice: GlBackendChoice): BackendSelection {
  if (choice !== 'auto') return { backend: choice, reason: 'requested' };
  const drivers = vulkanDrivers();
  const loader = ensureVulkanLoader() !== null;
  if (loader && drivers.hardwareManifests.length > 0 && drivers.deviceNode) return { backend: 'vulkan', reason: 'hardware Vulkan device' };
  if (process.env.DISPLAY) return { backend: 'glx', reason: 'X display set, no hardware Vulkan' };
  if (onPath('xvfb-run')) return { backend: 'glx', reason: 'no hardware Vulkan; GLX under xvfb-run' };
  if (loader && drivers.manifests.length > 0) return { backend: 'vulkan', reason: 'no X display and no xvfb-run; software Vulkan' };
  throw new InputError('no graphics back end: no Vulkan driver (apt-get install mesa-vulkan-drivers libvulkan1) and no X display (set DISPLAY or apt-get install xvfb)');
}

/**
 * Point ANGLE at the chosen back end before the first context is made (ANGLE
 * reads ANGLE_DEFAULT_PLATFORM when it opens its display). For Vulkan, makes
 * sure the loader is where ANGLE looks and fails with one line naming what is
 * missing.
 */
export function activateGlBackend(backend: GlBackend): void {
  if (backend === 'glx') {
    delete process.env.ANGLE_DEFAULT_PLATFORM;
    return;
  }
  if (!ensureVulkanLoader()) {
    throw new InputError(`--gl vulkan: no Vulkan loader (${LOADER}) for ANGLE in ${glReleaseDir()}: apt-get install libvulkan1, then npm ci (or run scripts/linkVulkanLoader.mjs)`);
  }
  if (vulkanDrivers().manifests.length === 0) {
    throw new InputError("--gl vulkan: no Vulkan driver found (apt-get install mesa-vulkan-drivers, or set VK_DRIVER_FILES to your GPU driver's ICD file)");
  }
  process.env.ANGLE_DEFAULT_PLATFORM = 'vulkan';
}
