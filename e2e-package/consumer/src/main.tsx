// A React shop's page: <Luxbox> from the installed tarball, its catalog as a URL, the cart total
// from onChange, and a button that runs a typed action through the ref.
import { StrictMode, useRef, useState } from 'react';
import { createRoot } from 'react-dom/client';
import { Luxbox, type BillOfMaterials, type LuxboxInstance } from 'luxbox/react';

declare global {
  interface Window {
    shop?: { instance: LuxboxInstance | null; errors: string[] };
  }
}

window.shop = { instance: null, errors: [] };

function Shop() {
  const luxbox = useRef<LuxboxInstance>(null);
  const [bom, setBom] = useState<BillOfMaterials | null>(null);
  return (
    <>
      <p data-testid="shop-total">{bom ? `${bom.total.toFixed(2)} ${bom.currency}` : '–'}</p>
      <button data-testid="shop-place-single" onClick={() => luxbox.current?.runAction('placePreset', { presetId: 'single' })}>
        Single rail
      </button>
      <Luxbox
        ref={luxbox}
        catalog="/catalog/catalog.json"
        locale="de-CH"
        room={{ width: 6, depth: 4.5, height: 3 }}
        quality="fast"
        style={{ height: '640px' }}
        onReady={(instance) => {
          window.shop!.instance = instance;
        }}
        onError={(error) => window.shop!.errors.push(error.message)}
        onChange={() => setBom(luxbox.current!.getBillOfMaterials())}
      />
    </>
  );
}

createRoot(document.getElementById('root')!).render(
  <StrictMode>
    <Shop />
  </StrictMode>,
);
