import { existsSync, readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

/**
 * The planner must not pay for three.js (docs/architecture.md: the viewer is loaded lazily). This walks the
 * static import graph of the app's entry (relative imports, `import … from` and `export … from`;
 * dynamic `import()` is the lazy boundary and is not followed) and lists every bare package
 * it reaches.
 */
function staticPackages(entry: string): { packages: Set<string>; files: Set<string> } {
  const files = new Set<string>();
  const packages = new Set<string>();
  const stack = [resolve(entry)];
  const spec = /(?:^|\n)\s*(?:import|export)\s+(?:type\s+)?(?:[^'"]*?\s+from\s+)?['"]([^'"]+)['"]/g;
  while (stack.length > 0) {
    const file = stack.pop()!;
    if (files.has(file)) continue;
    files.add(file);
    const text = readFileSync(file, 'utf8');
    for (const m of text.matchAll(spec)) {
      const s = m[1];
      if (/^import\s+type\b/.test(m[0].trim()) || /^export\s+type\b/.test(m[0].trim())) continue;
      if (!s.startsWith('.')) {
        packages.add(s.startsWith('@') ? s.split('/').slice(0, 2).join('/') : s.split('/')[0]);
        continue;
      }
      const base = resolve(dirname(file), s);
      const candidates = [base, `${base}.ts`, `${base}.tsx`, `${base}/index.ts`, `${base}/index.tsx`];
      const hit = candidates.find((c) => existsSync(c) && /\.(ts|tsx)$/.test(c));
      if (hit) stack.push(hit);
    }
  }
  return { packages, files };
}

describe('planner bundle', () => {
  it('the app entry reaches no three.js through static imports', () => {
    const { packages, files } = staticPackages('src/hosts/app/main.tsx');
    expect(files.size).toBeGreaterThan(20);
    expect([...packages].filter((p) => p === 'three' || p.startsWith('three'))).toEqual([]);
    // What the planner does use, so the walk is known to work.
    expect(packages).toContain('react');
    expect(packages).toContain('zustand');
    // The plan's gestures (planGestureListener.ts, @use-gesture) are a lazy chunk that usePlanGestures.ts loads.
    expect(packages).not.toContain('@use-gesture/vanilla');
    expect(packages).not.toContain('@use-gesture/react');
    // The plan's zoom spring (viewSpring.ts, React Spring) is a lazy chunk that usePlanView.ts loads: not in the first download.
    expect(packages).not.toContain('@react-spring/web');
  });

  it('the same walk does find three.js behind the lazy 3D view (the check can fail)', () => {
    expect(staticPackages('src/ui/viewer/View3D.tsx').packages).toContain('three');
  });

  /** What rooms of any shape add to the model: the lazy room-shape chunk (roomShapeSupport.ts, docs/architecture.md). */
  const SHAPE_CHUNK = [
    'src/core/model/actions/roomShapeChunk.ts',
    'src/core/model/configuration/roomShape.ts',
    'src/core/model/actions/roomShapeActions.ts',
    'src/core/model/actions/roomShapeGeometry.ts',
    'src/core/model/validation/roomShapeProblems.ts',
    'src/core/model/validation/shapedSystemFit.ts',
    'src/core/model/files/roomShapeFileSchema.ts',
    'src/core/model/files/migrations/legacyMigrations.ts',
    'src/core/room/roomProblems.ts',
    'src/core/room/roomSchema.ts',
    'src/core/room/normaliseRoom.ts',
  ].map((f) => resolve(f));

  it('neither page reaches the room-shape chunk through static imports: only its hook is on the first screen', () => {
    for (const entry of ['src/hosts/app/main.tsx', 'src/hosts/embedDemo/main.ts']) {
      const { files } = staticPackages(entry);
      expect(files).toContain(resolve('src/core/model/configuration/roomShapeSupport.ts'));
      expect(SHAPE_CHUNK.filter((f) => files.has(f))).toEqual([]);
    }
  });

  it('the same walk from the chunk reaches all of it (the check can fail)', () => {
    const { files } = staticPackages('src/core/model/actions/roomShapeChunk.ts');
    expect(SHAPE_CHUNK.filter((f) => !files.has(f))).toEqual([]);
  });
});
