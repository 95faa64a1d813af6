// Packs what a bare GPU server (no X, no package access, nothing installed) needs
// to run `luxbox bake|render|probe|bench --gpu` through ANGLE's Vulkan back end:
//   luxbox.mjs     the CLI bundled into one file by esbuild (gl kept external)
//   node.xz        this machine's node binary, xz-compressed (run.sh unpacks it once)
//   node_modules/  headless-gl's runtime files (JS, ANGLE .so files, webgl.node) and
//                  its small JS dependencies; the Vulkan loader as a real file where
//                  ANGLE looks for it
//   sysroot/       Debian's glvnd/EGL/GLES/Vulkan-loader libraries (NVIDIA's Vulkan
//                  ICD needs libglvnd), found through LD_LIBRARY_PATH, nothing written to /
//   run.sh         sets the environment and runs the CLI
// Usage: node scripts/packGpuBench.mjs [outDir]   (default gpu-pack/, git-ignored; < 60 MB)
// See docs/gpu-server.md for the recipe and docs/benchmarks.md for results.
import { execFileSync } from 'node:child_process';
import { chmodSync, cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, realpathSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';

const root = resolve(dirname(new URL(import.meta.url).pathname), '..');
const out = resolve(root, process.argv[2] ?? 'gpu-pack');
const sh = (cmd, args, opts = {}) => execFileSync(cmd, args, { stdio: ['ignore', 'pipe', 'inherit'], ...opts });

rmSync(out, { recursive: true, force: true });
mkdirSync(join(out, 'node_modules'), { recursive: true });

// 1. The CLI in one file, and the two device measurements that are scripts, not CLI commands
// (docs/benchmarks.md "GPU": the bright-patch selection and the per-frame relight).
const bundle = (entry, outfile, input) =>
  sh(
    join(root, 'node_modules/.bin/esbuild'),
    [
      ...(entry ? [entry] : ['--sourcefile=entry.ts', '--loader=ts']),
      '--bundle',
      '--platform=node',
      '--format=esm',
      '--target=node20',
      '--external:gl',
      `--outfile=${join(out, outfile)}`,
      // Bundled CommonJS dependencies call require(): give the ES module one.
      "--banner:js=import { createRequire as __luxboxRequire } from 'node:module'; const require = __luxboxRequire(import.meta.url);",
      '--log-level=warning',
    ],
    { cwd: root, ...(input ? { input, stdio: ['pipe', 'pipe', 'inherit'] } : {}) },
  );
bundle(join(root, 'src/hosts/cli/bundleEntry.ts'), 'luxbox.mjs');
// The bundle sits in gpu-pack/, so its import.meta.dirname + '../tests/fixtures' is the repository's.
bundle(join(root, 'scripts/measureBrightSelection.ts'), 'measureBrightSelection.mjs');
bundle(null, 'benchGpuRelight.mjs', "import { benchGpuRelight } from './scripts/bench/benchGpuRelight';\nconsole.log(JSON.stringify(benchGpuRelight(), null, 2));\n");

// 2. headless-gl's runtime and its runtime dependencies (build-time ones left out).
const BUILD_ONLY = new Set(['nan', 'node-gyp', 'prebuild-install']);
const copied = new Set();
function copyPackage(name, from) {
  if (copied.has(name) || BUILD_ONLY.has(name)) return;
  copied.add(name);
  const pkgJson = createRequire(join(from, 'package.json')).resolve(`${name}/package.json`);
  const dir = dirname(pkgJson);
  const pkg = JSON.parse(readFileSync(pkgJson, 'utf8'));
  const dest = join(out, 'node_modules', name);
  if (name === 'gl') {
    mkdirSync(join(dest, 'build/Release'), { recursive: true });
    for (const f of ['package.json', 'index.js']) cpSync(join(dir, f), join(dest, f));
    cpSync(join(dir, 'src/javascript'), join(dest, 'src/javascript'), { recursive: true });
    for (const f of readdirSync(join(dir, 'build/Release'))) {
      if (f.endsWith('.so') || f.endsWith('.node')) cpSync(realpathSync(join(dir, 'build/Release', f)), join(dest, 'build/Release', f));
    }
  } else {
    cpSync(dir, dest, { recursive: true, filter: (p) => !/\/(test|tests|example|examples|\.github)(\/|$)/.test(p.slice(dir.length)) });
  }
  for (const dep of Object.keys(pkg.dependencies ?? {})) copyPackage(dep, dir);
}
copyPackage('gl', root);

// 3. Debian's libraries for a machine that has only the NVIDIA driver.
const debs = ['libvulkan1', 'libglvnd0', 'libegl1', 'libgl1', 'libglx0', 'libopengl0', 'libgles2'];
const tmp = mkdtempSync(join(tmpdir(), 'luxbox-debs-'));
sh('apt-get', ['download', ...debs], { cwd: tmp });
for (const f of readdirSync(tmp).filter((f) => f.endsWith('.deb'))) sh('dpkg-deb', ['-x', join(tmp, f), join(out, 'sysroot')]);
rmSync(join(out, 'sysroot/usr/share'), { recursive: true, force: true });
const libDir = join(out, 'sysroot/usr/lib/x86_64-linux-gnu');
cpSync(realpathSync(join(libDir, 'libvulkan.so.1')), join(out, 'node_modules/gl/build/Release/libvulkan.so.1'));

// 4. node, compressed.
writeFileSync(join(out, 'node.xz'), sh('xz', ['-9', '-T0', '-c', process.execPath], { maxBuffer: 1 << 30 }));

// 5. The launcher.
writeFileSync(
  join(out, 'run.sh'),
  `#!/usr/bin/env bash
# luxbox on a bare GPU server: Vulkan back end, no X display.
# Usage: run.sh <luxbox args…>   or   run.sh --script <bundled script>.mjs <its args…>
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
[ -x "$HERE/node" ] || { xz -d -k -c "$HERE/node.xz" > "$HERE/node.tmp" && chmod +x "$HERE/node.tmp" && mv "$HERE/node.tmp" "$HERE/node"; }
export LD_LIBRARY_PATH="$HERE/sysroot/usr/lib/x86_64-linux-gnu\${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# NVIDIA's Vulkan ICD, where the driver container puts it, unless the caller chose one.
if [ -z "\${VK_DRIVER_FILES:-}\${VK_ICD_FILENAMES:-}" ]; then
  for f in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json /etc/vulkan/icd.d/nvidia_icd.json; do
    [ -f "$f" ] && { export VK_DRIVER_FILES="$f"; break; }
  done
fi
export LUXBOX_GL="\${LUXBOX_GL:-vulkan}"
if [ "\${1:-}" = --script ]; then
  # Scripts make their context with createHeadlessGL directly: ANGLE reads its platform from here.
  export ANGLE_DEFAULT_PLATFORM=vulkan
  exec "$HERE/node" "$HERE/$2" "\${@:3}"
fi
exec "$HERE/node" "$HERE/luxbox.mjs" "$@"
`,
);
chmodSync(join(out, 'run.sh'), 0o755);

let bytes = 0;
const walk = (p) => (statSync(p).isDirectory() ? readdirSync(p).forEach((f) => walk(join(p, f))) : (bytes += statSync(p).size));
walk(out);
console.log(`packed ${out}: ${(bytes / 1e6).toFixed(1)} MB (${[...copied].join(', ')})`);
if (!existsSync(join(out, 'luxbox.mjs'))) process.exit(1);
