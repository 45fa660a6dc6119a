// The page: its controls make a `zetafill fill` command line, a worker runs it (see worker.js)
// and the canvas draws the shapes as they come. A command line that the tool refuses shows the
// tool's message and leaves the last good fill on screen. The parameters live in the URL.
import { machines } from './zetafill_web.js';
import init from './zetafill_web.js';

const form = document.getElementById('controls');
const canvas = document.getElementById('canvas');
const finalImg = document.getElementById('final');
const message = document.getElementById('message');
const $ = (id) => document.getElementById(id);

// Flags that only colour a picture: the tool refuses them for JSON, G-code and digests.
const COLOUR_FLAGS = ['palette', 'color-by', 'background'];

const module = await WebAssembly.compileStreaming(fetch('zetafill_web_bg.wasm'));
await init({ module_or_path: module });
for (const name of machines()) $('machine').add(new Option(name, name));

const defaults = Object.fromEntries(new FormData(form));
let outline = null;
let motif = null;

// What the test and a curious reader can look at: the state of the fill shown.
const page = {
  state: 'loading', // running | done | error
  digest: null,
  halt: null,
  placed: 0,
  events: [], // in order: 'start', 'progress', 'done', 'input while STATE', 'error'
  times: [], // performance.now() of each event
  ms: null, // the finished fill's time in its worker, in ms
  exportBytes,
  argv: null,
  // The command line of each file of the fill shown, and of its digest.
  fileArgv: (kind, machine) => fileArgv(current.v, kind, machine),
  digestArgv: () => digestArgv(current.v),
  // The other tabs: the command line of a file, and its bytes.
  otherArgv: (ext) => otherArgv(ext),
  otherBytes: async (ext) => (await otherRun(ext)).bytes,
};
window.zetafill = page;

function note(event) {
  page.events.push(event);
  page.times.push(performance.now());
}

function values() {
  const v = Object.fromEntries(new FormData(form));
  v.periodic = form.elements.periodic.checked;
  return v;
}

// The command line of the controls; `colour` false leaves out the colour flags.
function argvOf(v, colour) {
  const a = [];
  const add = (flag, value) => a.push(`--${flag}`, value.trim());
  add('shape', v.shape);
  if (v['mix-order'] !== 'cycle') add('mix-order', v['mix-order']);
  if (v.rotate) add('rotate', v.rotate);
  add('region', v.region);
  if (v.periodic) a.push('--periodic');
  if (v.symmetry) {
    add('symmetry', v.symmetry);
    add('lattice', v.lattice);
  }
  add(v.law, v.exponent);
  add('n-offset', v['n-offset']);
  add(v.stop, v.until);
  if (v.gap.trim() !== '0') add('gap', v.gap);
  add('seed', v.seed);
  if (v.sampler !== 'fast') add('sampler', v.sampler);
  if (v.style !== 'outline') add('style', v.style);
  if (colour) {
    for (const f of COLOUR_FLAGS) if (v[f].trim() !== '') add(f, v[f]);
  }
  return a;
}

// The command line of each file the page offers.
function fileArgv(v, kind, machine) {
  switch (kind) {
    case 'svg': return [...argvOf(v, true), '-o', 'fill.svg'];
    case 'png': return [...argvOf(v, true), '-o', 'fill.png'];
    case 'json': return [...argvOf(v, false), '-o', 'fill.json'];
    case 'gcode': return [...argvOf(v, false), '--machine', machine, '-o', 'fill.gcode'];
  }
  throw new Error(`no such export: ${kind}`);
}

const digestArgv = (v) => [...argvOf(v, false), '-o', '-', '--format', 'digest'];

function shellWord(w) {
  return /^[A-Za-z0-9_.,:/=+-]+$/.test(w) ? w : `'${w.replaceAll("'", "'\\''")}'`;
}
const commandText = (words) => ['zetafill', ...words].map(shellWord).join(' ');

// --- the workers: `current` drew what is shown; `pending` runs a newer command line and takes
// over once it has placed a shape (a refused command line never does).
let current = null;
let pending = null;
let shown = null; // { argv, frame, periodic }
let requests = new Map();
let nextRequest = 1;

function start() {
  const v = values();
  const argv = fileArgv(v, 'svg');
  const search = new URLSearchParams();
  for (const [k, x] of Object.entries(v)) if (String(x) !== String(defaults[k] ?? false)) search.set(k, x);
  history.replaceState(null, '', search.size ? `?${search}` : location.pathname);
  if (pending) pending.worker.terminate();
  const worker = new Worker('worker.js', { type: 'module' });
  const run = { worker, argv, periodic: v.periodic, v };
  pending = run;
  worker.onmessage = (ev) => onWorker(run, ev.data);
  worker.postMessage({ type: 'run', module, argv, digestArgv: digestArgv(v), outline, motif });
  note('start');
}

function promote(run) {
  if (current && current !== run) current.worker.terminate();
  current = run;
  pending = null;
  for (const r of requests.values()) r.reject(new Error('the fill changed'));
  requests = new Map();
  page.argv = run.argv;
  $('command').textContent = commandText(['fill', ...run.argv]);
  finalImg.hidden = true;
  canvas.hidden = false;
  canvas.getContext('2d').clearRect(0, 0, canvas.width, canvas.height);
  shown = { frame: null, periodic: run.periodic, outline: run.v.style === 'outline' };
  page.state = 'running';
  page.digest = null;
  page.halt = null;
  message.hidden = true;
}

function onWorker(run, m) {
  if (m.type === 'error') {
    if (run === pending) {
      pending = null;
      run.worker.terminate();
    }
    note('error');
    message.textContent = m.message;
    message.hidden = false;
    if (run === current) page.state = 'error';
    else if (page.state !== 'running') page.state = current ? 'done' : 'error';
    $('state').textContent = run === current ? 'failed' : 'kept the last good fill';
    return;
  }
  if (m.type === 'bytes') {
    const r = requests.get(m.id);
    requests.delete(m.id);
    if (r) (m.error ? r.reject(new Error(m.error)) : r.resolve(m.bytes));
    return;
  }
  if (run === pending && (m.type === 'progress' || m.type === 'done')) promote(run);
  if (run !== current) return;
  if (m.type === 'progress') {
    note('progress');
    shown.frame = m.frame;
    draw(m.shapes);
    showStats(m.totals, m.ms);
    $('state').textContent = 'filling';
  } else if (m.type === 'done') {
    note('done');
    const url = URL.createObjectURL(new Blob([m.svg], { type: 'image/svg+xml' }));
    finalImg.onload = () => URL.revokeObjectURL(url);
    finalImg.src = url;
    finalImg.hidden = false;
    // The picture may be outlines on a clear background: the drawing beneath would show.
    canvas.hidden = true;
    page.digest = m.digest;
    page.halt = m.halt;
    page.placed = Number(m.digest.split(' ')[0]);
    page.ms = m.ms;
    $('state').textContent = `done in ${(m.ms / 1000).toFixed(2)} s · digest ${m.digest.split(' ')[1]}`;
    if (m.halt) {
      message.textContent = m.halt;
      message.hidden = false;
    }
    page.state = 'done';
  }
}

function showStats([placed, trials, area], ms) {
  page.placed = placed;
  $('placed').textContent = placed.toLocaleString('en');
  $('rate').textContent = Math.round(placed / Math.max(ms, 1) * 1000).toLocaleString('en');
  $('fraction').textContent = (area / shown.frame[4]).toFixed(4);
  $('trials').textContent = trials.toLocaleString('en');
}

// Draws a batch of shapes (the layout of worker.js's `progress`) in the region's frame, y up.
function draw(shapes) {
  const [x0, y0, x1, y1] = shown.frame;
  const g = canvas.getContext('2d');
  const s = Math.min(canvas.width / (x1 - x0), canvas.height / (y1 - y0));
  const w = x1 - x0;
  const h = y1 - y0;
  const images = shown.frame.length > 5 ? latticeShifts(shown.frame)
    : shown.periodic ? [-1, 0, 1].flatMap((i) => [-1, 0, 1].map((j) => [i * w, j * h])) : [[0, 0]];
  g.save();
  g.beginPath();
  g.rect(0, 0, w * s, h * s);
  g.clip();
  g.setTransform(s, 0, 0, -s, -x0 * s, y1 * s);
  g.fillStyle = '#264653';
  const path = new Path2D();
  for (let k = 0; k < shapes.length;) {
    const kind = shapes[k];
    for (const [dx, dy] of images) {
      if (kind === 0 || kind === 1) {
        const [x, y, r] = [shapes[k + 1] + dx, shapes[k + 2] + dy, shapes[k + 3]];
        path.moveTo(x + r, y);
        path.arc(x, y, r, 0, 2 * Math.PI);
        if (kind === 1) {
          const inner = shapes[k + 4];
          path.moveTo(x + inner, y);
          path.arc(x, y, inner, 0, 2 * Math.PI, true);
        }
      } else {
        const n = shapes[k + 1];
        path.moveTo(shapes[k + 2] + dx, shapes[k + 3] + dy);
        for (let i = 1; i < n; i++) path.lineTo(shapes[k + 2 + 2 * i] + dx, shapes[k + 3 + 2 * i] + dy);
        path.closePath();
      }
    }
    k += kind === 0 ? 4 : kind === 1 ? 5 : 2 + 2 * shapes[k + 1];
  }
  if (shown.outline) {
    g.lineWidth = 1 / s;
    g.strokeStyle = '#264653';
    g.stroke(path);
  } else {
    g.fill(path, 'evenodd');
  }
  g.restore();
}

// A symmetric fill's frame ends with its lattice [ax, bx, by]: the translates k a + l b that
// bring a shape of the fundamental rectangle [0, ax) x [0, by) into view.
function latticeShifts([x0, y0, x1, y1, , ax, bx, by]) {
  const out = [];
  for (let l = Math.floor(y0 / by) - 1; l <= Math.ceil(y1 / by) + 1; l++) {
    const sx = l * bx;
    for (let k = Math.floor((x0 - sx) / ax) - 1; k <= Math.ceil((x1 - sx) / ax) + 1; k++) out.push([k * ax + sx, l * by]);
  }
  return out;
}

// A group's lattice takes one, two or three numbers: a lattice of another arity becomes one
// that fits, so that picking a group gives a pattern at once.
const LATTICES = { p1: '40:30:70', p2: '40:30:70', pm: '40:30', pg: '40:30', cm: '40:30', pmm: '40:30', pmg: '40:30', pgg: '40:30', cmm: '40:30' };
form.elements.symmetry.addEventListener('input', () => {
  const g = form.elements.symmetry.value;
  const want = LATTICES[g] ?? '40';
  if (g && form.elements.lattice.value.split(':').length !== want.split(':').length) form.elements.lattice.value = want;
});

// The bytes of one file of the fill shown (what `zetafill fill` writes for its command).
function exportBytes(kind, machine = $('machine').value) {
  if (!current || page.state !== 'done') return Promise.reject(new Error('the fill is not finished'));
  const argv = fileArgv(current.v, kind, machine);
  $('file-command').textContent = commandText(['fill', ...argv]);
  const id = nextRequest++;
  return new Promise((resolve, reject) => {
    requests.set(id, { resolve, reject });
    current.worker.postMessage({ type: 'export', id, argv });
  });
}

const TYPES = { svg: 'image/svg+xml', png: 'image/png', json: 'application/json', gcode: 'text/plain' };
document.querySelectorAll('[data-export]').forEach((b) => b.addEventListener('click', async () => {
  const kind = b.dataset.export;
  try {
    const bytes = await exportBytes(kind);
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([bytes], { type: TYPES[kind] }));
    a.download = `fill.${kind}`;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
  } catch (e) {
    message.textContent = String(e.message ?? e);
    message.hidden = false;
  }
}));

$('copy').addEventListener('click', () => navigator.clipboard?.writeText($('command').textContent));
$('new-seed').addEventListener('click', () => {
  form.elements.seed.value = String(Math.floor(Math.random() * 2 ** 32));
  changed();
});
// An SVG chosen from disk: an outline (`--region svg:NAME`) or a motif (`--shape svg:NAME`).
// The file is read first (below): its input's own input event is not a change yet. `keep`
// holds the bytes, which go with the command.
function upload(id, field, keep) {
  $(id).addEventListener('input', (ev) => ev.stopPropagation());
  $(id).addEventListener('change', async (ev) => {
    const file = ev.target.files[0];
    if (!file) return;
    keep(new Uint8Array(await file.arrayBuffer()));
    form.elements[field].value = `svg:${file.name}`;
    changed();
  });
}
upload('outline', 'region', (bytes) => { outline = bytes; });
upload('motif', 'shape', (bytes) => { motif = bytes; });

function changed() {
  note(`input while ${page.state}`);
  start();
}
form.addEventListener('input', changed);
form.addEventListener('submit', (ev) => ev.preventDefault());

// --- the other commands' tabs: a command line of their own, one worker per change, the SVG
// shown and each download made by the same command with another output.
const EXAMPLES = {
  line: '--count 400 --render bars --bar-height 40 --palette 264653,2a9d8f,e9c46a,f4a261,e76f51 --background fefae0',
  territory: '--sites 3 --points 7000 --seed 3 --render filled',
  tile: '--seed 2 --radius 8 --spacing 2 --tries 3000 --style filled',
};
let tab = 'fill';
let other = null; // the worker of the shown tab's latest command line
const otherArgs = $('other-args');

function splitWords(text) {
  return [...text.matchAll(/'([^']*)'|"([^"]*)"|(\S+)/g)].map((m) => m[1] ?? m[2] ?? m[3]);
}

// The tab's controls: each owns one flag of the command line. A checkbox is a flag alone;
// any other control a flag and its value, where an empty value leaves the flag out.
const otherForm = () => document.querySelector(`.other-controls[data-for="${tab}"]`);
const isSwitch = (el) => el.type === 'checkbox';

// Where `--flag` stands in `words` (also as `--flag=value`), and the words it takes.
function flagAt(words, flag, from, takesValue) {
  for (let i = from; i < words.length; i++) {
    if (words[i] === `--${flag}`) return [i, takesValue && i + 1 < words.length ? 2 : 1];
    if (takesValue && words[i].startsWith(`--${flag}=`)) return [i, 1];
  }
  return null;
}

// The value of `el`'s flag in `words`: its last one (as clap takes it), or '' (or false).
function flagValue(words, el) {
  let value = isSwitch(el) ? false : '';
  for (let at = flagAt(words, el.dataset.flag, 0, !isSwitch(el)); at; at = flagAt(words, el.dataset.flag, at[0] + at[1], !isSwitch(el))) {
    const w = words[at[0]];
    value = isSwitch(el) ? true : w.includes('=') ? w.slice(w.indexOf('=') + 1) : (words[at[0] + 1] ?? '');
  }
  return value;
}

// The command line with `el`'s flag set from `el`: every earlier use of the flag goes, and
// the control's value (if any) is added at the end.
function withControl(text, el) {
  const words = splitWords(text);
  for (let at; (at = flagAt(words, el.dataset.flag, 0, !isSwitch(el)));) words.splice(at[0], at[1]);
  if (isSwitch(el) ? el.checked : el.value.trim() !== '') {
    words.push(`--${el.dataset.flag}`);
    if (!isSwitch(el)) words.push(el.value.trim());
  }
  return words.map(shellWord).join(' ');
}

// Sets the tab's controls from the command line.
function controlsFromArgs() {
  const words = splitWords(otherArgs.value);
  for (const el of otherForm()?.querySelectorAll('[data-flag]') ?? []) {
    const v = flagValue(words, el);
    if (isSwitch(el)) el.checked = v;
    // A value a select does not offer stays in the command line; the select shows the default.
    else if (el.tagName === 'SELECT') el.value = [...el.options].some((o) => o.value === v) ? v : '';
    else el.value = v;
  }
}
const otherArgv = (ext) => [tab, ...splitWords(otherArgs.value), '-o', `${tab}.${ext}`];

function otherRun(ext) {
  if (other) other.terminate();
  const worker = new Worker('worker.js', { type: 'module' });
  other = worker;
  const argv = otherArgv(ext);
  $('other-command').textContent = commandText(argv);
  return new Promise((resolve, reject) => {
    worker.onmessage = (ev) => {
      worker.terminate();
      if (other === worker) other = null;
      if (ev.data.type === 'output') resolve(ev.data);
      else reject(new Error(ev.data.message));
    };
    worker.postMessage({ type: 'output', module, argv });
  });
}

async function otherChanged() {
  const search = new URLSearchParams({ tab, args: otherArgs.value });
  history.replaceState(null, '', `?${search}`);
  $('other-state').textContent = 'drawing';
  try {
    const { bytes, ms } = await otherRun('svg');
    const img = $('other-picture');
    const url = URL.createObjectURL(new Blob([bytes], { type: 'image/svg+xml' }));
    img.onload = () => URL.revokeObjectURL(url);
    img.src = url;
    $('other-message').hidden = true;
    $('other-state').textContent = `done in ${(ms / 1000).toFixed(2)} s`;
  } catch (e) {
    $('other-message').textContent = e.message;
    $('other-message').hidden = false;
    $('other-state').textContent = 'kept the last good drawing';
  }
}

function showTab(name, args) {
  tab = name;
  document.querySelectorAll('[data-tab]').forEach((b) => b.classList.toggle('on', b.dataset.tab === name));
  $('fill').hidden = name !== 'fill';
  $('other').hidden = name === 'fill';
  if (name === 'fill') {
    start();
    return;
  }
  document.querySelectorAll('.tab-name').forEach((e) => { e.textContent = name; });
  document.querySelectorAll('.other-controls').forEach((f) => { f.hidden = f.dataset.for !== name; });
  otherArgs.value = args ?? EXAMPLES[name];
  controlsFromArgs();
  $('other-picture').removeAttribute('src');
  otherChanged();
}

document.querySelectorAll('[data-tab]').forEach((b) => b.addEventListener('click', () => showTab(b.dataset.tab)));
otherArgs.addEventListener('input', () => {
  controlsFromArgs();
  otherChanged();
});
document.querySelectorAll('.other-controls').forEach((f) => {
  f.addEventListener('input', (ev) => {
    if (!ev.target.dataset.flag) return;
    otherArgs.value = withControl(otherArgs.value, ev.target);
    otherChanged();
  });
  f.addEventListener('submit', (ev) => ev.preventDefault());
});
document.querySelectorAll('[data-other]').forEach((b) => b.addEventListener('click', async () => {
  const ext = b.dataset.other;
  try {
    const { bytes } = await otherRun(ext);
    const a = document.createElement('a');
    a.href = URL.createObjectURL(new Blob([bytes], { type: TYPES[ext] }));
    a.download = `${tab}.${ext}`;
    a.click();
    setTimeout(() => URL.revokeObjectURL(a.href), 10000);
  } catch (e) {
    $('other-message').textContent = e.message;
    $('other-message').hidden = false;
  }
}));

// The URL's parameters set the tab and the controls.
const query = new URLSearchParams(location.search);
if (EXAMPLES[query.get('tab')]) {
  showTab(query.get('tab'), query.get('args') ?? undefined);
} else {
  fillFromUrl();
  start();
}

function fillFromUrl() {
  for (const [k, x] of new URLSearchParams(location.search)) {
    const el = form.elements[k];
    if (!el) continue;
    if (el.type === 'checkbox') el.checked = x === 'on' || x === 'true';
    else el.value = x;
  }
}
