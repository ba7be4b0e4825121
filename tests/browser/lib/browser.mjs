// Opening covmap's HTML pages in headless Chromium for the browser tests (docs/RELIABILITY.md,
// "Browser tests").
//
// Contract:
// - launchBrowser() starts Debian's chromium ($CHROMIUM, else /usr/bin/chromium) through npm's
//   playwright-core. When either is missing it throws ToolMissing, whose message says how to install
//   it; a test turns that into a failure, never a skip (CI installs both).
// - openPage(browser, file, viewport) loads a local file as a file:// URL in a fresh context and
//   records, from before the first byte, every console error, every uncaught page error and every
//   request whose URL is not file: or data: (such requests are also aborted: the report must work
//   offline, and a test must never reach the network).
// - screenshot(page, dir, name, {fullPage, type}) writes dir/name.png (or .jpg for type 'jpeg')
//   and returns its path.
import { existsSync, mkdirSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

export const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
// Waits that bound a hung browser; far above what a healthy run takes.
export const LAUNCH_TIMEOUT_MS = 20000;
export const LOAD_TIMEOUT_MS = 15000;
// JPEG for long pages: a full-page PNG of a report takes much longer to encode, for no visible gain.
export const JPEG_QUALITY = 80;
// URL schemes a self-contained page may load from.
const LOCAL_SCHEMES = ['file:', 'data:'];

export class ToolMissing extends Error {}

const HOW_TO_INSTALL =
  'install with `bash scripts/setup-debian.sh && bash scripts/setup-browser-tests.sh` ' +
  '(scripts/build.sh runs both)';

async function loadPlaywright() {
  try {
    return await import('playwright-core');
  } catch (error) {
    throw new ToolMissing(`npm package playwright-core not found in tests/browser/node_modules ` +
                          `(${error.code || error.message}); ${HOW_TO_INSTALL}`);
  }
}

export async function launchBrowser() {
  if (!existsSync(CHROMIUM)) {
    throw new ToolMissing(`Chromium not found at ${CHROMIUM} (set $CHROMIUM to use another); ` +
                          `Debian package \`chromium\`: ${HOW_TO_INSTALL}`);
  }
  const { chromium } = await loadPlaywright();
  // --no-sandbox: CI runs as root, where Chromium refuses to start its sandbox.
  return chromium.launch({ executablePath: CHROMIUM, args: ['--no-sandbox'], timeout: LAUNCH_TIMEOUT_MS });
}

function isLocal(url) {
  return LOCAL_SCHEMES.some((scheme) => url.startsWith(scheme));
}

// Returns {page, context, log}; log.consoleErrors, log.pageErrors and log.remoteRequests are
// arrays of strings filled while the page lives. Close with `await context.close()`.
export async function openPage(browser, file, viewport) {
  const context = await browser.newContext({ viewport });
  const page = await context.newPage();
  const log = { consoleErrors: [], pageErrors: [], remoteRequests: [] };
  page.on('console', (message) => {
    if (message.type() === 'error') {
      const where = message.location();
      log.consoleErrors.push(`${message.text()} (${where.url || file}:${where.lineNumber})`);
    }
  });
  // The message and the innermost frame: enough to find the line in the page.
  page.on('pageerror', (error) => log.pageErrors.push(String(error.stack || error).split('\n').slice(0, 2)
    .map((line) => line.trim()).join(' ')));
  page.on('request', (request) => {
    if (!isLocal(request.url())) log.remoteRequests.push(`${request.method()} ${request.url()}`);
  });
  await context.route((url) => !isLocal(url.href), (route) => route.abort('blockedbyclient'));
  await page.goto(pathToFileURL(resolve(file)).href, { waitUntil: 'load', timeout: LOAD_TIMEOUT_MS });
  return { page, context, log };
}

export async function screenshot(page, dir, name, { fullPage = false, type = 'png' } = {}) {
  mkdirSync(dir, { recursive: true });
  const path = join(dir, `${name}.${type === 'jpeg' ? 'jpg' : type}`);
  await page.screenshot({ path, fullPage, type, ...(type === 'jpeg' ? { quality: JPEG_QUALITY } : {}) });
  return path;
}
