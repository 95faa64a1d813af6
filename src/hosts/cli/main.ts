import { InputError } from '../../core/inputError';
import { oneLine } from '../../core/untrustedJson';
import { loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { loadRoomShapeSupport } from '../../core/model/actions/loadRoomShapeSupport';

/** A subcommand: receives the arguments after its name, returns the exit code. */
export type Command = (args: string[]) => Promise<number>;

// Each command lives in its own module, loaded only when called, so `ies info`
// never pays for WebGL. Add new commands here.
const commands: Record<string, () => Promise<{ run: Command }>> = {
  ies: () => import('./iesCommand'),
  bake: () => import('./bakeCommand'),
  probe: () => import('./probeCommand'),
  render: () => import('./renderCommand'),
  bench: () => import('./benchCommand'),
  export: () => import('./exportCommand'),
  dmx: () => import('./dmxCommand'),
  filters: () => import('./filtersCommand'),
  catalog: () => import('./catalogCommand'),
};

const usage = `usage: luxbox <command> [...]
commands:
  ies info <file.ies|file.ldt> [--json]   describe a photometric file
  bake <scene.json> --out <dir> [--samples N --bounces N --texel m]   bake light maps (docs/baker.md)
  probe <scene.json> <points.json> [--samples N --bounces N --texel m --date YYYY-MM-DD --time HH:MM]   lux at surface points, or [x,y,z,nx,ny,nz] planes (daylight: a daylight block)
  render <config-or-scene.json> [more.json …] --out image.png|dir/ [--camera eye|top|corner|json (repeatable) --cameras file --width --height --ev EV100 | --exposure stops --mode light|lux --glare on|off --date YYYY-MM-DD --time HH:MM]   3D images, batches, daylight at a time of day (render --help)
  bench [--quick] [--out <dir>] [--daylight]   bake error vs time against the CPU reference (docs/benchmarks.md)
  export radiance <config-or-scene.json> --out <dir> [--near-field split|point]   Radiance scene folder (docs/radiance.md)
  dmx [--artnet] [--sacn] [--port N] [--bind ADDR] [--universes 1-4]   Art-Net/sACN → WebSocket bridge for live control (docs/dmx.md)
  filters [--json] [--cct K]   colour-filter library: x, y, transmission (CCT, Duv near white) for a K source (docs/colour-filters.md)
  catalog import <product.gldf> [more.gldf …] --into <catalog.json> --out <dir> [--mapping <mapping.json>] [--assets <dir>]   GLDF products into a catalog folder (docs/gldf.md)
  catalog export <catalog.json> --out <dir> [--type <id> …] [--assets <dir>]   module types back to GLDF, with mapping.json (docs/gldf.md)`;

export async function main(argv: string[]): Promise<number> {
  const [name, ...rest] = argv;
  if (!name || name === '--help' || name === '-h' || name === 'help') {
    process.stdout.write(usage + '\n');
    return name ? 0 : 2;
  }
  const load = commands[name];
  if (!load) {
    process.stderr.write(`luxbox: unknown command "${name}"\n${usage}\n`);
    return 2;
  }
  try {
    // Every command may compute a colour through a filter (a configuration's modules, `filters`):
    // the spectra load with the command (docs/colour-filters.md, "Two files"). So does the room-shape
    // support: any configuration a command reads may have a room of any shape (roomShapeSupport.ts).
    const [{ run }] = await Promise.all([load(), loadColourFilterSpectra(), loadRoomShapeSupport()]);
    return await run(rest);
  } catch (error) {
    if (error instanceof InputError) {
      process.stderr.write(`luxbox ${name}: ${oneLine(error.message)}\n`);
      return 1;
    }
    // Input too deep or too large for some reader that lacks a limit (the formats check depth and size
    // first, docs/scene-format.md): still one line, exit 1, not a stack trace. Other errors are bugs.
    if (error instanceof RangeError && /call stack|Invalid (array|string) length/i.test(error.message)) {
      process.stderr.write(`luxbox ${name}: input too deeply nested or too large to process (${oneLine(error.message, 80)})\n`);
      return 1;
    }
    throw error;
  }
}
