// A tiny runner for the browser tests: each check is reported on its own line, and the process
// fails if any does (docs/RELIABILITY.md, "Browser tests").
//
// Contract:
// - const run = new CheckRunner({ expectedToFail: [...names] }); await run.check(name, async () => {...})
//   runs one check. A check passes when its function returns; it fails when it throws. Throw
//   CheckFailed (or use expect/expectEqual) so that the message says what was expected and what was
//   seen; any other exception is reported as a failure too, with its message.
// - Names are unique (a repeated name is an error in the test itself).
// - A failing check whose name is in expectedToFail is XFAIL (known, not an error); one in the list
//   that passes is XPASS, an error: take it out of the list. A listed name that no check used is
//   an error as well (a renamed check would otherwise hide), unless run.fatal() stopped the test.
// - run.finish() prints the tally and returns the exit code: 0 when nothing is FAIL or XPASS.

export class CheckFailed extends Error {
  constructor(expected, saw) {
    super(`expected ${expected}; saw ${saw}`);
  }
}

export function expect(condition, expected, saw) {
  if (!condition) throw new CheckFailed(expected, typeof saw === 'function' ? saw() : saw);
}

export function expectEqual(saw, expected, what) {
  const text = (value) => JSON.stringify(value);
  if (text(saw) !== text(expected)) throw new CheckFailed(`${what} = ${text(expected)}`, text(saw));
}

const Outcome = Object.freeze({ PASS: 'PASS', FAIL: 'FAIL', XFAIL: 'XFAIL', XPASS: 'XPASS' });
const ERRORS = new Set([Outcome.FAIL, Outcome.XPASS]);

export class CheckRunner {
  constructor({ expectedToFail = [] } = {}) {
    this.expectedToFail = new Set(expectedToFail);
    this.outcomes = new Map();
    this.problems = [];
  }

  async check(name, body) {
    if (this.outcomes.has(name)) {
      this.problems.push(`check name used twice: "${name}"`);
      return false;
    }
    let failure = null;
    try {
      await body();
    } catch (error) {
      failure = error instanceof CheckFailed ? error.message : `threw ${error.stack || error}`;
    }
    const expectedToFail = this.expectedToFail.has(name);
    const outcome = failure ? (expectedToFail ? Outcome.XFAIL : Outcome.FAIL)
                            : (expectedToFail ? Outcome.XPASS : Outcome.PASS);
    this.outcomes.set(name, outcome);
    const note = outcome === Outcome.XPASS ? ': passes now; remove it from the expected-to-fail list' : '';
    console.log(`${outcome.padEnd(5)} ${name}${failure ? `: ${failure}` : note}`);
    return !failure;
  }

  // For a problem outside any one check (e.g. the audit that makes the page failed).
  fatal(message) {
    this.problems.push(message);
  }

  finish() {
    // After a fatal problem the checks did not run, and their names say nothing.
    const ranAll = this.problems.length === 0;
    for (const name of this.expectedToFail) {
      if (ranAll && !this.outcomes.has(name)) this.problems.push(`expected-to-fail name matches no check: "${name}"`);
    }
    for (const problem of this.problems) console.log(`ERROR ${problem}`);
    const tally = Object.values(Outcome)
      .map((outcome) => `${[...this.outcomes.values()].filter((o) => o === outcome).length} ${outcome}`)
      .join(', ');
    const failed = this.problems.length > 0 || [...this.outcomes.values()].some((o) => ERRORS.has(o));
    console.log(`${failed ? 'FAILED' : 'OK'}: ${tally}${this.problems.length ? `, ${this.problems.length} ERROR` : ''}`);
    return failed ? 1 : 0;
  }
}
