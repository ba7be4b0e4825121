// report.html's interactions in headless Chromium: filtering and searching the table,
// the default worst-first order, a row click centring the map on the sensor and outlining its cell,
// hover details, lon/lat under the cursor, the scale bar, the legend, and the size of what is put
// on the page. The oracle is always report.json (or sensors.geojson) of the same audit, never the
// page's own data.
//
// Usage: node tests/browser/report_features_test.mjs path/to/covmap path/to/datasets path/to/artefact-dir
import { openPage, screenshot } from './lib/browser.mjs';
import { expect, expectEqual } from './lib/checks.mjs';
import { runAuditedPageTest } from './lib/main.mjs';

const VIEWPORT = { width: 1280, height: 900 };
const MAP = 'bern';
// The table shows this many rows before "show more" (report/html/report.js, kPage).
const TABLE_PAGE = 200;
// A dot's centre lands on the 0.1 px grid and then on a device pixel: 1.5 px covers both.
const CENTRE_TOLERANCE_PX = 1.5;
// The cursor's lon/lat: mouse events carry whole CSS pixels, so the point under the cursor may be
// this many pixels from the dot's exact centre (whose grid position is itself rounded to 0.1 px).
const CURSOR_TOLERANCE_PX = 1.5;
const METRES_PER_DEGREE_LAT = 111000;
// Scale bar against two sensors' distance: the projection's scale distortion is ~1e-4 here, the
// dots' rounding a fraction of a pixel over hundreds.
const SCALE_TOLERANCE = 0.01;
// The highlight colour of a selected cell (report.js): #ffd400.
const HIGHLIGHT = [255, 212, 0];

const verdictOf = (s) => s.verdict ?? 'unreported';

// The documented order of attention (docs/FORMATS.md, sensors_by_severity), from report.json.
const RANK = { inconsistent: 0, model_misfit: 1, not_in_map: 2, unreported: 3, undetermined: 4, consistent: 5 };
function worstFirst(sensors) {
  const key = (v) => (v === null || v === undefined ? Infinity : -v);
  return [...sensors].sort((a, b) => RANK[verdictOf(a)] - RANK[verdictOf(b)] || key(a.chi2) - key(b.chi2) ||
    key(a.reported ? a.position_error_m : null) - key(b.reported ? b.position_error_m : null) ||
    (a.id < b.id ? -1 : a.id > b.id ? 1 : 0));
}

const tableIds = (page) => page.$$eval('#sensor-table tbody tr', (rows) => rows.map((r) => r.dataset.sensorId));

// How many canvas pixels are close to `rgb`, over the whole canvas.
function countColour(page, rgb) {
  return page.evaluate((rgb) => {
    const canvas = document.getElementById('map-canvas');
    const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    let n = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      if (Math.abs(pixels[i] - rgb[0]) < 12 && Math.abs(pixels[i + 1] - rgb[1]) < 12 && Math.abs(pixels[i + 2] - rgb[2]) < 12) ++n;
    }
    return n;
  }, rgb);
}

async function canvasCentre(page) {
  const box = await page.locator('#map-canvas').boundingBox();
  return [box.x + box.width / 2, box.y + box.height / 2];
}

function haversineMetres(a, b) {
  const r = 6371008.8, rad = Math.PI / 180;
  const dlat = (b.lat - a.lat) * rad, dlon = (b.lon - a.lon) * rad;
  const h = Math.sin(dlat / 2) ** 2 + Math.cos(a.lat * rad) * Math.cos(b.lat * rad) * Math.sin(dlon / 2) ** 2;
  return 2 * r * Math.asin(Math.sqrt(h));
}

async function checks(run, page, report, artefacts) {
  const sensors = report.sensors;
  const inconsistent = sensors.filter((s) => verdictOf(s) === 'inconsistent');
  expect(inconsistent.length >= 2, 'a bundled map with at least two inconsistent sensors', inconsistent.length);

  await run.check('table: worst first by default', async () => {
    const want = worstFirst(sensors).slice(0, TABLE_PAGE).map((s) => s.id);
    expectEqual(await tableIds(page), want, 'row ids in order');
  });

  await run.check('table: filter by verdict', async () => {
    for (const box of await page.locator('input[name="verdict-filter"]').all()) {
      if ((await box.getAttribute('value')) !== 'inconsistent') await box.uncheck();
    }
    const ids = await tableIds(page);
    expectEqual([...ids].sort(), inconsistent.map((s) => s.id).sort(), 'ids of the rows left');
    await page.click('#filter-all');
    expectEqual((await tableIds(page)).length, Math.min(TABLE_PAGE, sensors.length), 'rows after "all"');
  });

  await run.check('table: search by id', async () => {
    const target = inconsistent[1];
    const query = target.id.slice(0, Math.max(3, target.id.length - 2));
    await page.fill('#sensor-search', query);
    const want = sensors.filter((s) => s.id.toLowerCase().includes(query.toLowerCase()) ||
                                       (s.name ?? '').toLowerCase().includes(query.toLowerCase())).map((s) => s.id);
    expectEqual([...(await tableIds(page))].sort(), want.sort(), `rows matching "${query}"`);
    await page.fill('#sensor-search', '');
  });

  await run.check('row click centres the map on the sensor and outlines its cell', async () => {
    const target = inconsistent[0];
    expectEqual(await countColour(page, HIGHLIGHT), 0, 'highlight pixels before any selection');
    await page.click(`#sensor-table tbody tr[data-sensor-id="${target.id}"]`);
    await page.waitForFunction(() => window.covmapReport.selected() !== null);
    expectEqual(await page.evaluate(() => window.covmapReport.selected()), target.id, 'selected sensor');
    const [cx, cy] = await canvasCentre(page);
    const at = await page.evaluate((id) => window.covmapReport.screenPosition(id), target.id);
    expect(Math.hypot(at[0] - cx, at[1] - cy) <= CENTRE_TOLERANCE_PX, `sensor at the canvas centre (${cx}, ${cy})`, at);
    await page.waitForTimeout(100);  // one animation frame
    expect(await countColour(page, HIGHLIGHT) > 50, 'the selected cell outlined in #ffd400', 'no highlight pixels');
    expect(await page.isVisible('#map-selection'), 'the selection box shown', 'hidden');
    expect((await page.textContent('#map-selection')).includes(target.id), `selection box naming ${target.id}`,
           await page.textContent('#map-selection'));
  });

  await run.check('hover shows the sensor, its verdict and the numbers behind it', async () => {
    const target = inconsistent[0];  // selected above: the map is zoomed onto it
    const at = await page.evaluate((id) => window.covmapReport.screenPosition(id), target.id);
    await page.mouse.move(at[0], at[1]);
    await page.waitForSelector('#map-tooltip:not([hidden])');
    const text = await page.textContent('#map-tooltip');
    const off = target.position_error_m >= 1000 ? `${(target.position_error_m / 1000).toPrecision(3)} km`
                                                : `${target.position_error_m.toPrecision(3)} m`;
    for (const part of [target.id, 'inconsistent', off, target.chi2.toPrecision(3)]) {
      expect(text.includes(part), `tooltip containing "${part}"`, text);
    }
  });

  await run.check('cursor coordinates are the sensor\'s lon/lat', async () => {
    const target = inconsistent[0];
    const at = await page.evaluate((id) => window.covmapReport.screenPosition(id), target.id);
    await page.mouse.move(at[0], at[1]);
    const text = await page.textContent('#map-coords');
    const m = text.match(/([\d.]+)° ([NS]), ([\d.]+)° ([EW])/);
    expect(m, 'coordinates like "46.94812° N, 7.44744° E"', text);
    const lat = Number(m[1]) * (m[2] === 'S' ? -1 : 1), lon = Number(m[3]) * (m[4] === 'W' ? -1 : 1);
    // The tolerance in degrees from the scale bar's metres per pixel (checked against the sensors below).
    const bar = await page.$eval('#scale-bar', (e) => Number(e.dataset.metres) / Number(e.dataset.pixels));
    const tolerance = (CURSOR_TOLERANCE_PX * bar) / METRES_PER_DEGREE_LAT + 1e-5;
    const dLat = Math.abs(lat - target.lat), dLon = Math.abs(lon - target.lon) * Math.cos(target.lat * Math.PI / 180);
    expect(dLat < tolerance && dLon < tolerance,
           `lon/lat of ${target.id} from report.json (${target.lon}, ${target.lat}) within ${tolerance.toExponential(1)}°`, text);
  });

  await run.check('the dot drawn at a sensor has its verdict\'s colour', async () => {
    await page.click('#zoom-home');
    const target = inconsistent[1];
    const at = await page.evaluate((id) => window.covmapReport.screenPosition(id), target.id);
    const box = await page.locator('#map-canvas').boundingBox();
    const rgb = await page.evaluate(([x, y]) => {
      const canvas = document.getElementById('map-canvas'), dpr = canvas.width / canvas.clientWidth;
      return Array.from(canvas.getContext('2d').getImageData(Math.round(x * dpr), Math.round(y * dpr), 1, 1).data.slice(0, 3));
    }, [at[0] - box.x, at[1] - box.y]);
    expectEqual(rgb, [0xd7, 0x30, 0x27], `pixel at ${target.id}'s dot (inconsistent red #d73027)`);
  });

  await run.check('scale bar agrees with the distance between two sensors', async () => {
    const [a, b] = [inconsistent[0], inconsistent[1]];
    const pa = await page.evaluate((id) => window.covmapReport.screenPosition(id), a.id);
    const pb = await page.evaluate((id) => window.covmapReport.screenPosition(id), b.id);
    const pxPerMetre = Math.hypot(pa[0] - pb[0], pa[1] - pb[1]) / haversineMetres(a, b);
    const bar = await page.$eval('#scale-bar', (e) => ({ metres: Number(e.dataset.metres), pixels: Number(e.dataset.pixels),
                                                        text: e.textContent, width: e.querySelector('i').offsetWidth }));
    const barPxPerMetre = bar.pixels / bar.metres;
    expect(Math.abs(barPxPerMetre / pxPerMetre - 1) < SCALE_TOLERANCE,
           `scale bar ${bar.text} of ${bar.pixels.toFixed(1)} px = ${pxPerMetre.toFixed(6)} px/m (from ${a.id}–${b.id})`,
           `${barPxPerMetre.toFixed(6)} px/m`);
    const label = bar.metres >= 1000 ? `${bar.metres / 1000} km` : `${bar.metres} m`;
    expectEqual(bar.text.trim(), label, 'scale bar label');
    expect(Math.abs(bar.width - bar.pixels) <= 5, `bar drawn ${bar.pixels.toFixed(0)} px wide (plus its border)`, bar.width);
  });

  await run.check('legend names exactly the verdicts drawn', async () => {
    const drawn = new Set(sensors.filter((s) => s.in_map || s.reported).map(verdictOf));
    const shown = await page.$$eval('#map-legend li:not([hidden])', (items) => items.map((i) => i.dataset.symbol));
    const verdictSymbols = shown.filter((s) => s in RANK);
    expectEqual(verdictSymbols.sort(), [...drawn].sort(), 'verdicts in the legend');
  });

  await run.check('a layer switched off leaves the legend', async () => {
    await page.uncheck('input[data-layer="shifts"]');
    expect(!(await page.isVisible('#map-legend li[data-symbol="shift"]')), 'the arrow\'s legend entry hidden', 'visible');
    await page.check('input[data-layer="shifts"]');
    expect(await page.isVisible('#map-legend li[data-symbol="shift"]'), 'the arrow\'s legend entry back', 'hidden');
  });

  await run.check('attention list: every flagged sensor, worst first', async () => {
    const ids = await page.$$eval('#attention li[data-sensor-id]', (items) => items.map((i) => i.dataset.sensorId));
    const want = worstFirst(sensors).filter((s) => verdictOf(s) !== 'consistent').map((s) => s.id);
    expectEqual(ids, want, 'attention list');
    await page.click(`#attention li[data-sensor-id="${want[want.length - 1]}"]`);
    expectEqual(await page.evaluate(() => window.covmapReport.selected()), want[want.length - 1], 'selected from the list');
  });

  await screenshot(page, artefacts, 'report-features-after-interaction');
}

process.exitCode = await runAuditedPageTest('report_features_test.mjs', process.argv.slice(2), { map: MAP },
  async (run, browser, audit, artefacts) => {
    const { page, context, log } = await openPage(browser, audit.html, VIEWPORT);
    try {
      await checks(run, page, audit.report, artefacts);
    } catch (error) {
      run.fatal(`the checks stopped: ${error.message}`);
    }
    await run.check('no console or page errors while interacting', async () =>
      expect(log.consoleErrors.length + log.pageErrors.length === 0, 'none',
             [...log.consoleErrors, ...log.pageErrors].join(' | ')));
    await run.check('no request beyond file: and data:', async () =>
      expect(log.remoteRequests.length === 0, 'none', log.remoteRequests.join(' | ')));
    await context.close();
  });
