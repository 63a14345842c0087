// What the page carries packed, and its loading: the physics' WebAssembly (web/make_explorer.py)
// and, in a page written with `bookspin explore --engines`, the JavaScript engines' bundle
// (web/pack_engines.py), each as base64 of a gzip stream that the browser's own
// DecompressionStream inflates as the page starts: the page stays one file that opens from disk
// with no network request, at a third of the size (docs/explorer.md, "The page").

/** The bytes of base64 `text` holding a gzip stream, inflated: a promise of a Uint8Array. */
export async function inflate(text) {
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

/** base64 of `bytes`, in pieces (String.fromCharCode takes a bounded number of arguments). */
function toBase64(bytes) {
  let binary = '';
  for (let i = 0; i < bytes.length; i += 0x8000)
    binary += String.fromCharCode.apply(null, bytes.subarray(i, i + 0x8000));
  return btoa(binary);
}

/** The engines' bundle unpacked and run (web/pack_engines.py: a 4-byte little-endian header
 * length, the JSON header {code, blobs}, the code, then each WebAssembly blob, whose base64 goes
 * back in place of BOOKSPIN_BLOB_<i>): a promise of its adapters, window.BOOKSPIN_ENGINES. */
async function unpackEngines(text) {
  const all = await inflate(text);
  const length = new DataView(all.buffer, all.byteOffset).getUint32(0, true);
  const header = JSON.parse(new TextDecoder().decode(all.subarray(4, 4 + length)));
  let at = 4 + length;
  let code = new TextDecoder().decode(all.subarray(at, at + header.code));
  at += header.code;
  header.blobs.forEach((size, i) => {
    const blob = all.subarray(at, at + size);
    code = code.replace(`BOOKSPIN_BLOB_${i}`, () => toBase64(blob));
    at += size;
  });
  (0, eval)(code);  // the bundle's IIFE sets window.BOOKSPIN_ENGINES
  return window.BOOKSPIN_ENGINES || [];
}

/** A promise of the physics' WebAssembly bytes, inflated afresh (a Uint8Array of its own, for
 * the lab's fit worker: fit_worker.js); null where the page carries it unpacked (the module
 * then reads its own inlined copy). */
export function physicsBytes() {
  const packedWasm = window.BOOKSPIN_WASM_PACKED;
  return packedWasm ? inflate(packedWasm) : Promise.resolve(null);
}

/** A promise of [the WebAssembly module (BookspinPhysics), the engines' adapters, loaded]: an
 * engine that fails to load is left out, with a warning; [] without --engines. */
export function loadProgram() {
  const packedWasm = window.BOOKSPIN_WASM_PACKED;
  const physics = packedWasm
    ? inflate(packedWasm).then((wasmBinary) => BookspinPhysics({ wasmBinary }))
    : BookspinPhysics();
  const packedEngines = window.BOOKSPIN_ENGINES_PACKED;
  const engines = (packedEngines ? unpackEngines(packedEngines) : Promise.resolve(window.BOOKSPIN_ENGINES || []))
    .then((list) => Promise.all(list.map((e) => e.load().then(() => e, (err) => {
      console.warn(`${e.label}: not loaded: ${err}`);
      return null;
    }))))
    .then((loaded) => loaded.filter(Boolean));
  return Promise.all([physics, engines]);
}
