// covmap audit's report.html in headless Chromium: what holds for any good report, at two widths.
//
// Usage: node tests/browser/report_test.mjs path/to/covmap path/to/datasets path/to/artefact-dir
//
// Audits the bundled Bern map as a user would (lib/covmap.mjs), opens report.html at each width in
// WIDTHS (height FIRST_SCREEN_HEIGHT, the "first screen") and checks, each separately
// (lib/checks.mjs): no console errors, no uncaught page errors, no request other than file: and
// data: URLs, no sideways scrolling, the verdict counts (elements with ids `count-…`) equal to the
// verdicts listed in report.json and inside the first screen, the map (MAP_SELECTOR) mostly inside the first screen. Screenshots of the first screen and of the
// whole page at each width go to the artefact directory, kept for people to look at.
//
// EXPECTED_TO_FAIL_UNTIL_REDESIGN lists the checks the page fails until its redesign; they are
// reported XFAIL, and as an error once they pass, so the list can only shrink.
import { openPage, screenshot } from './lib/browser.mjs';
import { expect } from './lib/checks.mjs';
import { runAuditedPageTest } from './lib/main.mjs';

// A laptop and a desktop screen, the widths the page must read well at.
const WIDTHS = [1280, 1920];
const FIRST_SCREEN_HEIGHT = 900;
// The share of the map's height that must lie inside the first screen for the map to count as
// part of it: most of the map, not its top edge.
const MAP_MIN_SHARE_IN_FIRST_SCREEN = 0.5;
// The map's element: the SVG #map of the page before its redesign, the #map-view that holds the
// canvas after it.
const MAP_SELECTOR = '#map-view, svg#map';
const MAP = 'bern';
// The member names of report.json's summary that are totals, not verdicts (docs/FORMATS.md).
const SUMMARY_TOTALS = new Set(['sensors', 'in_map', 'reported']);

export const EXPECTED_TO_FAIL_UNTIL_REDESIGN = [];

// The oracle: counts by verdict from the sensors listed in report.json (null = "unreported") and
// their total, keyed as the page's ids are: count-<verdict>, with the verdict's `_` written `-`
// (count-not-in-map).
function expectedCounts(report) {
  const counts = { sensors: report.sensors.length };
  for (const name of Object.keys(report.summary)) if (!SUMMARY_TOTALS.has(name)) counts[idKey(name)] = 0;
  for (const sensor of report.sensors) {
    const key = idKey(sensor.verdict ?? 'unreported');
    counts[key] = (counts[key] ?? 0) + 1;
  }
  return counts;
}

function idKey(verdict) {
  return verdict.replaceAll('_', '-');
}

// id suffix -> {text, visible, box} for every element whose id starts with count- and whose text
// is a number (the cards; not the sentence #count-sum).
async function shownCounts(page) {
  const shown = {};
  for (const element of await page.locator('[id^="count-"]').all()) {
    const text = (await element.textContent()).trim();
    if (!/^\d+$/.test(text)) continue;
    const id = await element.getAttribute('id');
    shown[id.slice('count-'.length)] = { value: Number(text), visible: await element.isVisible(),
                                         box: await element.boundingBox() };
  }
  return shown;
}

function outsideFirstScreen(box) {
  return !box || box.y < 0 || box.y + box.height > FIRST_SCREEN_HEIGHT;
}

async function checkWidth(run, browser, reportHtml, expected, artefacts, width) {
  const name = (what) => `${width}px: ${what}`;
  const { page, context, log } = await openPage(browser, reportHtml, { width, height: FIRST_SCREEN_HEIGHT });
  try {
    await run.check(name('screenshots saved'), async () => {
      await screenshot(page, artefacts, `report-${width}-first-screen`);
      await screenshot(page, artefacts, `report-${width}-full-page`, { fullPage: true, type: 'jpeg' });
    });
    await run.check(name('no console errors'), async () =>
      expect(log.consoleErrors.length === 0, 'none', log.consoleErrors.join(' | ')));
    await run.check(name('no uncaught page errors'), async () =>
      expect(log.pageErrors.length === 0, 'none', log.pageErrors.join(' | ')));
    await run.check(name('no request beyond file: and data:'), async () =>
      expect(log.remoteRequests.length === 0, 'none', log.remoteRequests.join(' | ')));
    await run.check(name('no horizontal overflow'), async () => {
      const { scrollWidth, innerWidth } = await page.evaluate(() => ({
        scrollWidth: document.scrollingElement.scrollWidth, innerWidth: window.innerWidth }));
      expect(scrollWidth <= innerWidth, `page width (scrollWidth) <= window width ${innerWidth} px`, `${scrollWidth} px`);
    });
    const shown = await shownCounts(page);
    // A good page may leave out a verdict nobody has; one it shows must say 0.
    await run.check(name('verdict counts equal report.json'), async () => {
      const wrong = Object.entries(expected)
        .filter(([key, value]) => (key in shown || value > 0) && shown[key]?.value !== value)
        .map(([key, value]) => `#count-${key} ${shown[key]?.value ?? 'missing'} (report.json: ${value})`);
      expect(wrong.length === 0, `the total and the counts by verdict of report.json's sensors ` +
             `${JSON.stringify(expected)}, each non-zero one shown`, wrong.join(', '));
    });
    // The total and every verdict somebody has; a count of 0 may sit lower or be left out.
    await run.check(name('verdict counts in the first screen'), async () => {
      const off = Object.keys(expected).filter((key) => expected[key] > 0)
        .filter((key) => !shown[key]?.visible || outsideFirstScreen(shown[key].box))
        .map((key) => `#count-${key} ${!shown[key] ? 'missing' : !shown[key].visible ? 'hidden'
          : `at y ${Math.round(shown[key].box.y)}..${Math.round(shown[key].box.y + shown[key].box.height)}`}`);
      expect(off.length === 0, `every non-zero #count-… visible within y 0..${FIRST_SCREEN_HEIGHT}`, off.join(', '));
    });
    await run.check(name('map in the first screen'), async () => {
      const map = page.locator(MAP_SELECTOR);
      expect(await map.count() === 1, `one element ${MAP_SELECTOR}`, `${await map.count()}`);
      const box = await map.boundingBox();
      expect(box && box.height > 0, `${MAP_SELECTOR} with a size`, JSON.stringify(box));
      const inside = Math.max(0, Math.min(box.y + box.height, FIRST_SCREEN_HEIGHT) - Math.max(box.y, 0));
      expect(inside >= MAP_MIN_SHARE_IN_FIRST_SCREEN * box.height,
             `at least ${MAP_MIN_SHARE_IN_FIRST_SCREEN * 100} % of the map's height within y 0..${FIRST_SCREEN_HEIGHT}`,
             `the map (${MAP_SELECTOR}) at y ${Math.round(box.y)}..${Math.round(box.y + box.height)}, ${Math.round(inside)} px inside`);
    });
  } finally {
    await context.close();
  }
}

process.exitCode = await runAuditedPageTest('report_test.mjs', process.argv.slice(2),
  { map: MAP, expectedToFail: EXPECTED_TO_FAIL_UNTIL_REDESIGN }, async (run, browser, audit, artefacts) => {
    const start = performance.now();
    const expected = expectedCounts(audit.report);
    for (const width of WIDTHS) await checkWidth(run, browser, audit.html, expected, artefacts, width);
    console.log(`screenshots: ${artefacts}; ${((performance.now() - start) / 1000).toFixed(1)} s`);
  });
