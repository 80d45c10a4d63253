// replay_wasm.mjs - the fuzz targets that reach the page's module
// (fuzz/fuzz_reader.c, fuzz/fuzz_scene.c) replayed as WebAssembly, so
// that the library's size arithmetic runs with the module's 32-bit
// size_t: each input of fuzz/corpus/NAME and fuzz/regression/NAME once,
// through fuzz/replay.c built for wasm32-wasi (`make check-web` builds
// them as build/wasm/fuzz/replay-NAME.wasm and runs this with their
// paths; TAP on stdout).  A broken promise aborts, which traps here; the
// native replays (tests/cli/fuzz_replay.t) check the same inputs with
// 64 bits.  Not a fuzzer: libFuzzer does not target WebAssembly.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { WASI } from 'node:wasi';

const SOURCE = process.env.RAYO_SOURCE || process.cwd();
const files = process.argv.slice(2);
let count = 0, failed = 0;
function ok(cond, name, detail) {
  count++;
  if (!cond) failed++;
  console.log(`${cond ? 'ok' : 'not ok'} ${count} - ${name}`);
  if (!cond && detail) for (const l of String(detail).split('\n')) console.log(`#   ${l}`);
}

console.log(`1..${2 * files.length}`);
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'rayo-wasm-fuzz-'));
for (const file of files) {
  const name = path.basename(file).replace(/^replay-(.*)\.wasm$/, '$1');
  const inputs = ['corpus', 'regression'].map((d) => `/src/fuzz/${d}/${name}`)
    .filter((d) => fs.existsSync(path.join(SOURCE, d.slice(5))));
  const wasi = new WASI({
    version: 'preview1',
    args: ['replay', '--count-to', '/out/count', ...inputs],
    preopens: { '/src': SOURCE, '/out': tmp },
    returnOnExit: true,
    stdout: fs.openSync('/dev/null', 'w'),
    stderr: fs.openSync('/dev/null', 'w'),
  });
  let status, error = '';
  try {
    const module = await WebAssembly.compile(fs.readFileSync(file));
    const instance = await WebAssembly.instantiate(module, wasi.getImportObject());
    status = wasi.start(instance);
  } catch (e) {
    error = String(e);
  }
  ok(status === 0, `${name}: every input replayed in wasm32 without a trap`, error || `status ${status}`);
  const said = fs.existsSync(path.join(tmp, 'count')) ?
    fs.readFileSync(path.join(tmp, 'count'), 'utf8').trim() : '';
  const n = Number((said.match(/^replayed (\d+) files$/) || [])[1] || 0);
  ok(n > 0, `${name}: ${said || 'nothing replayed'}`);
  fs.rmSync(path.join(tmp, 'count'), { force: true });
}
fs.rmSync(tmp, { recursive: true, force: true });
process.exitCode = failed ? 1 : 0;
