/** The configurator's top-level component (room setup, then the planner). */
export function App() {
  return (
    <main>
      <h1>luxbox</h1>
      <p>Set up your room to start configuring lights.</p>
    </main>
  );
}
