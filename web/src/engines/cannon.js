// cannon-es (pure JavaScript, doubles) as a model of the page: one Body in a World with no
// gravity, no damping, no sleeping, stepped by World.step(dt) (one fixed step). Its principal
// moments are set on the body after its shape (Body.inertia, invInertia, then
// updateInertiaWorld), so the box's own inertia is never used. cannon-es integrates ω with the
// torque alone (semi-implicit Euler, no gyroscopic term), so a free body's ω stays fixed in the
// world frame (docs/explorer.md).
import { World, Body, Box, Vec3 } from 'cannon-es';
import { ENGINE_MODEL } from './models.js';

export const cannon = {
  model: ENGINE_MODEL.cannon,
  package: 'cannon-es',
  mode: '',
  label: 'cannon-es 0.20',
  load: () => Promise.resolve(),
  start(body, dt) {
    const world = new World({ gravity: new Vec3(0, 0, 0), allowSleep: false });
    world.quatNormalizeSkip = 0;
    world.quatNormalizeFast = false;
    const [a, b, c] = body.size;
    const rigid = new Body({
      mass: body.mass, shape: new Box(new Vec3(a / 2, b / 2, c / 2)),
      linearDamping: 0, angularDamping: 0, allowSleep: false,
    });
    const [ix, iy, iz] = body.moments;
    rigid.inertia.set(ix, iy, iz);
    rigid.invInertia.set(1 / ix, 1 / iy, 1 / iz);
    rigid.updateInertiaWorld(true);
    rigid.angularVelocity.set(body.omega0[0], body.omega0[1], body.omega0[2]);
    world.addBody(rigid);
    return {
      step: () => world.step(dt),
      quaternion: () => { const q = rigid.quaternion; return [q.w, q.x, q.y, q.z]; },
      omegaWorld: () => { const w = rigid.angularVelocity; return [w.x, w.y, w.z]; },
      dispose: () => world.removeBody(rigid),
    };
  },
};
