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
const RUNS = 3;
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
    return { ms: z.ms, drawn: z.times[z.events.lastIndexOf('progress')], done: z.times[z.events.lastIndexOf('done')] };
  });
  await page.close();
  return r;
}

function nativeFill(args) {
  const t0 = process.hrtime.bigint();
  const r = spawnSync(ZETAFILL, ['fill', '-q', ...args, '-o', '-', '--format', 'digest']);
  if (r.status !== 0) throw new Error(r.stderr.toString());
  return Number(process.hrtime.bigint() - t0) / 1e6;
}

for (const n of [10_000, 100_000]) {
  for (const sampler of ['fast', 'reference']) {
    const extra = sampler === 'fast' ? '' : '&sampler=reference';
    const args = ['--c', '1.3', '--count', String(n), '--seed', '1', '--sampler', sampler];
    const web = [];
    for (let i = 0; i < RUNS; i++) web.push(await pageFill(`?until=${n}&style=outline&palette=${extra}`));
    const native = median(Array.from({ length: RUNS }, () => nativeFill(args)));
    const w = median(web.map((x) => x.ms));
    console.log(
      `${n} circles, ${sampler}: browser ${w.toFixed(0)} ms (${Math.round(n / w * 1000)}/s), native ${native.toFixed(0)} ms (${Math.round(n / native * 1000)}/s), ratio ${(w / native).toFixed(2)}; `
      + `page start to all drawn ${median(web.map((x) => x.drawn)).toFixed(0)} ms, to the finished picture ${median(web.map((x) => x.done)).toFixed(0)} ms`,
    );
  }
}

if (process.env.DOTSTER) {
  const dotster = await serve(process.env.DOTSTER);
  for (const n of [10_000, 100_000]) {
    const page = await browser.newPage();
    // The page loads its formula typesetter from a CDN, which it does not need to fill.
    await page.route((url) => !url.href.startsWith(dotster.url), (route) => route.abort());
    await page.goto(`${dotster.url}index.html`);
    // Its "zeta scaled" program: A_k = 1/k^s in a box of area zeta(s), s = 1.3 (c = 1.3, N = 1).
    // As shipped it places one disk per timer tick; here its step runs back to back, drawing
    // included, so that the timer does not set the pace.
    const r = await page.evaluate((count) => {
      zs.resetClick();
      const t0 = performance.now();
      while (zs.diskCount < count && zs.doOneDisk() !== undefined) {
        if (zs.state === 'Exhausted' || zs.state === 'Jammed') break;
      }
      return { placed: zs.diskCount, ms: performance.now() - t0, s: zs.s };
    }, n);
    console.log(`dotster (s = ${r.s}), ${r.placed} disks back to back: ${r.ms.toFixed(0)} ms (${Math.round(r.placed / r.ms * 1000)}/s)`);
    if (n === 10_000) {
      await page.evaluate(() => { zs.resetClick(); zs.goStopClick(); });
      await page.waitForTimeout(5000);
      const shipped = await page.evaluate(() => { const k = zs.diskCount; zs.goStopClick(); return k; });
      console.log(`dotster as shipped (one disk per timer tick): ${shipped} disks in 5 s`);
    }
    await page.close();
  }
  await dotster.close();
}

await browser.close();
await server.close();
