// rayo.js - loads rayo.wasm (the library compiled to WebAssembly, web/wasm/)
// and wraps the functions it exports (web/wasm/web_api.c) so the page can
// call them with JavaScript values.  It only moves bytes: every reading,
// rendering and comparing is the library's.  The module needs the few
// WASI calls wasi-libc makes; it has no files, so they answer "bad file"
// (EBADF), its environment is empty (the library reads RAYO_WALK and
// RAYO_PACKETS from it: docs/geometry.md), and the clock is the
// browser's.  A classic script, not a
// module, so that the page also works opened from file://: the module's
// bytes come from assets.js (made by `make web`), not from a fetch.
//
// A call that traps (WebAssembly.RuntimeError: "unreachable", "memory
// access out of bounds") may leave the module's heap half updated, so
// the module is then dropped and instantiated again from the compiled
// code (rayo.ready settles when it is back); the call throws a RayoError
// saying so, and images made before are stale (their calls throw, their
// free does nothing; onRestart lets the page forget them).  Memory the
// module cannot give (web_alloc returning 0) is a RayoError too, never a
// write at address 0.
'use strict';
(function (global) {
const EBADF = 8;

// The imports of one instance; memory is set once it exists.
function imports() {
  let memory = null;
  const wasi = {
    clock_time_get(id, precision, out) {
      const ns = BigInt(Math.round(performance.now() * 1e6));
      new DataView(memory.buffer).setBigUint64(out, ns, true);
      return 0;
    },
    environ_sizes_get(count, size) {
      const view = new DataView(memory.buffer);
      view.setUint32(count, 0, true);
      view.setUint32(size, 0, true);
      return 0;
    },
    environ_get: () => 0,
    fd_close: () => EBADF,
    fd_read: () => EBADF,
    fd_seek: () => EBADF,
    fd_write: () => EBADF,
    proc_exit(code) {
      throw new Error(`rayo.wasm exited with status ${code}`);
    },
    sched_yield: () => 0,
  };
  return {
    object: { wasi_snapshot_preview1: wasi },
    bind(instance) { memory = instance.exports.memory; },
  };
}

async function instantiate(module) {
  const im = imports();
  const instance = await WebAssembly.instantiate(module, im.object);
  im.bind(instance);
  return instance;
}

async function loadRayo(bytes) {
  const module = await WebAssembly.compile(bytes);
  return new Rayo(module, await instantiate(module));
}

const decoder = new TextDecoder();
const encoder = new TextEncoder();

class RayoError extends Error {}

class Rayo {
  constructor(module, instance) {
    this.module = module;
    this.generation = 0;
    this.ready = Promise.resolve();
    this.onRestart = null;
    this.bind(instance);
  }
  // this.x: the exports, each call guarded against traps.
  bind(instance) {
    const raw = instance.exports, x = { memory: raw.memory };
    for (const [name, fn] of Object.entries(raw))
      if (typeof fn === 'function') x[name] = (...args) => this.call(fn, args);
    this.x = x;
  }
  call(fn, args) {
    if (this.restarting)
      throw new RayoError('rayo: the page is starting its module again; try once more');
    try {
      return fn(...args);
    } catch (e) {
      if (!(e instanceof WebAssembly.RuntimeError)) throw e;
      this.restart();
      throw new RayoError(`rayo: the page's module failed (${e.message}) and was started again; open the images again`);
    }
  }
  restart() {
    this.restarting = true;
    this.generation++;
    this.ready = instantiate(this.module).then((instance) => {
      this.bind(instance);
      this.restarting = false;
      if (this.lang) this.setLang(this.lang);
      if (this.onRestart) this.onRestart();
    });
  }
  // The language of the module's error lines ('es' or 'en'), kept across
  // a restart.
  setLang(lang) {
    this.lang = lang;
    this.x.web_set_lang(lang === 'es' ? 1 : 0);
  }
  // width x height, a file named name, fits the page (else a RayoError).
  sizeCheck(name, width, height) {
    const nm = this.put(name);
    const status = this.x.web_size_check(nm, width, height);
    this.x.web_free(nm);
    if (status !== 0) this.fail();
  }
  get heap() {
    return new Uint8Array(this.x.memory.buffer);
  }
  string(ptr) {
    const heap = this.heap;
    let end = ptr;
    while (heap[end] !== 0) end++;
    return decoder.decode(heap.subarray(ptr, end));
  }
  // Copies bytes (a Uint8Array or a string) into the module: a pointer
  // to free with this.x.web_free.
  put(bytes) {
    if (typeof bytes === 'string') bytes = encoder.encode(bytes + '\0');
    const ptr = this.alloc(bytes.length);
    this.heap.set(bytes, ptr);
    return ptr;
  }
  alloc(size) {
    const ptr = this.x.web_alloc(size);
    if (!ptr)
      throw new RayoError(`rayo: out of memory: the page cannot hold ${size} bytes more`);
    return ptr;
  }
  putDoubles(values) {
    const ptr = this.alloc(values.length * 8);
    new Float64Array(this.x.memory.buffer, ptr, values.length).set(values);
    return ptr;
  }
  fail() {
    throw new RayoError(this.string(this.x.web_error()));
  }
  // A PBM, PGM or PPM file's bytes as an image; null when they are a PNG
  // (the browser decodes those: fromPNG).  clamp: read as `rayo compare`
  // reads the image it checks.
  read(bytes, name, clamp) {
    const data = this.put(bytes);
    let nm;
    try {
      nm = this.put(name);
    } catch (e) {
      this.x.web_free(data);
      throw e;
    }
    const image = this.x.web_read(data, bytes.length, nm, clamp ? 1 : 0);
    this.x.web_free(data);
    this.x.web_free(nm);
    if (image) return new RayoImage(this, image);
    if (this.x.web_error_is_png()) return null;
    return this.fail();
  }
  // A PNG file (its bytes) decoded by the browser to RGBA (ImageData).
  fromPNG(bytes, imageData) {
    const png = this.put(bytes);
    let rgba;
    try {
      rgba = this.put(imageData.data);
    } catch (e) {
      this.x.web_free(png);
      throw e;
    }
    const image = this.x.web_from_png(png, bytes.length, rgba,
                                      imageData.width, imageData.height);
    this.x.web_free(png);
    this.x.web_free(rgba);
    return image ? new RayoImage(this, image) : this.fail();
  }
  // `rayo compare reference image`: its text, verdict, diagnosis and the
  // difference picture (PNG bytes).  course: the exercise (0, 1, 2) whose
  // image the reference is, or -1 for a file; lang: 'es' for the report in
  // Spanish (`rayo compare --lang es`), else English.
  compare(reference, image, course = -1, lang = 'en') {
    reference.live();
    image.live();
    const text = this.x.web_compare(reference.ptr, image.ptr, course, lang === 'es' ? 1 : 0);
    if (!text) this.fail();
    const diff = this.x.web_compare_diff();
    const size = this.x.web_compare_diff_size();
    return {
      text: this.string(text),
      verdict: this.string(this.x.web_compare_verdict()),
      diagnosis: this.string(this.x.web_compare_diagnosis()),
      diff: diff ? this.heap.slice(diff, diff + size) : null,
    };
  }
  // The spheres of a scene (-1 the seed, 0..2 the course's), [cx, cy, cz, r].
  spheres(scene) {
    const out = this.alloc(32), list = [];
    const n = this.x.web_scene_spheres(scene, 0, out);
    for (let i = 0; i < n; i++) {
      this.x.web_scene_spheres(scene, i, out);
      list.push(Array.from(new Float64Array(this.x.memory.buffer, out, 4)));
    }
    this.x.web_free(out);
    return list;
  }
  // camera: [width, height, fov, ox, oy, oz]; spheres as spheres() gives.
  render(scene, camera, spheres) {
    const cam = this.putDoubles(camera), sp = this.putDoubles(spheres.flat());
    const image = this.x.web_render(scene, cam, sp, spheres.length);
    this.x.web_free(cam);
    this.x.web_free(sp);
    return image ? new RayoImage(this, image) : this.fail();
  }
  // The ray through pixel (px, py): d, hit, t (the nearest hit), focal,
  // and beta and delta of the sphere they explain (index sphere, from 0:
  // the one hit nearest, else the first).
  ray(camera, spheres, px, py) {
    const cam = this.putDoubles(camera), sp = this.putDoubles(spheres.flat());
    const out = this.alloc(72);
    const status = this.x.web_ray(cam, sp, spheres.length, px, py, out);
    const v = Array.from(new Float64Array(this.x.memory.buffer, out, 9));
    this.x.web_free(cam);
    this.x.web_free(sp);
    this.x.web_free(out);
    if (status !== 0) return null;
    return { d: v.slice(0, 3), beta: v[3], delta: v[4], hit: v[5] === 1,
             t: v[6], focal: v[7], sphere: v[8] };
  }
}

const FORMATS = ['PBM', 'PGM', 'PPM', 'PNG'];

class RayoImage {
  constructor(rayo, ptr) {
    this.rayo = rayo;
    this.ptr = ptr;
    this.generation = rayo.generation;
    const info = (k) => rayo.x.web_info(ptr, k);
    this.width = info(0);
    this.height = info(1);
    this.channels = info(2);
    this.maxval = info(3);
    this.bilevel = info(4) === 0;
    this.format = FORMATS[info(5)];
    this.plain = info(6) === 1;
  }
  // Throws when the module was started again since this image was made.
  live() {
    if (this.generation !== this.rayo.generation || !this.ptr)
      throw new RayoError('rayo: this image was lost when the page started its module again; open it again');
  }
  imageData() {
    this.live();
    const ptr = this.rayo.x.web_rgba(this.ptr);
    if (!ptr) this.rayo.fail();
    const n = this.width * this.height * 4;
    const rgba = new Uint8ClampedArray(this.rayo.x.memory.buffer, ptr, n);
    return new ImageData(new Uint8ClampedArray(rgba), this.width, this.height);
  }
  free() {
    if (this.ptr && this.generation === this.rayo.generation && !this.rayo.restarting)
      this.rayo.x.web_image_free(this.ptr);
    this.ptr = 0;
  }
}

global.RayoWeb = { loadRayo, Rayo, RayoImage, RayoError };
})(typeof window !== 'undefined' ? window : globalThis);
