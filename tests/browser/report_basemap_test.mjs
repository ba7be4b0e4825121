// report.html's optional basemap: with `covmap audit --basemap URL` the page loads
// nothing until the reader switches the basemap on; then it asks for the slippy-map tiles that
// cover what is in view (the tiles holding every sensor of the whole-map view, computed here from
// report.json's lon/lat with the tile formulas) and draws them under the cells.
//
// Usage: node tests/browser/report_basemap_test.mjs path/to/covmap path/to/datasets path/to/artefact-dir
import { openPage, screenshot } from './lib/browser.mjs';
import { expect } from './lib/checks.mjs';
import { runAuditedPageTest } from './lib/main.mjs';

const VIEWPORT = { width: 1280, height: 900 };
const MAP = 'bern';
// A tile server nobody can reach (RFC 2606): the test answers its requests itself.
const TILE_HOST = 'https://tiles.covmap-test.invalid';
const TILE_URL = `${TILE_HOST}/{z}/{x}/{y}.png`;
const TILE_RGB = [0, 255, 0];  // a colour no other part of the map uses

const tileX = (lon, z) => Math.floor((lon + 180) / 360 * 2 ** z);
const tileY = (lat, z) => {
  const r = lat * Math.PI / 180;
  return Math.floor((1 - Math.log(Math.tan(r) + 1 / Math.cos(r)) / Math.PI) / 2 * 2 ** z);
};

// Pixels of the map close to `rgb`, read from a screenshot of the canvas: the canvas itself cannot
// be read once it shows images from another origin (as tiles are), and the page does not ask tile
// servers for CORS, so that any server works.
async function countColour(page, rgb) {
  const shot = (await page.locator('#map-canvas').screenshot()).toString('base64');
  return page.evaluate(async ([shot, rgb]) => {
    const img = new Image();
    img.src = `data:image/png;base64,${shot}`;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.naturalWidth; c.height = img.naturalHeight;
    const g = c.getContext('2d');
    g.drawImage(img, 0, 0);
    const px = g.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < px.length; i += 4) {
      if (Math.abs(px[i] - rgb[0]) < 8 && Math.abs(px[i + 1] - rgb[1]) < 8 && Math.abs(px[i + 2] - rgb[2]) < 8) ++n;
    }
    return n;
  }, [shot, rgb]);
}

async function checks(run, page, log, report, artefacts) {
  // One green PNG tile, made by the browser itself.
  const png = Buffer.from((await page.evaluate((rgb) => {
    const c = document.createElement('canvas');
    c.width = c.height = 256;
    const g = c.getContext('2d');
    g.fillStyle = `rgb(${rgb.join(',')})`;
    g.fillRect(0, 0, 256, 256);
    return c.toDataURL('image/png');
  }, TILE_RGB)).split(',')[1], 'base64');
  const asked = [];
  await page.route(`${TILE_HOST}/**`, (route) => {
    asked.push(route.request().url());
    return route.fulfill({ status: 200, contentType: 'image/png', body: png });
  });

  await run.check('nothing loaded until the basemap is switched on', async () => {
    expect(await page.isVisible('#basemap-toggle'), 'a basemap switch', 'none');
    expect(!(await page.isChecked('#basemap-toggle')), 'the switch off', 'on');
    expect(log.remoteRequests.length === 0, 'no request', log.remoteRequests.join(' | '));
    expect(await countColour(page, TILE_RGB) === 0, 'no tile pixels', 'some');
  });

  await run.check('switched on, the tiles holding every sensor are loaded and drawn', async () => {
    await page.check('#basemap-toggle');
    await page.waitForFunction(() => true);
    await page.waitForTimeout(500);
    expect(asked.length > 0, 'tile requests', 'none');
    const tiles = new Set(asked.map((url) => url.slice(TILE_HOST.length + 1, -'.png'.length)));
    const z = Number([...tiles][0].split('/')[0]);
    expect([...tiles].every((t) => Number(t.split('/')[0]) === z), 'one zoom level', [...tiles].join(' '));
    const missing = report.sensors.filter((s) => s.in_map)
      .map((s) => `${z}/${tileX(s.lon, z)}/${tileY(s.lat, z)}`).filter((t) => !tiles.has(t));
    expect(missing.length === 0, `every sensor's tile at zoom ${z} requested`, `missing ${[...new Set(missing)].join(' ')}`);
    expect(await countColour(page, TILE_RGB) > 1000, 'tile pixels drawn under the map', 'none');
    await screenshot(page, artefacts, 'report-basemap-on');
  });

  await run.check('switched off again, the tiles are gone', async () => {
    await page.uncheck('#basemap-toggle');
    await page.waitForTimeout(200);
    expect(await countColour(page, TILE_RGB) === 0, 'no tile pixels', 'some');
  });
}

process.exitCode = await runAuditedPageTest('report_basemap_test.mjs', process.argv.slice(2),
  { map: MAP, extraArgs: ['--basemap', TILE_URL] }, async (run, browser, audit, artefacts) => {
    const { page, context, log } = await openPage(browser, audit.html, VIEWPORT);
    try {
      await checks(run, page, log, audit.report, artefacts);
    } catch (error) {
      run.fatal(`the checks stopped: ${error.message}`);
    }
    await run.check('no console or page errors', async () =>
      expect(log.consoleErrors.length + log.pageErrors.length === 0, 'none',
             [...log.consoleErrors, ...log.pageErrors].join(' | ')));
    await context.close();
  });
