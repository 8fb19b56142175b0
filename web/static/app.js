// The page: options in the form and the URL, a file in, the worker's
// results out (tables, plots, downloads). The analysis itself is the
// library's (worker.js → pkg/, WebAssembly); nothing here computes.

const $ = (id) => document.getElementById(id);
const form = $('options');
const PRESETS = {
  // docs/REFERENCE.md's worked example.
  steel: { e1: '200e9', nu1: '0.3', e2: '200e9', nu2: '0.3', hardness: '2e9', delta_gamma: '0.3', epsilon: '0.4e-9' },
  // The README's aluminium pin on a nickel-coated disk.
  'al-ni': { e1: '70e9', nu1: '0.33', e2: '200e9', nu2: '0.31', hardness: '1e9', delta_gamma: '0.5', epsilon: '0.4e-9' },
};

let worker = null;
let busy = false;
let names = null;
let version = '';
let file = null; // { name, bytes: ArrayBuffer }
let run = 0; // the current analysis; older results are dropped
let current = {}; // its file and options
let started = 0;
let result = null;
let extra = {}; // URL keys the form has no field for: the library refuses them by name
const plots = {};

// One worker at a time. A restart (to drop a scan still running) posts its
// request at once: the worker queues it until its WebAssembly is ready, and
// its second 'ready' is not taken for the page's first (issue 49: taking it
// for one re-ran analyse(), which restarted the worker again, forever).
function startWorker() {
  if (worker) worker.terminate();
  worker = new Worker('worker.js', { type: 'module' });
  worker.onmessage = ({ data }) => handle(data);
  worker.onerror = (e) => showError(`the page's worker failed: ${e.message}`);
}

function status(text, progress) {
  $('status-text').textContent = text;
  const p = $('progress');
  if (progress === undefined) {
    p.hidden = true;
  } else {
    p.hidden = false;
    if (progress === null) p.removeAttribute('value');
    else { p.max = progress[1]; p.value = progress[0]; }
  }
}

function showError(message) {
  const e = $('error');
  e.textContent = message ? `error: ${message}` : '';
  e.hidden = !message;
  if (message) status('');
}

// The options: the form's non-empty fields and the URL's unknown keys.
function options() {
  const o = { ...extra };
  for (const el of form.elements) {
    if (el.name && el.value.trim() !== '') o[el.name] = el.value.trim();
  }
  return o;
}

function writeUrl() {
  const q = new URLSearchParams(options()).toString();
  history.replaceState(null, '', q ? `?${q}` : location.pathname);
}

function readUrl() {
  extra = {};
  for (const [key, value] of new URLSearchParams(location.search)) {
    const el = form.elements.namedItem(key);
    if (!el) { extra[key] = value; continue; }
    if (el.tagName === 'SELECT' && ![...el.options].some((o) => o.value === value)) {
      el.add(new Option(value, value)); // the library names the valid ones
    }
    el.value = value;
  }
}

function fillSelects() {
  for (const el of form.querySelectorAll('select[data-names]')) {
    el.replaceChildren(new Option('(default)', ''));
    for (const n of names[el.dataset.names]) el.add(new Option(n, n));
  }
  const ext = names.formats.map((f) => (f.extensions.length
    ? `${f.description} (${f.extensions.map((e) => '.' + e).join(', ')})` : f.description));
  $('formats').textContent = `Formats: ${ext.join('; ')}.`;
}

function analyse() {
  writeUrl();
  if (!file || !names) return;
  const opts = options();
  const key = JSON.stringify(opts);
  // A field's 'change' then the form's submit (Analyse, Enter): one run.
  if (busy && file === current.file && key === current.key) return;
  if (busy) startWorker(); // drop a scan still running
  current = { file, key };
  busy = true;
  run += 1;
  started = performance.now();
  showError('');
  $('results').classList.add('stale'); // the last result, until the new one
  status(`analysing ${file.name}…`, null);
  worker.postMessage({ id: run, bytes: file.bytes.slice(0), name: file.name, options: opts });
}

async function openFile(f) {
  started = performance.now();
  file = { name: f.name, bytes: await f.arrayBuffer() };
  analyse();
}

function handle(m) {
  if (m.type === 'ready') {
    if (names) return; // a restarted worker: its request is already posted
    names = m.names;
    // The fields' labels, as the page's messages name them (the browser test reads them).
    document.documentElement.dataset.labels = JSON.stringify(names.labels);
    version = m.version;
    $('version').textContent = version;
    fillSelects();
    readUrl();
    status('open a surface file');
    if (file) analyse();
    return;
  }
  if (m.id !== run) return;
  switch (m.type) {
    case 'error':
      busy = false;
      showError(m.message);
      if (/gives no sampling interval/.test(m.message)) form.elements.namedItem('dx').focus();
      $('results').hidden = true;
      $('record').textContent = '';
      break;
    case 'result':
      result = m;
      if (m.container) showContainer(m); else showResult(m);
      // The statistics are shown; why μ is not (kefric's message in the page's words).
      if (m.error) showError(m.error);
      requestAnimationFrame(() => {
        const what = m.container ? 'read and analysed' : 'read, analysed and μ(F) drawn';
        $('timing').textContent = `(${what} in ${Math.round(performance.now() - started)} ms)`;
        document.body.dataset.drawn = String(run);
      });
      status('spectra and histogram…', null);
      break;
    case 'curves':
      if (m.container) {
        result.psd = m.psd;
        drawContainerPsd(m.psd);
        status('scan over λs…', null);
        break;
      }
      result.histogram = m.histogram;
      result.psd = m.psd;
      // μ(F) under the other height models, over the analysis' own curve.
      if (result.load.load.length && Object.keys(m.models).length) {
        result.load.models = m.models;
        drawLoad(result.load, JSON.parse(result.record).friction);
      }
      drawHistogram(m.histogram);
      drawPsd(m.psd);
      status('scan over λs…', null);
      break;
    case 'progress':
      status(`scan over λs: ${m.done} of ${m.total}`, [m.done, m.total]);
      break;
    case 'scan':
      busy = false;
      result.scan = m.scan;
      if (m.container) drawContainerScan(m.scan); else drawScan(m.scan);
      status(`done: ${file.name}`);
      document.body.dataset.done = String(run);
      break;
  }
}

// A number with `digits` significant digits: plain from 0.001 to 10⁵,
// else scientific (6.45e17, not 645046000000000000; 1.66e-6, not
// 0.00000166), trailing zeros dropped.
function num(v, digits = 4) {
  if (v === 0 || !Number.isFinite(v)) return String(v);
  const a = Math.abs(v);
  if (a >= 1e-3 && a < 1e5) return String(Number(v.toPrecision(digits)));
  const [m, e] = v.toExponential(digits - 1).split('e');
  return `${String(Number(m))}e${Number(e)}`;
}
const fmt = (v) => (v === null || v === undefined ? '–' : typeof v === 'number' ? num(v) : String(v));

// The record, the command line and the warnings of a result shown; the
// page laid out for one surface or a container.
function showCommon(m, container) {
  $('results').hidden = false;
  $('results').classList.remove('stale');
  $('results').classList.toggle('container', container);
  $('record').textContent = m.record;
  $('command').textContent = m.command;
  const w = $('warnings');
  w.replaceChildren(...m.warnings.map((t) => Object.assign(document.createElement('li'), { textContent: t })));
}

function showStats(rows) {
  $('stats').replaceChildren(...rows.map(([k, v, u]) => {
    const tr = document.createElement('tr');
    tr.innerHTML = '<td></td><td class="v"></td><td></td>';
    tr.children[0].textContent = k;
    tr.children[1].textContent = fmt(v);
    tr.children[2].textContent = u;
    return tr;
  }));
}

function showResult(m) {
  const r = JSON.parse(m.record);
  showCommon(m, false);
  const s = r.surface;
  const rows = [
    ['σ (Sq)', s.sigma, 'm'], ['Sk (Ssk)', s.skewness, ''], ['K (Sku)', s.kurtosis, ''],
    ['m2', s.m2, ''], ['m4', s.m4, '1/m²'], ['α (bandwidth)', s.alpha, ''],
    ['η (summit density)', s.eta, '1/m²'], ['R (summit radius)', s.radius, 'm'], ['β = ηRσ', s.beta, ''],
    ['Δx', s.dx, 'm'], ['Δy', s.dy, 'm'], ['scan size x', s.size_x, 'm'], ['scan size y', s.size_y, 'm'],
    ['λs', s.lambda_s, 'm'], ['λc', s.lambda_c, 'm'],
  ];
  if (r.model) {
    const p = r.model;
    rows.push(['ψ', p.psi, ''], ['θ', p.theta, ''], ['β (model)', p.beta, ''], ['ε*', p.eps_star, ''],
      ['heights', `${p.distribution}`, '']);
  }
  if (r.friction) {
    const f = r.friction;
    rows.push(['F* = F/(Aₙ H)', f.f_star, ''], ['μ', f.mu, ''],
      f.friction_force !== undefined && f.friction_force !== null ? ['Q = μF', f.friction_force, 'N'] : ['μF/Aₙ', f.friction_stress, 'Pa'],
      ['h* (separation/σ)', f.h_star, '']);
  }
  showStats(rows);
  drawMap(m.map, s);
  drawLoad(m.load, r.friction);
  link('download-json', `${file.name}.json`, m.record + '\n', 'application/json');
  link('download-load', `${file.name}.mu-load.csv`,
    csv([`load_${m.load.unit === 'Pa' ? 'pa' : 'n'}`, 'mu'], [m.load.load, m.load.mu]), 'text/csv');
  for (const id of ['download-scan', 'download-psd', 'download-histogram']) $(id).removeAttribute('href');
}

// A container (kefric surface CONTAINER --json's record): its
// measurements, then the combined spectrum's band, moments and roughness,
// the model's inputs and μ at each load.
function showContainer(m) {
  const r = JSON.parse(m.record);
  showCommon(m, true);
  const row = (tag, cells) => {
    const tr = document.createElement('tr');
    tr.append(...cells.map((c) => Object.assign(document.createElement(tag), { textContent: fmt(c) })));
    return tr;
  };
  $('measurements').replaceChildren(
    row('th', ['measurement', 'file', 'instrument', 'unit', 'nx', 'ny', 'Δx (m)', 'size x (m)', 'size y (m)',
      'reliable from (m)', 'to (m)']),
    ...r.measurements.map((x) => row('td', [x.name, x.file, x.instrument, x.unit, x.nx, x.ny, x.dx, x.size[0],
      x.size[1], x.reliable?.lambda_min, x.reliable?.lambda_max])));
  const rows = [];
  if (r.combined) {
    const c = r.combined, g = c.roughness;
    rows.push(['λs (band)', c.band.lambda_s, 'm'], ['λc (band)', c.band.lambda_c, 'm'],
      ['rests on', c.rests_on.join(', '), ''], ['heights from', c.heights_from, ''],
      ['m0', c.moments.m0, 'm²'], ['m2', c.moments.m2, ''], ['m4', c.moments.m4, '1/m²'],
      ['σ', g.sigma, 'm'], ['α (bandwidth)', g.alpha, ''], ['η (summit density)', g.eta, '1/m²'],
      ['R (summit radius)', g.radius, 'm'], ['β = ηRσ', g.beta, '']);
  }
  if (r.model) {
    const p = r.model;
    rows.push(['ψ', p.psi, ''], ['θ', p.theta, ''], ['β (model)', p.beta, ''], ['ε*', p.eps_star, ''],
      ['heights', `${p.distribution}`, '']);
  }
  for (const f of r.friction ?? []) {
    rows.push(['F* = F/(Aₙ H)', f.f_star, ''], ['μ', f.mu, ''],
      f.friction_force !== undefined && f.friction_force !== null ? ['Q = μF', f.friction_force, 'N'] : ['μF/Aₙ', f.friction_stress, 'Pa'],
      ['h* (separation/σ)', f.h_star, '']);
  }
  showStats(rows);
  link('download-json', `${file.name}.json`, m.record + '\n', 'application/json');
  for (const id of ['download-load', 'download-scan', 'download-psd', 'download-histogram']) $(id).removeAttribute('href');
}

// CSV with a provenance header: the library's version, the file and every
// option (the equivalent command line).
function csv(header, columns) {
  const lines = [
    `# ke-friction ${version} (web page, WebAssembly)`,
    `# file: ${file.name}`,
    `# options: ${JSON.stringify(options())}`,
    `# command: ${result.command}`,
    header.join(','),
  ];
  const n = columns.length ? columns[0].length : 0;
  for (let i = 0; i < n; i++) lines.push(columns.map((c) => (c[i] === null || c[i] === undefined ? '' : String(c[i]))).join(','));
  return lines.join('\n') + '\n';
}

function link(id, name, text, type) {
  const a = $(id);
  if (a.href.startsWith('blob:')) URL.revokeObjectURL(a.href);
  a.href = URL.createObjectURL(new Blob([text], { type }));
  a.download = name;
}

// A perceptual colour map (viridis' ends and three stops between).
const STOPS = [[68, 1, 84], [59, 82, 139], [33, 145, 140], [94, 201, 98], [253, 231, 37]];
function colour(t) {
  const x = Math.min(Math.max(t, 0), 1) * (STOPS.length - 1);
  const k = Math.min(Math.floor(x), STOPS.length - 2);
  const f = x - k;
  return STOPS[k].map((c, i) => Math.round(c + f * (STOPS[k + 1][i] - c)));
}

function drawMap(map, s) {
  const canvas = $('map');
  const w = Math.ceil(map.nx / map.step);
  const h = Math.ceil(map.ny / map.step);
  let lo = Infinity, hi = -Infinity;
  for (const z of map.z) if (!Number.isNaN(z)) { lo = Math.min(lo, z); hi = Math.max(hi, z); }
  const span = hi > lo ? hi - lo : 1;
  canvas.width = w;
  canvas.height = h;
  const ctx = canvas.getContext('2d');
  const img = ctx.createImageData(w, h);
  for (let k = 0; k < map.z.length; k++) {
    const z = map.z[k];
    const [r, g, b] = Number.isNaN(z) ? [255, 255, 255] : colour((z - lo) / span);
    img.data.set([r, g, b, 255], 4 * k);
  }
  ctx.putImageData(img, 0, 0);
  canvas.style.height = map.ny === 1 ? '40px' : `${Math.round(400 * Math.min(1, (s.size_y ?? 0) / s.size_x || 1))}px`;
  const bar = $('colorbar');
  const bctx = bar.getContext('2d');
  for (let y = 0; y < bar.height; y++) {
    const [r, g, b] = colour(1 - y / (bar.height - 1));
    bctx.fillStyle = `rgb(${r},${g},${b})`;
    bctx.fillRect(0, y, bar.width, 1);
  }
  const um = (v) => `${fmt(v * 1e6)} µm`;
  $('colorbar-labels').replaceChildren(...[hi, (hi + lo) / 2, lo].map((v) => Object.assign(document.createElement('span'), { textContent: um(v) })));
  $('map-size').textContent = `${map.nx} × ${map.ny} points, ${um(s.size_x)}${s.size_y ? ' × ' + um(s.size_y) : ''}` +
    (map.step > 1 ? ` (one point in ${map.step} along x and y shown)` : '');
}

// Tick labels as num(): the fewest significant digits (1 to 6) that keep
// the labels of an axis distinct (no "1e-4, 1e-4"); on a log axis only
// the decades (uPlot passes the minor ticks too).
const ticks = (u, vs, axis) => {
  const log = u.scales[u.axes[axis].scale].distr === 3;
  const shown = vs.map((v) => v !== null && !(log && Math.abs(Math.log10(v) - Math.round(Math.log10(v))) > 1e-9));
  for (let digits = 1; ; digits++) {
    const labels = vs.map((v, i) => (v === null ? null : shown[i] ? num(v, digits) : ''));
    const set = labels.filter((l) => l);
    if (digits >= 6 || new Set(set).size === set.length) return labels;
  }
};

// uPlot turns a right axis' label to read downwards: this draws it
// upwards, as the left one, beside the right edge.
const rightLabel = (text) => (u) => {
  const ctx = u.ctx;
  ctx.save();
  ctx.font = `bold ${12 * devicePixelRatio}px system-ui, sans-serif`;
  ctx.fillStyle = '#000';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'bottom';
  ctx.translate(ctx.canvas.width - 4 * devicePixelRatio, u.bbox.top + u.bbox.height / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.fillText(text, 0, 0);
  ctx.restore();
};

function plot(id, opts, data) {
  for (const axis of opts.axes ?? []) axis.values ??= ticks;
  if (plots[id]) plots[id].destroy();
  const el = $(id);
  el.replaceChildren();
  plots[id] = new uPlot({ width: 520, height: 300, ...opts }, data, el);
}

function message(id, text) {
  if (plots[id]) { plots[id].destroy(); delete plots[id]; }
  $(id).replaceChildren(Object.assign(document.createElement('p'), { className: 'note', textContent: text }));
}

// μ against the load under each height model of the sensitivity (the
// chosen one emphasised, the others thinner; a model the surface does not
// admit named with its reason), the given load marked, and μ at the two
// ends of the reliable band (the record's sensitivity) below.
function drawLoad(load, friction) {
  if (!load.load.length) {
    message('mu-load', 'give the materials and a load (force and area, or pressure) for μ');
    return;
  }
  const unit = load.unit === 'Pa' ? 'pressure (Pa)' : 'normal force F (N)';
  const given = load.unit === 'Pa' ? friction.pressure : friction.force;
  const colours = { gaussian: '#2e7d32', pearson: '#6a1b9a', empirical: '#ef6c00' };
  const models = Object.entries(load.models ?? {}).filter(([, m]) => m.load && m.load.length);
  const refused = Object.entries(load.models ?? {}).filter(([, m]) => m.error);
  const tables = [[load.load, load.mu], ...models.map(([, m]) => [m.load, m.mu])];
  const data = models.length ? uPlot.join(tables) : [load.load, load.mu];
  const series = [{ label: unit }, { label: `μ (${load.chosen ?? 'chosen'})`, stroke: '#1565c0', width: 3 }];
  for (const [name] of models) {
    const chosen = name === load.chosen;
    series.push({ label: name, stroke: colours[name] ?? '#888', width: chosen ? 0 : 1.5, dash: chosen ? undefined : [6, 4], show: !chosen });
  }
  plot('mu-load', {
    scales: { x: { time: false, distr: 3 }, y: { distr: 3 } },
    axes: [{ label: unit }, { label: 'μ' }],
    series,
    hooks: {
      draw: [(u) => {
        const x = u.valToPos(given, 'x', true), y = u.valToPos(friction.mu, 'y', true);
        u.ctx.fillStyle = '#c62828';
        u.ctx.beginPath(); u.ctx.arc(x, y, 5 * devicePixelRatio, 0, 2 * Math.PI); u.ctx.fill();
      }],
    },
  }, data);
  const notes = refused.map(([name, m]) => `${name}: ${m.error}`);
  const band = friction.sensitivity?.lambda_s ?? [];
  if (band.length) {
    notes.unshift('μ at the reliable band\'s ends: ' + band.map((b) => `λs = ${fmt(b.lambda_s)} m: ${b.mu !== undefined ? fmt(b.mu) : b.error}`).join('; '));
  }
  for (const text of notes) {
    $('mu-load').append(Object.assign(document.createElement('p'), { className: 'note', textContent: text }));
  }
}

function drawHistogram(h) {
  if (h.error) { message('histogram', h.error); return; }
  const micro = h.z.map((z) => z * 1e6);
  const series = [{ label: 'height (µm)' },
    { label: 'measured', stroke: '#555', fill: 'rgba(120,120,120,0.3)', paths: uPlot.paths.bars({ size: [1, Infinity] }) }];
  const data = [micro, h.density.map((d) => d * 1e-6)];
  for (const [name, colourName] of [['gaussian', '#2e7d32'], ['pearson', '#c62828']]) {
    if (Array.isArray(h[name])) {
      series.push({ label: name, stroke: colourName, width: 2 });
      data.push(h[name].map((d) => d * 1e-6));
    }
  }
  plot('histogram', { scales: { x: { time: false } }, axes: [{ label: 'height (µm)' }, { label: 'density (1/µm)' }], series }, data);
  const fits = ['gaussian', 'pearson'].filter((n) => Array.isArray(h[n]));
  link('download-histogram', `${file.name}.histogram.csv`,
    csv(['z_m', 'density_per_m', ...fits.map((n) => `${n}_per_m`)], [h.z, h.density, ...fits.map((n) => h[n])]), 'text/csv');
}

function drawPsd(psd, column = 'direction') {
  if (psd.error) { message('psd', psd.error); $('download-psd').removeAttribute('href'); return; }
  const names = Object.keys(psd).filter((n) => n !== 'note');
  // uPlot's log axes span ±16 decades: C (~1e-30 m³) is drawn in a unit
  // 10^e that puts its largest value between 1 and 10.
  const top = Math.max(...names.flatMap((n) => psd[n].c.filter((c) => c > 0)));
  const e = Number.isFinite(top) ? Math.floor(Math.log10(top)) : 0;
  // q = 0 (the mean) has no place on a log axis.
  const tables = names.map((n) => {
    const k = psd[n].q.map((q, i) => i).filter((i) => psd[n].q[i] > 0);
    return [k.map((i) => psd[n].q[i]), k.map((i) => (psd[n].c[i] > 0 ? psd[n].c[i] / 10 ** e : null))];
  });
  const data = uPlot.join(tables);
  const colours = ['#1565c0', '#2e7d32', '#c62828', '#6a1b9a', '#ef6c00', '#00838f'];
  plot('psd', {
    scales: { x: { time: false, distr: 3 }, y: { distr: 3 } },
    axes: [{ label: 'q (rad/m)' }, { label: `C (10^${e} m³; m⁴ for the area)`, size: 60 }],
    series: [{ label: 'q' }, ...names.map((n, i) => ({ label: n, stroke: n === 'combined' ? '#000' : colours[i % colours.length],
      width: n === 'combined' ? 3 : 2, spanGaps: true }))],
  }, data);
  if (psd.note) $('psd').append(Object.assign(document.createElement('p'), { className: 'note', textContent: psd.note }));
  const rows = names.flatMap((n) => psd[n].q.map((q, i) => [n, q, psd[n].c[i]]));
  link('download-psd', `${file.name}.psd.csv`, csv([column, 'q', 'c'], [0, 1, 2].map((k) => rows.map((r) => r[k]))), 'text/csv');
}

// A container's spectra: each measurement's reliable one and the combined
// one (black), as kefric surface CONTAINER --psd gives them.
function drawContainerPsd(psd) {
  const curves = {};
  const notes = [];
  for (const m of psd.measurements) {
    if (m.q) curves[m.name] = m; else notes.push(`${m.name}: no reliable spectrum (${m.error})`);
  }
  if (psd.combined.q) curves.combined = psd.combined; else notes.push(`combined: ${psd.combined.error}`);
  if (!Object.keys(curves).length) { message('psd', notes.join('; ')); $('download-psd').removeAttribute('href'); return; }
  drawPsd(curves, 'measurement');
  for (const text of notes) $('psd').append(Object.assign(document.createElement('p'), { className: 'note', textContent: text }));
}

// A container's scan over λs (kefric surface CONTAINER --scan --json's
// rows): β and ψ of the combined spectrum over [λs, λc], μ, and its
// spread across the measurements taken alone.
function drawContainerScan(scan) {
  if (scan.error) { message('scan', scan.error); $('download-scan').removeAttribute('href'); return; }
  const rows = scan.rows;
  const pick = (f) => rows.map((r) => { const v = f(r); return typeof v === 'number' ? v : null; });
  const positive = (v) => v.map((x) => (x > 0 ? x : null));
  const lambda = rows.map((r) => r.lambda_s);
  const columns = {
    beta: pick((r) => r.roughness?.beta), psi: pick((r) => r.model?.psi), mu: pick((r) => r.friction?.mu),
    mu_min: pick((r) => r.spread?.[0]?.mu_min), mu_max: pick((r) => r.spread?.[0]?.mu_max),
  };
  const series = [{ label: 'λs (m)' }, { label: 'β', stroke: '#2e7d32', width: 2, scale: 'r' },
    { label: 'ψ', stroke: '#6a1b9a', width: 2, scale: 'r' }];
  const data = [lambda, columns.beta, columns.psi];
  if (columns.mu.some((v) => v !== null)) {
    series.push({ label: 'μ', stroke: '#1565c0', width: 2, scale: 'mu' },
      { label: 'μ min', stroke: '#1565c0', width: 1, dash: [4, 4], scale: 'mu' },
      { label: 'μ max', stroke: '#1565c0', width: 1, dash: [4, 4], scale: 'mu' });
    data.push(positive(columns.mu), positive(columns.mu_min), positive(columns.mu_max));
  }
  plot('scan', {
    scales: { x: { time: false, distr: 3 }, r: { distr: 3 }, mu: { distr: 3 } },
    axes: [{ label: 'λs (m)' }, { scale: 'mu', label: 'μ' }, { scale: 'r', side: 1, label: '', size: 70, grid: { show: false } }],
    series,
    hooks: { draw: [rightLabel('β, ψ')] },
  }, data);
  if (scan.warnings?.length) $('scan').append(Object.assign(document.createElement('p'), { className: 'note', textContent: scan.warnings.map((w) => w.summary).join(' · ') }));
  link('download-scan', `${file.name}.scan.csv`,
    csv(['lambda_s', 'lambda_c', 'measurements', 'beta', 'psi', 'mu', 'mu_min', 'mu_max', 'warnings', 'error'],
      [lambda, rows.map((r) => r.lambda_c), rows.map((r) => r.measurements.join(' ')),
        ...['beta', 'psi', 'mu', 'mu_min', 'mu_max'].map((k) => columns[k]),
        rows.map((r) => (r.warnings ?? []).map((w) => w.kind).join(';')), rows.map((r) => (r.error ? JSON.stringify(r.error) : ''))]), 'text/csv');
}

function drawScan(scan) {
  if (scan.error) { message('scan', scan.error); return; }
  const rows = scan.rows;
  const col = (k) => rows.map((r) => (typeof r[k] === 'number' ? r[k] : null));
  const lambda = col('lambda_s');
  const cutoff = scan.cutoff;
  const series = [{ label: 'λs (m)' }, { label: 'β', stroke: '#2e7d32', width: 2, scale: 'r' }];
  const data = [lambda, col('beta')];
  if (rows.some((r) => typeof r.psi === 'number')) { series.push({ label: 'ψ', stroke: '#6a1b9a', width: 2, scale: 'r' }); data.push(col('psi')); }
  if (rows.some((r) => typeof r.mu === 'number')) { series.push({ label: 'μ', stroke: '#1565c0', width: 2, scale: 'mu' }); data.push(col('mu').map((v) => (v > 0 ? v : null))); }
  plot('scan', {
    // μ on a log axis too: a large μ at the finest λs flattens the rest.
    scales: { x: { time: false, distr: 3 }, r: { distr: 3 }, mu: { distr: 3 } },
    axes: [{ label: 'λs (m)' }, { scale: 'mu', label: 'μ' }, { scale: 'r', side: 1, label: '', size: 70, grid: { show: false } }],
    series,
    hooks: {
      draw: [rightLabel('β, ψ')],
      drawClear: [(u) => {
        if (cutoff === null || cutoff === undefined) return;
        const x0 = Math.max(u.valToPos(cutoff, 'x', true), u.bbox.left);
        u.ctx.fillStyle = 'rgba(46,125,50,0.10)';
        u.ctx.fillRect(x0, u.bbox.top, u.bbox.left + u.bbox.width - x0, u.bbox.height);
      }],
      // Rows with warnings: a red ring on the row's last curve (μ, else ψ, else β).
      draw: [(u) => {
        const k = data.length - 1, scale = series[k].scale;
        u.ctx.strokeStyle = '#c62828'; u.ctx.lineWidth = 2 * devicePixelRatio;
        rows.forEach((r, i) => {
          if (!r.warnings?.length || data[k][i] === null) return;
          const x = u.valToPos(lambda[i], 'x', true), y = u.valToPos(data[k][i], scale, true);
          u.ctx.beginPath(); u.ctx.arc(x, y, 5 * devicePixelRatio, 0, 2 * Math.PI); u.ctx.stroke();
        });
      }],
    },
  }, data);
  if (scan.warnings?.length) $('scan').append(Object.assign(document.createElement('p'), { className: 'note', textContent: `ringed: rows with warnings. ${scan.warnings.map((w) => w.summary).join(' · ')}` }));
  const names = series.slice(1).map((s) => ({ 'β': 'beta', 'ψ': 'psi', 'μ': 'mu' })[s.label]);
  link('download-scan', `${file.name}.scan.csv`,
    csv(['lambda_s', 'reliable', ...names, 'error', 'warnings'],
      [lambda, rows.map((r) => r.reliable), ...names.map(col), rows.map((r) => (r.error ? JSON.stringify(r.error) : '')),
        rows.map((r) => (r.warnings ?? []).join(';'))]), 'text/csv');
}

// Events.
$('file').addEventListener('change', (e) => { if (e.target.files[0]) openFile(e.target.files[0]); });
$('example').addEventListener('click', async () => {
  started = performance.now();
  const response = await fetch('example.x3p');
  file = { name: 'example.x3p', bytes: await response.arrayBuffer() };
  analyse();
});
const drop = $('drop');
drop.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
drop.addEventListener('dragleave', () => drop.classList.remove('over'));
drop.addEventListener('drop', (e) => {
  e.preventDefault();
  drop.classList.remove('over');
  if (e.dataTransfer.files[0]) openFile(e.dataTransfer.files[0]);
});
form.addEventListener('submit', (e) => { e.preventDefault(); analyse(); });
form.addEventListener('change', (e) => { if (e.target.name) analyse(); });
$('preset').addEventListener('change', (e) => {
  const p = PRESETS[e.target.value];
  if (!p) return;
  for (const [k, v] of Object.entries(p)) form.elements.namedItem(k).value = v;
  analyse();
});

startWorker();
