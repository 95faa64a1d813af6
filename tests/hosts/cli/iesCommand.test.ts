import { spawnSync } from 'node:child_process';
import { describe, expect, it } from 'vitest';

function luxbox(...args: string[]): { status: number | null; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, ['bin/luxbox.js', ...args], { encoding: 'utf8' });
  return { status: r.status, stdout: r.stdout, stderr: r.stderr };
}

describe('luxbox ies info', () => {
  it('--json on an IES file', () => {
    const r = luxbox('ies', 'info', 'public/ies/bega_84659_flood_h90_270.ies', '--json');
    expect(r.status).toBe(0);
    const info = JSON.parse(r.stdout);
    expect(info).toMatchObject({
      format: 'IES',
      version: 'LM-63-1995',
      manufacturer: 'BEGA Copyright LUMCat V',
      luminaire: '84659K4 (Preliminary)',
      photometricType: 'C',
      symmetry: 'bilateral-c90',
      angles: { file: { vertical: 37, horizontal: 37, horizontalRange: [90, 270] }, expanded: { vertical: 39, horizontal: 73 } },
      statedLumens: 9600,
      inputWatts: 68,
      // The file's width 0.24 m runs along C90, its length 0.27 m along C0 (LM-63 §5.10); stored under EULUMDAT's names (width = along C0).
      luminousOpening: { shape: 'rectangular', width: 0.27, length: 0.24 },
      warnings: [],
    });
    expect(Math.abs(info.lumensRatio - 1)).toBeLessThan(0.01);
    expect(info.peak.candela).toBe(6458.4);
    expect(info.beam.c0).toBeGreaterThan(0);
    expect(info.field.c90).toBeGreaterThan(info.beam.c90);
  });

  it('--json on an LDT file, and text output', () => {
    const r = luxbox('ies', 'info', 'public/ies/zumtobel_sloin_linear_isym4.ldt', '--json');
    expect(r.status).toBe(0);
    const info = JSON.parse(r.stdout);
    expect(info).toMatchObject({ format: 'LDT', version: 'EULUMDAT', symmetry: 'quadrant', statedLumens: 2840 });
    expect(info.luminousOpening.length).toBeCloseTo(2.0, 6);
    const text = luxbox('ies', 'info', 'public/ies/zumtobel_sloin_linear_isym4.ldt');
    expect(text.stdout).toContain('integrated lumens:');
    expect(text.stdout).toContain('beam (50 %):');
    // The opening by the planes it lies along (EULUMDAT: width b along C0–C180, length along C90–C270).
    expect(text.stdout).toContain('luminous opening:  rectangular, 0.072 m along C0–C180 × 2 m along C90–C270');
  });

  it('warnings appear in the text output and in --json', () => {
    const warning = 'stated lumens 34 lm and integrated flux 2047 lm differ by 5921 % (ratio 60.21); the integrated flux of the candela data is used';
    const json = luxbox('ies', 'info', 'tests/fixtures/photometry/lumens_mismatch_60x.ies', '--json');
    expect(json.status).toBe(0);
    expect(JSON.parse(json.stdout).warnings).toEqual([warning]);
    const text = luxbox('ies', 'info', 'tests/fixtures/photometry/c_full_360_seam_differs.ies');
    expect(text.status).toBe(0);
    expect(text.stdout).toContain('warnings:          the 360° plane differs from the 0° plane');
  });

  it('hostile input: one short stderr line, exit 1, no echo of a 40 000-digit numeral', () => {
    const r = luxbox('ies', 'info', 'tests/fixtures/photometry/fuzz-regressions/long_message_ldt_header_numeral_40k_digits.ldt');
    expect(r.status).toBe(1);
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr.length).toBeLessThan(250);
    expect(r.stderr).toContain('line 5: the C-plane distance Dc: a numeral of 40001 characters is too long (limit 100)');
  });

  it('missing and malformed files: one stderr line, exit 1', () => {
    const missing = luxbox('ies', 'info', 'public/ies/nope.ies');
    expect(missing.status).toBe(1);
    expect(missing.stderr).toBe('luxbox ies: public/ies/nope.ies: no such file\n');
    const bad = luxbox('ies', 'info', 'tests/fixtures/photometry/bad/negative_candela.ies');
    expect(bad.status).toBe(1);
    expect(bad.stderr.trim().split('\n')).toHaveLength(1);
    expect(bad.stderr).toContain('negative_candela.ies line 9: negative candela value -80');
  });
});
