import { spawn } from 'node:child_process';
import { fileURLToPath } from 'node:url';

const repoRoot = fileURLToPath(new URL('..', import.meta.url));

export interface PreviewServer {
  url: string;
  stop(): Promise<void>;
}

/**
 * The built app served by `vite preview`, as playwright.config.ts serves it for the Chromium
 * suite. Port: LUXBOX_ENGINES_PORT, else LUXBOX_E2E_PORT + 1 (so two copies of the tree can run
 * side by side, and a Playwright server still shutting down is never hit); the build folder:
 * LUXBOX_ENGINES_OUTDIR, else dist/.
 */
export async function startPreview(): Promise<PreviewServer> {
  const port = Number(process.env.LUXBOX_ENGINES_PORT ?? Number(process.env.LUXBOX_E2E_PORT ?? 4173) + 1);
  const outDir = process.env.LUXBOX_ENGINES_OUTDIR ?? 'dist';
  const url = `http://localhost:${port}`;
  // Something already answering there would be tested instead of this tree's build: refuse.
  const taken = await fetch(url).then(
    () => true,
    () => false,
  );
  if (taken) throw new Error(`port ${port} is already in use; set LUXBOX_ENGINES_PORT to a free port`);
  const child = spawn('npx', ['vite', 'preview', '--port', String(port), '--strictPort', '--outDir', outDir], {
    cwd: repoRoot,
    stdio: ['ignore', 'ignore', 'pipe'],
    detached: true, // its own process group: stop() ends npx and the vite it started
  });
  let stderr = '';
  child.stderr!.on('data', (d) => (stderr += String(d)));
  const end = Date.now() + 60_000;
  for (;;) {
    if (child.exitCode !== null) throw new Error(`vite preview exited (${child.exitCode}) before serving ${url}: ${stderr.trim()}`);
    try {
      if ((await fetch(url)).ok) break;
    } catch {
      // not up yet
    }
    if (Date.now() > end) {
      process.kill(-child.pid!, 'SIGTERM');
      throw new Error(`vite preview did not serve ${url} within 60 s: ${stderr.trim()}`);
    }
    await new Promise((r) => setTimeout(r, 200));
  }
  return {
    url,
    stop: async () => {
      if (child.exitCode !== null) return;
      const exited = new Promise((r) => child.once('exit', r));
      process.kill(-child.pid!, 'SIGTERM');
      await exited;
    },
  };
}
