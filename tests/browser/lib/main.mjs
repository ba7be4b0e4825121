// The frame every browser test shares: read the command line, start Chromium, audit a bundled map,
// run the test's checks, report, clean up.
//
// Contract: runAuditedPageTest(script, argv, {map, extraArgs, expectedToFail}, body) reads argv as
// `path/to/covmap path/to/datasets path/to/artefact-dir` (usage and 2 when one is missing), audits
// datasets/maps/<map> with extraArgs (lib/covmap.mjs), and calls body(run, browser, audit,
// artefacts) with a CheckRunner. Returns the exit code: run.finish()'s, 1 when Chromium or
// playwright-core is missing (with how to install it; never a skip), and a fatal check when the
// audit fails. The browser is closed and the audit's folder removed whatever happens.
import { launchBrowser, ToolMissing } from './browser.mjs';
import { CheckRunner } from './checks.mjs';
import { auditBundledMap, removeAudit } from './covmap.mjs';

export async function runAuditedPageTest(script, argv, { map, extraArgs = [], expectedToFail = [] }, body) {
  const [covmap, datasets, artefacts] = argv;
  if (!covmap || !datasets || !artefacts) {
    console.error(`usage: node ${script} path/to/covmap path/to/datasets path/to/artefact-dir`);
    return 2;
  }
  const run = new CheckRunner({ expectedToFail });
  let browser = null;
  let audit = null;
  try {
    browser = await launchBrowser();
    try {
      audit = auditBundledMap(covmap, datasets, map, extraArgs);
    } catch (error) {
      run.fatal(`covmap audit of the bundled ${map} map failed: ${error.message}`);
      return run.finish();
    }
    await body(run, browser, audit, artefacts);
    return run.finish();
  } catch (error) {
    if (!(error instanceof ToolMissing)) throw error;
    console.error(`browser tests cannot run: ${error.message}`);
    return 1;
  } finally {
    if (browser) await browser.close();
    removeAudit(audit);
  }
}
