/** Path of the first module carrying `key` (its shape is checked later, so every step looks before it leaps). */
export function firstModuleWith(configuration: unknown, key: string): string | null {
  const list = (o: unknown, key: string): unknown[] => (typeof o === 'object' && o !== null && Array.isArray((o as Record<string, unknown>)[key]) ? ((o as Record<string, unknown>)[key] as unknown[]) : []);
  const systems = list(configuration, 'systems');
  for (let i = 0; i < systems.length; i++) {
    const rails = list(systems[i], 'rails');
    for (let k = 0; k < rails.length; k++) {
      const modules = list(rails[k], 'modules');
      for (let n = 0; n < modules.length; n++) {
        const m = modules[n];
        if (typeof m === 'object' && m !== null && key in m) return `systems[${i}].rails[${k}].modules[${n}].${key}`;
      }
    }
  }
  return null;
}
