import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { ACTION_NAMES } from '../../src/core/model/actions/actionDefinitions';
import { ACTION_TABLE_END, ACTION_TABLE_START, actionTableMarkdown, withActionTable } from '../../scripts/actionTable';

const doc = readFileSync(join(__dirname, '../../docs/embedding.md'), 'utf8');

describe('the action table of docs/embedding.md (issue 33)', () => {
  it('is the one the registry generates: every action, with its parameters as its schema states them', () => {
    const block = doc.slice(doc.indexOf(ACTION_TABLE_START), doc.indexOf(ACTION_TABLE_END) + ACTION_TABLE_END.length);
    expect(block).toBe(actionTableMarkdown());
    for (const name of ACTION_NAMES) expect(block).toContain(`| \`${name}\` |`);
  });

  it('writes optional fields with ?, enums as their values and nested objects whole', () => {
    const table = actionTableMarkdown();
    expect(table).toContain('| `placePreset` | Place preset | `{ presetId: string, x?: number, z?: number, rotation?: number }` |');
    expect(table).toContain("'inside-centred' \\| 'outside-centred'");
    expect(table).toContain('| `aimAt` | Aim at | `{ moduleId: string, point: [number, number, number] }` |');
  });

  it('an out-of-date table is replaced between its markers, the rest of the page kept', () => {
    const stale = `before\n${ACTION_TABLE_START}\n| old |\n${ACTION_TABLE_END}\nafter`;
    expect(withActionTable(stale)).toBe(`before\n${actionTableMarkdown()}\nafter`);
    expect(() => withActionTable('no markers')).toThrow('markers are missing');
  });
});
