// The page's JavaScript engines, bundled on their own (web/build.sh: explorer-engines.bundle.js)
// and written into the page only by `bookspin explore --engines`: they set
// window.BOOKSPIN_ENGINES, the adapters of engine.js that the page offers as models, in the order
// of models.js.
import { cannon } from './cannon.js';
import { rapier } from './rapier.js';
import { jolt, joltGyroscopic } from './jolt.js';

window.BOOKSPIN_ENGINES = [cannon, rapier, jolt, joltGyroscopic];
