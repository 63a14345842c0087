// Text the page hands to its WebAssembly module, checked first (docs/explorer.md, "Tests"): a
// lone surrogate (U+D800 … U+DFFF without its other half, which no UTF-8 holds) is refused naming
// the field it came from, in the words of every other door (the command line cannot be given
// one; Python's python/scene_input.cpp unicode_arg says this line). Unchecked, emscripten's UTF-8
// encoder took it and the character after it as one pair: the name "m\ud800x" reached the module
// as "m\u{10078}", the "x" eaten. One module for both WebAssembly doors: npm/build.sh copies this
// file into the npm package, whose index.mjs checks its every text with it. (Node 18, which the
// package supports, lacks String.prototype.isWellFormed, and that says no more than yes or no.)

const LONE = /[\uD800-\uDBFF](?![\uDC00-\uDFFF])|(?<![\uD800-\uDBFF])[\uDC00-\uDFFF]/;

/** Why `text` cannot reach the module, named as `argument` ("your name", "flights by hand"):
 * `ARGUMENT: "TEXT" holds a lone surrogate (U+D800) at character N: no UTF-8 text holds one`, the
 * text as JSON.stringify writes it and the character counted in code points (a pair is one, as
 * Python counts them); '' for anything else (a value that is no string included). */
export function loneSurrogateProblem(text, argument) {
  if (typeof text !== 'string') return '';
  const at = text.search(LONE);
  if (at < 0) return '';
  const code = text.charCodeAt(at).toString(16).toUpperCase();
  return `${argument}: ${JSON.stringify(text)} holds a lone surrogate (U+${code}) at character ` +
    `${[...text.slice(0, at)].length + 1}: no UTF-8 text holds one`;
}

/** `text` itself, or an Error with loneSurrogateProblem's line. */
export function wellFormed(text, argument) {
  const problem = loneSurrogateProblem(text, argument);
  if (problem) throw new Error(problem);
  return text;
}

/** The first lone surrogate in any string of `args` (a call's arguments: strings, arrays and
 * plain objects within them, as the lab's [{name, bytes, meta}]), named `method`'s argument
 * by its place ("fitRecordings: argument 1[0].name"); '' where there is none. The module's one
 * door (fit_worker.js) asks this of every call, so that no field left unchecked is joined. */
export function loneSurrogateInArguments(method, args) {
  const walk = (value, place) => {
    if (typeof value === 'string') return loneSurrogateProblem(value, place);
    if (Array.isArray(value)) {
      for (let k = 0; k < value.length; ++k) {
        const problem = walk(value[k], `${place}[${k}]`);
        if (problem) return problem;
      }
    } else if (value && Object.getPrototypeOf(value) === Object.prototype) {
      for (const [key, v] of Object.entries(value)) {
        const problem = walk(v, `${place}.${key}`);
        if (problem) return problem;
      }
    }
    return '';
  };
  for (let k = 0; k < args.length; ++k) {
    const problem = walk(args[k], `${method}: argument ${k + 1}`);
    if (problem) return problem;
  }
  return '';
}
