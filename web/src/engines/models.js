// The names of the JavaScript engines' models (the adapters of this folder, engine.js): the one
// list of them. The adapters take their `model` from here, and so does the page's state
// (state.js), which must know them in a page written without `--engines` too, where a link may
// still name one (the page then says how to get the engines). Only names here: this module is
// in the page's own bundle, the engines' packages are not.
export const ENGINE_MODEL = {
  cannon: 'cannon-es',
  rapier: 'rapier',
  jolt: 'jolt',
  joltGyroscopic: 'jolt-gyroscopic',
  havok: 'havok',
};

/** Every engine's model, in the order the page offers them (index.js). */
export const ENGINE_MODELS = Object.values(ENGINE_MODEL);

/** The engines that integrate ω with the torque alone, without the gyroscopic term ω × Iω: a
 * free body keeps ω fixed in the world and never turns over (docs/explorer.md, JavaScript
 * engines). The page says so beside their name. */
export const WITHOUT_GYROSCOPIC_TERM = [ENGINE_MODEL.cannon, ENGINE_MODEL.jolt, ENGINE_MODEL.havok];

/** The engines run only under node by web/flipcheck-engines.mjs (not offered in the page):
 * their motion files' names. */
export const NODE_ENGINE_MODEL = {
  ammo: 'ammo',
  oimo: 'oimo',
  mujoco: { euler: 'mujoco-js-euler', rk4: 'mujoco-js-rk4', implicit: 'mujoco-js-implicit',
    implicitfast: 'mujoco-js-implicitfast' },
};
