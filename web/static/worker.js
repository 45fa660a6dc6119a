// Runs one fill off the page's thread: the page starts a worker per command line and ends it
// when the command changes. Messages to the page: `progress` (shapes placed since the last one,
// and the totals), `done` (the finished picture as SVG, the digest, any halt), `error` (the
// command line's own message), and `bytes` (an export asked for). For the other commands'
// tabs, `output` carries the one file asked for.
import init, { Session, output } from './zetafill_web.js';

let session = null;

// The built-in font is not in the wasm: a text region or a glyph motif without `--font` fetches
// its file (once per worker; the browser's cache keeps it between workers).
const FONT = 'DejaVuSans-Bold.ttf';
async function fontFor(argv) {
  const at = argv.indexOf('--region');
  const text = argv.some((w) => w.startsWith('--region=text:')) || (at >= 0 && argv[at + 1]?.startsWith('text:'));
  const glyph = argv.some((w, i) => (argv[i - 1] === '--shape' || w.startsWith('--shape=')) && w.includes('glyph:'));
  if (!(text || glyph) || argv.includes('--font')) return undefined;
  return new Uint8Array(await (await fetch(FONT)).arrayBuffer());
}

// A PNG's pixels come from a second module (web/png), loaded the first time a command line
// asks for a PNG; the page's module hands it the SVG through `zetafillRasterise`.
let png = null;
function pngReady(argv) {
  const wants = argv.some((w, i) => /\.png$/i.test(w) || (w === 'png' && argv[i - 1] === '--format') || w === '--format=png');
  if (!wants) return Promise.resolve();
  png ??= import('./zetafill_web_png.js').then(async (m) => {
    await m.default({ module_or_path: 'zetafill_web_png_bg.wasm' });
    globalThis.zetafillRasterise = m.rasterise;
  });
  return png;
}

function fail(e) {
  postMessage({ type: 'error', message: String(e) });
}

async function run({ module, argv, digestArgv, outline, motif }) {
  await init({ module_or_path: module });
  try {
    session = new Session(argv, outline ?? undefined, await fontFor(argv), motif ?? undefined);
  } catch (e) {
    return fail(e);
  }
  const frame = session.frame();
  const t0 = performance.now();
  try {
    session.run((shapes, totals) => {
      postMessage({ type: 'progress', frame, shapes, totals, ms: performance.now() - t0 }, [shapes.buffer]);
    });
  } catch (e) {
    return fail(e);
  }
  const ms = performance.now() - t0;
  let svg, digest;
  try {
    svg = session.export(argv);
    digest = new TextDecoder().decode(session.export(digestArgv)).trim();
  } catch (e) {
    return fail(e);
  }
  postMessage({ type: 'done', ms, svg, digest, halt: session.halt() ?? null }, [svg.buffer]);
}

// One file of `zetafill line`, `territory` or `tile`.
async function once({ module, argv }) {
  await init({ module_or_path: module });
  await pngReady(argv);
  const t0 = performance.now();
  try {
    const bytes = output(argv);
    postMessage({ type: 'output', bytes, ms: performance.now() - t0 }, [bytes.buffer]);
  } catch (e) {
    fail(e);
  }
}

onmessage = (ev) => {
  const m = ev.data;
  if (m.type === 'output') {
    once(m).catch(fail);
  } else if (m.type === 'run') {
    run(m).catch(fail);
  } else if (m.type === 'export') {
    pngReady(m.argv).then(() => {
      const bytes = session.export(m.argv);
      postMessage({ type: 'bytes', id: m.id, bytes }, [bytes.buffer]);
    }).catch((e) => postMessage({ type: 'bytes', id: m.id, error: String(e) }));
  }
};
