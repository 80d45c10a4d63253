// looks.mjs - the page is right and looks finished, at one width: check.mjs
// runs it at a desktop's width (in English) and at a 375-px phone's (in
// Spanish).  Nothing shown before there is something to show; the
// reference follows the image's kind unless one is picked, and the page
// says which and why; the verdict is a coloured mark with a symbol; the
// image fits the window by default; a file that fails clears what the
// previous one left; the ray diagram explains the sphere the ray hits.
// Expectations come from the command (reports, errors) or are computed
// here from the assignment's formulas (the ray), never from the page's
// script.  Screenshots go to shots (RAYO_WEB_SHOTS, else a folder under
// the system's temporary one), kept for people to look at, not compared.
import fs from 'node:fs';
import path from 'node:path';

export const LOOKS_TESTS = 14;

// The page's own sentences the tests expect, in each language.
const WORDS = {
  en: {
    kind: {
      ej1: "Compared with the course's image for exercise 1, because your image is black and white.",
      ej2: "Compared with the course's image for exercise 2, because your image is gray.",
      ej3: "Compared with the course's image for exercise 3, because your image is in colour.",
    },
    picked1: "Compared with the course's image for exercise 1, the one you chose.",
    sphere: (k) => `Sphere ${k}: C = `,
    meets: (k, t) => `δ ≥ 0: the ray meets sphere ${k}, and it is the nearest hit of the scene: t = ${t}.`,
    misses: (k) => `δ < 0: the ray misses sphere ${k}.`,
    noneHit: 'No sphere of the scene meets this ray.',
  },
  es: {
    kind: {
      ej1: 'Se comparó con la imagen de la cátedra del ejercicio 1, porque tu imagen está en blanco y negro.',
      ej2: 'Se comparó con la imagen de la cátedra del ejercicio 2, porque tu imagen es gris.',
      ej3: 'Se comparó con la imagen de la cátedra del ejercicio 3, porque tu imagen está en color.',
    },
    picked1: 'Se comparó con la imagen de la cátedra del ejercicio 1, la que elegiste.',
    sphere: (k) => `Esfera ${k}: C = `,
    meets: (k, t) => `δ ≥ 0: el rayo toca la esfera ${k}, y es la intersección más cercana de la escena: t = ${t}.`,
    misses: (k) => `δ < 0: el rayo no toca la esfera ${k}.`,
    noneHit: 'Ninguna esfera de la escena toca este rayo.',
  },
};

// The assignment's ray through pixel (i, j) and every sphere's beta,
// delta and t (the smallest positive root, or Infinity).
function trace(camera, spheres, i, j) {
  const [w, h, fov, ox, oy, oz] = camera;
  const x = i - Math.floor(w / 2), y = Math.floor(h / 2) - j;
  const z = w / (2 * Math.tan((fov * Math.PI) / 360));
  const len = Math.hypot(x, y, z), d = [x / len, y / len, z / len];
  return spheres.map(([cx, cy, cz, r]) => {
    const l = [cx - ox, cy - oy, cz - oz];
    const beta = l[0] * d[0] + l[1] * d[1] + l[2] * d[2];
    const delta = beta * beta - (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]) + r * r;
    let t = Infinity;
    if (delta >= 0) {
      const root = Math.sqrt(delta);
      t = beta - root > 0 ? beta - root : beta + root > 0 ? beta + root : Infinity;
    }
    return { beta, delta, t };
  });
}

export async function looks(ctx) {
  const { browser, origin, tmp, rayo, course, ok, note, width, height, locale, lang, label } = ctx;
  const errors = [];
  const W = WORDS[lang];
  const shots = process.env.RAYO_WEB_SHOTS || path.join(path.dirname(tmp), 'rayo-web-shots');
  fs.mkdirSync(shots, { recursive: true });
  const context = await browser.newContext({ locale, viewport: { width, height } });
  const page = await context.newPage();
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  const T = (s) => `[data-test="${s}"]`;
  const text = (s) => page.locator(T(s)).textContent();
  const visible = (sel) => page.locator(sel).isVisible();
  const shot = async (name) => {
    const file = path.join(shots, `${name}-${label}.png`);
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    await page.screenshot({ path: file, fullPage: true });
    return fs.statSync(file).size > 0;
  };
  await page.goto(origin + '/index.html');
  await page.waitForSelector('body[data-ready="1"]', { timeout: 10000 });

  // Before anything: no 1x1 canvas, no empty diagram, no empty verdict.
  const stray = [];
  for (const sel of ['#canvas', '#zoom', '#diagram', T('mark'), T('verdict'), T('ref-note'), T('report'), '#diff-figure'])
    if (await visible(sel)) stray.push(sel);
  if (!(await visible(T('no-render')))) stray.push('(no word on the empty geometry)');
  let shotsOk = await shot('1-empty');
  ok(stray.length === 0, `${label}: nothing empty or stray before there is something to show`, stray.join(' '));

  // The reference follows the image's kind.
  async function open(file) {
    await page.setInputFiles(T('image-input'), []);
    await page.evaluate(() => { window.rayoTimes.compare = null; });
    await page.setInputFiles(T('image-input'), path.join(tmp, file));
    await page.waitForFunction(() => window.rayoTimes.compare !== null);
  }
  async function byKind(file, ej, n) {
    await open(file);
    const want = rayo(['compare', '--lang', lang, course(n), file]).out;
    const got = { note: await text('ref-note'), report: await text('report') };
    ok(got.note === W.kind[ej] && got.report === want,
       `${label}: ${file} is compared with ${ej.toUpperCase()}, and the page says why`,
       `note: ${got.note}\npage:\n${got.report}\ncommand:\n${want}`);
  }
  const markOf = () => page.locator(T('mark')).evaluate((m) => ({
    text: m.textContent, cls: m.className, bg: getComputedStyle(m).backgroundColor,
    shown: m.getBoundingClientRect().height > 0 }));
  await byKind('ej2.pgm', 'ej2', 2);
  const right = await markOf();
  shotsOk = (await shot('2-gray-right')) && shotsOk;
  ok(right.shown && right.text.startsWith('✓') && /\bright\b/.test(right.cls),
     `${label}: an identical image gets a ✓ mark`, JSON.stringify(right));
  await byKind('seed.pbm', 'ej1', 1);
  await byKind('swapped.ppm', 'ej3', 3);
  const wrong = await markOf();
  shotsOk = (await shot('3-colour-wrong')) && shotsOk;
  ok(wrong.shown && wrong.text.startsWith('✗') && /\bwrong\b/.test(wrong.cls) && wrong.bg !== right.bg,
     `${label}: an inconsistent image gets a ✗ mark, coloured unlike ✓`, JSON.stringify([right, wrong]));

  // A reference the student picks is kept, and said so.
  await open('ej2.pgm');
  await page.evaluate(() => { window.rayoTimes.compare = null; });
  await page.selectOption(T('reference'), 'ej1');
  await page.waitForFunction(() => window.rayoTimes.compare !== null);
  let want = rayo(['compare', '--lang', lang, course(1), 'ej2.pgm']).out;
  let got = { note: await text('ref-note'), report: await text('report') };
  ok(got.note === W.picked1 && got.report === want,
     `${label}: a reference picked is the one compared with, and said so`,
     `note: ${got.note}\npage:\n${got.report}\ncommand:\n${want}`);
  await page.selectOption(T('reference'), 'auto');

  // The picture fits the window by default; the other zooms are there.
  await open('seed.pbm');
  const fit = await page.evaluate(() => {
    const c = document.getElementById('canvas'), b = c.getBoundingClientRect();
    const z = document.getElementById('zoom');
    return { zoom: z.value, zooms: [...z.options].map((o) => o.value), w: b.width, h: b.height,
             page: document.documentElement.scrollWidth, inner: innerWidth, tall: innerHeight };
  });
  shotsOk = (await shot('4-fit')) && shotsOk;
  ok(fit.zoom === 'fit' && ['0.5', '1', '2', '4', '8'].every((z) => fit.zooms.includes(z)) &&
     fit.w <= fit.inner && fit.h <= fit.tall && fit.page <= fit.inner &&
     fit.w >= Math.min(640, fit.inner * 0.8),
     `${label}: the 640x480 picture fits the window by default (${fit.w.toFixed(0)} px wide of ${fit.inner})`,
     JSON.stringify(fit));
  await page.selectOption('#zoom', '2');
  const doubled = await page.locator('#canvas').evaluate((c) => c.getBoundingClientRect().width);
  await page.selectOption('#zoom', 'fit');
  const back = await page.locator('#canvas').evaluate((c) => c.getBoundingClientRect().width);
  ok(Math.abs(doubled - 1282) < 1 && Math.abs(back - fit.w) < 1,
     `${label}: zoom 200% doubles the picture, fit brings it back`, `${doubled} ${back} ${fit.w}`);

  // A file that fails clears what the previous file left.
  fs.writeFileSync(path.join(tmp, 'bad.pbm'), 'p1\n3 2\n1 0 1\n0 1 0\n');
  await page.setInputFiles(T('image-input'), path.join(tmp, 'bad.pbm'));
  await page.waitForFunction(() => document.getElementById('error').textContent !== '');
  const left = await page.evaluate(() => {
    const g = (id) => document.getElementById(id);
    return { info: g('info').textContent, verdict: g('verdict').textContent,
             diagnosis: g('diagnosis').textContent, report: g('report').textContent,
             mark: g('mark').textContent, note: g('ref-note').textContent,
             picture: g('picture').hidden, diff: g('diff-figure').hidden, save: g('save').disabled };
  });
  const err = rayo(['compare', '--lang', lang, course(1), 'bad.pbm']).err.trim();
  shotsOk = (await shot('5-failed')) && shotsOk;
  ok((await text('error')) === err && Object.values(left).every((v) => v === '' || v === true),
     `${label}: a file that fails ('p1') shows the command's error and nothing of the previous file`,
     `${await text('error')}\n${err}\n${JSON.stringify(left)}`);

  // The ray diagram explains the sphere the ray hits (EJ3: sphere 2 at
  // the centre, sphere 1 missed there) and never contradicts itself.
  await page.selectOption(T('scene'), 'ej3');
  await page.waitForFunction(() => document.getElementById('ray').textContent !== '');
  const scene = await page.evaluate(() => ({
    camera: ['width', 'height', 'fov', 'ox', 'oy', 'oz'].map((id) => Number(document.getElementById(id).value)),
    spheres: [...document.querySelectorAll('#spheres .sphere')].map(
      (row) => [...row.querySelectorAll('input')].map((i) => Number(i.value))),
  }));
  async function pointAt(i, j) {
    await page.locator('#canvas').evaluate((c, [i, j]) => {
      const b = c.getBoundingClientRect();
      c.dispatchEvent(new PointerEvent('pointermove', { bubbles: true,
        clientX: b.left + ((i + 0.5) / c.width) * b.width, clientY: b.top + ((j + 0.5) / c.height) * b.height }));
    }, [i, j]);
    const ray = await text('ray');
    const m = /\(i, j\) = \((\d+), (\d+)\)/.exec(ray);
    return { ray, at: m ? [+m[1], +m[2]] : null };
  }
  let p = await pointAt(320, 240);
  let traced = trace(scene.camera, scene.spheres, ...p.at);
  let near = traced.reduce((b, s, k) => (s.t < traced[b].t ? k : b), 0);
  const f4 = (v) => v.toFixed(4);
  shotsOk = (await shot('6-ray-hit')) && shotsOk;
  ok(near === 1 && traced[0].delta < 0 && p.ray.includes(W.sphere(2)) &&
     p.ray.includes(`β = L · d = ${f4(traced[1].beta)};  δ = β² − L · L + R² = ${f4(traced[1].delta)}`) &&
     p.ray.includes(W.meets(2, f4(traced[1].t))) && !p.ray.includes('δ <'),
     `${label}: the ray through the centre of EJ3 explains sphere 2, the one it hits`,
     `${p.ray}\n${JSON.stringify(traced.slice(0, 2))}`);
  p = await pointAt(0, 0);
  traced = trace(scene.camera, scene.spheres, ...p.at);
  ok(traced.every((s) => s.t === Infinity) && traced[0].delta < 0 &&
     p.ray.includes(`δ = β² − L · L + R² = ${f4(traced[0].delta)}`) &&
     p.ray.includes(W.misses(1)) && p.ray.includes(W.noneHit) && !p.ray.includes('δ ≥'),
     `${label}: a ray that misses every sphere says so, with sphere 1's δ`, p.ray);

  // After a render, a failed file clears the picture and the geometry too.
  await page.setInputFiles(T('image-input'), []);
  await page.setInputFiles(T('image-input'), path.join(tmp, 'bad.pbm'));
  await page.waitForFunction(() => document.getElementById('ray').textContent === '');
  const cleared = { canvas: await visible('#canvas'), diagram: await visible('#diagram'),
                    word: await visible(T('no-render')), info: await text('info') };
  ok(!cleared.canvas && !cleared.diagram && cleared.word && cleared.info === '',
     `${label}: after a render, a failed file clears the picture and the ray diagram`,
     JSON.stringify(cleared));
  ok(shotsOk && errors.length === 0, `${label}: no console error; screenshots in ${shots}`,
     errors.join('\n'));
  note(`screenshots (${label}): ${shots}`);
  await context.close();
}
