// app.js - the page's behaviour: files in, pictures and rayo's reports
// out.  It moves bytes between the browser and the library (rayo.js) and
// draws; it reads, renders and compares nothing itself.  The browser
// decodes PNG (createImageBitmap) and encodes it (canvas.toBlob).  Texts
// of the page's own are in Spanish and English (TEXT); rayo's reports are
// shown as the command prints them.  window.rayoTimes keeps how long the
// last load, render and compare took, for the tests (tests/web/).
'use strict';
(function () {
const TEXT = {
  es: {
    tagline: 'El trazador de rayos del curso, en el navegador: ver, convertir y validar una imagen sin instalar nada.',
    'open.title': '1. Ver y convertir (graficación)',
    'open.label': 'Imagen a ver y validar (PBM, PGM, PPM o PNG):',
    'open.drop': 'o arrastrala y soltala aquí.',
    'open.zoom': 'Zoom:',
    'open.fit': 'Ajustar a la ventana',
    'open.save': 'Guardar como PNG',
    'validate.title': '2. Validar (validación)',
    'validate.reference': 'Referencia:',
    'validate.note': 'El informe es el de rayo compare --lang es, palabra por palabra.',
    'validate.diff': 'La diferencia: rojo, negro sólo en la referencia; azul, negro sólo en la imagen (en grises y color: ámbar, explicada; rojo, no).',
    'ref.auto': 'Automática: según tu imagen',
    'ref.ej1': 'Cátedra: ejercicio 1 (esfera)',
    'ref.ej2': 'Cátedra: ejercicio 2 (grises)',
    'ref.ej3': 'Cátedra: ejercicio 3 (color)',
    'ref.file': 'Otro archivo…',
    'render.title': '3. Renderizar',
    'render.scene': 'Escena:',
    'scene.seed': 'La esfera del enunciado (semilla)',
    'scene.ej1': 'Ejercicio 1',
    'scene.ej2': 'Ejercicio 2',
    'scene.ej3': 'Ejercicio 3',
    'render.width': 'Ancho',
    'render.height': 'Alto',
    'render.fov': 'Campo de visión (°)',
    'render.origin': 'Origen x, y, z',
    'render.spheres': 'Esferas: centro x, y, z y radio',
    'render.sphere': 'Esfera',
    'render.button': 'Renderizar',
    'render.reset': 'Valores del enunciado',
    'geometry.title': '4. La geometría',
    'geometry.none': 'Renderizá una escena para ver sus rayos.',
    'geometry.help': 'Señalá un píxel de la imagen renderizada (o usá las flechas con la imagen enfocada): el rayo que lo atraviesa, visto de costado (y, z) y desde arriba (x, z).',
    footer: 'Es rayo mismo: la biblioteca en C compilada a WebAssembly. Nada sale de esta página.',
    info: (i) => `${i.name}: ${i.width} × ${i.height} píxeles, ${i.format}${i.kind}, maxval ${i.maxval}`,
    plain: ' plano', raw: ' binario', decoded: ' (decodificado por el navegador)',
    rendered: (ms) => `Renderizado en ${ms} ms.`,
    compared: (ms) => ` Comparado en ${ms} ms.`,
    side: 'de costado (z →, y ↑)', top: 'desde arriba (z →, x ↑)',
    pixel: 'píxel',
    sphereIs: (k) => `Esfera ${k}`,
    hits: (k, t) => `δ ≥ 0: el rayo toca la esfera ${k}, y es la intersección más cercana de la escena: t = ${t}.`,
    misses: (k) => `δ < 0: el rayo no toca la esfera ${k}.`,
    behind: (k) => `δ ≥ 0, pero la esfera ${k} queda detrás de la cámara (t < 0): el rayo no la toca.`,
    noneHit: 'Ninguna esfera de la escena toca este rayo.',
    byKind: {
      ej1: 'Se comparó con la imagen de la cátedra del ejercicio 1, porque tu imagen está en blanco y negro.',
      ej2: 'Se comparó con la imagen de la cátedra del ejercicio 2, porque tu imagen es gris.',
      ej3: 'Se comparó con la imagen de la cátedra del ejercicio 3, porque tu imagen está en color.',
    },
    picked: (n) => `Se comparó con la imagen de la cátedra del ejercicio ${n}, la que elegiste.`,
    pickedFile: (name) => `Se comparó con el archivo que elegiste (${name}).`,
    right: '✓ Correcta: coincide con la referencia',
    wrong: '✗ No es correcta: no coincide con la referencia',
    lang: 'English', langLabel: 'English',
    pngError: (name) => `rayo: ${name}: el navegador no pudo decodificar el PNG`,
  },
  en: {
    tagline: "The course's ray tracer in the browser: view, convert and validate an image with nothing to install.",
    'open.title': '1. View and convert (graficación)',
    'open.label': 'Image to view and validate (PBM, PGM, PPM or PNG):',
    'open.drop': 'or drag and drop it here.',
    'open.zoom': 'Zoom:',
    'open.fit': 'Fit to the window',
    'open.save': 'Save as PNG',
    'validate.title': '2. Validate (validación)',
    'validate.reference': 'Reference:',
    'validate.note': 'The report is rayo compare\'s, word for word.',
    'validate.diff': 'The difference: red, black only in the reference; blue, black only in the image (gray and colour: amber, explained; red, not).',
    'ref.auto': 'Automatic: by your image',
    'ref.ej1': "Course's exercise 1 (sphere)",
    'ref.ej2': "Course's exercise 2 (gray)",
    'ref.ej3': "Course's exercise 3 (colour)",
    'ref.file': 'Another file…',
    'render.title': '3. Render',
    'render.scene': 'Scene:',
    'scene.seed': "The assignment's sphere (seed)",
    'scene.ej1': 'Exercise 1',
    'scene.ej2': 'Exercise 2',
    'scene.ej3': 'Exercise 3',
    'render.width': 'Width',
    'render.height': 'Height',
    'render.fov': 'Field of view (°)',
    'render.origin': 'Origin x, y, z',
    'render.spheres': 'Spheres: centre x, y, z and radius',
    'render.sphere': 'Sphere',
    'render.button': 'Render',
    'render.reset': "The assignment's values",
    'geometry.title': '4. The geometry',
    'geometry.none': 'Render a scene to see its rays.',
    'geometry.help': 'Point at a pixel of the rendered image (or use the arrow keys with the image focused): the ray through it, seen from the side (y, z) and from above (x, z).',
    footer: 'It is rayo itself: the C library compiled to WebAssembly. Nothing leaves this page.',
    info: (i) => `${i.name}: ${i.width} × ${i.height} pixels, ${i.format}${i.kind}, maxval ${i.maxval}`,
    plain: ' plain', raw: ' raw', decoded: ' (decoded by the browser)',
    rendered: (ms) => `Rendered in ${ms} ms.`,
    compared: (ms) => ` Compared in ${ms} ms.`,
    side: 'side (z →, y ↑)', top: 'above (z →, x ↑)',
    pixel: 'pixel',
    sphereIs: (k) => `Sphere ${k}`,
    hits: (k, t) => `δ ≥ 0: the ray meets sphere ${k}, and it is the nearest hit of the scene: t = ${t}.`,
    misses: (k) => `δ < 0: the ray misses sphere ${k}.`,
    behind: (k) => `δ ≥ 0, but sphere ${k} is behind the camera (t < 0): the ray does not meet it.`,
    noneHit: 'No sphere of the scene meets this ray.',
    byKind: {
      ej1: "Compared with the course's image for exercise 1, because your image is black and white.",
      ej2: "Compared with the course's image for exercise 2, because your image is gray.",
      ej3: "Compared with the course's image for exercise 3, because your image is in colour.",
    },
    picked: (n) => `Compared with the course's image for exercise ${n}, the one you chose.`,
    pickedFile: (name) => `Compared with the file you chose (${name}).`,
    right: '✓ Correct: it matches the reference',
    wrong: '✗ Not correct: it does not match the reference',
    lang: 'Español', langLabel: 'Español',
    pngError: (name) => `rayo: ${name}: the browser could not decode the PNG`,
  },
};
// The course's exercises as the module's registry lists them (readCourses):
// each name's index (its scene, its reference) and number.
let COURSES = {};
const sceneOf = (which) => (which in COURSES ? COURSES[which].index : -1);
const $ = (id) => document.getElementById(id);
let lang = (localStorage.getItem('rayo-lang') ||
            (navigator.language || 'es')).slice(0, 2) === 'en' ? 'en' : 'es';
const t = (key) => TEXT[lang][key];

const times = (window.rayoTimes = { load: null, render: null, compare: null });
let rayo = null;
const state = { image: null, name: '', rendered: null, pixel: null, infoKind: '',
                compared: null };
const references = {};
const referenceNames = {};

function bytesOf(base64) {
  const s = atob(base64), out = new Uint8Array(s.length);
  for (let i = 0; i < s.length; i++) out[i] = s.charCodeAt(i);
  return out;
}

function showError(message) { $('error').textContent = message || ''; }

function applyLang() {
  document.documentElement.lang = lang;
  for (const el of document.querySelectorAll('[data-i18n]'))
    el.textContent = t(el.dataset.i18n);
  $('lang').textContent = t('lang');
  $('lang').setAttribute('aria-label', t('langLabel'));
  for (const [i, legend] of document.querySelectorAll('#spheres .sphere-label').entries())
    legend.textContent = `${t('render.sphere')} ${i + 1}`;
  showInfo();
  showCompared();
  drawRay();
}

// An image from a file's bytes: rayo reads Netpbm; the browser decodes PNG.
async function decode(bytes, name, clamp) {
  const image = rayo.read(bytes, name, clamp);
  if (image) return image;
  // The size its header (IHDR) promises, checked before the browser
  // decodes it: the page's memory holds only so many pixels.
  if (bytes.length >= 24) {
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.length);
    rayo.sizeCheck(name, view.getUint32(16), view.getUint32(20));
  }
  let bitmap;
  try {
    bitmap = await createImageBitmap(new Blob([bytes]),
      { premultiplyAlpha: 'none', colorSpaceConversion: 'none' });
  } catch (e) {
    throw new RayoWeb.RayoError(t('pngError')(name));
  }
  const c = document.createElement('canvas');
  c.width = bitmap.width;
  c.height = bitmap.height;
  const ctx = c.getContext('2d', { willReadFrequently: true });
  ctx.drawImage(bitmap, 0, 0);
  return rayo.fromPNG(bytes, ctx.getImageData(0, 0, c.width, c.height));
}

function showInfo() {
  const im = state.image;
  if (!im) { $('info').textContent = ''; return; }
  const kind = im.format === 'PNG' ? t('decoded')
             : state.rendered ? '' : im.plain ? t('plain') : t('raw');
  $('info').textContent = t('info')({ name: state.name, width: im.width,
    height: im.height, format: im.format, kind, maxval: im.maxval });
}

// Everything that belonged to the image shown: after a file that fails,
// nothing of the previous one stays beside its error.
function forget() {
  if (state.image) state.image.free();
  state.image = null;
  state.name = '';
  state.rendered = null;
  state.pixel = null;
  const canvas = $('canvas');
  canvas.width = 1;
  canvas.height = 1;
  $('picture').hidden = true;
  $('save').disabled = true;
  $('timing').textContent = '';
  showInfo();
  clearCompare();
  drawRay();
}

// The zoom: a factor, or "fit" (the default), the largest that shows the
// whole picture in the section's width and most of the window's height;
// whole factors only when it grows, so pixels stay even.
function zoom() {
  const value = $('zoom').value, canvas = $('canvas');
  if (value !== 'fit') return Number(value);
  const room = $('open').clientWidth - 2; // the canvas's border
  const tall = Math.max(120, window.innerHeight * 0.8 - 2);
  const scale = Math.min(room / canvas.width, tall / canvas.height);
  return scale >= 1 ? Math.floor(scale) : scale;
}

function show(image, name) {
  if (state.image) state.image.free();
  state.image = image;
  state.name = name;
  const canvas = $('canvas');
  canvas.width = image.width;
  canvas.height = image.height;
  canvas.getContext('2d').putImageData(image.imageData(), 0, 0);
  $('picture').hidden = false;
  applyZoom();
  $('save').disabled = false;
  showInfo();
}

function applyZoom() {
  const canvas = $('canvas');
  canvas.style.width = `${canvas.width * zoom()}px`;
  canvas.style.height = `${canvas.height * zoom()}px`;
}

function readCourses() {
  COURSES = {};
  const n = rayo.x.web_course_count();
  for (let i = 0; i < n; i++)
    COURSES[rayo.string(rayo.x.web_course_name(i))] = { index: i, number: rayo.x.web_course_number(i) };
}

// The reference to compare with: the one picked, or for "auto" the
// course's exercise of the image's kind, as the registry says.
function referenceChoice() {
  const picked = $('reference').value;
  if (picked !== 'auto') return { which: picked, auto: false };
  const im = state.image;
  const index = rayo.x.web_course_of_kind(im.bilevel ? 1 : 0, im.channels);
  const which = Object.keys(COURSES).find((k) => COURSES[k].index === index);
  return { which, auto: true };
}

async function referenceImage(which) {
  if (which === 'file') return references.file || null;
  if (!references[which]) {
    const bytes = bytesOf(window.RAYO_ASSETS[which]);
    references[which] = await decode(bytes, `referencia-catedra-${which}.png`, false);
  }
  return references[which];
}

function clearCompare() {
  state.compared = null;
  showCompared();
  $('verdict').textContent = '';
  $('diagnosis').textContent = '';
  $('report').textContent = '';
  $('diff-figure').hidden = true;
}

// The page's own words on the last compare: which reference and why, and
// the mark (a symbol and a word, not colour alone).
function showCompared() {
  const c = state.compared, note = $('ref-note'), mark = $('mark');
  if (!c) {
    note.textContent = '';
    mark.textContent = '';
    mark.className = 'mark';
    return;
  }
  note.textContent = c.which === 'file' ? t('pickedFile')(c.file)
                   : c.auto ? t('byKind')[c.which] : t('picked')(COURSES[c.which].number);
  const right = c.verdict === 'identical' || c.verdict === 'consistent';
  mark.textContent = right ? t('right') : t('wrong');
  mark.className = right ? 'mark right' : 'mark wrong';
}

async function compare() {
  if (!state.image) return clearCompare();
  const choice = referenceChoice();
  const reference = await referenceImage(choice.which);
  if (!reference) return clearCompare();
  const start = performance.now();
  const course = sceneOf(choice.which);
  const result = rayo.compare(reference, state.image, course, lang);
  times.compare = performance.now() - start;
  state.compared = { ...choice, file: referenceNames.file || '', verdict: result.verdict };
  showCompared();
  $('verdict').textContent = `verdict: ${result.verdict}`;
  $('diagnosis').textContent = result.diagnosis;
  $('report').textContent = result.text;
  const img = $('diff');
  if (img.src) URL.revokeObjectURL(img.src);
  if (result.diff) {
    img.src = URL.createObjectURL(new Blob([result.diff], { type: 'image/png' }));
    img.width = reference.width;
    $('diff-figure').hidden = false;
  }
}

// Runs work; a failure is shown on the error line, after onFail (if any)
// has cleared what the failed step leaves stale.
async function guarded(work, onFail) {
  try {
    await work();
    showError('');
  } catch (e) {
    if (onFail) onFail();
    showError(e instanceof RayoWeb.RayoError ? e.message : `rayo: ${e.message}`);
    if (!(e instanceof RayoWeb.RayoError)) console.warn(e);
  }
}

async function openFile(file) {
  await guarded(async () => {
    const bytes = new Uint8Array(await file.arrayBuffer());
    const image = await decode(bytes, file.name, true);
    state.rendered = null;
    show(image, file.name);
    drawRay();
    await compare();
  }, forget);
}

// The render section's values.
function camera() {
  return ['width', 'height', 'fov', 'ox', 'oy', 'oz'].map((id) => Number($(id).value));
}
function spheres() {
  return [...document.querySelectorAll('#spheres .sphere')].map(
    (row) => [...row.querySelectorAll('input')].map((i) => Number(i.value)));
}

function setSpheres(list) {
  const box = $('spheres');
  for (const row of box.querySelectorAll('.sphere')) row.remove();
  list.forEach((s, n) => {
    const row = document.createElement('div');
    row.className = 'sphere';
    const label = document.createElement('span');
    label.className = 'sphere-label';
    label.textContent = `${t('render.sphere')} ${n + 1}`;
    row.append(label);
    ['cx', 'cy', 'cz', 'r'].forEach((name, k) => {
      const input = document.createElement('input');
      input.type = 'number';
      input.step = '0.05';
      input.value = String(s[k]);
      input.setAttribute('aria-label', `${name} ${n + 1}`);
      input.dataset.test = `sphere-${n}-${name}`;
      if (name === 'r') input.min = '0';
      row.append(input);
    });
    box.append(row);
  });
}

function resetScene() {
  const id = sceneOf($('scene').value);
  for (const [k, v] of Object.entries({ width: 640, height: 480, fov: 90, ox: 0, oy: 0, oz: 0 }))
    $(k).value = String(v);
  setSpheres(rayo.spheres(id));
}

async function render() {
  await guarded(async () => {
    const which = $('scene').value, cam = camera(), sp = spheres();
    const start = performance.now();
    const image = rayo.render(sceneOf(which), cam, sp);
    times.render = performance.now() - start;
    state.rendered = { camera: cam, spheres: sp };
    const ext = image.format.toLowerCase();
    show(image, `${which === 'seed' ? 'esfera' : which}.${ext}`);
    $('reference').value = 'auto';
    $('reference-input').hidden = true;
    await compare();
    $('timing').textContent = t('rendered')(times.render.toFixed(1)) +
      t('compared')(times.compare.toFixed(1));
    if (!state.pixel || state.pixel[0] >= cam[0] || state.pixel[1] >= cam[1])
      state.pixel = [Math.floor(cam[0] * 0.625), Math.floor(cam[1] * 0.2)];
    drawRay();
  }, forget);
}

let pending = false;
function renderSoon() {
  if (pending) return;
  pending = true;
  requestAnimationFrame(() => { pending = false; render(); });
}

// The diagram: the camera, the image plane a unit ahead, the spheres and
// the ray through state.pixel, seen from the side and from above.
function drawRay() {
  const canvas = $('diagram'), ctx = canvas.getContext('2d');
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  ctx.font = '13px system-ui, sans-serif';
  const r = state.rendered;
  const shown = Boolean(r && state.pixel);
  canvas.hidden = !shown;
  $('no-render').hidden = shown;
  if (!shown) {
    $('ray').textContent = '';
    return;
  }
  const [w, h, fov, ox, oy, oz] = r.camera;
  const [i, j] = state.pixel;
  const ray = rayo.ray(r.camera, r.spheres, i, j);
  if (!ray) return;
  const f = ray.focal, x = i - Math.floor(w / 2), y = Math.floor(h / 2) - j;
  const reach = ray.hit ? ray.t : Math.max(3, ...r.spheres.map((s) => s[2] - oz + s[3]));
  const panels = [
    { title: t('side'), a: 1, half: h / 2 / f },
    { title: t('top'), a: 0, half: w / 2 / f },
  ];
  const pw = canvas.width / 2, ph = canvas.height;
  let zmax = Math.max(reach * ray.d[2], 1.2);
  let amax = 1;
  for (const s of r.spheres) {
    zmax = Math.max(zmax, s[2] - oz + s[3]);
    amax = Math.max(amax, Math.abs(s[0] - ox) + s[3], Math.abs(s[1] - oy) + s[3]);
  }
  panels.forEach((p, k) => {
    const scale = Math.min((pw - 40) / (zmax * 1.1), (ph - 50) / (2 * Math.max(amax, p.half) * 1.1));
    const X = (z) => k * pw + 20 + z * scale, Y = (a) => ph / 2 + 10 - a * scale;
    const o = [ox, oy, oz];
    ctx.strokeStyle = '#ccc';
    ctx.strokeRect(k * pw + 0.5, 0.5, pw - 1, ph - 1);
    ctx.fillStyle = '#333';
    ctx.fillText(p.title, k * pw + 8, 16);
    r.spheres.forEach((s, n) => {
      const cx = X(s[2] - oz), cy = Y(s[p.a] - o[p.a]);
      ctx.beginPath();
      ctx.arc(cx, cy, s[3] * scale, 0, 2 * Math.PI);
      ctx.fillStyle = n === ray.sphere ? '#cde' : '#eee';
      ctx.fill();
      ctx.strokeStyle = n === ray.sphere ? '#06c' : '#888';
      ctx.lineWidth = n === ray.sphere ? 2 : 1;
      ctx.stroke();
      ctx.lineWidth = 1;
      if (n === ray.sphere) {
        ctx.fillStyle = '#036';
        ctx.fillText(String(n + 1), cx - 4, cy + 4);
      }
    });
    ctx.strokeStyle = '#06c';
    ctx.lineWidth = 2;
    ctx.beginPath();
    ctx.moveTo(X(1), Y(-p.half));
    ctx.lineTo(X(1), Y(p.half));
    ctx.stroke();
    ctx.lineWidth = 1;
    ctx.strokeStyle = ray.hit ? '#c00' : '#e90';
    ctx.beginPath();
    ctx.moveTo(X(0), Y(0));
    ctx.lineTo(X(reach * ray.d[2]), Y(reach * ray.d[p.a]));
    ctx.stroke();
    ctx.fillStyle = '#000';
    ctx.fillRect(X(0) - 3, Y(0) - 3, 6, 6);
    if (ray.hit) {
      ctx.fillStyle = '#c00';
      ctx.beginPath();
      ctx.arc(X(ray.t * ray.d[2]), Y(ray.t * ray.d[p.a]), 4, 0, 2 * Math.PI);
      ctx.fill();
    }
  });
  const n = (v) => v.toFixed(4), k = ray.sphere + 1, s = r.spheres[ray.sphere];
  const lines = [
    `${t('pixel')} (i, j) = (${i}, ${j})`,
    `x = i − ⌊w/2⌋ = ${x},  y = ⌊h/2⌋ − j = ${y},  z = w / (2 tan(fov/2)) = ${f.toFixed(2)}`,
    `d = (x, y, z) / |(x, y, z)| = (${ray.d.map(n).join(', ')})`,
    `${t('sphereIs')(k)}: C = (${s.slice(0, 3).join(', ')}), R = ${s[3]}`,
    `L = C − O;  β = L · d = ${n(ray.beta)};  δ = β² − L · L + R² = ${n(ray.delta)}`,
    ray.hit ? t('hits')(k, n(ray.t)) : ray.delta >= 0 ? t('behind')(k) : t('misses')(k),
  ];
  if (!ray.hit && r.spheres.length > 1) lines.push(t('noneHit'));
  $('ray').textContent = lines.join('\n');
}

function pointAt(event) {
  if (!state.rendered) return;
  const canvas = $('canvas'), box = canvas.getBoundingClientRect();
  const i = Math.floor((event.clientX - box.left) / box.width * canvas.width);
  const j = Math.floor((event.clientY - box.top) / box.height * canvas.height);
  if (i < 0 || j < 0 || i >= canvas.width || j >= canvas.height) return;
  state.pixel = [i, j];
  drawRay();
}

function wire() {
  $('lang').addEventListener('click', () => {
    lang = lang === 'es' ? 'en' : 'es';
    localStorage.setItem('rayo-lang', lang);
    if (rayo) rayo.setLang(lang);
    applyLang();
    if (state.image) guarded(compare); // the report in the new language
  });
  $('image-input').addEventListener('change', (e) => {
    if (e.target.files[0]) openFile(e.target.files[0]);
  });
  const drop = $('drop');
  for (const target of [document.body]) {
    target.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
    target.addEventListener('dragleave', () => drop.classList.remove('over'));
    target.addEventListener('drop', (e) => {
      e.preventDefault();
      drop.classList.remove('over');
      if (e.dataTransfer.files[0]) openFile(e.dataTransfer.files[0]);
    });
  }
  $('zoom').addEventListener('change', applyZoom);
  window.addEventListener('resize', () => { if ($('zoom').value === 'fit') applyZoom(); });
  $('save').addEventListener('click', () => {
    $('canvas').toBlob((blob) => {
      const a = document.createElement('a');
      a.href = URL.createObjectURL(blob);
      a.download = state.name.replace(/\.[^.]*$/, '') + '.png';
      a.click();
      setTimeout(() => URL.revokeObjectURL(a.href), 1000);
    }, 'image/png');
  });
  $('reference').addEventListener('change', () => {
    const file = $('reference').value === 'file';
    $('reference-input').hidden = !file;
    if (file) $('reference-input').focus();
    guarded(compare);
  });
  $('reference-input').addEventListener('change', (e) => {
    const f = e.target.files[0];
    if (!f) return;
    guarded(async () => {
      const bytes = new Uint8Array(await f.arrayBuffer());
      const image = await decode(bytes, f.name, false);
      if (references.file) references.file.free();
      references.file = image;
      referenceNames.file = f.name;
      await compare();
    }, clearCompare);
  });
  $('scene').addEventListener('change', () => { resetScene(); renderSoon(); });
  $('render').addEventListener('click', render);
  $('reset').addEventListener('click', () => { resetScene(); renderSoon(); });
  document.querySelector('#render-section').addEventListener('input', (e) => {
    if (e.target.tagName === 'INPUT' && e.target.value !== '') renderSoon();
  });
  const canvas = $('canvas');
  canvas.addEventListener('pointermove', pointAt);
  canvas.addEventListener('pointerdown', pointAt);
  canvas.addEventListener('keydown', (e) => {
    const moves = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
    if (!state.rendered || !moves[e.key]) return;
    e.preventDefault();
    const step = e.shiftKey ? 10 : 1, [di, dj] = moves[e.key];
    const p = state.pixel || [0, 0];
    state.pixel = [Math.min(canvas.width - 1, Math.max(0, p[0] + di * step)),
                   Math.min(canvas.height - 1, Math.max(0, p[1] + dj * step))];
    drawRay();
  });
}

async function start() {
  wire();
  applyLang();
  try {
    rayo = await RayoWeb.loadRayo(bytesOf(window.RAYO_ASSETS.wasm));
    rayo.setLang(lang);
    readCourses();
  } catch (e) {
    showError(`rayo: ${e.message}`);
    return;
  }
  // A module started again after a failure holds none of the images.
  rayo.onRestart = () => {
    state.image = null;
    state.rendered = null;
    for (const key of Object.keys(references)) delete references[key];
    forget();
  };
  resetScene();
  times.load = performance.now();
  document.body.dataset.ready = '1';
}
start();
})();
