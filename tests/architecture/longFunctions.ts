import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import ts from 'typescript';

/** One function (declaration, expression, arrow, method, accessor, constructor) and its length in lines. */
export interface FunctionLength {
  /** Repo-relative path with forward slashes. */
  file: string;
  /** The name a reader finds it by: its own, the variable or property it is assigned to, or `<anonymous>`. */
  name: string;
  /** 1-based line of its first token (not its leading comment). */
  line: number;
  /** Lines from its first token to its last, both included (a nested function counts inside its parent too). */
  lines: number;
}

function nameOf(node: ts.FunctionLikeDeclaration): string {
  if (node.name && (ts.isIdentifier(node.name) || ts.isStringLiteral(node.name) || ts.isPrivateIdentifier(node.name))) return node.name.text;
  if (ts.isConstructorDeclaration(node)) return 'constructor';
  const parent = node.parent;
  if (ts.isVariableDeclaration(parent) && ts.isIdentifier(parent.name)) return parent.name.text;
  if (ts.isPropertyAssignment(parent) && (ts.isIdentifier(parent.name) || ts.isStringLiteral(parent.name))) return parent.name.text;
  if (ts.isPropertyDeclaration(parent) && ts.isIdentifier(parent.name)) return parent.name.text;
  // A component wrapped in memo()/forwardRef(), a callback handed to useEffect(): name it after the call.
  if (ts.isCallExpression(parent)) {
    const callee = parent.expression.getText();
    const holder = parent.parent;
    if (ts.isVariableDeclaration(holder) && ts.isIdentifier(holder.name)) return `${holder.name.text} (${callee})`;
    return `<${callee} callback>`;
  }
  return '<anonymous>';
}

/** Every function in one source text, with its length. */
export function functionLengths(file: string, text: string): FunctionLength[] {
  const kind = file.endsWith('.tsx') ? ts.ScriptKind.TSX : ts.ScriptKind.TS;
  const source = ts.createSourceFile(file, text, ts.ScriptTarget.Latest, true, kind);
  const out: FunctionLength[] = [];
  const visit = (node: ts.Node): void => {
    if (ts.isFunctionLike(node) && 'body' in node && node.body) {
      const fn = node as ts.FunctionLikeDeclaration;
      const first = source.getLineAndCharacterOfPosition(fn.getStart(source)).line;
      const last = source.getLineAndCharacterOfPosition(fn.getEnd()).line;
      out.push({ file, name: nameOf(fn), line: first + 1, lines: last - first + 1 });
    }
    ts.forEachChild(node, visit);
  };
  visit(source);
  return out;
}

function listSources(dir: string, out: string[]): string[] {
  for (const name of readdirSync(dir)) {
    const path = join(dir, name);
    if (statSync(path).isDirectory()) listSources(path, out);
    else if (/\.tsx?$/.test(name) && !name.endsWith('.d.ts')) out.push(path.split('\\').join('/'));
  }
  return out;
}

/** Every function under `dir` (repo-relative, e.g. `src`). */
export function readFunctionLengths(dir: string): FunctionLength[] {
  return listSources(dir, []).flatMap((file) => functionLengths(file, readFileSync(file, 'utf8')));
}

/** `file:name` for each function longer than `limit` lines that `allowed` does not name, with its length. */
export function longFunctionViolations(functions: readonly FunctionLength[], limit: number, allowed: ReadonlySet<string>): string[] {
  return functions.filter((f) => f.lines > limit && !allowed.has(`${f.file}:${f.name}`)).map((f) => `${f.file}:${f.name} (line ${f.line}) is ${f.lines} lines, over ${limit}`);
}
