import type { BomLine } from '../../core/model/power/billOfMaterials';

/** One line of the demo shop's cart: what the host copied out of getBillOfMaterials(). */
export interface CartLine {
  readonly article: string;
  readonly name: string;
  readonly count: number;
  readonly unitPrice: number;
  readonly total: number;
}

const cents = (x: number) => Math.round(x * 100);

/**
 * The cart after adding a bill of materials: lines with an article already in the cart add to
 * its count, new articles are appended in BOM order. Totals are recomputed in integer cents, as
 * the BOM does, so the cart sum is exact to the cent.
 */
export function addToCart(cart: readonly CartLine[], lines: readonly BomLine[]): CartLine[] {
  const next = cart.map((l) => ({ ...l }));
  for (const line of lines) {
    const existing = next.find((l) => l.article === line.article);
    const count = (existing?.count ?? 0) + line.count;
    const merged = { article: line.article, name: line.name, count, unitPrice: line.unitPrice, total: (cents(line.unitPrice) * count) / 100 };
    if (existing) next[next.indexOf(existing)] = merged;
    else next.push(merged);
  }
  return next;
}

export function cartTotal(cart: readonly CartLine[]): number {
  return cart.reduce((sum, l) => sum + cents(l.total), 0) / 100;
}
