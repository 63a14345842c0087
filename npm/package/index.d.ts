// flipcheck: bookspin's conformance kit for a free rigid body's motion (index.mjs).

/** A scenario as `bookspin flipcheck export` writes it (OUT/<scenario>.json). */
export interface Scenario {
  scenario: string;
  units: Record<string, string>;
  mass: number;
  /** about body x, y, z (mass · length²) */
  principal_moments: [number, number, number];
  principal_axes: string;
  /** w, x, y, z, body → world: the identity */
  q0: [number, number, number, number];
  q_convention: string;
  /** rad per time unit, the jiggle included */
  omega0_body: [number, number, number];
  omega0_world: [number, number, number];
  dt: number;
  steps: number;
  gravity: string;
  exact_motion: string;
}

/** The exact motion at every step n = 0 … steps, row-major. */
export interface ExactMotion {
  t: Float64Array; // N
  q: Float64Array; // N×4, w, x, y, z, body → world, w ≥ 0
  omegaBody: Float64Array; // N×3
  omegaWorld: Float64Array; // N×3
  L: Float64Array; // N×3, world frame
  E: Float64Array; // N
}

type Numbers = Float64Array | ArrayLike<number> | ArrayLike<ArrayLike<number>>;

/** A motion: t (N), q (N×4: w, x, y, z, body → world), omegaWorld (N×3, rad per time unit). */
export interface Motion {
  t: Numbers;
  q: Numbers;
  omegaWorld: Numbers;
}

/** The judgement CSV's row (bookspin's docs/flipcheck.md, "The judgement CSV"), and the verdict. */
export interface Judgement {
  scenario: string;
  motion: string;
  verdict: "pass" | "fail";
  stride: number;
  last_step: number;
  start_error: number | null;
  energy_drift: number | null;
  L_drift: number | null;
  flips: number;
  flips_exact: number;
  first_flip: number | null;
  first_flip_exact: number | null;
  first_flip_error: number | null;
  orientation_error: number | null;
  stable_spin: number;
  tumble_time: number | null;
  separatrix_ratio_drift: number | null;
  separatrix_approach: number | null;
  /** "; " between reasons, "" for a pass */
  failures: string;
  /** bookspin's version that judged (this package's `version`) */
  version: string;
  /** SHA-256 (hex) of the scenario's JSON as `bookspin flipcheck export` writes it */
  scenario_sha256: string;
  pass: boolean;
  /** the failures, one phrase each */
  reasons: string[];
  /** the line `bookspin flipcheck judge` prints: "PASS: …" or "FAIL (reasons): …" */
  line: string;
}

/** A scenario's name, or a scenario JSON export wrote. */
export type ScenarioArg = string | Scenario;

/** bookspin's version: package.json's, `bookspin --version`'s, every judgement's. */
export const version: string;
export function scenarios(): string[];
export function scenarioSha256(name: ScenarioArg): string;
export function scenario(name: string): Scenario;
/** A scenario JSON file's text read as `bookspin flipcheck judge` reads it (`file` names it in
 * messages): its scenario, which every function here takes; throws the command line's one line
 * for a file that is no scenario. */
export function readScenario(text: string, file?: string): Scenario;
export function exactMotion(name: ScenarioArg): ExactMotion;
export function exportFiles(name: ScenarioArg): { json: string; csv: string };
export function judge(name: ScenarioArg, motion: Motion, options?: { motion?: string }): Judgement;
export function judgeCsv(name: ScenarioArg, text: string | Uint8Array, options?: { file?: string; motion?: string }): Judgement;
/** judge() (or judgeCsv() for a CSV's text) that throws node's assert.AssertionError with
 * "SCENARIO MOTION: FAIL (reasons): …" when the motion fails, and returns the judgement when it
 * passes: `npx flipcheck judge`'s exit status 3, in a test runner. */
export function assertPasses(name: ScenarioArg, motion: Motion | string, options?: { motion?: string; file?: string }): Judgement;
