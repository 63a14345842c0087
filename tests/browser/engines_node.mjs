// The JavaScript engines of the explorer page run under node, written here apart from the page's
// adapters (web/src/engines/), as each package's documentation sets up a free body: the reference
// of tests/browser/explorer_engines_test.py. One rigid body with the given mass and principal
// moments (set explicitly, never a shape's), no gravity, no damping, no sleeping, `steps` steps
// of `dt` from body-frame ω0 at the identity; prints ω in the body frame at the end (Rᵀ·ω_world,
// R from the engine's quaternion) as JSON, one line.
// Usage: node engines_node.mjs NODE_MODULES ENGINE JSON
//   ENGINE: cannon-es | rapier | jolt | jolt-gyroscopic | havok
//   JSON: {"mass": m, "moments": [Ix, Iy, Iz], "size": [a, b, c], "omega0": [x, y, z],
//          "dt": dt, "steps": n}
import { createRequire } from 'node:module';
import { join, resolve as resolvePath } from 'node:path';
import { pathToFileURL } from 'node:url';

const [modules, engine, json] = process.argv.slice(2);
const spec = JSON.parse(json);
const resolve = createRequire(join(resolvePath(modules), 'resolve-from-here.js')).resolve;
const load = async (name) => import(pathToFileURL(resolve(name)).href);
const [Ix, Iy, Iz] = spec.moments;
const [w0x, w0y, w0z] = spec.omega0;
const [a, b, c] = spec.size;

/** [q (w, x, y, z), ω world] after the run. */
async function runCannon() {
  const CANNON = await load('cannon-es');
  const world = new CANNON.World();
  world.gravity.set(0, 0, 0);
  world.allowSleep = false;
  const box = new CANNON.Body({ mass: spec.mass, shape: new CANNON.Box(new CANNON.Vec3(a / 2, b / 2, c / 2)) });
  box.linearDamping = 0;
  box.angularDamping = 0;
  box.allowSleep = false;
  box.inertia = new CANNON.Vec3(Ix, Iy, Iz);
  box.invInertia = new CANNON.Vec3(1 / Ix, 1 / Iy, 1 / Iz);
  box.updateInertiaWorld(true);
  box.angularVelocity = new CANNON.Vec3(w0x, w0y, w0z);
  world.addBody(box);
  for (let i = 0; i < spec.steps; ++i) world.step(spec.dt);
  const q = box.quaternion, w = box.angularVelocity;
  return [[q.w, q.x, q.y, q.z], [w.x, w.y, w.z]];
}

async function runRapier() {
  const module = await load('@dimforge/rapier3d-compat');
  const R = module.default ?? module;
  await R.init();
  const world = new R.World(new R.Vector3(0, 0, 0));
  world.integrationParameters.dt = spec.dt;
  const desc = new R.RigidBodyDesc(R.RigidBodyType.Dynamic);
  desc.setAdditionalMassProperties(spec.mass, new R.Vector3(0, 0, 0), new R.Vector3(Ix, Iy, Iz),
    new R.Quaternion(0, 0, 0, 1));
  desc.setAngvel(new R.Vector3(w0x, w0y, w0z));
  desc.setLinearDamping(0);
  desc.setAngularDamping(0);
  desc.setCanSleep(false);
  desc.setGravityScale(0);
  const body = world.createRigidBody(desc);
  for (let i = 0; i < spec.steps; ++i) world.step();
  const q = body.rotation(), w = body.angvel();
  return [[q.w, q.x, q.y, q.z], [w.x, w.y, w.z]];
}

async function runJolt(gyroscopic) {
  const Jolt = await (await load('jolt-physics')).default();
  const settings = new Jolt.JoltSettings();
  const objectFilter = new Jolt.ObjectLayerPairFilterTable(1);
  const broadPhase = new Jolt.BroadPhaseLayerInterfaceTable(1, 1);
  broadPhase.MapObjectToBroadPhaseLayer(0, new Jolt.BroadPhaseLayer(0));
  settings.mObjectLayerPairFilter = objectFilter;
  settings.mBroadPhaseLayerInterface = broadPhase;
  settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(broadPhase, 1, objectFilter, 1);
  const jolt = new Jolt.JoltInterface(settings);
  const system = jolt.GetPhysicsSystem();
  system.SetGravity(new Jolt.Vec3(0, 0, 0));
  const shape = new Jolt.BoxShape(new Jolt.Vec3(a / 2, b / 2, c / 2), 0.05 * Math.min(a, b, c), null);
  const settingsBody = new Jolt.BodyCreationSettings(shape, new Jolt.RVec3(0, 0, 0), Jolt.Quat.prototype.sIdentity(),
    Jolt.EMotionType_Dynamic, 0);
  settingsBody.mOverrideMassProperties = Jolt.EOverrideMassProperties_MassAndInertiaProvided;
  const mass = settingsBody.mMassPropertiesOverride;
  mass.mMass = spec.mass;
  const inertia = Jolt.Mat44.prototype.sIdentity();
  inertia.SetAxisX(new Jolt.Vec3(Ix, 0, 0));
  inertia.SetAxisY(new Jolt.Vec3(0, Iy, 0));
  inertia.SetAxisZ(new Jolt.Vec3(0, 0, Iz));
  mass.mInertia = inertia;
  settingsBody.mMassPropertiesOverride = mass;
  settingsBody.mLinearDamping = 0;
  settingsBody.mAngularDamping = 0;
  settingsBody.mGravityFactor = 0;
  settingsBody.mAllowSleeping = false;
  settingsBody.mMaxAngularVelocity = 1e30;
  settingsBody.mApplyGyroscopicForce = gyroscopic;
  settingsBody.mAngularVelocity = new Jolt.Vec3(w0x, w0y, w0z);
  const bodies = system.GetBodyInterface();
  const body = bodies.CreateBody(settingsBody);
  bodies.AddBody(body.GetID(), Jolt.EActivation_Activate);
  for (let i = 0; i < spec.steps; ++i) jolt.Step(spec.dt, 1);
  const q = body.GetRotation(), w = body.GetAngularVelocity();
  return [[q.GetW(), q.GetX(), q.GetY(), q.GetZ()], [w.GetX(), w.GetY(), w.GetZ()]];
}

async function runHavok() {
  const { readFileSync } = await import('node:fs');
  const { dirname } = await import('node:path');
  const main = resolve('@babylonjs/havok');  // lib/umd/HavokPhysics_umd.js
  const wasmBinary = readFileSync(join(dirname(main), 'HavokPhysics.wasm'));
  const module = await import(pathToFileURL(main).href);
  const HK = await (module.default ?? module)({ wasmBinary });
  const world = HK.HP_World_Create()[1];
  HK.HP_World_SetGravity(world, [0, 0, 0]);
  HK.HP_World_SetIdealStepTime(world, 0);
  HK.HP_World_SetSpeedLimit(world, 1e30, 1e30);
  const body = HK.HP_Body_Create()[1];
  HK.HP_Body_SetShape(body, HK.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [a, b, c])[1]);
  HK.HP_Body_SetMotionType(body, HK.MotionType.DYNAMIC);
  // Havok's inertia is per unit mass.
  HK.HP_Body_SetMassProperties(body, [[0, 0, 0], spec.mass, [Ix / spec.mass, Iy / spec.mass, Iz / spec.mass],
    [0, 0, 0, 1]]);
  HK.HP_Body_SetLinearDamping(body, 0);
  HK.HP_Body_SetAngularDamping(body, 0);
  HK.HP_Body_SetGravityFactor(body, 0);
  HK.HP_Body_SetActivationControl(body, HK.ActivationControl.ALWAYS_ACTIVE);
  HK.HP_World_AddBody(world, body, false);
  HK.HP_Body_SetAngularVelocity(body, [w0x, w0y, w0z]);
  for (let i = 0; i < spec.steps; ++i) HK.HP_World_Step(world, spec.dt);
  const [x, y, z, w] = HK.HP_Body_GetOrientation(body)[1];
  return [[w, x, y, z], HK.HP_Body_GetAngularVelocity(body)[1]];
}

const runs = { 'cannon-es': runCannon, rapier: runRapier, jolt: () => runJolt(false),
  'jolt-gyroscopic': () => runJolt(true), havok: runHavok };
if (!runs[engine]) throw new Error(`unknown engine ${engine}`);
const [[qw, qx, qy, qz], w] = await runs[engine]();
// R of the unit quaternion (body → world); ω body = Rᵀ ω world.
const n = Math.hypot(qw, qx, qy, qz);
const [s, x, y, z] = [qw / n, qx / n, qy / n, qz / n];
const R = [
  [1 - 2 * (y * y + z * z), 2 * (x * y - s * z), 2 * (x * z + s * y)],
  [2 * (x * y + s * z), 1 - 2 * (x * x + z * z), 2 * (y * z - s * x)],
  [2 * (x * z - s * y), 2 * (y * z + s * x), 1 - 2 * (x * x + y * y)],
];
const body = [0, 1, 2].map((j) => R[0][j] * w[0] + R[1][j] * w[1] + R[2][j] * w[2]);
console.log(JSON.stringify({ engine, omega_body: body }));
