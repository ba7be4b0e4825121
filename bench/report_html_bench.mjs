// How report.html behaves in a real browser at scale: file size, time to the first
// drawn map, and the time of one redraw when zooming, panning and selecting a sensor, in headless
// Chromium (the browser tests' set-up: tests/browser/lib). Prints one JSON object per page.
//
// Usage: node bench/report_html_bench.mjs REPORT.html [REPORT.html ...] [--repeat N]
// Make the pages with covmap audit; docs/PERFORMANCE.md gives the commands of its figures.
import { statSync } from 'node:fs';
import { launchBrowser, openPage } from '../tests/browser/lib/browser.mjs';

const VIEWPORT = { width: 1280, height: 900 };

// Milliseconds from a change of the view to the end of the frame that draws it: the page redraws
// in requestAnimationFrame, so the next frame after that one starts once the drawing is done.
const timeRedraw = (page, action) => page.evaluate((action) => new Promise((done) => {
  const start = performance.now();
  if (action.kind === 'select') {
    window.covmapReport.select(action.id);
  } else if (action.kind === 'pan') {  // a drag of 40 px
    const canvas = document.getElementById('map-canvas'), r = canvas.getBoundingClientRect();
    const x = r.left + r.width / 2, y = r.top + r.height / 2;
    canvas.dispatchEvent(new MouseEvent('mousedown', {clientX: x, clientY: y, bubbles: true}));
    window.dispatchEvent(new MouseEvent('mousemove', {clientX: x + 40, clientY: y + 10, bubbles: true}));
    window.dispatchEvent(new MouseEvent('mouseup', {clientX: x + 40, clientY: y + 10, bubbles: true}));
  } else {
    document.getElementById(action.kind).click();
  }
  requestAnimationFrame(() => requestAnimationFrame(() => done(performance.now() - start)));
}), action);

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

async function measure(browser, file, repeat) {
  const loads = [], zooms = [], selects = [], pans = [];
  let sensors = 0, rows = 0, errors = [];
  for (let r = 0; r < repeat; ++r) {
    const start = Date.now();
    const { page, context, log } = await openPage(browser, file, VIEWPORT);
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    loads.push(Date.now() - start);
    sensors = await page.evaluate(() => window.covmapReport.data.sensors.id.length);
    rows = await page.$$eval('#sensor-table tbody tr', (trs) => trs.length);
    const ids = await page.evaluate(() => window.covmapReport.data.sensors.id.slice(0, 5));
    for (const id of ids) selects.push(await timeRedraw(page, { kind: 'select', id }));
    await timeRedraw(page, { kind: 'zoom-home' });
    for (let i = 0; i < 5; ++i) zooms.push(await timeRedraw(page, { kind: i % 2 ? 'zoom-out' : 'zoom-in' }));
    await timeRedraw(page, { kind: 'zoom-home' });
    for (let i = 0; i < 5; ++i) pans.push(await timeRedraw(page, { kind: 'pan' }));
    errors = [...log.consoleErrors, ...log.pageErrors];
    await context.close();
  }
  return {
    file, bytes: statSync(file).size, sensors, table_rows_in_dom: rows,
    load_to_first_frame_ms: median(loads), zoom_redraw_ms: median(zooms), pan_redraw_ms: median(pans),
    select_redraw_ms: median(selects),
    repeat, errors,
  };
}

const args = process.argv.slice(2);
const at = args.indexOf('--repeat');
const repeat = at >= 0 ? Number(args.splice(at, 2)[1]) : 3;
if (args.length === 0) {
  console.error('usage: node bench/report_html_bench.mjs REPORT.html [...] [--repeat N]');
  process.exit(2);
}
const browser = await launchBrowser();
try {
  for (const file of args) console.log(JSON.stringify(await measure(browser, file, repeat)));
} finally {
  await browser.close();
}
