import { existsSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { dirname, join, normalize, relative } from 'node:path';

/**
 * The product's layers (docs/architecture.md), bottom to top. A file may import its own layer
 * and the layers below it, never one above; within a layer, folders may import each other as
 * long as the folder graph has no cycle. `shaders/` holds the GLSL chunks and sits with the
 * engines that compose them. `src/reference` is the independent test oracle: it may use core,
 * and only tests and the benchmark (`src/hosts/bench`) may use it.
 */
export const LAYERS = ['core', 'engines', 'ui', 'hosts'] as const;
export type Layer = (typeof LAYERS)[number];

/** Packages a layer must not import (core is pure TS; engines have no React). */
export const FORBIDDEN_PACKAGES: Record<Layer | 'reference' | 'shaders', readonly string[]> = {
  core: ['react', 'react-dom', '@react-spring/web', '@use-gesture/react', 'three', 'gl'],
  engines: ['react', 'react-dom', '@react-spring/web', '@use-gesture/react', 'gl'],
  ui: ['gl'],
  hosts: [],
  reference: ['react', 'react-dom', 'three', 'gl'],
  shaders: ['react', 'react-dom', 'three', 'gl'],
};

/** Folders allowed to import `src/reference`. */
export const REFERENCE_USERS: readonly string[] = ['hosts/bench'];

/** One import: from a repo-relative file to a repo-relative file (or a package name). */
export interface ImportEdge {
  from: string;
  to: string;
  /** A package import (`react`, `three/examples/…` → `three`), not a file. */
  isPackage: boolean;
  /** The package import as written (`zod/mini`), where `to` is only the package's name. */
  spec?: string;
}

const SPEC = /(?:^|[\n;])\s*(?:import|export)\s+(?:type\s+)?(?:[^'";]*?\s+from\s+)?['"]([^'"]+)['"]|\bimport\(\s*['"]([^'"]+)['"]\s*\)/g;

function listSources(dir: string, out: string[]): string[] {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) listSources(path, out);
    else if (/\.(ts|tsx)$/.test(name)) out.push(path);
  }
  return out;
}

function resolveFile(fromFile: string, spec: string): string | null {
  const base = normalize(join(dirname(fromFile), spec));
  const candidates = [base, `${base}.ts`, `${base}.tsx`, join(base, 'index.ts'), join(base, 'index.tsx')];
  return candidates.find((c) => existsSync(c) && statSync(c).isFile()) ?? null;
}

function packageName(spec: string): string {
  return spec.startsWith('@') ? spec.split('/').slice(0, 2).join('/') : spec.split('/')[0];
}

/**
 * Every import of every TypeScript file under `src/` and `shaders/` (static, `export … from`,
 * type-only and dynamic `import()` alike: a lazy import is still a dependency).
 */
export function readImportGraph(root: string): ImportEdge[] {
  const edges: ImportEdge[] = [];
  const files = [...listSources(join(root, 'src'), []), ...listSources(join(root, 'shaders'), [])];
  for (const file of files) {
    const from = relative(root, file);
    for (const m of readFileSync(file, 'utf8').matchAll(SPEC)) {
      const spec = m[1] ?? m[2];
      if (spec.startsWith('node:')) continue;
      if (!spec.startsWith('.')) {
        edges.push({ from, to: packageName(spec), isPackage: true, spec });
        continue;
      }
      const target = resolveFile(file, spec);
      // A JSON file is a dependency on the folder that holds it, like a module.
      if (target && /\.(ts|tsx|json)$/.test(target)) edges.push({ from, to: relative(root, target), isPackage: false });
    }
  }
  return edges;
}

/** Folders whose sub-folders are folders of their own (the model's domains, docs/architecture.md). */
export const SPLIT_FOLDERS: readonly string[] = ['core/model'];

/**
 * The folder a file belongs to: `core/colour`, `core/model/rails` (a domain of a split folder, with
 * everything under it), `core` (a file directly in a layer folder), `shaders`, `reference`, or
 * `(root)` for a file directly in `src/`.
 */
export function folderOf(file: string): string {
  const parts = file.split(/[\\/]/);
  if (parts[0] === 'shaders') return 'shaders';
  if (parts[0] !== 'src') return parts[0];
  if (parts[1] === 'reference') return 'reference';
  if (parts.length > 4 && SPLIT_FOLDERS.includes(`${parts[1]}/${parts[2]}`)) return `${parts[1]}/${parts[2]}/${parts[3]}`;
  if (parts.length > 3) return `${parts[1]}/${parts[2]}`;
  return parts.length === 3 ? parts[1] : '(root)';
}

/** The layer's rank, or null for `reference` and unknown places. `shaders` counts as engines. */
export function layerRank(folder: string): number | null {
  const head = folder === 'shaders' ? 'engines' : folder.split('/')[0];
  const rank = (LAYERS as readonly string[]).indexOf(head);
  return rank < 0 ? null : rank;
}

/** Each violation in one readable line: file, the import, the rule it breaks. */
export function layerViolations(edges: readonly ImportEdge[]): string[] {
  const problems: string[] = [];
  const folderEdges = new Map<string, Set<string>>();
  for (const e of edges) {
    const from = folderOf(e.from);
    const kind = from === 'shaders' || from === 'reference' ? from : layerRank(from) !== null ? LAYERS[layerRank(from)!] : null;
    if (kind === null) {
      problems.push(`${e.from}: lies outside the layer folders (src/core, src/engines, src/ui, src/hosts, src/reference)`);
      continue;
    }
    if (e.isPackage) {
      if (FORBIDDEN_PACKAGES[kind].includes(e.to)) problems.push(`${e.from} imports the package ${e.to}, which the ${kind} layer must not use`);
      continue;
    }
    const to = folderOf(e.to);
    if (to === 'reference') {
      if (from !== 'reference' && !REFERENCE_USERS.includes(from)) {
        problems.push(`${e.from} imports the reference solver (${e.to}): only tests and ${REFERENCE_USERS.join(', ')} may`);
      }
    } else if (from === 'reference') {
      if (to !== 'core' && !to.startsWith('core/')) problems.push(`${e.from} imports ${e.to}: the reference may use only core, to stay independent of the engines`);
    } else {
      const toRank = layerRank(to);
      if (toRank === null) problems.push(`${e.from} imports ${e.to}, which lies outside the layer folders`);
      else if (toRank > layerRank(from)!) problems.push(`${e.from} imports ${e.to}: an upward import (${from} may not depend on ${to})`);
    }
    if (from !== to) {
      if (!folderEdges.has(from)) folderEdges.set(from, new Set());
      folderEdges.get(from)!.add(to);
    }
  }
  for (const cycle of folderCycles(folderEdges)) problems.push(`folders import each other: ${cycle.join(' → ')}`);
  return problems;
}

/** Each cycle of the folder graph once, as the path that closes it (Tarjan's strongly connected components). */
export function folderCycles(graph: ReadonlyMap<string, ReadonlySet<string>>): string[][] {
  let index = 0;
  const indices = new Map<string, number>();
  const low = new Map<string, number>();
  const stack: string[] = [];
  const onStack = new Set<string>();
  const components: string[][] = [];
  const visit = (v: string): void => {
    indices.set(v, index);
    low.set(v, index);
    index++;
    stack.push(v);
    onStack.add(v);
    for (const w of graph.get(v) ?? []) {
      if (!indices.has(w)) {
        visit(w);
        low.set(v, Math.min(low.get(v)!, low.get(w)!));
      } else if (onStack.has(w)) {
        low.set(v, Math.min(low.get(v)!, indices.get(w)!));
      }
    }
    if (low.get(v) === indices.get(v)) {
      const component: string[] = [];
      let w: string;
      do {
        w = stack.pop()!;
        onStack.delete(w);
        component.push(w);
      } while (w !== v);
      if (component.length > 1) components.push(component.sort());
    }
  };
  for (const v of [...graph.keys()].sort()) if (!indices.has(v)) visit(v);
  return components.map((c) => shortestCycle(graph, c));
}

/** The shortest path from the component's first folder back to itself (breadth first, inside the component). */
function shortestCycle(graph: ReadonlyMap<string, ReadonlySet<string>>, component: readonly string[]): string[] {
  const inside = new Set(component);
  const start = component[0];
  const previous = new Map<string, string>();
  const queue = [start];
  while (queue.length > 0) {
    const v = queue.shift()!;
    for (const w of [...(graph.get(v) ?? [])].sort()) {
      if (!inside.has(w)) continue;
      if (w === start) {
        const between: string[] = [];
        for (let u = v; u !== start; u = previous.get(u)!) between.unshift(u);
        return [start, ...between, start];
      }
      if (!previous.has(w)) {
        previous.set(w, v);
        queue.push(w);
      }
    }
  }
  return [...component, start];
}
