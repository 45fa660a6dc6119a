// The browser benchmark (figures in docs/performance.md, "Browser"): placements per second of
// the page against the native CLI on the same machine, at 10^4 and 10^5 circles, c = 1.3; the
// time until 10^4 circles are on screen; the page's weight, gzip-compressed. With DOTSTER set to
// a checkout of github.com/bit-player/dotster (not part of this repository), also that page's
// own fill (s = 1.3) in the same browser.
//
//   bash web/build.sh && cargo build --release -p zetafill-cli
//   cd web && npm ci && node bench.mjs            (DOTSTER=/path/to/dotster node bench.mjs)
import { spawnSync } from 'node:child_process';
import { readFileSync, readdirSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { serve } from './test/serve.mjs';

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const targetDir = process.env.CARGO_TARGET_DIR ? resolve(root, process.env.CARGO_TARGET_DIR) : join(root, 'target');
const ZETAFILL = process.env.ZETAFILL ?? join(targetDir, 'release/zetafill');
const RUNS = Number(process.env.RUNS ?? 3);
const COUNTS = (process.env.COUNTS ?? "10000,100000").split(",").map(Number);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const dist = join(root, 'web/dist');
let raw = 0;
let gz = 0;
for (const f of readdirSync(dist)) {
  const bytes = readFileSync(join(dist, f));
  raw += bytes.length;
  gz += gzipSync(bytes, { level: 9 }).length;
}
console.log(`page weight: ${(raw / 1024).toFixed(0)} KiB, ${(gz / 1024).toFixed(0)} KiB gzip-compressed`);

const server = await serve(dist);
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium', args: ['--no-sandbox'] });

// One fill on a fresh page: the fill's time in the worker, and the time from the page's start
// until every shape is drawn and until the finished picture is shown.
async function pageFill(query) {
  const page = await browser.newPage();
  await page.goto(`${server.url}index.html${query}`);
  await page.waitForFunction(() => window.zetafill?.state === 'done', null, { timeout: 600_000 });
  const r = await page.evaluate(() => {
    const z = window.zetafill;
    return { digest: z.digest, ms: z.ms, drawn: z.times[z.events.lastIndexOf('progress')], done: z.times[z.events.lastIndexOf('done')] };
  });
  // Then another seed on the loaded page: from the input to the drawing.
  const n0 = await page.evaluate(() => window.zetafill.events.length);
  await page.fill('input[name=seed]', '2');
  await page.waitForFunction((n) => window.zetafill.events.slice(n).includes('done'), n0, { timeout: 600_000 });
  r.warm = await page.evaluate((n) => {
    const z = window.zetafill;
    const [ev, t] = [z.events.slice(n), z.times.slice(n)];
    const input = t[ev.findIndex((e) => e.startsWith('input'))];
    return { drawn: t[ev.lastIndexOf('progress')] - input, done: t[ev.lastIndexOf('done')] - input };
  }, n0);
  await page.close();
  return r;
}

function nativeFill(args) {
  const t0 = process.hrtime.bigint();
  const r = spawnSync(ZETAFILL, ['fill', '-q', ...args, '-o', '-', '--format', 'digest']);
  if (r.status !== 0) throw new Error(r.stderr.toString());
  return { ms: Number(process.hrtime.bigint() - t0) / 1e6, digest: r.stdout.toString().trim() };
}

for (const n of COUNTS) {
  for (const sampler of ['fast', 'reference']) {
    const extra = sampler === 'fast' ? '' : '&sampler=reference';
    const args = ['--c', '1.3', '--count', String(n), '--seed', '1', '--sampler', sampler];
    const web = [];
    for (let i = 0; i < RUNS; i++) web.push(await pageFill(`?until=${n}&style=outline&palette=${extra}`));
    const natives = Array.from({ length: RUNS }, () => nativeFill(args));
    const native = median(natives.map((x) => x.ms));
    if (web.some((x) => x.digest !== natives[0].digest)) throw new Error(`the digests differ: ${web[0].digest}, ${natives[0].digest}`);
    const w = median(web.map((x) => x.ms));
    console.log(
      `${n} circles, ${sampler}: browser ${w.toFixed(0)} ms (${Math.round(n / w * 1000)}/s), native ${native.toFixed(0)} ms (${Math.round(n / native * 1000)}/s), ratio ${(w / native).toFixed(2)}; `
      + `page start to all drawn ${median(web.map((x) => x.drawn)).toFixed(0)} ms, to the finished picture ${median(web.map((x) => x.done)).toFixed(0)} ms; `
      + `new seed to all drawn ${median(web.map((x) => x.warm.drawn)).toFixed(0)} ms, to the finished picture ${median(web.map((x) => x.warm.done)).toFixed(0)} ms`,
    );
  }
}

if (process.env.DOTSTER) {
  const dotster = await serve(process.env.DOTSTER);
  for (const n of COUNTS) {
    const page = await browser.newPage();
    // The page loads its formula typesetter from a CDN, which it does not need to fill.
    await page.route((url) => !url.href.startsWith(dotster.url), (route) => route.abort());
    // Its programs live in a block: the benchmark's copy of zeta.js, as served, also hands the
    // "zeta scaled" one to the window (A_k = 1/k^s in a box of area zeta(s), s = 1.3 by
    // default: c = 1.3, N = 1).
    await page.route('**/zeta.js', async (route) => {
      const response = await route.fetch();
      const body = (await response.text()).replace(/\}\s*\/\/ DO NOT REMOVE THIS CURLY BRACE[^\n]*/, 'window.zetaScaled = zs;\n}');
      await route.fulfill({ response, body });
    });
    // Its formulas are typeset by MathJax, which is not loaded here: a stand-in that does nothing.
    await page.addInitScript(() => { window.MathJax = { typeset() {} }; });
    await page.goto(`${dotster.url}index.html`);
    // As shipped it places one disk per timer tick; here its step runs back to back, drawing
    // included, so that the timer does not set the pace.
    const r = await page.evaluate((count) => {
      const zs = window.zetaScaled;
      zs.resetClick();
      const t0 = performance.now();
      // At most two minutes.
      while (zs.diskCount < count && performance.now() - t0 < 120_000) {
        zs.doOneDisk();
        if (zs.state === 'Exhausted' || zs.state === 'Jammed') break;
      }
      return { placed: zs.diskCount, ms: performance.now() - t0, s: zs.s };
    }, n);
    console.log(`dotster (s = ${r.s}), ${r.placed} disks back to back: ${r.ms.toFixed(0)} ms (${Math.round(r.placed / r.ms * 1000)}/s)`);
    if (n === 10_000) {
      await page.evaluate(() => { window.zetaScaled.resetClick(); window.zetaScaled.goStopClick(); });
      await page.waitForTimeout(5000);
      const shipped = await page.evaluate(() => { const zs = window.zetaScaled; const k = zs.diskCount; zs.goStopClick(); return k; });
      console.log(`dotster as shipped (one disk per timer tick): ${shipped} disks in 5 s`);
    }
    await page.close();
  }
  await dotster.close();
}

await browser.close();
await server.close();
