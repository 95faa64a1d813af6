/**
 * A device that reports 2 GB of memory or less (`navigator.deviceMemory`, Chromium's Device
 * Memory API; other browsers do not report it and count as not low). Such devices free what is
 * only a cache: the baker's render-target pool after a bake (createBakeService), the hidden 3D
 * view behind the 2D plan (the planner).
 */
export function lowMemoryDevice(): boolean {
  const memory = typeof navigator === 'undefined' ? undefined : (navigator as Navigator & { deviceMemory?: number }).deviceMemory;
  return typeof memory === 'number' && memory <= 2;
}
