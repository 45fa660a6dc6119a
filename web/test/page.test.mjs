// The page in a real browser (Debian's Chromium, headless, driven by playwright-core): every
// file it offers is byte for byte the file the CLI writes for the command the page shows, the
// page stays responsive while it fills, and a refused value shows the CLI's own message while
// the last good fill stays on screen. Each checker is also shown to fail.
//
// Needs web/dist (bash web/build.sh) and the CLI built in release from the same tree. Environment:
// ZETAFILL (the binary; default target/release/zetafill), CHROMIUM (default /usr/bin/chromium),
// WEB_TEST_OUT (where the screenshot goes; default target/web-test).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
const targetDir = process.env.CARGO_TARGET_DIR ? resolve(root, process.env.CARGO_TARGET_DIR) : join(root, 'target');
const ZETAFILL = process.env.ZETAFILL ?? join(targetDir, 'release/zetafill');
const OUT = process.env.WEB_TEST_OUT ?? join(targetDir, 'web-test');
const MACHINES = cli(['machines', 'list']).stdout.toString().split('\n').filter((l) => /^\S+ +\d+ x \d+ mm/.test(l)).map((l) => l.split(' ')[0]);

let server;
let browser;
let work;

before(async () => {
  server = await serve(join(root, 'web/dist'));
  browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--no-sandbox'],
  });
  work = mkdtempSync(join(tmpdir(), 'zetafill-web-'));
  mkdirSync(OUT, { recursive: true });
});

after(async () => {
  await browser?.close();
  await server?.close();
  if (work) rmSync(work, { recursive: true, force: true });
});

/** Runs the CLI in `cwd`; exit 0, or 3 for a halt whose file is written. */
function cli(args, cwd = root) {
  return spawnSync(ZETAFILL, args, { cwd, maxBuffer: 1 << 30 });
}

/** The bytes the CLI writes for `zetafill fill ARGV` (its `-o` made a path in `work`). */
function cliFile(argv) {
  const i = argv.indexOf('-o');
  const out = join(work, argv[i + 1]);
  const args = [...argv.slice(0, i + 1), out, ...argv.slice(i + 2)];
  const r = cli(['fill', '-q', ...args], work);
  assert.ok(r.status === 0 || r.status === 3, `zetafill fill ${args.join(' ')}: exit ${r.status}: ${r.stderr}`);
  return readFileSync(out);
}

/** Fails unless `a` and `b` are the same bytes, naming the first difference. */
function sameBytes(a, b, what) {
  const ba = Buffer.from(a);
  const bb = Buffer.from(b);
  if (ba.equals(bb)) return;
  let i = 0;
  while (i < ba.length && ba[i] === bb[i]) i++;
  assert.fail(`${what}: ${ba.length} bytes against ${bb.length}, first difference at byte ${i}`);
}

async function openPage(query = '') {
  const page = await browser.newPage({ viewport: { width: 1100, height: 900 } });
  page.on('pageerror', (e) => console.error('page error:', e));
  await page.goto(`${server.url}index.html${query}`);
  return page;
}

/** Waits until the fill shown is finished (or refused). */
async function settled(page) {
  await page.waitForFunction(() => window.zetafill && ['done', 'error'].includes(window.zetafill.state), null, {
    timeout: 120_000,
  });
  return page.evaluate(() => window.zetafill.state);
}

/** The bytes of one export of the page, with its command line. */
async function pageFile(page, kind, machine) {
  const argv = await page.evaluate(([k, m]) => window.zetafill.fileArgv(k, m), [kind, machine]);
  return { argv, bytes: await bytesFrom(page, 'exportBytes', kind, machine) };
}

/** The bytes `window.zetafill[name](...args)` resolves to (carried as base64). */
async function bytesFrom(page, name, ...args) {
  const b64 = await page.evaluate(async ([n, a]) => {
    const bytes = await window.zetafill[n](...a);
    let s = '';
    for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return btoa(s);
  }, [name, args.filter((a) => a !== undefined)]);
  return Buffer.from(b64, 'base64');
}

/** Every file and the digest of the page's fill against the CLI's. */
async function compareAll(page) {
  const digestArgv = await page.evaluate(() => window.zetafill.digestArgv());
  const r = cli(['fill', '-q', ...digestArgv], work);
  assert.equal(await page.evaluate(() => window.zetafill.digest), r.stdout.toString().trim(), 'digest');
  for (const kind of ['svg', 'png', 'json']) {
    const { argv, bytes } = await pageFile(page, kind);
    sameBytes(bytes, cliFile(argv), `${kind} of ${argv.join(' ')}`);
  }
  for (const machine of MACHINES) {
    const { argv, bytes } = await pageFile(page, 'gcode', machine);
    sameBytes(bytes, cliFile(argv), `G-code of ${argv.join(' ')}`);
  }
}

// Parameter sets, as the page's URL carries them: every region kind, shapes, mixes, both
// samplers, both stop kinds beyond the count, c and D, gap, periodic, colour rules, letters.
const SETS = [
  '?until=800',
  '?shape=star:5:0.5&region=circle:80&exponent=1.25&until=300&seed=7&style=outline&palette=',
  '?shape=mix:circle,square,triangle&mix-order=random&periodic=true&region=rect:150:100&law=dimension&exponent=1.6&n-offset=2&stop=fill&until=0.5&gap=0.5&seed=3&color-by=kind',
  '?shape=ring:0.5&region=annulus:100:40&n-offset=6&until=200&rotate=none&sampler=reference&seed=11&background=fefae0',
  '?shape=blob:0.3&region=polygon:0,0,200,0,100,173.2&stop=min-size&until=4&seed=5&color-by=random',
  // Letters: the built-in font is fetched by the worker, not embedded in the wasm.
  '?region=text:ZF&n-offset=10&until=300&seed=2',
  // A wallpaper group's pattern, cut to the region.
  '?symmetry=p6m&lattice=50&shape=mix:circle,triangle&region=circle:90&n-offset=3&until=120&seed=4',
];

for (const query of SETS) {
  test(`exports match the CLI byte for byte: ${query}`, async () => {
    const page = await openPage(query);
    assert.equal(await settled(page), 'done');
    const argv = await page.evaluate(() => window.zetafill.argv);
    assert.equal(await page.textContent('#command'), ['zetafill', 'fill', ...argv].join(' '));
    await compareAll(page);
    await page.close();
  });
}

test('the PNG module is fetched only when a PNG is asked for, and its PNG is the CLI\'s', async () => {
  const page = await openPage('?until=200&seed=3');
  const fetched = [];
  page.on('request', (r) => fetched.push(r.url()));
  assert.equal(await settled(page), 'done');
  await pageFile(page, 'svg');
  await pageFile(page, 'gcode', MACHINES[0]);
  assert.ok(!fetched.some((u) => u.includes('zetafill_web_png')), fetched.join(' '));
  const { argv, bytes } = await pageFile(page, 'png');
  sameBytes(bytes, cliFile(argv), `png of ${argv.join(' ')}`);
  assert.ok(fetched.some((u) => u.endsWith('zetafill_web_png_bg.wasm')), fetched.join(' '));
  await page.close();
});

test('the symmetry control: a group takes a lattice that fits it, and the files are the CLI\'s', async () => {
  const page = await openPage('?shape=mix:circle,square&n-offset=3&until=100&region=rect:120:90');
  assert.equal(await settled(page), 'done');
  await page.selectOption('select[name=symmetry]', 'pmg');
  assert.equal(await page.inputValue('input[name=lattice]'), '40:30', 'a rectangular lattice for pmg');
  await page.waitForFunction(() => window.zetafill.argv?.includes('--symmetry') && window.zetafill.state === 'done', null, {
    timeout: 120_000,
  });
  const argv = await page.evaluate(() => window.zetafill.argv);
  assert.deepEqual(argv.slice(argv.indexOf('--symmetry'), argv.indexOf('--symmetry') + 4), ['--symmetry', 'pmg', '--lattice', '40:30']);
  await compareAll(page);
  // The fill fraction shown is over the fundamental region, as the JSON's is.
  const json = JSON.parse(Buffer.from((await pageFile(page, 'json')).bytes).toString());
  assert.equal(Number(await page.textContent('#fraction')), Number(json.stats.fill_fraction.toFixed(4)));
  await page.close();
});

test('an uploaded SVG outline gives the files of --region svg:FILE', async () => {
  const svg = '<svg xmlns="http://www.w3.org/2000/svg" width="240mm" height="200mm" viewBox="0 0 120 100">'
    + '<path d="M10 90 L60 5 L110 90 Z M45 70 L75 70 L60 45 Z"/></svg>';
  writeFileSync(join(work, 'outline.svg'), svg);
  const page = await openPage('?until=400&seed=4&n-offset=4');
  await settled(page);
  await page.setInputFiles('#outline', join(work, 'outline.svg'));
  await page.waitForFunction(() => window.zetafill.argv.includes('svg:outline.svg') && window.zetafill.state === 'done');
  await compareAll(page);
  await page.close();
});

test('an uploaded SVG motif gives the files of --shape svg:FILE', async () => {
  const heart = readFileSync(join(root, 'examples/motifs/heart-ring.svg'));
  writeFileSync(join(work, 'heart-ring.svg'), heart);
  const page = await openPage('?until=150&seed=3&exponent=1.15&n-offset=4');
  await settled(page);
  await page.setInputFiles('#motif', join(work, 'heart-ring.svg'));
  await page.waitForFunction(() => window.zetafill.argv.includes('svg:heart-ring.svg') && window.zetafill.state === 'done');
  await compareAll(page);
  // The JSON names the file by its SHA-256, as the CLI's does.
  const json = JSON.parse(Buffer.from((await pageFile(page, 'json')).bytes).toString());
  assert.equal(json.params.motif_sha256.length, 1);
  assert.equal(json.shapes[0].kind, 'motif');
  await page.close();
});

test('the comparisons can fail: another seed gives other bytes and another digest', async () => {
  const page = await openPage('?until=300&seed=1');
  await settled(page);
  const { argv, bytes } = await pageFile(page, 'svg');
  const other = argv.map((w, i) => (argv[i - 1] === '--seed' ? '2' : w));
  assert.throws(() => sameBytes(bytes, cliFile(other), 'svg'), /first difference/);
  const digestArgv = (await page.evaluate(() => window.zetafill.digestArgv())).map((w, i, a) => (a[i - 1] === '--seed' ? '2' : w));
  assert.notEqual(await page.evaluate(() => window.zetafill.digest), cli(['fill', ...digestArgv], work).stdout.toString().trim());
  await page.close();
});

test('the page draws the fill, and a screenshot shows it', async () => {
  const page = await openPage('?until=3000&seed=2');
  await settled(page);
  await page.screenshot({ path: join(OUT, 'page.png') });
  // The finished picture is the CLI's SVG; the canvas was drawn as the shapes came.
  assert.equal(await page.evaluate(() => document.getElementById('final').hidden), false);
  const inked = await page.evaluate(() => {
    const c = document.getElementById('canvas');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 3; i < d.length; i += 4) if (d[i] > 0) n++;
    return n / (d.length / 4);
  });
  assert.ok(inked > 0.3, `the canvas is ${inked} inked`);
  assert.match(await page.textContent('#placed'), /^3,000$/);
  await page.close();
});

test('the page stays responsive: an input during a long fill restarts it at once', async () => {
  const page = await openPage('?until=400000&seed=9');
  await page.waitForFunction(() => window.zetafill?.events.includes('progress'));
  await page.fill('input[name=until]', '1500');
  assert.equal(await settled(page), 'done');
  const events = await page.evaluate(() => window.zetafill.events);
  // The input was handled while the long fill was running, before it could finish...
  const input = events.indexOf('input while running');
  assert.ok(input > 0, events.join(' '));
  assert.ok(!events.slice(0, input).includes('done'), events.join(' '));
  // ...and the fill shown is the new one.
  assert.equal(await page.evaluate(() => window.zetafill.placed), 1500);
  await page.close();
});

/** The CLI's message for `zetafill fill ARGV`. */
function cliMessage(argv) {
  const r = cli(['fill', ...argv], work);
  assert.equal(r.status, 2, `exit ${r.status}`);
  return r.stderr.toString().trim();
}

test('a refused value shows the CLI message and keeps the last good fill', async () => {
  const page = await openPage('?until=500&seed=6');
  await settled(page);
  const goodCommand = await page.textContent('#command');
  // Refused by the parser (c <= 1), then by the run (a gap no shape fits in).
  for (const [name, value] of [['exponent', '0.9'], ['gap', '150']]) {
    const good = await page.evaluate(() => ({ src: document.getElementById('final').src, digest: window.zetafill.digest }));
    const before = await page.evaluate(() => window.zetafill.events.length);
    await page.fill(`input[name=${name}]`, value);
    await page.waitForFunction((n) => window.zetafill.events.slice(n).includes('error'), before);
    const shown = (await page.textContent('#message')).trim();
    const argv = await page.evaluate(() => window.zetafill.argv);
    // The page's own command line is still the good one; the refused one is the same with the
    // changed value.
    const refused = argv.map((w, i) => {
      const flag = argv[i - 1];
      if (name === 'exponent' && flag === '--c') return value;
      return w;
    });
    if (name === 'gap') refused.splice(refused.indexOf('--seed'), 0, '--gap', value);
    const expected = cliMessage(refused);
    assert.equal(shown, expected);
    // The checker fails on another message.
    assert.notEqual(shown, cliMessage(refused.map((w, i) => (refused[i - 1] === '--c' ? '-2' : refused[i - 1] === '--gap' ? '300' : w))));
    assert.equal(await page.textContent('#command'), goodCommand);
    const now = await page.evaluate(() => ({ src: document.getElementById('final').src, digest: window.zetafill.digest }));
    assert.deepEqual(now, good);
    assert.equal(await page.evaluate(() => document.getElementById('final').hidden), false);
    const done = await page.evaluate(() => window.zetafill.events.filter((e) => e === 'done').length);
    await page.fill(`input[name=${name}]`, name === 'gap' ? '0' : '1.3');
    await page.waitForFunction((n) => window.zetafill.events.filter((e) => e === 'done').length > n, done);
  }
  await page.close();
});

// The other commands' tabs: the drawing shown, and each file the CLI's.
const TABS = [
  ['line', '--count 300 --render circles --seed 4', ['svg', 'png', 'json']],
  ['territory', '--sites 3 --points 3000 --seed 3 --render filled', ['svg', 'png', 'json']],
  ['tile', '--seed 2 --radius 8 --spacing 2 --tries 1500 --style filled', ['svg', 'png', 'json']],
  ['tile', '--seed 5 --layout planet --rows 3 --tries 800 --radius 8 --spacing 2', ['svg', 'png']],
];

for (const [tab, args, exts] of TABS) {
  test(`the ${tab} tab's files match the CLI byte for byte: ${exts.join(', ')}`, async () => {
    const page = await openPage(`?${new URLSearchParams({ tab, args })}`);
    await page.waitForFunction(() => /^done/.test(document.getElementById('other-state').textContent), null, { timeout: 120_000 });
    assert.match(await page.getAttribute('#other-picture', 'src'), /^blob:/);
    for (const ext of exts) {
      const argv = await page.evaluate((e) => window.zetafill.otherArgv(e), ext);
      const bytes = await bytesFrom(page, 'otherBytes', ext);
      const out = join(work, `${tab}.${ext}`);
      const r = cli([...argv.slice(0, -1), out], work);
      assert.ok(r.status === 0 || r.status === 3, `zetafill ${argv.join(' ')}: ${r.stderr}`);
      sameBytes(bytes, readFileSync(out), `${ext} of zetafill ${argv.join(' ')}`);
    }
    await page.close();
  });
}

/** The bytes the CLI writes for the other tabs' `argv` (as `otherArgv` gives it). */
function otherFile(argv) {
  const out = join(work, argv.at(-1));
  const r = cli([...argv.slice(0, -1), out], work);
  assert.ok(r.status === 0 || r.status === 3, `zetafill ${argv.join(' ')}: ${r.stderr}`);
  return readFileSync(out);
}

test("the other tabs' controls and their command line set each other", async () => {
  const page = await openPage(`?${new URLSearchParams({ tab: 'tile', args: '--seed 2 --radius 8 --spacing 2 --tries 800' })}`);
  const args = () => page.inputValue('#other-args');
  // Waits for a drawing other than `before` to be shown and returns its address.
  const drawn = async (before) => {
    await page.waitForFunction((b) => {
      const src = document.getElementById('other-picture').getAttribute('src');
      return src && src !== b && /^done/.test(document.getElementById('other-state').textContent);
    }, before, { timeout: 120_000 });
    return page.getAttribute('#other-picture', 'src');
  };
  let src = await drawn(null);
  const tile = (flag) => `#controls-tile [data-flag=${flag}]`;
  // The command line sets the controls; only the tab's own are shown.
  assert.equal(await page.inputValue(tile('seed')), '2');
  assert.equal(await page.inputValue(tile('radius')), '8');
  assert.equal(await page.inputValue(tile('layout')), '');
  assert.equal(await page.isVisible('#controls-tile'), true);
  assert.equal(await page.isVisible('#controls-line'), false);
  // A control rewrites its own flag, and the files are the CLI's for the new command line.
  await page.selectOption(tile('layout'), 'mosaic');
  assert.equal(await args(), '--seed 2 --radius 8 --spacing 2 --tries 800 --layout mosaic');
  src = await drawn(src);
  const before = await bytesFrom(page, 'otherBytes', 'svg');
  await page.fill(tile('seed'), '5');
  assert.equal(await args(), '--radius 8 --spacing 2 --tries 800 --layout mosaic --seed 5');
  src = await drawn(src);
  const argv = await page.evaluate(() => window.zetafill.otherArgv('svg'));
  assert.deepEqual(argv, ['tile', '--radius', '8', '--spacing', '2', '--tries', '800', '--layout', 'mosaic', '--seed', '5', '-o', 'tile.svg']);
  const bytes = await bytesFrom(page, 'otherBytes', 'svg');
  sameBytes(bytes, otherFile(argv), `svg of zetafill ${argv.join(' ')}`);
  // The comparison can fail: the seed's control changed the drawing.
  assert.throws(() => sameBytes(before, bytes, 'seed 2 against seed 5'), /first difference/);
  // An emptied control leaves its flag out (the CLI's default).
  await page.fill(tile('seed'), '');
  assert.equal(await args(), '--radius 8 --spacing 2 --tries 800 --layout mosaic');
  // An edit of the command line sets the controls, `--flag=value` included.
  await page.fill('#other-args', '--seed=7 --radius 8 --spacing 2 --tries 800 --layout planet --rows 3 --style filled');
  assert.equal(await page.inputValue(tile('seed')), '7');
  assert.equal(await page.inputValue(tile('layout')), 'planet');
  assert.equal(await page.inputValue(tile('rows')), '3');
  assert.equal(await page.inputValue(tile('style')), 'filled');
  // The line tab: a checkbox is a flag alone.
  await page.click('[data-tab=line]');
  assert.equal(await page.isVisible('#controls-line'), true);
  assert.equal(await page.isVisible('#controls-tile'), false);
  assert.equal(await page.inputValue('#controls-line [data-flag=render]'), 'bars');
  await page.check('#controls-line [data-flag=periodic]');
  await page.selectOption('#controls-line [data-flag=render]', 'circles');
  assert.match(await args(), / --periodic --render circles$/);
  src = await drawn(src);
  const lineArgv = await page.evaluate(() => window.zetafill.otherArgv('svg'));
  sameBytes(await bytesFrom(page, 'otherBytes', 'svg'), otherFile(lineArgv), `svg of zetafill ${lineArgv.join(' ')}`);
  await page.uncheck('#controls-line [data-flag=periodic]');
  assert.doesNotMatch(await args(), /--periodic/);
  await page.close();
});

// The page's size targets: at most 2 MB of WebAssembly, 700 KB gzipped (level 9), loaded to
// run, with no argument parser inside; the PNG renderer, loaded only for a PNG, within 350 KB
// gzipped; and what the page leaves out is refused with a message.
test('the wasm is small, links no argument parser, and refuses what it leaves out', async () => {
  const size = (name) => {
    const file = join(root, 'web/dist', name);
    const bytes = readFileSync(file);
    const gz = spawnSync('gzip', ['-9', '-c', file], { maxBuffer: 1 << 26 }).stdout.length;
    console.log(`${name}: ${bytes.length} bytes, ${gz} gzipped`);
    return { bytes, gz };
  };
  const wasm = size('zetafill_web_bg.wasm');
  assert.ok(wasm.bytes.length <= 2_000_000, `${wasm.bytes.length} bytes`);
  assert.ok(wasm.gz <= 700_000, `${wasm.gz} bytes gzipped`);
  const png = size('zetafill_web_png_bg.wasm');
  assert.ok(png.gz <= 350_000, `the PNG module: ${png.gz} bytes gzipped`);
  // clap's own texts, which any build that links its parser carries; the checker fails on
  // such a build: the CLI binary holds them.
  const clapTexts = ['Usage:', 'Print help', 'possible values: '];
  const holds = (bytes) => clapTexts.filter((t) => bytes.includes(Buffer.from(t)));
  assert.deepEqual(holds(wasm.bytes), []);
  assert.deepEqual(holds(png.bytes), []);
  assert.deepEqual(holds(readFileSync(ZETAFILL)), clapTexts);

  const page = await openPage('?until=50');
  await settled(page);
  const said = await page.evaluate(async () => {
    const m = await import('./zetafill_web.js');
    await m.default();
    const refused = (argv) => {
      try {
        new m.Session(argv);
        return null;
      } catch (e) {
        return String(e);
      }
    };
    return {
      fixed: refused(['--scalar', 'fixed', '--count', '5', '-o', 'x.svg']),
      f64: refused(['--scalar', 'f64', '--count', '5', '-o', 'x.svg']),
      typo: refused(['--cuont', '5', '-o', 'x.svg']),
    };
  });
  assert.equal(said.f64, null);
  assert.match(said.fixed, /^error: --scalar: this build computes in f64 only/);
  // Unknown flags get the first line of the CLI's message, and its closing hint.
  const cli = cliMessage(['--cuont', '5', '-o', 'x.svg']).split('\n');
  assert.equal(said.typo, `${cli[0]}\n\n${cli.at(-1)}`);
  await page.close();
});
