// check.mjs - rayo's page (build/web/, web/) in a real browser: Debian's
// chromium, headless, driven by playwright-core (no browser download).
// `make check-web` runs it (TAP on stdout) with RAYO (the command),
// RAYO_WEB (the built site), RAYO_SOURCE (the tree) and CHROMIUM.
//
// The page is served by `python3 -m http.server` on 127.0.0.1 and every
// expectation comes from the command itself: the page's report must be
// `rayo compare`'s standard output, its error line the command's stderr,
// its render the command's PBM.  Timings are printed (the issue's
// targets: seed render 50 ms, 640x480 compare 100 ms, load 1 s) and only
// bounded generously.  RAYO_WEB_SCREENSHOT=FILE saves the README's
// screenshot there.  Then looks.mjs checks how the page looks and what
// it says, at a desktop's width and a phone's.
import { spawn, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { looks, LOOKS_TESTS } from './looks.mjs';

const RAYO = process.env.RAYO;
const WEB = process.env.RAYO_WEB;
const SOURCE = process.env.RAYO_SOURCE;
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const course = (n) => path.join(SOURCE, 'data/course', `referencia-catedra-ej${n}.png`);

let count = 0, failed = 0;
function ok(cond, name, detail) {
  count++;
  if (!cond) failed++;
  console.log(`${cond ? 'ok' : 'not ok'} ${count} - ${name}`);
  if (!cond && detail !== undefined)
    for (const line of String(detail).split('\n')) console.log(`#   ${line}`);
}
const note = (text) => console.log(`# ${text}`);

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'rayo-web-'));
function rayo(args) {
  const r = spawnSync(RAYO, args, { cwd: tmp, encoding: 'utf8' });
  return { out: r.stdout, err: r.stderr, status: r.status };
}

// Test inputs, made by the command and changed here byte by byte.
function netpbm(file) {
  const b = fs.readFileSync(path.join(tmp, file));
  const words = [];
  let i = 0;
  while (words.length < 4) {
    while (/\s/.test(String.fromCharCode(b[i]))) i++;
    if (b[i] === 0x23) { while (b[i] !== 10) i++; continue; }
    let w = '';
    while (!/\s/.test(String.fromCharCode(b[i]))) w += String.fromCharCode(b[i++]);
    words.push(w);
    if (/^P[14]$/.test(words[0]) && words.length === 3) break;
  }
  return { magic: words[0], width: +words[1], height: +words[2], data: b.subarray(i + 1) };
}
// The bits of a PBM (plain or raw): 1 black, row by row.
function pbmBits(file) {
  const p = netpbm(file), bits = new Uint8Array(p.width * p.height);
  if (p.magic === 'P4') {
    const stride = Math.ceil(p.width / 8);
    for (let y = 0; y < p.height; y++)
      for (let x = 0; x < p.width; x++)
        bits[y * p.width + x] = (p.data[y * stride + (x >> 3)] >> (7 - (x & 7))) & 1;
  } else {
    let k = 0;
    for (const c of p.data) if (c === 0x30 || c === 0x31) bits[k++] = c - 0x30;
  }
  return { ...p, bits };
}

function setup() {
  rayo(['-o', 'seed.pbm']);
  const seed = pbmBits('seed.pbm');
  const rows = [];
  for (let y = seed.height - 1; y >= 0; y--)
    rows.push(Array.from(seed.bits.subarray(y * seed.width, (y + 1) * seed.width)).join(' '));
  fs.writeFileSync(path.join(tmp, 'flipped.pbm'),
                   `P1\n${seed.width} ${seed.height}\n${rows.join('\n')}\n`);
  rayo(['convert', course(2), 'ej2.pgm']);
  // One pixel past the page's 2^25: 8193x4096, raw.
  fs.writeFileSync(path.join(tmp, 'wide.pbm'), Buffer.concat([
    Buffer.from('P4\n8193 4096\n'), Buffer.alloc(Math.ceil(8193 / 8) * 4096)]));
  // A PNG's signature and header (IHDR, 65536x16384 gray, 1 bit) alone.
  const ihdr = Buffer.alloc(25);
  ihdr.writeUInt32BE(13, 0);
  ihdr.write('IHDR', 4);
  ihdr.writeUInt32BE(65536, 8);
  ihdr.writeUInt32BE(16384, 12);
  ihdr[16] = 1;
  fs.writeFileSync(path.join(tmp, 'huge.png'), Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]), ihdr]));
  rayo(['render', path.join(SOURCE, 'examples/ej2.scene'), '-o', 'ej2-render.pgm']);
  rayo(['convert', course(3), 'ej3.ppm']);
  const gray = netpbm('ej2.pgm');
  const lighter = Buffer.from(gray.data).map((v) => Math.min(255, v + 40));
  fs.writeFileSync(path.join(tmp, 'lighter.pgm'),
                   Buffer.concat([Buffer.from(`P5\n${gray.width} ${gray.height}\n255\n`), lighter]));
  const colour = netpbm('ej3.ppm');
  const swapped = Buffer.from(colour.data);
  for (let i = 0; i + 2 < swapped.length; i += 3) {
    const r = swapped[i];
    swapped[i] = swapped[i + 2];
    swapped[i + 2] = r;
  }
  fs.writeFileSync(path.join(tmp, 'swapped.ppm'),
                   Buffer.concat([Buffer.from(`P6\n${colour.width} ${colour.height}\n255\n`), swapped]));
  fs.writeFileSync(path.join(tmp, 'malformed.pgm'), 'P2\n3 2\n255\n0 128 255\n7 x 1\n');
  fs.copyFileSync(course(3), path.join(tmp, 'ej3.png'));
  return seed;
}

function serve() {
  return new Promise((resolve, reject) => {
    const server = spawn('python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1',
                                     '--directory', WEB], { stdio: ['ignore', 'pipe', 'pipe'] });
    server.stdout.on('data', (d) => {
      const m = /port (\d+)/.exec(String(d));
      if (m) resolve({ server, port: +m[1] });
    });
    server.on('error', reject);
    setTimeout(() => reject(new Error('http.server did not start')), 10000);
  });
}

function siteBytes(dir) {
  let n = 0;
  for (const e of fs.readdirSync(dir, { withFileTypes: true }))
    n += e.isDirectory() ? siteBytes(path.join(dir, e.name)) : fs.statSync(path.join(dir, e.name)).size;
  return n;
}

async function main() {
  const planned = 43 + 2 * LOOKS_TESTS;
  console.log(`1..${planned}`);
  const seed = setup();
  const size = siteBytes(WEB);
  ok(size <= 3 * 1024 * 1024, `build/web/ is ${size} bytes, at most 3 MiB`);
  const { server, port } = await serve();
  const origin = `http://127.0.0.1:${port}`;
  const browser = await chromium.launch({
    executablePath: CHROMIUM, headless: true,
    args: process.getuid && process.getuid() === 0 ? ['--no-sandbox'] : [],
  });
  try {
    await run(browser, origin, seed);
    const common = { browser, origin, tmp, rayo, course, ok, note };
    await looks({ ...common, width: 1000, height: 900, locale: 'en-US', lang: 'en', label: 'desktop' });
    await looks({ ...common, width: 375, height: 740, locale: 'es-AR', lang: 'es', label: 'phone' });
  } finally {
    await browser.close();
    server.kill();
    fs.rmSync(tmp, { recursive: true, force: true });
  }
  if (count !== planned) ok(false, `planned ${planned} tests, ran ${count}`);
  process.exitCode = failed ? 1 : 0;
}

async function run(browser, origin, seed) {
  const context = await browser.newContext({ locale: 'en-US', viewport: { width: 1000, height: 900 } });
  const page = await context.newPage();
  const errors = [], offsite = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('request', (r) => {
    const u = r.url();
    if (!u.startsWith(origin + '/') && !u.startsWith('blob:') && !u.startsWith('data:'))
      offsite.push(u);
  });
  const t0 = Date.now();
  await page.goto(origin + '/index.html');
  await page.waitForSelector('body[data-ready="1"]', { timeout: 10000 });
  const wall = Date.now() - t0;
  const load = await page.evaluate(() => window.rayoTimes.load);
  note(`first load: ${load.toFixed(0)} ms in the page (navigation to ready), ${wall} ms from goto (target 1000 ms)`);
  ok(load < 5000, 'the page loads and the library starts');

  const T = (s) => `[data-test="${s}"]`;
  const text = (s) => page.locator(T(s)).textContent();
  ok((await page.locator('header p').textContent()).includes("The course's ray tracer"),
     'English text with an English browser');
  await page.click('#lang');
  ok((await page.locator('header p').textContent()).includes('El trazador de rayos del curso'),
     'the switch gives the Spanish text');
  await page.click('#lang');
  const options = await page.locator(`${T('reference')} option`).evaluateAll(
    (os) => os.map((o) => o.value));
  ok(['ej1', 'ej2', 'ej3'].every((v) => options.includes(v)), 'the reference offers ej1, ej2 and ej3');

  async function check(file, ref, refPath, name) {
    await page.selectOption(T('reference'), ref);
    await page.setInputFiles(T('image-input'), path.join(tmp, file));
    await page.waitForFunction((f) => document.getElementById('info').textContent.startsWith(f), file);
    await page.waitForFunction(() => document.getElementById('report').textContent !== '');
    const want = rayo(['compare', '--lang', 'en', refPath, file]);
    const got = await text('report');
    ok(got === want.out, `${name}: the report is rayo compare's`, `page:\n${got}\ncommand:\n${want.out}`);
    return { verdict: await text('verdict'), diagnosis: await text('diagnosis'), want,
             compare: await page.evaluate(() => window.rayoTimes.compare) };
  }
  let r = await check('seed.pbm', 'ej1', course(1), 'seed vs EJ1');
  ok(r.verdict === 'verdict: consistent' && r.diagnosis === '', 'the seed is consistent with EJ1', r.verdict);
  const maskCompare = r.compare;
  r = await check('flipped.pbm', 'ej1', course(1), 'flipped seed vs EJ1');
  ok(r.verdict === 'verdict: inconsistent' && /upside down/.test(r.diagnosis) &&
     r.want.out.includes(`diagnosis: ${r.diagnosis}`),
     'the flipped seed is inconsistent and upside down', `${r.verdict} / ${r.diagnosis}`);
  r = await check('lighter.pgm', 'ej2', course(2), 'lighter gray vs EJ2');
  const toneCompare = r.compare;
  ok(r.want.out.includes(r.verdict + '\n') || r.want.out.endsWith(r.verdict),
     `a gray image: the command's verdict (${r.verdict})`);
  r = await check('swapped.ppm', 'ej3', course(3), 'swapped colour vs EJ3');
  const colourCompare = r.compare;
  ok(r.want.out.includes(r.verdict) && r.verdict === 'verdict: inconsistent',
     `a colour image: the command's verdict (${r.diagnosis})`);
  r = await check('ej3.png', 'ej3', course(3), 'the EJ3 reference as a PNG vs EJ3');
  ok(r.verdict === 'verdict: identical', 'a PNG decoded by the browser: identical', r.verdict);
  // Each kind of 640x480 compare timed RUNS times (the image opened
  // again, its compare only), the median printed against the target.
  const RUNS = 5, times = {};
  async function timed(file, ref, kind) {
    await page.selectOption(T('reference'), ref);
    const runs = [];
    for (let k = 0; k < RUNS; k++) {
      await page.setInputFiles(T('image-input'), []); // so the same file changes it again
      await page.evaluate(() => { window.rayoTimes.compare = null; });
      await page.setInputFiles(T('image-input'), path.join(tmp, file));
      await page.waitForFunction(() => window.rayoTimes.compare !== null);
      runs.push(await page.evaluate(() => window.rayoTimes.compare));
    }
    const first = runs[0];
    runs.sort((a, b) => a - b);
    times[kind] = runs[RUNS >> 1];
    note(`640x480 compare, ${kind}: median ${times[kind].toFixed(1)} ms of ${RUNS} ` +
         `(first ${first.toFixed(1)}; ${runs.map((v) => v.toFixed(1)).join(', ')}) (target 100 ms)`);
  }
  note(`640x480 compare, the first of each kind in the page (the course's scene rendered and ` +
       `the reference's maps made then): ${maskCompare.toFixed(1)} ms bilevel, ` +
       `${toneCompare.toFixed(1)} ms gray (lighter), ${colourCompare.toFixed(1)} ms colour (swapped)`);
  await timed('seed.pbm', 'ej1', 'bilevel (seed vs EJ1)');
  await timed('lighter.pgm', 'ej2', 'gray (a lighter EJ2 vs EJ2)');
  await timed('ej2-render.pgm', 'ej2', 'gray (EJ2 rendered vs its reference)');
  await timed('swapped.ppm', 'ej3', 'colour (a channel-swapped EJ3 vs EJ3)');
  const slowest = Math.max(maskCompare, toneCompare, colourCompare, ...Object.values(times));
  ok(slowest < 3000, `compares take well under seconds (slowest ${slowest.toFixed(1)} ms)`);
  const diff = await page.locator(T('diff')).evaluate((img) => img.naturalWidth);
  ok(diff === 640, 'the difference picture is shown', diff);

  // Drag and drop: the same as the file picker.
  const flippedText = fs.readFileSync(path.join(tmp, 'flipped.pbm'), 'latin1');
  await page.selectOption(T('reference'), 'ej1');
  await page.evaluate((text) => {
    const dt = new DataTransfer();
    dt.items.add(new File([text], 'dropped.pbm'));
    document.getElementById('drop').dispatchEvent(
      new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, flippedText);
  await page.waitForFunction(() => document.getElementById('info').textContent.startsWith('dropped.pbm'));
  await page.waitForFunction(() => /upside down/.test(document.getElementById('diagnosis').textContent));
  ok(true, 'a dropped file is opened and checked');

  // A malformed file: the command's one-line message, in the page.
  await page.setInputFiles(T('image-input'), path.join(tmp, 'malformed.pgm'));
  await page.waitForFunction(() => document.getElementById('error').textContent !== '');
  const want = rayo(['compare', '--lang', 'en', course(1), 'malformed.pgm']).err.trim();
  const got = await text('error');
  ok(got === want && !got.includes('\n'), 'a malformed file: the command\'s message', `page: ${got}\ncommand: ${want}`);

  // Images past what the module's memory holds (2^25 pixels) are refused
  // with one line, a PNG before the browser decodes it, and the page
  // goes on working.
  await page.setInputFiles(T('image-input'), path.join(tmp, 'wide.pbm'));
  await page.waitForFunction(() => /8193x4096/.test(document.getElementById('error').textContent));
  let refused = await text('error');
  ok(refused === 'rayo: wide.pbm: the image is 8193x4096, 33558528 pixels; the page takes at most 33554432 (e.g. 8192x4096): compare it with the command, rayo compare',
     'an 8193x4096 PBM: refused, one line', refused);
  await page.setInputFiles(T('image-input'), path.join(tmp, 'huge.png'));
  await page.waitForFunction(() => /65536x16384/.test(document.getElementById('error').textContent));
  refused = await text('error');
  ok(/^rayo: huge\.png: the image is 65536x16384, 1073741824 pixels; the page takes at most 33554432/.test(refused),
     'a PNG whose header says 65536x16384: refused before decoding', refused);
  r = await check('seed.pbm', 'ej1', course(1), 'after the refusals, the seed vs EJ1');
  ok(r.verdict === 'verdict: consistent', 'after the refusals, the page still compares', r.verdict);

  // The module itself: the legal 65536x16384 PBM (2^30 pixels),
  // then a call that traps; the module is started again and works.
  const mod = await page.evaluate(async () => {
    const wasm = Uint8Array.from(atob(window.RAYO_ASSETS.wasm), (c) => c.charCodeAt(0));
    const r = await RayoWeb.loadRayo(wasm);
    const out = {};
    const big = new Uint8Array(20 + 8192 * 16384);
    big.set(new TextEncoder().encode('P4\n65536 16384\n'));
    const body = big.subarray(0, 16 + 8192 * 16384);
    try { r.read(body, 'big.pbm', true); out.big = 'read'; } catch (e) { out.big = e.message; }
    try { r.x.web_info(0xfffffff0, 0); out.trap = 'no trap'; } catch (e) {
      out.trap = e instanceof RayoWeb.RayoError ? e.message : `other: ${e}`;
    }
    await r.ready;
    out.generation = r.generation;
    const small = new TextEncoder().encode('P1\n3 2\n1 0 1\n0 1 0\n');
    const a = r.read(small, 'a.pbm', false), b = r.read(small, 'b.pbm', true);
    out.verdict = r.compare(a, b).verdict;
    a.free();
    b.free();
    return out;
  });
  ok(/^rayo: big\.pbm: the image is 65536x16384, 1073741824 pixels; the page takes at most/.test(mod.big),
     'the module: a 65536x16384 PBM refused, not written past its memory', mod.big);
  ok(/^rayo: the page's module failed \(.*\) and was started again/.test(mod.trap),
     'a call that traps: a RayoError, and the module started again', mod.trap);
  ok(mod.generation === 1 && mod.verdict === 'identical',
     'the module started again compares (generation 1, identical)', JSON.stringify(mod));

  // The seed scene rendered on the canvas: the command's PBM exactly.
  await page.selectOption(T('reference'), 'ej1');
  const renders = [];
  for (let k = 0; k < 5; k++) {
    await page.evaluate(() => { window.rayoTimes.render = null; });
    await page.click(T('render'));
    await page.waitForFunction(() => window.rayoTimes.render !== null);
    renders.push(await page.evaluate(() => window.rayoTimes.render));
  }
  renders.sort((a, b) => a - b);
  note(`seed render: median ${renders[2].toFixed(1)} ms of 5 (${renders.map((v) => v.toFixed(1)).join(', ')}) (target 50 ms)`);
  ok(renders[2] < 500, 'the seed renders in well under a second');
  const canvasBits = () => page.locator(T('canvas')).evaluate((c) => {
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let s = `${c.width} ${c.height} `;
    for (let i = 0; i < d.length; i += 4) s += d[i] === 0 && d[i + 1] === 0 && d[i + 2] === 0 ? '1' : (d[i] === 255 ? '0' : '?');
    return s;
  });
  const pixels = await canvasBits();
  const wantPixels = `${seed.width} ${seed.height} ${seed.bits.join('')}`;
  ok(pixels === wantPixels, 'the rendered seed equals the command\'s PBM pixel for pixel',
     `${pixels.length} vs ${wantPixels.length} characters`);
  ok((await text('verdict')) === 'verdict: consistent', 'the render is checked against EJ1');
  ok(!/^$/.test(await text('ray')) && /β = L · d = /.test(await text('ray')), 'the ray diagram gives β and δ');
  await page.locator(T('canvas')).focus();
  const before = await text('ray');
  await page.keyboard.press('ArrowLeft');
  ok((await text('ray')) !== before, 'the arrow keys move the pointed pixel');

  // Save as PNG: the browser's PNG of the canvas is the command's image.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#save')]);
  const saved = path.join(tmp, download.suggestedFilename());
  await download.saveAs(saved);
  const same = rayo(['compare', 'seed.pbm', saved]);
  ok(download.suggestedFilename() === 'esfera.png' && /verdict: identical/.test(same.out),
     'Save as PNG gives the rendered image', same.out + same.err);

  // The scene's values are editable and the picture follows them.
  await page.fill('[data-test="sphere-0-r"]', '0.5');
  await page.waitForFunction(() => /diagnosis/.test(document.getElementById('report').textContent));
  rayo(['--sphere', '0.5,0.75,1.9,0.5', '-o', 'small.pbm']);
  const small = pbmBits('small.pbm');
  const smallPixels = await canvasBits();
  ok(smallPixels === `${small.width} ${small.height} ${small.bits.join('')}`,
     'a smaller radius redraws the picture: the command\'s --sphere image');

  // Another file as the reference.
  await page.selectOption(T('reference'), 'file');
  await page.setInputFiles(T('reference-input'), path.join(tmp, 'small.pbm'));
  await page.waitForFunction(() => document.getElementById('verdict').textContent === 'verdict: identical');
  ok(true, 'another file as the reference: identical to the image it made');

  // A phone's width: nothing wider than the screen.
  const phone = await browser.newContext({ locale: 'es-AR', viewport: { width: 360, height: 740 } });
  const p1 = await phone.newPage();
  p1.on('pageerror', (e) => errors.push(String(e)));
  await p1.goto(origin + '/index.html');
  await p1.waitForSelector('body[data-ready="1"]');
  await p1.click(T('render'));
  await p1.waitForFunction(() => document.getElementById('report').textContent !== '');
  const wide = await p1.evaluate(() => document.documentElement.scrollWidth);
  ok(wide <= 360, `readable on a phone's width (360 px: the page is ${wide} px wide)`);
  await phone.close();

  // Opened from a file: the page fetches nothing, so it works there too.
  const local = await browser.newContext();
  const p3 = await local.newPage();
  p3.on('pageerror', (e) => errors.push(String(e)));
  await p3.goto('file://' + path.join(WEB, 'index.html'));
  await p3.waitForSelector('body[data-ready="1"]', { timeout: 10000 });
  await p3.click(T('render'));
  await p3.waitForFunction(() => document.getElementById('verdict').textContent !== '');
  ok((await p3.locator(T('verdict')).textContent()) === 'verdict: consistent',
     'from file:// the page renders and compares');
  await local.close();

  // A consistent render of EJ2 against its reference (a tone compare).
  await page.selectOption(T('scene'), 'ej2');
  await page.waitForFunction(() => document.getElementById('info').textContent.startsWith('ej2.pgm'));
  await page.waitForFunction(() => /gray/.test(document.getElementById('report').textContent));
  const ej2Compare = [await page.evaluate(() => window.rayoTimes.compare)];
  for (let k = 1; k < 5; k++) {
    await page.evaluate(() => { window.rayoTimes.compare = null; });
    await page.click(T('render'));
    await page.waitForFunction(() => window.rayoTimes.compare !== null);
    ej2Compare.push(await page.evaluate(() => window.rayoTimes.compare));
  }
  const ej2First = ej2Compare[0];
  ej2Compare.sort((a, b) => a - b);
  note(`640x480 compare, EJ2 rendered in the page vs its reference (consistent): median ` +
       `${ej2Compare[2].toFixed(1)} ms of 5 (first ${ej2First.toFixed(1)}) (target 100 ms)`);
  ok((await text('verdict')) === 'verdict: consistent', 'the EJ2 scene rendered is consistent with EJ2');

  // A Spanish browser gets Spanish first.
  const es = await browser.newContext({ locale: 'es-AR' });
  const p2 = await es.newPage();
  p2.on('pageerror', (e) => errors.push(String(e)));
  await p2.goto(origin + '/index.html');
  await p2.waitForSelector('body[data-ready="1"]');
  ok((await p2.locator('header p').textContent()).includes('El trazador de rayos del curso'),
     'Spanish text with a Spanish browser');
  // ... and the report in Spanish: `rayo compare --lang es`, word for word.
  await p2.selectOption(T('reference'), 'ej1');
  await p2.setInputFiles(T('image-input'), path.join(tmp, 'flipped.pbm'));
  await p2.waitForFunction(() => document.getElementById('info').textContent.startsWith('flipped.pbm'));
  await p2.waitForFunction(() => document.getElementById('report').textContent !== '');
  const wantEs = rayo(['compare', '--lang', 'es', course(1), 'flipped.pbm']);
  const gotEs = await p2.locator(T('report')).textContent();
  ok(gotEs === wantEs.out && /veredicto: /.test(gotEs),
     "a Spanish page's report is rayo compare --lang es's", `page:\n${gotEs}\ncommand:\n${wantEs.out}`);
  // ... and its error line in Spanish: the command's, and the page's own.
  await p2.setInputFiles(T('image-input'), path.join(tmp, 'malformed.pgm'));
  await p2.waitForFunction(() => document.getElementById('error').textContent !== '');
  const wantErrEs = rayo(['compare', '--lang', 'es', course(1), 'malformed.pgm']).err.trim();
  const gotErrEs = await p2.locator(T('error')).textContent();
  ok(gotErrEs === wantErrEs && gotErrEs !== want,
     "a Spanish page's error line is rayo compare --lang es's", `page: ${gotErrEs}\ncommand: ${wantErrEs}`);
  await p2.setInputFiles(T('image-input'), path.join(tmp, 'wide.pbm'));
  await p2.waitForFunction(() => /8193x4096/.test(document.getElementById('error').textContent));
  const refusedEs = await p2.locator(T('error')).textContent();
  ok(refusedEs === 'rayo: wide.pbm: la imagen es de 8193x4096, 33558528 píxeles; la página acepta hasta 33554432 (por ejemplo 8192x4096): comparala con el comando, rayo compare',
     "a Spanish page's own refusal in Spanish", refusedEs);
  await es.close();

  // The README's picture: a mistake found.
  if (process.env.RAYO_WEB_SCREENSHOT) {
    await page.setViewportSize({ width: 760, height: 1000 });
    await page.selectOption(T('reference'), 'auto');
    await page.setInputFiles(T('image-input'), path.join(tmp, 'flipped.pbm'));
    await page.waitForFunction(() => /upside down/.test(document.getElementById('diagnosis').textContent));
    await page.selectOption('#zoom', '0.5');
    await page.evaluate(() => { document.activeElement.blur(); window.scrollTo(0, 0); });
    await page.screenshot({ path: process.env.RAYO_WEB_SCREENSHOT });
    note(`screenshot: ${process.env.RAYO_WEB_SCREENSHOT}`);
  }

  ok(errors.length === 0, 'no console error', errors.join('\n'));
  ok(offsite.length === 0, 'no request off the machine', offsite.join('\n'));
  await context.close();
}

main().catch((e) => {
  console.log(`not ok ${count + 1} - ${String(e).split('\n')[0]}`);
  console.log(`# ${e.stack}`);
  process.exitCode = 1;
});
