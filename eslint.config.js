import js from '@eslint/js';
import tseslint from 'typescript-eslint';
import reactHooks from 'eslint-plugin-react-hooks';
import globals from 'globals';

// Build output (the app's dist/, the package's lib/ and build/), test artefacts, docs.
const ignores = ['dist/**', 'lib/**', 'build/**', 'node_modules/**', 'test-results/**', 'playwright-report/**', 'out/**', 'docs/**', 'gpu-pack/**', '.venv/**'];

export default tseslint.config({ ignores }, js.configs.recommended, ...tseslint.configs.recommended, {
  files: ['**/*.{ts,tsx,js,mjs}'],
  languageOptions: { globals: { ...globals.browser, ...globals.node } },
  plugins: { 'react-hooks': reactHooks },
  rules: {
    ...reactHooks.configs.recommended.rules,
    '@typescript-eslint/no-unused-vars': ['error', { argsIgnorePattern: '^_', varsIgnorePattern: '^_' }],
  },
});
