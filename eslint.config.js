// ESLint's configuration (`npx eslint .`, run by scripts/test): the page's
// classic scripts (web/js), the browser tests and the benchmarks (node
// modules that also hand functions to the page), and this file. ESLint's
// recommended rules, a few more that catch real mistakes, and none turned
// off. web/gen is generated (by `manifold build`, from the Haskell library)
// and not linted.
"use strict";
const js = require("@eslint/js");
const globals = require("globals");

// Browser globals whose names are also likely names of one's own variables:
// a forgotten declaration would quietly read window.name, window.event, …
// instead of failing (no-undef does not see them).
const CONFUSING_GLOBALS = ["event", "name", "status", "length", "top", "parent", "self", "origin",
  "closed", "opener", "frames", "external", "screen", "find", "print", "stop"];

// Rules beyond the recommended ones, each for a kind of bug.
const BUG_RULES = {
  // a map/filter/reduce callback that forgets to return
  "array-callback-return": ["error", { checkForEach: false }],
  // `x == y` coerces; every comparison in this code means ===
  eqeqeq: ["error", "always"],
  // a statement that computes and drops a value (`a && b;`, `x === 1;`)
  "no-unused-expressions": ["error", { enforceForJSX: false }],
  "no-self-compare": "error",
  // "${x}" in a plain string was meant to be a template
  "no-template-curly-in-string": "error",
  "no-unreachable-loop": "error",
  // throw "text" loses the stack; throw an Error
  "no-throw-literal": "error",
  "no-restricted-globals": ["error", ...CONFUSING_GLOBALS],
  // a `let` or `const` read before its declaration runs throws; functions are hoisted
  "no-use-before-define": ["error", { functions: false, classes: true, variables: true }],
  // an unused variable is usually a mistake; a caught error left unused is
  // deliberate (`catch (err) { /* why it is ignored */ }`)
  "no-unused-vars": ["error", { caughtErrors: "none" }],
};

module.exports = [
  { ignores: ["web/gen/**", "node_modules/**", "test-output/**", "dist-newstyle/**", ".stack-work/**"] },
  js.configs.recommended,
  { rules: BUG_RULES },
  {
    // the page: classic scripts, one IIFE each, in the browser (world.js also under node's vm)
    files: ["web/js/**/*.js"],
    languageOptions: { ecmaVersion: 2022, sourceType: "script", globals: { ...globals.browser } },
    rules: {
      // each file's function is strict ("use strict" in the IIFE)
      strict: ["error", "function"],
      // nothing leaks into the page's global scope but what a file exports
      // (its module's var, named in /* exported */)
      "no-implicit-globals": "error",
    },
  },
  {
    // the browser tests and the benchmarks: node modules whose page.evaluate
    // callbacks run in the page (so browser globals too)
    files: ["test/**/*.mjs", "bench/**/*.mjs"],
    languageOptions: { ecmaVersion: 2022, sourceType: "module", globals: { ...globals.node, ...globals.browser } },
  },
  {
    // the peer benchmark's classic script, run both under node (vm) and in the page
    files: ["bench/**/*.js"],
    languageOptions: { ecmaVersion: 2022, sourceType: "script", globals: { ...globals.node, ...globals.browser } },
  },
  {
    files: ["eslint.config.js"],
    languageOptions: { ecmaVersion: 2022, sourceType: "commonjs", globals: { ...globals.node } },
  },
];
