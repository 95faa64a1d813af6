/**
 * The reason a tip shows next to a one-tap remedy (docs/planner.md, "Reasons at the control"). The
 * model's refusals state the problem first and then, after a semicolon, where to go to fix it by
 * hand ("the 240 W driver is full: 234 W used; choose the 321.6 W driver in the system options or
 * add a second feed"), in every language. Next to a button that performs the fix, sending the
 * shopper elsewhere is wrong, so the tip keeps the problem only; the full sentence stays the
 * control's title and the status line's text, where no remedy is offered.
 */
export function reasonBesideRemedy(reason: string): string {
  // French puts a narrow no-break space before the semicolon: trim any space that ends the problem.
  const cut = reason.indexOf(';');
  return cut > 0 ? reason.slice(0, cut).trimEnd() : reason;
}
