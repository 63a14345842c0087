// Rapier (@dimforge/rapier3d-compat: Rust compiled to WebAssembly, single precision, the
// WebAssembly inlined as base64) as a model of the page: one dynamic rigid body with no
// collider, its mass and principal moments given as its only mass properties
// (setAdditionalMassProperties, principal frame = body frame), no gravity, no damping, no
// sleeping, World.step() at timestep dt.
import RAPIER from '@dimforge/rapier3d-compat';
import { ENGINE_MODEL } from './models.js';

export const rapier = {
  model: ENGINE_MODEL.rapier,
  package: '@dimforge/rapier3d-compat',
  mode: '',
  label: 'Rapier 0.21',
  load: () => RAPIER.init(),
  start(body, dt) {
    const world = new RAPIER.World({ x: 0, y: 0, z: 0 });
    world.timestep = dt;
    const [ix, iy, iz] = body.moments;
    const [wx, wy, wz] = body.omega0;
    const desc = RAPIER.RigidBodyDesc.dynamic()
      .setLinearDamping(0).setAngularDamping(0).setCanSleep(false).setGravityScale(0)
      .setAdditionalMassProperties(body.mass, { x: 0, y: 0, z: 0 }, { x: ix, y: iy, z: iz },
        { w: 1, x: 0, y: 0, z: 0 })
      .setAngvel({ x: wx, y: wy, z: wz });
    const rigid = world.createRigidBody(desc);
    return {
      step: () => world.step(),
      quaternion: () => { const q = rigid.rotation(); return [q.w, q.x, q.y, q.z]; },
      omegaWorld: () => { const w = rigid.angvel(); return [w.x, w.y, w.z]; },
      dispose: () => world.free(),
    };
  },
};
