// oimo (oimo.js: pure JavaScript, doubles) as a model run under node by
// web/flipcheck-engines.mjs. One moving box body (World.add) in a world with no gravity, its
// mass and principal moments set after the shape's (mass, inverseMass, localInertia and its
// inverse, syncShapes), allowSleep false, World.step() at the world's timestep dt. oimo has no
// damping and no speed limit on a lone body, and no integrator or gyroscopic option: ω
// changes only by torque (RigidBody.updatePosition), so a free body keeps ω fixed in the world.
import OIMO from 'oimo';
import { NODE_ENGINE_MODEL } from './models.js';

export const oimo = {
  model: NODE_ENGINE_MODEL.oimo,
  package: 'oimo',
  mode: '',
  label: 'oimo',
  load: () => Promise.resolve(),
  start(body, dt) {
    const world = new OIMO.World({ timestep: dt, iterations: 8, broadphase: 2, worldscale: 1,
      random: false, info: false, gravity: [0, 0, 0] });
    const rigid = world.add({ type: 'box', size: [...body.size], pos: [0, 0, 0], move: true });
    rigid.allowSleep = false;
    const [ix, iy, iz] = body.moments;
    rigid.mass = body.mass;
    rigid.inverseMass = 1 / body.mass;
    rigid.localInertia.set(ix, 0, 0, 0, iy, 0, 0, 0, iz);
    rigid.inverseLocalInertia.set(1 / ix, 0, 0, 0, 1 / iy, 0, 0, 0, 1 / iz);
    rigid.syncShapes();
    rigid.angularVelocity.set(...body.omega0);
    return {
      step: () => world.step(),
      quaternion: () => { const q = rigid.orientation; return [q.w, q.x, q.y, q.z]; },
      omegaWorld: () => { const w = rigid.angularVelocity; return [w.x, w.y, w.z]; },
      dispose: () => world.clear(),
    };
  },
};
