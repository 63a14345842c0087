// Havok (@babylonjs/havok: Babylon.js's physics, C++ compiled to WebAssembly) as a model of the
// page. One DYNAMIC body with a box shape in a world with no gravity; its mass properties set
// explicitly (HP_Body_SetMassProperties: centre of mass 0, the mass, the principal moments per
// unit mass, as Havok takes them, principal frame = body frame), never built from the shape;
// linear and angular damping 0 (Havok's defaults are not 0), gravity factor 0, ALWAYS_ACTIVE
// (no sleeping), the world's speed limits raised to 1e30 and its ideal step time 0 (no solver
// retuning), HP_World_Step(dt). Havok exposes no integrator or gyroscopic option: one mode.
// Its WebAssembly is given as bytes (`wasmBinary`: the node runner reads the package's file,
// the page's bundle inlines it), so it loads without a fetch, from file:// too.
import HavokPhysics from '@babylonjs/havok';
import { ENGINE_MODEL } from './models.js';

/** Havok's result codes are the first element of every call's answer, or the answer. */
function ok(H, r) {
  const code = Array.isArray(r) ? r[0] : r;
  if (code !== H.Result.RESULT_OK) throw new Error(`Havok call failed: result ${code}`);
  return Array.isArray(r) ? r.slice(1) : [];
}

export const havok = {
  model: ENGINE_MODEL.havok,
  package: '@babylonjs/havok',
  mode: '',
  label: 'Havok 1.3',
  wasmBinary: null,
  load() {
    // locateFile: the module's own lookup reads import.meta.url, which a page's bundle lacks.
    if (!this.module) this.module = HavokPhysics({ wasmBinary: this.wasmBinary, locateFile: (f) => f });
    return this.module.then((H) => { this.H = H; });
  },
  start(body, dt) {
    const H = this.H;
    const [world] = ok(H, H.HP_World_Create());
    ok(H, H.HP_World_SetGravity(world, [0, 0, 0]));
    ok(H, H.HP_World_SetSpeedLimit(world, 1e30, 1e30));
    ok(H, H.HP_World_SetIdealStepTime(world, 0));
    const [a, b, c] = body.size;
    const [shape] = ok(H, H.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [a, b, c]));
    const [rigid] = ok(H, H.HP_Body_Create());
    ok(H, H.HP_Body_SetShape(rigid, shape));
    ok(H, H.HP_Body_SetMotionType(rigid, H.MotionType.DYNAMIC));
    const [ix, iy, iz] = body.moments;
    const m = body.mass;
    ok(H, H.HP_Body_SetMassProperties(rigid, [[0, 0, 0], m, [ix / m, iy / m, iz / m], [0, 0, 0, 1]]));
    ok(H, H.HP_Body_SetLinearDamping(rigid, 0));
    ok(H, H.HP_Body_SetAngularDamping(rigid, 0));
    ok(H, H.HP_Body_SetGravityFactor(rigid, 0));
    ok(H, H.HP_Body_SetActivationControl(rigid, H.ActivationControl.ALWAYS_ACTIVE));
    ok(H, H.HP_Body_SetQTransform(rigid, [[0, 0, 0], [0, 0, 0, 1]]));
    ok(H, H.HP_World_AddBody(world, rigid, false));
    ok(H, H.HP_Body_SetAngularVelocity(rigid, [...body.omega0]));
    return {
      step: () => ok(H, H.HP_World_Step(world, dt)),
      quaternion: () => { const [[, q]] = ok(H, H.HP_Body_GetQTransform(rigid)); return [q[3], q[0], q[1], q[2]]; },
      omegaWorld: () => ok(H, H.HP_Body_GetAngularVelocity(rigid))[0],
      dispose() {
        ok(H, H.HP_World_RemoveBody(world, rigid));
        ok(H, H.HP_Body_Release(rigid));
        ok(H, H.HP_Shape_Release(shape));
        ok(H, H.HP_World_Release(world));
      },
    };
  },
};
