// The morphcut-city HTML report's script (pipeline/html_report.cpp writes the data it reads).
// Data (script#mc-data): {format, meta, tiles, buildings, geometry}
//   buildings[i]: id, s status, r reason, t tile index, j job seconds, f input faces,
//     h Hausdorff, p parts per level, c volume-weighted convexity per level (meta.levels
//     order, null = none), ro role, xy centroid (m), fp footprint rings (flat x,y in
//     dm, both relative to meta.origin), g index into geometry
//   geometry[k]: o origin (m, x/y relative to meta.origin), v flat x,y,z in mm relative to o,
//     ghost faces, l per level: parts [index, volume, convexity, neighbours, role, id, faces];
//     a face is a ring of vertex indices, or [outer ring, hole, ...]
// Plain DOM, SVG and canvas for everything but the 3D view (three.js, inline before this script).
// Hook for tests and scripting: window.mcReport.
(function () {
  'use strict';
  const D = JSON.parse(document.getElementById('mc-data').textContent);
  const M = D.meta, B = D.buildings, G = D.geometry || [], L = M.levels || [];
  const $ = (id) => document.getElementById(id);
  const STATUS = { ok: '#2f8a4c', partial: '#e09a00', failed: '#c8322c', skipped: '#9aa0ae' };
  const statusColour = (s) => STATUS[s] || '#556070';
  const LEVEL_COLOURS = ['#2c5cc5', '#e07b39', '#3a9e5c', '#9b4dca', '#c8322c', '#1b9aaa', '#8c6d31'];
  const levelColour = (k) => LEVEL_COLOURS[k % LEVEL_COLOURS.length];
  const fmt = (v, d) => (v == null || !isFinite(v) ? '–' : Number(v).toFixed(d));
  const esc = (s) => String(s == null ? '' : s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
  const finest = (b) => { for (let k = L.length - 1; k >= 0; --k) if (b.p && b.p[k] != null) return k; return -1; };
  const hook = (window.mcReport = { ready: false, errors: [] });

  // ---------- summary ----------
  function kv(k, v, small) {
    return `<div class="kv"><div class="k">${esc(k)}</div><div class="v${small ? ' small' : ''}">${v}</div></div>`;
  }
  function secs(s) {
    if (s == null || !isFinite(s)) return '–';
    if (s < 120) return fmt(s, 1) + ' s';
    if (s < 7200) return fmt(s / 60, 1) + ' min';
    return fmt(s / 3600, 2) + ' h';
  }
  function summary() {
    const inp = M.input || {};
    const parts = [];
    if (M.kind === 'merged') {
      parts.push(kv('tiles', (M.tiles || []).length + (M.missing_tiles && M.missing_tiles.length ? ` (${M.missing_tiles.length} missing)` : '')));
    } else {
      parts.push(kv('input', esc(inp.path || '–'), true));
      if (inp.format) parts.push(kv('format', esc(inp.format + (inp.version ? ' ' + inp.version : '') + (inp.crs ? ', ' + inp.crs : ''))));
    }
    parts.push(kv('tool version', esc(M.version || '–')));
    parts.push(kv('config hash', esc(M.config_sha256 ? M.config_sha256.slice(0, 16) : (M.kind === 'merged' ? 'differs between tiles' : '–')), true));
    if (M.config_file) parts.push(kv('config file', esc(M.config_file), true));
    parts.push(kv('buildings', esc(M.building_count != null ? M.building_count : B.length)));
    parts.push(kv(M.kind === 'merged' ? 'wall time (sum of tiles)' : 'wall time', secs(M.wall_seconds)));
    if (M.cpu_seconds != null) parts.push(kv('CPU time', secs(M.cpu_seconds)));
    if (M.job_seconds_sum != null) parts.push(kv('sum of building job times', secs(M.job_seconds_sum)));
    if (M.threads != null) parts.push(kv('threads', esc(M.threads)));
    if (M.wall_seconds && B.length) parts.push(kv('buildings / s', fmt(B.length / M.wall_seconds, 2)));
    if (M.peak_rss_mb != null) parts.push(kv('peak memory', fmt(M.peak_rss_mb, 0) + ' MB'));
    if (M.cache) parts.push(kv('cache', `${M.cache.hits} hits, ${M.cache.misses} misses`));
    parts.push(kv('levels (thresholds)', esc(L.join(', ') || '–')));
    if (inp.sha256) parts.push(kv('input SHA-256', esc(inp.sha256.slice(0, 16)), true));
    $('summary-body').innerHTML = parts.join('');
    $('subtitle').textContent = `${B.length} buildings` + (M.kind === 'merged' ? `, ${(M.tiles || []).length} tiles (merged report)` : '') +
      (M.report ? ` · report ${M.report}` : ' · made from the city files alone (no run report)');

    const counts = M.counts || {};
    const total = Object.values(counts).reduce((a, b) => a + b, 0) || 1;
    let bars = '', legend = '';
    for (const [s, n] of Object.entries(counts)) {
      legend += `<span><span class="sw" style="background:${statusColour(s)}"></span>${esc(s)} ${n}</span>`;
      if (n) bars += `<div style="width:${(100 * n) / total}%;background:${statusColour(s)}" title="${esc(s)}: ${n}">${esc(s)} ${n}</div>`;
    }
    $('status-bars').innerHTML = bars;
    $('status-bars').insertAdjacentHTML('afterend', `<div class="legend">${legend}</div>`);
  }

  // ---------- plots (SVG) ----------
  const W = 460, H = 240, PAD = { l: 44, r: 20, t: 10, b: 34 };
  function frame(xTicks, yTicks, xLabel, yLabel) {
    let s = '';
    for (const t of yTicks) s += `<line class="grid" x1="${PAD.l}" x2="${W - PAD.r}" y1="${t.p}" y2="${t.p}"/><text x="${PAD.l - 4}" y="${t.p + 4}" text-anchor="end">${t.label}</text>`;
    for (const t of xTicks) s += `<text x="${t.p}" y="${H - PAD.b + 14}" text-anchor="middle">${t.label}</text>`;
    s += `<line class="axis" x1="${PAD.l}" x2="${W - PAD.r}" y1="${H - PAD.b}" y2="${H - PAD.b}"/><line class="axis" x1="${PAD.l}" x2="${PAD.l}" y1="${PAD.t}" y2="${H - PAD.b}"/>`;
    s += `<text x="${(PAD.l + W - PAD.r) / 2}" y="${H - 4}" text-anchor="middle">${esc(xLabel)}</text>`;
    s += `<text transform="translate(11 ${(PAD.t + H - PAD.b) / 2}) rotate(-90)" text-anchor="middle">${esc(yLabel)}</text>`;
    return s;
  }
  function niceTicks(lo, hi, n) {
    const span = hi - lo || 1, step0 = span / n, mag = Math.pow(10, Math.floor(Math.log10(step0)));
    const step = [1, 2, 5, 10].map((m) => m * mag).find((s) => span / s <= n) || 10 * mag;
    const out = [];
    for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9; v += step) out.push(+v.toFixed(10));
    return out;
  }
  function levelLegend() {
    return '<div class="legend">' + L.map((t, k) => `<span><span class="sw" style="background:${levelColour(k)}"></span>level ${t}</span>`).join('') + '</div>';
  }
  function svgWrap(body) { return `<svg viewBox="0 0 ${W} ${H}" role="img">${body}</svg>`; }

  function plotParts() {
    if (!L.length) { $('plot-parts').innerHTML = '<div class="note">no levels</div>'; return; }
    const CAP = 20;
    const hist = L.map(() => new Array(CAP + 1).fill(0));
    let maxP = 1;
    for (const b of B) L.forEach((t, k) => {
      const p = b.p && b.p[k];
      if (p == null || p < 1) return;
      const bin = Math.min(p, CAP);
      hist[k][bin]++;
      maxP = Math.max(maxP, bin);
    });
    const maxN = Math.max(1, ...hist.map((h) => Math.max(...h)));
    const x0 = PAD.l, x1 = W - PAD.r, y0 = H - PAD.b, y1 = PAD.t;
    const bw = (x1 - x0) / maxP, gw = (bw * 0.84) / L.length;
    const ys = (n) => y0 - ((y0 - y1) * n) / maxN;
    let s = frame(
      Array.from({ length: maxP }, (_, i) => i + 1).filter((p) => maxP <= 12 || p % 2 === 1 || p === maxP)
        .map((p) => ({ p: x0 + bw * (p - 0.5), label: p === CAP ? CAP + '+' : p })),
      niceTicks(0, maxN, 5).map((v) => ({ p: ys(v), label: v })), 'parts per building', 'buildings');
    L.forEach((t, k) => {
      for (let p = 1; p <= maxP; ++p) {
        const n = hist[k][p];
        if (!n) continue;
        const x = x0 + bw * (p - 1) + bw * 0.08 + gw * k;
        s += `<rect x="${x.toFixed(1)}" y="${ys(n).toFixed(1)}" width="${gw.toFixed(1)}" height="${(y0 - ys(n)).toFixed(1)}" fill="${levelColour(k)}"><title>level ${t}: ${n} buildings with ${p === CAP ? CAP + ' or more' : p} parts</title></rect>`;
      }
    });
    $('plot-parts').innerHTML = svgWrap(s) + levelLegend();
  }

  function plotConvexity() {
    const vals = L.map((t, k) => B.map((b) => b.c && b.c[k]).filter((v) => v != null && isFinite(v)));
    const all = [].concat(...vals);
    if (!all.length) { $('plot-convexity').innerHTML = '<div class="note">no convexity values</div>'; return; }
    const lo = Math.max(0, Math.min(0.95, Math.floor(Math.min(...all) * 20) / 20));
    const NB = 25, bw = (1 - lo) / NB;
    const hist = vals.map((vs) => { const h = new Array(NB).fill(0); for (const v of vs) h[Math.min(NB - 1, Math.max(0, Math.floor((v - lo) / bw)))]++; return h; });
    const maxN = Math.max(1, ...hist.map((h) => Math.max(...h)));
    const x0 = PAD.l, x1 = W - PAD.r, y0 = H - PAD.b, y1 = PAD.t;
    const xs = (v) => x0 + ((x1 - x0) * (v - lo)) / (1 - lo), ys = (n) => y0 - ((y0 - y1) * n) / maxN;
    let s = frame(niceTicks(lo, 1, 6).map((v) => ({ p: xs(v), label: v })), niceTicks(0, maxN, 5).map((v) => ({ p: ys(v), label: v })),
      'convexity (volume / convex hull volume)', 'buildings');
    hist.forEach((h, k) => {
      let d = `M${xs(lo).toFixed(1)},${y0}`;
      h.forEach((n, i) => { d += `L${xs(lo + i * bw).toFixed(1)},${ys(n).toFixed(1)}L${xs(lo + (i + 1) * bw).toFixed(1)},${ys(n).toFixed(1)}`; });
      d += `L${xs(1).toFixed(1)},${y0}`;
      s += `<path d="${d}" fill="none" stroke="${levelColour(k)}" stroke-width="1.6"><title>level ${L[k]}: median ${fmt(median(vals[k]), 4)}</title></path>`;
    });
    $('plot-convexity').innerHTML = svgWrap(s) + levelLegend();
  }
  function median(v) { if (!v.length) return NaN; const s = v.slice().sort((a, b) => a - b); return s[s.length >> 1]; }

  function plotTime() {
    const pts = [];
    B.forEach((b, i) => { if (b.j != null && b.f != null && b.f > 0) pts.push([b.f, Math.max(b.j, 1e-3), i]); });
    if (!pts.length) { $('plot-time').innerHTML = '<div class="note">no timings (no run report)</div>'; return; }
    const lx = (v) => Math.log10(v);
    const fx = pts.map((p) => lx(p[0])), fy = pts.map((p) => lx(p[1]));
    const xlo = Math.floor(Math.min(...fx)), xhi = Math.max(xlo + 1, Math.ceil(Math.max(...fx)));
    const ylo = Math.floor(Math.min(...fy)), yhi = Math.max(ylo + 1, Math.ceil(Math.max(...fy)));
    const x0 = PAD.l, x1 = W - PAD.r, y0 = H - PAD.b, y1 = PAD.t;
    const xs = (v) => x0 + ((x1 - x0) * (lx(v) - xlo)) / (xhi - xlo), ys = (v) => y0 - ((y0 - y1) * (lx(v) - ylo)) / (yhi - ylo);
    const dec = (a, b) => { const o = []; for (let e = a; e <= b; ++e) o.push(Math.pow(10, e)); return o; };
    const lab = (v) => (v >= 1 ? String(v) : String(+v.toPrecision(1)));
    let s = frame(dec(xlo, xhi).map((v) => ({ p: xs(v), label: lab(v) })), dec(ylo, yhi).map((v) => ({ p: ys(v), label: lab(v) + ' s' })),
      'input faces (log)', 'job time (log)');
    const order = ['skipped', 'ok', 'partial', 'failed'];
    pts.sort((a, b) => order.indexOf(B[a[2]].s) - order.indexOf(B[b[2]].s));
    for (const [f, j, i] of pts)
      s += `<circle cx="${xs(f).toFixed(1)}" cy="${ys(j).toFixed(1)}" r="2.6" fill="${statusColour(B[i].s)}" fill-opacity="0.75" data-i="${i}"><title>${esc(B[i].id)}: ${f} faces, ${fmt(B[i].j, 2)} s, ${esc(B[i].s)}</title></circle>`;
    const legend = Object.keys(STATUS).map((k) => `<span><span class="sw" style="background:${STATUS[k]}"></span>${k}</span>`).join('');
    $('plot-time').innerHTML = svgWrap(s) + `<div class="legend">${legend}</div>`;
    $('plot-time').addEventListener('click', (e) => { const i = e.target.getAttribute && e.target.getAttribute('data-i'); if (i != null) selectBuilding(+i); });
  }

  function table(rows, cols) {
    if (!rows.length) return '<div class="note">none</div>';
    let s = '<table><thead><tr>' + cols.map((c) => `<th class="${c.num ? 'num' : ''}">${c.h}</th>`).join('') + '</tr></thead><tbody>';
    for (const i of rows) s += `<tr class="pick" data-i="${i}">` + cols.map((c) => `<td class="${c.num ? 'num' : ''}">${c.f(B[i], i)}</td>`).join('') + '</tr>';
    return s + '</tbody></table>';
  }
  const partsText = (b) => (b.p || []).map((p) => (p == null ? '–' : p)).join(' / ');
  function tables() {
    const idCol = { h: 'building', f: (b) => `<span class="id">${esc(b.id)}</span>` + (b.g == null ? ' <span class="hint">(no 3D)</span>' : '') };
    const tileCol = D.tiles && D.tiles.length ? [{ h: 'tile', f: (b) => esc(b.t != null ? D.tiles[b.t] : '') }] : [];
    const slow = B.map((b, i) => i).filter((i) => B[i].j != null).sort((a, b) => B[b].j - B[a].j).slice(0, 15);
    $('table-slowest').innerHTML = table(slow, [idCol, ...tileCol,
      { h: 'status', f: (b) => `<span class="st-${esc(b.s)}">${esc(b.s)}</span>` },
      { h: 'job s', num: true, f: (b) => fmt(b.j, 2) }, { h: 'faces', num: true, f: (b) => esc(b.f) },
      { h: 'parts per level', f: partsText }]);
    const flagged = B.map((b, i) => i).filter((i) => B[i].s === 'failed' || B[i].s === 'partial');
    $('table-flagged').innerHTML = table(flagged, [idCol, ...tileCol,
      { h: 'status', f: (b) => `<span class="st-${esc(b.s)}">${esc(b.s)}</span>` },
      { h: 'reason', f: (b) => esc(b.r || '') }, { h: 'job s', num: true, f: (b) => fmt(b.j, 2) },
      { h: 'parts per level', f: partsText }]);
    for (const id of ['table-slowest', 'table-flagged'])
      $(id).addEventListener('click', (e) => { const tr = e.target.closest('tr.pick'); if (tr) selectBuilding(+tr.dataset.i); });
  }

  // ---------- plan view (canvas) ----------
  const plan = { canvas: $('plan'), scale: 1, ox: 0, oy: 0, boxes: [], mode: '' };
  const RAMP = ['#fde725', '#90d743', '#35b779', '#21918c', '#31688e', '#443983', '#440154'];
  function ramp(x) {
    x = Math.max(0, Math.min(1, x));
    const f = x * (RAMP.length - 1), i = Math.min(RAMP.length - 2, Math.floor(f)), u = f - i;
    const a = parseInt(RAMP[i].slice(1), 16), b = parseInt(RAMP[i + 1].slice(1), 16);
    const c = (s) => Math.round(((a >> s) & 255) * (1 - u) + ((b >> s) & 255) * u);
    return `rgb(${c(16)},${c(8)},${c(0)})`;
  }
  const roles = [...new Set(B.map((b) => b.ro).filter(Boolean))].sort();
  const ROLE_COLOURS = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#bab0ac'];
  const roleColour = (r) => ROLE_COLOURS[roles.indexOf(r) % ROLE_COLOURS.length];
  let maxParts = 1;
  for (const b of B) for (const p of b.p || []) if (p != null) maxParts = Math.max(maxParts, p);

  function planColour(b) {
    const m = plan.mode;
    if (m === 'status') return statusColour(b.s);
    if (m === 'role') return b.ro ? roleColour(b.ro) : '#d5d8de';
    if (m === 'convexity') {
      const k = finest(b), c = k >= 0 && b.c ? b.c[k] : null;
      return c == null ? '#d5d8de' : ramp((1 - c) / 0.2);
    }
    const k = +m.slice(1), p = b.p && b.p[k];
    return p == null ? '#d5d8de' : ramp(maxParts > 1 ? Math.log(p) / Math.log(maxParts) : 0);
  }
  function planLegend() {
    const m = plan.mode;
    let s = '';
    if (m === 'status') s = Object.keys(STATUS).map((k) => `<span class="sw" style="background:${STATUS[k]}"></span>${k} `).join('');
    else if (m === 'role') s = roles.map((r) => `<span class="sw" style="background:${roleColour(r)}"></span>${esc(r)} `).join('');
    else if (m === 'convexity') s = `<span class="sw" style="background:${ramp(0)}"></span>1.0 <span class="sw" style="background:${ramp(0.5)}"></span>0.9 <span class="sw" style="background:${ramp(1)}"></span>≤0.8`;
    else s = [1, Math.round(Math.sqrt(maxParts)), maxParts].filter((v, i, a) => a.indexOf(v) === i)
      .map((p) => `<span class="sw" style="background:${ramp(maxParts > 1 ? Math.log(p) / Math.log(maxParts) : 0)}"></span>${p} `).join('') + 'parts';
    $('plan-legend').innerHTML = s;
  }
  function planInit() {
    const sel = $('plan-colour');
    const opts = L.map((t, k) => [`p${k}`, `parts at level ${t}`]);
    opts.push(['convexity', 'convexity (finest level)'], ['status', 'status']);
    if (roles.length) opts.unshift(['role', 'massing role']);
    sel.innerHTML = opts.map(([v, l]) => `<option value="${v}">${esc(l)}</option>`).join('');
    plan.mode = roles.length ? 'role' : L.length ? `p${L.length - 1}` : 'status';
    sel.value = plan.mode;
    sel.addEventListener('change', () => { plan.mode = sel.value; planLegend(); planDraw(); });
    // world bounds (m, relative to meta.origin)
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    plan.boxes = B.map((b) => {
      let bx0 = Infinity, by0 = Infinity, bx1 = -Infinity, by1 = -Infinity;
      if (b.fp) for (const r of b.fp) for (let i = 0; i < r.length; i += 2) {
        const x = r[i] / 10, y = r[i + 1] / 10;
        bx0 = Math.min(bx0, x); by0 = Math.min(by0, y); bx1 = Math.max(bx1, x); by1 = Math.max(by1, y);
      } else if (b.xy) { bx0 = bx1 = b.xy[0]; by0 = by1 = b.xy[1]; }
      if (bx0 <= bx1) { x0 = Math.min(x0, bx0); y0 = Math.min(y0, by0); x1 = Math.max(x1, bx1); y1 = Math.max(y1, by1); }
      return bx0 <= bx1 ? [bx0, by0, bx1, by1] : null;
    });
    plan.world = isFinite(x0) ? [x0, y0, x1, y1] : [0, 0, 1, 1];
    planFit();
    planLegend();
    const c = plan.canvas;
    let drag = null, moved = false;
    c.addEventListener('pointerdown', (e) => { drag = [e.offsetX, e.offsetY]; moved = false; c.setPointerCapture(e.pointerId); });
    c.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const k = c.width / c.clientWidth, dx = (e.offsetX - drag[0]) * k, dy = (e.offsetY - drag[1]) * k;
      if (Math.abs(dx) + Math.abs(dy) > 2) moved = true;
      plan.ox += dx; plan.oy += dy; drag = [e.offsetX, e.offsetY];
      planDraw();
    });
    c.addEventListener('pointerup', (e) => {
      const wasDrag = moved; drag = null;
      if (!wasDrag) { const i = planHit(e.offsetX, e.offsetY); if (i >= 0) selectBuilding(i); }
    });
    c.addEventListener('wheel', (e) => {
      e.preventDefault();
      const k = c.width / c.clientWidth, px = e.offsetX * k, py = e.offsetY * k, f = Math.exp(-e.deltaY * 0.0015);
      plan.ox = px - (px - plan.ox) * f; plan.oy = py - (py - plan.oy) * f; plan.scale *= f;
      planDraw();
    }, { passive: false });
    $('plan-note').textContent = (M.bound.footprints_capped ? `More than ${M.bound.max_footprints} footprints: buildings are drawn as dots. ` : '') +
      `Footprints: ground surfaces (else the vertical projection) of each building's input geometry. x/y relative to (${M.origin.join(', ')})` + (M.crs ? ` in ${M.crs}` : '') + '.';
  }
  function planFit() {
    const c = plan.canvas, [x0, y0, x1, y1] = plan.world, m = 16;
    plan.scale = Math.min((c.width - 2 * m) / Math.max(x1 - x0, 1), (c.height - 2 * m) / Math.max(y1 - y0, 1));
    plan.ox = m - x0 * plan.scale + (c.width - 2 * m - (x1 - x0) * plan.scale) / 2;
    plan.oy = c.height - m + y0 * plan.scale - (c.height - 2 * m - (y1 - y0) * plan.scale) / 2;
  }
  const toScreen = (x, y) => [plan.ox + x * plan.scale, plan.oy - y * plan.scale];
  function planDraw() {
    const c = plan.canvas, g = c.getContext('2d');
    g.clearRect(0, 0, c.width, c.height);
    g.lineWidth = 0.6;
    B.forEach((b, i) => {
      if (b.fp) {
        g.beginPath();
        for (const r of b.fp) {
          for (let k = 0; k < r.length; k += 2) { const [sx, sy] = toScreen(r[k] / 10, r[k + 1] / 10); k ? g.lineTo(sx, sy) : g.moveTo(sx, sy); }
          g.closePath();
        }
        g.fillStyle = planColour(b); g.fill('evenodd');
        g.strokeStyle = 'rgba(30,35,50,0.55)'; g.stroke();
      } else if (b.xy) {
        const [sx, sy] = toScreen(b.xy[0], b.xy[1]);
        g.beginPath(); g.arc(sx, sy, 2.5, 0, 2 * Math.PI); g.fillStyle = planColour(b); g.fill();
      }
    });
    if (view.current >= 0) {
      const b = B[view.current];
      g.lineWidth = 2.5; g.strokeStyle = '#e0245e';
      if (b.fp) {
        g.beginPath();
        for (const r of b.fp) { for (let k = 0; k < r.length; k += 2) { const [sx, sy] = toScreen(r[k] / 10, r[k + 1] / 10); k ? g.lineTo(sx, sy) : g.moveTo(sx, sy); } g.closePath(); }
        g.stroke();
      } else if (b.xy) { const [sx, sy] = toScreen(b.xy[0], b.xy[1]); g.beginPath(); g.arc(sx, sy, 6, 0, 2 * Math.PI); g.stroke(); }
    }
    // scale bar
    const target = 100 / plan.scale, nice = [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000].find((v) => v >= target) || 10000;
    const len = nice * plan.scale;
    g.fillStyle = '#334'; g.fillRect(12, c.height - 14, len, 3);
    g.font = '11px system-ui, sans-serif'; g.fillText(nice >= 1000 ? nice / 1000 + ' km' : nice + ' m', 12, c.height - 18);
  }
  function pointIn(r, x, y) {
    let inside = false;
    for (let i = 0, j = r.length - 2; i < r.length; j = i, i += 2) {
      const xi = r[i] / 10, yi = r[i + 1] / 10, xj = r[j] / 10, yj = r[j + 1] / 10;
      if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  }
  function planHit(offX, offY) {
    const c = plan.canvas, k = c.width / c.clientWidth, px = offX * k, py = offY * k;
    const x = (px - plan.ox) / plan.scale, y = (plan.oy - py) / plan.scale;
    let best = -1, bestD = Infinity;
    B.forEach((b, i) => {
      const bx = plan.boxes[i];
      if (!bx) return;
      if (b.fp) {
        if (x < bx[0] || x > bx[2] || y < bx[1] || y > bx[3]) return;
        let inside = false;
        for (const r of b.fp) if (pointIn(r, x, y)) inside = !inside;
        if (inside) { best = i; bestD = 0; }
      } else {
        const d = Math.hypot(bx[0] - x, bx[1] - y) * plan.scale;
        if (d < 8 && d < bestD) { best = i; bestD = d; }
      }
    });
    return best;
  }

  // ---------- 3D view (three.js) ----------
  const view = { current: -1, level: -1, ready3d: false, parts: [], ghost: null, explode: false };
  function viewMessage(text) {
    const host = $('view3d');
    let m = host.querySelector('.msg');
    if (!m) { m = document.createElement('div'); m.className = 'msg'; host.appendChild(m); }
    m.textContent = text;
    m.style.display = text ? 'flex' : 'none';
  }
  function webglAvailable() {
    try { const c = document.createElement('canvas'); return !!(c.getContext('webgl2') || c.getContext('webgl')); } catch (e) { return false; }
  }
  function init3d() {
    if (!M.three || typeof THREE === 'undefined') { viewMessage('This page was built without three.js (tools/html/setup.sh installs it): no 3D view.'); return; }
    if (!webglAvailable()) { viewMessage('WebGL is not available in this browser: no 3D view.'); return; }
    const host = $('view3d');
    const renderer = new THREE.WebGLRenderer({ antialias: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(host.clientWidth, host.clientHeight);
    host.appendChild(renderer.domElement);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xeef0f4);
    scene.add(new THREE.HemisphereLight(0xffffff, 0x667088, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(0.5, -0.8, 1.4);
    scene.add(sun);
    const camera = new THREE.PerspectiveCamera(40, host.clientWidth / host.clientHeight, 0.1, 20000);
    camera.up.set(0, 0, 1);
    const controls = new THREE.OrbitControls(camera, renderer.domElement);
    controls.addEventListener('change', () => render());
    Object.assign(view, { renderer, scene, camera, controls, raycaster: new THREE.Raycaster(), group: new THREE.Group(), ready3d: true });
    scene.add(view.group);
    renderer.domElement.addEventListener('pointermove', hover);
    renderer.domElement.addEventListener('pointerleave', () => { setHover(null); });
    window.addEventListener('resize', () => {
      renderer.setSize(host.clientWidth, host.clientHeight);
      camera.aspect = host.clientWidth / host.clientHeight; camera.updateProjectionMatrix(); render();
    });
  }
  function render() { if (view.ready3d) view.renderer.render(view.scene, view.camera); }

  // Faces -> triangles (earcut via THREE.ShapeUtils in the face's dominant plane), flat normals.
  function buildFaces(faces, P) {
    const pos = [], nor = [], edges = [];
    const V = (i) => [P[3 * i], P[3 * i + 1], P[3 * i + 2]];
    for (const face of faces) {
      const rings = typeof face[0] === 'number' ? [face] : face;
      const outer = rings[0];
      let nx = 0, ny = 0, nz = 0;
      for (let i = 0; i < outer.length; ++i) {
        const a = V(outer[i]), b = V(outer[(i + 1) % outer.length]);
        nx += (a[1] - b[1]) * (a[2] + b[2]); ny += (a[2] - b[2]) * (a[0] + b[0]); nz += (a[0] - b[0]) * (a[1] + b[1]);
      }
      const nl = Math.hypot(nx, ny, nz) || 1; nx /= nl; ny /= nl; nz /= nl;
      const ax = Math.abs(nx), ay = Math.abs(ny), az = Math.abs(nz);
      const [u, v] = az >= ax && az >= ay ? [0, 1] : ax >= ay ? [1, 2] : [0, 2];
      const flat = [];
      const pts2 = rings.map((r) => r.map((i) => { flat.push(i); const p = V(i); return new THREE.Vector2(p[u], p[v]); }));
      let tris;
      if (outer.length === 3 && rings.length === 1) tris = [[0, 1, 2]];
      else tris = THREE.ShapeUtils.triangulateShape(pts2[0], pts2.slice(1));
      for (const t of tris) for (const k of t) { const p = V(flat[k]); pos.push(p[0], p[1], p[2]); nor.push(nx, ny, nz); }
      for (const r of rings) for (let i = 0; i < r.length; ++i) { const a = V(r[i]), b = V(r[(i + 1) % r.length]); edges.push(a[0], a[1], a[2], b[0], b[1], b[2]); }
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    g.setAttribute('normal', new THREE.Float32BufferAttribute(nor, 3));
    const e = new THREE.BufferGeometry();
    e.setAttribute('position', new THREE.Float32BufferAttribute(edges, 3));
    return { mesh: g, edges: e };
  }
  const partColour = (j, role) => role && roles.length ? new THREE.Color(roleColour(role)) : new THREE.Color().setHSL(((j * 0.618034) + 0.08) % 1, 0.62, 0.56);

  function clearGroup() {
    const g = view.group;
    while (g.children.length) {
      const o = g.children.pop();
      if (o.geometry) o.geometry.dispose();
      if (o.material) o.material.dispose();
    }
    view.parts = []; view.ghost = null;
  }
  function show3d(i, keepCamera) {
    const b = B[i];
    const host = $('view3d');
    host.dataset.building = b.id;
    host.dataset.parts = '0';
    if (!view.ready3d) return;
    clearGroup();
    if (b.g == null) {
      viewMessage(`No geometry embedded for ${b.id} (the page embeds ${M.bound.with_3d} of ${B.length} buildings: ${M.bound.rule}).`);
      render();
      return;
    }
    viewMessage('');
    const geo = G[b.g];
    const P = new Float32Array(geo.v.length);
    for (let k = 0; k < geo.v.length; ++k) P[k] = geo.v[k] / 1000;
    let cx = 0, cy = 0, cz = 0, x0 = Infinity, y0 = Infinity, z0 = Infinity, x1 = -Infinity, y1 = -Infinity, z1 = -Infinity;
    for (let k = 0; k < P.length; k += 3) {
      x0 = Math.min(x0, P[k]); x1 = Math.max(x1, P[k]); y0 = Math.min(y0, P[k + 1]); y1 = Math.max(y1, P[k + 1]); z0 = Math.min(z0, P[k + 2]); z1 = Math.max(z1, P[k + 2]);
    }
    cx = (x0 + x1) / 2; cy = (y0 + y1) / 2; cz = (z0 + z1) / 2;
    const level = view.level;
    const parts = level >= 0 && geo.l[level] ? geo.l[level] : [];
    parts.forEach((p, j) => {
      const { mesh, edges } = buildFaces(p[6], P);
      const mat = new THREE.MeshLambertMaterial({ color: partColour(j, p[4]), side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
      const m = new THREE.Mesh(mesh, mat);
      m.userData = { part: p, level: L[level], base: mat.color.clone() };
      const lines = new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ color: 0x1d2330, transparent: true, opacity: 0.7 }));
      mesh.computeBoundingBox();
      const c = new THREE.Vector3(); mesh.boundingBox.getCenter(c);
      m.userData.dir = new THREE.Vector3(c.x - cx, c.y - cy, (c.z - cz) * 0.5);
      m.userData.lines = lines;
      view.group.add(m); view.group.add(lines);
      view.parts.push(m);
    });
    applyExplode();
    if (geo.ghost && geo.ghost.length) {
      const { mesh, edges } = buildFaces(geo.ghost, P);
      const gm = new THREE.Mesh(mesh, new THREE.MeshBasicMaterial({ color: 0x7d8aa3, transparent: true, opacity: 0.16, depthWrite: false, side: THREE.DoubleSide }));
      const gl = new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ color: 0x55607a, transparent: true, opacity: 0.35, depthWrite: false }));
      gm.renderOrder = 2; gl.renderOrder = 3;
      gm.visible = gl.visible = $('ghost-toggle').checked;
      view.group.add(gm); view.group.add(gl);
      view.ghost = [gm, gl];
    }
    host.dataset.parts = String(view.parts.length);
    host.dataset.level = level >= 0 ? String(L[level]) : '';
    if (!keepCamera) {
      // Frame the bounding sphere, seen from the south-east and above.
      const radius = Math.max(0.5 * Math.hypot(x1 - x0, y1 - y0, z1 - z0), 0.5), d = 2 * radius;
      const dist = (radius / Math.sin((view.camera.fov * Math.PI) / 360)) * 0.92;
      const dir = new THREE.Vector3(0.55, -0.72, 0.42).normalize().multiplyScalar(dist);
      view.controls.target.set(cx, cy, cz);
      view.camera.position.set(cx + dir.x, cy + dir.y, cz + dir.z);
      view.camera.near = d / 100; view.camera.far = d * 100; view.camera.updateProjectionMatrix();
      view.controls.update();
    }
    render();
  }
  function applyExplode() {
    for (const m of view.parts) {
      const f = view.explode ? 0.35 : 0;
      m.position.copy(m.userData.dir).multiplyScalar(f);
      m.userData.lines.position.copy(m.position);
    }
  }
  let hovered = null;
  function setHover(m, ev) {
    const tip = $('tooltip');
    if (hovered && hovered !== m) hovered.material.color.copy(hovered.userData.base);
    hovered = m;
    if (!m) { tip.style.display = 'none'; render(); return; }
    m.material.color.copy(m.userData.base).offsetHSL(0, 0, 0.18);
    const p = m.userData.part;
    tip.innerHTML = `<b>${esc(p[5])}</b><br>level ${m.userData.level}, part ${p[0]}<br>volume ${fmt(p[1], 2)} m³<br>convexity ${fmt(p[2], 4)}<br>neighbours ${p[3]}` + (p[4] ? `<br>role ${esc(p[4])}` : '');
    const host = $('view3d').getBoundingClientRect();
    tip.style.left = Math.min(ev.clientX - host.left + 14, host.width - 230) + 'px';
    tip.style.top = ev.clientY - host.top + 12 + 'px';
    tip.style.display = 'block';
    render();
  }
  function hover(ev) {
    if (!view.parts.length) return;
    const r = view.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((ev.clientX - r.left) / r.width) * 2 - 1, -((ev.clientY - r.top) / r.height) * 2 + 1);
    view.raycaster.setFromCamera(ndc, view.camera);
    const hit = view.raycaster.intersectObjects(view.parts, false)[0];
    setHover(hit ? hit.object : null, ev);
  }

  function levelButtons(i) {
    const b = B[i], geo = b.g != null ? G[b.g] : null;
    $('level-buttons').innerHTML = L.map((t, k) => {
      const has = geo && geo.l[k] && geo.l[k].length;
      return `<button data-k="${k}" class="${k === view.level ? 'on' : ''}" ${has ? '' : 'disabled'}>${t} (${b.p && b.p[k] != null ? b.p[k] : '–'})</button>`;
    }).join('') + ' <label><input type="checkbox" id="explode-toggle"' + (view.explode ? ' checked' : '') + '> explode</label>';
    $('explode-toggle').addEventListener('change', (e) => { view.explode = e.target.checked; applyExplode(); render(); });
  }
  function buildingInfo(b) {
    const t = b.t != null && D.tiles ? `tile ${esc(D.tiles[b.t])} · ` : '';
    $('building-info').innerHTML = `<span class="id">${esc(b.id)}</span> · ${t}<span class="st-${esc(b.s)}">${esc(b.s)}</span>` +
      (b.r ? ` (${esc(b.r)})` : '') + ` · parts per level ${partsText(b)} · convexity ${(b.c || []).map((c) => fmt(c, 3)).join(' / ')}` +
      (b.j != null ? ` · job ${fmt(b.j, 2)} s` : '') + (b.f != null ? ` · ${b.f} input faces` : '') + (b.h != null ? ` · Hausdorff ${fmt(b.h, 3)} m` : '');
  }
  function selectBuilding(i, level) {
    if (i < 0 || i >= B.length) return;
    const b = B[i];
    view.current = i;
    const geo = b.g != null ? G[b.g] : null;
    if (level != null) view.level = level;
    else if (!(geo && view.level >= 0 && geo.l[view.level] && geo.l[view.level].length)) {
      view.level = -1;
      if (geo) for (let k = L.length - 1; k >= 0; --k) if (geo.l[k] && geo.l[k].length) { view.level = k; break; }
    }
    const pick = $('pick');
    if (b.g != null) pick.value = String(i);
    levelButtons(i);
    buildingInfo(b);
    show3d(i);
    planDraw();
  }

  function pickerInit() {
    const sel = $('pick');
    const idx = B.map((b, i) => i).filter((i) => B[i].g != null);
    sel.innerHTML = idx.map((i) => `<option value="${i}">${esc(B[i].id)} (${esc(B[i].s)}, ${partsText(B[i])})</option>`).join('');
    sel.addEventListener('change', () => selectBuilding(+sel.value));
    $('level-buttons').addEventListener('click', (e) => {
      const k = e.target.dataset && e.target.dataset.k;
      if (k == null || e.target.disabled) return;
      view.level = +k;
      levelButtons(view.current);
      show3d(view.current, true);
    });
    $('ghost-toggle').addEventListener('change', (e) => { if (view.ghost) for (const o of view.ghost) o.visible = e.target.checked; render(); });
    // First building shown: the embedded one with the most parts at the finest level.
    let first = -1, most = -1;
    for (const i of idx) { const k = finest(B[i]), p = k >= 0 ? B[i].p[k] : 0; if (p > most) { most = p; first = i; } }
    return first;
  }

  function about() {
    const bd = M.bound;
    $('about').innerHTML =
      `<p>3D geometry (input ghost and every level's parts) is embedded for ${bd.with_3d} of ${B.length} buildings: ${esc(bd.rule)} (bound: ${bd.max_3d} buildings and ${bd.max_3d_mb} MB of geometry, so that a large city's page stays small). Every building has its row in the tables, its point in the plots and its footprint in the plan${bd.footprints_capped ? ` (as a dot: more than ${bd.max_footprints} footprints)` : ''}.</p>` +
      `<p>Sources: ${M.report ? `run report <code>${esc(M.report)}</code>; ` : ''}city files ${(M.city_files || []).map((f) => `<code>${esc(f)}</code>`).join(', ') || 'none'}. Parts are the BuildingParts with <code>morphcut_level</code>; the ghost is each building's own input geometry at its highest LoD. Made again from the same outputs with <code>morphcut-city html REPORT.json [CITY.json ...] -o OUT.html</code>.</p>` +
      (M.warnings && M.warnings.length ? `<p>Warnings: ${M.warnings.map(esc).join('; ')}</p>` : '') +
      `<p>This page is self-contained and makes no network request (its Content-Security-Policy forbids any). The 3D view uses three.js ${typeof THREE !== 'undefined' ? esc(THREE.REVISION) : '(not included)'} (MIT licence, © three.js authors; the licence text is in the comment at the head of the inline three.js script).</p>`;
  }

  function main() {
    summary();
    plotParts();
    plotConvexity();
    plotTime();
    tables();
    planInit();
    init3d();
    const first = pickerInit();
    about();
    if (first >= 0) selectBuilding(first);
    else { planDraw(); if (view.ready3d) viewMessage('No building geometry embedded.'); }
    hook.select = (id) => { const i = B.findIndex((b) => b.id === id); if (i >= 0) selectBuilding(i); return i; };
    hook.level = (k) => { if (view.current >= 0) selectBuilding(view.current, k); };
    hook.shown = () => ({ building: view.current >= 0 ? B[view.current].id : null, level: view.level >= 0 ? L[view.level] : null, parts: view.parts.length, ghost: !!view.ghost });
    // Where a building is on the plan canvas, in client (page viewport) coordinates.
    hook.planPoint = (id) => {
      const i = B.findIndex((b) => b.id === id), bx = plan.boxes[i];
      if (!bx) return null;
      const b = B[i];
      let x = (bx[0] + bx[2]) / 2, y = (bx[1] + bx[3]) / 2;
      if (b.fp && !b.fp.some((r) => pointIn(r, x, y))) {  // concave: use a vertex-adjacent inner point
        const r = b.fp[0];
        for (let k = 0; k < r.length; k += 2) {
          const tx = r[k] / 10 * 0.9 + x * 0.1, ty = r[k + 1] / 10 * 0.9 + y * 0.1;
          if (pointIn(r, tx, ty)) { x = tx; y = ty; break; }
        }
      }
      const [sx, sy] = toScreen(x, y), c = plan.canvas, rc = c.getBoundingClientRect(), k = c.clientWidth / c.width;
      return { x: rc.left + sx * k, y: rc.top + sy * k };
    };
    hook.ready = true;
    document.body.dataset.ready = '1';
  }
  try { main(); } catch (e) { hook.errors.push(String(e && e.stack || e)); throw e; }
})();
