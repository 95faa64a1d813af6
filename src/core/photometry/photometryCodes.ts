/**
 * Codes for the photometry readers' sentences (docs/i18n.md, "Messages from the core").
 * Warnings travel as English strings (Photometry.warnings: bake reports, `luxbox ies info`, the
 * worker boundary) and a parse error reaches the 3D view as its message, so the code and params
 * of each sentence are recovered here from the sentence itself, by one pattern per sentence the
 * readers write (parseIes, parseLdt, checks, expandTypeC, numberReader, readGrid). Each pattern is
 * tested against the readers' real output (tests/photometry/photometryCodes.test.ts), so a
 * reworded sentence fails a test instead of silently showing English.
 */
import type { CodedText, MessageParams } from '../inputError';

type Pattern = readonly [RegExp, string, (m: RegExpExecArray) => MessageParams];

const num = (s: string): number | string => (Number.isFinite(Number(s)) ? Number(s) : s);

/** The nouns a count names ('vertical angles'), as parameters a UI words by code. */
const NOUNS: Record<string, string> = {
  'vertical angles': 'verticalAngles',
  'horizontal angles': 'horizontalAngles',
  'candela values': 'candelaValues',
  'tilt angles': 'tiltAngles',
  'tilt factors': 'tiltFactors',
  'C-planes': 'cPlanes',
  'gamma angles': 'gammaAngles',
};

const WARNINGS: readonly Pattern[] = [
  [
    /^stated lumens (\S+) lm and integrated flux (\S+) lm differ by (\S+) % \(ratio (\S+)\); the integrated flux of the candela data is used$/,
    'lumensDiffer',
    (m) => ({ stated: num(m[1]), flux: num(m[2]), percent: num(m[3]), ratio: num(m[4]) }),
  ],
  [/^integrated flux (\S+) lm exceeds the stated lamp lumens (\S+) lm \(light output ratio (\S+) > 1\); the candela data is used$/, 'fluxAboveLamps', (m) => ({ flux: num(m[1]), stated: num(m[2]), ratio: num(m[3]) })],
  [/^integrated flux (\S+) lm is only (\S+) % of the stated lamp lumens (\S+) lm; the candela data is used$/, 'fluxBelowLamps', (m) => ({ flux: num(m[1]), percent: num(m[2]), stated: num(m[3]) })],
  [/^every candela value is 0: the luminaire emits no light$/, 'noLight', () => ({})],
  [/^number of lamps is (.+); treated as 1$/, 'lampsTreatedAsOne', (m) => ({ value: m[1] })],
  [/^lumens per lamp is (.+); treated as absolute photometry$/, 'absolutePhotometry', (m) => ({ value: m[1] })],
  [/^the "future use" field is (.+) \(LM-63-2002 and later: ignored\)$/, 'futureUseIgnored', (m) => ({ value: m[1] })],
  [/^input watts (\S+) exceed (\S+) W; ignored$/, 'wattsIgnored', (m) => ({ watts: num(m[1]), max: num(m[2]) })],
  [/^total wattage (\S+) W exceeds (\S+) W; ignored$/, 'wattsIgnored', (m) => ({ watts: num(m[1]), max: num(m[2]) })],
  [/^the (\d+) vertical angles are listed in descending order; read in ascending order with their values$/, 'verticalDescending', (m) => ({ count: Number(m[1]) })],
  [/^the (\d+) horizontal angles are listed in descending order; read in ascending order with their planes$/, 'horizontalDescending', (m) => ({ count: Number(m[1]) })],
  [/^the (\d+) tilt angles are listed in descending order; read in ascending order with their factors$/, 'tiltDescending', (m) => ({ count: Number(m[1]) })],
  [/^(.+) states (\S+) lm, out of range \((\S+) to (\S+) lm\); ignored$/, 'statedLumensIgnored', (m) => ({ source: m[1], value: num(m[2]), min: num(m[3]), max: num(m[4]) })],
  [/^ignored (\d+) trailing item\(s\) after the data from line (\d+) \("(.*)"\)$/s, 'trailingItems', (m) => ({ count: Number(m[1]), line: Number(m[2]), items: m[3] })],
  [/^type indicator Ityp is (.+) \(expected 0\.\.3\); ignored$/, 'itypIgnored', (m) => ({ value: m[1] })],
  [/^line (\d+): the intensity conversion factor is not given; 1 is used$/, 'noConversionFactor', (m) => ({ line: Number(m[1]) })],
  [/^line (\d+): the light output ratio LORL is not given; no stated lumens$/, 'noLorl', (m) => ({ line: Number(m[1]) })],
  [/^light output ratio LORL is (\S+) % \(expected 0\.\.100\)$/, 'lorlRange', (m) => ({ value: num(m[1]) })],
  [/^the 360° plane differs from the 0° plane \(by up to (\S+) cd, (\S+) % of their peak, at γ (\S+)°\); the 0° plane is used for both$/, 'seamDiffers', (m) => ({ cd: num(m[1]), percent: num(m[2]), gamma: num(m[3]) })],
];

const PROBLEMS: readonly Pattern[] = [
  [/^the file is empty$/, 'fileEmpty', () => ({})],
  [/^no "TILT=" line found: not an IES LM-63 file$/, 'noTiltLine', () => ({})],
  [/^no "TILT=" line found in the first (\d+) lines: not an IES LM-63 file$/, 'noTiltLineIn', (m) => ({ lines: Number(m[1]) })],
  [/^the file is (\S+) MB, over the (\S+) MB limit for photometric files$/, 'fileTooBig', (m) => ({ size: num(m[1]), max: num(m[2]) })],
  [/^expected (\d+) (.+), found (\d+) \(the file ends early\)$/, 'endsEarly', (m) => ({ expected: Number(m[1]), what: m[2], found: Number(m[3]) })],
  [/^candela value (\S+) is out of range \(0 to (\S+) cd\)$/, 'candelaRange', (m) => ({ value: num(m[1]), max: num(m[2]) })],
  [/^integrated flux (\S+) lm is out of range \(0 to (\S+) lm\)$/, 'fluxRange', (m) => ({ value: num(m[1]), max: num(m[2]) })],
  [/^stated lumens (\S+) lm are out of range \((\S+) to (\S+) lm\)$/, 'statedLumensRange', (m) => ({ value: num(m[1]), min: num(m[2]), max: num(m[3]) })],
  [/^candela multiplier must be positive, found (.+)$/, 'multiplierNotPositive', (m) => ({ value: m[1] })],
  [/^ballast factor must be positive, found (.+)$/, 'ballastNotPositive', (m) => ({ value: m[1] })],
  [/^photometric type must be 1 \(C\), 2 \(B\) or 3 \(A\), found (.+)$/, 'photometricType', (m) => ({ value: m[1] })],
  [/^units type must be 1 \(feet\) or 2 \(metres\), found (.+)$/, 'unitsType', (m) => ({ value: m[1] })],
  [/^negative candela value (\S+) at (.+)$/, 'negativeCandela', (m) => ({ value: num(m[1]), at: m[2] })],
];

function match(patterns: readonly Pattern[], text: string): CodedText {
  for (const [re, code, params] of patterns) {
    const m = re.exec(text);
    if (m) {
      const p = { ...params(m) };
      // A count's noun ('vertical angles') becomes a code a UI words; one it does not know stays as written.
      if (typeof p.what === 'string' && NOUNS[p.what]) p.what = NOUNS[p.what];
      return { text, code, params: p };
    }
  }
  return { text };
}

/** A warning of photometryWarnings() with its code and params (`photometry.<code>`), or just the text for one not coded. */
export function codePhotometryWarning(text: string): CodedText {
  return match(WARNINGS, text);
}

/**
 * A photometric file's error message ("ies/x.ies line 12: problem", "ies/x.ies: problem") as the
 * file, the line and the problem, each coded where known; null when the message names no file.
 */
export function codePhotometryError(message: string): CodedText | null {
  const at = /^(.+?) line (\d+): (.*)$/s.exec(message);
  if (at) return { text: message, code: 'photometryErrorAt', params: { name: at[1], line: Number(at[2]) }, detail: match(PROBLEMS, at[3]) };
  const plain = /^(.+?): (.*)$/s.exec(message);
  if (plain) return { text: message, code: 'photometryError', params: { name: plain[1] }, detail: match(PROBLEMS, plain[2]) };
  return null;
}
