// MuJoCo's own WebAssembly module (mujoco-js, doubles) as models run under node by
// web/flipcheck-engines.mjs, one per integrator of mjOption (Euler, RK4, implicit,
// implicitfast). The model is written as MJCF: one body on a free joint whose <inertial> gives
// the mass and diag(Ix, Iy, Iz) (no geom: nothing is derived from a shape), gravity 0, the
// integrator and timestep dt in <option>, contacts and the velocity limit off by default;
// joint damping and armature 0 (MJCF's defaults). MuJoCo keeps the gyroscopic term in its
// bias forces with every integrator; mj_step is one step of dt. A free joint's qvel holds ω in
// the body frame (MuJoCo's convention): ω0 is set there, and read back rotated into the world.
import loadMujoco from 'mujoco-js';
import { NODE_ENGINE_MODEL } from './models.js';

const INTEGRATORS = { euler: 'Euler', rk4: 'RK4', implicit: 'implicit', implicitfast: 'implicitfast' };

/** v rotated by the unit quaternion q = [w, x, y, z] (body → world). */
function rotate(q, v) {
  const [w, x, y, z] = q;
  const t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])];
  return [v[0] + w * t[0] + (y * t[2] - z * t[1]), v[1] + w * t[1] + (z * t[0] - x * t[2]),
    v[2] + w * t[2] + (x * t[1] - y * t[0])];
}

function mujocoAdapter(integrator) {
  return {
    model: NODE_ENGINE_MODEL.mujoco[integrator],
    package: 'mujoco-js',
    mode: integrator,
    label: `MuJoCo (WebAssembly), ${INTEGRATORS[integrator]}`,
    load() {
      if (!mujocoAdapter.module) mujocoAdapter.module = loadMujoco();
      return mujocoAdapter.module.then((M) => {
        this.M = M;
        if (!mujocoAdapter.mounted) {
          M.FS.mkdir('/flipcheck');
          M.FS.mount(M.MEMFS, { root: '.' }, '/flipcheck');
          mujocoAdapter.mounted = true;
        }
      });
    },
    start(body, dt) {
      const M = this.M;
      const [ix, iy, iz] = body.moments;
      const xml = `<mujoco model="flipcheck">
  <option timestep="${dt}" gravity="0 0 0" integrator="${INTEGRATORS[integrator]}"/>
  <worldbody>
    <body name="body">
      <freejoint/>
      <inertial pos="0 0 0" mass="${body.mass}" diaginertia="${ix} ${iy} ${iz}"/>
    </body>
  </worldbody>
</mujoco>`;
      M.FS.writeFile('/flipcheck/body.xml', xml);
      const model = M.MjModel.loadFromXML('/flipcheck/body.xml');
      const data = new M.MjData(model);
      const qvel = data.qvel;
      const w0 = body.omega0;  // world = body frame at the start (q = identity)
      for (let i = 0; i < 3; ++i) { qvel[i] = 0; qvel[3 + i] = w0[i]; }
      const quaternion = () => { const p = data.qpos; return [p[3], p[4], p[5], p[6]]; };
      return {
        step: () => M.mj_step(model, data),
        quaternion,
        omegaWorld: () => { const v = data.qvel; return rotate(quaternion(), [v[3], v[4], v[5]]); },
        dispose() { data.delete(); model.delete(); },
      };
    },
  };
}

export const mujocoEuler = mujocoAdapter('euler');
export const mujocoRk4 = mujocoAdapter('rk4');
export const mujocoImplicit = mujocoAdapter('implicit');
export const mujocoImplicitfast = mujocoAdapter('implicitfast');
