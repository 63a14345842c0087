// The page's JavaScript engines (cannon-es, Rapier, Jolt, Havok), bundled on their own (web/build.sh: explorer-engines.bundle.js)
// and written into the page only by `bookspin explore --engines`: they set
// window.BOOKSPIN_ENGINES, the adapters of engine.js that the page offers as models, in the order
// of models.js.
import { cannon } from './cannon.js';
import { rapier } from './rapier.js';
import { jolt, joltGyroscopic } from './jolt.js';
import { havok } from './havok.js';
// Havok's WebAssembly as bytes, inlined by esbuild's binary loader (web/build.sh), so that it
// loads from file:// with no fetch.
import havokWasm from '@babylonjs/havok/lib/esm/HavokPhysics.wasm';

havok.wasmBinary = havokWasm;
window.BOOKSPIN_ENGINES = [cannon, rapier, jolt, joltGyroscopic, havok];
