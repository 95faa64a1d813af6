import os from 'node:os';

/** Where and when a benchmark ran: numbers mean little without it. */
export interface MachineInfo {
  date: string;
  cpuModel: string;
  cores: number;
  memoryGiB: number;
  os: string;
  node: string;
  glVersion: string;
  glRenderer: string;
}

/** Renderer strings of a WebGL context, unmasked where the debug extension is offered. */
export function glStrings(gl: WebGL2RenderingContext): { glVersion: string; glRenderer: string } {
  const debug = gl.getExtension('WEBGL_debug_renderer_info') as { UNMASKED_RENDERER_WEBGL: number; UNMASKED_VENDOR_WEBGL: number } | null;
  const renderer = String(gl.getParameter(debug ? debug.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  const vendor = String(gl.getParameter(debug ? debug.UNMASKED_VENDOR_WEBGL : gl.VENDOR));
  return { glVersion: String(gl.getParameter(gl.VERSION)), glRenderer: `${vendor} — ${renderer}` };
}

export function machineInfo(gl: WebGL2RenderingContext, now = new Date()): MachineInfo {
  const cpus = os.cpus();
  return {
    date: now.toISOString(),
    cpuModel: cpus[0]?.model.trim() ?? 'unknown',
    cores: cpus.length,
    memoryGiB: Math.round((os.totalmem() / 2 ** 30) * 10) / 10,
    os: `${os.type()} ${os.release()} ${os.arch()} (${os.version()})`,
    node: process.version,
    ...glStrings(gl),
  };
}
