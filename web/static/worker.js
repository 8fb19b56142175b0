// The analysis runs here, off the page's thread: the WebAssembly library
// reads the file, takes the statistics and μ, then the curves; the scan
// over λs (the slowest part) reports its progress.
import init, { Analysis, ContainerAnalysis, is_container, names, version } from './pkg/ke_friction_web.js';

const ready = init().then(() => {
  postMessage({ type: 'ready', names: JSON.parse(names()), version: version() });
});

// At most this many points a side of the height map sent to the page.
const MAP_SIDE = 512;

onmessage = async ({ data }) => {
  await ready;
  const { id, bytes, name, options } = data;
  // A contact.engineering container (detected by its content, as kefric
  // does): its measurements, combined spectrum, μ and scan.
  if (is_container(new Uint8Array(bytes))) {
    container(id, new Uint8Array(bytes), name, options);
    return;
  }
  let analysis;
  try {
    analysis = new Analysis(new Uint8Array(bytes), name, JSON.stringify(options));
  } catch (e) {
    postMessage({ type: 'error', id, message: String(e.message ?? e) });
    return;
  }
  try {
    const step = Math.max(1, Math.ceil(Math.max(analysis.nx(), analysis.ny()) / MAP_SIDE));
    postMessage({
      type: 'result', id,
      record: analysis.record(),
      error: analysis.error() ?? null,
      warnings: JSON.parse(analysis.warnings()),
      command: analysis.command(),
      load: JSON.parse(analysis.mu_against_load()),
      map: { nx: analysis.nx(), ny: analysis.ny(), step, z: analysis.heights(step) },
    });
    let histogram = null, psd = null;
    try { histogram = JSON.parse(analysis.histogram(60)); } catch (e) { histogram = { error: String(e.message ?? e) }; }
    try { psd = JSON.parse(analysis.psd()); } catch (e) { psd = { error: String(e.message ?? e) }; }
    let models = {};
    try { models = JSON.parse(analysis.mu_against_load_models()); } catch (e) { models = {}; }
    postMessage({ type: 'curves', id, histogram, psd, models });
    let scan;
    try {
      scan = JSON.parse(analysis.scan((done, total) => postMessage({ type: 'progress', id, done, total })));
    } catch (e) { scan = { error: String(e.message ?? e) }; }
    postMessage({ type: 'scan', id, scan });
  } finally {
    analysis.free();
  }
};

const failed = (e) => ({ error: String(e.message ?? e) });

function container(id, bytes, name, options) {
  let c;
  try {
    c = new ContainerAnalysis(bytes, name, JSON.stringify(options));
  } catch (e) {
    postMessage({ type: 'error', id, message: String(e.message ?? e) });
    return;
  }
  try {
    postMessage({
      type: 'result', id, container: true,
      record: c.record(),
      error: c.error() ?? null,
      warnings: JSON.parse(c.warnings()),
      command: c.command(),
    });
    let psd;
    try { psd = JSON.parse(c.psd()); } catch (e) { psd = failed(e); }
    postMessage({ type: 'curves', id, container: true, psd });
    let scan;
    try { scan = JSON.parse(c.scan()); } catch (e) { scan = failed(e); }
    postMessage({ type: 'scan', id, container: true, scan });
  } finally {
    c.free();
  }
}
