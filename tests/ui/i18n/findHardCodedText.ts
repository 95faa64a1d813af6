import ts from 'typescript';

/**
 * The no-hard-coded-text rule (docs/i18n.md, "No hard-coded text"), as a check on a .tsx file's
 * syntax tree. Reported as user-visible text:
 * - JSX text, and string/template literals rendered as JSX children (`{'Close'}`, `{open ? 'Close' : 'Open'}`);
 * - literals given to text props: aria-label, aria-description, aria-valuetext, aria-roledescription,
 *   title, placeholder, alt, label, and any prop whose name ends in Label, Title, Text, Hint,
 *   Message or Placeholder (`emptyLabel="…"`);
 * - literals in object properties named label, hint, title, text, message, placeholder,
 *   description, reason or notice (tables of fields or buttons rendered later), except in an
 *   object that also has a `code` (a coded message: its English is for logs and the API, the UI
 *   shows the code's translation) or an `ok` (an API result such as `{ ok: false, reason }`);
 * - arguments of alert(), confirm() and prompt().
 * A literal counts only if it contains a word: a run of letters that is not in WORDLESS, the
 * units and symbols every language writes the same (m, lx, cd, W, K, ρ, EV, the illuminance
 * symbols Ē, Emin, Emax, U0 of EN 12464-1, the name luxbox).
 */
export const WORDLESS = new Set(['m', 'mm', 'cm', 'm²', 'lx', 'lm', 'cd', 'sr', 'W', 'kW', 'V', 'K', 'EV', 'ρ', 'Ra', 'UGR', 'Ē', 'Emin', 'Emax', 'U', 'luxbox', 'x', 'y', 'z']);

const TEXT_PROPS = /^(aria-label|aria-description|aria-valuetext|aria-roledescription|title|placeholder|alt|label|\w*(Label|Title|Text|Hint|Message|Placeholder))$/;
const TEXT_KEYS = new Set(['label', 'hint', 'title', 'text', 'message', 'placeholder', 'description', 'reason', 'notice']);
const DIALOGS = new Set(['alert', 'confirm', 'prompt']);

export interface HardCodedText {
  file: string;
  line: number;
  text: string;
  /** Where it was found: 'jsx-text', 'prop <name>', 'key <name>', 'call <name>'. */
  where: string;
}

/** Whether `text` holds a word (a letter run outside WORDLESS). */
export function hasWord(text: string): boolean {
  for (const run of text.match(/\p{L}[\p{L}²]*/gu) ?? []) if (!WORDLESS.has(run)) return true;
  return false;
}

/** String and template literal pieces an expression can evaluate to directly (through ?:, &&, ||, ??, parentheses). */
function literalTexts(e: ts.Expression): string[] {
  if (ts.isStringLiteral(e) || ts.isNoSubstitutionTemplateLiteral(e)) return [e.text];
  if (ts.isTemplateExpression(e)) return [e.head.text, ...e.templateSpans.map((s) => s.literal.text)].filter((s) => s !== '').length ? [[e.head.text, ...e.templateSpans.map((s) => s.literal.text)].join(' ')] : [];
  if (ts.isParenthesizedExpression(e) || ts.isAsExpression(e)) return literalTexts(e.expression);
  if (ts.isConditionalExpression(e)) return [...literalTexts(e.whenTrue), ...literalTexts(e.whenFalse)];
  if (ts.isBinaryExpression(e)) {
    const op = e.operatorToken.kind;
    if (op === ts.SyntaxKind.AmpersandAmpersandToken) return literalTexts(e.right);
    if (op === ts.SyntaxKind.BarBarToken || op === ts.SyntaxKind.QuestionQuestionToken || op === ts.SyntaxKind.PlusToken) return [...literalTexts(e.left), ...literalTexts(e.right)];
  }
  return [];
}

function keyName(name: ts.PropertyName): string | null {
  return ts.isIdentifier(name) || ts.isStringLiteral(name) ? name.text : null;
}

/** Every piece of hard-coded user-visible text in one .tsx source. */
export function findHardCodedText(file: string, source: string): HardCodedText[] {
  const sf = ts.createSourceFile(file, source, ts.ScriptTarget.Latest, true, ts.ScriptKind.TSX);
  const found: HardCodedText[] = [];
  const report = (node: ts.Node, text: string, where: string) => {
    if (!hasWord(text)) return;
    found.push({ file, line: sf.getLineAndCharacterOfPosition(node.getStart(sf)).line + 1, text: text.trim().replace(/\s+/g, ' '), where });
  };
  const visit = (node: ts.Node) => {
    if (ts.isJsxText(node)) report(node, node.text, 'jsx-text');
    else if (ts.isJsxExpression(node) && node.expression && (ts.isJsxElement(node.parent) || ts.isJsxFragment(node.parent))) {
      for (const text of literalTexts(node.expression)) report(node, text, 'jsx-child');
    } else if (ts.isJsxAttribute(node)) {
      const name = node.name.getText(sf);
      if (TEXT_PROPS.test(name) && node.initializer) {
        const init = node.initializer;
        if (ts.isStringLiteral(init)) report(node, init.text, `prop ${name}`);
        else if (ts.isJsxExpression(init) && init.expression) for (const text of literalTexts(init.expression)) report(node, text, `prop ${name}`);
      }
    } else if (ts.isPropertyAssignment(node)) {
      const key = keyName(node.name);
      const coded = ts.isObjectLiteralExpression(node.parent) && node.parent.properties.some((p) => p.name !== undefined && ['code', 'ok'].includes(keyName(p.name as ts.PropertyName) ?? ''));
      if (key && TEXT_KEYS.has(key) && !coded) for (const text of literalTexts(node.initializer)) report(node, text, `key ${key}`);
    } else if (ts.isCallExpression(node)) {
      const callee = node.expression;
      const name = ts.isIdentifier(callee) ? callee.text : ts.isPropertyAccessExpression(callee) && ts.isIdentifier(callee.expression) && callee.expression.text === 'window' ? callee.name.text : null;
      if (name && DIALOGS.has(name)) for (const arg of node.arguments) for (const text of literalTexts(arg)) report(node, text, `call ${name}`);
    }
    ts.forEachChild(node, visit);
  };
  visit(sf);
  return found;
}
