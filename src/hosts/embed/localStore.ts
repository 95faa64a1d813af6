/**
 * Thin, failure-tolerant access to localStorage. Private browsing, disabled storage and a
 * full quota all throw from the Storage API; autosave is a convenience, so those cases
 * degrade to "nothing saved" instead of breaking the configurator.
 */

function storage(): Storage | null {
  try {
    return typeof window !== 'undefined' && window.localStorage ? window.localStorage : null;
  } catch {
    return null;
  }
}

export function readLocal(key: string): string | null {
  try {
    return storage()?.getItem(key) ?? null;
  } catch {
    return null;
  }
}

/** Returns whether the value was stored. */
export function writeLocal(key: string, value: string): boolean {
  try {
    const s = storage();
    if (!s) return false;
    s.setItem(key, value);
    return true;
  } catch {
    return false;
  }
}
