// `covmap serve`'s web page in headless Chromium, against a real server on a free
// loopback port: upload the Bern map with its sensors, watch the job finish, open its reports, see a
// bad map refused with the server's message, delete the job.
//
// Usage: node tests/browser/service_page_test.mjs path/to/covmap path/to/datasets path/to/artefact-dir
//
// The oracle is the server's own API (read with the browser's request context, not the page):
// the page shows the jobs GET /v1/audits lists, with their status and the files of a finished
// job; the report.json it links lists the map's 58 sensors. The page must load nothing but the
// server's own URLs (it works without the network), and log no console or page error.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createInterface } from 'node:readline';

import { launchBrowser, screenshot, ToolMissing } from './lib/browser.mjs';

const [covmap, datasets, artefacts] = process.argv.slice(2);
const JOB_TIMEOUT_MS = 120000;
const VIEWPORT = { width: 1280, height: 900 };
const failures = [];
const check = (ok, what) => { if (!ok) { failures.push(what); console.log(`FAIL: ${what}`); } return ok; };

// covmap serve on a free port; resolves to {process, base}.
function startServer(data) {
  return new Promise((resolvePromise, reject) => {
    const server = spawn(covmap, ['serve', '--port', '0', '--data', data, '--workers', '1'], { stdio: ['ignore', 'pipe', 'inherit'] });
    const lines = createInterface({ input: server.stdout });
    lines.once('line', (line) => {
      const match = /http:\/\/([^/]+)\//.exec(line);
      if (match) resolvePromise({ process: server, base: `http://${match[1]}` });
      else reject(new Error(`covmap serve did not start: ${line}`));
    });
    server.once('exit', (code) => reject(new Error(`covmap serve exited ${code}`)));
  });
}

async function main() {
  const data = mkdtempSync(join(tmpdir(), 'covmap-page-'));
  const server = await startServer(data);
  let browser;
  try {
    browser = await launchBrowser();
    const context = await browser.newContext({ viewport: VIEWPORT });
    const page = await context.newPage();
    const errors = [];
    const foreign = [];
    // Chromium logs every response of status >= 400 as a console error; the refused upload below is
    // one on purpose (its 400 is checked through the page's message instead).
    const expectedRefusal = /^Failed to load resource: the server responded with a status of 400/;
    page.on('console', (m) => { if (m.type() === 'error' && !expectedRefusal.test(m.text())) errors.push(m.text()); });
    page.on('pageerror', (e) => errors.push(String(e)));
    await context.route((url) => !url.href.startsWith(server.base), (route) => { foreign.push(route.request().url()); route.abort(); });
    await page.goto(server.base + '/', { waitUntil: 'load' });
    check(await page.locator('#no-jobs').isVisible(), 'a fresh server: "No audits yet." is not shown');

    // Upload and watch the job finish.
    const bern = join(datasets, 'maps', 'bern');
    await page.setInputFiles('#map', join(bern, 'map.geojson'));
    await page.setInputFiles('#sensors', join(bern, 'sensors.geojson'));
    await page.fill('#alpha', '3.5');
    await page.click('#submit');
    const done = page.locator('#jobs tbody tr[data-status="done"]');
    await done.first().waitFor({ timeout: JOB_TIMEOUT_MS });
    const jobs = (await (await context.request.get(server.base + '/v1/audits')).json()).jobs;
    check(jobs.length === 1 && jobs[0].status === 'done', `the API lists ${jobs.length} jobs, the first ${jobs[0]?.status}`);
    const row = page.locator(`#jobs tbody tr[data-id="${jobs[0].id}"]`);
    check(await row.count() === 1, 'the page has no row for the API\'s job');
    const links = await row.locator('a').evaluateAll((as) => as.map((a) => a.getAttribute('href')));
    check(JSON.stringify(links.sort()) === JSON.stringify(Object.values(jobs[0].files).sort()),
          `the row links ${links} but the job's files are ${Object.values(jobs[0].files)}`);
    const report = await (await context.request.get(server.base + jobs[0].files['report.json'])).json();
    check(report.sensors.length === 58, `the linked report.json lists ${report.sensors.length} sensors, not Bern's 58`);
    await screenshot(page, artefacts, 'service_page_done');

    // A bad map: the server's message on the page, no job added.
    const bad = join(data, 'broken.geojson');
    writeFileSync(bad, '{"type": "FeatureCollection", "features": [');
    await page.setInputFiles('#map', bad);
    await page.setInputFiles('#sensors', []);
    await page.click('#submit');
    const message = page.locator('#submit-error');
    await page.waitForFunction(() => document.getElementById('submit-error').textContent.length > 0);
    const text = await message.textContent();
    check(/^map/.test(text) && /JSON/i.test(text), `the refusal reads "${text}"`);
    const after = (await (await context.request.get(server.base + '/v1/audits')).json()).jobs;
    check(after.length === 1, `a refused upload left ${after.length - 1} job(s)`);
    await screenshot(page, artefacts, 'service_page_refused');

    // Delete the job from the page.
    await row.locator('button').click();
    await page.locator('#no-jobs').waitFor({ state: 'visible', timeout: 10000 });
    const left = (await (await context.request.get(server.base + '/v1/audits')).json()).jobs;
    check(left.length === 0, `after delete the API still lists ${left.length} job(s)`);

    check(errors.length === 0, `console or page errors: ${errors.join(' | ')}`);
    check(foreign.length === 0, `requests outside the server: ${foreign.join(', ')}`);
    await context.close();
  } finally {
    if (browser) await browser.close();
    server.process.kill('SIGTERM');
    rmSync(data, { recursive: true, force: true });
  }
  console.log(failures.length ? `service page: ${failures.length} failure(s)` : 'service page: all checks passed');
  process.exit(failures.length ? 1 : 0);
}

main().catch((error) => {
  console.log(`FAIL: ${error instanceof ToolMissing ? '' : 'error: '}${error.message}`);
  process.exit(1);
});
