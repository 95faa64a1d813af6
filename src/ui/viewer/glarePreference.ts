/** Where the user's glare switch is kept (per browser), when the host lets luxbox remember (BakeHost.remember). */
export const GLARE_STORAGE_KEY = 'luxbox.glare';

/** The stored switch, or true (the default: on) when none is stored, storage is blocked or the host keeps nothing. */
export function initialGlare(remember: boolean): boolean {
  if (!remember) return true;
  try {
    return typeof localStorage === 'undefined' || localStorage.getItem(GLARE_STORAGE_KEY) !== 'off';
  } catch {
    return true; // storage blocked (privacy settings, sandboxed frame)
  }
}

export function storeGlare(on: boolean, remember: boolean): void {
  if (!remember) return;
  try {
    localStorage.setItem(GLARE_STORAGE_KEY, on ? 'on' : 'off');
  } catch {
    // Storage blocked: the choice holds for this page only.
  }
}
