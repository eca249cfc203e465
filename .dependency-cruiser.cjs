/**
 * Import layering of the library (src/, systems/, components/), checked by
 * tests/layout.test.ts on every `npm test` and printed by `npm run depcruise`.
 *
 * Layers, lowest first; a module may import only from its own layer or lower:
 *   1a components/, src/config/, src/check.ts, src/events.ts, src/geometry.ts,
 *      src/clock.ts, src/math.ts, src/random.ts  (leaf utilities)
 *   1b src/reference/        (the rigid-sphere reference; may use 1a)
 *   2  src/world/
 *   3  src/motion/
 *   4  src/contacts/
 *   5  systems/ (incl. systems/variants/)
 *   6  src/schedule.ts
 *   7  src/commands/
 *   8  src/api/, src/panel.ts, src/physical/, src/index.ts, src/ecs.ts
 *   9  demo/, bench/, scripts/, tests/ (may import anything; never imported)
 *
 * Only runtime edges count: `import type` / `export type` are erased
 * (tsPreCompilationDeps: false). Under verbatimModuleSyntax an
 * `import { type X } from` with only type specifiers still loads the module
 * (it compiles to `import {} from`), so it does count.
 *
 * Paths in the rules match a module with any extension (`src/index\.`):
 * with TypeScript 7, which dependency-cruiser cannot load, the test cruises a
 * type-stripped .js copy of the tree (see tests/layout.test.ts).
 */

/** One alternative per layer, so the rules below read as "layer N -> above N". */
const L = {
  leaf: '^(components/|src/config/|src/(check|events|geometry|clock|math|random)\\.)',
  reference: '^src/reference/',
  world: '^src/world/',
  motion: '^src/motion/',
  contacts: '^src/contacts/',
  systems: '^systems/',
  schedule: '^src/schedule\\.',
  commands: '^src/commands/',
  top: '^(src/(api|physical)/|src/(panel|index|ecs)\\.)',
}

/** Everything strictly above the named layer. */
function above(layer) {
  const order = ['leaf', 'reference', 'world', 'motion', 'contacts', 'systems', 'schedule', 'commands', 'top']
  return order.slice(order.indexOf(layer) + 1).map((k) => L[k])
}

function notUp(name, layer, comment) {
  return {
    name,
    severity: 'error',
    comment,
    from: { path: L[layer] },
    to: { path: above(layer), dependencyTypesNot: ['type-only'] },
  }
}

/** @type {import('dependency-cruiser').IConfiguration} */
module.exports = {
  forbidden: [
    {
      name: 'no-circular',
      severity: 'error',
      comment: 'Runtime import cycles make module initialisation order-dependent; break the cycle.',
      from: {},
      to: { circular: true, viaOnly: { dependencyTypesNot: ['type-only'] } },
    },
    notUp(
      'leaf-not-up',
      'leaf',
      'components/, src/config/, check, events, geometry, clock are leaf utilities: they import nothing above them (not even src/reference/).',
    ),
    notUp('reference-not-up', 'reference', 'src/reference/ may use only the leaf utilities (config, geometry, events, ...).'),
    notUp('world-not-up', 'world', 'src/world/ may use only src/reference/ and the leaf utilities.'),
    notUp('motion-not-up', 'motion', 'src/motion/ may use only src/world/ and below.'),
    notUp('contacts-not-up', 'contacts', 'src/contacts/ may use only src/motion/, src/world/ and below.'),
    notUp('systems-not-up', 'systems', 'systems/ may use only src/contacts/ and below (not the schedule, commands or API).'),
    notUp('schedule-not-up', 'schedule', 'src/schedule.ts may use only systems/ and below.'),
    notUp('commands-not-up', 'commands', 'src/commands/ may use only src/schedule.ts and below (not the API or entry points).'),
    {
      name: 'library-not-tooling',
      severity: 'error',
      comment: 'The library (src/, systems/, components/) never imports demo/, bench/, scripts/ or tests/.',
      from: { path: '^(src|systems|components)/' },
      to: { path: '^(demo|bench|scripts|tests)/' },
    },
    {
      name: 'layer-unassigned',
      severity: 'error',
      comment:
        'Every library module belongs to a layer; a new file or folder outside the list escapes every rule. Add it to a layer in .dependency-cruiser.cjs.',
      from: {
        path: '^(src|systems|components)/',
        pathNot: Object.values(L),
      },
      to: {},
    },
    {
      name: 'not-to-unresolvable',
      severity: 'error',
      comment: 'This import resolves to nothing on disk (a typo, a moved file, or a missing package).',
      from: {},
      to: { couldNotResolve: true },
    },
    {
      name: 'no-orphans',
      severity: 'warn',
      comment: 'Nothing imports this module and it imports nothing: dead code, or an entry point to list here.',
      from: {
        orphan: true,
        pathNot: [
          '(^|/)[.][^/]+[.](?:js|cjs|mjs|ts|cts|mts|json)$', // dot files
          '[.]d[.]ts$',
          '(^|/)tsconfig[.]json$',
          '^src/(index|ecs)\\.', // package entry points
          '^src/reference/index\\.',
        ],
      },
      to: {},
    },
  ],
  options: {
    doNotFollow: { path: ['node_modules'] },
    // `import type` / `export type` are not runtime edges: look at the code
    // after the TypeScript types are stripped.
    tsPreCompilationDeps: false,
    // resolves the `.js` specifiers of the library to its `.ts` files
    tsConfig: { fileName: 'tsconfig.json' },
    enhancedResolveOptions: {
      exportsFields: ['exports'],
      conditionNames: ['import', 'require', 'node', 'default', 'types'],
      mainFields: ['module', 'main', 'types', 'typings'],
    },
    skipAnalysisNotInRules: true,
    reporterOptions: {
      text: { highlightFocused: true },
    },
  },
}
