// prepare (npm ci / npm install in the repository): let ANGLE (inside headless-gl) find the system's Vulkan loader.
// ANGLE dlopens libvulkan.so.1 from its own folder (node_modules/gl/build/Release),
// not from the system library path, so link it there. Harmless when either side
// is missing (no gl installed yet, or no libvulkan1: the GLX back end still works).
import { existsSync, lstatSync, symlinkSync, unlinkSync } from 'node:fs';
import { join } from 'node:path';

const release = join(process.cwd(), 'node_modules', 'gl', 'build', 'Release');
const candidates = ['/usr/lib/x86_64-linux-gnu', '/usr/lib/aarch64-linux-gnu', '/usr/lib64', '/usr/lib'].map((d) => join(d, 'libvulkan.so.1'));
const system = candidates.find((p) => existsSync(p));
const local = join(release, 'libvulkan.so.1');
if (!existsSync(release)) {
  console.log('linkVulkanLoader: headless-gl not built yet, skipped');
} else if (!system) {
  console.log('linkVulkanLoader: no system libvulkan.so.1 (apt-get install libvulkan1): only the GLX back end will work');
} else {
  let isLink;
  try {
    isLink = lstatSync(local).isSymbolicLink();
  } catch {
    isLink = false;
  }
  if (isLink) unlinkSync(local);
  if (isLink || !existsSync(local)) symlinkSync(system, local);
  console.log(`linkVulkanLoader: ${local} -> ${system}`);
}
