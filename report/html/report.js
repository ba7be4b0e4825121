// report.html's script: the map on a canvas, the sensor table, and the links between them.
// Reads the JSON block #report-data (report/audit_html_data.h describes it). Plain ES2017, no
// library, nothing loaded from anywhere (the basemap's tiles only when the reader switches it on).
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('report-data').textContent);
  // The data lists sensors by column (audit_html_data.h); the page works with one object each.
  const columns = Object.keys(data.sensors);
  const sensors = columns.length ? data.sensors[columns[0]].map((_, i) => {
    const s = {};
    for (const c of columns) s[c] = data.sensors[c][i];
    return s;
  }) : [];
  const verdicts = data.verdicts, G = data.grid;
  const byId = new Map(sensors.map((s, i) => [s.id, i]));

  // ------------------------------------------------------------------ numbers for people
  // The rules of report/audit_html_text.h's human_number: `sig` significant digits in fixed
  // notation, the exponent form only below 1e-3 and from 1e15, an en dash when unknown.
  function human(v, sig) {
    sig = sig || 3;
    if (v === null || v === undefined || !isFinite(v)) return '\u2013';
    if (v === 0) return '0';
    const a = Math.abs(v);
    if (a < 1e-3 || a >= 1e15) return v.toPrecision(sig).replace(/\.?0+e/, 'e');
    const digits = Math.floor(Math.log10(a)) + 1;
    return v.toFixed(Math.max(0, sig - digits));
  }
  function metres(v) {
    if (v === null || v === undefined || !isFinite(v)) return '\u2013';
    return Math.abs(v) >= 1000 ? human(v / 1000) + ' km' : human(v) + ' m';
  }
  function el(tag, attrs, text) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  function label(s) { return s.name ? s.name + ' (' + s.id + ')' : s.id; }

  // The lines of a sensor's details, shared by the hover tooltip and the selection box.
  function details(s) {
    const v = verdicts[s.verdict];
    const lines = [];
    lines.push(['verdict', v.words + (s.basis ? ', judged by ' + s.basis : '')]);
    if (s.moved !== null) lines.push(['reported position off by', metres(s.moved) + (s.sigma !== null ? ' (\u00b1 ' + metres(s.sigma) + ' 1\u03c3)' : '')]);
    else if (s.sigma !== null) lines.push(['position uncertainty', '\u00b1 ' + metres(s.sigma) + ' (1\u03c3)']);
    if (s.power_error !== null) lines.push(['power error', human(s.power_error) + ' dB (reported \u2212 map)']);
    if (s.power !== null || s.reported_power !== null)
      lines.push(['power', human(s.power, 4) + ' dBm from the map, ' + human(s.reported_power, 4) + ' dBm reported']);
    if (s.chi2 !== null) lines.push(['\u03c7\u00b2', human(s.chi2)]);
    if (s.iou !== null) lines.push(['cell overlap', human(100 * s.iou) + ' %']);
    return lines;
  }
  function fillDetails(box, s) {
    box.textContent = '';
    const head = el('div', {class: 'tip-head'});
    head.appendChild(el('i', {style: 'background:' + verdicts[s.verdict].colour}));
    head.appendChild(el('b', {}, s.id));
    if (s.name) head.appendChild(el('span', {}, ' ' + s.name));
    box.appendChild(head);
    const table = el('table');
    for (const [k, v] of details(s)) {
      const tr = el('tr');
      tr.appendChild(el('th', {}, k));
      tr.appendChild(el('td', {}, v));
      table.appendChild(tr);
    }
    box.appendChild(table);
    if (s.reason) box.appendChild(el('p', {}, s.reason));
  }

  // ------------------------------------------------------------------ the map
  const view = document.getElementById('map-view');
  const canvas = document.getElementById('map-canvas');
  const ctx = canvas.getContext('2d');
  const tip = document.getElementById('map-tooltip');
  const selectionBox = document.getElementById('map-selection');
  const coords = document.getElementById('map-coords');
  const scaleBar = document.getElementById('scale-bar');

  // Widens bbox [xmin, ymin, xmax, ymax] to hold the box [x0, y0, x1, y1] (a point: x1 = x0, y1 = y0).
  function grow(bbox, x0, y0, x1 = x0, y1 = y0) {
    bbox[0] = Math.min(bbox[0], x0); bbox[1] = Math.min(bbox[1], y0); bbox[2] = Math.max(bbox[2], x1); bbox[3] = Math.max(bbox[3], y1);
  }
  function ringsPath(rings, bbox) {  // closed rings, widening bbox by their points
    const p = new Path2D();
    for (const r of rings) {
      let x = r[0], y = r[1];
      p.moveTo(x, y);
      grow(bbox, x, y);
      for (let i = 2; i < r.length; i += 2) {
        x += r[i]; y += r[i + 1];
        p.lineTo(x, y);
        grow(bbox, x, y);
      }
      p.closePath();
    }
    return p;
  }
  const cells = data.cells.map(c => {
    const bbox = [Infinity, Infinity, -Infinity, -Infinity];
    const path = ringsPath(c.slice(1), bbox);
    return {sensor: c[0], path, bbox};
  });
  const cellsOf = new Map();
  cells.forEach((c, i) => { if (!cellsOf.has(c.sensor)) cellsOf.set(c.sensor, []); cellsOf.get(c.sensor).push(i); });

  // ---- level of detail. Zoomed in, cells are filled one by one (those in view) and lines drawn
  // by buckets in view. The whole map at once is drawn from coarse copies: rings simplified to
  // kCoarseTolerancePx at that zoom, the cells of one tint in one path. At 10^4 cells this halves
  // what the browser rasterises and turns 10^4 fills into a dozen.
  const kCoarseTolerancePx = 0.6;
  const kCoarseUpTo = 1.5;  // times the whole-map zoom
  const kBuckets = 8;       // lines are cut into kBuckets² buckets by position

  // Douglas-Peucker on a polyline of [x, y] pairs: the points to keep, every dropped one within tol.
  function simplifyPoints(pts, tol) {
    if (pts.length <= 2) return pts;
    const keep = new Uint8Array(pts.length);
    keep[0] = keep[pts.length - 1] = 1;
    const stack = [[0, pts.length - 1]];
    while (stack.length) {
      const [a, b] = stack.pop();
      const [ax, ay] = pts[a], dx = pts[b][0] - ax, dy = pts[b][1] - ay, len2 = dx * dx + dy * dy;
      let worst = -1, at = -1;
      for (let i = a + 1; i < b; ++i) {
        const px = pts[i][0] - ax, py = pts[i][1] - ay;
        const t = len2 ? Math.max(0, Math.min(1, (px * dx + py * dy) / len2)) : 0;
        const d = Math.hypot(px - t * dx, py - t * dy);
        if (d > worst) { worst = d; at = i; }
      }
      if (at < 0 || worst <= tol) continue;
      keep[at] = 1;
      stack.push([a, at], [at, b]);
    }
    return pts.filter((_, i) => keep[i]);
  }
  function decode(r) {
    const pts = [[r[0], r[1]]];
    for (let i = 2; i < r.length; i += 2) pts.push([pts[pts.length - 1][0] + r[i], pts[pts.length - 1][1] + r[i + 1]]);
    return pts;
  }
  function addPoints(path, pts, closed) {
    path.moveTo(pts[0][0], pts[0][1]);
    for (let i = 1; i < pts.length; ++i) path.lineTo(pts[i][0], pts[i][1]);
    if (closed) path.closePath();
  }
  function coarsePath(rings, closed, tol) {
    const p = new Path2D();
    for (const r of rings) {
      const pts = decode(r);
      const kept = closed ? simplifyPoints(pts.concat([pts[0]]), tol).slice(0, -1) : simplifyPoints(pts, tol);
      if (kept.length >= (closed ? 3 : 2)) addPoints(p, kept, closed);
    }
    return p;
  }
  let coarse = null;  // built for one whole-map zoom
  function coarseCopies() {
    if (coarse && coarse.homeK === homeK) return coarse;
    const tol = kCoarseTolerancePx / homeK;
    const groups = new Map();  // cells of one tint (verdict, flagged or not; unknown sensors apart)
    data.cells.forEach((c, i) => {
      const key = c[0] < 0 ? 'none' : sensors[c[0]].verdict + (sensors[c[0]].attention ? '!' : '');
      if (!groups.has(key)) groups.set(key, {cell: i, rings: []});
      groups.get(key).rings.push(...c.slice(1));
    });
    coarse = {
      homeK,
      groups: [...groups.values()].map(g => ({cell: g.cell, path: coarsePath(g.rings, true, tol)})),
      boundaries: coarsePath(data.boundaries, false, tol),
      frame: coarsePath(data.frame, false, tol),
      reported: data.reported_boundaries ? coarsePath(data.reported_boundaries, false, tol) : null,
    };
    return coarse;
  }
  // Full lines in buckets by where they start, each with the bounding box of its lines.
  function buckets(polylines) {
    const out = new Map();
    for (const r of polylines) {
      const pts = decode(r);
      const key = Math.min(kBuckets - 1, Math.max(0, Math.floor(pts[0][0] / G.w * kBuckets))) * kBuckets +
                  Math.min(kBuckets - 1, Math.max(0, Math.floor(pts[0][1] / G.h * kBuckets)));
      if (!out.has(key)) out.set(key, {path: new Path2D(), bbox: [Infinity, Infinity, -Infinity, -Infinity]});
      const b = out.get(key);
      addPoints(b.path, pts, false);
      for (const [x, y] of pts) grow(b.bbox, x, y);
    }
    return [...out.values()];
  }
  const lines = {
    boundaries: buckets(data.boundaries),
    frame: buckets(data.frame),
    reported: data.reported_boundaries ? buckets(data.reported_boundaries) : null,
  };
  const layerOn = name => { const box = document.querySelector('input[data-layer="' + name + '"]'); return !box || box.checked; };

  let W = 0, H = 0, dpr = 1, k = 1, cx = G.w / 2, cy = G.h / 2, homeK = 1, selected = -1;
  function resize() {
    dpr = window.devicePixelRatio || 1;
    W = Math.max(200, view.clientWidth);
    // As tall as the map's shape asks, within what is left of the first screen below the map's top.
    const top = view.getBoundingClientRect().top + window.scrollY;
    H = Math.round(Math.max(320, Math.min(W * G.h / G.w, window.innerHeight - top - 60)));
    view.style.height = H + 'px';
    canvas.width = Math.round(W * dpr); canvas.height = Math.round(H * dpr);
    canvas.style.width = W + 'px'; canvas.style.height = H + 'px';
    const wasHome = k === homeK;
    homeK = 0.96 * Math.min(W / G.w, H / G.h);
    if (wasHome) k = homeK;
  }
  function goHome() { k = homeK; cx = G.w / 2; cy = G.h / 2; }
  const toScreen = (gx, gy) => [(gx - cx) * k + W / 2, (gy - cy) * k + H / 2];
  const toGrid = (sx, sy) => [(sx - W / 2) / k + cx, (sy - H / 2) / k + cy];

  function hexAlpha(hex, a) {
    const n = parseInt(hex.slice(1), 16);
    return 'rgba(' + (n >> 16) + ',' + ((n >> 8) & 255) + ',' + (n & 255) + ',' + a + ')';
  }
  const cellColouring = document.getElementById('cell-colouring');
  function cellFill(c, basemap) {
    if (c.sensor < 0) return 'rgba(200,200,200,0.5)';
    const s = sensors[c.sensor];
    if (cellColouring && cellColouring.value === 'sensor') return hexAlpha(s.colour, basemap ? 0.45 : 0.75);
    return hexAlpha(verdicts[s.verdict].colour, basemap ? 0.25 : (s.attention ? 0.38 : 0.2));
  }
  function dotRadius() {
    const drawn = Math.max(1, sensors.length);
    const spacing = k * Math.sqrt(G.w * G.h / drawn);
    return Math.max(1.5, Math.min(4.5, 0.18 * spacing));
  }
  // The map's cells and lines are drawn into an off-screen canvas CACHE_MARGIN views larger on every side;
  // while the zoom and the layers stay the same, panning only moves that picture (at 10^4 cells a
  // full drawing takes a good part of a second in a software-rendering browser).
  const CACHE_MARGIN = 0.25;  // a drag of a quarter view redraws nothing; the drawing costs (1 + 2·0.25)² of a view
  const cache = document.createElement('canvas');
  let cached = null;  // {key, k, cx, cy, mx, my}

  function drawStatic(g, basemapOn, mx, my) {
    g.setTransform(dpr * k, 0, 0, dpr * k, dpr * (W / 2 + mx - cx * k), dpr * (H / 2 + my - cy * k));
    const [x0, y0] = toGrid(-mx, -my), [x1, y1] = toGrid(W + mx, H + my);
    const visible = b => b[2] >= x0 && b[0] <= x1 && b[3] >= y0 && b[1] <= y1;
    const whole = k <= kCoarseUpTo * homeK, lod = whole ? coarseCopies() : null;
    const strokeLines = (set, coarsePath) => {
      if (whole) { g.stroke(coarsePath); return; }
      for (const b of set) if (visible(b.bbox)) g.stroke(b.path);
    };
    if (layerOn('cells')) {
      if (whole && !(cellColouring && cellColouring.value === 'sensor')) {
        // One fill per tint. Nonzero, not even-odd: a hole of one cell may hold another cell of the
        // same tint, and the rings' orientations (outer counter-clockwise, holes clockwise) keep it filled.
        for (const group of lod.groups) {
          g.fillStyle = cellFill(cells[group.cell], basemapOn);
          g.fill(group.path, 'nonzero');
        }
      } else {
        for (const c of cells) {
          if (!visible(c.bbox)) continue;
          g.fillStyle = cellFill(c, basemapOn);
          g.fill(c.path, 'evenodd');
        }
      }
    }
    g.lineJoin = 'round';
    if (layerOn('diagram')) {
      g.lineWidth = 1 / k; g.strokeStyle = '#777'; strokeLines(lines.frame, whole && lod.frame);
      g.lineWidth = 1.2 / k; g.strokeStyle = '#1d1d1d'; strokeLines(lines.boundaries, whole && lod.boundaries);
    }
    if (lines.reported && layerOn('reported-diagram')) {
      g.setLineDash([5 / k, 3 / k]); g.lineWidth = 1.4 / k; g.strokeStyle = '#6a3d9a';
      strokeLines(lines.reported, whole && lod.reported); g.setLineDash([]);
    }
  }

  function draw() {
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.clearRect(0, 0, W, H);
    const basemapOn = drawBasemap();
    const key = [W, H, dpr, basemapOn, cellColouring ? cellColouring.value : '',
                 ...Array.from(document.querySelectorAll('input[data-layer]'), b => b.checked)].join();
    const fits = cached && cached.key === key && cached.k === k &&
                 Math.abs(cx - cached.cx) * k <= cached.mx && Math.abs(cy - cached.cy) * k <= cached.my;
    if (!fits) {
      const mx = Math.round(W * CACHE_MARGIN), my = Math.round(H * CACHE_MARGIN);
      cache.width = Math.round((W + 2 * mx) * dpr); cache.height = Math.round((H + 2 * my) * dpr);
      drawStatic(cache.getContext('2d'), basemapOn, mx, my);
      cached = {key, k, cx, cy, mx, my};
    }
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.drawImage(cache, Math.round(dpr * ((cached.cx - cx) * k - cached.mx)), Math.round(dpr * ((cached.cy - cy) * k - cached.my)));
    if (selected >= 0) {
      ctx.setTransform(dpr * k, 0, 0, dpr * k, dpr * (W / 2 - cx * k), dpr * (H / 2 - cy * k));
      for (const i of cellsOf.get(selected) || []) {
        ctx.lineWidth = 5 / k; ctx.strokeStyle = '#111'; ctx.stroke(cells[i].path);
        ctx.lineWidth = 2.5 / k; ctx.strokeStyle = '#ffd400'; ctx.stroke(cells[i].path);
      }
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    drawMarks();
    updateScaleBar();
  }

  function arrow(shaft, head, x0, y0, x1, y1) {
    const len = Math.hypot(x1 - x0, y1 - y0);
    if (len < 2) return;
    shaft.moveTo(x0, y0); shaft.lineTo(x1, y1);
    const h = Math.min(9, len / 2), ux = (x1 - x0) / len, uy = (y1 - y0) / len;
    head.moveTo(x1, y1);
    head.lineTo(x1 - h * ux - 0.5 * h * uy, y1 - h * uy + 0.5 * h * ux);
    head.lineTo(x1 - h * ux + 0.5 * h * uy, y1 - h * uy - 0.5 * h * ux);
    head.closePath();
  }
  function inView(x, y, pad) { return x >= -pad && y >= -pad && x <= W + pad && y <= H + pad; }

  // Marks are batched: one path per colour and kind, so 10^4 sensors cost a few dozen draw calls.
  function batches() { return verdicts.map(() => new Path2D()); }
  // Below this dot radius (px) the map is dense: dots become squares without outline, and only
  // flagged sensors keep their rings and arrows (the others' would be a few pixels of clutter).
  const kDenseRadius = 2.5;
  function drawMarks() {
    const r = dotRadius(), dense = r < kDenseRadius;
    if (layerOn('shifts')) {
      const shafts = batches(), heads = batches();
      for (const s of sensors) {
        if (s.x === null || s.rx === null || (dense && !s.attention)) continue;
        const [x0, y0] = toScreen(s.rx, s.ry), [x1, y1] = toScreen(s.x, s.y);
        if (!inView(x0, y0, 50) && !inView(x1, y1, 50)) continue;
        arrow(shafts[s.verdict], heads[s.verdict], x0, y0, x1, y1);
      }
      ctx.lineWidth = 1.6;
      verdicts.forEach((v, i) => {
        ctx.strokeStyle = v.colour; ctx.fillStyle = v.colour;
        ctx.stroke(shafts[i]); ctx.fill(heads[i]);
      });
    }
    if (!layerOn('sensors')) return;
    const rings = batches(), ringRadius = Math.max(2, 0.8 * r);
    for (const s of sensors) {  // reported positions: rings
      if (s.rx === null || (dense && !s.attention)) continue;
      const [x, y] = toScreen(s.rx, s.ry);
      if (!inView(x, y, 10)) continue;
      rings[s.verdict].moveTo(x + ringRadius, y);
      rings[s.verdict].arc(x, y, ringRadius, 0, 2 * Math.PI);
    }
    ctx.lineWidth = 1.5; ctx.fillStyle = '#fff';
    verdicts.forEach((v, i) => { ctx.strokeStyle = v.colour; ctx.fill(rings[i]); ctx.stroke(rings[i]); });
    // Dots, the worst verdicts drawn last (on top), flagged ones a little larger.
    const dots = batches();
    for (const s of sensors) {
      if (s.x === null) continue;
      const [x, y] = toScreen(s.x, s.y);
      if (!inView(x, y, 10)) continue;
      const radius = s.attention ? r + 1 : r;
      if (dense && !s.attention) {
        dots[s.verdict].rect(x - radius, y - radius, 2 * radius, 2 * radius);
      } else {
        dots[s.verdict].moveTo(x + radius, y);
        dots[s.verdict].arc(x, y, radius, 0, 2 * Math.PI);
      }
    }
    ctx.lineWidth = 1; ctx.strokeStyle = '#fff';
    dotOrder.forEach((i) => {
      ctx.fillStyle = verdicts[i].colour; ctx.fill(dots[i]);
      if (!dense) ctx.stroke(dots[i]);
    });
    drawLabels(r);
  }
  // Verdicts from the least to the most severe, for drawing the worst dots last: the data lists the
  // sensors worst first (sensors_by_severity), so the order of first appearance is the severity.
  const dotOrder = [...new Set(sensors.map(s => s.verdict))].reverse();

  // Flagged sensors get their label, worst first, where it does not cover another label.
  const kMaxLabels = 400;
  function drawLabels(r) {
    ctx.font = '12px system-ui, sans-serif';
    ctx.textBaseline = 'middle';
    const placed = [];
    let tried = 0;
    for (let i = 0; i < sensors.length && tried < kMaxLabels; ++i) {
      const s = sensors[i];
      if (!s.attention || verdicts[s.verdict].key === 'unreported') continue;
      const gx = s.x !== null ? s.x : s.rx, gy = s.x !== null ? s.y : s.ry;
      if (gx === null) continue;
      const [x, y] = toScreen(gx, gy);
      if (!inView(x, y, 0)) continue;
      ++tried;
      const text = s.name || s.id, w = ctx.measureText(text).width + 6;
      const box = [x + r + 2, y - 8, x + r + 2 + w, y + 8];
      if (placed.some(b => b[0] < box[2] && box[0] < b[2] && b[1] < box[3] && box[1] < b[3])) continue;
      placed.push(box);
      ctx.fillStyle = 'rgba(255,255,255,0.85)';
      ctx.fillRect(box[0], box[1], w, 16);
      ctx.fillStyle = verdicts[s.verdict].colour;
      ctx.fillText(text, box[0] + 3, y);
    }
  }

  function niceLength(target) {
    const p = Math.pow(10, Math.floor(Math.log10(target)));
    for (const f of [5, 2, 1]) if (f * p <= target) return f * p;
    return p;
  }
  function updateScaleBar() {
    const metresPerPx = G.m / k;
    const length = niceLength(120 * metresPerPx);
    scaleBar.querySelector('i').style.width = (length / metresPerPx).toFixed(1) + 'px';
    // A round length: written as it is ("20 km", "500 m", "0.2 m"), not to a count of digits.
    scaleBar.querySelector('span').textContent = length >= 1000 ? String(length / 1000) + ' km' : String(+length.toPrecision(1)) + ' m';
    scaleBar.dataset.metres = String(length);
    scaleBar.dataset.pixels = String(length / metresPerPx);
  }

  // lon/lat of a grid point, bilinear on the data's node grid (planar maps: null).
  function lonlat(gx, gy) {
    const L = data.lonlat;
    if (!L) return null;
    // Outside the frame the nearest grid cell is extended (linear extrapolation), not clamped.
    const n = L.n, u = gx / G.w * n, v = gy / G.h * n;
    const i = Math.max(0, Math.min(n - 1, Math.floor(u))), j = Math.max(0, Math.min(n - 1, Math.floor(v))), fu = u - i, fv = v - j;
    const at = (a, ii, jj) => a[jj * (n + 1) + ii];
    const mix = a => (1 - fv) * ((1 - fu) * at(a, i, j) + fu * at(a, i + 1, j)) + fv * ((1 - fu) * at(a, i, j + 1) + fu * at(a, i + 1, j + 1));
    return [mix(L.lon), mix(L.lat)];
  }
  function coordinateText(gx, gy) {
    const ll = lonlat(gx, gy);
    if (ll) return Math.abs(ll[1]).toFixed(5) + '\u00b0 ' + (ll[1] >= 0 ? 'N' : 'S') + ', ' + Math.abs(ll[0]).toFixed(5) + '\u00b0 ' + (ll[0] >= 0 ? 'E' : 'W');
    return 'x ' + (G.x0 + gx * G.m).toFixed(1) + ' m, y ' + (G.y0 - gy * G.m).toFixed(1) + ' m';
  }

  // ---- the optional basemap: slippy-map tiles, each drawn with the affine map of its corners
  const tiles = new Map();
  const basemapBox = document.getElementById('basemap-toggle');
  function gridOfLonLat(lon, lat) {
    const B = data.basemap, n = B.n;
    const u = (lon - B.west) / (B.east - B.west) * n, v = (B.north - lat) / (B.north - B.south) * n;
    const i = Math.max(0, Math.min(n - 1, Math.floor(u))), j = Math.max(0, Math.min(n - 1, Math.floor(v))), fu = u - i, fv = v - j;
    const at = (a, ii, jj) => a[jj * (n + 1) + ii];
    const mix = a => (1 - fv) * ((1 - fu) * at(a, i, j) + fu * at(a, i + 1, j)) + fv * ((1 - fu) * at(a, i, j + 1) + fu * at(a, i + 1, j + 1));
    return [mix(B.x), mix(B.y)];
  }
  function tileLon(x, z) { return x / Math.pow(2, z) * 360 - 180; }
  function tileLat(y, z) { const m = Math.PI - 2 * Math.PI * y / Math.pow(2, z); return 180 / Math.PI * Math.atan(Math.sinh(m)); }
  function drawBasemap() {
    if (!data.basemap || !basemapBox || !basemapBox.checked) return false;
    const B = data.basemap;
    const corners = [toGrid(0, 0), toGrid(W, 0), toGrid(0, H), toGrid(W, H)].map(g => lonlat(g[0], g[1]));
    const west = Math.max(B.west, Math.min(...corners.map(c => c[0]))), east = Math.min(B.east, Math.max(...corners.map(c => c[0])));
    const south = Math.max(B.south, Math.min(...corners.map(c => c[1]))), north = Math.min(B.north, Math.max(...corners.map(c => c[1])));
    if (!(west < east && south < north)) return true;
    const metresPerPx = G.m / k, lat = (south + north) / 2;
    const z = Math.max(0, Math.min(19, Math.round(Math.log2(156543.03 * Math.cos(lat * Math.PI / 180) / metresPerPx))));
    const n = Math.pow(2, z);
    const tx0 = Math.floor((west + 180) / 360 * n), tx1 = Math.floor((east + 180) / 360 * n);
    const ty = l => Math.floor((1 - Math.log(Math.tan(l * Math.PI / 180) + 1 / Math.cos(l * Math.PI / 180)) / Math.PI) / 2 * n);
    const ty0 = ty(north), ty1 = ty(south);
    if ((tx1 - tx0 + 1) * (ty1 - ty0 + 1) > 100) return true;  // more tiles than a screen needs
    for (let x = tx0; x <= tx1; ++x) {
      for (let y = ty0; y <= ty1; ++y) {
        const url = B.url.replace('{z}', z).replace('{x}', x).replace('{y}', y);
        let img = tiles.get(url);
        if (!img) {
          img = new Image();
          img.onload = () => requestDraw();
          img.src = url;
          tiles.set(url, img);
        }
        if (!img.complete || !img.naturalWidth) continue;
        const nw = toScreen(...gridOfLonLat(tileLon(x, z), tileLat(y, z)));
        const ne = toScreen(...gridOfLonLat(tileLon(x + 1, z), tileLat(y, z)));
        const sw = toScreen(...gridOfLonLat(tileLon(x, z), tileLat(y + 1, z)));
        const s = img.naturalWidth;
        ctx.setTransform(dpr * (ne[0] - nw[0]) / s, dpr * (ne[1] - nw[1]) / s, dpr * (sw[0] - nw[0]) / s, dpr * (sw[1] - nw[1]) / s, dpr * nw[0], dpr * nw[1]);
        ctx.drawImage(img, 0, 0, s + 1, s + 1);  // one tile pixel of overlap: no seams between tiles
      }
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    return true;
  }

  let pending = false;
  function requestDraw() {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => { pending = false; draw(); });
  }

  // ---- hover, selection, pan and zoom
  function sensorAt(sx, sy) {
    const reach = Math.max(6, dotRadius() + 3);
    let best = -1, bestD = reach;
    sensors.forEach((s, i) => {
      for (const [gx, gy] of [[s.x, s.y], [s.rx, s.ry]]) {
        if (gx === null) continue;
        const [x, y] = toScreen(gx, gy), d = Math.hypot(x - sx, y - sy);
        if (d < bestD) { bestD = d; best = i; }
      }
    });
    if (best >= 0 || !layerOn('cells')) return best;
    const [gx, gy] = toGrid(sx, sy);
    ctx.setTransform(dpr * k, 0, 0, dpr * k, dpr * (W / 2 - cx * k), dpr * (H / 2 - cy * k));
    let found = -1;
    for (const c of cells) {
      const b = c.bbox;
      if (c.sensor < 0 || gx < b[0] || gx > b[2] || gy < b[1] || gy > b[3]) continue;
      if (ctx.isPointInPath(c.path, sx * dpr, sy * dpr, 'evenodd')) { found = c.sensor; break; }
    }
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    return found;
  }

  function select(id) {
    const i = byId.has(id) ? byId.get(id) : -1;
    selected = i;
    if (i < 0) { selectionBox.hidden = true; requestDraw(); return; }
    const s = sensors[i];
    const bbox = [Infinity, Infinity, -Infinity, -Infinity];
    for (const c of cellsOf.get(i) || []) {
      const b = cells[c].bbox;
      grow(bbox, ...b);
    }
    const gx = s.x !== null ? s.x : s.rx, gy = s.x !== null ? s.y : s.ry;
    if (gx !== null) { cx = gx; cy = gy; }
    else if (bbox[0] <= bbox[2]) { cx = (bbox[0] + bbox[2]) / 2; cy = (bbox[1] + bbox[3]) / 2; }
    if (bbox[0] <= bbox[2]) {
      const span = Math.max(2 * Math.abs(cx - bbox[0]), 2 * Math.abs(bbox[2] - cx), 2 * Math.abs(cy - bbox[1]), 2 * Math.abs(bbox[3] - cy), 1);
      k = Math.max(homeK, Math.min(homeK * 200, 0.5 * Math.min(W, H) / span));
    } else {
      k = Math.max(k, 4 * homeK);
    }
    fillDetails(selectionBox.querySelector('.content'), s);
    selectionBox.hidden = false;
    document.querySelectorAll('[data-sensor-id].selected').forEach(e => e.classList.remove('selected'));
    document.querySelectorAll('[data-sensor-id]').forEach(e => { if (e.dataset.sensorId === id) e.classList.add('selected'); });
    requestDraw();
  }
  selectionBox.querySelector('button').addEventListener('click', () => { selected = -1; selectionBox.hidden = true; requestDraw(); });

  let drag = null;
  canvas.addEventListener('mousedown', e => { drag = {x: e.clientX, y: e.clientY, cx, cy, moved: false}; canvas.style.cursor = 'grabbing'; });
  window.addEventListener('mouseup', e => {
    if (drag && !drag.moved && e.target === canvas) {
      const r = canvas.getBoundingClientRect(), i = sensorAt(e.clientX - r.left, e.clientY - r.top);
      if (i >= 0) select(sensors[i].id);
    }
    drag = null; canvas.style.cursor = '';
  });
  window.addEventListener('mousemove', e => {
    if (!drag) return;
    if (Math.abs(e.clientX - drag.x) + Math.abs(e.clientY - drag.y) > 3) drag.moved = true;
    cx = drag.cx - (e.clientX - drag.x) / k; cy = drag.cy - (e.clientY - drag.y) / k;
    requestDraw();
  });
  canvas.addEventListener('mousemove', e => {
    const r = canvas.getBoundingClientRect(), sx = e.clientX - r.left, sy = e.clientY - r.top;
    coords.textContent = coordinateText(...toGrid(sx, sy));
    if (drag) { tip.hidden = true; return; }
    const i = sensorAt(sx, sy);
    if (i < 0) { tip.hidden = true; return; }
    fillDetails(tip, sensors[i]);
    tip.hidden = false;
    tip.dataset.sensorId = sensors[i].id;
    const left = sx + 14 + tip.offsetWidth > W ? sx - 14 - tip.offsetWidth : sx + 14;
    tip.style.left = Math.max(0, left) + 'px';
    tip.style.top = Math.max(0, Math.min(H - tip.offsetHeight, sy + 14)) + 'px';
  });
  canvas.addEventListener('mouseleave', () => { tip.hidden = true; });
  function zoomAt(sx, sy, f) {
    const [gx, gy] = toGrid(sx, sy);
    k = Math.max(homeK / 4, Math.min(homeK * 2000, k * f));
    cx = gx - (sx - W / 2) / k; cy = gy - (sy - H / 2) / k;
    requestDraw();
  }
  canvas.addEventListener('wheel', e => {
    e.preventDefault();
    const r = canvas.getBoundingClientRect();
    zoomAt(e.clientX - r.left, e.clientY - r.top, e.deltaY < 0 ? 1.25 : 0.8);
  }, {passive: false});
  canvas.addEventListener('dblclick', () => { goHome(); requestDraw(); });
  document.getElementById('zoom-in').addEventListener('click', () => zoomAt(W / 2, H / 2, 1.5));
  document.getElementById('zoom-out').addEventListener('click', () => zoomAt(W / 2, H / 2, 1 / 1.5));
  document.getElementById('zoom-home').addEventListener('click', () => { goHome(); requestDraw(); });

  // The legend shows only the symbols of the layers that are on, and the cells' current colouring.
  function updateLegend() {
    document.querySelectorAll('#map-legend li').forEach(e => {
      e.hidden = !layerOn(e.dataset.layer) || (e.dataset.colouring !== undefined && cellColouring && e.dataset.colouring !== cellColouring.value);
    });
  }
  for (const box of document.querySelectorAll('input[data-layer]')) box.addEventListener('change', () => { updateLegend(); requestDraw(); });
  if (cellColouring) cellColouring.addEventListener('change', () => { updateLegend(); requestDraw(); });
  updateLegend();
  if (basemapBox) basemapBox.addEventListener('change', requestDraw);

  // ------------------------------------------------------------------ the sensor table
  const table = document.getElementById('sensor-table');
  const body = table.tBodies[0];
  const heads = Array.from(table.tHead.rows[0].cells);
  const search = document.getElementById('sensor-search');
  const countText = document.getElementById('table-count');
  const more = document.getElementById('table-more');
  const kPage = 200;
  let shown = kPage, sortKey = null, ascending = true;

  // Columns whose every value is unknown are hidden (a map audited without powers, say).
  const keys = heads.map(th => th.dataset.key);
  const emptyColumn = keys.map(key => th_numeric(key) && sensors.every(s => s[key] === null));
  function th_numeric(key) { return heads[keys.indexOf(key)].dataset.type === 'num'; }
  heads.forEach((th, c) => { th.hidden = emptyColumn[c]; });

  function cellText(s, key) {
    switch (key) {
      case 'sensor': return null;
      case 'verdict': return verdicts[s.verdict].words;
      case 'moved': case 'sigma': return human(s[key]);
      case 'weight': case 'power': case 'reported_power': return human(s[key], 4);
      case 'iou': return s.iou === null ? '\u2013' : human(100 * s.iou) + ' %';
      case 'reason': return s.reason;
      default: return human(s[key]);
    }
  }
  function verdictFilter() {
    return new Set(Array.from(document.querySelectorAll('input[name="verdict-filter"]:checked')).map(b => b.value));
  }
  function matching() {
    const allowed = verdictFilter();
    const q = search.value.trim().toLowerCase();
    const rows = [];
    sensors.forEach((s, i) => {
      if (!allowed.has(verdicts[s.verdict].key)) return;
      if (q && !s.id.toLowerCase().includes(q) && !(s.name || '').toLowerCase().includes(q)) return;
      rows.push(i);
    });
    if (sortKey) {
      const numeric = th_numeric(sortKey);
      const value = i => sortKey === 'sensor' ? sensors[i].id : sortKey === 'verdict' ? i : numeric ? sensors[i][sortKey] : String(sensors[i][sortKey] || '');
      rows.sort((a, b) => {
        const x = value(a), y = value(b);
        if (numeric || sortKey === 'verdict') {
          if (x === null || y === null) return (x === null) - (y === null);  // unknown last either way
          return ascending ? x - y : y - x;
        }
        return ascending ? x.localeCompare(y, undefined, {numeric: true}) : y.localeCompare(x, undefined, {numeric: true});
      });
    }
    return rows;
  }
  function render() {
    const rows = matching();
    body.textContent = '';
    const frag = document.createDocumentFragment();
    for (const i of rows.slice(0, shown)) {
      const s = sensors[i];
      const tr = el('tr', {'class': 'v-' + verdicts[s.verdict].key.replace(/_/g, '-'), 'data-sensor-id': s.id});
      if (i === selected) tr.classList.add('selected');
      keys.forEach((key, c) => {
        if (emptyColumn[c]) return;
        const td = el('td', {'class': heads[c].dataset.type === 'num' ? 'n' : key});
        if (key === 'sensor') {
          td.appendChild(el('code', {}, s.id));
          if (s.name) td.appendChild(el('div', {'class': 'name'}, s.name));
        } else if (key === 'reason') {
          // Two lines in the table (the numbers are in their columns); all of it on hover and when selected.
          td.appendChild(el('div', {'class': 'clamp'}, s.reason));
          td.title = s.reason;
        } else {
          td.textContent = cellText(s, key);
        }
        tr.appendChild(td);
      });
      frag.appendChild(tr);
    }
    body.appendChild(frag);
    countText.textContent = 'Showing ' + Math.min(shown, rows.length) + ' of ' + rows.length + ' matching sensors (' + sensors.length + ' in all).';
    more.hidden = rows.length <= shown;
  }
  body.addEventListener('click', e => {
    const tr = e.target.closest('tr[data-sensor-id]');
    if (!tr) return;
    select(tr.dataset.sensorId);
    document.getElementById('map-panel').scrollIntoView({block: 'nearest'});
  });
  heads.forEach(th => th.addEventListener('click', () => {
    const key = th.dataset.key;
    ascending = sortKey === key ? !ascending : th.dataset.type !== 'num';
    sortKey = key;
    heads.forEach(h => { delete h.dataset.dir; });
    th.dataset.dir = ascending ? 'asc' : 'desc';
    render();
  }));
  document.getElementById('sort-severity').addEventListener('click', () => {
    sortKey = null; heads.forEach(h => { delete h.dataset.dir; }); render();
  });
  search.addEventListener('input', () => { shown = kPage; render(); });
  document.querySelectorAll('input[name="verdict-filter"]').forEach(b => b.addEventListener('change', () => { shown = kPage; render(); }));
  document.getElementById('filter-attention').addEventListener('click', () => {
    document.querySelectorAll('input[name="verdict-filter"]').forEach(b => { b.checked = b.value !== 'consistent'; });
    shown = kPage; render();
  });
  document.getElementById('filter-all').addEventListener('click', () => {
    document.querySelectorAll('input[name="verdict-filter"]').forEach(b => { b.checked = true; });
    shown = kPage; render();
  });
  more.addEventListener('click', () => { shown += kPage; render(); });

  // The attention list (written by the page itself) links to the map the same way.
  document.querySelectorAll('#attention [data-sensor-id]').forEach(li => li.addEventListener('click', () => select(li.dataset.sensorId)));

  // For tests and for people who script the page: what the map shows and how to drive it.
  window.covmapReport = {
    data,
    select,
    selected: () => (selected >= 0 ? sensors[selected].id : null),
    view: () => ({cx, cy, k, width: W, height: H, home: homeK}),
    screenPosition: id => {  // client coordinates of a sensor's dot (reported ring when not in the map)
      const s = sensors[byId.get(id)];
      const gx = s.x !== null ? s.x : s.rx, gy = s.x !== null ? s.y : s.ry;
      if (gx === null) return null;
      const r = canvas.getBoundingClientRect(), [x, y] = toScreen(gx, gy);
      return [r.left + x, r.top + y];
    },
    lonlat: (gx, gy) => lonlat(gx, gy),
  };

  resize();
  goHome();
  render();
  draw();
  window.addEventListener('resize', () => { resize(); requestDraw(); });
})();
