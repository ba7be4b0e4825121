// Making a report to look at: covmap audit on a bundled map, as a user would run it.
//
// Contract: auditBundledMap(covmap, datasets, map, extraArgs = []) audits datasets/maps/<map> (its map.geojson,
// its sensors.geojson, --alpha from its truth.json's generator, --planar for a planar map; as
// scripts/demo.sh and tests/cli/bundled_maps_truth_test.py do) into a new temporary folder and
// returns {dir, html, json, report}: the folder, the paths of report.html and report.json, and
// report.json parsed; extraArgs are added to the command line (e.g. ['--basemap', url]). Throws, with covmap's stderr in the message, when the audit fails. The caller
// removes dir (removeAudit).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

export function auditBundledMap(covmap, datasets, map, extraArgs = []) {
  const folder = join(datasets, 'maps', map);
  const generator = JSON.parse(readFileSync(join(folder, 'truth.json'), 'utf8')).generator;
  const dir = mkdtempSync(join(tmpdir(), `covmap-browser-${map}-`));
  const args = ['audit', join(folder, 'map.geojson'), '--sensors', join(folder, 'sensors.geojson'),
                '--alpha', String(generator.alpha), '-o', dir, '-q'];
  if (generator.frame === 'planar') args.push('--planar');
  args.push(...extraArgs);
  try {
    execFileSync(covmap, args, { stdio: ['ignore', 'ignore', 'pipe'] });
  } catch (error) {
    rmSync(dir, { recursive: true, force: true });
    throw new Error(`${covmap} ${args.join(' ')}: ${error.stderr?.toString().trim() || `exit status ${error.status ?? error.message}`}`);
  }
  const json = join(dir, 'report.json');
  return { dir, html: join(dir, 'report.html'), json, report: JSON.parse(readFileSync(json, 'utf8')) };
}

export function removeAudit(audit) {
  if (audit) rmSync(audit.dir, { recursive: true, force: true });
}
