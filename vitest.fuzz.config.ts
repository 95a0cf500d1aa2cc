import { defineConfig } from 'vitest/config';
import unit from './vitest.config';

/**
 * `npm run fuzz`: the property suites only, with many seeds (test/property/settings.ts) and no time
 * limit. (Spread, not mergeConfig: that would add the unit run's include globs to these.)
 */
export default defineConfig({
  ...unit,
  test: {
    ...unit.test,
    include: ['test/property/**/*.test.ts'],
    testTimeout: 0,
    env: { FULCRUM_FUZZ: '1' },
  },
});
