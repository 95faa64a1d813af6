// The consumer's shop page without <Luxbox>: the baseline whose first screen is subtracted to
// measure what luxbox/react adds to a React app (scripts/packageBudgets.mjs).
import { StrictMode, useState } from 'react';
import { createRoot } from 'react-dom/client';

function Shop() {
  const [total, setTotal] = useState(0);
  return (
    <>
      <p data-testid="shop-total">{total.toFixed(2)}</p>
      <button data-testid="shop-place-single" onClick={() => setTotal(total + 1)}>
        Single rail
      </button>
    </>
  );
}

createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <Shop />
  </StrictMode>,
);
