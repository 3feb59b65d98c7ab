// The command lines of the bench scripts and of the browser test runner:
// positional arguments first, then `--name value` options from the script's
// own list. `--help` (or `-h`) prints the usage and exits; an unknown
// option, an option without its value or a missing positional argument
// prints the usage to standard error and exits with 2, so that a mistyped
// option is never silently ignored (the script would run with its default,
// and report.mjs would rewrite bench/README.md). A flag (from the list
// `flags`) takes no value.
function fail(message) {
  console.error(message);
  process.exit(2);
}

// usage: the usage line; positional: how many arguments come before the
// options; known: the option names; flags: the names of options without a
// value. Returns the positional arguments, flag (whether a flag is given)
// and readers of an option's value (each given the default for when it is
// absent): text, count (a whole number from min), positive, nonNegative.
export function commandLine({ usage, positional = 0, known, flags = [], argv = process.argv.slice(2) }) {
  const line = "usage: " + usage;
  if (argv.includes("--help") || argv.includes("-h")) { console.log(line); process.exit(0); }
  const args = argv.slice(0, positional);
  if (args.length < positional || args.some((a) => a.startsWith("--"))) fail(line);
  const values = new Map(), given = new Set();
  for (let i = positional; i < argv.length; i += 2) {
    const name = argv[i], value = argv[i + 1];
    if (flags.includes(name)) { given.add(name); i--; continue; }
    if (!known.includes(name)) fail(name + ": no such option\n" + line);
    if (value === undefined) fail(name + ": needs a value\n" + line);
    values.set(name, value);
  }
  const text = (name, dflt) => (values.has(name) ? values.get(name) : dflt);
  const number = (name, dflt, ok, what) => {
    if (!values.has(name)) return dflt;
    const x = Number(values.get(name));
    if (values.get(name).trim() === "" || !ok(x)) fail(name + " must be " + what + " (not " + JSON.stringify(values.get(name)) + ")");
    return x;
  };
  return {
    positional: args,
    flag: (name) => given.has(name),
    text,
    // a whole number, at least min
    count: (name, dflt, min) => number(name, dflt, (x) => Number.isInteger(x) && x >= min, "a whole number ≥ " + min),
    // a finite number above 0
    positive: (name, dflt) => number(name, dflt, (x) => isFinite(x) && x > 0, "a positive number"),
    // a finite number, at least 0
    nonNegative: (name, dflt) => number(name, dflt, (x) => isFinite(x) && x >= 0, "a number ≥ 0"),
  };
}
