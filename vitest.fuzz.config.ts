import { defineConfig, mergeConfig } from 'vitest/config';
import unit from './vitest.config';

/** `npm run fuzz`: the property suites only, with many seeds (test/property/settings.ts) and no time limit. */
export default mergeConfig(
  unit,
  defineConfig({
    test: {
      include: ['test/property/**/*.test.ts'],
      testTimeout: 0,
      env: { FULCRUM_FUZZ: '1' },
    },
  }),
);
