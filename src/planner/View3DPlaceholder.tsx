export interface View3DPlaceholderProps {
  luminaireCount: number;
  onBack: () => void;
}

/**
 * What the 2D/3D toggle opens until the lazily loaded three.js viewer exists. It renders
 * nothing pretending to be light: it says plainly that the 3D view is coming, and what it
 * will show, so no one mistakes it for a simulation result.
 */
export function View3DPlaceholder({ luminaireCount, onBack }: View3DPlaceholderProps) {
  return (
    <section className="view3d-placeholder" aria-labelledby="view3d-title" data-testid="view3d-placeholder">
      <div>
        <h2 id="view3d-title">3D view coming soon</h2>
        <p>
          The 3D view with the measured light of your {luminaireCount} {luminaireCount === 1 ? 'module' : 'modules'} is not
          available yet. Your configuration is ready for it; switch back to the 2D plan to keep editing.
        </p>
        <button type="button" className="btn btn-primary" onClick={onBack}>
          Back to 2D plan
        </button>
      </div>
    </section>
  );
}
