import { resolve } from 'node:path'
import { defineConfig } from 'vitest/config'

export default defineConfig({
  resolve: {
    // the package's own names, for tests that run the README's examples as a user would write them
    alias: [
      { find: /^positron-ball-physics$/, replacement: resolve(import.meta.dirname, 'src/index.ts') },
      { find: /^positron-ball-physics\/ecs$/, replacement: resolve(import.meta.dirname, 'src/ecs.ts') },
      { find: /^positron-ball-physics\/reference$/, replacement: resolve(import.meta.dirname, 'src/reference/index.ts') },
    ],
  },
  test: {
    include: ['tests/**/*.test.ts'],
    environment: 'node',
    testTimeout: 60_000,
  },
})
